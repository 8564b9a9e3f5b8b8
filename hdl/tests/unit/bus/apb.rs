//! Tests of `drcc_hdl::bus::apb`.

use drcc_hdl::bus::apb::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    #[test]
    fn apb_bridge_synthesizes() {
        let mut uut = ApbBridge::<8, 6>::default();
        uut.connect_all();
        crate::synth_check::yosys_check("apb_bridge", &generate_verilog(&uut));
    }

    /// §2's wiring: the access phase alone strobes the port, the word index
    /// is `paddr[7:2]`, and `pready` / `pslverr` are the port's answer.
    #[test]
    fn access_phase_strobes_and_the_answer_is_pready() {
        let mut uut = ApbBridge::<8, 6>::default();
        uut.connect_all();
        let check = |uut: &mut ApbBridge<8, 6>, sel: bool, en: bool| {
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

    /// The SJA1000 view's width (9-bit byte address, stride 4): register 127
    /// at byte 0x1FC is word 127, and `paddr[1:0]` never reach the port.
    #[test]
    fn nine_bit_address_gives_a_seven_bit_word_index() {
        let mut uut = ApbBridge::<9, 7>::default();
        uut.connect_all();
        for (paddr, word) in [(0x1FC, 127), (0x1FF, 127), (0x100, 64), (0x0FC, 63)] {
            uut.s_apb_paddr.next = paddr.into();
            assert!(simulate(&mut uut, 10));
            assert_eq!(uut.wb_adr_o.val().to_u64(), word, "paddr {paddr:#x}");
        }
    }
}
