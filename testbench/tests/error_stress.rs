//! Random error stress: 3 to 5 nodes exchange random traffic while random faults
//! hit the bus (`drcc_testbench::fault_gen`, the fault kinds of
//! `drcc_cosim::bus`): single-bit flips, glitches shorter than a bit (some at a
//! node's sample point), flipped bits in chosen fields (ACK slot, EOF,
//! intermission, suspend, error flags and delimiters, bus-off ...), stuck-dominant
//! windows (some longer than 17 bits: error passive; one per episode held in the
//! middle of a frame until its transmitter is bus-off), stuck-recessive windows,
//! and faults on one node's transmitter or receiver only. Then the faults stop and
//! the run goes on fault free until every frame has been sent.
//!
//! Every configuration runs short seeded *episodes* (the bus scans its whole fault
//! list every clock while faults are pending, so short fault lists are cheap, and
//! every episode ends with its own recovery to check):
//! - model vs Verilator, in lock step (every output and probe of every node at
//!   every clock, `drcc_cosim::cosim::lockstep`): six configurations, 125 k to
//!   1 Mbit/s, 8 and 24 MHz clocks, brp 0 to 11, SJW 1 to 4, one with triple
//!   sampling; more than 1,000,000 bit times in all
//!   (`verilator_runs_cover_a_million_bit_times`);
//! - model vs rust-hdl: about 20,000 bit times.
//!
//! Besides zero divergence, every episode checks, from ISO 11898-1 and not from
//! either engine's view of itself:
//! - liveness: after the faults stop, every node reaches bus idle (field IDLE, not
//!   bus-off) within a bound (a bus-off node after its 128 x 11 recessive bits),
//!   then all nodes are idle together; the run ends with every frame sent
//!   (`tx_pending` clear) and, 11 recessive bits after the last frame, every node
//!   idle (an error-passive transmitter after its 8 suspend bits);
//! - integrity: every frame a node accepts (`rx_valid`) is a frame another node
//!   submitted, every submitted frame is sent (`tx_done`) exactly once;
//! - once all nodes have been idle together after the faults: no error or
//!   overload flag, counters only go down, every frame sent is delivered once to
//!   every other node, and 11 recessive bits on the bus mean every node idle;
//! - the faults did something (over a configuration): error flags, non-zero
//!   counters, entries into error passive and bus-off, every bus-off recovered.
//!
//! Two more tests check fault confinement of a node whose transceiver dies
//! (receiver or transmitter stuck recessive): by ISO 11898-1 bit monitoring it
//! reads its own dominant bits recessive, so it is bus-off within a few hundred
//! bit times and the other nodes communicate although the fault persists.
//!
//! Soak runs: `DRCC_STRESS_SCALE=k` runs k times as many episodes, and
//! `DRCC_STRESS_SEED=s` draws other traffic and faults (every seed shifted by
//! `s << 16`); the defaults are what CI runs.
//!
//! A missing Verilator skips locally and fails in CI (`CI` or
//! `DRCC_REQUIRE_VERILATOR` set). On a divergence the test prints it (cycle, bit,
//! node, signal, both values) and leaves the VCDs of both engines around it and
//! the episode's scenario with its faults (`scenario.toml`, for `drcc cosim`) in a
//! directory under the cargo target tmp dir, whose path it prints.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::PathBuf;
use std::rc::Rc;
use std::time::Instant;

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::cosim::{compare_samples, lockstep, CosimError, CosimOptions};
use drcc_cosim::model::field;
use drcc_cosim::system::{NodeEvent, System};
use drcc_cosim::{ChannelEngine, ChannelInputs, ChannelOutputs, Frame, Probes};
use drcc_testbench::engines::{available, make_engine, verilator_required, VERILATOR_HINT};
use drcc_testbench::fault_gen::{plan, FaultEvent, FaultParams, FaultPlan};
use drcc_testbench::random::Traffic;
use drcc_testbench::run::build_system_with;
use drcc_testbench::scenario::Expectations;
use drcc_testbench::{EngineKind, Scenario};

/// Longest frame on the bus in bit times (extended, 8 data bytes, worst-case
/// stuffing, ACK delimiter, EOF and intermission), rounded up.
const MAX_FRAME_BITS: u64 = 160;

/// After the faults stop, every node must be idle within this many bit times: a
/// bus-off node needs 128 occurrences of 11 recessive bits (rule l), and a busy
/// bus gives at least one per frame; plus the frame and error frame in progress.
const SETTLE_BOUND_BITS: u64 = 128 * MAX_FRAME_BITS + 4 * MAX_FRAME_BITS;

/// One stress configuration: `episodes` seeded runs (seeds `seed`, `seed + 1`,
/// ...), each with its own traffic and faults and its own fault-free end. Short
/// episodes keep the bus's fault list short (it is scanned every clock while
/// faults are pending) and give many recoveries to check.
#[derive(Clone, Copy, Debug)]
struct Stress {
    name: &'static str,
    seed: u64,
    nodes: usize,
    clock_hz: u64,
    bitrate: u64,
    triple_sampling: bool,
    /// Bit timing instead of the solver's (same clocks per bit): brp, tseg1,
    /// tseg2, sjw.
    timing: Option<(u8, u8, u8, u8)>,
    episodes: u64,
    /// Faults are injected from bit 25 to this bit of every episode; the traffic
    /// goes on for a quarter more, then the run goes on until every frame is sent.
    fault_bits: u64,
    /// Bit times the configuration covers at least (asserted).
    min_bits: u64,
}

/// The model vs Verilator configurations (their `min_bits` add up to more than
/// 1,000,000).
const VERILATOR_RUNS: [Stress; 6] = [
    Stress {
        name: "3n-8MHz-1M",
        seed: 0x5_7E55_0100,
        nodes: 3,
        clock_hz: 8_000_000,
        bitrate: 1_000_000,
        triple_sampling: false,
        timing: None,
        episodes: 40,
        fault_bits: 8000,
        min_bits: 400_000,
    },
    Stress {
        name: "4n-8MHz-500k-sjw4",
        seed: 0x5_7E55_0200,
        nodes: 4,
        clock_hz: 8_000_000,
        bitrate: 500_000,
        triple_sampling: false,
        // SJW 4, the largest jump.
        timing: Some((0, 10, 5, 4)),
        episodes: 46,
        fault_bits: 4000,
        min_bits: 250_000,
    },
    Stress {
        name: "5n-24MHz-500k-brp2",
        seed: 0x5_7E55_0300,
        nodes: 5,
        clock_hz: 24_000_000,
        bitrate: 500_000,
        triple_sampling: false,
        timing: None,
        episodes: 50,
        fault_bits: 2000,
        min_bits: 150_000,
    },
    Stress {
        name: "3n-24MHz-1M-brp1-sjw1",
        seed: 0x5_7E55_0400,
        nodes: 3,
        clock_hz: 24_000_000,
        bitrate: 1_000_000,
        triple_sampling: false,
        // SJW 1, the smallest jump.
        timing: Some((1, 8, 3, 1)),
        episodes: 30,
        fault_bits: 3000,
        min_bits: 120_000,
    },
    Stress {
        name: "4n-8MHz-125k-brp3-triple",
        seed: 0x5_7E55_0500,
        nodes: 4,
        clock_hz: 8_000_000,
        bitrate: 125_000,
        triple_sampling: true,
        timing: None,
        episodes: 20,
        fault_bits: 2000,
        min_bits: 60_000,
    },
    Stress {
        name: "3n-24MHz-125k-brp11",
        seed: 0x5_7E55_0600,
        nodes: 3,
        clock_hz: 24_000_000,
        bitrate: 125_000,
        triple_sampling: false,
        timing: None,
        episodes: 14,
        fault_bits: 2000,
        min_bits: 40_000,
    },
];

/// The model vs rust-hdl configuration.
const RUSTHDL_RUN: Stress = Stress {
    name: "3n-8MHz-1M-rusthdl",
    seed: 0x5_7E55_0700,
    nodes: 3,
    clock_hz: 8_000_000,
    bitrate: 1_000_000,
    triple_sampling: false,
    timing: None,
    episodes: 2,
    fault_bits: 7000,
    min_bits: 18_000,
};

fn verilator_present() -> bool {
    match available(EngineKind::Verilator) {
        Ok(()) => true,
        Err(e) => {
            assert!(
                !verilator_required(),
                "Verilator is required in CI ({VERILATOR_HINT}): {e}"
            );
            eprintln!("SKIPPED: {e}");
            false
        }
    }
}

#[test]
fn verilator_runs_cover_a_million_bit_times() {
    let total: u64 = VERILATOR_RUNS.iter().map(|r| r.min_bits).sum();
    assert!(total >= 1_000_000, "{total}");
}

#[test]
fn stress_3_nodes_8mhz_1m_vs_verilator() {
    stress_vs_verilator(0);
}

#[test]
fn stress_4_nodes_8mhz_500k_sjw4_vs_verilator() {
    stress_vs_verilator(1);
}

#[test]
fn stress_5_nodes_24mhz_500k_brp2_vs_verilator() {
    stress_vs_verilator(2);
}

#[test]
fn stress_3_nodes_24mhz_1m_brp1_sjw1_vs_verilator() {
    stress_vs_verilator(3);
}

#[test]
fn stress_4_nodes_8mhz_125k_triple_vs_verilator() {
    stress_vs_verilator(4);
}

#[test]
fn stress_3_nodes_24mhz_125k_brp11_vs_verilator() {
    stress_vs_verilator(5);
}

#[test]
fn stress_vs_rusthdl() {
    stress(&RUSTHDL_RUN, EngineKind::RustHdl);
}

fn stress_vs_verilator(i: usize) {
    if verilator_present() {
        stress(&VERILATOR_RUNS[i], EngineKind::Verilator);
    }
}

// ---------------------------------------------------------------------------
// Scenario and faults

/// Largest gap between bursts of frames, in bit times (about 140 bit times per
/// frame on average: a busy bus with room to recover).
const MAX_GAP_BITS: u64 = 600;

/// The traffic of one episode, its fault plan, and the scenario holding both.
fn build(spec: &Stress, seed: u64) -> (Scenario, FaultPlan) {
    // Plenty of traffic (about 140 bit times per frame); cut after planning.
    let mut t = Traffic::new(
        seed,
        (spec.fault_bits / 25) as usize,
        spec.clock_hz,
        spec.bitrate,
    );
    t.nodes = spec.nodes;
    t.max_gap_bits = MAX_GAP_BITS;
    let mut sc = t.scenario().unwrap();
    let cpb = sc.clocks_per_bit();
    sc.name = format!("error-stress-{}-{seed:#x}", spec.name);
    if let Some((brp, tseg1, tseg2, sjw)) = spec.timing {
        sc.timing.brp = brp;
        sc.timing.tseg1 = tseg1;
        sc.timing.tseg2 = tseg2;
        sc.timing.sjw = sjw;
        assert_eq!(sc.timing.clocks_per_bit() as u64, cpb, "{}", spec.name);
    }
    sc.timing.triple_sampling = spec.triple_sampling;
    sc.timing.validate().unwrap();
    // Faults make the default expectation (every frame to every other node)
    // meaningless; the checks are this file's.
    sc.expect = Expectations::Explicit(Vec::new());
    // Every episode: a long stuck-dominant window (error passive) and a
    // stuck-dominant line held in a frame until a node is bus-off, besides the
    // random events.
    let mut params = FaultParams::new(seed, 25 * cpb, spec.fault_bits * cpb);
    params.forced = vec![(0.3, FaultEvent::LongDominant), (0.6, FaultEvent::BusOff)];
    let fp = plan(&sc, &params).unwrap();
    // The traffic goes on for a quarter of the fault window after the faults
    // (and at least to where the planner ran, so the replay is the planner's).
    let cut = (fp.end + spec.fault_bits / 4 * cpb)
        .max(fp.planned_until)
        .max(spec.fault_bits / 4 * 5 * cpb);
    let last_due = sc.frames.iter().map(|f| f.at_cycle).max().unwrap();
    assert!(
        cut <= last_due,
        "{}: the traffic (until cycle {last_due}) is too short for the faults (until cycle {})",
        sc.name,
        fp.end
    );
    sc.frames.retain(|f| f.at_cycle <= cut);
    let last_due = sc.frames.iter().map(|f| f.at_cycle).max().unwrap();
    sc.faults = fp.faults.clone();
    sc.description = format!(
        "error stress {}: {} random frames on {} nodes (traffic and fault seed {seed:#x}), \
         {} faults until cycle {} (bit {})",
        spec.name,
        sc.frames.len(),
        spec.nodes,
        fp.faults.len(),
        fp.end,
        fp.end / cpb
    );
    // A generous cycle limit: a node that locks up shows as frames never sent.
    let bits = last_due / cpb + (sc.frames.len() as u64 + 128) * MAX_FRAME_BITS + 2000;
    sc.max_cycles = bits * cpb;
    (sc, fp)
}

// ---------------------------------------------------------------------------
// Observation: a transparent wrapper around the engines of the first system

/// One change of a node's probes (recorded from the fault-free cycle on).
#[derive(Clone, Copy, Debug)]
struct Mark {
    cycle: u64,
    field: u8,
    err_state: u8,
    tec: u16,
    rec: u8,
}

/// What one node did, as seen through its outputs.
#[derive(Clone, Debug, Default)]
struct NodeLog {
    max_tec: u16,
    max_rec: u8,
    /// Entries into error passive (from error active).
    passive: usize,
    /// Entries into bus-off.
    bus_off: usize,
    /// Bus-off -> error active.
    recovered: usize,
    /// Error flags started (field becoming ERROR_FLAG).
    error_flags: usize,
    /// Overload flags started.
    overload_flags: usize,
    /// First fault-free cycle at which the node is idle (and not bus-off).
    settled: Option<u64>,
    /// Fault free: every change of field, error state or counters.
    trail: Vec<Mark>,
    /// Fault free: cycles at which the node's `rx` had been recessive for more
    /// than 11 bit times (plus the sampling delay) and the node was not idle
    /// (nor bus-off, nor in its 8 suspend bits): (cycle, field).
    not_idle: Vec<(u64, u8)>,
}

struct Watch {
    inner: Box<dyn ChannelEngine>,
    log: Rc<RefCell<NodeLog>>,
    cycle: u64,
    fault_free: u64,
    cpb: u64,
    prev: Probes,
    rx_run: u64,
    was_bad: bool,
}

impl ChannelEngine for Watch {
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn step(&mut self, i: &ChannelInputs) -> ChannelOutputs {
        let o = self.inner.step(i);
        let c = self.cycle;
        self.cycle += 1;
        let p = o.probes;
        let mut log = self.log.borrow_mut();
        log.max_tec = log.max_tec.max(p.tec);
        log.max_rec = log.max_rec.max(p.rec);
        if p.err_state != self.prev.err_state {
            match (self.prev.err_state, p.err_state) {
                (0, 1) => log.passive += 1,
                (_, 2) => log.bus_off += 1,
                (2, 0) => log.recovered += 1,
                _ => {}
            }
        }
        if p.field != self.prev.field {
            match p.field {
                field::ERROR_FLAG => log.error_flags += 1,
                field::OVERLOAD_FLAG => log.overload_flags += 1,
                _ => {}
            }
        }
        self.rx_run = if i.rx && !i.rst { self.rx_run + 1 } else { 0 };
        if c >= self.fault_free {
            let q = &self.prev;
            if c == self.fault_free
                || (p.field, p.err_state, p.tec, p.rec) != (q.field, q.err_state, q.tec, q.rec)
            {
                log.trail.push(Mark {
                    cycle: c,
                    field: p.field,
                    err_state: p.err_state,
                    tec: p.tec,
                    rec: p.rec,
                });
            }
            if log.settled.is_none() && p.field == field::IDLE && p.err_state != 2 {
                log.settled = Some(c);
            }
            // 11 recessive bits: the 11th is sampled at most one bit plus the
            // two synchronizer clocks after it started.
            let idle_after = 12 * self.cpb + 2;
            let bad = self.rx_run >= idle_after
                && !(p.field == field::IDLE
                    || p.field == field::BUS_OFF
                    || (p.field == field::SUSPEND && self.rx_run < idle_after + 8 * self.cpb));
            if bad && !self.was_bad {
                log.not_idle.push((c, p.field));
            }
            self.was_bad = bad;
        }
        self.prev = p;
        o
    }
}

// ---------------------------------------------------------------------------
// The run

/// Totals of a configuration.
#[derive(Clone, Debug, Default)]
struct Totals {
    timing: String,
    bits: u64,
    cycles: u64,
    frames: usize,
    deliveries: usize,
    faults: usize,
    events: usize,
    error_flags: usize,
    overload_flags: usize,
    passive: usize,
    bus_off: usize,
    recovered: usize,
    max_tec: u16,
    max_rec: u8,
    /// Longest time from the end of the faults until every node was idle / all
    /// nodes were idle together, in bit times.
    settle_bits: u64,
    quiet_bits: u64,
    /// Frames sent after all nodes were idle together (checked delivered).
    synchronised_frames: usize,
}

/// A numeric environment variable (soak runs), or `default`.
fn env_u64(name: &str, default: u64) -> u64 {
    match std::env::var(name) {
        Ok(v) => v
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("{name}={v:?} is not a number")),
        Err(_) => default,
    }
}

fn stress(spec: &Stress, other: EngineKind) {
    let t0 = Instant::now();
    // Soak runs: DRCC_STRESS_SCALE=k runs k times the episodes, and
    // DRCC_STRESS_SEED=s shifts every seed by s << 16 (other traffic and faults).
    let scale = env_u64("DRCC_STRESS_SCALE", 1).max(1);
    let shift = env_u64("DRCC_STRESS_SEED", 0) << 16;
    let spec = &Stress {
        episodes: spec.episodes * scale,
        min_bits: spec.min_bits * scale,
        seed: spec.seed + shift,
        ..*spec
    };
    let mut tot = Totals::default();
    let mut problems = Vec::new();
    for e in 0..spec.episodes {
        episode(spec, spec.seed + e, other, &mut tot, &mut problems);
    }
    // The faults did something (over the configuration: single episodes may be
    // unlucky).
    if tot.error_flags < tot.events / 4 {
        problems.push(format!(
            "FAULTS INEFFECTIVE: only {} error flags for {} fault events",
            tot.error_flags, tot.events
        ));
    }
    if tot.passive < spec.episodes as usize / 2 {
        problems.push(format!(
            "FAULTS INEFFECTIVE: only {} entries into error passive in {} episodes with long \
             stuck-dominant windows",
            tot.passive, spec.episodes
        ));
    }
    if tot.bus_off < spec.episodes as usize / 2 {
        problems.push(format!(
            "FAULTS INEFFECTIVE: only {} bus-off entries in {} episodes that force one",
            tot.bus_off, spec.episodes
        ));
    }
    if tot.bits < spec.min_bits {
        problems.push(format!(
            "the configuration covered only {} bit times, less than the {} it is counted for",
            tot.bits, spec.min_bits
        ));
    }
    eprintln!(
        "[{}] model vs {}: {} episodes, {} bit times ({} cycles), {} nodes, {} Hz, {} bit/s, \
         {}; {} frames, {} deliveries; {} faults ({} events); error flags {}, \
         overload flags {}, error passive {}, bus-off {} (recovered {}), max tec {} rec {}; \
         after the faults every node idle within {} bits, all together within {} bits, then {} \
         frames sent and delivered everywhere; {:.1} s",
        spec.name,
        other.name(),
        spec.episodes,
        tot.bits,
        tot.cycles,
        spec.nodes,
        spec.clock_hz,
        spec.bitrate,
        tot.timing,
        tot.frames,
        tot.deliveries,
        tot.faults,
        tot.events,
        tot.error_flags,
        tot.overload_flags,
        tot.passive,
        tot.bus_off,
        tot.recovered,
        tot.max_tec,
        tot.max_rec,
        tot.settle_bits,
        tot.quiet_bits,
        tot.synchronised_frames,
        t0.elapsed().as_secs_f64()
    );
    assert!(
        problems.is_empty(),
        "{}: {} problem(s), no divergence:\n  {}",
        spec.name,
        problems.len(),
        problems
            .iter()
            .take(40)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n  ")
    );
}

/// One episode: model vs `other` in lock step, then every check. A divergence
/// panics at once (with the VCDs and the scenario left in the printed directory);
/// other problems are collected.
fn episode(spec: &Stress, seed: u64, other: EngineKind, tot: &mut Totals, all: &mut Vec<String>) {
    let (sc, fp) = build(spec, seed);
    let cpb = sc.clocks_per_bit();
    let fault_free = fp.end;
    let logs: Vec<Rc<RefCell<NodeLog>>> = (0..spec.nodes)
        .map(|_| Rc::new(RefCell::new(NodeLog::default())))
        .collect();
    let mut a = build_system_with(&sc, |i| {
        Ok(Box::new(Watch {
            inner: make_engine(EngineKind::Model)?,
            log: logs[i].clone(),
            cycle: 0,
            fault_free,
            cpb,
            prev: Probes::default(),
            rx_run: 0,
            was_bad: false,
        }) as Box<dyn ChannelEngine>)
    })
    .unwrap();
    let mut b = build_system_with(&sc, |_| make_engine(other)).unwrap();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "error-stress-{}-{seed:#x}-model-{}",
        spec.name,
        other.name()
    ));
    let opts = CosimOptions {
        max_cycles: sc.max_cycles,
        clock_hz: sc.clock_hz,
        vcd_dir: Some(dir.clone()),
        before: (60 * cpb as usize).max(2000),
        after: (20 * cpb).max(200),
    };
    let report = match lockstep(&mut a, &mut b, &opts) {
        Ok(r) => r,
        Err(e) => {
            let _ = std::fs::create_dir_all(&dir);
            let toml = dir.join("scenario.toml");
            let _ = std::fs::write(&toml, sc.to_toml());
            let when = match &e {
                CosimError::Divergence(d) if d.cycle < fault_free => "while faults are injected",
                CosimError::Divergence(_) => "after the faults stopped",
                CosimError::Setup(_) => "at setup",
            };
            panic!(
                "DIVERGENCE in {} ({}), {when} (faults until cycle {fault_free}, bit {}):\n{e}\n\
                 files in {}\nreproduce: drcc cosim {} --engines model,{} --vcd-dir {}",
                spec.name,
                sc.description,
                fault_free / cpb,
                dir.display(),
                toml.display(),
                other.name(),
                dir.display()
            );
        }
    };
    let mut problems = Vec::new();
    let end = report.outcome.cycles();
    if !report.outcome.is_idle() {
        let mut why = Vec::new();
        for n in 0..a.nodes() {
            let o = &a.sample().outputs[n];
            why.push(format!(
                "node{n}: {} queued, pending {}, field {} ({}), err_state {}, tec {}, rec {}",
                a.queued(n),
                o.tx_pending,
                o.probes.field,
                field::name(o.probes.field),
                o.probes.err_state,
                o.probes.tec,
                o.probes.rec
            ));
        }
        problems.push(format!(
            "LOCKUP: the run did not end within {} bit times ({} after the faults stopped): {}",
            end / cpb,
            end.saturating_sub(fault_free) / cpb,
            why.join("; ")
        ));
    } else {
        final_idle_check(&mut a, &mut b, cpb, &mut problems);
    }
    let logs: Vec<NodeLog> = logs.iter().map(|l| l.borrow().clone()).collect();
    check(&sc, &fp, &a, &logs, tot, &mut problems);
    tot.timing = format!("{:?}", sc.timing);
    tot.bits += end / cpb;
    tot.cycles += end;
    tot.frames += sc.frames.len();
    tot.deliveries += a.deliveries().len();
    tot.faults += fp.faults.len();
    tot.events += fp.events.len();
    for l in &logs {
        tot.error_flags += l.error_flags;
        tot.overload_flags += l.overload_flags;
        tot.passive += l.passive;
        tot.bus_off += l.bus_off;
        tot.recovered += l.recovered;
        tot.max_tec = tot.max_tec.max(l.max_tec);
        tot.max_rec = tot.max_rec.max(l.max_rec);
    }
    if !problems.is_empty() {
        let _ = std::fs::create_dir_all(&dir);
        let toml = dir.join("scenario.toml");
        let _ = std::fs::write(&toml, sc.to_toml());
        all.push(format!(
            "episode {seed:#x} ({}; scenario with its faults: {}):",
            sc.description,
            toml.display()
        ));
        all.extend(problems.into_iter().map(|p| format!("  {p}")));
    }
}

/// After the run ended idle (nothing pending, the bus recessive for 11 bit
/// times), keeps both systems in lock step for 10 more bits: right away every
/// node is idle, or in the 8 bits of suspend transmission of an error-passive
/// transmitter; 10 bits later every node is idle.
fn final_idle_check(a: &mut System, b: &mut System, cpb: u64, problems: &mut Vec<String>) {
    for k in 1..=10 * cpb {
        a.step();
        b.step();
        if let Some((node, signal, va, vb)) = compare_samples(a.sample(), b.sample()) {
            problems.push(format!(
                "divergence after the end of the run, cycle {} (bit {}), node{node} `{signal}`: \
                 {} {va}, {} {vb}",
                a.sample().cycle,
                a.sample().cycle / cpb,
                a.engine_label(),
                b.engine_label()
            ));
            return;
        }
        if k == 2 * cpb || k == 10 * cpb {
            for (n, o) in a.sample().outputs.iter().enumerate() {
                let p = o.probes;
                let ok = p.field == field::IDLE
                    || (k == 2 * cpb && p.field == field::SUSPEND && p.err_state == 1);
                if !ok {
                    problems.push(format!(
                        "node{n} is not idle {} bit times after the bus went idle at the end \
                         (cycle {}): field {} ({}), err_state {}",
                        11 + k / cpb,
                        a.sample().cycle,
                        p.field,
                        field::name(p.field),
                        p.err_state
                    ));
                }
            }
        }
    }
}

type Key = (u32, bool);

fn key(f: &Frame) -> Key {
    let f = f.normalized();
    (f.id, f.ide)
}

/// Every check of a finished episode; adds the liveness timings to `tot`.
fn check(
    sc: &Scenario,
    fp: &FaultPlan,
    sys: &System,
    logs: &[NodeLog],
    tot: &mut Totals,
    problems: &mut Vec<String>,
) {
    let cpb = sc.clocks_per_bit();
    let ff = fp.end;
    let bit = |c: u64| c / cpb;
    let phase = |c: u64| {
        if c < ff {
            "during faults"
        } else {
            "fault free"
        }
    };

    // Integrity: deliveries are submitted frames of other nodes; every frame is
    // sent exactly once.
    let submitted: HashMap<Key, (usize, Frame)> = sc
        .frames
        .iter()
        .map(|f| (key(&f.frame), (f.node, f.frame.normalized())))
        .collect();
    for d in sys.deliveries() {
        match submitted.get(&key(&d.frame)) {
            Some((from, f)) if *f == d.frame.normalized() && *from != d.node => {}
            Some((from, _)) if *from == d.node => problems.push(format!(
                "node{} delivered its own frame {} at cycle {} (bit {}, {})",
                d.node,
                d.frame,
                d.cycle,
                bit(d.cycle),
                phase(d.cycle)
            )),
            _ => problems.push(format!(
                "CORRUPTED FRAME ACCEPTED: node{} delivered {} at cycle {} (bit {}, {}), \
                 which no node submitted",
                d.node,
                d.frame,
                d.cycle,
                bit(d.cycle),
                phase(d.cycle)
            )),
        }
    }
    let mut sent: HashMap<Key, usize> = HashMap::new();
    for e in sys.tx_done() {
        match submitted.get(&key(&e.frame)) {
            Some((from, f)) if *f == e.frame.normalized() && *from == e.node => {
                *sent.entry(key(&e.frame)).or_default() += 1;
            }
            _ => problems.push(format!(
                "node{} reported tx_done for {} at cycle {}, which it did not submit",
                e.node, e.frame, e.cycle
            )),
        }
    }
    for f in &sc.frames {
        let n = sent.get(&key(&f.frame)).copied().unwrap_or(0);
        if n != 1 {
            problems.push(format!(
                "frame {} of node{} (due at bit {}) was sent {n} times",
                f.frame,
                f.node,
                bit(f.at_cycle)
            ));
        }
    }

    // Liveness: every node idle within the bound after the faults stopped.
    let bound = ff + SETTLE_BOUND_BITS * cpb;
    for (n, l) in logs.iter().enumerate() {
        match l.settled {
            Some(c) if c <= bound => {}
            Some(c) => problems.push(format!(
                "LIVENESS: node{n} first idle {} bit times after the faults stopped (bound {})",
                bit(c - ff),
                SETTLE_BOUND_BITS
            )),
            None => problems.push(format!(
                "LIVENESS: node{n} never idle after the faults stopped (at bit {})",
                bit(ff)
            )),
        }
    }
    let settled = logs.iter().filter_map(|l| l.settled).max().unwrap_or(ff);

    // All nodes idle together: from here on the nodes agree on the bus.
    let quiet = all_idle_from(logs, ff);
    let Some(quiet) = quiet else {
        problems.push(format!(
            "LIVENESS: the nodes were never all idle at once after the faults stopped (bit {})",
            bit(ff)
        ));
        return;
    };
    if quiet > bound + 4 * MAX_FRAME_BITS * cpb {
        problems.push(format!(
            "LIVENESS: all nodes idle together only {} bit times after the faults stopped",
            bit(quiet - ff)
        ));
    }
    for (n, l) in logs.iter().enumerate() {
        let mut prev: Option<Mark> = None;
        for m in l.trail.iter().filter(|m| m.cycle > quiet) {
            if matches!(
                m.field,
                field::ERROR_FLAG
                    | field::ERROR_DELIM
                    | field::OVERLOAD_FLAG
                    | field::OVERLOAD_DELIM
                    | field::BUS_OFF
                    | field::INTEGRATING
            ) {
                problems.push(format!(
                    "node{n} in {} at cycle {} (bit {}), after all nodes were idle together at \
                     bit {} on a fault-free bus",
                    field::name(m.field),
                    m.cycle,
                    bit(m.cycle),
                    bit(quiet)
                ));
                break;
            }
            if let Some(p) = prev {
                if m.tec > p.tec || m.rec > p.rec || m.err_state > p.err_state {
                    problems.push(format!(
                        "node{n}: counters rose at cycle {} (bit {}) on a fault-free, \
                         synchronised bus: tec {} -> {}, rec {} -> {}, err_state {} -> {}",
                        m.cycle,
                        bit(m.cycle),
                        p.tec,
                        m.tec,
                        p.rec,
                        m.rec,
                        p.err_state,
                        m.err_state
                    ));
                    break;
                }
            }
            prev = Some(*m);
        }
        if let Some(&(c, f)) = l.not_idle.iter().find(|(c, _)| *c > quiet) {
            problems.push(format!(
                "node{n} not idle after 11 recessive bits: field {} ({}) at cycle {} (bit {})",
                f,
                field::name(f),
                c,
                bit(c)
            ));
        }
    }
    // Every frame sent once the nodes agree reaches every other node, once.
    let mut got: HashMap<(usize, Key), Vec<u64>> = HashMap::new();
    for d in sys.deliveries() {
        got.entry((d.node, key(&d.frame)))
            .or_default()
            .push(d.cycle);
    }
    let late: Vec<&NodeEvent> = sys.tx_done().iter().filter(|e| e.cycle > quiet).collect();
    for e in &late {
        for r in (0..sc.nodes.len()).filter(|&r| r != e.node) {
            let n = got.get(&(r, key(&e.frame))).map_or(0, |v| {
                v.iter()
                    .filter(|&&c| c + 2 * cpb >= e.cycle && c <= e.cycle)
                    .count()
            });
            if n != 1 {
                problems.push(format!(
                    "frame {} sent by node{} at bit {} (fault free) was delivered {n} times to node{r}",
                    e.frame,
                    e.node,
                    bit(e.cycle)
                ));
            }
        }
    }
    let late_deliveries = sys.deliveries().iter().filter(|d| d.cycle > quiet).count();
    if late_deliveries != late.len() * (sc.nodes.len() - 1) {
        problems.push(format!(
            "{late_deliveries} deliveries after all nodes were idle together, for {} frames sent",
            late.len()
        ));
    }

    let (offs, recovered): (usize, usize) = logs
        .iter()
        .fold((0, 0), |(o, r), l| (o + l.bus_off, r + l.recovered));
    if recovered != offs {
        problems.push(format!(
            "{offs} bus-off entries but {recovered} recoveries by the end of the run"
        ));
    }
    for (n, l) in logs.iter().enumerate() {
        if l.max_tec == 0 && l.max_rec == 0 && !fp.faults.is_empty() {
            problems.push(format!(
                "FAULTS INEFFECTIVE: node{n}'s counters never left 0"
            ));
        }
    }
    tot.settle_bits = tot.settle_bits.max(bit(settled.saturating_sub(ff)));
    tot.quiet_bits = tot.quiet_bits.max(bit(quiet - ff));
    tot.synchronised_frames += late.len();
}

/// The first cycle at or after `from` at which every node is idle (and not
/// bus-off), from the nodes' trails.
fn all_idle_from(logs: &[NodeLog], from: u64) -> Option<u64> {
    let mut idx = vec![0usize; logs.len()];
    let mut cur: Vec<Option<Mark>> = vec![None; logs.len()];
    loop {
        // The next cycle at which some node changes.
        let next = logs
            .iter()
            .zip(&idx)
            .filter_map(|(l, &i)| l.trail.get(i).map(|m| m.cycle))
            .min()?;
        for (n, l) in logs.iter().enumerate() {
            while let Some(m) = l.trail.get(idx[n]).filter(|m| m.cycle == next) {
                cur[n] = Some(*m);
                idx[n] += 1;
            }
        }
        if next >= from
            && cur
                .iter()
                .all(|m| m.is_some_and(|m| m.field == field::IDLE && m.err_state != 2))
        {
            return Some(next);
        }
    }
}

// ---------------------------------------------------------------------------
// Fault confinement of a dead node

/// A node whose receiver reads recessive for good (a broken transceiver RXD)
/// sends its SOF and reads it back recessive. ISO 11898-1 bit monitoring: a node
/// sending a bit detects a bit error when it reads another value; the only
/// exceptions are a recessive bit read dominant in arbitration or in the ACK
/// slot and a passive error flag. So the SOF is a bit error (rule c: TEC + 8), its
/// active error flag reads back recessive (rule d: + 8 per flag), and after at
/// most 32 errors (a few hundred bit times) the node is bus-off: it sends
/// recessive only, and the other nodes communicate again although the fault
/// persists (this is what fault confinement is for).
#[test]
fn dead_receiver_is_confined_by_bus_off() {
    dead_node_is_confined(FaultTarget::Rx(0));
}

/// A node whose transmitter cannot drive dominant (a broken transceiver TXD)
/// reads its own SOF recessive: bit errors at every attempt and in its own flags,
/// bus-off after at most 32 of them (ISO 11898-1 bit monitoring, rules c and d).
#[test]
fn dead_transmitter_goes_bus_off() {
    dead_node_is_confined(FaultTarget::Tx(0));
}

fn dead_node_is_confined(target: FaultTarget) {
    let mut kinds = vec![EngineKind::Model, EngineKind::RustHdl];
    if verilator_present() {
        kinds.push(EngineKind::Verilator);
    }
    let timing = drcc_testbench::bitrate::solve(8_000_000, 1_000_000).unwrap();
    let cpb = timing.clocks_per_bit() as u64;
    let frame = |id: u32| Frame {
        id,
        ide: false,
        rtr: false,
        dlc: 2,
        data: [0xA5, 0x5A, 0, 0, 0, 0, 0, 0],
    };
    let mut problems = Vec::new();
    for kind in kinds {
        let engines = (0..3).map(|_| make_engine(kind).unwrap()).collect();
        let mut sys = System::new(engines, timing).unwrap();
        // Node 0 has a frame to send when its transceiver breaks (bit 20, for
        // 4000 bits). By ISO 11898-1 it is bus-off a few hundred bits later (16
        // bit errors in its active flags, then 16 attempts of about 26 bits as
        // an error-passive transmitter); nodes 1 and 2 send a frame every 150 bits
        // from bit 1300 on.
        sys.submit(0, 30 * cpb, frame(0x100)).unwrap();
        for k in 0..12u64 {
            let node = 1 + (k % 2) as usize;
            sys.submit(node, (1300 + 150 * k) * cpb, frame(0x200 + k as u32))
                .unwrap();
        }
        sys.add_fault(Fault {
            target,
            kind: FaultKind::StuckRecessive,
            start: 20 * cpb,
            cycles: 4000 * cpb,
        })
        .unwrap();
        let mut bus_off_at = None;
        let mut max_tec = 0;
        while sys.cycle() < 3200 * cpb {
            let s = sys.step();
            let p = s.outputs[0].probes;
            max_tec = max_tec.max(p.tec);
            if p.err_state == 2 && bus_off_at.is_none() {
                bus_off_at = Some(s.cycle / cpb);
            }
        }
        let others = sys.tx_done().iter().filter(|e| e.node != 0).count();
        let o = sys.sample().outputs[0];
        let state = format!(
            "{kind}: node0 {:?} stuck recessive from bit 20: max tec {max_tec}, bus-off at bit \
             {bus_off_at:?}; at bit 3200 field {} ({}), tx {}, tx_pending {}; nodes 1 and 2 sent \
             {others} of their 12 frames (due from bit 1300 on) by bit 3200",
            target,
            o.probes.field,
            field::name(o.probes.field),
            o.tx,
            o.tx_pending
        );
        if bus_off_at.is_none_or(|b| b > 1200) {
            problems.push(format!("node0 not bus-off by bit 1200 -- {state}"));
        }
        if others < 6 {
            problems.push(format!(
                "nodes 1 and 2 do not communicate while node0 is confined -- {state}"
            ));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
