//! Tests of `drcc_hdl::channel::bsp::error_detection`.

use drcc_hdl::channel::bsp::error_detection::*;
use drcc_hdl::channel::bsp::field::Field;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn uut() -> ErrorDetection {
        let mut uut = ErrorDetection::default();
        uut.connect_all();
        uut.sample.next = true;
        uut.sampled.next = true;
        uut.tx_bit.next = true;
        uut.crc_ok.next = true;
        simulate(&mut uut, 100);
        uut
    }

    /// 12.1.3.1 / 12.1.2: a transmitter reading dominant for its recessive bit
    /// loses arbitration in the arbitration field and has a bit error after it.
    #[test]
    fn bit_monitoring_and_arbitration() {
        let mut uut = uut();
        uut.is_tx.next = true;
        uut.in_frame.next = true;
        uut.in_arbitration.next = true;
        uut.field.next = Field::IdA;
        uut.sampled.next = false;
        simulate(&mut uut, 100);
        assert!(uut.lost.val() && !uut.error.val());
        uut.in_arbitration.next = false;
        uut.field.next = Field::Data;
        simulate(&mut uut, 100);
        assert!(!uut.lost.val() && uut.error.val() && uut.bit_err.val());
        // Not at a sample point: nothing.
        uut.sample.next = false;
        simulate(&mut uut, 100);
        assert!(!uut.error.val());
    }

    /// 10.5 / 12.1.3.2: a stuff bit equal to the bit before it is a stuff error.
    #[test]
    fn stuff_error() {
        let mut uut = uut();
        uut.at_stuff_bit.next = true;
        uut.stuff_last.next = false;
        uut.sampled.next = false;
        simulate(&mut uut, 100);
        assert!(uut.error.val() && uut.stuff_err.val() && !uut.bit_err.val());
        uut.sampled.next = true;
        simulate(&mut uut, 100);
        assert!(!uut.error.val());
    }

    /// 12.1.3.4: dominant CRC delimiter is a form error; 12.1.3.5: recessive
    /// ACK slot seen by the transmitter is an ACK error.
    #[test]
    fn form_and_ack_errors() {
        let mut uut = uut();
        uut.field.next = Field::CrcDelim;
        uut.sampled.next = false;
        simulate(&mut uut, 100);
        assert!(uut.error.val() && uut.form_err.val());
        uut.field.next = Field::AckSlot;
        uut.is_tx.next = true;
        uut.sampled.next = true;
        simulate(&mut uut, 100);
        assert!(uut.error.val() && uut.ack_err.val());
        uut.ack_check_off.next = true;
        simulate(&mut uut, 100);
        assert!(!uut.error.val());
    }

    #[test]
    fn error_detection_synthesizes() {
        let mut uut = ErrorDetection::default();
        uut.connect_all();
        crate::synth_check::yosys_check("error_detection", &generate_verilog(&uut));
    }
}
