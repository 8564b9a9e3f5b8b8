//! Tests of `drcc_hdl::channel::bsp::tx_pin`.

use drcc_hdl::channel::bsp::field::Field;
use drcc_hdl::channel::bsp::tx_pin::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn clock(uut: &mut TxPin) {
        assert!(simulate(uut, 100), "settles");
        uut.clk.next = Clock { clk: true };
        simulate(uut, 100);
        uut.clk.next = Clock { clk: false };
        simulate(uut, 100);
    }

    /// The pin after one `bit_start` in the given state.
    fn pin_after_bit_start(uut: &mut TxPin) -> bool {
        uut.bit_start.next = true;
        clock(uut);
        uut.bit_start.next = false;
        clock(uut);
        uut.tx.val()
    }

    /// Contract §4.2 / §7: the pin changes only at a bit start; an active error
    /// flag and the receiver's ACK are dominant, except in listen-only mode.
    #[test]
    fn drives_flags_and_ack_at_bit_start() {
        let mut uut = TxPin::default();
        uut.connect_all();
        uut.rst.next = true;
        clock(&mut uut);
        uut.rst.next = false;
        uut.field.next = Field::ErrorFlag;
        clock(&mut uut);
        assert!(uut.tx.val(), "recessive until a bit starts");
        assert!(!pin_after_bit_start(&mut uut), "active error flag (10.4.3)");
        uut.flag_passive.next = true;
        assert!(pin_after_bit_start(&mut uut), "passive error flag");
        uut.field.next = Field::AckSlot;
        uut.crc_ok.next = true;
        assert!(!pin_after_bit_start(&mut uut), "ACK (10.4.2.7)");
        uut.listen_only.next = true;
        assert!(pin_after_bit_start(&mut uut), "listen-only sends no ACK");
        uut.listen_only.next = false;
        // A pending frame starts from idle with its SOF; a transmitter sends the
        // stuff bit, the complement of the last five (10.5).
        uut.field.next = Field::Idle;
        uut.tx_starts.next = true;
        assert!(!pin_after_bit_start(&mut uut), "SOF");
        uut.field.next = Field::IdA;
        uut.is_tx.next = true;
        uut.frame_bit.next = true;
        assert!(pin_after_bit_start(&mut uut));
        uut.stuff_insert.next = true;
        uut.stuff_last.next = true;
        assert!(!pin_after_bit_start(&mut uut), "stuff bit");
    }

    #[test]
    fn tx_pin_synthesizes() {
        let mut uut = TxPin::default();
        uut.connect_all();
        crate::synth_check::yosys_check("tx_pin", &generate_verilog(&uut));
    }
}
