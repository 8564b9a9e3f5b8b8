//! Tests of `drcc_hdl::channel::bsp::protocol`.

use drcc_hdl::channel::bsp::protocol::*;
use rust_hdl::prelude::*;

#[test]
fn protocol_controller_synthesizes() {
    let mut uut: ProtocolController = ProtocolController::default();
    uut.connect_all();
    crate::synth_check::yosys_check("protocol_controller", &generate_verilog(&uut));
}
