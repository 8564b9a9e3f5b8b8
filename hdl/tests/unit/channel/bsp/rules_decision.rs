//! Tests of `drcc_hdl::channel::bsp::rules_decision`.

use drcc_hdl::channel::bsp::rules_decision::*;
use rust_hdl::prelude::*;

#[test]
fn rules_decision_synthesizes() {
    let mut uut = RulesDecision::default();
    uut.connect_all();
    crate::synth_check::yosys_check("rules_decision", &generate_verilog(&uut));
}
