//! An 8-bit saturating event counter (DMR contract §2.1: `state_changes`,
//! `acl_switches` and the four `DMR_CS_COUNT` fields stop at 255), cleared only by
//! `rst` like the other statistics.

use rust_hdl::prelude::*;

/// Saturating 8-bit count of one-clock events.
#[derive(LogicBlock)]
pub struct SatCount8 {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: the count to 0.
    pub rst: Signal<In, Bit>,
    /// One event at this edge.
    pub inc: Signal<In, Bit>,
    /// The count (stays at 255).
    pub count: Signal<Out, Bits<8>>,
    /// The count register.
    pub count_q: DFF<Bits<8>>,
    one8: Constant<Bits<8>>,
    max8: Constant<Bits<8>>,
    zero8: Constant<Bits<8>>,
}

impl Default for SatCount8 {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inc: Default::default(),
            count: Default::default(),
            count_q: Default::default(),
            one8: Constant::new(1.into()),
            max8: Constant::new(0xFF.into()),
            zero8: Constant::new(0.into()),
        }
    }
}

impl Logic for SatCount8 {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, count_q);
        if self.inc.val() & (self.count_q.q.val() != self.max8.val()) {
            self.count_q.d.next = self.count_q.q.val() + self.one8.val();
        }
        if self.rst.val() {
            self.count_q.d.next = self.zero8.val();
        }
        self.count.next = self.count_q.q.val();
    }
}
