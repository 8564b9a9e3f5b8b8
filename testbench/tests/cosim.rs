//! Co-simulation: the engines agree with the reference model on every output and
//! probe of every node at every clock.
//!
//! - model vs verilator: 2650 random frames over three bit timings (brp 0, 2 and
//!   11), and every bundled scenario (faults included);
//! - model vs rust-hdl: every bundled scenario and 50 random frames (rust-hdl's
//!   simulator is about 50 times slower than Verilator);
//! - the controller configuration and host control (timing contract §6-§9):
//!   every mode, single shot (configured and per frame), low warning limits,
//!   per-node mixes, bus errors and aborts, model vs verilator (and a short mix on rust-hdl), so `tx_failed` and
//!   every diagnostics register are compared clock by clock.
//!
//! A missing Verilator skips locally and fails in CI (`CI` or
//! `DRCC_REQUIRE_VERILATOR` set). On a divergence the test fails with the report;
//! the scenario (as TOML, for `drcc cosim`) and VCDs of both engines around the
//! divergence are left in the cargo target tmp dir.

use std::path::PathBuf;

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::{ControllerConfig, Mode};
use drcc_testbench::engines::available;
use drcc_testbench::random::Traffic;
use drcc_testbench::run::cosim;
use drcc_testbench::scenario::{Expectations, ScheduledAbort};
use drcc_testbench::{scenarios_dir, EngineKind, Scenario};

fn verilator_present() -> bool {
    drcc_tools::verilated("can_channel top", available(EngineKind::Verilator)).is_some()
}

fn lockstep(sc: &Scenario, a: EngineKind, b: EngineKind) {
    if let Err(e) = try_lockstep(sc, a, b) {
        panic!("{e}");
    }
}

/// As [`lockstep`], returning the failure report instead of panicking.
fn try_lockstep(sc: &Scenario, a: EngineKind, b: EngineKind) -> Result<(), String> {
    let dir: PathBuf = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "cosim-{}-{}-{}",
        sc.name,
        a.name(),
        b.name()
    ));
    match cosim(sc, a, b, Some(dir.clone())) {
        Ok(run) => {
            if !run.result.passed() {
                return Err(format!("{}: {}", sc.name, run.result.problems.join("\n")));
            }
            if !run.report.outcome.is_idle() {
                return Err(format!("{}: {:?}", sc.name, run.report.outcome));
            }
            Ok(())
        }
        Err(e) => {
            let _ = std::fs::create_dir_all(&dir);
            let toml = dir.join("scenario.toml");
            let _ = std::fs::write(&toml, sc.to_toml());
            Err(format!(
                "{} ({}):\n{e}\nreproduce: drcc cosim {} --engines {},{} --vcd-dir {}",
                sc.name,
                sc.description,
                toml.display(),
                a.name(),
                b.name(),
                dir.display()
            ))
        }
    }
}

fn random(seed: u64, frames: usize, clock_hz: u64, bitrate: u64) -> Scenario {
    Traffic::new(seed, frames, clock_hz, bitrate)
        .scenario()
        .unwrap()
}

#[test]
fn model_vs_verilator_1m_random() {
    if verilator_present() {
        lockstep(
            &random(101, 2000, 8_000_000, 1_000_000),
            EngineKind::Model,
            EngineKind::Verilator,
        );
    }
}

#[test]
fn model_vs_verilator_500k_brp2_random() {
    if verilator_present() {
        lockstep(
            &random(102, 500, 24_000_000, 500_000),
            EngineKind::Model,
            EngineKind::Verilator,
        );
    }
}

#[test]
fn model_vs_verilator_125k_brp11_random() {
    if verilator_present() {
        lockstep(
            &random(103, 150, 24_000_000, 125_000),
            EngineKind::Model,
            EngineKind::Verilator,
        );
    }
}

fn scenario_files() -> Vec<Scenario> {
    let mut v = Vec::new();
    for entry in std::fs::read_dir(scenarios_dir()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            v.push(Scenario::load(&path).unwrap_or_else(|e| panic!("{e}")));
        }
    }
    assert!(v.len() >= 4);
    v
}

#[test]
fn model_vs_verilator_scenarios() {
    if verilator_present() {
        for sc in scenario_files() {
            lockstep(&sc, EngineKind::Model, EngineKind::Verilator);
        }
    }
}

#[test]
fn model_vs_rusthdl_scenarios() {
    for sc in scenario_files() {
        lockstep(&sc, EngineKind::Model, EngineKind::RustHdl);
    }
}

#[test]
fn model_vs_rusthdl_random() {
    let mut t = Traffic::new(104, 50, 8_000_000, 1_000_000);
    t.max_gap_bits = 40;
    lockstep(
        &t.scenario().unwrap(),
        EngineKind::Model,
        EngineKind::RustHdl,
    );
}

/// Node configurations to co-simulate: (label, per-node configuration of 3 nodes).
fn config_cases() -> Vec<(&'static str, Vec<ControllerConfig>)> {
    let c = |mode, ewl, single_shot| ControllerConfig {
        mode,
        ewl,
        single_shot,
    };
    let n = |mode| c(mode, 96, false);
    vec![
        ("low-ewl", vec![c(Mode::Normal, 8, false); 3]),
        ("single-shot", vec![c(Mode::Normal, 96, true); 3]),
        (
            "listen-only-node",
            vec![n(Mode::ListenOnly), n(Mode::Normal), n(Mode::Normal)],
        ),
        (
            "mixed",
            vec![
                c(Mode::Normal, 1, true),
                n(Mode::SelfTest),
                n(Mode::Loopback),
            ],
        ),
        ("self-test", vec![c(Mode::SelfTest, 0, false); 3]),
        ("listen-only", vec![n(Mode::ListenOnly); 3]),
        ("loopback", vec![c(Mode::Loopback, 255, true); 3]),
    ]
}

/// Random traffic on 3 nodes with the given configuration, a few bit flips on the
/// bus (errors for the diagnostics) and aborts; expectations are not checked
/// (they depend on the mode), only agreement and an idle end.
fn configured(seed: u64, frames: usize, label: &str, configs: Vec<ControllerConfig>) -> Scenario {
    let mut sc = random(seed, frames, 8_000_000, 500_000);
    let cpb = sc.clocks_per_bit();
    sc.name = format!("{}-{label}", sc.name);
    sc.description = format!("{} ({label})", sc.description);
    sc.configs = configs;
    sc.expect = Expectations::Explicit(Vec::new());
    let first = sc.frames[0].at_cycle;
    let last = sc.frames.iter().map(|f| f.at_cycle).max().unwrap_or(0);
    let span = (last - first).max(1);
    // Flips of a whole bit (sure to be sampled) and of 1 or 2 clocks (edges).
    sc.faults = (0..12u64)
        .map(|k| Fault {
            target: FaultTarget::Bus,
            kind: FaultKind::Flip,
            start: first + 40 * cpb + (k * 7919 * cpb + k * 5) % span,
            cycles: if k % 3 == 0 { cpb } else { k % 3 },
        })
        .collect();
    // Every third frame is requested single shot (timing contract §8
    // `tx_single`), on top of the node's configuration.
    for f in sc.frames.iter_mut().skip(1).step_by(3) {
        f.single_shot = true;
    }
    sc.aborts = sc
        .frames
        .iter()
        .step_by(4)
        .enumerate()
        .map(|(k, f)| ScheduledAbort {
            node: f.node,
            at_cycle: f.at_cycle + (k as u64 * 13 * cpb + k as u64) % (80 * cpb),
        })
        .collect();
    sc
}

/// Every case runs; the failures are reported together.
#[test]
fn model_vs_verilator_modes_and_aborts() {
    if verilator_present() {
        let failures: Vec<String> = config_cases()
            .into_iter()
            .enumerate()
            .filter_map(|(k, (label, configs))| {
                let sc = configured(300 + k as u64, 40, label, configs);
                try_lockstep(&sc, EngineKind::Model, EngineKind::Verilator).err()
            })
            .collect();
        assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    }
}

#[test]
fn model_vs_rusthdl_modes_and_aborts() {
    let (label, configs) = config_cases().swap_remove(3);
    lockstep(
        &configured(310, 12, label, configs),
        EngineKind::Model,
        EngineKind::RustHdl,
    );
}

/// Bus-off and its recovery, clock by clock: node 0's receiver stuck
/// recessive reads each of its own dominant bits back wrong (bit errors, TEC
/// plus 8, §4.5), so it goes bus-off, counts its 128 runs of 11 recessive bits
/// (`boff_runs`) and recovers, again and again while the fault lasts; the
/// transmitter role (`is_tx`) begins and ends with every attempt. The model
/// run shows that the scenario does reach bus-off and a whole recovery.
fn bus_off_and_recovery() -> Scenario {
    let mut sc = random(320, 6, 8_000_000, 500_000);
    let cpb = sc.clocks_per_bit();
    sc.name = format!("{}-rx-stuck", sc.name);
    sc.expect = Expectations::Explicit(Vec::new());
    let first = sc.frames.iter().map(|f| f.at_cycle).min().unwrap_or(0);
    for f in sc.frames.iter_mut() {
        f.node = 0;
    }
    sc.faults = vec![Fault {
        target: FaultTarget::Rx(0),
        kind: FaultKind::StuckRecessive,
        start: first.saturating_sub(5 * cpb),
        cycles: 4000 * cpb,
    }];
    sc.max_cycles = sc.max_cycles.max(first + 8000 * cpb);
    sc
}

#[test]
fn bus_off_and_recovery_model_reaches_a_whole_recovery() {
    let sc = bus_off_and_recovery();
    let mut sys = drcc_testbench::run::build_system(&sc, EngineKind::Model).unwrap();
    let (mut max_runs, mut recoveries, mut was_off) = (0u8, 0, false);
    for _ in 0..sc.max_cycles {
        let p = sys.step().outputs[0].probes;
        max_runs = max_runs.max(p.boff_runs);
        if was_off && p.err_state != 2 {
            recoveries += 1;
        }
        was_off = p.err_state == 2;
    }
    assert_eq!(max_runs, 127, "the last run before the recovery edge");
    assert!(
        recoveries >= 2,
        "bus-off and recovery, twice ({recoveries})"
    );
}

#[test]
fn model_vs_verilator_bus_off_and_recovery() {
    if verilator_present() {
        lockstep(
            &bus_off_and_recovery(),
            EngineKind::Model,
            EngineKind::Verilator,
        );
    }
}

/// The comparison itself: two model systems of the demo, one with a glitch on
/// node 2's receiver, must diverge at the glitch; the VCDs written around it show
/// the same first difference to `wave-diff`.
#[test]
fn divergence_is_found_and_traced() {
    use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
    use drcc_cosim::cosim::{lockstep as run_lockstep, CosimError, CosimOptions};
    use drcc_cosim::trace::{first_difference, read_vcd};
    use drcc_testbench::run::build_system;

    let sc = Scenario::load(&scenarios_dir().join("demo.toml")).unwrap();
    let mut a = build_system(&sc, EngineKind::Model).unwrap();
    let mut b = build_system(&sc, EngineKind::Model).unwrap();
    let at = 40 * sc.clocks_per_bit() + 3; // inside frame 0
    b.add_fault(Fault {
        target: FaultTarget::Rx(2),
        kind: FaultKind::Flip,
        start: at,
        cycles: sc.clocks_per_bit(),
    })
    .unwrap();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cosim-divergence-selftest");
    let opts = CosimOptions {
        max_cycles: sc.max_cycles,
        clock_hz: sc.clock_hz,
        vcd_dir: Some(dir),
        ..CosimOptions::default()
    };
    let Err(CosimError::Divergence(d)) = run_lockstep(&mut a, &mut b, &opts) else {
        panic!("no divergence found");
    };
    assert_eq!((d.cycle, d.node, d.signal.as_str()), (at, 2, "rx"));
    assert_eq!((d.bit(), d.clock_in_bit()), (40, 3));
    assert_eq!(d.vcd_files.len(), 3, "{:?}", d.vcd_error);
    let ta = read_vcd(&d.vcd_files[0]).unwrap();
    let tb = read_vcd(&d.vcd_files[1]).unwrap();
    let diff = first_difference(&ta, &tb, &[]).unwrap();
    let first = diff.first.expect("the traces differ");
    assert_eq!(first.signal, "tb.node2.rx");
    assert_eq!(
        first.cycle,
        Some(at - 1),
        "rx of cycle n is drawn with the tx of n-1"
    );
    // Restricted to node 2's outputs, the first difference comes later (the
    // synchronizer, then the sample point).
    let out = first_difference(
        &ta,
        &tb,
        &["node2.tx".to_string(), "node2.sampled_bit".to_string()],
    )
    .unwrap()
    .first
    .map(|f| f.cycle);
    assert!(matches!(out, Some(Some(c)) if c > at), "{out:?}");
}
