//! Random fault plans for error-stress runs: bit flips, glitches, stuck-dominant
//! and stuck-recessive windows on the line and on single nodes' transmitters and
//! receivers (the fault kinds of [`drcc_cosim::bus`]), drawn from a seed.
//!
//! Some faults are aimed: a glitch at one node's next sample point, a flipped bit
//! in a chosen field (ACK slot, EOF, intermission, error flag or delimiter, ...),
//! a stuck-dominant line in the middle of a frame, held until its transmitter is
//! bus-off, a dead transmitter or receiver on a node that has a frame pending. To
//! aim them the generator runs the scenario on the reference model (the
//! *planner*) and adds each fault while the planner is still before it: a fault
//! never acts in the planner's past, so a system built from the scenario with the
//! final fault list replays the planner's run exactly (the model is
//! deterministic). Aiming uses only the probes every engine has (`sample_point`,
//! `field`, `err_state`, `tx_pending`).
//!
//! Faults start in `[first_cycle, last_cycle)`; after [`FaultPlan::end`] the bus
//! is fault free.

use std::collections::BTreeMap;

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::model::field;
use drcc_cosim::system::System;

use crate::engines::EngineKind;
use crate::random::SplitMix64;
use crate::run::build_system;
use crate::scenario::Scenario;

/// The fault events the generator draws. One event adds one fault
/// ([`FaultEvent::BusOff`] may add a few consecutive ones).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum FaultEvent {
    /// The line inverted for one bit time, at a random phase.
    BitFlip,
    /// The bit one node samples next, in a chosen field, inverted (or forced) on
    /// the line or at that node's receiver only.
    FieldFlip,
    /// An inversion (sometimes a forced dominant) shorter than half a bit, at a
    /// random time, on the line, a transmitter or a receiver.
    Glitch,
    /// A glitch of one or two time quanta around one node's next sample point.
    SampleGlitch,
    /// One node's receiver inverted for one to three bit times.
    RxFlip,
    /// Stuck dominant for 1 to 16 bit times (line or one transmitter).
    ShortDominant,
    /// Stuck dominant for 17 to 300 bit times (line or one transmitter): error
    /// flags overrun by dominant bits, counters up by 8 every 8 bits (rule f),
    /// receivers error passive.
    LongDominant,
    /// Stuck recessive for 1 to 40 bit times (line, one transmitter or one receiver).
    StuckRecessive,
    /// The line (or one transmitter) stuck dominant while a frame is in progress,
    /// in windows of 150 bit times until some node is bus-off: the transmitter's
    /// error flag is followed by dominant bits, TEC + 8 every 8 of them (rules c
    /// and f) past 255; the receivers' REC climbs the same way (error passive).
    BusOff,
    /// A node with a frame pending loses its transmitter or its receiver (stuck
    /// recessive) for 20 to 400 bit times: every dominant bit it sends is read
    /// back recessive.
    DeadNode,
}

impl FaultEvent {
    /// Every event, in report order.
    pub const ALL: [FaultEvent; 10] = [
        FaultEvent::BitFlip,
        FaultEvent::FieldFlip,
        FaultEvent::Glitch,
        FaultEvent::SampleGlitch,
        FaultEvent::RxFlip,
        FaultEvent::ShortDominant,
        FaultEvent::LongDominant,
        FaultEvent::StuckRecessive,
        FaultEvent::BusOff,
        FaultEvent::DeadNode,
    ];

    /// Short name for reports.
    pub fn name(self) -> &'static str {
        match self {
            FaultEvent::BitFlip => "bit_flip",
            FaultEvent::FieldFlip => "field_flip",
            FaultEvent::Glitch => "glitch",
            FaultEvent::SampleGlitch => "sample_glitch",
            FaultEvent::RxFlip => "rx_flip",
            FaultEvent::ShortDominant => "short_dominant",
            FaultEvent::LongDominant => "long_dominant",
            FaultEvent::StuckRecessive => "stuck_recessive",
            FaultEvent::BusOff => "bus_off",
            FaultEvent::DeadNode => "dead_node",
        }
    }
}

/// Fields a [`FaultEvent::FieldFlip`] aims at, with how many further bits (at
/// most) it may skip into the field before flipping.
const AIMED_FIELDS: [(u8, u64); 21] = [
    (field::IDLE, 0),
    (field::ID_A, 10),
    (field::SRR_RTR, 0),
    (field::IDE, 0),
    (field::ID_B, 17),
    (field::RTR_EXT, 0),
    (field::R0, 0),
    (field::DLC, 3),
    (field::DATA, 30),
    (field::CRC, 14),
    (field::CRC_DELIM, 0),
    (field::ACK_SLOT, 0),
    (field::ACK_DELIM, 0),
    (field::EOF, 6),
    (field::INTERMISSION, 2),
    (field::SUSPEND, 7),
    (field::ERROR_FLAG, 5),
    (field::ERROR_DELIM, 7),
    (field::OVERLOAD_FLAG, 5),
    (field::OVERLOAD_DELIM, 7),
    (field::BUS_OFF, 60),
];

/// Parameters of a fault plan.
#[derive(Clone, Debug)]
pub struct FaultParams {
    /// Seed of the fault generator (independent of the traffic seed).
    pub seed: u64,
    /// No fault acts before this cycle.
    pub first_cycle: u64,
    /// No fault starts at or after this cycle (a long one may last beyond it).
    pub last_cycle: u64,
    /// Gap between two events, in bit times, drawn uniformly from this range
    /// (counted from the end of a long stuck window or a bus-off window).
    pub gap_bits: (u64, u64),
    /// Relative weights of the randomly drawn events.
    pub weights: Vec<(FaultEvent, u32)>,
    /// Events placed in any case, at these fractions (0..1) of the fault window.
    pub forced: Vec<(f64, FaultEvent)>,
    /// Longest [`FaultEvent::BusOff`] window, in bit times (it ends at the first
    /// 150-bit chunk after which a node is bus-off).
    pub max_attack_bits: u64,
}

impl FaultParams {
    /// Default mix: mostly single flips and glitches, some stuck windows, rare
    /// long stuck-dominant windows, dead nodes and bus-off windows.
    pub fn new(seed: u64, first_cycle: u64, last_cycle: u64) -> Self {
        FaultParams {
            seed,
            first_cycle,
            last_cycle,
            gap_bits: (5, 150),
            weights: vec![
                (FaultEvent::BitFlip, 20),
                (FaultEvent::FieldFlip, 30),
                (FaultEvent::Glitch, 15),
                (FaultEvent::SampleGlitch, 15),
                (FaultEvent::RxFlip, 8),
                (FaultEvent::ShortDominant, 6),
                (FaultEvent::LongDominant, 2),
                (FaultEvent::StuckRecessive, 6),
                (FaultEvent::BusOff, 1),
                (FaultEvent::DeadNode, 2),
            ],
            forced: Vec::new(),
            max_attack_bits: 900,
        }
    }
}

/// A generated fault plan.
#[derive(Clone, Debug, Default)]
pub struct FaultPlan {
    /// The faults, in order of their start.
    pub faults: Vec<Fault>,
    /// Every event drawn: (cycle it was placed at, event).
    pub events: Vec<(u64, FaultEvent)>,
    /// First cycle at which no fault is active any more (the bus is fault free
    /// from here on).
    pub end: u64,
    /// Bus-off entries the planner saw while faults were placed (a hint only:
    /// the test checks the real run).
    pub planner_bus_offs: usize,
    /// The cycle the planner ran to. A replay with frames due after it differs
    /// from the planner only from then on, so the traffic may be extended or cut
    /// there without moving any aimed fault.
    pub planned_until: u64,
}

impl FaultPlan {
    /// Number of events of one kind.
    pub fn count(&self, e: FaultEvent) -> usize {
        self.events.iter().filter(|(_, x)| *x == e).count()
    }

    /// Events by kind, for reports.
    pub fn summary(&self) -> String {
        let mut m: BTreeMap<FaultEvent, usize> = BTreeMap::new();
        for (_, e) in &self.events {
            *m.entry(*e).or_default() += 1;
        }
        m.iter()
            .map(|(e, n)| format!("{} {n}", e.name()))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// Draws a fault plan for the scenario (its frames, timing and faults already
/// present are respected; the returned faults are the new ones only).
pub fn plan(sc: &Scenario, params: &FaultParams) -> Result<FaultPlan, String> {
    if params.last_cycle <= params.first_cycle {
        return Err(format!(
            "empty fault window {}..{}",
            params.first_cycle, params.last_cycle
        ));
    }
    let sys = build_system(sc, EngineKind::Model)?;
    let t = sc.timing;
    let tq = t.brp as u64 + 1;
    let mut p = Planner {
        nodes: sys.nodes(),
        err_state: vec![0; sys.nodes()],
        sys,
        rng: SplitMix64::new(params.seed ^ 0xFA17_5EED_0000_0000),
        cpb: sc.clocks_per_bit(),
        tq,
        sjw: t.sjw.min(t.tseg2) as u64 * tq,
        triple: t.triple_sampling,
        plan: FaultPlan::default(),
    };
    let total_weight: u64 = params.weights.iter().map(|w| w.1 as u64).sum();
    if total_weight == 0 && params.forced.is_empty() {
        return Err("no fault events to draw: every weight is 0".to_string());
    }
    let window = params.last_cycle - params.first_cycle;
    let mut forced: Vec<(u64, FaultEvent)> = params
        .forced
        .iter()
        .map(|&(f, e)| {
            (
                params.first_cycle + (window as f64 * f.clamp(0.0, 1.0)) as u64,
                e,
            )
        })
        .collect();
    forced.sort_by_key(|x| std::cmp::Reverse(x.0));
    let mut next = params.first_cycle;
    loop {
        let (lo, hi) = params.gap_bits;
        let gap = (lo + p.rng.below(hi.saturating_sub(lo) + 1)) * p.cpb + p.rng.below(p.cpb);
        next = next.max(p.sys.cycle()) + gap;
        let event = match forced.last() {
            Some(&(at, e)) if at <= next => {
                forced.pop();
                next = next.max(at);
                e
            }
            _ if total_weight == 0 => match forced.pop() {
                Some((at, e)) => {
                    next = next.max(at);
                    e
                }
                None => break,
            },
            _ => {
                let mut r = p.rng.below(total_weight);
                let mut pick = params.weights[0].0;
                for &(e, w) in &params.weights {
                    if r < w as u64 {
                        pick = e;
                        break;
                    }
                    r -= w as u64;
                }
                pick
            }
        };
        if next >= params.last_cycle {
            break;
        }
        p.advance_to(next);
        let busy_until = p.event(event, params);
        next = next.max(busy_until);
    }
    p.plan.faults.sort_by_key(|f| (f.start, f.cycles));
    p.plan.end = p.plan.faults.iter().map(|f| f.end()).max().unwrap_or(0);
    p.plan.planned_until = p.sys.cycle();
    Ok(p.plan)
}

struct Planner {
    sys: System,
    nodes: usize,
    err_state: Vec<u8>,
    rng: SplitMix64,
    cpb: u64,
    tq: u64,
    sjw: u64,
    triple: bool,
    plan: FaultPlan,
}

impl Planner {
    fn step(&mut self) {
        let s = self.sys.step();
        for (i, o) in s.outputs.iter().enumerate() {
            let e = o.probes.err_state;
            if e == 2 && self.err_state[i] != 2 {
                self.plan.planner_bus_offs += 1;
            }
            self.err_state[i] = e;
        }
    }

    fn advance_to(&mut self, cycle: u64) {
        while self.sys.cycle() < cycle {
            self.step();
        }
    }

    /// Steps until node `n`'s next sample point; returns its cycle (the SAMPLE
    /// edge reads the `rx` of two cycles before), or `None` at `limit`.
    fn next_sample(&mut self, n: usize, limit: u64) -> Option<u64> {
        while self.sys.cycle() < limit {
            self.step();
            if self.sys.sample().outputs[n].probes.sample_point {
                return Some(self.sys.sample().cycle);
            }
        }
        None
    }

    fn add(
        &mut self,
        event: FaultEvent,
        target: FaultTarget,
        kind: FaultKind,
        start: u64,
        cycles: u64,
    ) {
        // Never in the planner's past: the replay must see exactly what it saw.
        let start = start.max(self.sys.cycle());
        let f = Fault {
            target,
            kind,
            start,
            cycles: cycles.max(1),
        };
        self.sys
            .add_fault(f)
            .expect("fault targets are drawn from the node range");
        self.plan.faults.push(f);
        self.plan.events.push((start, event));
    }

    fn node(&mut self) -> usize {
        self.rng.below(self.nodes as u64) as usize
    }

    fn range(&mut self, lo: u64, hi: u64) -> u64 {
        lo + self.rng.below(hi.saturating_sub(lo) + 1)
    }

    /// Places one event at the planner's current cycle; returns the cycle until
    /// which the next event should wait.
    fn event(&mut self, event: FaultEvent, params: &FaultParams) -> u64 {
        let now = self.sys.cycle();
        let cpb = self.cpb;
        match event {
            FaultEvent::BitFlip => {
                let start = now + self.rng.below(cpb);
                self.add(event, FaultTarget::Bus, FaultKind::Flip, start, cpb);
                now
            }
            FaultEvent::FieldFlip => self.field_flip(event, now),
            FaultEvent::Glitch => self.glitch(event, now),
            FaultEvent::SampleGlitch => self.sample_glitch(event, now),
            FaultEvent::RxFlip => {
                let n = self.node();
                let bits = self.range(1, 3);
                let start = now + self.rng.below(cpb);
                let len = bits * cpb + self.rng.below(cpb);
                self.add(event, FaultTarget::Rx(n), FaultKind::Flip, start, len);
                now
            }
            FaultEvent::ShortDominant => {
                let target = if self.rng.percent(60) {
                    FaultTarget::Bus
                } else {
                    FaultTarget::Tx(self.node())
                };
                let len = self.range(1, 16) * cpb + self.rng.below(cpb);
                let start = now + self.rng.below(cpb);
                self.add(event, target, FaultKind::StuckDominant, start, len);
                now + len
            }
            FaultEvent::LongDominant => {
                let target = if self.rng.percent(60) {
                    FaultTarget::Bus
                } else {
                    FaultTarget::Tx(self.node())
                };
                let len = self.range(17, 300) * cpb + self.rng.below(cpb);
                let start = now + self.rng.below(cpb);
                self.add(event, target, FaultKind::StuckDominant, start, len);
                start + len
            }
            FaultEvent::StuckRecessive => {
                let target = match self.rng.below(3) {
                    0 => FaultTarget::Bus,
                    1 => FaultTarget::Tx(self.node()),
                    _ => FaultTarget::Rx(self.node()),
                };
                let len = self.range(1, 40) * cpb + self.rng.below(cpb);
                let start = now + self.rng.below(cpb);
                self.add(event, target, FaultKind::StuckRecessive, start, len);
                now + len
            }
            FaultEvent::BusOff => self.bus_off(event, now, params),
            FaultEvent::DeadNode => self.dead_node(event, now),
        }
    }

    /// A flip or a stuck level aimed at a bit of one of [`AIMED_FIELDS`] as node `n`
    /// samples it, with margins of up to SJW around the sample point.
    fn field_flip(&mut self, event: FaultEvent, now: u64) -> u64 {
        let cpb = self.cpb;
        let n = self.node();
        let (want, skip_max) = AIMED_FIELDS[self.rng.below(AIMED_FIELDS.len() as u64) as usize];
        let limit = now + 600 * cpb;
        // Find a sample point after which node n expects a bit of `want`;
        // give up (flip whatever comes next) at the limit.
        let mut last = None;
        while let Some(s) = self.next_sample(n, limit) {
            last = Some(s);
            if self.sys.sample().outputs[n].probes.field == want {
                break;
            }
        }
        let skip = self.rng.below(skip_max + 1);
        for _ in 0..skip {
            if let Some(s) = self.next_sample(n, limit + 40 * cpb) {
                last = Some(s);
            }
        }
        let s = match last {
            Some(s) => s,
            None => self.sys.cycle(),
        };
        // The next SAMPLE edge (one bit later, if no resynchronisation
        // moves it) reads rx of cycle s + cpb - 2; cover it with margins
        // of up to SJW (and two quanta more for triple sampling).
        let c = s + cpb - 2;
        let extra = if self.triple { 2 * self.tq } else { 0 };
        let before = extra + self.rng.below(self.sjw + 1);
        let after = self.rng.below(self.sjw + 1);
        let target = if self.rng.percent(60) {
            FaultTarget::Bus
        } else {
            FaultTarget::Rx(n)
        };
        let kind = match self.rng.below(10) {
            0..=6 => FaultKind::Flip,
            7 | 8 => FaultKind::StuckDominant,
            _ => FaultKind::StuckRecessive,
        };
        self.add(
            event,
            target,
            kind,
            c.saturating_sub(before),
            before + after + 1,
        );
        self.sys.cycle()
    }

    /// A glitch shorter than half a bit on the bus, a TX or an RX line.
    fn glitch(&mut self, event: FaultEvent, now: u64) -> u64 {
        let cpb = self.cpb;
        let target = match self.rng.below(4) {
            0 | 1 => FaultTarget::Bus,
            2 => FaultTarget::Tx(self.node()),
            _ => FaultTarget::Rx(self.node()),
        };
        let kind = if self.rng.percent(70) {
            FaultKind::Flip
        } else {
            FaultKind::StuckDominant
        };
        let len = if self.rng.percent(50) {
            self.range(1, (2 * self.tq).min(cpb / 2))
        } else {
            self.range(1, cpb / 2)
        };
        let start = now + self.rng.below(4 * cpb);
        self.add(event, target, kind, start, len);
        now
    }

    /// A glitch of up to two quanta around a node's next sample point.
    fn sample_glitch(&mut self, event: FaultEvent, now: u64) -> u64 {
        let cpb = self.cpb;
        let n = self.node();
        if let Some(s) = self.next_sample(n, now + 4 * cpb) {
            let c = s + cpb - 2;
            let len = self.range(1, 2 * self.tq);
            // From two quanta early to one quantum late: sometimes it hits
            // the sample, sometimes it only moves an edge.
            let start = (c + self.rng.below(3 * self.tq + 1)).saturating_sub(2 * self.tq);
            let target = if self.rng.percent(50) {
                FaultTarget::Bus
            } else {
                FaultTarget::Rx(n)
            };
            self.add(event, target, FaultKind::Flip, start, len);
        }
        self.sys.cycle()
    }

    /// A dominant level in chunks of 150 bits, once a node is inside a frame past
    /// arbitration, until some node is bus-off (or `params.max_attack_bits`).
    fn bus_off(&mut self, event: FaultEvent, now: u64, params: &FaultParams) -> u64 {
        let cpb = self.cpb;
        // Wait (up to 2000 bits) until node n is inside a frame, past
        // arbitration: exactly one node is transmitter then.
        let n = self.node();
        let limit = now + 2000 * cpb;
        while self.sys.cycle() < limit {
            self.step();
            let f = self.sys.sample().outputs[n].probes.field;
            if (field::R1..=field::CRC).contains(&f) {
                break;
            }
        }
        let target = if self.rng.percent(70) {
            FaultTarget::Bus
        } else {
            FaultTarget::Tx(self.node())
        };
        // In chunks of 150 bits until some node is bus-off.
        let chunk = 150 * cpb;
        let mut spent = 0;
        loop {
            let start = self.sys.cycle() + self.rng.below(cpb);
            self.add(event, target, FaultKind::StuckDominant, start, chunk);
            spent += 150;
            let mut off = false;
            while self.sys.cycle() < start + chunk {
                self.step();
                off |= self.err_state.contains(&2);
            }
            if off || spent >= params.max_attack_bits {
                break;
            }
        }
        self.sys.cycle()
    }

    /// A node with a frame pending loses its TX or its RX line for 20 to 400 bits.
    fn dead_node(&mut self, event: FaultEvent, now: u64) -> u64 {
        let cpb = self.cpb;
        // A node with a frame pending (wait up to 1000 bits for one).
        let limit = now + 1000 * cpb;
        let n = loop {
            let pending: Vec<usize> = (0..self.nodes)
                .filter(|&i| self.sys.sample().outputs[i].tx_pending)
                .collect();
            if !pending.is_empty() {
                break pending[self.rng.below(pending.len() as u64) as usize];
            }
            if self.sys.cycle() >= limit {
                break self.node();
            }
            self.step();
        };
        let target = if self.rng.percent(50) {
            FaultTarget::Tx(n)
        } else {
            FaultTarget::Rx(n)
        };
        let len = self.range(20, 400) * cpb + self.rng.below(cpb);
        let start = self.sys.cycle();
        self.add(event, target, FaultKind::StuckRecessive, start, len);
        start + len
    }
}

#[cfg(test)]
mod tests;
