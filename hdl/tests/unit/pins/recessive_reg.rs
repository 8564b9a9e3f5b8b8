//! Tests of `drcc_hdl::pins::recessive_reg`.

use drcc_hdl::pins::recessive_reg::*;
use rust_hdl::prelude::*;
use std::ops::Not;

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
