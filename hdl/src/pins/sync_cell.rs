//! Two-flip-flop synchronizer cell for an asynchronous CAN `rx` pin (timing
//! contract §2), with the attributes that vendor tools use to recognise
//! synchronizer flip-flops: Vivado's `ASYNC_REG` (placed together, excluded from
//! retiming, MTBF analysis), Quartus's synchronizer identification, and
//! Synplify's `syn_preserve` (Libero, Radiant: not merged or optimised away).
//! yosys, Verilator and Icarus ignore them.
//!
//! Both stages take 1 (recessive) at an edge with `rst = 1`, so a reset never
//! shows a false start-of-frame edge.

use rust_hdl::prelude::*;

/// `q` is `d` two rising edges of `clock` later; 1 after an edge with `rst`.
#[derive(LogicBlock, Default)]
pub struct SyncCell {
    /// The clock.
    pub clock: Signal<In, Clock>,
    /// Synchronous reset: both stages take 1 (recessive).
    pub rst: Signal<In, Bit>,
    /// The asynchronous input (the `rx` pin).
    pub d: Signal<In, Bit>,
    /// The synchronized value.
    pub q: Signal<Out, Bit>,
    /// First stage (may go metastable).
    _meta: bool,
    /// Second stage.
    _sync: bool,
}

impl Logic for SyncCell {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            let rst = self.rst.val();
            self._sync = rst || self._meta;
            self._meta = rst || self.d.val();
        }
        self.q.next = self._sync;
    }

    fn connect(&mut self) {
        self.q.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(
            "\
// Synchronizer flip-flops (see the attributes): meta may go metastable.
(* ASYNC_REG = \"TRUE\", altera_attribute = \"-name SYNCHRONIZER_IDENTIFICATION FORCED\", syn_preserve = 1 *)
reg meta;
(* ASYNC_REG = \"TRUE\", altera_attribute = \"-name SYNCHRONIZER_IDENTIFICATION FORCED\", syn_preserve = 1 *)
reg sync;

always @(posedge clock) begin
   meta <= rst | d;
   sync <= rst | meta;
end

always @(*) begin
   q = sync;
end
"
            .into(),
        )
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "sync_cell".into(),
            clock: "clock".into(),
            inputs: vec!["d".into(), "rst".into()],
            outputs: vec!["q".into()],
        }]
    }
}
