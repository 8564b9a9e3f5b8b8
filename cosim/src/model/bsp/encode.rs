//! The transmitter's frame as an unstuffed bit string, from SOF to the last CRC bit
//! (ISO 11898-1:2015 clause 10: data frame 10.4.2, remote frame 10.4.3, base and
//! extended format; bits leave MSB first).
//!
//! At most 1 + 11 + 1 + 1 + 18 + 1 + 1 + 1 + 4 + 64 + 15 = 118 bits, so the whole
//! frame fits in one `u128`; stuff bits are inserted on the fly while sending.

use crate::frame::Frame;
use crate::model::crc::crc15_step;

/// A frame ready to send: `len` bits, bit 0 (SOF) in position `len - 1`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TxStream {
    bits: u128,
    len: u8,
}

impl TxStream {
    /// Encodes `frame`: SOF, identifier (base: 11 bits, RTR, IDE = 0, r0 = 0;
    /// extended: 11 bits, SRR = 1, IDE = 1, 18 bits, RTR, r1 = 0, r0 = 0), DLC,
    /// min(DLC, 8) data bytes (none for a remote frame), CRC-15 over all of these.
    /// The identifier is masked to its format and the DLC to 4 bits.
    pub fn encode(frame: &Frame) -> Self {
        let mut s = TxStream::default();
        s.push(0, 1); // SOF
        if frame.ide {
            let id = frame.id & 0x1FFF_FFFF;
            s.push(id >> 18, 11);
            s.push(1, 1); // SRR
            s.push(1, 1); // IDE
            s.push(id & 0x3FFFF, 18);
            s.push(frame.rtr as u32, 1);
            s.push(0, 2); // r1, r0
        } else {
            s.push(frame.id & 0x7FF, 11);
            s.push(frame.rtr as u32, 1);
            s.push(0, 2); // IDE, r0
        }
        let dlc = frame.dlc & 0xF;
        s.push(dlc as u32, 4);
        if !frame.rtr {
            for &byte in &frame.data[..(dlc as usize).min(8)] {
                s.push(byte as u32, 8);
            }
        }
        let crc = (0..s.len).fold(0, |crc, i| crc15_step(crc, s.bit(i)));
        s.push(crc as u32, 15);
        s
    }

    /// Appends the `n` low bits of `value`, MSB first.
    fn push(&mut self, value: u32, n: u8) {
        let mask = (1u128 << n) - 1;
        self.bits = (self.bits << n) | (value as u128 & mask);
        self.len += n;
    }

    /// Bit `i` counted from SOF (`i = 0`); recessive past the end.
    #[inline]
    pub fn bit(&self, i: u8) -> bool {
        if i >= self.len {
            true
        } else {
            (self.bits >> (self.len - 1 - i)) & 1 == 1
        }
    }
}
