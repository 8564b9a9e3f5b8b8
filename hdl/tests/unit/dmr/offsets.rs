//! Tests of `drcc_hdl::dmr::offsets`.

use drcc_hdl::dmr::offsets::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_offsets_synthesizes() {
    let mut uut = DmrOffsets::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_offsets", &generate_verilog(&uut));
}
