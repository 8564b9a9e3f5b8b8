//! Frame tracker of the hub (ReCANcentrate paper section 4: the hub follows the
//! frame to know where the ACK slot is; hub contract §5 "Tracker"). At every
//! SAMPLE edge of the hub's bit timing logic it destuffs the coupled signal and
//! follows SOF, the arbitration field, IDE, RTR and DLC far enough to find the CRC
//! delimiter, the ACK slot and the ACK delimiter; it counts the frames tracked to
//! their ACK slot and its own stuff / CRC-delimiter form errors (STATS). A dominant
//! bit after at least 10 recessive bits is a start of frame (contract decision).
//!
//! It also hands the guards (§6) the per-bit events of the frame, valid in the
//! clock of the SAMPLE edge: `ev_sof` (SOF_PORTS), `ev_frame` (FRAME_PORTS: every
//! sampled bit of FRAME), `in_arb`, `ev_stuff_rec` (a stuff error on a recessive
//! bit), `ev_rid` (data bit 10 with an identifier 0x000/0x001) and `ev_ack`
//! (ACK_PORTS). Every register is held at its reset value while `rst` (the hub's
//! `rst | reset_mode`).

use rust_hdl::prelude::*;

/// Tracker states (contract §5 encodings).
pub const IDLE_WAIT: u64 = 0;
pub const FRAME: u64 = 1;
pub const ACK_SLOT: u64 = 2;
pub const ACK_DELIM: u64 = 3;

/// The hub's frame tracker.
#[derive(LogicBlock)]
pub struct FrameTracker {
    // clock and reset
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst | reset_mode`: every register held at its reset value.
    pub rst: Signal<In, Bit>,
    // from the bit timing logic and the coupler
    /// A SAMPLE edge of the hub's bit timing logic (one clock).
    pub sample: Signal<In, Bit>,
    /// `coupled_q`: the sampled bus value at a SAMPLE edge.
    pub b: Signal<In, Bit>,
    // state and statistics
    /// Tracker state (`STATUS.trk`): 0 IDLE_WAIT, 1 FRAME, 2 ACK_SLOT, 3 ACK_DELIM.
    pub trk: Signal<Out, Bits<2>>,
    /// Frames tracked to their ACK slot (saturating).
    pub frames: Signal<Out, Bits<16>>,
    /// The tracker's own stuff and CRC-delimiter form errors (saturating).
    pub errors: Signal<Out, Bits<16>>,
    // events for the guards (valid in the clock of the SAMPLE edge)
    /// `SOF_PORTS`: a dominant bit after at least 10 recessive ones, a start of frame.
    pub ev_sof: Signal<Out, Bit>,
    /// `FRAME_PORTS`: every sampled bit of FRAME (stuff bits and the CRC delimiter included).
    pub ev_frame: Signal<Out, Bit>,
    /// The bit at this edge is in the arbitration field (`pos <= 13`, or `pos <= 32` with IDE).
    pub in_arb: Signal<Out, Bit>,
    /// A stuff error on a recessive bit.
    pub ev_stuff_rec: Signal<Out, Bit>,
    /// Data bit 10 of a frame with identifier 0x000 or 0x001 (reserved identifiers).
    pub ev_rid: Signal<Out, Bit>,
    /// `ACK_PORTS`: the ACK slot is sampled.
    pub ev_ack: Signal<Out, Bit>,
    // registers
    trk_q: DFF<Bits<2>>,
    rec_run: DFF<Bits<4>>,
    pos: DFF<Bits<7>>,
    same_run: DFF<Bits<3>>,
    last_q: DFF<Bit>,
    ide: DFF<Bit>,
    rtr: DFF<Bit>,
    dlc: DFF<Bits<4>>,
    id_zero: DFF<Bit>,
    crc_end: DFF<Bits<7>>,
    frames_q: DFF<Bits<16>>,
    errors_q: DFF<Bits<16>>,
    // combinational
    st_idle: Signal<Local, Bit>,
    st_frame: Signal<Local, Bit>,
    st_ack: Signal<Local, Bit>,
    stuff_due: Signal<Local, Bit>,
    at_crc_delim: Signal<Local, Bit>,
    data_bit: Signal<Local, Bit>,
    id_zero_new: Signal<Local, Bit>,
    dlc_new: Signal<Local, Bits<4>>,
    dlc_field: Signal<Local, Bit>,
    last_dlc: Signal<Local, Bit>,
    dlc8: Signal<Local, Bits<4>>,
    data_len: Signal<Local, Bits<7>>,
    crc_base: Signal<Local, Bits<7>>,
    err_evt: Signal<Local, Bit>,
    // constants
    s_idle: Constant<Bits<2>>,
    s_frame: Constant<Bits<2>>,
    s_ack: Constant<Bits<2>>,
    s_delim: Constant<Bits<2>>,
    n4_0: Constant<Bits<4>>,
    n4_1: Constant<Bits<4>>,
    n4_8: Constant<Bits<4>>,
    n4_10: Constant<Bits<4>>,
    n3_1: Constant<Bits<3>>,
    n3_5: Constant<Bits<3>>,
    p0: Constant<Bits<7>>,
    p1: Constant<Bits<7>>,
    p10: Constant<Bits<7>>,
    p12: Constant<Bits<7>>,
    p13: Constant<Bits<7>>,
    p15: Constant<Bits<7>>,
    p18: Constant<Bits<7>>,
    p32: Constant<Bits<7>>,
    p34: Constant<Bits<7>>,
    p35: Constant<Bits<7>>,
    p38: Constant<Bits<7>>,
    p54: Constant<Bits<7>>,
    p127: Constant<Bits<7>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
}

impl Default for FrameTracker {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            sample: Default::default(),
            b: Default::default(),
            trk: Default::default(),
            frames: Default::default(),
            errors: Default::default(),
            ev_sof: Default::default(),
            ev_frame: Default::default(),
            in_arb: Default::default(),
            ev_stuff_rec: Default::default(),
            ev_rid: Default::default(),
            ev_ack: Default::default(),
            trk_q: Default::default(),
            rec_run: Default::default(),
            pos: Default::default(),
            same_run: Default::default(),
            last_q: Default::default(),
            ide: Default::default(),
            rtr: Default::default(),
            dlc: Default::default(),
            id_zero: Default::default(),
            crc_end: Default::default(),
            frames_q: Default::default(),
            errors_q: Default::default(),
            st_idle: Default::default(),
            st_frame: Default::default(),
            st_ack: Default::default(),
            stuff_due: Default::default(),
            at_crc_delim: Default::default(),
            data_bit: Default::default(),
            id_zero_new: Default::default(),
            dlc_new: Default::default(),
            dlc_field: Default::default(),
            last_dlc: Default::default(),
            dlc8: Default::default(),
            data_len: Default::default(),
            crc_base: Default::default(),
            err_evt: Default::default(),
            s_idle: Constant::new(IDLE_WAIT.into()),
            s_frame: Constant::new(FRAME.into()),
            s_ack: Constant::new(ACK_SLOT.into()),
            s_delim: Constant::new(ACK_DELIM.into()),
            n4_0: Constant::new(0.into()),
            n4_1: Constant::new(1.into()),
            n4_8: Constant::new(8.into()),
            n4_10: Constant::new(10.into()),
            n3_1: Constant::new(1.into()),
            n3_5: Constant::new(5.into()),
            p0: Constant::new(0.into()),
            p1: Constant::new(1.into()),
            p10: Constant::new(10.into()),
            p12: Constant::new(12.into()),
            p13: Constant::new(13.into()),
            p15: Constant::new(15.into()),
            p18: Constant::new(18.into()),
            p32: Constant::new(32.into()),
            p34: Constant::new(34.into()),
            p35: Constant::new(35.into()),
            p38: Constant::new(38.into()),
            p54: Constant::new(54.into()),
            p127: Constant::new(127.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            max16: Constant::new(0xFFFF.into()),
        }
    }
}

impl Logic for FrameTracker {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, trk_q, rec_run, pos, same_run, last_q, ide, rtr, dlc, id_zero, crc_end,
            frames_q, errors_q
        );
        self.st_idle.next = self.trk_q.q.val() == self.s_idle.val();
        self.st_frame.next = self.trk_q.q.val() == self.s_frame.val();
        self.st_ack.next = self.trk_q.q.val() == self.s_ack.val();
        // FRAME: a stuff bit is due, else the CRC delimiter, else data bit `pos`
        self.stuff_due.next = self.same_run.q.val() == self.n3_5.val();
        self.at_crc_delim.next = self.pos.q.val() == self.crc_end.q.val();
        self.data_bit.next = self.st_frame.val() & !self.stuff_due.val() & !self.at_crc_delim.val();
        // in_arb with pos and ide before the edge
        self.in_arb.next = (self.pos.q.val() <= self.p13.val())
            | (self.ide.q.val() & (self.pos.q.val() <= self.p32.val()));
        // identifier bits 1..10 all dominant: identifier 0x000 or 0x001
        if (self.pos.q.val() >= self.p1.val()) & (self.pos.q.val() <= self.p10.val()) {
            self.id_zero_new.next = self.id_zero.q.val() & !self.b.val();
        } else {
            self.id_zero_new.next = self.id_zero.q.val();
        }
        // DLC field: 15..18 base, 35..38 extended
        self.dlc_new.next = (self.dlc.q.val() << 1) | bit_cast::<4, 1>(self.b.val().into());
        if self.ide.q.val() {
            self.dlc_field.next =
                (self.pos.q.val() >= self.p35.val()) & (self.pos.q.val() <= self.p38.val());
            self.last_dlc.next = self.pos.q.val() == self.p38.val();
            // data_start + 15 = 39 + 15
            self.crc_base.next = self.p54.val();
        } else {
            self.dlc_field.next =
                (self.pos.q.val() >= self.p15.val()) & (self.pos.q.val() <= self.p18.val());
            self.last_dlc.next = self.pos.q.val() == self.p18.val();
            // data_start + 15 = 19 + 15
            self.crc_base.next = self.p34.val();
        }
        if self.dlc_new.val() > self.n4_8.val() {
            self.dlc8.next = self.n4_8.val();
        } else {
            self.dlc8.next = self.dlc_new.val();
        }
        if self.rtr.q.val() {
            self.data_len.next = self.p0.val();
        } else {
            self.data_len.next = bit_cast::<7, 4>(self.dlc8.val()) << 3;
        }

        // events for the guards
        self.ev_sof.next = self.sample.val()
            & self.st_idle.val()
            & !self.b.val()
            & (self.rec_run.q.val() >= self.n4_10.val());
        self.ev_frame.next = self.sample.val() & self.st_frame.val();
        self.ev_stuff_rec.next = self.sample.val()
            & self.st_frame.val()
            & self.stuff_due.val()
            & (self.b.val() == self.last_q.q.val())
            & self.b.val();
        self.ev_rid.next = self.sample.val()
            & self.data_bit.val()
            & (self.pos.q.val() == self.p10.val())
            & self.id_zero_new.val();
        self.ev_ack.next = self.sample.val() & self.st_ack.val();

        // the tracker (§5)
        self.err_evt.next = false;
        if self.sample.val() {
            if self.st_idle.val() {
                if self.b.val() {
                    if self.rec_run.q.val() < self.n4_10.val() {
                        self.rec_run.d.next = self.rec_run.q.val() + self.n4_1.val();
                    }
                } else if self.rec_run.q.val() >= self.n4_10.val() {
                    // start of frame
                    self.trk_q.d.next = self.s_frame.val();
                    self.pos.d.next = self.p1.val();
                    self.same_run.d.next = self.n3_1.val();
                    self.last_q.d.next = false;
                    self.ide.d.next = false;
                    self.rtr.d.next = false;
                    self.dlc.d.next = self.n4_0.val();
                    self.id_zero.d.next = true;
                    self.crc_end.d.next = self.p127.val();
                } else {
                    // error / overload flags: wait again
                    self.rec_run.d.next = self.n4_0.val();
                }
            } else if self.st_frame.val() {
                if self.stuff_due.val() {
                    if self.b.val() == self.last_q.q.val() {
                        // STUFF_ERROR
                        self.err_evt.next = true;
                        self.trk_q.d.next = self.s_idle.val();
                        self.rec_run.d.next = self.n4_0.val();
                    } else {
                        self.same_run.d.next = self.n3_1.val();
                        self.last_q.d.next = self.b.val();
                    }
                } else if self.at_crc_delim.val() {
                    if !self.b.val() {
                        // FORM_ERROR
                        self.err_evt.next = true;
                        self.trk_q.d.next = self.s_idle.val();
                        self.rec_run.d.next = self.n4_0.val();
                    } else {
                        self.trk_q.d.next = self.s_ack.val();
                    }
                } else {
                    if self.b.val() == self.last_q.q.val() {
                        self.same_run.d.next = self.same_run.q.val() + self.n3_1.val();
                    } else {
                        self.same_run.d.next = self.n3_1.val();
                    }
                    self.last_q.d.next = self.b.val();
                    self.id_zero.d.next = self.id_zero_new.val();
                    if self.pos.q.val() == self.p12.val() {
                        self.rtr.d.next = self.b.val();
                    }
                    if self.pos.q.val() == self.p13.val() {
                        self.ide.d.next = self.b.val();
                    }
                    if (self.pos.q.val() == self.p32.val()) & self.ide.q.val() {
                        self.rtr.d.next = self.b.val();
                    }
                    if self.dlc_field.val() {
                        self.dlc.d.next = self.dlc_new.val();
                    }
                    if self.last_dlc.val() {
                        self.crc_end.d.next = self.crc_base.val() + self.data_len.val();
                    }
                    self.pos.d.next = self.pos.q.val() + self.p1.val();
                }
            } else if self.st_ack.val() {
                if self.frames_q.q.val() != self.max16.val() {
                    self.frames_q.d.next = self.frames_q.q.val() + self.one16.val();
                }
                self.trk_q.d.next = self.s_delim.val();
            } else {
                // ACK_DELIM: the ACK delimiter is the first recessive bit
                self.trk_q.d.next = self.s_idle.val();
                if self.b.val() {
                    self.rec_run.d.next = self.n4_1.val();
                } else {
                    self.rec_run.d.next = self.n4_0.val();
                }
            }
        }
        if self.err_evt.val() & (self.errors_q.q.val() != self.max16.val()) {
            self.errors_q.d.next = self.errors_q.q.val() + self.one16.val();
        }
        if self.rst.val() {
            self.trk_q.d.next = self.s_idle.val();
            self.rec_run.d.next = self.n4_0.val();
            self.pos.d.next = self.p0.val();
            self.same_run.d.next = self.n3_1.val();
            self.last_q.d.next = false;
            self.ide.d.next = false;
            self.rtr.d.next = false;
            self.dlc.d.next = self.n4_0.val();
            self.id_zero.d.next = true;
            self.crc_end.d.next = self.p127.val();
            self.frames_q.d.next = self.zero16.val();
            self.errors_q.d.next = self.zero16.val();
        }
        self.trk.next = self.trk_q.q.val();
        self.frames.next = self.frames_q.q.val();
        self.errors.next = self.errors_q.q.val();
    }
}
