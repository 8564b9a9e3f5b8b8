//! Tests of `drcc_hdl::bus::apb`.

use drcc_hdl::bus::apb::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    #[test]
    fn apb_bridge_synthesizes() {
        let mut uut = ApbBridge::default();
        uut.connect_all();
        crate::synth_check::yosys_check("apb_bridge", &generate_verilog(&uut));
    }

    /// §2's wiring: the access phase alone strobes the port, the word index
    /// is `paddr[7:2]`, and `pready` / `pslverr` are the port's answer.
    #[test]
    fn access_phase_strobes_and_the_answer_is_pready() {
        let mut uut = ApbBridge::default();
        uut.connect_all();
        let check = |uut: &mut ApbBridge, sel: bool, en: bool| {
            uut.s_apb_psel.next = sel;
            uut.s_apb_penable.next = en;
            assert!(simulate(uut, 10));
            uut.wb_cyc_o.val()
        };
        assert!(!check(&mut uut, true, false), "setup phase: no strobe");
        assert!(!check(&mut uut, false, true), "not selected: no strobe");
        assert!(check(&mut uut, true, true), "access phase: strobe");
        uut.s_apb_paddr.next = 0x2F.into(); // word 11, byte 3
        uut.wb_err_i.next = true;
        assert!(simulate(&mut uut, 10));
        assert_eq!(uut.wb_adr_o.val().to_u64(), 11);
        assert!(uut.s_apb_pready.val() && uut.s_apb_pslverr.val());
        uut.wb_err_i.next = false;
        uut.wb_ack_i.next = true;
        assert!(simulate(&mut uut, 10));
        assert!(uut.s_apb_pready.val() && !uut.s_apb_pslverr.val());
    }
}
