//! Tests of `drcc_hdl::redcan::rcm`.

use drcc_hdl::redcan::rcm::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    #[test]
    fn rcm_synthesizes() {
        let mut uut = Rcm::default();
        uut.connect_all();
        crate::synth_check::yosys_check("rcm", &generate_verilog(&uut));
    }
}
