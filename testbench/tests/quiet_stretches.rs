//! `System::run_until_idle` and `System::run_for` run the stretches in which the
//! host raises nothing through `ChannelEngine::step_quiet` (the Verilator engine
//! then converts only the outputs the host needs): they must give exactly what
//! stepping clock by clock gives. Every scenario file and random traffic with
//! faults, aborts, single-shot and listen-only nodes, on Verilator and on the
//! model (wrapped so that its system takes the quiet stretches too, with the
//! trait's default `step_quiet`): the same outcome, the same events (deliveries,
//! sends, failures, lost arbitrations, with their cycles) and the same last
//! sample; `run_for` also in chunks of odd lengths against as many steps.

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::engine::model::ModelEngine;
use drcc_cosim::engine::{ChannelInputs, ChannelOutputs, ControllerConfig, Mode};
use drcc_cosim::system::System;
use drcc_cosim::ChannelEngine;
use drcc_testbench::engines::{available, make_engine};
use drcc_testbench::random::Traffic;
use drcc_testbench::run::build_system_with;
use drcc_testbench::scenario::ScheduledAbort;
use drcc_testbench::{scenarios_dir, EngineKind, Scenario};

/// Whether `kind` can run here; Verilator missing fails when it is required.
fn engine_here(kind: EngineKind) -> bool {
    drcc_tools::verilated(
        &format!("can_channel top ({})", kind.name()),
        available(kind),
    )
    .is_some()
}

/// The model, taking quiet stretches (the default `step_quiet`).
struct QuietModel(ModelEngine);

impl ChannelEngine for QuietModel {
    fn name(&self) -> &'static str {
        "model"
    }
    fn step(&mut self, inputs: &ChannelInputs) -> ChannelOutputs {
        self.0.step(inputs)
    }
    fn gains_from_quiet(&self) -> bool {
        true
    }
}

fn build_system(sc: &Scenario, kind: EngineKind) -> Result<System, String> {
    build_system_with(sc, |_| match kind {
        EngineKind::Model => Ok(Box::new(QuietModel(ModelEngine::new())) as Box<dyn ChannelEngine>),
        k => make_engine(k),
    })
}

/// Everything a run leaves: events with their cycles and the last sample.
fn state(sys: &System) -> String {
    format!(
        "cycle {}\ndeliveries {:?}\nsent {:?}\nfailed {:?}\narb_lost {:?}\nsample {:?}",
        sys.cycle(),
        sys.deliveries(),
        sys.tx_done(),
        sys.tx_failed(),
        sys.arb_lost(),
        sys.sample()
    )
}

/// Compares the runs; returns the clock-by-clock run's (deliveries, sent, failed,
/// lost arbitrations).
fn same_runs(sc: &Scenario, kind: EngineKind) -> [usize; 4] {
    let what = format!("{} on {}", sc.name, kind.name());
    // run_until_idle against clock-by-clock stepping.
    let mut stepwise = build_system(sc, kind).unwrap();
    let expected = stepwise.run_until_idle_stepwise(sc.max_cycles);
    let mut quiet = build_system(sc, kind).unwrap();
    assert_eq!(quiet.run_until_idle(sc.max_cycles), expected, "{what}");
    assert_eq!(state(&quiet), state(&stepwise), "{what}: run_until_idle");
    // run_for in chunks against as many steps, compared after every chunk.
    let mut a = build_system(sc, kind).unwrap();
    let mut b = build_system(sc, kind).unwrap();
    let mut chunk = 1;
    while a.cycle() < expected.cycles() {
        a.run_for(chunk);
        for _ in 0..chunk {
            b.step();
        }
        assert_eq!(state(&a), state(&b), "{what}: run_for({chunk})");
        chunk = chunk * 7 % 1009 + 1;
    }
    [
        stepwise.deliveries().len(),
        stepwise.tx_done().len(),
        stepwise.tx_failed().len(),
        stepwise.arb_lost().len(),
    ]
}

/// Random traffic on three nodes, plus what makes the host's schedule and the
/// pulses interesting: a receiver fault, a stuck line, aborts, a single-shot and a
/// listen-only node.
fn stressed(seed: u64) -> Scenario {
    let mut t = Traffic::new(seed, 60, 8_000_000, 1_000_000);
    t.nodes = 3;
    t.max_gap_bits = 60;
    let mut sc = t.scenario().unwrap();
    sc.name = format!("stressed traffic {seed}");
    let cpb = sc.clocks_per_bit();
    sc.faults.push(Fault {
        target: FaultTarget::Rx(2),
        kind: FaultKind::StuckRecessive,
        start: 900 * cpb,
        cycles: 300 * cpb,
    });
    sc.faults.push(Fault {
        target: FaultTarget::Bus,
        kind: FaultKind::StuckDominant,
        start: 2_000 * cpb,
        cycles: 40 * cpb,
    });
    for (node, bit) in [(0, 150), (1, 1_234), (1, 1_235), (2, 3_000)] {
        sc.aborts.push(ScheduledAbort {
            node,
            at_cycle: bit * cpb + 3,
        });
    }
    sc.configs[1] = ControllerConfig {
        single_shot: true,
        ..sc.configs[1]
    };
    sc.max_cycles = sc.max_cycles.max(20_000 * cpb);
    sc
}

fn listen_only(seed: u64) -> Scenario {
    let mut sc = stressed(seed);
    sc.name = format!("listen-only node {seed}");
    sc.configs[2] = ControllerConfig {
        mode: Mode::ListenOnly,
        ..sc.configs[2]
    };
    sc
}

fn every_scenario(kind: EngineKind) {
    if !engine_here(kind) {
        return;
    }
    let mut files: Vec<_> = std::fs::read_dir(scenarios_dir())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    assert!(!files.is_empty());
    for f in files {
        let _ = same_runs(&Scenario::load(&f).unwrap(), kind);
    }
    for sc in [stressed(1), stressed(2), listen_only(3)] {
        let counts = same_runs(&sc, kind);
        // Every kind of event happened (else the comparison proves less).
        assert!(counts.iter().all(|&n| n > 0), "{}: {counts:?}", sc.name);
    }
}

#[test]
fn quiet_stretches_match_stepping_on_the_model() {
    every_scenario(EngineKind::Model);
}

#[test]
fn quiet_stretches_match_stepping_on_verilator() {
    every_scenario(EngineKind::Verilator);
}
