//! Dual-bus fault scenarios (issue "The DRCC itself"): 4 DRCC nodes in redundancy
//! mode (switch after 2 failed attempts, every message on both lines), every host
//! submitting 24 frames, one fault on line A. For each fault: every frame submitted
//! by every host is delivered exactly once to every other host, the failure is
//! readable from the registers while it lasts, and after the fault is removed the
//! nodes that left channel A come back to it through wait4 -> idle1 and send on A
//! again. The model and the Verilated RTL run in lock step (a divergence fails).

use drcc_cosim::engine::drcc_verilator::DrccVerilatorEngine;
use drcc_testbench::dual::{run_dual, DualFault, DualReport, DualScenario};
use drcc_testbench::engines::lockstep_engine;
use drcc_testbench::EngineKind;

fn cosim_engine() -> Option<EngineKind> {
    lockstep_engine("DRCC", || DrccVerilatorEngine::new().map(|_| ()))
}

fn run(fault: DualFault) -> DualReport {
    let s = DualScenario::standard(fault);
    let r = run_dual(&s, EngineKind::Model, cosim_engine()).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        r.exactly_once(),
        "{}: missing {:?}, duplicates {:?}, foreign {}",
        fault.name(),
        r.missing,
        r.duplicates,
        r.foreign
    );
    assert_eq!(r.delivered, s.nodes * (s.nodes - 1) * s.frames_per_node);
    r
}

/// AUX_A register: state [1:0], causes [5:2], failures [23:16].
fn aux_failures(aux: u32) -> u32 {
    aux >> 16 & 0xFF
}

/// STATUS register: main FSM state [3:0], aux A state [6:5].
fn fsm_state(status: u32) -> u32 {
    status & 0xF
}
fn aux_a_state(status: u32) -> u32 {
    status >> 5 & 3
}

/// The `affected` nodes judged channel A failed (AUX_A counts a failure while the
/// fault lasts); every node that left channel A came back to it through
/// wait4 -> idle1 after its last failure and sent frames on line A after the
/// fault ended; at the end every node is in idle1 with channel A valid.
fn check_failure_and_return(r: &DualReport, affected: &[usize]) {
    for &n in affected {
        assert!(
            aux_failures(r.aux_a_during[n]) >= 1,
            "{}: node {n} AUX_A {:#x} reports no failure during the fault",
            r.scenario,
            r.aux_a_during[n]
        );
    }
    for n in 0..r.status_end.len() {
        if r.a_failed[n] {
            assert!(
                r.back_on_a[n].is_some(),
                "{}: node {n} did not return to channel A (wait4 -> idle1) after its last failure",
                r.scenario
            );
            assert!(
                r.a_frames_after[n] >= 1,
                "{}: node {n} sent nothing on line A after its return and the fault's end",
                r.scenario
            );
        }
        let status = r.status_end[n];
        assert_eq!(
            fsm_state(status),
            0,
            "{}: node {n} ends in idle1",
            r.scenario
        );
        assert_eq!(
            aux_a_state(status),
            0,
            "{}: node {n} channel A valid again",
            r.scenario
        );
    }
}

#[test]
fn no_fault_every_message_once_and_copies_dropped() {
    let r = run(DualFault::None);
    // dual_tx: every message also reaches every receiver on B; those copies are the
    // duplicates STATS0 counts (3 senders x 24 frames per receiver).
    for (n, stats) in r.stats0_end.iter().enumerate() {
        assert_eq!(stats & 0xFFFF, 72, "node {n} STATS0 duplicates dropped");
        assert_eq!(stats >> 16, 0, "node {n} no RX overrun");
    }
    assert!(r.first_aux_failure.is_none());
}

#[test]
fn cut_line_a() {
    // Each half of line A still acknowledges its own frames: no transmitter sees
    // an error, so no node leaves A; dual_tx's copies on B carry the frames across.
    let r = run(DualFault::CutA);
    check_failure_and_return(&r, &[]);
    assert!(r.a_failed.iter().all(|&f| !f), "nobody needs to leave A");
}

#[test]
fn line_a_stuck_dominant() {
    let r = run(DualFault::AStuckDominant);
    check_failure_and_return(&r, &[0, 1, 2, 3]);
}

#[test]
fn line_a_stuck_recessive() {
    let r = run(DualFault::AStuckRecessive);
    check_failure_and_return(&r, &[0, 1, 2, 3]);
}

#[test]
fn dead_transceiver_on_node_0() {
    let r = run(DualFault::DeadTransceiver);
    check_failure_and_return(&r, &[0]);
}

#[test]
fn node_0_channel_a_bus_off() {
    let r = run(DualFault::ABusOff);
    check_failure_and_return(&r, &[0]);
    // STATUS[10:9]: channel A error state 2 = bus-off (fault confinement, ISO
    // 11898-1 12.1.4.2: TEC > 255 after the babbling), read while the fault lasts.
    assert_eq!(
        r.status_during[0] >> 9 & 3,
        2,
        "node 0 STATUS {:#x}: channel A bus-off",
        r.status_during[0]
    );
}

/// DRCC contract §11.6, manual bus-off recovery, in lock step with the RTL:
/// every node runs with `CTRL.busoff_manual`; node 0's channel A goes bus-off
/// (its transmitter babbles) and stays bus-off after the fault until its host
/// writes `TX_CMD.recover_a`, long after the automatic recovery of the same
/// scenario has ended; from the write it needs at least ISO 11898-1's 128 x 11
/// recessive bits (12.1.4.4) to become error active; the redundancy loses
/// nothing meanwhile and node 0 returns to channel A afterwards.
#[test]
fn node_0_channel_a_bus_off_manual_recovery() {
    const HELD_BITS: u64 = 4_000;
    let auto = run(DualFault::ABusOff);
    let s = DualScenario {
        manual_recovery_bits: Some(HELD_BITS),
        ..DualScenario::standard(DualFault::ABusOff)
    };
    let r = run_dual(&s, EngineKind::Model, cosim_engine()).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        r.exactly_once(),
        "manual recovery: missing {:?}, duplicates {:?}, foreign {}",
        r.missing,
        r.duplicates,
        r.foreign
    );
    assert_eq!(r.delivered, s.nodes * (s.nodes - 1) * s.frames_per_node);
    check_failure_and_return(&r, &[0]);
    let bit = (r.fault_end - r.fault_start) / s.fault_bits;
    let auto_end = auto.a_bus_off_end.expect("automatic recovery ends");
    let written = r.recover_written.expect("the host wrote recover_a");
    assert!(
        auto_end < written - 50 * bit,
        "the automatic recovery ({auto_end}) ends before the manual one is asked ({written})"
    );
    // STATUS[10:9], read 50 bit times before the write: still bus-off.
    assert_eq!(
        r.status_during[0] >> 9 & 3,
        2,
        "node 0 STATUS {:#x}: channel A held bus-off",
        r.status_during[0]
    );
    let end = r.a_bus_off_end.expect("channel A recovers after the write");
    assert!(
        end >= written + 128 * 11 * bit,
        "recovery took {} bit times after the write, ISO 11898-1 needs 128 x 11",
        (end - written) / bit
    );
}
