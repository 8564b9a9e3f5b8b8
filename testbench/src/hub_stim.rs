//! Random stimulus for one hub alone (the lock-step sign-off of `hub.v` against the
//! model): the hub's node ports and incoming sublinks are driven with what a CAN
//! network puts on them — idle gaps, correctly stuffed frames with a valid CRC
//! (this crate's own encoder, `conformance::bits`) from a random port, ACKs from a
//! random set of other ports, frames with reserved identifiers, error-flag-like
//! dominant bursts, stuck-at and bit-flipping ports, a per-port phase skew of a few
//! clocks — and its Wishbone slave with random register accesses, legal and illegal,
//! including the decoupling commands and reset mode.
//!
//! The generator is open-loop on the links and only waits for `wb_ack_o` on the
//! Wishbone side, so two engines that agree clock by clock get identical stimulus.

use crate::conformance::bits::FrameBits;
use crate::random::SplitMix64;
use drcc_cosim::engine::hub::{HubInputs, HubOutputs};
use drcc_cosim::Frame;
use std::collections::VecDeque;

/// Clocks per bit of the stimulus: BRP 0, TSEG1 5, TSEG2 2 (the hub's BTR is
/// written to match).
pub const STIM_CLOCKS_PER_BIT: u64 = 8;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PortFault {
    None,
    StuckDominant,
    StuckRecessive,
    Flip,
}

/// Random stimulus for a hub with `n` node ports and `m` interlinks.
pub struct HubStim {
    rng: SplitMix64,
    n: usize,
    m: usize,
    /// Per port: bit values still to send (1 = recessive), one per bit time.
    lanes: Vec<VecDeque<bool>>,
    /// Per port: delay line of the port's value (phase skew, in clocks).
    skew: Vec<usize>,
    history: Vec<VecDeque<bool>>,
    faults: Vec<(PortFault, u64)>,
    clock_in_bit: u64,
    /// Wishbone: the access in progress and an idle count before the next one.
    wb: Option<(bool, u8, u32, u8)>,
    wb_idle: u64,
    setup: VecDeque<(u8, u32)>,
    pub cycle: u64,
}

impl HubStim {
    /// A generator from a seed; the first accesses configure the hub with small
    /// thresholds so that isolations, restorations and decoupling happen often.
    pub fn new(seed: u64, n: usize, m: usize) -> Self {
        let mut rng = SplitMix64::new(seed);
        let ports = n + m;
        let skew = (0..ports).map(|_| rng.below(4) as usize).collect();
        let restore = 40 + rng.below(200) as u32;
        let decouple = 60 + rng.below(400) as u32;
        let setup = VecDeque::from(vec![
            (1, 1 | (rng.below(2) as u32) << 8), // CTRL: reset mode, ack_interdep
            (2, (4 << 6) | (1 << 10) | (rng.below(2) as u32) << 13), // BTR: 8 tq, SJW 1 or 2
            (
                3,
                (14 + rng.below(4) as u32)
                    | ((14 + rng.below(6) as u32) << 8)
                    | ((1 + rng.below(4) as u32) << 16),
            ),
            (
                4,
                (8 + rng.below(24) as u32) | ((8 + rng.below(40) as u32) << 8),
            ),
            (5, restore | decouple << 16),
            (8, 0xF),
            (1, rng.below(2) as u32 * 0x100), // leave reset mode
        ]);
        HubStim {
            rng,
            n,
            m,
            lanes: vec![VecDeque::new(); ports],
            skew,
            history: vec![VecDeque::from(vec![true; 4]); ports],
            faults: vec![(PortFault::None, 0); ports],
            clock_in_bit: 0,
            wb: None,
            wb_idle: 20,
            setup,
            cycle: 0,
        }
    }

    fn ports(&self) -> usize {
        self.n + self.m
    }

    /// Schedules the next bus episode once every lane is empty.
    fn schedule(&mut self) {
        let ports = self.ports();
        let r = self.rng.below(100);
        let gap = if self.rng.percent(80) {
            10 + self.rng.below(6) as usize
        } else {
            self.rng.below(12) as usize
        };
        for lane in self.lanes.iter_mut() {
            lane.extend(std::iter::repeat_n(true, gap));
        }
        if r < 75 {
            // A frame from a random port, ACKed by a random set of the others.
            let tx = self.rng.below(ports as u64) as usize;
            let ide = self.rng.percent(30);
            let id = if self.rng.percent(8) {
                self.rng.below(2) as u32
            } else if ide {
                self.rng.next_u64() as u32 & 0x1FFF_FFFF
            } else {
                self.rng.below(0x7F0) as u32
            };
            let mut data = [0u8; 8];
            for d in data.iter_mut() {
                *d = self.rng.next_u64() as u8;
            }
            let f = Frame {
                id,
                ide,
                rtr: self.rng.percent(10),
                dlc: self.rng.below(16) as u8,
                data,
            };
            let bits = FrameBits::new(&f).values();
            let ack = bits.len() - 9; // ACK slot: before ACK delimiter + 7 EOF bits
            let corrupt = if self.rng.percent(15) {
                Some((
                    self.rng.below(ports as u64) as usize,
                    1 + self.rng.below(ack as u64 - 1) as usize,
                ))
            } else {
                None
            };
            for p in 0..ports {
                let mut v: Vec<bool> = if p == tx {
                    bits.clone()
                } else {
                    let mut v = vec![true; bits.len()];
                    if self.rng.percent(70) {
                        v[ack] = false;
                    }
                    v
                };
                if let Some((cp, at)) = corrupt {
                    if cp == p {
                        v[at] = !v[at];
                        if self.rng.percent(50) {
                            // An error flag after the corruption.
                            for b in v.iter_mut().skip(at + 1).take(6) {
                                *b = false;
                            }
                        }
                    }
                }
                self.lanes[p].extend(v);
            }
        } else if r < 85 {
            // Error-flag-like dominant bursts on a few ports.
            let len = 1 + self.rng.below(14) as usize;
            for p in 0..ports {
                let burst = self.rng.percent(40);
                self.lanes[p].extend(std::iter::repeat_n(!burst, len));
            }
        } else {
            // A fault on one port for a while.
            let p = self.rng.below(ports as u64) as usize;
            let kind = match self.rng.below(3) {
                0 => PortFault::StuckDominant,
                1 => PortFault::StuckRecessive,
                _ => PortFault::Flip,
            };
            let bits = 5 + self.rng.below(60);
            self.faults[p] = (kind, bits * STIM_CLOCKS_PER_BIT);
        }
        // Equalize the lanes.
        let len = self.lanes.iter().map(|l| l.len()).max().unwrap_or(0);
        for lane in self.lanes.iter_mut() {
            while lane.len() < len {
                lane.push_back(true);
            }
        }
    }

    /// The inputs of the next clock, given the hub's outputs of the previous one.
    pub fn next(&mut self, prev: &HubOutputs) -> HubInputs {
        let mut i = HubInputs {
            rst: self.cycle < 4,
            ..HubInputs::default()
        };
        if self.clock_in_bit == 0 {
            if self.lanes[0].is_empty() {
                self.schedule();
            }
            for lane in self.lanes.iter_mut() {
                lane.pop_front();
            }
        }
        let mut up = 0xFFFFu16;
        let mut sub = 0xFFu8;
        for p in 0..self.ports() {
            let nominal = self.lanes[p].front().copied().unwrap_or(true);
            let mut v = nominal;
            let (kind, left) = self.faults[p];
            if left > 0 {
                v = match kind {
                    PortFault::StuckDominant => false,
                    PortFault::StuckRecessive => true,
                    PortFault::Flip => {
                        if (left / STIM_CLOCKS_PER_BIT).is_multiple_of(5) {
                            !v
                        } else {
                            v
                        }
                    }
                    PortFault::None => v,
                };
                self.faults[p].1 -= 1;
            }
            let h = &mut self.history[p];
            h.push_back(v);
            let out = h[h.len() - 1 - self.skew[p]];
            h.pop_front();
            if !out {
                if p < self.n {
                    up &= !(1 << p);
                } else {
                    sub &= !(1 << (p - self.n));
                }
            }
        }
        i.uplink = up;
        i.sublink_in = sub;
        self.clock_in_bit = (self.clock_in_bit + 1) % STIM_CLOCKS_PER_BIT;
        // Wishbone.
        if !i.rst {
            if let Some((w, a, d, sel)) = self.wb {
                if prev.wb_ack || prev.wb_err {
                    self.wb = None;
                    self.wb_idle = self.rng.below(if self.setup.is_empty() { 400 } else { 2 });
                } else {
                    i.wb_cyc = true;
                    i.wb_stb = true;
                    i.wb_we = w;
                    i.wb_adr = a;
                    i.wb_dat_w = d;
                    i.wb_sel = sel;
                }
            } else if self.wb_idle > 0 {
                self.wb_idle -= 1;
            } else {
                let op = if let Some((a, d)) = self.setup.pop_front() {
                    (true, a, d, 0xF)
                } else {
                    let write = self.rng.percent(30);
                    let adr = if self.rng.percent(80) {
                        self.rng.below(10) as u8
                    } else if self.rng.percent(80) {
                        16 + self.rng.below(self.ports() as u64 + 1) as u8
                    } else {
                        self.rng.below(64) as u8
                    };
                    let mut data = self.rng.next_u64() as u32;
                    if write && adr == 1 {
                        // CTRL: mostly commands while running, rarely reset mode.
                        data &= 0x106;
                        if self.rng.percent(5) {
                            data |= 1;
                        }
                    }
                    if write && adr == 2 && self.rng.percent(80) {
                        data = (4 << 6) | (1 << 10);
                    }
                    if write && adr == 7 {
                        data &= 0xF;
                    }
                    // a write in 13 with partial byte lanes, from the data bits so
                    // that the random stream stays the one the seeds were chosen on
                    let sel = if write && data.is_multiple_of(13) {
                        ((data >> 4) & 0xF) as u8
                    } else {
                        0xF
                    };
                    (write, adr, data, sel)
                };
                self.wb = Some(op);
                i.wb_cyc = true;
                i.wb_stb = true;
                i.wb_we = op.0;
                i.wb_adr = op.1;
                i.wb_dat_w = op.2;
                i.wb_sel = op.3;
            }
        }
        self.cycle += 1;
        i
    }
}
