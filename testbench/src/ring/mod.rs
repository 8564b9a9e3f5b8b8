//! REDCAN rings of DRCC nodes (`ring_contract.md`): scenarios, the hosts that run
//! CanKingdom and the REDCAN algorithms through the `cankingdom` crate, the run,
//! and what it measured.
//!
//! Time: the ring runs at 125 kbit/s with 8 clocks per bit, so one clock is one
//! microsecond and the hosts' clocks (`now_us`) are the cycle count.

pub mod app;
mod hosts;
mod judge;
pub mod lockstep;
pub mod post;
pub mod table;

use crate::dual::drcc_engine;
use crate::engines::EngineKind;
use app::AppTraffic;
use drcc_cosim::engine::drcc::DrccEngine;
use drcc_cosim::engine::rcm::{rcm_engine, RcmEngine};
use drcc_cosim::host::{HostConfig, Policy};
use drcc_cosim::ring::{NodeFault, RingSystem, SectionFaults, Shape};
use drcc_cosim::Frame;
use hosts::{host_apps, Hosts};
use judge::judge;
use post::{ring_btr, DrccPost, PostState};
use redcan::central::CentralTiming;
use redcan::distributed::DistTiming;

/// Clocks per bit (125 kbit/s at 1 MHz).
pub const CLOCKS_PER_BIT: u64 = 8;
/// The ring's clock: one clock per microsecond (traffic export timestamps).
pub const CLOCK_HZ: u64 = 1_000_000;
/// Microseconds per millisecond.
const MS: u64 = 1_000;
/// Envelope of the application frames: `APP_BASE + node`.
pub const APP_BASE: u32 = 0x500;

/// A fault of `ring_contract.md` §3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RingFault {
    /// Nothing.
    None,
    /// Section `section` broken after its `point`-th plain node.
    SectionOpen { section: usize, point: usize },
    /// Section `section` stuck dominant.
    SectionShort { section: usize },
    /// Ring node `node`'s transmitter stuck dominant, its host dead, its relay held.
    Babbling { node: usize },
    /// Ring node `node` loses power (relay at rest: transparent).
    Crash { node: usize },
}

impl RingFault {
    /// The CLI name of the kind.
    pub fn kind_name(self) -> &'static str {
        match self {
            RingFault::None => "no_fault",
            RingFault::SectionOpen { .. } => "section_open",
            RingFault::SectionShort { .. } => "section_short",
            RingFault::Babbling { .. } => "babbling_idiot",
            RingFault::Crash { .. } => "node_crash",
        }
    }

    /// Where it is, in words.
    pub fn position(self) -> String {
        match self {
            RingFault::None => "-".into(),
            RingFault::SectionOpen { section, point } => {
                format!("section {section}, after plain node {point}")
            }
            RingFault::SectionShort { section } => format!("section {section}"),
            RingFault::Babbling { node } | RingFault::Crash { node } => format!("ring node {node}"),
        }
    }
}

/// The REDCAN algorithm the hosts run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Algorithm {
    /// Seed §3 on a CanKingdom King (`central`).
    Centralized,
    /// Seed §4 as ring contract §6 schedules it (`distributed`).
    Distributed,
}

/// One ring run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RingScenario {
    /// Ring nodes (3..=10).
    pub ring_nodes: usize,
    /// Plain nodes on every section.
    pub plain_per_section: usize,
    pub fault: RingFault,
    pub algorithm: Algorithm,
    /// Relay operate time in microseconds (ring contract §1).
    pub relay_us: u64,
    /// Fault onset in microseconds from power-up.
    pub onset_us: u64,
    /// Run length after the onset.
    pub after_us: u64,
    /// Application frame period per node.
    pub app_period_us: u64,
}

impl RingScenario {
    /// `n` ring nodes with one plain node per section, the centralized algorithm
    /// with the paper's T1 and T2, relays of 2 ms, the fault 450 ms after power-up
    /// (the kingdom's start-up takes about 310 ms), 1.4 s after it, every node
    /// sending one application frame every 100 ms.
    pub fn standard(n: usize, fault: RingFault) -> Self {
        RingScenario {
            ring_nodes: n,
            plain_per_section: 1,
            fault,
            algorithm: Algorithm::Centralized,
            relay_us: 2 * MS,
            onset_us: 450 * MS,
            after_us: 1_400 * MS,
            app_period_us: 100 * MS,
        }
    }

    /// [`RingScenario::standard`] with the distributed algorithm, which recovers
    /// in well under T2: 600 ms after the onset suffice.
    pub fn distributed(n: usize, fault: RingFault) -> Self {
        RingScenario {
            algorithm: Algorithm::Distributed,
            after_us: 600 * MS,
            ..Self::standard(n, fault)
        }
    }

    fn shape(&self) -> Shape {
        Shape {
            plain: vec![self.plain_per_section; self.ring_nodes],
        }
    }
}

/// The EAN a City reports (40 bits; the test Kingdom's product numbers).
pub fn ean_of(address: u8) -> u64 {
    0x00_4711_0000 + address as u64
}

/// What a run showed.
#[derive(Clone, Debug, Default)]
pub struct RingReport {
    /// The King's start-up ended with membership agreed, at this time (µs).
    pub kingdom_at: Option<u64>,
    pub onset: u64,
    /// First host that acted on the fault, and when (µs).
    pub detected: Option<(usize, u64)>,
    /// Last relay change applied (µs).
    pub last_relay_change: Option<u64>,
    /// Nodes that are working (not faulty, not physically cut off).
    pub working: Vec<bool>,
    /// Nodes on the reference node's bus at the end.
    pub reachable: Vec<bool>,
    /// Every working node on one bus.
    pub no_partition: bool,
    /// That bus is a line terminated once at each end.
    pub single_termination: bool,
    /// Application frames (sender, sequence) submitted after the onset that some
    /// working, reachable node never received.
    pub lost: Vec<(usize, u32)>,
    /// Application frames submitted after the onset by working nodes.
    pub app_frames: usize,
    /// Of those, the ring nodes' (the rest are the plain nodes').
    pub ring_app_frames: usize,
    /// Application frames that ring nodes submitted again after a detection
    /// (`app`: delivered at least once).
    pub resent: usize,
    /// Relay states in force at the end (1 left, 2 right, 3 transparent).
    pub final_modes: Vec<u8>,
    /// Illegal RCM writes refused (ring contract §2).
    pub refused: u32,
    /// Every frame each node's host popped, with the clock (µs) it was popped at.
    pub received: Vec<Vec<(u64, Frame)>>,
}

/// Builds and runs `s` on DRCC engine `kind` (the RCMs on the same kind).
pub fn run(s: &RingScenario, kind: EngineKind) -> Result<RingReport, String> {
    run_observed(s, kind, |_| Ok(()))
}

/// [`run`], calling `observe` with the system after every clock (after
/// `RingSystem::step`, before the hosts react to that clock's outputs). An error
/// of `observe` ends the run and is returned.
pub fn run_observed(
    s: &RingScenario,
    kind: EngineKind,
    mut observe: impl FnMut(&RingSystem) -> Result<(), String>,
) -> Result<RingReport, String> {
    let shape = s.shape();
    let (n, total) = (shape.ring_nodes(), shape.nodes());
    let engines = (0..total)
        .map(|_| drcc_engine(kind))
        .collect::<Result<Vec<Box<dyn DrccEngine>>, _>>()?;
    let rcms = (0..n)
        .map(|_| rcm_engine(kind.name()))
        .collect::<Result<Vec<Box<dyn RcmEngine>>, _>>()?;
    let config = HostConfig {
        btr: ring_btr(),
        redundancy: false,
        policy: Policy::None,
        dedup_window: 0,
        ..HostConfig::default()
    };
    let mut sys = RingSystem::new(shape.clone(), engines, rcms, config, s.relay_us)?;
    let onset = s.onset_us;
    match s.fault {
        RingFault::None => {}
        RingFault::SectionOpen { section, point } => sys.add_section_faults(
            SectionFaults {
                open: vec![(section, point)],
                short: vec![],
            },
            onset,
        )?,
        RingFault::SectionShort { section } => sys.add_section_faults(
            SectionFaults {
                open: vec![],
                short: vec![section],
            },
            onset,
        )?,
        RingFault::Babbling { node } => {
            sys.add_node_fault(NodeFault::Babbling { node, start: onset })?
        }
        RingFault::Crash { node } => sys.add_node_fault(NodeFault::Crash { node, start: onset })?,
    }
    if let RingFault::Babbling { node } | RingFault::Crash { node } = s.fault {
        if node >= n {
            return Err(format!("ring node {node}: the ring has ring nodes 0..{n}"));
        }
    }
    let mut central = CentralTiming::paper(s.relay_us);
    central.plain_silence = s.app_period_us * 5 / 2;
    let mut dist = DistTiming::standard(s.relay_us);
    dist.plain_silence = dist.plain_silence_for(s.app_period_us);
    let hosts = Hosts {
        algorithm: s.algorithm,
        n,
        total,
        central,
        dist,
    };
    let mut apps = host_apps(&hosts)?;
    let mut posts: Vec<PostState> = (0..total).map(|_| PostState::new(config)).collect();
    let mut report = RingReport {
        onset,
        ..RingReport::default()
    };
    let mut sent: Vec<(usize, u32, u64)> = Vec::new();
    // Each node's application period starts at its own phase (nodes do not share
    // a clock): twenty frames submitted in the same microsecond would queue the
    // last node's alive letter behind its own application frame for ~16 ms.
    let app_phase: Vec<u64> = (0..total)
        .map(|i| i as u64 * s.app_period_us / total as u64)
        .collect();
    // Distributed: held frames resent from the horizon, one per 2 Ta; the
    // centralized algorithm keeps the seed's behaviour (`app`).
    let horizon = hosts.dist.resend_horizon();
    let mut traffic: Vec<AppTraffic> = (0..total)
        .map(|i| {
            let t = AppTraffic::new(i, APP_BASE, s.app_period_us, 0, horizon, 2 * hosts.dist.ta);
            match s.algorithm {
                Algorithm::Centralized => t.without_keeping(),
                Algorithm::Distributed => t,
            }
        })
        .collect();
    let end = onset + s.after_us;
    let mut relays = sys.wiring().relays().to_vec();
    let host_dead = |i: usize, now: u64| match s.fault {
        RingFault::Babbling { node } | RingFault::Crash { node } => node == i && now >= onset,
        _ => false,
    };
    while sys.cycle() < end {
        sys.step();
        observe(&sys)?;
        let now = sys.cycle();
        if sys.wiring().relays() != relays.as_slice() {
            relays = sys.wiring().relays().to_vec();
            if now >= onset {
                report.last_relay_change = Some(now);
            }
        }
        if now % CLOCKS_PER_BIT != 0 || now < MS {
            continue;
        }
        for i in 0..total {
            if host_dead(i, now) {
                continue;
            }
            let node = sys.node_mut(i);
            let mut post = DrccPost {
                host: &mut node.host,
                state: &mut posts[i],
                now,
            };
            let command = apps[i].poll(i, now, &mut post, &hosts, &mut report)?;
            if let Some(c) = command {
                sys.module_mut(i).command = Some(c);
            }
            // Application traffic once the kingdom runs (`app`: a ring node
            // holds its frames while it rebuilds the ring and resends those the
            // fault may have cut off).
            let state = hosts::ring_state(&apps[i]);
            let due = report
                .kingdom_at
                .is_some_and(|k| now >= k + 50 * MS + app_phase[i]);
            let (produced, out) = traffic[i].poll(now, due, state);
            if let Some(seq) = produced {
                sent.push((i, seq, now));
            }
            for f in out {
                sys.node_mut(i).host.submit(now, f, 0);
            }
        }
        if now == onset && report.kingdom_at.is_none() {
            return Err("the kingdom was not running at the fault onset".to_string());
        }
    }
    report.resent = traffic.iter().map(|t| t.resent).sum();
    judge(s, &sys, &shape, &sent, &mut report);
    Ok(report)
}
