//! Co-simulation: the engines agree with the reference model on every output and
//! probe of every node at every clock.
//!
//! - model vs verilator: 2650 random frames over three bit timings (brp 0, 2 and
//!   11), and every bundled scenario (faults included);
//! - model vs rust-hdl: every bundled scenario and 50 random frames (rust-hdl's
//!   simulator is about 50 times slower than Verilator).
//!
//! A missing Verilator skips locally and fails in CI (`CI` or
//! `DRCC_REQUIRE_VERILATOR` set). On a divergence the test fails with the report;
//! the scenario (as TOML, for `drcc cosim`) and VCDs of both engines around the
//! divergence are left in the cargo target tmp dir.

use std::path::PathBuf;

use drcc_testbench::engines::{available, verilator_required, VERILATOR_HINT};
use drcc_testbench::random::Traffic;
use drcc_testbench::run::cosim;
use drcc_testbench::{scenarios_dir, EngineKind, Scenario};

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

fn lockstep(sc: &Scenario, a: EngineKind, b: EngineKind) {
    let dir: PathBuf = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "cosim-{}-{}-{}",
        sc.name,
        a.name(),
        b.name()
    ));
    match cosim(sc, a, b, Some(dir.clone())) {
        Ok(run) => {
            assert!(
                run.result.passed(),
                "{}: {}",
                sc.name,
                run.result.problems.join("\n")
            );
            assert!(
                run.report.outcome.is_idle(),
                "{}: {:?}",
                sc.name,
                run.report.outcome
            );
        }
        Err(e) => {
            let _ = std::fs::create_dir_all(&dir);
            let toml = dir.join("scenario.toml");
            let _ = std::fs::write(&toml, sc.to_toml());
            panic!(
                "{} ({}):\n{e}\nreproduce: drcc cosim {} --engines {},{} --vcd-dir {}",
                sc.name,
                sc.description,
                toml.display(),
                a.name(),
                b.name(),
                dir.display()
            );
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
