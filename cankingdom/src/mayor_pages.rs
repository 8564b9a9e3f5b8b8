//! The Mayor's Document: Mayor's Pages 0 (EAN-13) and 1 (serial number).
//!
//! Both pages: Line 0 reserved (= 0), Line 1 page number, Lines 2..6 an
//! unsigned 40-bit integer (LSB in Line 2, MSB in Line 6), Line 7 reserved
//! (= 0). A Mayor's Letter travels in envelope base number + city address.

use crate::letter::{lines, EncodeError, Reject};

/// Largest value of a 40-bit field.
pub const MAX_40_BIT: u64 = (1 << 40) - 1;

/// One of the Mayor's pages this crate implements.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MayorPage {
    /// Page 0: City identification, EAN-13 code without its check digit.
    Identification {
        /// The EAN-13 (12 digits, check digit omitted) as a 40-bit integer.
        ean: u64,
    },
    /// Page 1: City identification, serial number.
    Serial {
        /// The serial number as a 40-bit integer.
        serial: u64,
    },
}

impl MayorPage {
    /// The page number written in Line 1.
    pub const fn number(&self) -> u8 {
        match self {
            MayorPage::Identification { .. } => 0,
            MayorPage::Serial { .. } => 1,
        }
    }

    /// The eight lines of this page.
    pub fn encode(&self) -> Result<[u8; 8], EncodeError> {
        let value = match *self {
            MayorPage::Identification { ean } => ean,
            MayorPage::Serial { serial } => serial,
        };
        if value > MAX_40_BIT {
            return Err(EncodeError::ValueTooLarge);
        }
        let mut p = [0u8; 8];
        p[1] = self.number();
        p[2..7].copy_from_slice(&value.to_le_bytes()[..5]);
        Ok(p)
    }

    /// Decode a Mayor's page from its data bytes (must be exactly 8).
    pub fn decode(data: &[u8]) -> Result<Self, Reject> {
        let p = lines(data)?;
        if p[1] > 1 {
            return Err(Reject::UnknownPage);
        }
        if p[0] != 0 || p[7] != 0 {
            return Err(Reject::ReservedBitsSet);
        }
        let value = u64::from_le_bytes([p[2], p[3], p[4], p[5], p[6], 0, 0, 0]);
        Ok(if p[1] == 0 {
            MayorPage::Identification { ean: value }
        } else {
            MayorPage::Serial { serial: value }
        })
    }
}
