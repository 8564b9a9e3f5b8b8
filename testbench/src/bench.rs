//! The engine benchmark (`cargo bench`, `drcc bench`): the same workloads on every
//! available engine in one run, reporting simulated clock cycles per second and
//! the ratios between engines. It measures; it asserts nothing about time.
//!
//! Workloads (8 MHz clock, 1 Mbit/s):
//! - `1 channel`: one node sending random frames that nobody acknowledges (ACK
//!   errors, error frames, retransmissions: the channel is busy all the time),
//! - `3-node system`: three nodes exchanging random traffic with contested
//!   arbitration (cycles of the system: three channels per cycle); both channel
//!   workloads run as `drcc sim` runs a scenario without traces
//!   (`System::run_for`: every clock stepped, outputs converted where the host
//!   needs them),
//! - `DRCC dual bus`: four DRCC nodes (`drcc` top: two channels, redundancy
//!   management, registers, DMR) on a dual bus, each host driving its node over
//!   Wishbone as in `drcc redundancy` (polling the receive FIFO, pushing a frame
//!   every [`DUAL_PERIOD_BITS`] bit times, sent on both lines: the lines are busy
//!   most of the time),
//! - `hub 4x2`: one ReCANcentrate hub (4 node ports, 2 interlinks) on the random
//!   stimulus of its co-simulation test (frames, ACKs, faulty ports, register
//!   traffic).

use crate::campaign::Topology;
use std::io::{self, Write};
use std::time::{Duration, Instant};

use drcc_cosim::dual::DualBusSystem;
use drcc_cosim::engine::drcc::DrccEngine;
use drcc_cosim::engine::drcc_rusthdl;
use drcc_cosim::engine::hub::HubOutputs;

use crate::dual::{drcc_engine, DualFault, DualScenario, CLOCKS_PER_BIT};
use crate::engines::{make_engine, EngineKind};
use crate::hub_stim::HubStim;
use crate::random::Traffic;
use crate::run::build_system_with;
use crate::star::{hub_engine, HUB_M, HUB_N};

/// One measurement.
#[derive(Clone, Debug)]
pub struct Measurement {
    /// Engine.
    pub engine: EngineKind,
    /// Workload name.
    pub workload: &'static str,
    /// Simulated system clock cycles.
    pub cycles: u64,
    /// Wall-clock time.
    pub seconds: f64,
}

impl Measurement {
    /// Simulated cycles per second.
    pub fn rate(&self) -> f64 {
        self.cycles as f64 / self.seconds.max(1e-9)
    }
}

/// The channel workloads: (name, nodes).
pub const WORKLOADS: [(&str, usize); 2] = [("1 channel", 1), ("3-node system", 3)];

/// Name of the DRCC workload.
pub const DUAL_WORKLOAD: &str = "DRCC dual bus";

/// Name of the hub workload.
pub const HUB_WORKLOAD: &str = "hub 4x2";

/// Every workload, in the order of the table's columns.
pub const COLUMNS: [&str; 4] = [WORKLOADS[0].0, WORKLOADS[1].0, DUAL_WORKLOAD, HUB_WORKLOAD];

/// Nodes of the DRCC workload.
pub const DUAL_NODES: usize = 4;

/// Bit times between two frames of one host in the DRCC workload (four hosts, a
/// frame of about 60 bits on each line: about 80 % bus load).
pub const DUAL_PERIOD_BITS: u64 = 300;

/// Simulated cycles between two looks at the clock (and, on the DRCC workload,
/// between two rounds of frame submissions).
const BATCH: u64 = 1000;

/// Calls `run(first, BATCH)` (run clocks `first .. first + batch`) for
/// `first` = 0, `batch`, ... for about `budget` of wall-clock time (at least one
/// batch, at most `max_cycles`), looking at the clock between batches.
fn time_cycles(
    engine: EngineKind,
    workload: &'static str,
    budget: Duration,
    max_cycles: u64,
    batch: u64,
    mut run: impl FnMut(u64, u64),
) -> Measurement {
    let start = Instant::now();
    let mut cycles = 0u64;
    loop {
        run(cycles, batch);
        cycles += batch;
        if cycles >= max_cycles || start.elapsed() >= budget {
            break;
        }
    }
    Measurement {
        engine,
        workload,
        cycles,
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// Runs one channel workload on one engine for about `budget` of wall-clock time
/// (at least 1000 cycles, at most `max_cycles`).
pub fn measure(
    engine: EngineKind,
    workload: &'static str,
    nodes: usize,
    budget: Duration,
    max_cycles: u64,
) -> Result<Measurement, String> {
    let mut traffic = Traffic::new(0xD_CC, 5000, 8_000_000, 1_000_000);
    traffic.nodes = nodes;
    traffic.max_gap_bits = 40;
    let sc = traffic.scenario()?;
    let mut sys = build_system_with(&sc, |_| make_engine(engine))?;
    // `run_for`: what runs nobody watches clock by clock use (`drcc sim` without
    // traces); the same events as stepping clock by clock.
    Ok(time_cycles(
        engine,
        workload,
        budget,
        max_cycles,
        BATCH,
        |_, n| sys.run_for(n),
    ))
}

/// The DRCC nodes of the [`DUAL_WORKLOAD`] on `engine`. rust-hdl has its own DRCC
/// engine, which the scenario runners refuse for being too slow for network runs.
fn dual_node(engine: EngineKind) -> Result<Box<dyn DrccEngine>, String> {
    match engine {
        EngineKind::RustHdl => Ok(drcc_rusthdl::drcc()),
        k => drcc_engine(k),
    }
}

/// Runs the [`DUAL_WORKLOAD`] on `engine` for about `budget` (at least `batch`
/// cycles, at most `max_cycles`): the hosts configure their nodes as the dual-bus
/// fault scenarios do, then submit frames every [`DUAL_PERIOD_BITS`] bit times.
pub fn measure_dual(
    engine: EngineKind,
    budget: Duration,
    max_cycles: u64,
    batch: u64,
) -> Result<Measurement, String> {
    let s = DualScenario::standard(DualFault::None);
    let engines = (0..DUAL_NODES)
        .map(|_| dual_node(engine))
        .collect::<Result<Vec<_>, _>>()?;
    let mut sys = DualBusSystem::new(engines, vec![s.host_config(); DUAL_NODES])?;
    let period = DUAL_PERIOD_BITS * CLOCKS_PER_BIT;
    // Frame k of host n is due at 100 bit times + k periods, staggered by node
    // (as in `dual::run_dual`); submitted one batch ahead.
    let due = |n: usize, k: u64| 100 * CLOCKS_PER_BIT + k * period + n as u64 * 37 * CLOCKS_PER_BIT;
    let mut next = [0u64; DUAL_NODES];
    Ok(time_cycles(
        engine,
        DUAL_WORKLOAD,
        budget,
        max_cycles,
        batch,
        |first, n| {
            for (node, k) in next.iter_mut().enumerate() {
                while due(node, *k) < first + 2 * n {
                    let frame = DualScenario::frame(node, *k as usize);
                    sys.node_mut(node).host.submit(due(node, *k), frame, 0);
                    *k += 1;
                }
            }
            for _ in 0..n {
                sys.step();
            }
        },
    ))
}

/// Runs one hub (N = 4, M = 2) on `engine` with the co-simulation test's random
/// stimulus for about `budget`.
pub fn measure_hub(
    engine: EngineKind,
    budget: Duration,
    max_cycles: u64,
) -> Result<Measurement, String> {
    let mut hub = hub_engine(engine, 0, HUB_N, HUB_M)?;
    let mut stim = HubStim::new(0xD_CC, HUB_N, HUB_M);
    let mut prev = HubOutputs::default();
    Ok(time_cycles(
        engine,
        HUB_WORKLOAD,
        budget,
        max_cycles,
        BATCH,
        |_, n| {
            for _ in 0..n {
                let i = stim.next(&prev);
                prev = hub.step(&i);
            }
        },
    ))
}

/// Every workload of the table on `engine`, in [`COLUMNS`] order; an error where
/// the engine cannot run it.
pub fn measure_engine(engine: EngineKind, budget: Duration) -> Vec<Result<Measurement, String>> {
    const MAX: u64 = 200_000_000;
    let mut row: Vec<Result<Measurement, String>> = WORKLOADS
        .iter()
        .map(|&(name, nodes)| measure(engine, name, nodes, budget, MAX))
        .collect();
    // rust-hdl's DRCC is slow: small batches keep it near the budget.
    let batch = if engine == EngineKind::RustHdl {
        10
    } else {
        BATCH
    };
    row.push(measure_dual(engine, budget, MAX, batch));
    row.push(measure_hub(engine, budget, MAX));
    row
}

fn human(rate: f64) -> String {
    if rate >= 1e6 {
        format!("{:.2} M/s", rate / 1e6)
    } else if rate >= 1e3 {
        format!("{:.1} k/s", rate / 1e3)
    } else {
        format!("{rate:.0} /s")
    }
}

/// Runs every workload on every available engine and prints the table: per
/// workload the rate and the ratio to the model's rate in the same run.
pub fn run(out: &mut dyn Write, budget: Duration) -> io::Result<Vec<Measurement>> {
    run_engines(out, budget, &EngineKind::ALL)
}

/// [`run`] on `engines` only (ratios need the model among them; the campaign lines
/// are printed when the model or Verilator is among them). For profiling one
/// engine: `DRCC_BENCH_ENGINES=verilator cargo bench --bench engines`.
pub fn run_engines(
    out: &mut dyn Write,
    budget: Duration,
    engines: &[EngineKind],
) -> io::Result<Vec<Measurement>> {
    writeln!(
        out,
        "drcc bench: simulated clock cycles per second, same workloads on every engine \
         (8 MHz clock, 1 Mbit/s; about {:.1} s per measurement; x = speed vs model)",
        budget.as_secs_f64()
    )?;
    let rows: Vec<(EngineKind, Vec<Result<Measurement, String>>)> = engines
        .iter()
        .map(|&e| (e, measure_engine(e, budget)))
        .collect();
    let model: Vec<Option<f64>> = rows
        .iter()
        .find(|(e, _)| *e == EngineKind::Model)
        .map(|(_, r)| {
            r.iter()
                .map(|m| m.as_ref().ok().map(|m| m.rate()))
                .collect()
        })
        .unwrap_or_else(|| vec![None; COLUMNS.len()]);
    let mut header = format!("{:<10}", "engine");
    for c in COLUMNS {
        header += &format!(" {c:>22}");
    }
    writeln!(out, "{header}")?;
    let mut all = Vec::new();
    let mut unavailable = Vec::new();
    for (engine, row) in &rows {
        let mut line = format!("{:<10}", engine.name());
        for ((m, base), column) in row.iter().zip(&model).zip(COLUMNS) {
            let cell = match (m, base) {
                (Ok(m), Some(b)) => format!("{} {:>7}", human(m.rate()), ratio(m.rate() / b)),
                (Ok(m), None) => human(m.rate()),
                (Err(e), _) => {
                    unavailable.push(format!("{column} on {}: {e}", engine.name()));
                    "n/a".to_string()
                }
            };
            line += &format!(" {cell:>22}");
        }
        writeln!(out, "{line}")?;
        all.extend(row.iter().filter_map(|m| m.as_ref().ok().cloned()));
    }
    for u in unavailable {
        writeln!(out, "not available: {u}")?;
    }
    // Fault campaign throughput on one core: single-fault scenarios of `drcc
    // campaign` (seed 1) per topology, model and Verilated RTL side by side.
    let campaign_engines: Vec<EngineKind> = [EngineKind::Model, EngineKind::Verilator]
        .into_iter()
        .filter(|e| engines.contains(e))
        .collect();
    for topology in [Topology::Dual, Topology::Star] {
        if campaign_engines.is_empty() {
            break;
        }
        let mut campaign_line = Vec::new();
        for &engine in &campaign_engines {
            match campaign_rate(topology, engine, budget) {
                Ok((n, secs)) => campaign_line.push(format!(
                    "{} {:.2} scenarios/s ({n} in {secs:.1} s)",
                    engine.name(),
                    n as f64 / secs
                )),
                Err(e) => campaign_line.push(format!("{}: not available: {e}", engine.name())),
            }
        }
        writeln!(
            out,
            "campaign, {}, single faults, per core: {}",
            topology.name(),
            campaign_line.join(", ")
        )?;
    }
    let rate = |k: EngineKind, w: &str| {
        all.iter()
            .find(|m| m.engine == k && m.workload == w)
            .map(|m| m.rate())
    };
    for w in COLUMNS {
        if let (Some(v), Some(r)) = (rate(EngineKind::Verilator, w), rate(EngineKind::RustHdl, w)) {
            writeln!(
                out,
                "{w}: verilator runs {:.0}x as fast as rust-hdl",
                v / r.max(1e-9)
            )?;
        }
    }
    Ok(all)
}

/// `0.45x`, with three decimals below 0.1x (rust-hdl is around 0.001x).
fn ratio(r: f64) -> String {
    if r < 0.1 {
        format!("{r:.3}x")
    } else {
        format!("{r:.2}x")
    }
}

/// Single-fault campaign scenarios of `topology` run on one core within `budget`
/// (at least one): (scenarios, seconds).
fn campaign_rate(
    topology: Topology,
    engine: EngineKind,
    budget: Duration,
) -> Result<(u64, f64), String> {
    crate::engines::available(engine)?;
    let start = std::time::Instant::now();
    let mut n = 0;
    while n == 0 || start.elapsed() < budget {
        let spec = crate::campaign::draw(topology, 1, 1, n);
        crate::campaign::run_one(&spec, engine)?;
        n += 1;
    }
    Ok((n, start.elapsed().as_secs_f64()))
}
