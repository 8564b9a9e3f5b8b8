//! Tests of `drcc_hdl::bus::hub_tops`.

use drcc_hdl::bus::hub_tops::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    /// Both hub bus tops elaborate (every port and child driven); the AXI one
    /// (the larger bridge) also passes yosys.
    #[test]
    fn hub_bus_tops_synthesize() {
        let mut apb = HubApb::<4, 2, 6, 0>::default();
        apb.connect_all();
        assert!(generate_verilog(&apb).contains("module top"));
        let mut axi = HubAxi::<4, 2, 6, 0>::default();
        axi.connect_all();
        crate::synth_check::yosys_check("hub_axi", &generate_verilog(&axi));
    }
}
