//! The engine benchmark (`cargo bench`, `drcc bench`): the same workloads on every
//! available engine in one run, reporting simulated clock cycles per second and
//! the ratios between engines. It measures; it asserts nothing about time.
//!
//! Workloads (8 MHz clock, 1 Mbit/s):
//! - `1 channel`: one node sending random frames that nobody acknowledges (ACK
//!   errors, error frames, retransmissions: the channel is busy all the time),
//! - `3-node system`: three nodes exchanging random traffic with contested
//!   arbitration (cycles of the system: three channels per cycle),
//! - `hub 4x2`: one ReCANcentrate hub (4 node ports, 2 interlinks) on the random
//!   stimulus of its co-simulation test (frames, ACKs, faulty ports, register
//!   traffic).

use crate::campaign::Topology;
use std::io::{self, Write};
use std::time::{Duration, Instant};

use drcc_cosim::engine::hub::HubOutputs;

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

/// The workloads: (name, nodes).
pub const WORKLOADS: [(&str, usize); 2] = [("1 channel", 1), ("3-node system", 3)];

/// Runs one workload on one engine for about `budget` of wall-clock time (at
/// least 1000 cycles, at most `max_cycles`).
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
    let start = Instant::now();
    let mut cycles = 0u64;
    loop {
        for _ in 0..1000 {
            sys.step();
        }
        cycles += 1000;
        if cycles >= max_cycles || start.elapsed() >= budget {
            break;
        }
    }
    Ok(Measurement {
        engine,
        workload,
        cycles,
        seconds: start.elapsed().as_secs_f64(),
    })
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
    let start = Instant::now();
    let mut cycles = 0u64;
    loop {
        for _ in 0..1000 {
            let i = stim.next(&prev);
            prev = hub.step(&i);
        }
        cycles += 1000;
        if cycles >= max_cycles || start.elapsed() >= budget {
            break;
        }
    }
    Ok(Measurement {
        engine,
        workload: "hub 4x2",
        cycles,
        seconds: start.elapsed().as_secs_f64(),
    })
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

/// Runs every workload on every available engine and prints the table.
pub fn run(out: &mut dyn Write, budget: Duration) -> io::Result<Vec<Measurement>> {
    writeln!(
        out,
        "drcc bench: simulated clock cycles per second, same workloads on every engine \
         (8 MHz clock, 1 Mbit/s; about {:.1} s per measurement)",
        budget.as_secs_f64()
    )?;
    let mut all = Vec::new();
    let mut rows: Vec<(EngineKind, Result<Vec<Measurement>, String>)> = Vec::new();
    for engine in EngineKind::ALL {
        let mut ms = Vec::new();
        let mut err = None;
        for (name, nodes) in WORKLOADS {
            match measure(engine, name, nodes, budget, 200_000_000) {
                Ok(m) => ms.push(m),
                Err(e) => {
                    err = Some(e);
                    break;
                }
            }
        }
        rows.push((engine, err.map_or(Ok(ms), Err)));
    }
    let model: Vec<f64> = rows
        .iter()
        .find(|(e, _)| *e == EngineKind::Model)
        .and_then(|(_, r)| r.as_ref().ok())
        .map(|ms| ms.iter().map(|m| m.rate()).collect())
        .unwrap_or_default();
    writeln!(
        out,
        "{:<10} {:>16} {:>16}   {:>22}",
        "engine", WORKLOADS[0].0, WORKLOADS[1].0, "speed vs model (1ch / 3n)"
    )?;
    for (engine, r) in &rows {
        match r {
            Ok(ms) => {
                let ratios: Vec<String> = ms
                    .iter()
                    .zip(&model)
                    .map(|(m, base)| format!("{:.3}x", m.rate() / base.max(1e-9)))
                    .collect();
                writeln!(
                    out,
                    "{:<10} {:>16} {:>16}   {:>22}",
                    engine.name(),
                    human(ms[0].rate()),
                    human(ms[1].rate()),
                    ratios.join(" / ")
                )?;
                all.extend(ms.iter().cloned());
            }
            Err(e) => writeln!(out, "{:<10} not available: {e}", engine.name())?,
        }
    }
    let rate = |k: EngineKind, w: &str| {
        all.iter()
            .find(|m| m.engine == k && m.workload == w)
            .map(|m| m.rate())
    };
    let mut hub_rates = Vec::new();
    for engine in EngineKind::ALL {
        match measure_hub(engine, budget, 200_000_000) {
            Ok(m) => hub_rates.push((engine, m.rate())),
            Err(e) => writeln!(out, "hub 4x2 on {}: not available: {e}", engine.name())?,
        }
    }
    let hub_model = hub_rates
        .iter()
        .find(|(e, _)| *e == EngineKind::Model)
        .map(|(_, r)| *r);
    let hub_line: Vec<String> = hub_rates
        .iter()
        .map(|(e, r)| match hub_model {
            Some(base) => format!("{} {} ({:.3}x)", e.name(), human(*r), r / base.max(1e-9)),
            None => format!("{} {}", e.name(), human(*r)),
        })
        .collect();
    writeln!(out, "hub 4x2 (speed vs model): {}", hub_line.join(", "))?;
    // Fault campaign throughput on one core: single-fault scenarios of `drcc
    // campaign` (seed 1) per topology, model and Verilated RTL side by side.
    for topology in [Topology::Dual, Topology::Star] {
        let mut campaign_line = Vec::new();
        for engine in [EngineKind::Model, EngineKind::Verilator] {
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
    for (w, _) in WORKLOADS {
        if let (Some(v), Some(r)) = (rate(EngineKind::Verilator, w), rate(EngineKind::RustHdl, w)) {
            writeln!(
                out,
                "{w}: verilator runs {:.1}x as fast as rust-hdl",
                v / r.max(1e-9)
            )?;
        }
    }
    Ok(all)
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
