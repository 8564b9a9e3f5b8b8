//! The DMR reception statistics (DMR contract §2.1 `DMR_RX_STATS`, §8):
//! `pcl_frames` (16 bits), `released` and `expired` (8 bits), each saturating
//! and cleared only by `rst`, like the other statistics.

use rust_hdl::prelude::*;

/// Saturating `DMR_RX_STATS` counters.
#[derive(LogicBlock)]
pub struct DmrRxStats {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst`: the counts clear (reset mode keeps them).
    pub rst: Signal<In, Bit>,
    // ---- events at this edge ----
    /// A frame of the passive line was taken (`DECIDE` with `pcl`).
    pub pcl_inc: Signal<In, Bit>,
    /// A waiting frame was released to the FIFO (`RELEASE`).
    pub released_inc: Signal<In, Bit>,
    /// An undelivered, unmatched history entry expired.
    pub expired_inc: Signal<In, Bit>,
    // ---- counts ----
    /// `DMR_RX_STATS[15:0]`.
    pub pcl_frames: Signal<Out, Bits<16>>,
    /// `DMR_RX_STATS[23:16]`.
    pub released: Signal<Out, Bits<8>>,
    /// `DMR_RX_STATS[31:24]`.
    pub expired: Signal<Out, Bits<8>>,
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

impl Default for DmrRxStats {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            pcl_inc: Default::default(),
            released_inc: Default::default(),
            expired_inc: Default::default(),
            pcl_frames: Default::default(),
            released: Default::default(),
            expired: Default::default(),
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

impl Logic for DmrRxStats {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, pcl_q, released_q, expired_q);
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
            self.pcl_q.d.next = self.zero16.val();
            self.released_q.d.next = self.zero8.val();
            self.expired_q.d.next = self.zero8.val();
        }
        self.pcl_frames.next = self.pcl_q.q.val();
        self.released.next = self.released_q.q.val();
        self.expired.next = self.expired_q.q.val();
    }
}

#[test]
fn dmr_rx_stats_synthesizes() {
    let mut uut = DmrRxStats::default();
    uut.connect_all();
    yosys_validate("dmr_rx_stats", &generate_verilog(&uut)).unwrap();
}
