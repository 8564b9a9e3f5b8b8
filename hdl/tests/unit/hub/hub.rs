//! Tests of `drcc_hdl::hub::hub`.

use drcc_hdl::hub::hub::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    #[test]
    fn hub_synthesizes() {
        let mut uut = Hub4x2::default();
        uut.connect_all();
        crate::synth_check::yosys_check("hub", &generate_verilog(&uut));
    }

    #[test]
    fn hub_b_synthesizes() {
        let mut uut = HubB4x2::default();
        uut.connect_all();
        crate::synth_check::yosys_check("hub_b", &generate_verilog(&uut));
    }

    #[test]
    fn hub_2x1_synthesizes() {
        let mut uut = Hub::<2, 1, 3>::default();
        uut.connect_all();
        crate::synth_check::yosys_check("hub_2x1", &generate_verilog(&uut));
    }
}
