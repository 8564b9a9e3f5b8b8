//! Tests of `drcc_hdl::channel::bsp::error_decision`.

use drcc_hdl::channel::bsp::error_decision::*;
use rust_hdl::prelude::*;

#[test]
fn error_decision_synthesizes() {
    let mut uut = ErrorDecision::default();
    uut.connect_all();
    crate::synth_check::yosys_check("error_decision", &generate_verilog(&uut));
}
