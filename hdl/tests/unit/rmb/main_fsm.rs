//! Tests of `drcc_hdl::rmb::main_fsm`.

use drcc_hdl::rmb::main_fsm::*;
use rust_hdl::prelude::*;

#[test]
fn main_fsm_synthesizes() {
    let mut uut = MainFsm::default();
    uut.connect_all();
    crate::synth_check::yosys_check("main_fsm", &generate_verilog(&uut));
}
