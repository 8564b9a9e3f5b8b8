//! Tests of `drcc_hdl::channel::bsp::crc`.

use drcc_hdl::channel::bsp::crc::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    /// The catalogued check value of CRC-15/CAN over ASCII "123456789" is 0x059E.
    #[test]
    fn crc15_check_value() {
        let mut uut = Crc15Step::default();
        uut.connect_all();
        let mut crc: Bits<15> = 0.into();
        for byte in b"123456789" {
            for i in (0..8).rev() {
                uut.crc.next = crc;
                uut.data_bit.next = (byte >> i) & 1 == 1;
                simulate(&mut uut, 10);
                crc = uut.crc_next.val();
            }
        }
        assert_eq!(crc, Bits::<15>::from(0x059E));
    }

    #[test]
    fn crc15_synthesizes() {
        let mut uut = Crc15Step::default();
        uut.connect_all();
        crate::synth_check::yosys_check("crc15_step", &generate_verilog(&uut));
    }
}
