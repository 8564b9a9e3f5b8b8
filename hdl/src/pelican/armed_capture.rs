//! One SJA1000 capture register with its re-arm (pelican_contract.md P-CAP-1,
//! P-CAP-2, P-CAP-3; SJA1000 data sheet 6.4.8 "arbitration lost capture", 6.4.9
//! "error code capture"): the first event after the register was read loads
//! it, later events leave it alone until the host reads it again. The view has
//! two: `ALC` (event `arb_lost`) and `ECC` (event `err_valid`).
//!
//! At an edge with `pulse` while armed: the register takes `value` and
//! disarms. A read of the register taken at an edge re-arms it at that edge;
//! an event at the same edge wins (it loads and stays disarmed). `rst` clears
//! the register and arms it; the view's reset mode changes neither.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// A capture register loaded by the first event after each read.
#[derive(LogicBlock, Default)]
pub struct ArmedCapture {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: the register 0, armed.
    pub rst: Signal<In, Bit>,
    // ---- the channel's event ----
    /// The channel's event pulse of this clock (`event` is a SystemVerilog keyword).
    pub pulse: Signal<In, Bit>,
    /// The value to capture with it.
    pub value: Signal<In, Bits<8>>,
    // ---- the host ----
    /// A read of the register is taken at this edge.
    pub read: Signal<In, Bit>,
    /// The register as the host reads it.
    pub q: Signal<Out, Bits<8>>,
    // ---- registers ----
    /// The captured byte.
    capture: DFF<Bits<8>>,
    /// The next event loads the register.
    armed: DFF<Bit>,
    zero8: Const<8, 0>,
}

impl Logic for ArmedCapture {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, capture, armed);
        if self.pulse.val() && self.armed.q.val() {
            self.capture.d.next = self.value.val();
            self.armed.d.next = false;
        } else if self.read.val() {
            self.armed.d.next = true;
        }
        self.q.next = self.capture.q.val();
        if self.rst.val() {
            self.capture.d.next = self.zero8.val();
            self.armed.d.next = true;
        }
    }
}
