//! Classic pcap files of link type `LINKTYPE_CAN_SOCKETCAN` (227), as Wireshark,
//! tshark and tcpdump read them.
//!
//! The global header uses the nanosecond magic `0xA1B23C4D` (one clock of an 8 MHz
//! node is 125 ns; microseconds would merge neighbouring bits), version 2.4, and is
//! written little-endian (readers take the byte order from the magic). Every record
//! is one 16-byte SocketCAN `can_frame`: the identifier and flags **big-endian**
//! (as the link type requires; `CAN_EFF_FLAG` 0x8000_0000 for an extended
//! identifier, `CAN_RTR_FLAG` 0x4000_0000 for a remote frame, `CAN_ERR_FLAG`
//! 0x2000_0000 for an error frame), the payload length (a remote frame: its DLC as
//! SocketCAN keeps it; an error frame: 8), the FD flags (0), a reserved byte (0),
//! `len8_dlc` (the DLC of a data frame whose DLC is 9..15, else 0), then 8 data
//! bytes, zero past the length.
//!
//! LINKTYPE 227 has no interface name per packet, so node and line are not in the
//! file: record n is the event of line n of the candump log of the same run
//! (`--candump`), which names them. Wireshark filters such as `can.id == 0x123` or
//! `can.flags.err` work on the whole capture.

use std::io::{self, Write};

use super::{timestamp, TrafficEvent, TrafficKind};

/// The link type of SocketCAN frames.
pub const LINKTYPE_CAN_SOCKETCAN: u32 = 227;
/// The magic of a classic pcap file with nanosecond timestamps.
pub const MAGIC_NANOSECONDS: u32 = 0xA1B2_3C4D;
/// Snapshot length of the header: larger than any record.
pub const SNAPLEN: u32 = 65_535;
/// Size of a `can_frame`, the length of every record.
pub const CAN_FRAME_LEN: usize = 16;

/// `CAN_EFF_FLAG` of `linux/can.h`: the identifier is an extended one.
pub const CAN_EFF_FLAG: u32 = 0x8000_0000;
/// `CAN_RTR_FLAG` of `linux/can.h`: a remote frame.
pub const CAN_RTR_FLAG: u32 = 0x4000_0000;

/// The 24-byte global header.
pub fn global_header() -> [u8; 24] {
    let mut h = [0u8; 24];
    h[0..4].copy_from_slice(&MAGIC_NANOSECONDS.to_le_bytes());
    h[4..6].copy_from_slice(&2u16.to_le_bytes());
    h[6..8].copy_from_slice(&4u16.to_le_bytes());
    // thiszone and sigfigs stay 0
    h[16..20].copy_from_slice(&SNAPLEN.to_le_bytes());
    h[20..24].copy_from_slice(&LINKTYPE_CAN_SOCKETCAN.to_le_bytes());
    h
}

/// The SocketCAN `can_frame` of a frame or an error frame.
pub fn can_frame(kind: &TrafficKind) -> [u8; CAN_FRAME_LEN] {
    let mut b = [0u8; CAN_FRAME_LEN];
    let (id, len, data) = match kind {
        TrafficKind::Frame(f) => {
            let f = f.normalized();
            let mut id = f.id;
            if f.ide {
                id |= CAN_EFF_FLAG;
            }
            if f.rtr {
                id |= CAN_RTR_FLAG;
            }
            let len = if f.rtr {
                f.dlc.min(8)
            } else {
                f.data_len() as u8
            };
            if !f.rtr && f.dlc > 8 {
                b[7] = f.dlc;
            }
            (id, len, f.data)
        }
        TrafficKind::Error(e) => (e.can_id, super::error::CAN_ERR_DLC, e.data),
    };
    b[0..4].copy_from_slice(&id.to_be_bytes());
    b[4] = len;
    b[8..16].copy_from_slice(&data);
    b
}

/// The record of `ev`: the 16-byte record header (seconds, nanoseconds, captured
/// and original length, little-endian) and the `can_frame`.
pub fn record(ev: &TrafficEvent, clock_hz: u64) -> [u8; 16 + CAN_FRAME_LEN] {
    let (sec, ns) = timestamp(ev.cycle, clock_hz);
    let mut r = [0u8; 16 + CAN_FRAME_LEN];
    r[0..4].copy_from_slice(&(sec as u32).to_le_bytes());
    r[4..8].copy_from_slice(&ns.to_le_bytes());
    r[8..12].copy_from_slice(&(CAN_FRAME_LEN as u32).to_le_bytes());
    r[12..16].copy_from_slice(&(CAN_FRAME_LEN as u32).to_le_bytes());
    r[16..].copy_from_slice(&can_frame(&ev.kind));
    r
}

/// Writes the global header, then one record per event.
#[derive(Debug)]
pub struct PcapWriter<W: Write> {
    out: W,
    clock_hz: u64,
}

impl<W: Write> PcapWriter<W> {
    /// Writes the global header into `out`; events are timed by `clock_hz`.
    pub fn new(mut out: W, clock_hz: u64) -> io::Result<Self> {
        out.write_all(&global_header())?;
        Ok(PcapWriter { out, clock_hz })
    }

    /// Writes one record.
    pub fn write(&mut self, ev: &TrafficEvent) -> io::Result<()> {
        self.out.write_all(&record(ev, self.clock_hz))
    }

    /// The output.
    pub fn get_mut(&mut self) -> &mut W {
        &mut self.out
    }

    /// Gives the output back (not flushed).
    pub fn into_inner(self) -> W {
        self.out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame::Frame;
    use crate::traffic::ErrorFrame;

    fn frame(id: u32, ide: bool, rtr: bool, dlc: u8, data: &[u8]) -> TrafficKind {
        let mut d = [0; 8];
        d[..data.len()].copy_from_slice(data);
        TrafficKind::Frame(Frame {
            id,
            ide,
            rtr,
            dlc,
            data: d,
        })
    }

    /// The header byte by byte from the pcap definition (little-endian fields).
    #[test]
    fn the_global_header_is_nanosecond_pcap_of_link_type_227() {
        let mut w = PcapWriter::new(Vec::new(), 8_000_000).unwrap();
        w.get_mut().flush().unwrap();
        assert_eq!(
            w.into_inner(),
            [
                0x4D, 0x3C, 0xB2, 0xA1, // magic 0xA1B23C4D, nanoseconds
                2, 0, 4, 0, // version 2.4
                0, 0, 0, 0, // thiszone
                0, 0, 0, 0, // sigfigs
                0xFF, 0xFF, 0, 0, // snaplen 65535
                227, 0, 0, 0, // LINKTYPE_CAN_SOCKETCAN
            ]
        );
    }

    /// One record: 8 MHz, cycle 12_000_001 = 1 s + 500_000_125 ns.
    #[test]
    fn a_base_frame_record() {
        let ev = TrafficEvent {
            cycle: 12_000_001,
            node: 0,
            line: None,
            kind: frame(0x123, false, false, 3, &[0x11, 0x22, 0x33]),
        };
        assert_eq!(
            record(&ev, 8_000_000),
            [
                1, 0, 0, 0, // seconds
                0x7D, 0x65, 0xCD, 0x1D, // 500_000_125 ns = 0x1DCD657D
                16, 0, 0, 0, // captured length
                16, 0, 0, 0, // original length
                0, 0, 0x01, 0x23, // identifier, big-endian
                3, 0, 0, 0, // length, FD flags, reserved, len8_dlc
                0x11, 0x22, 0x33, 0, 0, 0, 0, 0,
            ]
        );
    }

    #[test]
    fn extended_remote_and_error_frames() {
        assert_eq!(
            can_frame(&frame(0x18FEF100, true, false, 2, &[1, 2])),
            [0x98, 0xFE, 0xF1, 0x00, 2, 0, 0, 0, 1, 2, 0, 0, 0, 0, 0, 0]
        );
        assert_eq!(
            can_frame(&frame(0x321, false, true, 4, &[])),
            [0x40, 0, 0x03, 0x21, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
        );
        let e = TrafficKind::Error(ErrorFrame {
            can_id: 0x2000_02A0,
            data: [0, 0, 0, 0, 0, 0, 0x80, 0x01],
        });
        assert_eq!(
            can_frame(&e),
            [0x20, 0, 0x02, 0xA0, 8, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x80, 0x01]
        );
        // DLC 12: 8 bytes, the DLC kept in len8_dlc.
        let long = can_frame(&frame(0x7FF, false, false, 12, &[9; 8]));
        assert_eq!(long[..8], [0, 0, 0x07, 0xFF, 8, 0, 0, 12]);
    }
}
