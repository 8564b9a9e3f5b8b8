//! The classical CAN frame as the DRCC's TX and RX registers carry it, and its
//! `embedded_can::Frame` implementation.

use embedded_can::{ExtendedId, Id, StandardId};

/// The channel a frame was received on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Channel {
    /// Channel A (the DCL in DMR mode).
    #[default]
    A,
    /// Channel B (the RCL in DMR mode).
    B,
}

/// A CAN 2.0B frame: identifier, remote flag, DLC 0..=15 (at most 8 data bytes)
/// and, for a received frame, the channel it came from and its timestamp.
///
/// Equality compares everything but the timestamp (reception metadata), so
/// a received frame equals the frame built to describe it on that channel.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    id: Id,
    rtr: bool,
    dlc: u8,
    data: [u8; 8],
    channel: Channel,
    timestamp: u16,
}

impl Frame {
    /// A data frame whose DLC is the length of `data` (0..=8).
    pub fn data_frame(id: impl Into<Id>, data: &[u8]) -> Option<Frame> {
        if data.len() > 8 {
            return None;
        }
        let mut bytes = [0; 8];
        bytes[..data.len()].copy_from_slice(data);
        Some(Frame {
            id: id.into(),
            rtr: false,
            dlc: data.len() as u8,
            data: bytes,
            channel: Channel::A,
            timestamp: 0,
        })
    }

    /// A remote frame with DLC `dlc` (0..=15).
    pub fn remote_frame(id: impl Into<Id>, dlc: u8) -> Option<Frame> {
        (dlc <= 15).then(|| Frame {
            id: id.into(),
            rtr: true,
            dlc,
            data: [0; 8],
            channel: Channel::A,
            timestamp: 0,
        })
    }

    /// The frame as the registers encode it: raw identifier, `ide`, `rtr`, DLC,
    /// the eight data bytes. `None` if the identifier does not fit.
    pub fn from_raw(id: u32, ide: bool, rtr: bool, dlc: u8, data: [u8; 8]) -> Option<Frame> {
        let id = if ide {
            Id::Extended(ExtendedId::new(id)?)
        } else {
            Id::Standard(StandardId::new(u16::try_from(id).ok()?)?)
        };
        if dlc > 15 {
            return None;
        }
        let mut frame = Frame {
            id,
            rtr,
            dlc,
            data,
            channel: Channel::A,
            timestamp: 0,
        };
        let len = frame.len();
        frame.data[len..].fill(0);
        Some(frame)
    }

    /// The raw identifier (11 or 29 bits, right-aligned).
    pub fn raw_id(&self) -> u32 {
        match self.id {
            Id::Standard(s) => u32::from(s.as_raw()),
            Id::Extended(e) => e.as_raw(),
        }
    }

    /// The data length code as sent or received (0..=15).
    pub fn dlc_code(&self) -> u8 {
        self.dlc
    }

    /// The channel the frame was received on ([`Channel::A`] for a frame built here).
    pub fn channel(&self) -> Channel {
        self.channel
    }

    /// The same frame tagged with `channel`.
    pub fn with_channel(mut self, channel: Channel) -> Frame {
        self.channel = channel;
        self
    }

    /// For a received frame, `RX_TIME.rx_time`: the nominal bit time (16 bits,
    /// wrapping, the clock of [`crate::Drcc::now`]) at which it entered the RX
    /// FIFO; 0 for a frame built here. Its age is `now.wrapping_sub(timestamp)`.
    pub fn timestamp(&self) -> u16 {
        self.timestamp
    }

    /// The same frame with `timestamp`.
    pub fn with_timestamp(mut self, timestamp: u16) -> Frame {
        self.timestamp = timestamp;
        self
    }

    /// All eight data bytes as the registers hold them (bytes past the length 0).
    pub fn raw_data(&self) -> [u8; 8] {
        self.data
    }

    fn len(&self) -> usize {
        if self.rtr {
            0
        } else {
            usize::from(self.dlc.min(8))
        }
    }
}

impl PartialEq for Frame {
    fn eq(&self, other: &Frame) -> bool {
        (self.id, self.rtr, self.dlc, self.data, self.channel)
            == (other.id, other.rtr, other.dlc, other.data, other.channel)
    }
}

impl Eq for Frame {}

impl embedded_can::Frame for Frame {
    fn new(id: impl Into<Id>, data: &[u8]) -> Option<Self> {
        Frame::data_frame(id, data)
    }

    fn new_remote(id: impl Into<Id>, dlc: usize) -> Option<Self> {
        if dlc > 8 {
            return None;
        }
        Frame::remote_frame(id, dlc as u8)
    }

    fn is_extended(&self) -> bool {
        matches!(self.id, Id::Extended(_))
    }

    fn is_remote_frame(&self) -> bool {
        self.rtr
    }

    fn id(&self) -> Id {
        self.id
    }

    fn dlc(&self) -> usize {
        usize::from(self.dlc)
    }

    fn data(&self) -> &[u8] {
        &self.data[..self.len()]
    }
}
