//! The traffic of the test plan: every device sends its two messages alternately,
//! each frame due when the device's previous frames have used exactly its share of
//! the seed's 85 % average bus load.
//!
//! A frame's length on the bus is counted exactly, from SOF to the last EOF bit with
//! every stuff bit (the testbench's own encoder, [`crate::conformance::bits`]), plus
//! the 3-bit intermission that separates it from the next frame. With `N` devices and
//! a load of `L` %, each device's share is `L / N` %: the frame after one of `b` bits
//! is due `b x 100 N / L` bit times later (for 4 devices at 85 %: `b x 80 / 17`, about
//! 4.7 frame lengths). Due times accumulate exactly (no rounding drift): frame `k` of
//! a device is due at `start + floor(B_k x 800 N / L)` clocks, `B_k` the bits of its
//! frames before `k`.
//!
//! A frame names its sender and sequence number in its data (bytes 0..2), so every
//! delivery can be matched to its push, and a run to its fault-free baseline.

use drcc_cosim::Frame;

use super::marker::DEVICES;
use super::setup::{base_id, PlanConfig};
use super::{CLOCKS_PER_BIT, CLOCKS_PER_MS};
use crate::conformance::bits::FrameBits;

/// Bits between the end of a frame and the next start of frame (ISO 11898-1 10.4.5).
pub const INTERMISSION: u64 = 3;

/// The `seq`-th frame of device `device`: `Dd.M1` for even `seq`, `Dd.M2` for odd, 8
/// data bytes: device, sequence number (big endian), message number, then a fixed
/// pattern.
pub fn frame(device: usize, seq: u16) -> Frame {
    let m = (seq & 1) as u8;
    let [hi, lo] = seq.to_be_bytes();
    Frame {
        id: base_id(device) + m as u32,
        ide: false,
        rtr: false,
        dlc: 8,
        data: [device as u8, hi, lo, m + 1, 0x5A, 0xC3, 0x0F, 0x96],
    }
}

/// The (device, sequence number) a frame of the plan carries, if it is one.
pub fn decode(f: &Frame) -> Option<(usize, u16)> {
    let device = f.data[0] as usize;
    let seq = u16::from_be_bytes([f.data[1], f.data[2]]);
    (device < DEVICES.len() && *f == frame(device, seq)).then_some((device, seq))
}

/// Bus time of a frame in bit times: SOF to the last EOF bit, stuff bits included,
/// plus the intermission.
pub fn bus_bits(f: &Frame) -> u64 {
    FrameBits::new(f).len() as u64 + INTERMISSION
}

/// One frame a host submits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Submission {
    /// Clock at which it is due.
    pub due: u64,
    pub seq: u16,
    pub frame: Frame,
    /// Its bus time in bit times ([`bus_bits`]).
    pub bits: u64,
}

/// Every device's submissions in the traffic window of `c` (module docs). Device `d`
/// starts `d / 4` ms after the window opens, so the devices do not all start at once.
pub fn schedule(c: &PlanConfig) -> Vec<Vec<Submission>> {
    let n = DEVICES.len() as u64;
    let start = c.traffic_start_ms * CLOCKS_PER_MS;
    let end = c.traffic_end_ms * CLOCKS_PER_MS;
    (0..DEVICES.len())
        .map(|d| {
            let first = start + d as u64 * CLOCKS_PER_MS / 4;
            let mut out = Vec::new();
            let mut cum_bits = 0u64;
            for seq in 0..=u16::MAX {
                let due = first + cum_bits * CLOCKS_PER_BIT * 100 * n / c.load_percent;
                if due >= end {
                    break;
                }
                let f = frame(d, seq);
                let bits = bus_bits(&f);
                out.push(Submission {
                    due,
                    seq,
                    frame: f,
                    bits,
                });
                cum_bits += bits;
            }
            out
        })
        .collect()
}

/// The traffic of a schedule in numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadSummary {
    /// Per device: frames, mean frame length (bit times, intermission included),
    /// mean period (ms).
    pub devices: Vec<(usize, f64, f64)>,
    /// Offered load: the bus time of every frame due in the window over the window.
    pub load: f64,
    /// Shortest and longest frame, bit times.
    pub min_bits: u64,
    pub max_bits: u64,
}

/// Summarises `sched` over the traffic window of `c`.
pub fn summary(c: &PlanConfig, sched: &[Vec<Submission>]) -> LoadSummary {
    let window_bits = (c.traffic_end_ms - c.traffic_start_ms) * super::BITS_PER_MS;
    let all = || sched.iter().flatten();
    let devices = sched
        .iter()
        .map(|s| {
            let bits: u64 = s.iter().map(|x| x.bits).sum();
            let span = s.last().map_or(0, |l| l.due) - s.first().map_or(0, |f| f.due);
            let periods = s.len().saturating_sub(1).max(1);
            (
                s.len(),
                bits as f64 / s.len().max(1) as f64,
                super::ms(span) / periods as f64,
            )
        })
        .collect();
    LoadSummary {
        devices,
        load: all().map(|x| x.bits).sum::<u64>() as f64 / window_bits as f64,
        min_bits: all().map(|x| x.bits).min().unwrap_or(0),
        max_bits: all().map(|x| x.bits).max().unwrap_or(0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_decode_to_their_sender_and_sequence_number() {
        for d in 0..4 {
            for seq in [0u16, 1, 255, 256, 65535] {
                let f = frame(d, seq);
                assert_eq!(decode(&f), Some((d, seq)));
                assert_eq!(f.id & 1, seq as u32 & 1, "M1 even, M2 odd");
            }
        }
        let mut f = frame(1, 7);
        f.data[7] ^= 1;
        assert_eq!(decode(&f), None);
    }

    #[test]
    fn frame_length_counts_stuff_bits() {
        // A base data frame with 8 data bytes is 44 + 64 = 108 bits without stuff
        // bits (ISO 11898-1), plus 3 bits of intermission; stuff bits only add.
        for d in 0..4 {
            for seq in 0..64 {
                let b = bus_bits(&frame(d, seq));
                assert!((111..=111 + 24).contains(&b), "{b}");
            }
        }
        // An all-zero identifier and data stuff at every fifth bit.
        let zeros = Frame {
            id: 0,
            ide: false,
            rtr: false,
            dlc: 8,
            data: [0; 8],
        };
        assert!(bus_bits(&zeros) > 111 + 15);
    }

    #[test]
    fn the_schedule_offers_the_seeds_85_percent() {
        let c = PlanConfig::standard();
        let sched = schedule(&c);
        let s = summary(&c, &sched);
        assert!((s.load - 0.85).abs() < 0.002, "offered load {}", s.load);
        for dev in &sched {
            for w in dev.windows(2) {
                // Frame k+1 is due b_k x 80/17 bit times after frame k.
                let gap = (w[1].due - w[0].due) as f64 / CLOCKS_PER_BIT as f64;
                assert!((gap - w[0].bits as f64 * 80.0 / 17.0).abs() <= 1.0);
            }
        }
    }
}
