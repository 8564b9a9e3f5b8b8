//! Tests of `drcc_hdl::dmr::control`.

use drcc_hdl::dmr::control::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_control_synthesizes() {
    let mut uut = DmrControl::default();
    uut.connect_all();
    let v = generate_verilog(&uut);
    // for the area report and the Verilator lint: DRCC_DMR_CONTROL_V=<file>
    if let Ok(path) = std::env::var("DRCC_DMR_CONTROL_V") {
        std::fs::write(path, &v).unwrap();
    }
    crate::synth_check::yosys_check("dmr_control", &v);
}
