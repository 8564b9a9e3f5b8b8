//! Tests of `drcc_hdl::host::dmr_regs`.

use drcc_hdl::host::dmr_regs::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_regs_synthesizes() {
    let mut uut = DmrRegs::<16>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_regs", &generate_verilog(&uut));
}
