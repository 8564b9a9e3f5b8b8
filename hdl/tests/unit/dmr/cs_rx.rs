//! Tests of `drcc_hdl::dmr::cs_rx`.

use drcc_hdl::dmr::cs_rx::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_cs_rx_synthesizes() {
    let mut uut = DmrCsRx::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_cs_rx", &generate_verilog(&uut));
}
