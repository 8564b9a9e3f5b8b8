//! Tests of `drcc_hdl::memory::release_scan`.

use drcc_hdl::memory::release_scan::*;
use rust_hdl::prelude::*;

#[test]
fn release_scan_synthesizes() {
    let mut uut = ReleaseScan::default();
    uut.connect_all();
    crate::synth_check::yosys_check("release_scan", &generate_verilog(&uut));
}
