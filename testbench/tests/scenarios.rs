//! Every bundled scenario runs on the reference model and meets its expected
//! deliveries; the demo also shows the contested arbitrations it is written for.

use drcc_testbench::run::{build_system, run, run_system};
use drcc_testbench::{scenarios_dir, EngineKind, Scenario};

fn load(name: &str) -> Scenario {
    let path = scenarios_dir().join(name);
    Scenario::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn run_model(name: &str) -> drcc_testbench::run::RunResult {
    let sc = load(name);
    let r = run(&sc, EngineKind::Model).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        r.passed(),
        "{name} on the model:\n  {}",
        r.problems.join("\n  ")
    );
    assert!(r.outcome.is_idle());
    r
}

#[test]
fn every_scenario_file_loads() {
    let mut n = 0;
    for entry in std::fs::read_dir(scenarios_dir()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            Scenario::load(&path).unwrap_or_else(|e| panic!("{e}"));
            n += 1;
        }
    }
    assert!(n >= 4, "{n} scenario files");
}

#[test]
fn demo_on_model() {
    let r = run_model("demo.toml");
    // 7 frames, each to two receivers.
    assert_eq!(r.sent.len(), 7);
    assert_eq!(r.deliveries.len(), 14);
    // Two contests: the sensor loses to the ECU, the gateway's extended frame to
    // the ECU's base frame.
    assert!(r.arb_lost >= 2, "{} arbitrations lost", r.arb_lost);
    let order: Vec<u32> = r.sent.iter().map(|e| e.frame.id).collect();
    assert_eq!(
        order,
        vec![0x123, 0x321, 0x18FEF100, 0x0A0, 0x0A1, 0x500, 0x14000000]
    );
}

#[test]
fn arbitration_on_model() {
    let r = run_model("arbitration.toml");
    let order: Vec<u32> = r.sent.iter().map(|e| e.frame.id).collect();
    // Lowest arbitration field first within each simultaneous start.
    assert_eq!(
        order,
        vec![
            0x00F,
            0x7EF,
            0x7F0,
            0x0FFF_FFFF,
            0x400,
            0x1000_0000,
            0x3FF,
            0x3FF,
            0x0FFC_0000
        ]
    );
    assert!(r.arb_lost >= 6);
}

#[test]
fn faults_on_model() {
    let sc = load("faults.toml");
    let mut sys = build_system(&sc, EngineKind::Model).unwrap();
    // Count error flags started (field probe enters ERROR_FLAG = 18) per node.
    let mut flags = vec![0u32; sc.nodes.len()];
    let mut prev = vec![0u8; sc.nodes.len()];
    let r = run_system(&sc, &mut sys, |s| {
        for (i, o) in s.outputs.iter().enumerate() {
            if o.probes.field == 18 && prev[i] != 18 {
                flags[i] += 1;
            }
            prev[i] = o.probes.field;
        }
        Ok(())
    })
    .unwrap();
    assert!(r.passed(), "{}", r.problems.join("\n"));
    assert_eq!(r.sent.len(), 3);
    // Every fault hit a frame: three corrupted frames, each flagged by every node.
    assert!(
        flags.iter().all(|&n| n >= 3),
        "error flags per node: {flags:?}"
    );
}

#[test]
fn slow_triple_on_model() {
    run_model("slow_triple.toml");
}
