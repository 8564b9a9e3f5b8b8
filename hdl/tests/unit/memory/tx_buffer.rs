//! Tests of `drcc_hdl::memory::tx_buffer`.

use drcc_hdl::memory::tx_buffer::*;
use rust_hdl::prelude::*;

#[test]
fn tx_buffer_synthesizes() {
    let mut uut = TxBuffer::default();
    uut.connect_all();
    crate::synth_check::yosys_check("tx_buffer", &generate_verilog(&uut));
}
