//! Tests of `drcc_hdl::host::dmr_check`.

use drcc_hdl::host::dmr_check::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_check_synthesizes() {
    let mut uut = DmrCheck::<16>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_check", &generate_verilog(&uut));
}
