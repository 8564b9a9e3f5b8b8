//! CRC-15 of classical CAN (ISO 11898-1:2015 clause 10, data frame: CRC field): generator
//! polynomial x^15 + x^14 + x^10 + x^8 + x^7 + x^4 + x^3 + 1 (0x4599), initial
//! value 0, computed bit-serially over the destuffed bits from SOF to the end of
//! the data field (contract §4.3).

/// The generator polynomial without its x^15 term.
pub const POLY: u16 = 0x4599;

/// Shifts one bit into the CRC register (the bit-serial divider of the standard).
#[inline]
pub fn crc15_step(crc: u16, bit: bool) -> u16 {
    let feedback = bit ^ ((crc >> 14) & 1 == 1);
    let shifted = (crc << 1) & 0x7FFF;
    if feedback {
        shifted ^ POLY
    } else {
        shifted
    }
}

/// CRC-15 of a bit sequence, starting from 0.
pub fn crc15(bits: impl IntoIterator<Item = bool>) -> u16 {
    bits.into_iter().fold(0, crc15_step)
}

/// CRC-15 of bytes fed MSB first (the standard check value uses this order).
pub fn crc15_bytes(bytes: &[u8]) -> u16 {
    crc15(
        bytes
            .iter()
            .flat_map(|&b| (0..8).rev().map(move |i| (b >> i) & 1 == 1)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_value_of_123456789() {
        // CRC-15/CAN catalogue check value.
        assert_eq!(crc15_bytes(b"123456789"), 0x059E);
    }

    #[test]
    fn zero_message_has_zero_crc() {
        assert_eq!(crc15(std::iter::repeat_n(false, 40)), 0);
    }
}
