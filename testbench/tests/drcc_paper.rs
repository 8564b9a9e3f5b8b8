//! The DRCC paper's Figs. 5-8 (seed 003, section IV): channel A has no
//! acknowledging node; TEC climbs by 8 per failed attempt (ISO 11898-1 fault
//! confinement rule 3) to 0x80, channel A turns error passive, the main FSM goes
//! ch1 -> abort1 -> wait2 -> idle2 -> wait3 -> ch2 (Table 1), the message is sent once
//! on B, `transmission_ack` and then `tx_success` pulse for one clock each, and
//! `tx_ok_channel` names channel B.
//!
//! Every expectation below comes from the paper and ISO 11898-1; the golden VCD is
//! the reference model's trace (the oracle), and the Verilated RTL must produce the
//! same outputs clock by clock (lock step in the same run).

use drcc_cosim::engine::drcc_verilator::DrccVerilatorEngine;
use drcc_cosim::host::Policy;
use drcc_testbench::engines::lockstep_engine;
use drcc_testbench::paper::{run_paper, PaperReport, Rate};
use drcc_testbench::EngineKind;

/// Table 1 states: idle1 wait1 ch1 abort1 wait2 idle2 wait3 ch2 (then back to idle2).
const SWITCH_PATH: [u8; 9] = [0, 1, 2, 3, 4, 5, 6, 7, 5];

/// The Verilated RTL to run in lock step with the model; required in CI.
fn cosim_engine() -> Option<EngineKind> {
    lockstep_engine("DRCC", || DrccVerilatorEngine::new().map(|_| ()))
}

fn check_switch(r: &PaperReport, attempts_on_a: usize) {
    assert_eq!(r.states, SWITCH_PATH, "main FSM path (Table 1)");
    assert_eq!(
        r.transmission_ack.len(),
        1,
        "transmission_ack pulses once, one clock"
    );
    assert_eq!(r.tx_success.len(), 1, "tx_success pulses once, one clock");
    assert_eq!(
        r.tx_success[0],
        r.transmission_ack[0] + 1,
        "tx_success follows transmission_ack (paper IV.C steps 4 and 5)"
    );
    assert_eq!(r.tx_ok_channel, 0b10, "tx_ok_channel names channel B");
    assert_eq!(r.tx_failure.len(), 1, "tx_failure pulses once, one clock");
    assert_eq!(
        r.tx_failure_channel, 0b01,
        "tx_failure_channel names channel A"
    );
    assert_eq!(
        r.received_by_node1.len(),
        1,
        "node 1 delivers the message exactly once: {:?}",
        r.received_by_node1
    );
    assert_eq!(r.received_by_node1[0].1, 1, "and it came on channel B");
    let expected_tec: Vec<u16> = (0..=attempts_on_a as u16).map(|k| 8 * k).collect();
    assert_eq!(
        &r.tec_a[..=attempts_on_a],
        &expected_tec[..],
        "TEC of channel A climbs by 8 per failed attempt"
    );
    assert!(r.first_sof_a.unwrap() < r.first_sof_b.unwrap());
    assert!(
        r.tx_failure[0] < r.first_sof_b.unwrap(),
        "A is aborted before B starts"
    );
}

#[test]
fn figs_5_to_8_error_passive_policy_switches_after_sixteen_attempts() {
    let mut vcd = Vec::new();
    let r = run_paper(
        Policy::ErrorPassive,
        Rate::M1,
        EngineKind::Model,
        cosim_engine(),
        Some(&mut vcd),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    // Sixteen ACK errors: TEC 0x80, error passive (ISO 11898-1 12.1.4.2), switch.
    check_switch(&r, 16);
    assert!(r.error_passive_at.unwrap() < r.tx_failure[0]);
    let text = String::from_utf8(vcd).expect("VCD is text");
    insta::assert_snapshot!("drcc_figs_5_8_error_passive_1M", text);
}

#[test]
fn fastest_policy_switches_after_one_failed_attempt() {
    let r = run_paper(
        Policy::KFailed(1),
        Rate::K500,
        EngineKind::Model,
        cosim_engine(),
        None,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    check_switch(&r, 1);
    assert!(
        r.error_passive_at.is_none(),
        "channel A never became error passive"
    );
    // The switchover time itself is measured by the benchmark (`cargo bench --bench
    // switchover`), not asserted here.
}

#[test]
fn k_failed_policy_counts_attempts() {
    let r = run_paper(
        Policy::KFailed(3),
        Rate::M1,
        EngineKind::Model,
        cosim_engine(),
        None,
    )
    .unwrap_or_else(|e| panic!("{e}"));
    check_switch(&r, 3);
}
