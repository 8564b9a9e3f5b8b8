//! Tests of `drcc_hdl::channel::config`.

use drcc_hdl::channel::config::*;
use rust_hdl::prelude::*;

#[test]
fn channel_config_synthesizes() {
    let mut uut = ChannelConfig::default();
    uut.connect_all();
    crate::synth_check::yosys_check("channel_config", &generate_verilog(&uut));
}
