//! A CAN 2.0B frame as the host sees it, shared by every engine and the scenario format.
//!
//! Identifier: base frames use `id[10:0]`; extended frames use `id[28:0]`, whose
//! bits `[28:18]` are the base identifier sent first (ISO 11898-1, 10.4.2.2).
//! Data: byte 0 is sent first; on the RTL's 64-bit data ports byte 0 sits in
//! bits `[63:56]` so the data field leaves MSB first from bit 63 down.

/// One CAN 2.0B frame (data or remote, base or extended).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Frame {
    /// 11-bit (base) or 29-bit (extended) identifier.
    pub id: u32,
    /// Identifier extension: `true` for a 29-bit identifier.
    pub ide: bool,
    /// Remote transmission request: `true` for a remote frame (no data field).
    pub rtr: bool,
    /// Data length code as sent, 0..=15; values above 8 carry 8 bytes.
    pub dlc: u8,
    /// Data bytes; bytes past `data_len()` are zero.
    pub data: [u8; 8],
}

impl Frame {
    /// A base-format data frame with identifier `id` (11 bits) carrying `data`
    /// (at most 8 bytes; the DLC is its length).
    pub fn base(id: u32, data: &[u8]) -> Frame {
        let n = data.len().min(8);
        let mut d = [0u8; 8];
        d[..n].copy_from_slice(&data[..n]);
        Frame {
            id: id & 0x7FF,
            ide: false,
            rtr: false,
            dlc: n as u8,
            data: d,
        }
    }

    /// Number of data bytes on the bus: 0 for remote frames, else min(dlc, 8).
    pub fn data_len(&self) -> usize {
        if self.rtr {
            0
        } else {
            (self.dlc as usize).min(8)
        }
    }

    /// The data bytes packed the way the RTL ports carry them (byte 0 in bits 63..56).
    pub fn data_word(&self) -> u64 {
        u64::from_be_bytes(self.data)
    }

    /// Inverse of [`Frame::data_word`].
    pub fn with_data_word(mut self, word: u64) -> Self {
        self.data = word.to_be_bytes();
        self
    }

    /// The identifier mask for this format.
    pub fn id_mask(&self) -> u32 {
        if self.ide {
            0x1FFF_FFFF
        } else {
            0x7FF
        }
    }

    /// A copy with the identifier masked to its format, DLC to 4 bits and unused
    /// data bytes cleared: what a receiver can reconstruct from the bus.
    pub fn normalized(&self) -> Frame {
        let mut f = *self;
        f.id &= f.id_mask();
        f.dlc &= 0xF;
        let n = f.data_len();
        for b in f.data.iter_mut().skip(n) {
            *b = 0;
        }
        f
    }
}

impl std::fmt::Display for Frame {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.ide {
            write!(f, "{:08X}x", self.id)?;
        } else {
            write!(f, "{:03X}", self.id)?;
        }
        if self.rtr {
            write!(f, " R dlc={}", self.dlc)
        } else {
            write!(f, " [{}]", self.dlc)?;
            for b in &self.data[..self.data_len()] {
                write!(f, " {:02X}", b)?;
            }
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Frame;

    #[test]
    fn a_base_frame_carries_its_bytes_with_their_count_as_dlc() {
        let f = Frame::base(0x123, &[0xDE, 0xAD]);
        assert_eq!(
            f,
            Frame {
                id: 0x123,
                ide: false,
                rtr: false,
                dlc: 2,
                data: [0xDE, 0xAD, 0, 0, 0, 0, 0, 0],
            }
        );
        // At most 8 bytes: a classical CAN data field.
        assert_eq!(Frame::base(0x7FF, &[1; 10]).dlc, 8);
    }
}
