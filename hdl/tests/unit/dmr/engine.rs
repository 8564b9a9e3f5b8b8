//! Tests of `drcc_hdl::dmr::engine`.

use drcc_hdl::dmr::engine::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_engine_synthesizes() {
    let mut uut = DmrEngine::<MAILBOXES>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_engine", &generate_verilog(&uut));
}
