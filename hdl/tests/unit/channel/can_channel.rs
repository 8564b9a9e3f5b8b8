//! Tests of `drcc_hdl::channel::can_channel`.

use drcc_hdl::channel::can_channel::*;
use rust_hdl::prelude::*;

#[test]
fn can_channel_synthesizes() {
    let mut uut: CanChannel = CanChannel::default();
    uut.connect_all();
    crate::synth_check::yosys_check("can_channel", &generate_verilog(&uut));
}
