//! The channels' error and arbitration-lost captures as the host reads them
//! (DRCC contract §10.2): `CAP_A` / `CAP_B` hold the first error and the first
//! lost arbitration of their channel since the host acknowledged the matching
//! interrupt (the SJA1000 keeps its ECC and ALC that way), and the three
//! interrupt events of §10.2 (`err_warning`, `arb_lost`, `bus_error`).
//!
//! The channels load their own capture outputs at the edge where they raise
//! `err_valid` / `arb_lost` (timing contract §9), so the values seen beside the
//! pulse are the event's. A re-arm (a taken `INT_STATUS` write with the bit set)
//! clears both channels' valid flags; a capture at the same edge wins.

use super::map::lsb;
use super::registers::MAP;
use crate::channel::bsp::field::Field;
use rust_hdl::prelude::*;

/// `CAP_A`, `CAP_B` and the §10.2 interrupt events.
#[derive(LogicBlock)]
pub struct Captures {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: both captures empty (reset mode keeps them).
    pub rst: Signal<In, Bit>,
    // ---- channel A's capture outputs (timing contract §9) ----
    /// Channel A: one-clock pulse, an error was detected (`err_*` hold it).
    pub err_valid_a: Signal<In, Bit>,
    /// Channel A: kind of the error, 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK.
    pub err_kind_a: Signal<In, Bits<3>>,
    /// Channel A: field of the bit in error.
    pub err_field_a: Signal<In, Field>,
    /// Channel A: transmitter at the error.
    pub err_tx_a: Signal<In, Bit>,
    /// Channel A: one-clock pulse, arbitration lost (`alc_a` holds the position).
    pub arb_lost_a: Signal<In, Bit>,
    /// Channel A: arbitration-lost position.
    pub alc_a: Signal<In, Bits<5>>,
    /// Channel A: TEC or REC at or above the error warning limit.
    pub ew_a: Signal<In, Bit>,
    // ---- channel B's capture outputs (timing contract §9) ----
    /// Channel B: one-clock pulse, an error was detected (`err_*` hold it).
    pub err_valid_b: Signal<In, Bit>,
    /// Channel B: kind of the error, 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK.
    pub err_kind_b: Signal<In, Bits<3>>,
    /// Channel B: field of the bit in error.
    pub err_field_b: Signal<In, Field>,
    /// Channel B: transmitter at the error.
    pub err_tx_b: Signal<In, Bit>,
    /// Channel B: one-clock pulse, arbitration lost (`alc_b` holds the position).
    pub arb_lost_b: Signal<In, Bit>,
    /// Channel B: arbitration-lost position.
    pub alc_b: Signal<In, Bits<5>>,
    /// Channel B: TEC or REC at or above the error warning limit.
    pub ew_b: Signal<In, Bit>,
    // ---- from the register block ----
    /// A taken `INT_STATUS` write with `bus_error` set: the error captures re-arm.
    pub rearm_err: Signal<In, Bit>,
    /// A taken `INT_STATUS` write with `arb_lost` set: the ALC captures re-arm.
    pub rearm_alc: Signal<In, Bit>,
    /// A host view's load of `CAP_A` (bit 0) or `CAP_B` (bit 1): both captures
    /// of that channel re-arm (PeliCAN contract P-X-3; 0 in the native top).
    pub rearm_chan: Signal<In, Bits<2>>,
    // ---- to the host ----
    /// `CAP_A` as it reads.
    pub cap_a: Signal<Out, Bits<32>>,
    /// `CAP_B` as it reads.
    pub cap_b: Signal<Out, Bits<32>>,
    /// `INT_STATUS.err_warning` event: a channel's warning flag changed.
    pub ev_err_warning: Signal<Out, Bit>,
    /// `INT_STATUS.arb_lost` event.
    pub ev_arb_lost: Signal<Out, Bit>,
    /// `INT_STATUS.bus_error` event.
    pub ev_bus_error: Signal<Out, Bit>,
    // ---- registers: {valid, tx, field, kind} and {valid, alc} per channel ----
    err_a: DFF<Bits<10>>,
    err_b: DFF<Bits<10>>,
    alc_a_q: DFF<Bits<6>>,
    alc_b_q: DFF<Bits<6>>,
    ew_a_prev: DFF<Bit>,
    ew_b_prev: DFF<Bit>,
    // ---- the re-arm of each capture ----
    rearm_err_a: Signal<Local, Bit>,
    rearm_err_b: Signal<Local, Bit>,
    rearm_alc_a: Signal<Local, Bit>,
    rearm_alc_b: Signal<Local, Bit>,
    // ---- field positions (from the table) ----
    at_err: Constant<Bits<5>>,
    at_alc: Constant<Bits<5>>,
    zero6: Constant<Bits<6>>,
    zero10: Constant<Bits<10>>,
    /// A re-arm keeps the error fields and clears `err_valid` (bit 9).
    keep_err: Constant<Bits<10>>,
    /// A re-arm keeps `alc` and clears `alc_valid` (bit 5).
    keep_alc: Constant<Bits<6>>,
}

impl Default for Captures {
    fn default() -> Self {
        // the RTL keeps err_kind, err_field, err_tx, err_valid adjacent from
        // `err_kind` and alc, alc_valid adjacent from `alc`
        let first = MAP.field("CAP_A", "err_kind").lsb;
        for (name, off, width) in [
            ("err_kind", 0, 3),
            ("err_field", 3, 5),
            ("err_tx", 8, 1),
            ("err_valid", 9, 1),
        ] {
            super::map::placed(&MAP, "CAP_A", name, first + off, width);
            super::map::placed(&MAP, "CAP_B", name, first + off, width);
        }
        let alc = MAP.field("CAP_A", "alc").lsb;
        for reg in ["CAP_A", "CAP_B"] {
            super::map::placed(&MAP, reg, "alc", alc, 5);
            super::map::placed(&MAP, reg, "alc_valid", alc + 5, 1);
        }
        Self {
            clk: Default::default(),
            rst: Default::default(),
            err_valid_a: Default::default(),
            err_kind_a: Default::default(),
            err_field_a: Default::default(),
            err_tx_a: Default::default(),
            arb_lost_a: Default::default(),
            alc_a: Default::default(),
            ew_a: Default::default(),
            err_valid_b: Default::default(),
            err_kind_b: Default::default(),
            err_field_b: Default::default(),
            err_tx_b: Default::default(),
            arb_lost_b: Default::default(),
            alc_b: Default::default(),
            ew_b: Default::default(),
            rearm_err: Default::default(),
            rearm_alc: Default::default(),
            rearm_chan: Default::default(),
            cap_a: Default::default(),
            cap_b: Default::default(),
            ev_err_warning: Default::default(),
            ev_arb_lost: Default::default(),
            ev_bus_error: Default::default(),
            err_a: Default::default(),
            err_b: Default::default(),
            alc_a_q: Default::default(),
            alc_b_q: Default::default(),
            ew_a_prev: Default::default(),
            ew_b_prev: Default::default(),
            rearm_err_a: Default::default(),
            rearm_err_b: Default::default(),
            rearm_alc_a: Default::default(),
            rearm_alc_b: Default::default(),
            at_err: lsb(&MAP, "CAP_A", "err_kind", 3),
            at_alc: lsb(&MAP, "CAP_A", "alc", 5),
            zero6: Constant::new(0.into()),
            zero10: Constant::new(0.into()),
            keep_err: Constant::new(0x1FF.into()),
            keep_alc: Constant::new(0x1F.into()),
        }
    }
}

impl Logic for Captures {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, err_a, err_b, alc_a_q, alc_b_q, ew_a_prev, ew_b_prev);
        // §10.2: a capture while empty, or re-armed at this edge, loads the event;
        // a re-arm alone empties the capture
        self.rearm_err_a.next = self.rearm_err.val() | self.rearm_chan.val().get_bit(0);
        self.rearm_err_b.next = self.rearm_err.val() | self.rearm_chan.val().get_bit(1);
        self.rearm_alc_a.next = self.rearm_alc.val() | self.rearm_chan.val().get_bit(0);
        self.rearm_alc_b.next = self.rearm_alc.val() | self.rearm_chan.val().get_bit(1);
        if self.err_valid_a.val() & (!self.err_a.q.val().get_bit(9) | self.rearm_err_a.val()) {
            self.err_a.d.next = bit_cast::<10, 3>(self.err_kind_a.val())
                | (bit_cast::<10, 5>(self.err_field_a.val().into()) << 3)
                | (bit_cast::<10, 1>(self.err_tx_a.val().into()) << 8)
                | (bit_cast::<10, 1>(true.into()) << 9);
        } else if self.rearm_err_a.val() {
            self.err_a.d.next = self.err_a.q.val() & self.keep_err.val();
        }
        if self.err_valid_b.val() & (!self.err_b.q.val().get_bit(9) | self.rearm_err_b.val()) {
            self.err_b.d.next = bit_cast::<10, 3>(self.err_kind_b.val())
                | (bit_cast::<10, 5>(self.err_field_b.val().into()) << 3)
                | (bit_cast::<10, 1>(self.err_tx_b.val().into()) << 8)
                | (bit_cast::<10, 1>(true.into()) << 9);
        } else if self.rearm_err_b.val() {
            self.err_b.d.next = self.err_b.q.val() & self.keep_err.val();
        }
        if self.arb_lost_a.val() & (!self.alc_a_q.q.val().get_bit(5) | self.rearm_alc_a.val()) {
            self.alc_a_q.d.next =
                bit_cast::<6, 5>(self.alc_a.val()) | (bit_cast::<6, 1>(true.into()) << 5);
        } else if self.rearm_alc_a.val() {
            self.alc_a_q.d.next = self.alc_a_q.q.val() & self.keep_alc.val();
        }
        if self.arb_lost_b.val() & (!self.alc_b_q.q.val().get_bit(5) | self.rearm_alc_b.val()) {
            self.alc_b_q.d.next =
                bit_cast::<6, 5>(self.alc_b.val()) | (bit_cast::<6, 1>(true.into()) << 5);
        } else if self.rearm_alc_b.val() {
            self.alc_b_q.d.next = self.alc_b_q.q.val() & self.keep_alc.val();
        }
        self.ew_a_prev.d.next = self.ew_a.val();
        self.ew_b_prev.d.next = self.ew_b.val();
        if self.rst.val() {
            self.err_a.d.next = self.zero10.val();
            self.err_b.d.next = self.zero10.val();
            self.alc_a_q.d.next = self.zero6.val();
            self.alc_b_q.d.next = self.zero6.val();
            self.ew_a_prev.d.next = false;
            self.ew_b_prev.d.next = false;
        }
        // ---- events (§8, §10.2) ----
        self.ev_err_warning.next = (self.ew_a.val() != self.ew_a_prev.q.val())
            | (self.ew_b.val() != self.ew_b_prev.q.val());
        self.ev_arb_lost.next = self.arb_lost_a.val() | self.arb_lost_b.val();
        self.ev_bus_error.next = self.err_valid_a.val() | self.err_valid_b.val();
        // ---- the words ----
        self.cap_a.next = (bit_cast::<32, 10>(self.err_a.q.val()) << self.at_err.val())
            | (bit_cast::<32, 6>(self.alc_a_q.q.val()) << self.at_alc.val());
        self.cap_b.next = (bit_cast::<32, 10>(self.err_b.q.val()) << self.at_err.val())
            | (bit_cast::<32, 6>(self.alc_b_q.q.val()) << self.at_alc.val());
    }
}
