//! Tests of `drcc_hdl::bus::axi_lite`.

use drcc_hdl::bus::axi_lite::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    #[test]
    fn axi_lite_bridge_synthesizes() {
        let mut uut = AxiLiteBridge::<8, 6>::default();
        uut.connect_all();
        crate::synth_check::yosys_check("axi_lite_bridge", &generate_verilog(&uut));
    }
}
