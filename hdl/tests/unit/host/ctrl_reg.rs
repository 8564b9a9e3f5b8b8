//! Tests of `drcc_hdl::host::ctrl_reg`.

use drcc_hdl::host::ctrl_reg::*;
use rust_hdl::prelude::*;

#[test]
fn ctrl_reg_synthesizes() {
    let mut uut = CtrlReg::default();
    uut.connect_all();
    crate::synth_check::yosys_check("ctrl_reg", &generate_verilog(&uut));
}
