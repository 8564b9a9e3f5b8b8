//! Tests of `drcc_hdl::host::wishbone`.

use drcc_hdl::host::wishbone::*;
use rust_hdl::prelude::*;

#[test]
fn wb_regs_synthesizes() {
    let mut uut = WbRegs::default();
    uut.connect_all();
    crate::synth_check::yosys_check("wb_regs", &generate_verilog(&uut));
}
