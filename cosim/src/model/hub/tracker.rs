//! Frame tracker (hub contract §5): follows the frame on `coupled_q` at the sample
//! points of the hub's bit timing logic, enough to know the bit boundaries, the
//! arbitration field and the ACK slot (ISO 11898-1 clause 10: destuffing, IDE, RTR,
//! DLC). It does not check the CRC. It also keeps the `STATS` counters (frames
//! tracked to their ACK slot, stuff and CRC-delimiter form errors).
//!
//! [`Tracker::sample`] is one SAMPLE edge; it returns which per-port action of §6
//! this bit calls for (`SOF_PORTS`, `FRAME_PORTS` with the facts the guards need,
//! `ACK_PORTS`, or none).

/// Tracker state encodings (`trk[1:0]`).
pub const IDLE_WAIT: u8 = 0;
pub const FRAME: u8 = 1;
pub const ACK_SLOT: u8 = 2;
pub const ACK_DELIM: u8 = 3;

/// Recessive bits after which a dominant bit is a start of frame (§5 Decision).
const SOF_RUN: u8 = 10;

/// The per-port action a sampled bit calls for (contract §6).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrkEvent {
    /// No per-frame action (idle, error/overload flags, the ACK delimiter).
    None,
    /// `SOF_PORTS`: a start of frame.
    Sof,
    /// `FRAME_PORTS`: a bit of `FRAME` (data bit, stuff bit or CRC delimiter).
    Frame {
        /// `in_arb` with `pos` and `ide` before the edge.
        in_arb: bool,
        /// A stuff error with a recessive bit (six recessive bits): every port with
        /// `cand` is blamed.
        stuff_recessive: bool,
        /// Data bit `pos == 10` with the new `id_zero` = 1 (identifier 0x000 or
        /// 0x001): rule RID.
        reserved_id: bool,
    },
    /// `ACK_PORTS`: the ACK slot (`trk == ACK_SLOT` before the edge).
    Ack,
}

/// Tracker registers and the `STATS` counters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tracker {
    /// `trk`.
    pub state: u8,
    /// Recessive samples in a row in `IDLE_WAIT` (0..10).
    rec_run: u8,
    /// Data bit number (SOF = 0), 7 bits.
    pos: u8,
    /// Equal bits in a row of the stuffed stream (1..5).
    same_run: u8,
    /// Last bit of the stuffed stream.
    last: bool,
    ide: bool,
    rtr: bool,
    dlc: u8,
    /// The identifier bits 1..10 seen so far are all dominant.
    id_zero: bool,
    /// `pos` of the CRC delimiter.
    crc_end: u8,
    /// `STATS[15:0]`: frames tracked to their ACK slot (saturating).
    pub frames: u16,
    /// `STATS[31:16]`: tracker errors, stuff and CRC delimiter form (saturating).
    pub errors: u16,
}

impl Default for Tracker {
    fn default() -> Self {
        Self::new()
    }
}

impl Tracker {
    /// Reset state: `IDLE_WAIT`, `rec_run = 0`, counters 0.
    pub fn new() -> Self {
        Tracker {
            state: IDLE_WAIT,
            rec_run: 0,
            pos: 0,
            same_run: 0,
            last: false,
            ide: false,
            rtr: false,
            dlc: 0,
            id_zero: true,
            crc_end: 127,
            frames: 0,
            errors: 0,
        }
    }

    /// `ack_window` (§4): the tracker is in the ACK slot or ACK delimiter.
    #[inline]
    pub fn ack_window(&self) -> bool {
        self.state == ACK_SLOT || self.state == ACK_DELIM
    }

    /// STUFF_ERROR, FORM_ERROR: count, wait for the bus to be idle again.
    fn error(&mut self) {
        self.errors = self.errors.saturating_add(1);
        self.state = IDLE_WAIT;
        self.rec_run = 0;
    }

    /// One SAMPLE edge with the sampled bus value `b` (1 = recessive).
    pub fn sample(&mut self, b: bool) -> TrkEvent {
        match self.state {
            IDLE_WAIT => {
                if b {
                    self.rec_run = (self.rec_run + 1).min(SOF_RUN);
                    TrkEvent::None
                } else if self.rec_run >= SOF_RUN {
                    self.state = FRAME;
                    self.pos = 1;
                    self.same_run = 1;
                    self.last = false;
                    self.ide = false;
                    self.rtr = false;
                    self.dlc = 0;
                    self.id_zero = true;
                    self.crc_end = 127;
                    TrkEvent::Sof
                } else {
                    // Error or overload flags: wait for the bus to be idle again.
                    self.rec_run = 0;
                    TrkEvent::None
                }
            }
            FRAME => {
                let in_arb = self.pos <= 13 || (self.ide && self.pos <= 32);
                if self.same_run == 5 {
                    // A stuff bit is due.
                    if b == self.last {
                        self.error();
                        TrkEvent::Frame {
                            in_arb,
                            stuff_recessive: b,
                            reserved_id: false,
                        }
                    } else {
                        self.same_run = 1;
                        self.last = b;
                        TrkEvent::Frame {
                            in_arb,
                            stuff_recessive: false,
                            reserved_id: false,
                        }
                    }
                } else if self.pos == self.crc_end {
                    // The CRC delimiter (never stuffed).
                    if b {
                        self.state = ACK_SLOT;
                    } else {
                        self.error();
                    }
                    TrkEvent::Frame {
                        in_arb,
                        stuff_recessive: false,
                        reserved_id: false,
                    }
                } else {
                    // Data bit number `pos`.
                    let pos = self.pos;
                    self.same_run = if b == self.last { self.same_run + 1 } else { 1 };
                    self.last = b;
                    if (1..=10).contains(&pos) {
                        self.id_zero &= !b;
                    }
                    let reserved_id = pos == 10 && self.id_zero;
                    if pos == 12 {
                        // RTR of a base frame, SRR of an extended one.
                        self.rtr = b;
                    }
                    if pos == 13 {
                        self.ide = b;
                    }
                    if pos == 32 && self.ide {
                        self.rtr = b;
                    }
                    let (dlc_first, data_start) = if self.ide { (35, 39) } else { (15, 19) };
                    if (dlc_first..dlc_first + 4).contains(&pos) {
                        self.dlc = ((self.dlc << 1) | b as u8) & 0xF;
                        if pos == dlc_first + 3 {
                            let data = if self.rtr { 0 } else { 8 * self.dlc.min(8) };
                            self.crc_end = data_start + data + 15;
                        }
                    }
                    self.pos = (pos + 1) & 0x7F;
                    TrkEvent::Frame {
                        in_arb,
                        stuff_recessive: false,
                        reserved_id,
                    }
                }
            }
            ACK_SLOT => {
                self.frames = self.frames.saturating_add(1);
                self.state = ACK_DELIM;
                TrkEvent::Ack
            }
            _ => {
                // ACK_DELIM: the ACK delimiter is the first recessive bit.
                self.state = IDLE_WAIT;
                self.rec_run = b as u8;
                TrkEvent::None
            }
        }
    }
}
