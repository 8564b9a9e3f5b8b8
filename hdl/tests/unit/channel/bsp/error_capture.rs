//! Tests of `drcc_hdl::channel::bsp::error_capture`.

use drcc_hdl::channel::bsp::error_capture::*;
use drcc_hdl::channel::bsp::field::Field;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn clock(uut: &mut ErrorCapture) {
        assert!(simulate(uut, 100), "settles");
        uut.clk.next = Clock { clk: true };
        simulate(uut, 100);
        uut.clk.next = Clock { clk: false };
        simulate(uut, 100);
    }

    /// Contract §9: a captured bit error (its kind one-hot, precedence applied by
    /// `ErrorDecision`) counts once, is held as kind 1, err_valid is one clock.
    #[test]
    fn bit_error_wins_and_is_counted() {
        let mut uut = ErrorCapture::default();
        uut.connect_all();
        uut.rst.next = true;
        clock(&mut uut);
        uut.rst.next = false;
        uut.field.next = Field::Data;
        clock(&mut uut);
        uut.capture.next = true;
        uut.kind_bit.next = true;
        uut.as_tx.next = true;
        clock(&mut uut);
        uut.capture.next = false;
        uut.kind_bit.next = false;
        assert!(uut.err_valid.val() && uut.err_tx.val());
        assert_eq!(uut.err_kind.val(), Bits::<3>::from(1));
        assert_eq!(uut.err_field.val(), Field::Data);
        assert_eq!(uut.cnt_bit.val(), Bits::<8>::from(1));
        assert_eq!(uut.cnt_stuff.val(), Bits::<8>::from(0));
        clock(&mut uut);
        assert!(!uut.err_valid.val());
    }

    /// Contract §9: arbitration lost at ID_B bit 4 reads 13 + 4.
    #[test]
    fn arbitration_lost_position() {
        let mut uut = ErrorCapture::default();
        uut.connect_all();
        uut.field.next = Field::IdB;
        uut.bit_cnt.next = 4.into();
        clock(&mut uut);
        uut.arb_lost.next = true;
        clock(&mut uut);
        assert_eq!(uut.alc.val(), Bits::<5>::from(17));
    }

    #[test]
    fn error_capture_synthesizes() {
        let mut uut = ErrorCapture::default();
        uut.connect_all();
        crate::synth_check::yosys_check("error_capture", &generate_verilog(&uut));
    }
}
