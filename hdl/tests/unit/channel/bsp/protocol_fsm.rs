//! Tests of `drcc_hdl::channel::bsp::protocol_fsm`.

use drcc_hdl::channel::bsp::protocol_fsm::*;
use rust_hdl::prelude::*;

#[test]
fn protocol_fsm_synthesizes() {
    let mut uut = ProtocolFsm::default();
    uut.connect_all();
    crate::synth_check::yosys_check("protocol_fsm", &generate_verilog(&uut));
}
