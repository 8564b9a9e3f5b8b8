//! Tests of `drcc_hdl::hub::nrap_ahead`.

use drcc_hdl::hub::nrap_ahead::*;
use rust_hdl::prelude::*;

#[test]
fn nrap_ahead_synthesizes() {
    let mut uut = NrapAhead::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_nrap_ahead", &generate_verilog(&uut));
}
