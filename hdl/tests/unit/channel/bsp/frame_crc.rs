//! Tests of `drcc_hdl::channel::bsp::frame_crc`.

use drcc_hdl::channel::bsp::frame_crc::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn clock(uut: &mut FrameCrc) {
        assert!(simulate(uut, 100), "settles");
        uut.clk.next = Clock { clk: true };
        simulate(uut, 100);
        uut.clk.next = Clock { clk: false };
        simulate(uut, 100);
    }

    /// CRC-15/CAN over the bits of "123456789" is 0x059E (the catalogued check
    /// value); receiving exactly that sequence keeps `crc_ok`, one wrong bit
    /// clears it.
    #[test]
    fn computes_and_checks_the_crc() {
        let mut uut = FrameCrc::default();
        uut.connect_all();
        uut.rst.next = true;
        clock(&mut uut);
        uut.rst.next = false;
        for byte in b"123456789" {
            for i in (0..8).rev() {
                uut.sampled.next = (byte >> i) & 1 == 1;
                uut.step.next = true;
                clock(&mut uut);
            }
        }
        uut.step.next = false;
        assert_eq!(uut.crc.val(), Bits::<15>::from(0x059E));
        let receive = |uut: &mut FrameCrc, flip: u64| {
            uut.in_crc_field.next = true;
            for n in 0..15u64 {
                uut.bit_cnt.next = n.into();
                clock(uut); // the pre-decode of bit n
                uut.sampled.next = ((0x059E >> (14 - n)) & 1 == 1) ^ (n == flip);
                uut.check.next = true;
                clock(uut);
                uut.check.next = false;
            }
        };
        receive(&mut uut, 99);
        assert!(uut.crc_ok.val());
        receive(&mut uut, 3);
        assert!(!uut.crc_ok.val());
    }

    #[test]
    fn frame_crc_synthesizes() {
        let mut uut = FrameCrc::default();
        uut.connect_all();
        crate::synth_check::yosys_check("frame_crc", &generate_verilog(&uut));
    }
}
