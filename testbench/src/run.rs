//! Running scenarios: build a [`System`] from a [`Scenario`] on an engine, run it
//! until idle, check the expected deliveries; and co-simulate a scenario on two
//! engines.

use std::path::PathBuf;

use drcc_cosim::cosim::{lockstep_observed, CosimError, CosimOptions, CosimReport};
use drcc_cosim::system::{NodeEvent, RunOutcome, Sample, System};
use drcc_cosim::{ChannelEngine, Frame};

use crate::engines::{make_engine, EngineKind};
use crate::scenario::{Expectations, Scenario};

/// The outcome of one run.
#[derive(Clone, Debug)]
pub struct RunResult {
    /// Engines that ran.
    pub engine: String,
    /// How the run ended.
    pub outcome: RunOutcome,
    /// Every delivered frame.
    pub deliveries: Vec<NodeEvent>,
    /// Every sent frame (`tx_done`).
    pub sent: Vec<NodeEvent>,
    /// Every dropped frame (`tx_failed`).
    pub failed: Vec<NodeEvent>,
    /// Number of lost arbitrations.
    pub arb_lost: usize,
    /// Expectations not met (empty: pass).
    pub problems: Vec<String>,
}

impl RunResult {
    /// Whether every expectation was met.
    pub fn passed(&self) -> bool {
        self.problems.is_empty()
    }
}

/// Builds the system of a scenario with engines from `make` (called once per node).
pub fn build_system_with(
    sc: &Scenario,
    mut make: impl FnMut(usize) -> Result<Box<dyn ChannelEngine>, String>,
) -> Result<System, String> {
    let engines = (0..sc.nodes.len())
        .map(&mut make)
        .collect::<Result<Vec<_>, _>>()?;
    let mut sys = System::new(engines, sc.timing)?;
    sys.set_names(sc.nodes.clone())?;
    sys.set_reset_cycles(sc.reset_cycles);
    for (node, config) in sc.configs.iter().enumerate() {
        sys.set_node_config(node, *config)?;
    }
    for f in &sc.faults {
        sys.add_fault(*f)?;
    }
    for f in &sc.frames {
        if f.single_shot {
            sys.submit_single_shot(f.node, f.at_cycle, f.frame)?;
        } else {
            sys.submit(f.node, f.at_cycle, f.frame)?;
        }
    }
    for a in &sc.aborts {
        sys.abort(a.node, a.at_cycle)?;
    }
    Ok(sys)
}

/// Builds the system of a scenario with every node on `kind`.
pub fn build_system(sc: &Scenario, kind: EngineKind) -> Result<System, String> {
    build_system_with(sc, |_| make_engine(kind))
}

/// Runs a scenario on an engine and checks it. Nobody watches single clocks:
/// [`System::run_until_idle`] (the same events as [`run_observed`]'s clock by
/// clock stepping).
pub fn run(sc: &Scenario, kind: EngineKind) -> Result<RunResult, String> {
    run_with_progress(sc, kind, |_| {})
}

/// [`run`], calling `progress` with the cycle reached at every multiple of
/// 65,536 cycles the run passes.
pub fn run_with_progress(
    sc: &Scenario,
    kind: EngineKind,
    mut progress: impl FnMut(u64),
) -> Result<RunResult, String> {
    const CHUNK: u64 = 65_536;
    let mut sys = build_system(sc, kind)?;
    // Stopping at a chunk's end changes nothing: run_until_idle decides from the
    // system's state alone.
    let outcome = loop {
        let limit = ((sys.cycle() / CHUNK + 1) * CHUNK).min(sc.max_cycles);
        match sys.run_until_idle(limit) {
            RunOutcome::CycleLimit { cycle } if cycle < sc.max_cycles => progress(cycle),
            o => break o,
        }
    };
    Ok(result(sc, &sys, outcome))
}

/// As [`run`], calling `observe` with every sample (to write traces).
pub fn run_observed(
    sc: &Scenario,
    kind: EngineKind,
    observe: impl FnMut(&Sample) -> Result<(), String>,
) -> Result<RunResult, String> {
    let mut sys = build_system(sc, kind)?;
    run_system(sc, &mut sys, observe)
}

/// Runs an already built system of a scenario and checks it.
pub fn run_system(
    sc: &Scenario,
    sys: &mut System,
    observe: impl FnMut(&Sample) -> Result<(), String>,
) -> Result<RunResult, String> {
    let outcome = sys.run_until_idle_with(sc.max_cycles, observe)?;
    Ok(result(sc, sys, outcome))
}

/// Collects the result of a finished run.
pub fn result(sc: &Scenario, sys: &System, outcome: RunOutcome) -> RunResult {
    RunResult {
        engine: sys.engine_label(),
        outcome,
        deliveries: sys.deliveries().to_vec(),
        sent: sys.tx_done().to_vec(),
        failed: sys.tx_failed().to_vec(),
        arb_lost: sys.arb_lost().len(),
        problems: check(sc, sys, outcome),
    }
}

fn describe(sc: &Scenario, node: usize) -> String {
    format!(
        "node {node} (`{}`)",
        sc.nodes.get(node).map_or("?", |s| s.as_str())
    )
}

/// Compares expected frame numbers with observed events of one node.
fn compare(
    sc: &Scenario,
    node: usize,
    verb: &str,
    expected: &[usize],
    observed: &[&NodeEvent],
    problems: &mut Vec<String>,
) {
    let mut open: Vec<(usize, Frame)> = expected
        .iter()
        .map(|&i| (i, sc.frames[i].frame.normalized()))
        .collect();
    for ev in observed {
        let f = ev.frame.normalized();
        match open.iter().position(|(_, e)| *e == f) {
            Some(p) => {
                open.remove(p);
            }
            None => problems.push(format!(
                "{} {verb} an unexpected frame {f} at cycle {} (bit {})",
                describe(sc, node),
                ev.cycle,
                ev.cycle / sc.clocks_per_bit()
            )),
        }
    }
    for (i, f) in open {
        problems.push(format!(
            "{} did not {} frame {i} ({f})",
            describe(sc, node),
            match verb {
                "received" => "receive",
                "dropped" => "drop (tx_failed)",
                _ => "send",
            }
        ));
    }
}

/// Checks a finished run against the scenario's expectations; returns the
/// problems found (empty: pass).
pub fn check(sc: &Scenario, sys: &System, outcome: RunOutcome) -> Vec<String> {
    let mut problems = Vec::new();
    if let RunOutcome::CycleLimit { cycle } = outcome {
        let mut why = Vec::new();
        for n in 0..sys.nodes() {
            let q = sys.queued(n);
            let pending = sys.sample().outputs.get(n).is_some_and(|o| o.tx_pending);
            if q > 0 || pending {
                why.push(format!(
                    "{}: {q} queued{}",
                    describe(sc, n),
                    if pending { ", one pending" } else { "" }
                ));
            }
        }
        problems.push(format!(
            "the run did not end within {cycle} cycles ({} bit times){}",
            cycle / sc.clocks_per_bit(),
            if why.is_empty() {
                " (the bus never became idle)".to_string()
            } else {
                format!(": {}", why.join("; "))
            }
        ));
    }
    let n = sc.nodes.len();
    let rx_of =
        |k: usize| -> Vec<&NodeEvent> { sys.deliveries().iter().filter(|e| e.node == k).collect() };
    let tx_of =
        |k: usize| -> Vec<&NodeEvent> { sys.tx_done().iter().filter(|e| e.node == k).collect() };
    let failed_of =
        |k: usize| -> Vec<&NodeEvent> { sys.tx_failed().iter().filter(|e| e.node == k).collect() };
    match &sc.expect {
        Expectations::EveryFrameToEveryOtherNode => {
            for k in 0..n {
                let receives: Vec<usize> = (0..sc.frames.len())
                    .filter(|&i| sc.frames[i].node != k)
                    .collect();
                let sends: Vec<usize> = (0..sc.frames.len())
                    .filter(|&i| sc.frames[i].node == k)
                    .collect();
                compare(sc, k, "received", &receives, &rx_of(k), &mut problems);
                compare(sc, k, "sent", &sends, &tx_of(k), &mut problems);
            }
        }
        Expectations::Explicit(list) => {
            for e in list {
                if let Some(r) = &e.receives {
                    compare(sc, e.node, "received", r, &rx_of(e.node), &mut problems);
                }
                if let Some(s) = &e.sends {
                    compare(sc, e.node, "sent", s, &tx_of(e.node), &mut problems);
                }
                if let Some(f) = &e.fails {
                    compare(sc, e.node, "dropped", f, &failed_of(e.node), &mut problems);
                }
            }
        }
    }
    problems
}

/// A successful co-simulation, with the expectations checked on the first system.
#[derive(Clone, Debug)]
pub struct CosimRun {
    /// The lock-step report.
    pub report: CosimReport,
    /// The result of the first system (deliveries, expectations).
    pub result: RunResult,
}

/// Co-simulates a scenario on engines `a` and `b`. Engine construction failures
/// are [`CosimError::Setup`]; a divergence is [`CosimError::Divergence`].
pub fn cosim(
    sc: &Scenario,
    a: EngineKind,
    b: EngineKind,
    vcd_dir: Option<PathBuf>,
) -> Result<CosimRun, CosimError> {
    cosim_observed(sc, a, b, vcd_dir, &mut |_| {})
}

/// [`cosim`], calling `observe` with the first system after every clock both
/// systems agree on (traffic taps).
pub fn cosim_observed(
    sc: &Scenario,
    a: EngineKind,
    b: EngineKind,
    vcd_dir: Option<PathBuf>,
    observe: &mut dyn FnMut(&System),
) -> Result<CosimRun, CosimError> {
    let mut sa = build_system(sc, a).map_err(CosimError::Setup)?;
    let mut sb = build_system(sc, b).map_err(CosimError::Setup)?;
    let opts = CosimOptions {
        max_cycles: sc.max_cycles,
        clock_hz: sc.clock_hz,
        vcd_dir,
        ..CosimOptions::default()
    };
    let report = lockstep_observed(&mut sa, &mut sb, &opts, observe)?;
    let result = result(sc, &sa, report.outcome);
    Ok(CosimRun { report, result })
}
