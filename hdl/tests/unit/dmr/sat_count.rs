//! Tests of `drcc_hdl::dmr::sat_count`.

use drcc_hdl::dmr::sat_count::*;
use rust_hdl::prelude::*;

#[test]
fn sat_count8_saturates() {
    let mut uut = SatCount8::default();
    uut.connect_all();
    uut.clk.next = Clock::from(false);
    uut.rst.next = true;
    for cycle in 0..300 {
        uut.clk.next = Clock::from(false);
        uut.inc.next = true;
        assert!(simulate(&mut uut, 50));
        uut.clk.next = Clock::from(true);
        assert!(simulate(&mut uut, 50));
        uut.rst.next = false;
        // 255 is the largest value of the field (§2.1 "saturating 255")
        let want = if cycle == 0 { 0 } else { cycle.min(255) };
        assert_eq!(
            uut.count.val(),
            Bits::<8>::from(want as u64),
            "cycle {cycle}"
        );
    }
}

#[test]
fn sat_count8_synthesizes() {
    let mut uut = SatCount8::default();
    uut.connect_all();
    crate::synth_check::yosys_check("sat_count8", &generate_verilog(&uut));
}
