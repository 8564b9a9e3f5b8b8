//! Tests of `drcc_hdl::rmb::stats`.

use drcc_hdl::rmb::stats::*;
use rust_hdl::prelude::*;

#[test]
fn redundancy_stats_synthesizes() {
    let mut uut = RedundancyStats::default();
    uut.connect_all();
    crate::synth_check::yosys_check("redundancy_stats", &generate_verilog(&uut));
}
