//! Tests of `drcc_hdl::hub::config`.

use drcc_hdl::hub::config::*;
use rust_hdl::prelude::*;

#[test]
fn hub_config_synthesizes() {
    let mut uut = HubConfig::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_config", &generate_verilog(&uut));
}
