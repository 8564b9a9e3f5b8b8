//! One sample-point decision taken one clock ahead (Fmax on the iCE40UP5K): the
//! decision is registered every clock for both bus levels the next sample point
//! can read, and the sample point only picks one of the two.
//!
//! Why this is exact: the decisions fed through here are functions of the bus
//! level at the sample point and of protocol state that changes only at SAMPLE
//! edges, at `bit_start` edges (the `tx` pin) and at reset, plus registered
//! pre-decodes of that state. The next SAMPLE edge comes at least 8 clocks
//! after a SAMPLE edge, at least 3 clocks after a `bit_start` edge and at least
//! 4 clocks after reset (timing contract §3: TSEG1 lasts at least 3 clocks), so
//! in the clock of a sample point each registered decision equals the one the
//! state of that clock gives. The pre-decodes that feed the decisions are at most
//! one register deep, so two clocks of stable state suffice.

use rust_hdl::prelude::*;

/// A decision for a dominant and for a recessive sample, registered; the value
/// in the clock of the sample point.
#[derive(LogicBlock, Default)]
pub struct SampleLookahead {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// The sample point of the current bit (one clock).
    pub sample: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    /// The decision if the next sample point reads a dominant bit.
    pub if_dominant: Signal<In, Bit>,
    /// The decision if the next sample point reads a recessive bit.
    pub if_recessive: Signal<In, Bit>,
    /// The decision in the clock of the sample point, 0 in every other clock.
    pub decision: Signal<Out, Bit>,
    dominant_q: DFF<Bit>,
    recessive_q: DFF<Bit>,
}

impl Logic for SampleLookahead {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, dominant_q, recessive_q);
        self.dominant_q.d.next = self.if_dominant.val();
        self.recessive_q.d.next = self.if_recessive.val();
        // One LUT4 after the sample point: sample, sampled and the two registers.
        if self.sampled.val() {
            self.decision.next = self.sample.val() && self.recessive_q.q.val();
        } else {
            self.decision.next = self.sample.val() && self.dominant_q.q.val();
        }
    }
}
