//! Tests of `drcc_hdl::memory::rx_fifo`.

use drcc_hdl::memory::rx_fifo::*;
use rust_hdl::prelude::*;

#[test]
fn rx_fifo_synthesizes() {
    let mut uut = RxFifo::default();
    uut.connect_all();
    crate::synth_check::yosys_check("rx_fifo", &generate_verilog(&uut));
}
