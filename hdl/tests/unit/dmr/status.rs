//! Tests of `drcc_hdl::dmr::status`.

use drcc_hdl::dmr::status::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_status_synthesizes() {
    let mut uut = DmrStatus::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_status", &generate_verilog(&uut));
}
