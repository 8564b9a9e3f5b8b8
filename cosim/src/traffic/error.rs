//! SocketCAN error frames: the constants of Linux `include/uapi/linux/can/error.h`
//! (same names, same values, same meaning) and the error frames the taps build from
//! a channel's error capture (timing contract §9) and its fault-confinement state
//! (§4.5).
//!
//! An error frame is a `can_frame` whose identifier has [`CAN_ERR_FLAG`] set and
//! whose other identifier bits name the error classes; `data` holds the details
//! of each class at the byte `error.h` assigns to it.

use crate::model::field;

/// Identifier flag of an error frame (`CAN_ERR_FLAG` of `linux/can.h`).
pub const CAN_ERR_FLAG: u32 = 0x2000_0000;
/// Payload length of every error frame (`CAN_ERR_DLC`).
pub const CAN_ERR_DLC: u8 = 8;

/// Class: the controller has problems; details in `data[1]` (`CAN_ERR_CRTL_*`).
pub const CAN_ERR_CRTL: u32 = 0x0000_0004;
/// Class: a protocol violation; its type in `data[2]` (`CAN_ERR_PROT_*`), its
/// location in the frame in `data[3]` (`CAN_ERR_PROT_LOC_*`).
pub const CAN_ERR_PROT: u32 = 0x0000_0008;
/// Class: a transmitter received no acknowledgement (ACK error).
pub const CAN_ERR_ACK: u32 = 0x0000_0020;
/// Class: the controller went bus-off.
pub const CAN_ERR_BUSOFF: u32 = 0x0000_0040;
/// Class: a bus error was detected (an error flag follows; Linux drivers set it
/// with every detected bus error, readers such as python-can key on it).
pub const CAN_ERR_BUSERROR: u32 = 0x0000_0080;
/// Class: the controller restarted (here: left bus-off after the recovery of 128
/// times 11 recessive bits).
pub const CAN_ERR_RESTARTED: u32 = 0x0000_0100;
/// Class: the error counters are valid: TEC in `data[6]`, REC in `data[7]`.
pub const CAN_ERR_CNT: u32 = 0x0000_0200;

/// `data[1]` of [`CAN_ERR_CRTL`]: the REC reached the error warning limit.
pub const CAN_ERR_CRTL_RX_WARNING: u8 = 0x04;
/// `data[1]` of [`CAN_ERR_CRTL`]: the TEC reached the error warning limit.
pub const CAN_ERR_CRTL_TX_WARNING: u8 = 0x08;
/// `data[1]` of [`CAN_ERR_CRTL`]: error passive because the REC exceeds 127.
pub const CAN_ERR_CRTL_RX_PASSIVE: u8 = 0x10;
/// `data[1]` of [`CAN_ERR_CRTL`]: error passive because the TEC exceeds 127.
pub const CAN_ERR_CRTL_TX_PASSIVE: u8 = 0x20;
/// `data[1]` of [`CAN_ERR_CRTL`]: back to error active (both counters below the
/// warning limit).
pub const CAN_ERR_CRTL_ACTIVE: u8 = 0x40;

/// `data[2]` of [`CAN_ERR_PROT`]: the type is not known.
pub const CAN_ERR_PROT_UNSPEC: u8 = 0x00;
/// `data[2]` of [`CAN_ERR_PROT`]: a bit error, direction not told.
pub const CAN_ERR_PROT_BIT: u8 = 0x01;
/// `data[2]` of [`CAN_ERR_PROT`]: a form error (a fixed-form bit had the wrong value).
pub const CAN_ERR_PROT_FORM: u8 = 0x02;
/// `data[2]` of [`CAN_ERR_PROT`]: a stuff error (six equal bits in the stuffed region).
pub const CAN_ERR_PROT_STUFF: u8 = 0x04;
/// `data[2]` of [`CAN_ERR_PROT`]: a bit error: the node sent dominant and read
/// recessive ("unable to send dominant bit").
pub const CAN_ERR_PROT_BIT0: u8 = 0x08;
/// `data[2]` of [`CAN_ERR_PROT`]: a bit error: the node sent recessive and read
/// dominant ("unable to send recessive bit").
pub const CAN_ERR_PROT_BIT1: u8 = 0x10;
/// `data[2]` of [`CAN_ERR_PROT`], or-ed with the type: the node was transmitter.
pub const CAN_ERR_PROT_TX: u8 = 0x80;

/// `data[3]` of [`CAN_ERR_PROT`]: the location is not known.
pub const CAN_ERR_PROT_LOC_UNSPEC: u8 = 0x00;
/// `data[3]`: start of frame.
pub const CAN_ERR_PROT_LOC_SOF: u8 = 0x03;
/// `data[3]`: SRR bit of an extended frame, RTR bit of a base frame.
pub const CAN_ERR_PROT_LOC_SRTR: u8 = 0x04;
/// `data[3]`: identifier extension bit.
pub const CAN_ERR_PROT_LOC_IDE: u8 = 0x05;
/// `data[3]`: CRC sequence.
pub const CAN_ERR_PROT_LOC_CRC_SEQ: u8 = 0x08;
/// `data[3]`: reserved bit r0.
pub const CAN_ERR_PROT_LOC_RES0: u8 = 0x09;
/// `data[3]`: data field.
pub const CAN_ERR_PROT_LOC_DATA: u8 = 0x0A;
/// `data[3]`: data length code.
pub const CAN_ERR_PROT_LOC_DLC: u8 = 0x0B;
/// `data[3]`: RTR bit of an extended frame.
pub const CAN_ERR_PROT_LOC_RTR: u8 = 0x0C;
/// `data[3]`: reserved bit r1.
pub const CAN_ERR_PROT_LOC_RES1: u8 = 0x0D;
/// `data[3]`: intermission.
pub const CAN_ERR_PROT_LOC_INTERM: u8 = 0x12;
/// `data[3]`: CRC delimiter.
pub const CAN_ERR_PROT_LOC_CRC_DEL: u8 = 0x18;
/// `data[3]`: ACK slot.
pub const CAN_ERR_PROT_LOC_ACK: u8 = 0x19;
/// `data[3]`: end of frame.
pub const CAN_ERR_PROT_LOC_EOF: u8 = 0x1A;
/// `data[3]`: ACK delimiter.
pub const CAN_ERR_PROT_LOC_ACK_DEL: u8 = 0x1B;

/// A SocketCAN error frame (`can_frame` with [`CAN_ERR_FLAG`], length
/// [`CAN_ERR_DLC`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ErrorFrame {
    /// [`CAN_ERR_FLAG`] or-ed with the error class bits.
    pub can_id: u32,
    /// The class details, at the bytes `error.h` gives them.
    pub data: [u8; 8],
}

/// Error kinds of the `err_kind` capture register (timing contract §9).
pub mod kind {
    /// Bit error.
    pub const BIT: u8 = 1;
    /// Stuff error.
    pub const STUFF: u8 = 2;
    /// CRC error.
    pub const CRC: u8 = 3;
    /// Form error.
    pub const FORM: u8 = 4;
    /// ACK error.
    pub const ACK: u8 = 5;
}

impl ErrorFrame {
    /// An error frame of the classes `class` with empty details.
    pub fn new(class: u32) -> Self {
        ErrorFrame {
            can_id: CAN_ERR_FLAG | class,
            data: [0; 8],
        }
    }

    /// The same frame with the error counters ([`CAN_ERR_CNT`]): TEC in `data[6]`
    /// (a bus-off TEC above 255 shows as 255), REC in `data[7]`.
    pub fn with_counters(mut self, tec: u16, rec: u8) -> Self {
        self.can_id |= CAN_ERR_CNT;
        self.data[6] = tec.min(255) as u8;
        self.data[7] = rec;
        self
    }

    /// The bus error a CAN channel captured (`err_valid`, timing contract §9):
    /// `kind` and `at_field` are `err_kind` and `err_field`, `transmitter` is
    /// `err_tx`, `sent_recessive` the node's `tx` in the bit in error (it tells
    /// the two directions of a bit error apart).
    ///
    /// ACK error: [`CAN_ERR_ACK`]. Every other kind: [`CAN_ERR_PROT`] with the type
    /// (bit: [`CAN_ERR_PROT_BIT0`] / [`CAN_ERR_PROT_BIT1`], stuff, form; a CRC error
    /// has no type bit in `error.h` and is located at the CRC sequence), plus
    /// [`CAN_ERR_PROT_TX`] for a transmitter, and the location from `at_field`.
    /// Always with [`CAN_ERR_BUSERROR`]; the caller adds the counters.
    pub fn bus_error(kind: u8, at_field: u8, transmitter: bool, sent_recessive: bool) -> Self {
        if kind == kind::ACK {
            return ErrorFrame::new(CAN_ERR_ACK | CAN_ERR_BUSERROR);
        }
        let mut f = ErrorFrame::new(CAN_ERR_PROT | CAN_ERR_BUSERROR);
        f.data[2] = match kind {
            kind::BIT if sent_recessive => CAN_ERR_PROT_BIT1,
            kind::BIT => CAN_ERR_PROT_BIT0,
            kind::STUFF => CAN_ERR_PROT_STUFF,
            kind::FORM => CAN_ERR_PROT_FORM,
            _ => CAN_ERR_PROT_UNSPEC,
        };
        if transmitter {
            f.data[2] |= CAN_ERR_PROT_TX;
        }
        f.data[3] = match kind {
            kind::CRC => CAN_ERR_PROT_LOC_CRC_SEQ,
            _ => location(at_field),
        };
        f
    }

    /// A bus error whose kind is not known (a DRCC channel, which has no error
    /// capture register on its ports): [`CAN_ERR_PROT`] of type
    /// [`CAN_ERR_PROT_UNSPEC`] located at `at_field`, with [`CAN_ERR_BUSERROR`].
    pub fn unknown_bus_error(at_field: u8) -> Self {
        let mut f = ErrorFrame::new(CAN_ERR_PROT | CAN_ERR_BUSERROR);
        f.data[3] = location(at_field);
        f
    }
}

/// The `error.h` location of a `field` probe code (`crate::model::field`). The
/// identifier fields span several `error.h` ranges (ID28_21 and ID20_18 for the
/// base identifier, ID17_13 .. ID04_00 for the extension) and the probe does not
/// say which bit: they, the error and overload frames and the idle states are
/// unspecified. A dominant bit sent in IDLE is the node's own start of frame.
pub fn location(code: u8) -> u8 {
    match code {
        field::IDLE => CAN_ERR_PROT_LOC_SOF,
        field::SRR_RTR => CAN_ERR_PROT_LOC_SRTR,
        field::IDE => CAN_ERR_PROT_LOC_IDE,
        field::RTR_EXT => CAN_ERR_PROT_LOC_RTR,
        field::R1 => CAN_ERR_PROT_LOC_RES1,
        field::R0 => CAN_ERR_PROT_LOC_RES0,
        field::DLC => CAN_ERR_PROT_LOC_DLC,
        field::DATA => CAN_ERR_PROT_LOC_DATA,
        field::CRC => CAN_ERR_PROT_LOC_CRC_SEQ,
        field::CRC_DELIM => CAN_ERR_PROT_LOC_CRC_DEL,
        field::ACK_SLOT => CAN_ERR_PROT_LOC_ACK,
        field::ACK_DELIM => CAN_ERR_PROT_LOC_ACK_DEL,
        field::EOF => CAN_ERR_PROT_LOC_EOF,
        field::INTERMISSION => CAN_ERR_PROT_LOC_INTERM,
        _ => CAN_ERR_PROT_LOC_UNSPEC,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_ack_error_is_its_own_class() {
        let f = ErrorFrame::bus_error(kind::ACK, field::ACK_SLOT, true, true).with_counters(8, 0);
        // error.h: CAN_ERR_FLAG | CAN_ERR_ACK | CAN_ERR_BUSERROR | CAN_ERR_CNT
        assert_eq!(f.can_id, 0x2000_0000 | 0x20 | 0x80 | 0x200);
        assert_eq!(f.data, [0, 0, 0, 0, 0, 0, 8, 0]);
    }

    #[test]
    fn a_transmitters_bit_error_names_direction_role_and_place() {
        // Sent dominant in the data field, read recessive: BIT0 | TX at DATA.
        let f = ErrorFrame::bus_error(kind::BIT, field::DATA, true, false);
        assert_eq!(f.can_id, 0x2000_0088);
        assert_eq!(f.data, [0, 0, 0x08 | 0x80, 0x0A, 0, 0, 0, 0]);
        // A receiver's stuff error in the CRC field; a CRC error sits at CRC_SEQ.
        let s = ErrorFrame::bus_error(kind::STUFF, field::CRC, false, true);
        assert_eq!(s.data[2..4], [0x04, 0x08]);
        let c = ErrorFrame::bus_error(kind::CRC, field::ACK_DELIM, false, true);
        assert_eq!(c.data[2..4], [0x00, 0x08]);
    }

    #[test]
    fn counters_saturate_at_one_byte() {
        let f = ErrorFrame::new(CAN_ERR_BUSOFF).with_counters(263, 17);
        assert_eq!(f.can_id, 0x2000_0240);
        assert_eq!(f.data[6..], [255, 17]);
    }
}
