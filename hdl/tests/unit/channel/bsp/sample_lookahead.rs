//! Tests of `drcc_hdl::channel::bsp::sample_lookahead`.

use drcc_hdl::channel::bsp::sample_lookahead::*;
use rust_hdl::prelude::*;

#[test]
fn sample_lookahead_synthesizes() {
    let mut uut = SampleLookahead::default();
    uut.connect_all();
    crate::synth_check::yosys_check("sample_lookahead", &generate_verilog(&uut));
}
