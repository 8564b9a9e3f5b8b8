//! The candump log format (`candump -l`, can-utils `log` files), one event a line:
//!
//! ```text
//! (0.000123) node0 123#DEADBEEF
//! (0.000456) node1a 18FEF100#0102
//! (0.000789) node2 321#R
//! (0.001011) node0 20000088#0000880A00000800
//! ```
//!
//! `(seconds.microseconds) INTERFACE ID#DATA`: the identifier in upper-case hex, 3
//! digits for a base identifier and 8 for an extended one (the readers tell the
//! formats apart by the digit count); the data bytes in hex. A remote frame is
//! `ID#R`, followed by its DLC when it is 1..8 (`321#R4`): can-utils' `lib.c`
//! (`parse_canframe`) and python-can's `CanutilsLogReader` both read that. An error
//! frame is its 8-digit identifier with the error flag and its 8 data bytes. A DLC
//! above 8 cannot be written in a form both readers take: data frames show their 8
//! bytes, remote frames `R8`. python-can picks this reader for files named `*.log`.

use std::io::{self, Write};

use super::{timestamp, TrafficEvent, TrafficKind};
use crate::frame::Frame;

/// The `ID#DATA` part of a frame.
pub fn frame_text(f: &Frame) -> String {
    let mut s = if f.ide {
        format!("{:08X}#", f.id & 0x1FFF_FFFF)
    } else {
        format!("{:03X}#", f.id & 0x7FF)
    };
    if f.rtr {
        s.push('R');
        let dlc = f.dlc.min(8);
        if dlc > 0 {
            s.push_str(&dlc.to_string());
        }
    } else {
        hex(&mut s, &f.data[..f.data_len()]);
    }
    s
}

fn hex(s: &mut String, bytes: &[u8]) {
    for b in bytes {
        s.push_str(&format!("{b:02X}"));
    }
}

/// One log line of `ev` at `clock_hz`, without the newline.
pub fn line(ev: &TrafficEvent, clock_hz: u64) -> String {
    let (sec, ns) = timestamp(ev.cycle, clock_hz);
    let body = match &ev.kind {
        TrafficKind::Frame(f) => frame_text(f),
        TrafficKind::Error(e) => {
            let mut s = format!("{:08X}#", e.can_id);
            hex(&mut s, &e.data);
            s
        }
    };
    format!("({sec}.{:06}) {} {body}", ns / 1000, ev.interface())
}

/// Writes events as candump log lines.
#[derive(Debug)]
pub struct CandumpWriter<W: Write> {
    out: W,
    clock_hz: u64,
}

impl<W: Write> CandumpWriter<W> {
    /// A writer of events timed by `clock_hz` into `out`.
    pub fn new(out: W, clock_hz: u64) -> Self {
        CandumpWriter { out, clock_hz }
    }

    /// Writes one line.
    pub fn write(&mut self, ev: &TrafficEvent) -> io::Result<()> {
        writeln!(self.out, "{}", line(ev, self.clock_hz))
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
    use crate::traffic::ErrorFrame;

    fn ev(cycle: u64, node: usize, line: Option<u8>, kind: TrafficKind) -> TrafficEvent {
        TrafficEvent {
            cycle,
            node,
            line,
            kind,
        }
    }

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

    /// Lines written by hand from the format: `(sec.usec) iface ID#DATA`.
    #[test]
    fn lines_follow_the_candump_log_format() {
        let mut w = CandumpWriter::new(Vec::new(), 8_000_000);
        let events = [
            // 8 MHz: cycle 9_876_543 is 1.234567875 s, shown to the microsecond.
            ev(
                9_876_543,
                0,
                None,
                frame(0x123, false, false, 4, &[0xDE, 0xAD, 0xBE, 0xEF]),
            ),
            ev(8, 1, Some(0), frame(0x18FEF100, true, false, 2, &[1, 2])),
            ev(16, 2, Some(1), frame(0x321, false, true, 0, &[])),
            ev(24, 2, None, frame(0x7FF, false, true, 4, &[])),
            ev(32, 0, None, frame(0x5, true, false, 0, &[])),
            ev(
                40,
                0,
                None,
                frame(0x0A0, false, false, 12, &[1, 2, 3, 4, 5, 6, 7, 8]),
            ),
            ev(
                0,
                3,
                Some(0),
                TrafficKind::Error(ErrorFrame {
                    can_id: 0x2000_0088,
                    data: [0, 0, 0x88, 0x0A, 0, 0, 8, 0],
                }),
            ),
        ];
        for e in &events {
            w.write(e).unwrap();
        }
        let text = String::from_utf8(w.into_inner()).unwrap();
        assert_eq!(
            text,
            "(1.234567) node0 123#DEADBEEF\n\
             (0.000001) node1a 18FEF100#0102\n\
             (0.000002) node2b 321#R\n\
             (0.000003) node2 7FF#R4\n\
             (0.000004) node0 00000005#\n\
             (0.000005) node0 0A0#0102030405060708\n\
             (0.000000) node3a 20000088#0000880A00000800\n"
        );
    }
}
