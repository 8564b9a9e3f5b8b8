//! Tests of `drcc_hdl::channel::bsp::field_decode`.

use drcc_hdl::channel::bsp::field::Field;
use drcc_hdl::channel::bsp::field_decode::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    /// 10.4.2.2: the IDE bit is arbitration only for an extended frame; every
    /// decode is the registered value of the state one clock before.
    #[test]
    fn ide_is_arbitration_only_when_extended() {
        let mut uut = FieldDecode::default();
        uut.connect_all();
        uut.field.next = Field::Ide;
        uut.bit_cnt.next = 0.into();
        uut.clk.next = Clock { clk: true };
        simulate(&mut uut, 100);
        assert!(uut.in_frame.val() && uut.crc_covered.val() && uut.bc0.val());
        assert!(!uut.in_arbitration.val());
        uut.frame_ide.next = true;
        simulate(&mut uut, 100);
        assert!(uut.in_arbitration.val());
        uut.clk.next = Clock { clk: false };
        uut.field.next = Field::Crc;
        simulate(&mut uut, 100);
        assert!(
            uut.in_arbitration.val(),
            "registered: no change before the edge"
        );
        uut.clk.next = Clock { clk: true };
        simulate(&mut uut, 100);
        assert!(!uut.in_arbitration.val() && uut.in_frame.val() && !uut.crc_covered.val());
    }

    #[test]
    fn field_decode_synthesizes() {
        let mut uut = FieldDecode::default();
        uut.connect_all();
        crate::synth_check::yosys_check("field_decode", &generate_verilog(&uut));
    }
}
