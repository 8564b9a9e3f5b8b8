//! CRC-15/CAN next-state function (ISO 11898-1, 10.4.2.6): generator polynomial
//! x^15 + x^14 + x^10 + x^8 + x^7 + x^4 + x^3 + 1 (0x4599), initial value 0, one
//! destuffed bit per step, MSB first. Purely combinational: the protocol
//! controller holds the register and decides which bits are covered.

use rust_hdl::prelude::*;

/// One step of the CRC-15 shift register.
#[derive(LogicBlock)]
pub struct Crc15Step {
    /// The CRC register before this bit.
    pub crc: Signal<In, Bits<15>>,
    /// The destuffed bit shifted in.
    pub data_bit: Signal<In, Bit>,
    /// The CRC register after this bit: `crc << 1`, XOR 0x4599 when `crc[14] ^ data_bit`.
    pub crc_next: Signal<Out, Bits<15>>,
    polynomial: Constant<Bits<15>>,
    zero: Constant<Bits<15>>,
    feedback: Signal<Local, Bit>,
}

impl Default for Crc15Step {
    fn default() -> Self {
        Self {
            crc: Default::default(),
            data_bit: Default::default(),
            crc_next: Default::default(),
            polynomial: Constant::new(0x4599.into()),
            zero: Constant::new(0.into()),
            feedback: Default::default(),
        }
    }
}

impl Logic for Crc15Step {
    #[hdl_gen]
    fn update(&mut self) {
        self.feedback.next = self.crc.val().get_bit(14) ^ self.data_bit.val();
        if self.feedback.val() {
            self.crc_next.next = (self.crc.val() << 1) ^ self.polynomial.val();
        } else {
            self.crc_next.next = (self.crc.val() << 1) ^ self.zero.val();
        }
    }
}
