//! Tests of `drcc_hdl::hub::guard_stage`.

use drcc_hdl::hub::guard_stage::*;
use rust_hdl::prelude::*;

#[test]
fn guard_stage_synthesizes() {
    let mut uut = GuardStage::<4, 2>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_guard_stage", &generate_verilog(&uut));
}
