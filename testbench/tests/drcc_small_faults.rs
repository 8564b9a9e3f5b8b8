//! The dual-bus fault scenarios (`drcc_faults.rs`) with every node a `drcc_small`
//! (drcc_contract.md §1.1: no DMR mailboxes, RX FIFO 8, TX queues 4, history 16):
//! the model built with those sizes and the Verilated `drcc_small` in lock step
//! (a divergence fails), and every frame submitted by every host delivered
//! exactly once to every other host. The hosts push only while a TX queue holds
//! fewer than 4 frames, as firmware built for the configuration would.

use drcc_cosim::engine::drcc_verilator::DrccSmallVerilatorEngine;
use drcc_testbench::drcc_build::DrccBuild;
use drcc_testbench::dual::{run_dual, DualFault, DualScenario};
use drcc_testbench::engines::lockstep_engine;
use drcc_testbench::EngineKind;

fn cosim_engine() -> Option<EngineKind> {
    lockstep_engine("drcc_small", || DrccSmallVerilatorEngine::new().map(|_| ()))
}

fn run(fault: DualFault) {
    let s = DualScenario {
        build: DrccBuild::Small,
        ..DualScenario::standard(fault)
    };
    let r = run_dual(&s, EngineKind::Model, cosim_engine()).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        r.exactly_once(),
        "drcc_small {}: missing {:?}, duplicates {:?}, foreign {}",
        fault.name(),
        r.missing,
        r.duplicates,
        r.foreign
    );
    assert_eq!(r.delivered, s.nodes * (s.nodes - 1) * s.frames_per_node);
    if fault == DualFault::None {
        // dual_tx: every receiver drops the B copies of 3 senders x 24 frames
        // (contract §7), so the 16-entry history found every copy's first.
        for (n, stats) in r.stats0_end.iter().enumerate() {
            assert_eq!(stats & 0xFFFF, 72, "node {n} STATS0 duplicates dropped");
        }
    }
}

#[test]
fn small_no_fault() {
    run(DualFault::None);
}

#[test]
fn small_cut_line_a() {
    run(DualFault::CutA);
}

#[test]
fn small_line_a_stuck_dominant() {
    run(DualFault::AStuckDominant);
}

#[test]
fn small_line_a_stuck_recessive() {
    run(DualFault::AStuckRecessive);
}

#[test]
fn small_dead_transceiver() {
    run(DualFault::DeadTransceiver);
}

#[test]
fn small_node_0_channel_a_bus_off() {
    run(DualFault::ABusOff);
}
