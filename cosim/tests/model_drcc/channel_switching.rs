//! Transmission and channel switching: normal mode (queue A on channel A, queue B
//! on channel B), the error-passive policy of the paper's Fig. 5-7, the k-failed
//! policy and the recovery of channel A through probation.

use super::*;

#[test]
fn normal_mode_queue_a_on_channel_a_queue_b_on_channel_b() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB); // bus integration
    let f1 = frame(
        0x123,
        false,
        false,
        8,
        &[0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88],
    );
    let f2 = frame(0x1ABC_DEF0, true, false, 3, &[0xC0, 0xFF, 0xEE]);
    sys.push(0, &f1, 0);
    let mut b_dominant = false;
    let mut a_dominant = false;
    for _ in 0..(200 * CPB) {
        sys.step();
        b_dominant |= !sys.nodes[0].out.chan_b_tx;
        a_dominant |= !sys.nodes[0].out.chan_a_tx;
    }
    assert!(
        a_dominant && !b_dominant,
        "queue A leaves on channel A only"
    );
    assert_eq!(sys.plain[pa].received, vec![f1]);
    assert!(sys.plain[pb].received.is_empty());
    let st = sys.read(0, INT_STATUS);
    assert_eq!(st & (I_TX_DONE | I_TX_FAILURE), I_TX_DONE);
    sys.write(0, INT_STATUS, 0xFF);
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0, "popped at tx_done");

    sys.push(0, &f2, 1);
    let mut a_dominant = false;
    let mut b_dominant = false;
    for _ in 0..(200 * CPB) {
        sys.step();
        b_dominant |= !sys.nodes[0].out.chan_b_tx;
        a_dominant |= !sys.nodes[0].out.chan_a_tx;
    }
    assert!(
        b_dominant && !a_dominant,
        "queue B leaves on channel B only"
    );
    assert_eq!(sys.plain[pb].received, vec![f2]);
    assert_eq!(sys.plain[pa].received, vec![f1]);
    assert_eq!(sys.read(0, INT_STATUS) & I_TX_DONE, I_TX_DONE);
    let s = sys.read(0, STATUS);
    assert_eq!((status_txq(s, 0), status_txq(s, 1)), (0, 0));
    // The FSM stays in idle1 in normal mode.
    assert_eq!(status_state(s), IDLE1);

    // Both queues at once: each goes on its own channel, in order.
    let g: Vec<Frame> = (0..3)
        .map(|i| frame(0x200 + i, false, false, 1, &[i as u8]))
        .collect();
    for f in &g {
        sys.push(0, f, 0);
        sys.push(0, f, 1);
    }
    sys.run(600 * CPB);
    assert_eq!(sys.plain[pa].received[1..], g[..]);
    assert_eq!(sys.plain[pb].received[1..], g[..]);
}

// ---------------------------------------------------------------------------
// (d) paper Fig 5-7: error-passive policy, channel A without an acknowledging node
// ---------------------------------------------------------------------------

#[test]
fn error_passive_policy_switches_to_channel_b_paper_fig5_to_7() {
    let mut sys = Sys::new(1);
    // Channel A: nobody else (every attempt is an ACK error). Channel B: one node.
    let pb = sys.add_plain(1, true);
    sys.start(0, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let f = frame(0x2A5, false, false, 2, &[0xC3, 0x3C]);
    sys.push(0, &f, 0);
    sys.run(4000 * CPB);

    // TEC of A climbs by 8 per failed attempt up to 0x80, never above; then the
    // restart of channel A clears it.
    let climb: Vec<u16> = (0..=16).map(|i| i * 8).collect();
    assert_eq!(
        sys.trace.tec_a[..17],
        climb[..],
        "TEC A: {:?}",
        sys.trace.tec_a
    );
    assert_eq!(
        sys.trace.tec_a[17..],
        [0],
        "TEC A after the switch: {:?}",
        sys.trace.tec_a
    );

    // Main FSM: idle1 wait1 ch1 abort1 wait2 idle2 wait3 ch2 idle2, then back to A
    // once aux A is valid again (idle2 wait4 idle1).
    assert_eq!(
        sys.trace.state_seq(),
        [IDLE1, WAIT1, CH1, ABORT1, WAIT2, IDLE2, WAIT3, CH2, IDLE2, WAIT4, IDLE1],
        "{:?}",
        sys.trace.states
    );
    // Aux A: valid -> failed (error passive) -> restart -> probation -> valid.
    assert_eq!(
        sys.trace.aux_a.iter().map(|s| s.1).collect::<Vec<_>>(),
        [VALID, FAILED, RESTART, PROBATION, VALID]
    );
    // Sent once on B, acknowledged by the node there.
    assert_eq!(sys.plain[pb].received, vec![f]);
    // transmission_ack then tx_success, one clock each, consecutive.
    assert_eq!(sys.trace.ack.len(), 1);
    assert_eq!(sys.trace.success, vec![sys.trace.ack[0] + 1]);
    // The ack comes with the ch2 -> idle2 edge.
    assert_eq!(sys.trace.ack[0], sys.trace.states[8].0);
    // tx_failure once, for channel A (01), at the wait2 -> idle2 edge.
    assert_eq!(sys.trace.failure, vec![(sys.trace.clock_of(IDLE2), 0b01)]);
    let p = sys.nodes[0].out.probes;
    assert_eq!(p.tx_ok_channel, 0b10, "delivered on channel B");
    assert_eq!(p.tx_failure_channel, 0b01, "latched");

    // Host view.
    let aux_a = sys.read(0, AUX_A);
    assert_eq!(aux_a & 3, VALID as u32);
    assert_eq!(aux_a >> 2 & 0xF, 0b0001, "cause error-passive only");
    assert_eq!(aux_a >> 16 & 0xFF, 1, "one failure");
    assert_eq!(aux_a >> 24 & 0xFF, 1, "one recovery");
    assert_eq!(sys.read(0, AUX_B), 0);
    let stats1 = sys.read(0, STATS1);
    assert_eq!(stats1 & 0xFFFF, 2, "switch to B and back");
    assert_eq!(stats1 >> 16, 1, "one recovery");
    let ints = sys.read(0, INT_STATUS);
    for bit in [I_TX_DONE, I_SWITCH, I_ERR_STATE, I_TX_FAILURE, I_AUX] {
        assert_eq!(ints & bit, bit, "INT_STATUS bit {bit:#x} in {ints:#x}");
    }
    assert_eq!(ints & (I_RX | I_OVERRUN | I_ILLEGAL), 0);
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0, "popped");

    // TIMES: tx_time counts nominal bits from the wait1 -> ch1 edge (cleared there).
    // switch_time is latched at wait2 -> idle2; last_tx_time at the finish (the
    // resend on B does not clear tx_time).
    let times = sys.read(0, TIMES);
    let ch1 = sys.trace.clock_of(CH1);
    let switch_bits = (sys.trace.clock_of(IDLE2) - ch1) / CPB;
    let total_bits = (sys.trace.ack[0] - ch1) / CPB;
    assert!(
        (times >> 16).abs_diff(switch_bits as u32) <= 1,
        "switch_time {} vs {switch_bits}",
        times >> 16
    );
    assert!(
        (times & 0xFFFF).abs_diff(total_bits as u32) <= 1,
        "last_tx_time {} vs {total_bits}",
        times & 0xFFFF
    );
    assert!(switch_bits > 16 * 40, "sixteen attempts before the switch");
}

// ---------------------------------------------------------------------------
// (e) k-failed policy, k = 1
// ---------------------------------------------------------------------------

#[test]
fn k_failed_policy_switches_after_one_failed_attempt() {
    let mut sys = Sys::new(1);
    let pb = sys.add_plain(1, true);
    sys.write(0, RMB_CFG, 50_000); // no recovery during the test
    sys.start(0, REDUNDANCY | policy(2) | k(1));
    sys.run(20 * CPB);
    let f = frame(0x0F0, false, false, 1, &[0x5A]);
    sys.push(0, &f, 0);
    sys.run(400 * CPB);
    // One ACK error (TEC 8), the abort is carried out before any retry, then the
    // restart clears TEC.
    assert_eq!(sys.trace.tec_a, [0, 8, 0], "TEC A: {:?}", sys.trace.tec_a);
    assert_eq!(
        sys.trace.state_seq(),
        [IDLE1, WAIT1, CH1, ABORT1, WAIT2, IDLE2, WAIT3, CH2, IDLE2]
    );
    assert_eq!(
        sys.trace.aux_a.iter().map(|s| s.1).collect::<Vec<_>>(),
        [VALID, FAILED, RESTART, PROBATION]
    );
    assert_eq!(sys.plain[pb].received, vec![f]);
    assert_eq!(sys.trace.success, vec![sys.trace.ack[0] + 1]);
    assert_eq!(sys.nodes[0].out.probes.tx_ok_channel, 0b10);
    let aux_a = sys.read(0, AUX_A);
    assert_eq!(aux_a & 3, PROBATION as u32);
    assert_eq!(aux_a >> 2 & 0xF, 0b0100, "cause k-failed");
    assert_eq!(aux_a >> 8 & 0xF, 0, "failed attempts cleared at restart");
    assert_eq!(aux_a >> 16 & 0xFF, 1);
    // k = 2: two failed attempts (TEC 16) before the switch.
    let mut sys = Sys::new(1);
    sys.add_plain(1, true);
    sys.write(0, RMB_CFG, 50_000);
    sys.start(0, REDUNDANCY | policy(2) | k(2));
    sys.run(20 * CPB);
    sys.push(0, &f, 0);
    sys.run(400 * CPB);
    assert_eq!(
        sys.trace.tec_a,
        [0, 8, 16, 0],
        "TEC A: {:?}",
        sys.trace.tec_a
    );
    assert_eq!(sys.plain[0].received, vec![f]);
}

// ---------------------------------------------------------------------------
// (f) recovery of channel A and return to it
// ---------------------------------------------------------------------------

#[test]
fn recovery_returns_to_channel_a_after_probation() {
    const R: u64 = 100;
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, false); // channel A cut: its only partner is missing
    let pb = sys.add_plain(1, true);
    sys.write(0, RMB_CFG, R as u32);
    sys.start(0, REDUNDANCY | policy(2) | k(1));
    sys.run(20 * CPB);
    let f1 = frame(0x101, false, false, 1, &[1]);
    sys.push(0, &f1, 0);
    // Run until the message is delivered on B, then repair line A.
    while sys.trace.ack.is_empty() {
        sys.run(1);
    }
    assert_eq!(sys.plain[pb].received, vec![f1]);
    sys.plain[pa].connected = true;
    sys.run((R + 50) * CPB);
    assert_eq!(
        sys.trace.aux_a.iter().map(|s| s.1).collect::<Vec<_>>(),
        [VALID, FAILED, RESTART, PROBATION, VALID]
    );
    // Probation lasts `recovery_bits` sample points of channel A: they are counted
    // at the edges after entering probation, and the edge after probe_cnt reaches R
    // returns to valid.
    let enter = sys.trace.aux_a[3].0;
    let valid = sys.trace.aux_a[4].0;
    let samples = sys
        .trace
        .sample_a
        .iter()
        .filter(|&&(c, s)| s && c >= enter && c <= valid - 2)
        .count() as u64;
    assert_eq!(samples, R);
    // Main FSM: idle2 -> wait4 at the next edge, wait4 -> idle1 at the one after.
    assert_eq!(
        sys.trace.state_seq(),
        [IDLE1, WAIT1, CH1, ABORT1, WAIT2, IDLE2, WAIT3, CH2, IDLE2, WAIT4, IDLE1]
    );
    assert_eq!(sys.trace.clock_of(WAIT4), valid + 1);
    assert_eq!(sys.trace.states[10].0, valid + 2);
    let stats1 = sys.read(0, STATS1);
    assert_eq!(stats1, 2 | 1 << 16, "two switches, one recovery");
    // The next message goes on channel A (acknowledged by the repaired node).
    let f2 = frame(0x102, false, false, 1, &[2]);
    sys.push(0, &f2, 0);
    let mut b_dominant = false;
    for _ in 0..(200 * CPB) {
        sys.step();
        b_dominant |= !sys.nodes[0].out.chan_b_tx;
    }
    assert!(!b_dominant);
    assert_eq!(sys.plain[pa].received, vec![f2]);
    assert_eq!(sys.plain[pb].received, vec![f1]);
    assert_eq!(sys.nodes[0].out.probes.tx_ok_channel, 0b01);
    assert_eq!(sys.trace.ack.len(), 2);
    assert_eq!(
        sys.trace.success,
        vec![sys.trace.ack[0] + 1, sys.trace.ack[1] + 1]
    );
    assert_eq!(sys.read(0, AUX_A) >> 24, 1, "one recovery of A");
}
