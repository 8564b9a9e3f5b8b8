//! Tests of `drcc_hdl::hub::port_guard`.

use drcc_hdl::hub::port_guard::*;
use rust_hdl::prelude::*;

#[test]
fn port_guard_synthesizes() {
    let mut uut = PortGuard::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_port_guard", &generate_verilog(&uut));
}
