//! The register behind a CAN transmit pin (or a hub's downlinks): a D flip-flop
//! whose value is recessive (all ones) from the end of FPGA configuration on,
//! before the first clock edge and whatever `rst` does.
//!
//! A node whose `tx` came out of configuration dominant would hold every other
//! node of its bus off until its first reset edge. So the flip-flops store the
//! complement of the pin (1 = dominant) and the pin is their inverse: their
//! power-up value 0 is recessive. The `initial` statement makes the 0 explicit
//! for every flow that honours initial values (yosys, Vivado, Quartus, Synplify
//! for Libero and Radiant, Verilator, Icarus); a flow that drops it still gives
//! an uninitialised flip-flop 0 on iCE40, ECP5, Xilinx 7-series and UltraScale,
//! and Intel devices without "power-up don't care". The inverter between the
//! flip-flop and the pin has one input, so it cannot glitch.

use rust_hdl::prelude::*;
use std::ops::Not;

/// A D flip-flop that reads all ones from configuration on (`q = d` one clock
/// later, like rust-hdl's `DFF`).
#[derive(LogicBlock, Default)]
pub struct RecessiveReg<T: Synth + Not<Output = T>> {
    /// The value `q` takes at the next rising edge of `clock`.
    pub d: Signal<In, T>,
    /// The registered value; all ones (recessive) until the first edge.
    pub q: Signal<Out, T>,
    /// The clock.
    pub clock: Signal<In, Clock>,
    /// The stored complement of `q` (1 = dominant), 0 at power-up.
    _dominant: T,
}

impl<T: Synth + Not<Output = T>> Logic for RecessiveReg<T> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self._dominant = !self.d.val();
        }
        self.q.next = !self._dominant;
    }

    fn connect(&mut self) {
        self.q.connect();
    }

    fn hdl(&self) -> Verilog {
        let w = T::BITS;
        let range = if w == 1 {
            String::new()
        } else {
            format!("[{}:0] ", w - 1)
        };
        Verilog::Custom(format!(
            "\
// The complement of the pin (1 = dominant): its power-up 0 is recessive.
reg {range}dominant;
initial dominant = {w}'d0;

always @(posedge clock) begin
   dominant <= ~d;
end

always @(*) begin
   q = ~dominant;
end
"
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "recessive_reg".into(),
            clock: "clock".into(),
            inputs: vec!["d".into()],
            outputs: vec!["q".into()],
        }]
    }
}
