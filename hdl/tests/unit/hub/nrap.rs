//! Tests of `drcc_hdl::hub::nrap`.

use drcc_hdl::hub::nrap::*;
use rust_hdl::prelude::*;

#[test]
fn nrap_synthesizes() {
    let mut uut = Nrap::<0>::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hub_nrap", &generate_verilog(&uut));
}
