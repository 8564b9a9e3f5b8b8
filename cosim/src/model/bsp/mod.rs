//! Bit stream processor (timing contract §4; ISO 11898-1:2015 clause 10, MAC
//! sub-layer: frame formats, bit stuffing, arbitration, error detection and
//! signalling, overload signalling, interframe space; clause 12, fault confinement).
//!
//! The BSP moves only at SAMPLE edges (`sample`, with the sampled bus value) and
//! loads `tx` only at bit_start edges (`bit_start`). This file holds the state, the
//! dispatch on the `field` probe and what goes on `tx` (contract §4.2); the fields
//! live in `frame.rs`, the interframe states in `interframe.rs`, error and overload
//! frames in `error.rs`, the counters in `confinement.rs`, the transmitter's bit
//! string in `encode.rs`.
//!
//! Decisions where the standard or the contract leave room (the list is repeated
//! in timing_contract.md §4.5):
//! 1. Roles. A node is *transmitter* from the SOF it starts as transmitter until
//!    the next SOF, until it loses arbitration, until the end of the
//!    intermission that follows its frame (the SAMPLE edge of the 3rd recessive
//!    intermission bit), or until it becomes bus-off; the `is_tx` probe shows
//!    the role after the edge. Error and overload frames in between
//!    count for it as transmitter (rules c, d, f) and make it suspend transmission
//!    when error passive. Every other node is a receiver.
//! 2. Counters change at the SAMPLE edge where the error is detected (for a CRC
//!    error: at the ACK delimiter, where its flag is decided), once per error flag
//!    even if several errors coincide (CRC error plus form error: one +1). The
//!    error state follows at the same edge, and the flag that starts at the next
//!    bit is active or passive according to the new state.
//! 3. A bit error in an active error flag or an overload flag costs +8 (rule d or
//!    e) and restarts an error flag at the next bit; rules a and c do not add to it.
//! 4. Rule c exception 2 (stuff error in arbitration on a recessive stuff bit read
//!    dominant) leaves both counters unchanged. A stuff bit is "in arbitration" when
//!    the last non-stuff bit before it belongs to ID_A, SRR_RTR, IDE, ID_B or
//!    RTR_EXT (the contract's arbitration fields).
//! 5. Rule c exception 1 (error-passive transmitter, ACK error): no increment at
//!    detection; +8 once at the first dominant bit sampled during its passive flag.
//! 6. Rule b (+8 for a receiver whose first bit after an error flag is dominant)
//!    applies after active and passive error flags, not after overload flags.
//! 7. Rule f counts dominant bits after the flag (active or overload flag: the
//!    14th dominant bit counted from the flag's start is the 8th after it; passive
//!    flag: the 8th after the 6 equal bits that completed it), then every further 8.
//! 8. Rule h (REC - 1) applies at the ACK slot, where the standard places it
//!    ("no error up to the ACK slot and the ACK bit sent successfully"); REC > 127
//!    becomes 127.
//! 9. Bus-off takes effect at the edge where TEC exceeds 255: no (further) flag
//!    bit is sent, `tx` is recessive from the next bit_start, the pending frame
//!    stays pending. Recovery after 128 x 11 recessive bits goes to IDLE (the node
//!    has just seen 11 recessive bits, which is bus integration), TEC = REC = 0.
//!    While the `boff_hold` input is 1 at a SAMPLE edge, neither count (the
//!    recessive samples of the run, the completed runs) changes at that edge, and a
//!    dominant sample does not restart the run; the node stays in BUS_OFF.
//! 10. A node whose suspend transmission is due (error passive, transmitter of the
//!     frame that just ended) does not join a SOF at intermission bit 3: for it
//!     `start_ok` is false there, as in SUSPEND.
//! 11. Receivers accept either value of SRR, r1 and r0; a dominant EOF bit 7 starts
//!     an overload frame for a receiver and is an error for the transmitter.
//! 12. The 8th bit of an error or overload delimiter sampled dominant starts an
//!     overload frame (no counter change); a dominant bit at delimiter bits 2..7 is a
//!     form error.
//!
//! Operating modes (contract §7), transmit control (§8) and diagnostics (§9):
//! 13. LISTEN_ONLY forces every bit the node sends to recessive (`next_tx_bit`,
//!     `start_ok`), makes every error flag passive, follows overload flags without
//!     checking them and freezes the counters; errors are still detected and
//!     captured. SELF_TEST and LOOPBACK skip the transmitter's ACK slot check;
//!     LOOPBACK also delivers the node's own frame at EOF bit 6 (the model's
//!     `ChannelModel` feeds the synchronizer with `tx` and holds the pin recessive).
//! 14. An *attempt* runs from the SOF at which the node becomes transmitter until
//!     `tx_done`, lost arbitration or the first error it detects as transmitter.
//!     An attempt that ends without success drops the frame (`tx_failed`) in
//!     single-shot mode (`cfg_single_shot`, or `tx_single` latched with the frame
//!     by its accepted `tx_req`) or when an abort is remembered.
//! 15. `tx_abort` (and a remembered abort, at every edge until it is carried out)
//!     drops the pending frame at once when the node is not transmitter and its
//!     `tx` register is recessive; otherwise it is remembered. A node whose own
//!     SOF is on `tx` (dominant) keeps it at the later SOF decisions (the hard
//!     sync on its own SOF edge, the SOF sample point) whatever the abort: its
//!     attempt has begun and runs on (`starts`).
//! 16. `err_valid` and the capture registers are loaded in `error` and for a bit
//!     error in an own flag (`capture`), also for the error that makes the node
//!     bus-off; `alc` at the arbitration loss.

mod confinement;
mod control;
mod encode;
mod error;
mod frame;
mod interframe;

pub use confinement::{Counters, BUS_OFF as STATE_BUS_OFF, ERROR_ACTIVE, ERROR_PASSIVE};
pub use control::{Diag, KIND_ACK, KIND_BIT, KIND_CRC, KIND_FORM, KIND_STUFF};

use self::encode::TxStream;
use crate::engine::Mode;
use crate::frame::Frame;
use crate::model::field;

/// Bit stream processor state of one channel.
#[derive(Clone, Debug)]
pub struct Bsp {
    // §4.1: the field of the next non-stuff bit and the bit counter inside it.
    field: u8,
    cnt: u8,
    // §4.2: the `tx` register and the bit prepared for the next bit_start.
    tx: bool,
    tx_bit: bool,
    // §4.4: the latched frame.
    tx_pending: bool,
    stream: TxStream,
    /// Role of the node (decision 1).
    transmitter: bool,
    // §4.3: stuffing state of the stuffed region.
    stuff_cnt: u8,
    stuff_last: bool,
    /// The last non-stuff bit belonged to the arbitration fields (decision 4).
    last_arb: bool,
    // The frame on the bus.
    /// Destuffed bits since SOF (SOF = bit 0): index of the next frame bit.
    pos: u8,
    crc: u16,
    id: u32,
    srr_rtr: bool,
    ide: bool,
    rtr: bool,
    dlc: u8,
    data: u64,
    data_bits: u8,
    rx_crc: u16,
    crc_ok: bool,
    // Error and overload frames.
    /// The error flag being sent is active (dominant).
    flag_active: bool,
    /// Passive flag: last bit value and how many equal bits in a row.
    flag_last: bool,
    flag_eq: u8,
    /// The next delimiter bit is the first bit after an error flag (rule b).
    first_after_flag: bool,
    /// Dominant bits after the flag, modulo 8 (rule f).
    dom_cnt: u8,
    /// Rule c exception 1 is pending (decision 5).
    ack_exception: bool,
    /// Occurrences of 11 recessive bits while bus-off (rule l).
    busoff_occ: u8,
    counters: Counters,
    // Configuration captured in reset mode (§6, §7, §8).
    /// LISTEN_ONLY: never drives dominant, counters frozen.
    listen_only: bool,
    /// SELF_TEST or LOOPBACK: the transmitter accepts a recessive ACK slot.
    ack_optional: bool,
    /// LOOPBACK: the transmitter delivers its own frame too.
    loopback: bool,
    /// No automatic retransmission.
    single_shot: bool,
    /// `tx_single` latched with the pending frame: this frame is single shot (§8).
    tx_single: bool,
    // §8: transmit control.
    /// The pending frame's attempt is on the bus (decision 14).
    attempt: bool,
    /// A `tx_abort` is remembered (decision 15).
    abort_pending: bool,
    /// The abort became remembered at this edge: an attempt that ends at this same
    /// edge is judged without it (§8, "on the state before it").
    abort_new: bool,
    // Host side.
    rx_frame: Frame,
    tx_done: bool,
    arb_lost: bool,
    rx_valid: bool,
    tx_failed: bool,
    /// §9 registers.
    diag: Diag,
}

impl Default for Bsp {
    fn default() -> Self {
        Self::new()
    }
}

impl Bsp {
    /// Reset state in NORMAL mode with automatic retransmission.
    pub fn new() -> Self {
        Self::with_config(Mode::Normal, false)
    }

    /// Reset state: INTEGRATING, `tx` recessive, nothing pending, error active,
    /// with the captured mode and single-shot setting (contract §6).
    pub fn with_config(mode: Mode, single_shot: bool) -> Self {
        let listen_only = mode == Mode::ListenOnly;
        let mut counters = Counters::new();
        if listen_only {
            counters.freeze();
        }
        Bsp {
            field: field::INTEGRATING,
            cnt: 0,
            tx: true,
            tx_bit: true,
            tx_pending: false,
            stream: TxStream::default(),
            transmitter: false,
            stuff_cnt: 0,
            stuff_last: true,
            last_arb: false,
            pos: 0,
            crc: 0,
            id: 0,
            srr_rtr: false,
            ide: false,
            rtr: false,
            dlc: 0,
            data: 0,
            data_bits: 0,
            rx_crc: 0,
            crc_ok: false,
            flag_active: true,
            flag_last: true,
            flag_eq: 0,
            first_after_flag: false,
            dom_cnt: 0,
            ack_exception: false,
            busoff_occ: 0,
            counters,
            listen_only,
            ack_optional: matches!(mode, Mode::SelfTest | Mode::Loopback),
            loopback: mode == Mode::Loopback,
            single_shot,
            tx_single: false,
            attempt: false,
            abort_pending: false,
            abort_new: false,
            rx_frame: Frame::default(),
            tx_done: false,
            arb_lost: false,
            rx_valid: false,
            tx_failed: false,
            diag: Diag::default(),
        }
    }

    /// The `tx` register.
    #[inline]
    pub fn tx(&self) -> bool {
        self.tx
    }

    /// A frame is latched and not yet sent.
    #[inline]
    pub fn tx_pending(&self) -> bool {
        self.tx_pending
    }

    /// The `field` probe.
    #[inline]
    pub fn field(&self) -> u8 {
        self.field
    }

    /// `err_reset` (contract §4.5).
    pub fn err_reset(&mut self) {
        self.counters.err_reset();
    }

    /// Error counters and state.
    #[inline]
    pub fn counters(&self) -> &Counters {
        &self.counters
    }

    /// Last received frame.
    #[inline]
    pub fn rx_frame(&self) -> &Frame {
        &self.rx_frame
    }

    /// Pulses raised by the current edge: (`tx_done`, `arb_lost`, `rx_valid`,
    /// `tx_failed`).
    #[inline]
    pub fn pulses(&self) -> (bool, bool, bool, bool) {
        (self.tx_done, self.arb_lost, self.rx_valid, self.tx_failed)
    }

    /// Diagnostics registers (§9; `err_warning` is derived by the caller).
    #[inline]
    pub fn diag(&self) -> &Diag {
        &self.diag
    }

    /// Clears the one-clock pulses at the start of an edge.
    #[inline]
    pub fn clear_pulses(&mut self) {
        self.tx_done = false;
        self.arb_lost = false;
        self.rx_valid = false;
        self.tx_failed = false;
        self.diag.err_valid = false;
        self.abort_new = false;
    }

    /// `tx_req` while nothing is pending (contract §4.4): latch the frame and its
    /// `tx_single` (§8), or in LISTEN_ONLY refuse it with `tx_failed` (§7).
    pub fn latch(&mut self, frame: &Frame, single: bool) {
        if self.listen_only {
            self.tx_failed = true;
            return;
        }
        self.stream = TxStream::encode(frame);
        self.tx_single = single;
        self.tx_pending = true;
    }

    /// The `is_tx` probe: the transmitter role (contract §4.5 "Roles").
    #[inline]
    pub fn is_tx(&self) -> bool {
        self.transmitter
    }

    /// The `boff_runs` probe: completed runs of 11 recessive samples in the
    /// current bus-off, 0 outside bus-off (contract §4.5 "Bus-off").
    #[inline]
    pub fn boff_runs(&self) -> u8 {
        if self.counters.is_bus_off() {
            self.busoff_occ
        } else {
            0
        }
    }

    /// `hard_sync_enable` (contract §4.1).
    #[inline]
    pub fn hard_sync_enable(&self) -> bool {
        matches!(
            self.field,
            field::INTEGRATING | field::IDLE | field::SUSPEND | field::BUS_OFF
        ) || (self.field == field::INTERMISSION && self.cnt == 2)
    }

    /// `start_ok` (contract §4.2 and §8, with decision 10 for suspend
    /// transmission). `tx_abort` of this edge has already been applied (`abort`):
    /// it either cleared `tx_pending` or set `abort_pending`.
    #[inline]
    fn start_ok(&self) -> bool {
        self.tx_pending
            && !self.counters.is_bus_off()
            && !self.listen_only
            && !self.abort_pending
            && match self.field {
                field::SUSPEND => false,
                field::INTERMISSION => !(self.counters.is_passive() && self.transmitter),
                _ => true,
            }
    }

    /// The SOF decision (contract §4.2, §4.4, §8): `start_ok`, except that a node
    /// whose SOF is already on `tx` (dominant `tx` register with a frame pending)
    /// keeps it; its attempt has begun and an abort does not withdraw it (decision
    /// 15). Only an abort can make `start_ok` fall while the SOF is on `tx`.
    #[inline]
    fn starts(&self) -> bool {
        (!self.tx && self.tx_pending) || self.start_ok()
    }

    /// A bit_start edge: load `tx` (contract §4.2).
    #[inline]
    pub fn bit_start(&mut self, hard: bool) {
        self.tx = if hard && matches!(self.field, field::SUSPEND | field::INTERMISSION) {
            // SUSPEND: joins as receiver only. Intermission bit 3: a joining
            // transmitter sends no SOF bit (ISO 11898-1 10.4.6, contract §4.2).
            true
        } else if self.field == field::IDLE {
            !self.starts()
        } else {
            self.tx_bit
        };
    }

    /// A SAMPLE edge with the sampled bus value `b` (`true` = recessive) and the
    /// `boff_hold` input before the edge (contract §4.5: while it is 1 a bus-off
    /// node's recovery counts stand still, decision 9).
    pub fn sample(&mut self, b: bool, boff_hold: bool) {
        match self.field {
            field::INTEGRATING => self.integrating(b),
            field::IDLE => self.idle(b),
            field::INTERMISSION => self.intermission(b),
            field::SUSPEND => self.suspend(b),
            // §4.5: `boff_hold` freezes both recovery counts.
            field::BUS_OFF if boff_hold => {}
            field::BUS_OFF => self.bus_off(b),
            field::ID_A..=field::CRC_DELIM => self.stuffed_bit(b),
            field::ACK_SLOT => self.ack_slot(b),
            field::ACK_DELIM => self.ack_delim(b),
            field::EOF => self.eof(b),
            field::ERROR_FLAG => self.error_flag(b),
            field::OVERLOAD_FLAG => self.overload_flag(b),
            field::ERROR_DELIM | field::OVERLOAD_DELIM => self.delimiter(b),
            other => unreachable!("field code {other}"),
        }
        if self.counters.is_bus_off() && self.field != field::BUS_OFF {
            self.enter_bus_off();
        }
        self.tx_bit = self.next_tx_bit();
    }

    /// The bit to send at the next bit_start (contract §4.2): a stuff bit or the
    /// next frame bit of a transmitter, the ACK of a receiver whose CRC matched, the
    /// dominant bits of active error and overload flags, recessive otherwise.
    #[inline]
    fn next_tx_bit(&self) -> bool {
        if self.listen_only {
            // §7: every bit a listen-only node would send is recessive.
            return true;
        }
        match self.field {
            field::ID_A..=field::CRC_DELIM => {
                if !self.transmitter {
                    true
                } else if self.stuff_cnt == 5 {
                    !self.stuff_last
                } else {
                    self.stream.bit(self.pos)
                }
            }
            field::ACK_SLOT => self.transmitter || !self.crc_ok,
            field::ERROR_FLAG => !self.flag_active,
            field::OVERLOAD_FLAG => false,
            _ => true,
        }
    }
}
