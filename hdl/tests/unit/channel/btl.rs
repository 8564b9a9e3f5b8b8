//! Tests of `drcc_hdl::channel::btl`.

use drcc_hdl::channel::btl::*;
use rust_hdl::prelude::*;

#[test]
fn btl_synthesizes() {
    let mut uut = BitTimingLogic::default();
    uut.connect_all();
    crate::synth_check::yosys_check("bit_timing_logic", &generate_verilog(&uut));
}
