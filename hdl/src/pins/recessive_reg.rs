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

#[cfg(test)]
mod tests {
    use super::*;

    fn edge<T: Synth + Not<Output = T>>(uut: &mut RecessiveReg<T>) {
        uut.clock.next = Clock { clk: true };
        assert!(simulate(uut, 100));
        uut.clock.next = Clock { clk: false };
        assert!(simulate(uut, 100));
    }

    /// Recessive before any edge, then `q = d` one edge later, for both values.
    #[test]
    fn recessive_until_the_first_edge_then_follows_d() {
        let mut uut = RecessiveReg::<Bit>::default();
        uut.connect_all();
        assert!(simulate(&mut uut, 100));
        assert!(uut.q.val(), "recessive before any clock edge");
        uut.d.next = false;
        assert!(simulate(&mut uut, 100));
        assert!(uut.q.val(), "d alone does not change q");
        edge(&mut uut);
        assert!(!uut.q.val(), "dominant one edge after d = 0");
        uut.d.next = true;
        edge(&mut uut);
        assert!(uut.q.val());
    }

    /// A vector register is all ones before any edge.
    #[test]
    fn a_vector_is_all_ones_before_any_edge() {
        let mut uut = RecessiveReg::<Bits<4>>::default();
        uut.connect_all();
        assert!(simulate(&mut uut, 100));
        assert_eq!(uut.q.val(), Bits::<4>::from(0xF));
        uut.d.next = 0x5.into();
        edge(&mut uut);
        assert_eq!(uut.q.val(), Bits::<4>::from(0x5));
    }

    #[test]
    fn recessive_reg_synthesizes() {
        let mut uut = RecessiveReg::<Bits<3>>::default();
        uut.connect_all();
        crate::synth_check::yosys_check("recessive_reg", &generate_verilog(&uut));
    }
}
