//! `STATS1` of the DRCC (contract §3, §4.3, §5): the channel switches of the main
//! FSM and the recoveries of both auxiliary FSMs, 16-bit saturating counters
//! cleared only by `rst` (the top ORs in `STATS_CLR`, DRCC contract §11.4).

use rust_hdl::prelude::*;

/// The redundancy statistics.
#[derive(LogicBlock)]
pub struct RedundancyStats {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: both counts to 0 (reset mode keeps them).
    pub rst: Signal<In, Bit>,
    /// One clock: the main FSM switched channel (`failover` changed, §4.3).
    pub switch_evt: Signal<In, Bit>,
    /// One clock: aux FSM A recovered its channel (§5).
    pub recover_a: Signal<In, Bit>,
    /// One clock: aux FSM B recovered its channel.
    pub recover_b: Signal<In, Bit>,
    /// `STATS1.switches` (saturating).
    pub switches: Signal<Out, Bits<16>>,
    /// `STATS1.recoveries`, both channels (saturating; two at one edge count 2).
    pub recoveries: Signal<Out, Bits<16>>,
    switches_q: DFF<Bits<16>>,
    recov_q: DFF<Bits<16>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    two16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
    max16m1: Constant<Bits<16>>,
}

impl Default for RedundancyStats {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            switch_evt: Default::default(),
            recover_a: Default::default(),
            recover_b: Default::default(),
            switches: Default::default(),
            recoveries: Default::default(),
            switches_q: Default::default(),
            recov_q: Default::default(),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            two16: Constant::new(2.into()),
            max16: Constant::new(0xFFFF.into()),
            max16m1: Constant::new(0xFFFE.into()),
        }
    }
}

impl Logic for RedundancyStats {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, switches_q, recov_q);
        if self.switch_evt.val() & (self.switches_q.q.val() != self.max16.val()) {
            self.switches_q.d.next = self.switches_q.q.val() + self.one16.val();
        }
        if self.recover_a.val() & self.recover_b.val() {
            if self.recov_q.q.val() >= self.max16m1.val() {
                self.recov_q.d.next = self.max16.val();
            } else {
                self.recov_q.d.next = self.recov_q.q.val() + self.two16.val();
            }
        } else if (self.recover_a.val() | self.recover_b.val())
            & (self.recov_q.q.val() != self.max16.val())
        {
            self.recov_q.d.next = self.recov_q.q.val() + self.one16.val();
        }
        if self.rst.val() {
            self.switches_q.d.next = self.zero16.val();
            self.recov_q.d.next = self.zero16.val();
        }
        self.switches.next = self.switches_q.q.val();
        self.recoveries.next = self.recov_q.q.val();
    }
}
