//! Tests of `drcc_hdl::channel::bus_sampling::synchronizer`.

use drcc_hdl::channel::bus_sampling::synchronizer::*;
use rust_hdl::prelude::*;

#[test]
fn synchronizer_synthesizes() {
    let mut uut = RxSynchronizer::default();
    uut.connect_all();
    crate::synth_check::yosys_check("rx_synchronizer", &generate_verilog(&uut));
}
