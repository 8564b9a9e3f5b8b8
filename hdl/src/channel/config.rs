//! Configuration registers of one channel (timing contract §6): the bit-timing
//! fields, the operating mode, the error warning limit and single-shot mode are
//! captured while `rst` is high ("reset mode", as ISO 11898-1 requires for
//! bit-timing changes) and held while running, so a configuration change during
//! operation takes effect only at the next reset.
//!
//! Illegal values are clamped here, never passed on:
//! - SJW' = min(SJW, TSEG2) (SJW may not exceed PHASE_SEG2);
//! - TSEG1' = max(TSEG1, 7 - TSEG2, M), M = 3 for BRP = 0, 2 for BRP = 1, else 1:
//!   at least the 8 tq per bit of ISO 11898-1 11.3.1, and at least 3 clocks of
//!   TSEG1 so a node reads back its own bit through the 2-clock synchronizer.
//!
//! All values use the minus-one encodings of the ports.

use crate::channel::BRP_BITS;
use rust_hdl::prelude::*;

/// Captured, clamped configuration.
#[derive(LogicBlock)]
pub struct ChannelConfig {
    // clock and reset (reset mode = capture)
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Channel reset, reset mode: while high the configuration inputs are captured.
    pub rst: Signal<In, Bit>,
    // configuration inputs
    /// Baud-rate prescaler BRP as is: a time quantum lasts `cfg_brp + 1` clocks.
    pub cfg_brp: Signal<In, Bits<BRP_BITS>>,
    /// TSEG1 (PROP_SEG + PHASE_SEG1) minus one; clamped at capture (module doc).
    pub cfg_tseg1: Signal<In, Bits<4>>,
    /// TSEG2 (PHASE_SEG2) minus one.
    pub cfg_tseg2: Signal<In, Bits<3>>,
    /// Resynchronisation jump width SJW minus one; clamped to TSEG2 at capture.
    pub cfg_sjw: Signal<In, Bits<2>>,
    /// Triple sampling, 1 = on.
    pub cfg_triple: Signal<In, Bit>,
    /// Operating mode: 0 normal, 1 listen-only, 2 self-test, 3 loop-back.
    pub cfg_mode: Signal<In, Bits<2>>,
    /// Error warning limit EWL (`err_warning`: TEC or REC at or above it).
    pub cfg_ewl: Signal<In, Bits<8>>,
    /// 1 = single shot: no automatic retransmission.
    pub cfg_single_shot: Signal<In, Bit>,
    // held configuration
    /// The BRP held from the next clock on (the input while capturing), so the
    /// prescaler can register its tick one clock ahead.
    pub brp_next: Signal<Out, Bits<BRP_BITS>>,
    /// Triple sampling as captured in reset mode.
    pub triple: Signal<Out, Bit>,
    /// Operating mode as captured (0 normal, 1 listen-only, 2 self-test, 3 loop-back).
    pub mode: Signal<Out, Bits<2>>,
    /// Error warning limit as captured.
    pub ewl: Signal<Out, Bits<8>>,
    /// Single-shot mode as captured.
    pub single_shot: Signal<Out, Bit>,
    // derived lengths in time quanta (registered, so the bit timing logic has
    // no adders on its sample-point path): TSEG1', TSEG2, SJW'
    /// TSEG1' in time quanta (1..16, not minus one): lengthened to at least 8 tq per bit and 3
    /// clocks.
    pub tseg1_len: Signal<Out, Bits<5>>,
    /// TSEG2 in time quanta (1..8).
    pub tseg2_len: Signal<Out, Bits<4>>,
    /// SJW' = min(SJW, TSEG2) in time quanta (1..4).
    pub sjw_len: Signal<Out, Bits<4>>,
    tseg1_len_q: DFF<Bits<5>>,
    tseg2_len_q: DFF<Bits<4>>,
    sjw_len_q: DFF<Bits<4>>,
    one4: Constant<Bits<4>>,
    one5: Constant<Bits<5>>,
    brp_q: DFF<Bits<BRP_BITS>>,
    triple_q: DFF<Bit>,
    mode_q: DFF<Bits<2>>,
    ewl_q: DFF<Bits<8>>,
    single_shot_q: DFF<Bit>,
    // clamping
    brp0: Signal<Local, Bit>,
    brp1: Signal<Local, Bit>,
    tseg1_low: Signal<Local, Bits<4>>,
    tseg1_low_len: Signal<Local, Bits<5>>,
    tseg1_inc: Signal<Local, Bits<5>>,
    tseg1_clamped_len: Signal<Local, Bits<5>>,
    n3_0: Constant<Bits<3>>,
    n3_1: Constant<Bits<3>>,
    n3_2: Constant<Bits<3>>,
    n3_3: Constant<Bits<3>>,
    n3_4: Constant<Bits<3>>,
    n4_3: Constant<Bits<4>>,
    n4_4: Constant<Bits<4>>,
    n5_1: Constant<Bits<5>>,
    n5_2: Constant<Bits<5>>,
    n5_3: Constant<Bits<5>>,
    n5_4: Constant<Bits<5>>,
    n5_5: Constant<Bits<5>>,
    n5_6: Constant<Bits<5>>,
    sjw_clamped: Signal<Local, Bits<2>>,
    n4_5: Constant<Bits<4>>,
    n4_0: Constant<Bits<4>>,
    n4_1: Constant<Bits<4>>,
    n4_2: Constant<Bits<4>>,
    brp_is_0: Constant<Bits<BRP_BITS>>,
    brp_is_1: Constant<Bits<BRP_BITS>>,
}

impl Default for ChannelConfig {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            cfg_brp: Default::default(),
            cfg_tseg1: Default::default(),
            cfg_tseg2: Default::default(),
            cfg_sjw: Default::default(),
            cfg_triple: Default::default(),
            cfg_mode: Default::default(),
            cfg_ewl: Default::default(),
            cfg_single_shot: Default::default(),
            brp_next: Default::default(),
            triple: Default::default(),
            mode: Default::default(),
            ewl: Default::default(),
            single_shot: Default::default(),
            tseg1_len: Default::default(),
            tseg2_len: Default::default(),
            sjw_len: Default::default(),
            tseg1_len_q: Default::default(),
            tseg2_len_q: Default::default(),
            sjw_len_q: Default::default(),
            one4: Constant::new(1.into()),
            one5: Constant::new(1.into()),
            brp_q: Default::default(),
            triple_q: Default::default(),
            mode_q: Default::default(),
            ewl_q: Default::default(),
            single_shot_q: Default::default(),
            brp0: Default::default(),
            brp1: Default::default(),
            tseg1_low: Default::default(),
            tseg1_low_len: Default::default(),
            tseg1_inc: Default::default(),
            tseg1_clamped_len: Default::default(),
            n3_0: Constant::new(0.into()),
            n3_1: Constant::new(1.into()),
            n3_2: Constant::new(2.into()),
            n3_3: Constant::new(3.into()),
            n3_4: Constant::new(4.into()),
            n4_3: Constant::new(3.into()),
            n4_4: Constant::new(4.into()),
            n5_1: Constant::new(1.into()),
            n5_2: Constant::new(2.into()),
            n5_3: Constant::new(3.into()),
            n5_4: Constant::new(4.into()),
            n5_5: Constant::new(5.into()),
            n5_6: Constant::new(6.into()),
            sjw_clamped: Default::default(),
            n4_5: Constant::new(5.into()),
            n4_0: Constant::new(0.into()),
            n4_1: Constant::new(1.into()),
            n4_2: Constant::new(2.into()),
            brp_is_0: Constant::new(0.into()),
            brp_is_1: Constant::new(1.into()),
        }
    }
}

impl Logic for ChannelConfig {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            brp_q,
            triple_q,
            mode_q,
            ewl_q,
            single_shot_q,
            tseg1_len_q,
            tseg2_len_q,
            sjw_len_q
        );
        // TSEG1' - 1 = max(TSEG1 - 1, L) with the lower bound L = max(5 - (TSEG2 - 1)
        // (8 tq per bit: TSEG1 >= 7 - TSEG2), 2 for BRP = 0 / 1 for BRP = 1 (own-bit
        // read-back: (BRP+1) * TSEG1 >= 3 clocks)). L and L + 1 are a table of the
        // inputs and TSEG1 + 1 is formed beside the comparison, so the capture path
        // has one comparator and no chained adders.
        self.brp0.next = self.cfg_brp.val() == self.brp_is_0.val();
        self.brp1.next = self.cfg_brp.val() == self.brp_is_1.val();
        if self.cfg_tseg2.val() == self.n3_0.val() {
            self.tseg1_low.next = self.n4_5.val();
            self.tseg1_low_len.next = self.n5_6.val();
        } else if self.cfg_tseg2.val() == self.n3_1.val() {
            self.tseg1_low.next = self.n4_4.val();
            self.tseg1_low_len.next = self.n5_5.val();
        } else if self.cfg_tseg2.val() == self.n3_2.val() {
            self.tseg1_low.next = self.n4_3.val();
            self.tseg1_low_len.next = self.n5_4.val();
        } else if (self.cfg_tseg2.val() == self.n3_3.val()) || self.brp0.val() {
            self.tseg1_low.next = self.n4_2.val();
            self.tseg1_low_len.next = self.n5_3.val();
        } else if self.brp1.val() || (self.cfg_tseg2.val() == self.n3_4.val()) {
            self.tseg1_low.next = self.n4_1.val();
            self.tseg1_low_len.next = self.n5_2.val();
        } else {
            self.tseg1_low.next = self.n4_0.val();
            self.tseg1_low_len.next = self.n5_1.val();
        }
        self.tseg1_inc.next = bit_cast::<5, 4>(self.cfg_tseg1.val()) + self.one5.val();
        if self.cfg_tseg1.val() < self.tseg1_low.val() {
            self.tseg1_clamped_len.next = self.tseg1_low_len.val();
        } else {
            self.tseg1_clamped_len.next = self.tseg1_inc.val();
        }
        // SJW <= TSEG2 (both minus-one encoded).
        if bit_cast::<3, 2>(self.cfg_sjw.val()) > self.cfg_tseg2.val() {
            self.sjw_clamped.next = self.cfg_tseg2.val().get_bits::<2>(0);
        } else {
            self.sjw_clamped.next = self.cfg_sjw.val();
        }
        if self.rst.val() {
            self.brp_q.d.next = self.cfg_brp.val();
            self.triple_q.d.next = self.cfg_triple.val();
            self.mode_q.d.next = self.cfg_mode.val();
            self.ewl_q.d.next = self.cfg_ewl.val();
            self.single_shot_q.d.next = self.cfg_single_shot.val();
            self.tseg1_len_q.d.next = self.tseg1_clamped_len.val();
            self.tseg2_len_q.d.next = bit_cast::<4, 3>(self.cfg_tseg2.val()) + self.one4.val();
            self.sjw_len_q.d.next = bit_cast::<4, 2>(self.sjw_clamped.val()) + self.one4.val();
        }
        if self.rst.val() {
            self.brp_next.next = self.cfg_brp.val();
        } else {
            self.brp_next.next = self.brp_q.q.val();
        }
        self.triple.next = self.triple_q.q.val();
        self.mode.next = self.mode_q.q.val();
        self.ewl.next = self.ewl_q.q.val();
        self.single_shot.next = self.single_shot_q.q.val();
        self.tseg1_len.next = self.tseg1_len_q.q.val();
        self.tseg2_len.next = self.tseg2_len_q.q.val();
        self.sjw_len.next = self.sjw_len_q.q.val();
    }
}
