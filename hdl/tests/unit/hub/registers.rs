//! Tests of `drcc_hdl::hub::registers`.

use drcc_hdl::hub::registers::*;
use rust_hdl::prelude::*;

#[test]
fn hub_regs_synthesizes() {
    let mut uut = HubRegs::<4, 2, 6, 0>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_regs", &generate_verilog(&uut));
}
