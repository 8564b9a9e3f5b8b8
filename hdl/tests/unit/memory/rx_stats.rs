//! Tests of `drcc_hdl::memory::rx_stats`.

use drcc_hdl::memory::rx_stats::*;
use rust_hdl::prelude::*;

#[test]
fn rx_stats_synthesizes() {
    let mut uut = RxStats::default();
    uut.connect_all();
    crate::synth_check::yosys_check("rx_stats", &generate_verilog(&uut));
}
