//! Tests of `drcc_hdl::memory::dedup`.

use drcc_hdl::memory::dedup::*;
use rust_hdl::prelude::*;

#[test]
fn rx_writer_synthesizes() {
    let mut uut = RxWriter::default();
    uut.connect_all();
    crate::synth_check::yosys_check("rx_writer", &generate_verilog(&uut));
}
