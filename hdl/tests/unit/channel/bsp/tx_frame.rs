//! Tests of `drcc_hdl::channel::bsp::tx_frame`.

use drcc_hdl::channel::bsp::field::Field;
use drcc_hdl::channel::bsp::tx_frame::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    /// The bits of a base data frame, ID 0x123, DLC 1, data 0xA5, field by
    /// field as ISO 11898-1 10.4.2 orders them (MSB first), before stuffing.
    #[test]
    fn base_frame_bits_in_order() {
        let mut uut = TxFrame::default();
        uut.connect_all();
        uut.load.next = true;
        uut.id.next = 0x123.into();
        uut.dlc.next = 1.into();
        uut.data.next = Bits::<64>::from(0xA5u64 << 56);
        uut.clk.next = Clock { clk: true };
        simulate(&mut uut, 100);
        uut.load.next = false;
        uut.clk.next = Clock { clk: false };
        simulate(&mut uut, 100);
        let mut bits = vec![];
        let mut read = |uut: &mut TxFrame, f: Field, n: u64| {
            uut.field.next = f;
            uut.bit_cnt.next = n.into();
            simulate(uut, 100);
            bits.push(uut.frame_bit.val() as u8);
        };
        for n in 0..11 {
            read(&mut uut, Field::IdA, n);
        }
        read(&mut uut, Field::SrrRtr, 0);
        read(&mut uut, Field::Ide, 0);
        read(&mut uut, Field::R0, 0);
        for n in 0..4 {
            read(&mut uut, Field::Dlc, n);
        }
        for n in 0..8 {
            read(&mut uut, Field::Data, n);
        }
        let expect = [
            0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 1, // ID 0x123
            0, 0, 0, // RTR, IDE, r0 dominant
            0, 0, 0, 1, // DLC 1
            1, 0, 1, 0, 0, 1, 0, 1, // 0xA5
        ];
        assert_eq!(bits, expect);
        assert!(!uut.frame_ide.val());
    }

    #[test]
    fn tx_frame_synthesizes() {
        let mut uut = TxFrame::default();
        uut.connect_all();
        crate::synth_check::yosys_check("tx_frame", &generate_verilog(&uut));
    }
}
