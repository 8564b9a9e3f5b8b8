//! A random search for the DRCC main FSM's races (coverage workload): two or three
//! DRCC nodes on a dual bus, node 0 with a random redundancy configuration (policy,
//! stall limit, dual_tx, recovery), random line faults on A and B that fail and
//! heal its channels while its frames are in flight. The races of Table 1 it looks
//! for: an abort that loses against the attempt's success (abort1 / abort2 ->
//! idle), and channel A failing again while B's attempt ends in wait4.
//!
//! Nothing is judged here (the scenarios and the campaigns judge deliveries); the
//! runs only feed the cover points. Deterministic: run `i` draws from seed `i`.

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::dual::lockstep::compare;
use drcc_cosim::dual::{DualBusSystem, Line};
use drcc_cosim::host::{btr, HostConfig, Policy};
use drcc_cosim::Frame;

use crate::dual::{drcc_engine, CLOCKS_PER_BIT};
use crate::engines::EngineKind;
use crate::random::SplitMix64;

/// Runs in one search.
pub const RUNS: u64 = 1_500;
/// Bit times per run.
const RUN_BITS: u64 = 4_000;

fn config(r: &mut SplitMix64, dut: bool) -> HostConfig {
    let base = HostConfig {
        btr: btr(0, 5, 2, 1, false, 96),
        redundancy: true,
        policy: Policy::KFailed(2),
        dual_tx: true,
        recovery_bits: 1_000,
        stall_limit: 500,
        dedup_window: 2_000,
        ..HostConfig::default()
    };
    if !dut {
        return base;
    }
    HostConfig {
        policy: match r.below(3) {
            0 => Policy::ErrorPassive,
            1 => Policy::KFailed(1),
            _ => Policy::KFailed(2),
        },
        dual_tx: r.below(2) == 0,
        recovery_bits: 30 + r.below(400) as u16,
        stall_limit: 40 + r.below(200) as u16,
        ..base
    }
}

fn frame(node: usize, k: usize, dlc: u8) -> Frame {
    Frame {
        id: 0x100 + (node as u32) * 0x40 + k as u32,
        ide: false,
        rtr: false,
        dlc,
        data: [node as u8, k as u8, 0x5A, 0xA5, 0, 1, 2, 3],
    }
}

/// The races of Table 1 the search is for: (from, to) main FSM state codes
/// (DRCC contract §4: abort1 3, abort2 8, wait4 9, idle1 0, idle2 5).
pub const RACES: [(u8, u8); 4] = [(3, 0), (3, 5), (8, 5), (9, 5)];

/// One run of the search on the model (for the cover points).
pub fn run(i: u64) -> Result<(), String> {
    run_on(i, EngineKind::Model, None).map(|_| ())
}

/// Run `i` on `kind`, or on two engines in lock step (a divergence is an error);
/// returns the races of [`RACES`] node 0's main FSM went through.
pub fn run_on(
    i: u64,
    kind: EngineKind,
    cosim: Option<EngineKind>,
) -> Result<Vec<(u8, u8)>, String> {
    let mut main = build(i, kind)?;
    let mut other = match cosim {
        Some(k) => Some(build(i, k)?),
        None => None,
    };
    let mut seen = Vec::new();
    let mut prev = 0u8;
    while main.cycle() < RUN_BITS * CLOCKS_PER_BIT {
        main.step();
        if let Some(o) = other.as_mut() {
            o.step();
            if let Some(d) = compare(&main, o) {
                return Err(format!("race search run {i}: {d:?}"));
            }
        }
        let state = main.node(0).outputs.probes.state;
        if RACES.contains(&(prev, state)) && !seen.contains(&(prev, state)) {
            seen.push((prev, state));
        }
        prev = state;
    }
    Ok(seen)
}

fn build(i: u64, kind: EngineKind) -> Result<DualBusSystem, String> {
    let mut r = SplitMix64::new(0x5EED_0000 + i);
    let nodes = 2 + r.below(2) as usize;
    let configs: Vec<HostConfig> = (0..nodes).map(|n| config(&mut r, n == 0)).collect();
    let engines = (0..nodes)
        .map(|_| drcc_engine(kind))
        .collect::<Result<Vec<_>, _>>()?;
    let mut sys = DualBusSystem::new(engines, configs)?;
    for n in 0..nodes {
        let frames = if n == 0 { 4 + r.below(6) } else { r.below(4) };
        for k in 0..frames as usize {
            let at = 50 + r.below(RUN_BITS - 1_200);
            let dlc = r.below(9) as u8;
            sys.node_mut(n).host.submit(
                at * CLOCKS_PER_BIT + r.below(CLOCKS_PER_BIT),
                frame(n, k, dlc),
                0,
            );
        }
    }
    for _ in 0..1 + r.below(3) {
        let line = if r.below(3) == 0 { Line::B } else { Line::A };
        let kind = match r.below(3) {
            0 => FaultKind::StuckDominant,
            _ => FaultKind::StuckRecessive,
        };
        let target = match r.below(3) {
            0 => FaultTarget::Tx(0),
            1 => FaultTarget::Rx(0),
            _ => FaultTarget::Bus,
        };
        let start = (50 + r.below(RUN_BITS - 1_500)) * CLOCKS_PER_BIT + r.below(CLOCKS_PER_BIT);
        let cycles = (1 + r.below(400)) * CLOCKS_PER_BIT + r.below(CLOCKS_PER_BIT);
        sys.add_fault(
            line,
            Fault {
                target,
                kind,
                start,
                cycles,
            },
        )?;
    }
    Ok(sys)
}
