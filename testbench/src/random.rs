//! Random CAN traffic: a seeded generator (SplitMix64, no dependencies) producing
//! scenarios of N random frames — random base and extended identifiers, data and
//! remote frames, DLC 0..=15, random data — sent by random nodes, with bursts where
//! two or three nodes start at the same clock (contested arbitration) and random
//! gaps (sometimes none, so frames queue up back to back).
//!
//! The (identifier, format) pairs are unique within a scenario: two frames with
//! the same arbitration field sent at the same time by two nodes would collide in
//! the data field (a bit error, by design of CAN), which is not what random
//! traffic is meant to test.

use std::collections::HashSet;

use drcc_cosim::Frame;

use crate::bitrate;
use crate::scenario::{Expectations, Scenario, ScheduledFrame};

/// SplitMix64 (Steele, Lea, Flood 2014): tiny, fast, good enough for test traffic.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n` (0 if n is 0).
    pub fn below(&mut self, n: u64) -> u64 {
        if n == 0 {
            0
        } else {
            ((self.next_u64() as u128 * n as u128) >> 64) as u64
        }
    }

    /// True with probability `percent` / 100.
    pub fn percent(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }
}

/// Parameters of random traffic.
#[derive(Clone, Debug)]
pub struct Traffic {
    /// Seed.
    pub seed: u64,
    /// Number of frames.
    pub frames: usize,
    /// Number of nodes (at least 1).
    pub nodes: usize,
    /// Clock frequency.
    pub clock_hz: u64,
    /// Bit rate (solved into a bit timing).
    pub bitrate: u64,
    /// Largest gap between bursts, in bit times.
    pub max_gap_bits: u64,
    /// Percentage of bursts where 2 or 3 nodes start at the same clock.
    pub simultaneous_percent: u64,
    /// Percentage of extended frames.
    pub extended_percent: u64,
    /// Percentage of remote frames.
    pub remote_percent: u64,
    /// Largest DLC drawn (0..=15).
    pub max_dlc: u8,
    /// Remote frames always have DLC 0.
    pub remote_dlc_zero: bool,
}

impl Traffic {
    /// Defaults: 3 nodes, gaps up to 200 bits, 40 % simultaneous bursts, half of
    /// the frames extended, a fifth remote.
    pub fn new(seed: u64, frames: usize, clock_hz: u64, bitrate: u64) -> Self {
        Traffic {
            seed,
            frames,
            nodes: 3,
            clock_hz,
            bitrate,
            max_gap_bits: 200,
            simultaneous_percent: 40,
            extended_percent: 50,
            remote_percent: 20,
            max_dlc: 15,
            remote_dlc_zero: false,
        }
    }

    /// Restricts the traffic to what sigrok's CAN decoder reads correctly
    /// (libsigrokdecode 0.5: DLC 0..=8, remote frames with DLC 0).
    pub fn sigrok_decodable(mut self) -> Self {
        self.max_dlc = 8;
        self.remote_dlc_zero = true;
        self
    }

    /// Generates the scenario (expectation: every frame to every other node).
    pub fn scenario(&self) -> Result<Scenario, String> {
        if self.nodes == 0 {
            return Err("random traffic needs at least one node".to_string());
        }
        let timing = bitrate::solve(self.clock_hz, self.bitrate)?;
        let cpb = timing.clocks_per_bit() as u64;
        let mut rng = SplitMix64::new(self.seed);
        let mut used: HashSet<(u32, bool)> = HashSet::new();
        let mut frames = Vec::with_capacity(self.frames);
        // First burst after the nodes have integrated (11 bits) and a little more.
        let mut t = 20 * cpb + rng.below(cpb);
        while frames.len() < self.frames {
            let mut k = 1;
            if self.nodes > 1 && rng.percent(self.simultaneous_percent) {
                k = 2 + rng.below(2.min(self.nodes as u64 - 1)) as usize;
            }
            k = k.min(self.frames - frames.len());
            let mut senders: Vec<usize> = (0..self.nodes).collect();
            for _ in 0..k {
                let j = rng.below(senders.len() as u64) as usize;
                let node = senders.swap_remove(j);
                let frame = self.frame(&mut rng, &mut used);
                frames.push(ScheduledFrame {
                    node,
                    at_cycle: t,
                    frame,
                    single_shot: false,
                });
            }
            // Gap: none a quarter of the time (back-to-back), else random, at a
            // random phase within the bit.
            let gap_bits = if rng.percent(25) {
                0
            } else {
                rng.below(self.max_gap_bits + 1)
            };
            t += gap_bits * cpb + rng.below(cpb) + 1;
        }
        let max_cycles = Scenario::default_max_cycles(&frames, cpb);
        Ok(Scenario {
            name: format!("random-{}-{}-{}", self.seed, self.clock_hz, self.bitrate),
            description: format!(
                "{} random frames, {} nodes, seed {}, {} Hz clock, {} bit/s",
                self.frames, self.nodes, self.seed, self.clock_hz, self.bitrate
            ),
            source: format!("random traffic (seed {})", self.seed),
            clock_hz: self.clock_hz,
            timing,
            nodes: (0..self.nodes).map(|i| format!("node{i}")).collect(),
            configs: vec![drcc_cosim::ControllerConfig::default(); self.nodes],
            frames,
            expect: Expectations::EveryFrameToEveryOtherNode,
            faults: Vec::new(),
            aborts: Vec::new(),
            max_cycles,
            reset_cycles: drcc_cosim::system::DEFAULT_RESET_CYCLES,
        })
    }

    fn frame(&self, rng: &mut SplitMix64, used: &mut HashSet<(u32, bool)>) -> Frame {
        let mut ide = rng.percent(self.extended_percent);
        let mut tries = 0;
        let id = loop {
            let id = if ide {
                rng.next_u64() as u32 & 0x1FFF_FFFF
            } else {
                rng.next_u64() as u32 & 0x7FF
            };
            if used.insert((id, ide)) {
                break id;
            }
            tries += 1;
            if tries > 64 {
                // The base identifier space is crowded: use an extended one.
                ide = true;
            }
        };
        let rtr = rng.percent(self.remote_percent);
        let mut dlc = rng.below(self.max_dlc.min(15) as u64 + 1) as u8;
        if rtr && self.remote_dlc_zero {
            dlc = 0;
        }
        let mut f = Frame {
            id,
            ide,
            rtr,
            dlc,
            data: [0; 8],
        };
        let n = f.data_len();
        for b in f.data[..n].iter_mut() {
            *b = rng.next_u64() as u8;
        }
        f
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix_reference_values() {
        // First outputs for seed 1234567 (reference implementation).
        let mut r = SplitMix64::new(1234567);
        assert_eq!(r.next_u64(), 6457827717110365317);
        assert_eq!(r.next_u64(), 3203168211198807973);
    }

    #[test]
    fn traffic_is_deterministic_and_varied() {
        let t = Traffic::new(42, 300, 8_000_000, 500_000);
        let a = t.scenario().unwrap();
        assert_eq!(a, t.scenario().unwrap());
        assert_eq!(a.frames.len(), 300);
        let f = |p: &dyn Fn(&ScheduledFrame) -> bool| a.frames.iter().filter(|x| p(x)).count();
        assert!(f(&|x| x.frame.ide) > 50);
        assert!(f(&|x| !x.frame.ide) > 50);
        assert!(f(&|x| x.frame.rtr) > 20);
        assert!(f(&|x| x.frame.dlc > 8) > 20);
        assert!(f(&|x| x.frame.dlc == 0) > 3);
        // Simultaneous starts by different nodes.
        let simultaneous = a
            .frames
            .windows(2)
            .filter(|w| w[0].at_cycle == w[1].at_cycle && w[0].node != w[1].node)
            .count();
        assert!(simultaneous > 30, "{simultaneous}");
        let triples = a
            .frames
            .windows(3)
            .filter(|w| w[0].at_cycle == w[2].at_cycle)
            .count();
        assert!(triples > 5, "{triples}");
        for x in &a.frames {
            assert_eq!(x.frame, x.frame.normalized());
        }
        let mut keys: Vec<(u32, bool)> =
            a.frames.iter().map(|x| (x.frame.id, x.frame.ide)).collect();
        keys.sort();
        keys.dedup();
        assert_eq!(keys.len(), 300);
    }
}
