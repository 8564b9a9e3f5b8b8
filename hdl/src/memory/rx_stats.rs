//! The receive statistics of the RX writer (`super::dedup`), each saturating and
//! cleared only by `rst` or `STATS_CLR` (§11.4; reset mode keeps them): `STATS0` (duplicates dropped,
//! RX overruns; DRCC contract §7), `OMISSIONS` (per channel, history entries
//! of the other channel that expired without a copy; §7) and `DMR_RX_STATS`
//! (`pcl_frames` 16 bits, `released` and `expired` 8 bits; DMR contract §2.1,
//! §8). The writer raises one strobe per event, valid in the clock of its edge.

use rust_hdl::prelude::*;

/// Saturating receive statistics.
#[derive(LogicBlock)]
pub struct RxStats {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst`: the counts clear (reset mode keeps them).
    pub rst: Signal<In, Bit>,
    // ---- events at this edge ----
    /// A duplicate was dropped (`decide` with `hit`).
    pub dup_inc: Signal<In, Bit>,
    /// A frame was dropped because the RX FIFO was full.
    pub overrun_inc: Signal<In, Bit>,
    /// An omission of channel A: an entry of channel B expired without a copy.
    pub omit_a: Signal<In, Bit>,
    /// An omission of channel B: an entry of channel A expired without a copy.
    pub omit_b: Signal<In, Bit>,
    /// A frame of the passive line was taken (`DECIDE` with `pcl`).
    pub pcl_inc: Signal<In, Bit>,
    /// A waiting frame was released to the FIFO (`RELEASE`).
    pub released_inc: Signal<In, Bit>,
    /// An undelivered, unmatched history entry expired.
    pub expired_inc: Signal<In, Bit>,
    // ---- counts ----
    /// `STATS0[15:0]`.
    pub duplicates: Signal<Out, Bits<16>>,
    /// `STATS0[31:16]`.
    pub overruns: Signal<Out, Bits<16>>,
    /// `OMISSIONS[15:0]`.
    pub omissions_a: Signal<Out, Bits<16>>,
    /// `OMISSIONS[31:16]`.
    pub omissions_b: Signal<Out, Bits<16>>,
    /// `DMR_RX_STATS[15:0]`.
    pub pcl_frames: Signal<Out, Bits<16>>,
    /// `DMR_RX_STATS[23:16]`.
    pub released: Signal<Out, Bits<8>>,
    /// `DMR_RX_STATS[31:24]`.
    pub expired: Signal<Out, Bits<8>>,
    dups_q: DFF<Bits<16>>,
    overruns_q: DFF<Bits<16>>,
    omit_a_q: DFF<Bits<16>>,
    omit_b_q: DFF<Bits<16>>,
    pcl_q: DFF<Bits<16>>,
    released_q: DFF<Bits<8>>,
    expired_q: DFF<Bits<8>>,
    one8: Constant<Bits<8>>,
    max8: Constant<Bits<8>>,
    zero8: Constant<Bits<8>>,
    one16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
}

impl Default for RxStats {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            dup_inc: Default::default(),
            overrun_inc: Default::default(),
            omit_a: Default::default(),
            omit_b: Default::default(),
            pcl_inc: Default::default(),
            released_inc: Default::default(),
            expired_inc: Default::default(),
            duplicates: Default::default(),
            overruns: Default::default(),
            omissions_a: Default::default(),
            omissions_b: Default::default(),
            pcl_frames: Default::default(),
            released: Default::default(),
            expired: Default::default(),
            dups_q: Default::default(),
            overruns_q: Default::default(),
            omit_a_q: Default::default(),
            omit_b_q: Default::default(),
            pcl_q: Default::default(),
            released_q: Default::default(),
            expired_q: Default::default(),
            one8: Constant::new(1.into()),
            max8: Constant::new(0xFF.into()),
            zero8: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            max16: Constant::new(0xFFFF.into()),
            zero16: Constant::new(0.into()),
        }
    }
}

impl Logic for RxStats {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, dups_q, overruns_q, omit_a_q, omit_b_q, pcl_q, released_q, expired_q);
        self.dups_q.d.next = self.dups_q.q.val();
        if self.dup_inc.val() & (self.dups_q.q.val() != self.max16.val()) {
            self.dups_q.d.next = self.dups_q.q.val() + self.one16.val();
        }
        self.overruns_q.d.next = self.overruns_q.q.val();
        if self.overrun_inc.val() & (self.overruns_q.q.val() != self.max16.val()) {
            self.overruns_q.d.next = self.overruns_q.q.val() + self.one16.val();
        }
        self.omit_a_q.d.next = self.omit_a_q.q.val();
        if self.omit_a.val() & (self.omit_a_q.q.val() != self.max16.val()) {
            self.omit_a_q.d.next = self.omit_a_q.q.val() + self.one16.val();
        }
        self.omit_b_q.d.next = self.omit_b_q.q.val();
        if self.omit_b.val() & (self.omit_b_q.q.val() != self.max16.val()) {
            self.omit_b_q.d.next = self.omit_b_q.q.val() + self.one16.val();
        }
        self.pcl_q.d.next = self.pcl_q.q.val();
        if self.pcl_inc.val() & (self.pcl_q.q.val() != self.max16.val()) {
            self.pcl_q.d.next = self.pcl_q.q.val() + self.one16.val();
        }
        self.released_q.d.next = self.released_q.q.val();
        if self.released_inc.val() & (self.released_q.q.val() != self.max8.val()) {
            self.released_q.d.next = self.released_q.q.val() + self.one8.val();
        }
        self.expired_q.d.next = self.expired_q.q.val();
        if self.expired_inc.val() & (self.expired_q.q.val() != self.max8.val()) {
            self.expired_q.d.next = self.expired_q.q.val() + self.one8.val();
        }
        if self.rst.val() {
            self.dups_q.d.next = self.zero16.val();
            self.overruns_q.d.next = self.zero16.val();
            self.omit_a_q.d.next = self.zero16.val();
            self.omit_b_q.d.next = self.zero16.val();
            self.pcl_q.d.next = self.zero16.val();
            self.released_q.d.next = self.zero8.val();
            self.expired_q.d.next = self.zero8.val();
        }
        self.duplicates.next = self.dups_q.q.val();
        self.overruns.next = self.overruns_q.q.val();
        self.omissions_a.next = self.omit_a_q.q.val();
        self.omissions_b.next = self.omit_b_q.q.val();
        self.pcl_frames.next = self.pcl_q.q.val();
        self.released.next = self.released_q.q.val();
        self.expired.next = self.expired_q.q.val();
    }
}
