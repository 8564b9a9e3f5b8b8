//! Tests of `drcc_hdl::rmb::aux_fsm`.

use drcc_hdl::rmb::aux_fsm::*;
use rust_hdl::prelude::*;

#[test]
fn aux_fsm_synthesizes() {
    let mut uut = AuxFsm::default();
    uut.connect_all();
    crate::synth_check::yosys_check("aux_fsm", &generate_verilog(&uut));
}
