//! Tests of `drcc_hdl::channel::bsp::fault_confinement`.

use drcc_hdl::channel::bsp::fault_confinement::*;
use rust_hdl::prelude::*;

#[test]
fn fault_confinement_synthesizes() {
    let mut uut = FaultConfinement::default();
    uut.connect_all();
    crate::synth_check::yosys_check("fault_confinement", &generate_verilog(&uut));
}
