//! Tests of `drcc_hdl::dmr::line`.

use drcc_hdl::dmr::line::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_line_synthesizes() {
    let mut uut = DmrLine::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_line", &generate_verilog(&uut));
}
