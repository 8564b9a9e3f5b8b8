//! RX timestamps (contract §11.2) and the per-channel transmit events of
//! `INT_STATUS` (§11.3). The expected timestamps are computed here from the bit
//! timing (§4.3: one `tick` every `(brp+1) * (3 + tseg1 + tseg2)` clocks from the
//! edge that leaves reset mode) and the edge of the FIFO write (`INT_STATUS.rx`,
//! seen on `irq` one clock later, §8).

use super::filters::RX_TIME;
use super::*;

// INT_STATUS bits of §11.3.
const I_TX_DONE_A: u32 = 1 << 13;
const I_TX_DONE_B: u32 = 1 << 14;
const I_TX_FAILURE_A: u32 = 1 << 15;
const I_TX_FAILURE_B: u32 = 1 << 16;
/// The transmit bits: tx_done, tx_failure and the four of §11.3.
const TX_BITS: u32 = I_TX_DONE | I_TX_FAILURE | 0xF << 13;
const SINGLE_SHOT: u32 = 1 << 16;

/// BTR: brp 1, tseg1 5, tseg2 2, sjw 0, ewl 96 (§3 field positions).
const BTR_SLOW: u32 = 1 | 5 << 6 | 2 << 10 | 96 << 16;
/// Clocks per tick: (1 + 1) * (3 + 5 + 2) = 20.
const P: u64 = 20;

/// `now` before edge `e` (§7, §4.3): reset mode is left at edge `e0` (the counters
/// are still held there), the first tick is at edge `e0 + P`, so after edge `e`
/// `now = (e - e0) / P` and before it `(e - 1 - e0) / P`, wrapping at 2^16.
fn now_before(e: u64, e0: u64) -> u32 {
    ((e - 1 - e0) / P % 65536) as u32
}

/// Steps until node 0's irq (INT_ENABLE = rx, INT_STATUS clear) rises; returns
/// the edge that set INT_STATUS.rx, the FIFO write edge (irq follows one edge
/// later). `sys.clock` after a step is that step's edge number.
fn write_edge(sys: &mut Sys) -> u64 {
    let mut clocks = 0;
    while !sys.nodes[0].out.irq {
        sys.step();
        clocks += 1;
        assert!(clocks < 400 * P, "a frame written into node 0's FIFO");
    }
    sys.clock - 1
}

/// RX_TIME.rx_time of each FIFO entry is `now` at its write edge; RX_TIME.now is
/// `now` at the edge the read is taken; an entry never written reads 0; reset
/// mode clears `now`.
#[test]
fn rx_time_is_now_at_the_fifo_write_edge() {
    let mut sys = Sys::new(2);
    for n in 0..2 {
        sys.write(n, BTR, BTR_SLOW);
    }
    sys.write(0, INT_ENABLE, I_RX);
    sys.start(1, policy(1) | k(1));
    // The request edge of node 0's CTRL write is the next step's.
    let e0 = sys.clock + 1;
    sys.start(0, policy(1) | k(1));
    sys.run(1234);
    // Empty FIFO: entry 0 never written, rx_time 0; now from the read's edge.
    let e = sys.clock + 1;
    assert_eq!(sys.read(0, RX_TIME), now_before(e, e0) << 16);
    // e - e0 = 1 (the write's ack clock) + 1234 + 1: before e, 1235 / 20 = 61.
    assert_eq!(now_before(e, e0), 61);

    let f1 = frame(0x321, false, false, 2, &[1, 2]);
    sys.push(1, &f1, 0);
    let w1 = write_edge(&mut sys);
    let ts1 = now_before(w1, e0);
    sys.write(0, INT_STATUS, I_RX);
    sys.run(3000);
    let f2 = frame(0x0AB_CDEF, true, false, 1, &[3]);
    sys.push(1, &f2, 1);
    let w2 = write_edge(&mut sys);
    let ts2 = now_before(w2, e0);
    assert!(ts2 > ts1 + 150, "the second frame later: {ts1} {ts2}");

    sys.run(500);
    let e = sys.clock + 1;
    assert_eq!(
        sys.read(0, RX_TIME),
        ts1 | now_before(e, e0) << 16,
        "head f1"
    );
    assert_eq!(sys.pop(0), Some((f1, 0)));
    let e = sys.clock + 1;
    assert_eq!(
        sys.read(0, RX_TIME),
        ts2 | now_before(e, e0) << 16,
        "head f2"
    );
    assert_eq!(sys.pop(0), Some((f2, 1)));
    // Entry 2 was never written.
    let e = sys.clock + 1;
    assert_eq!(sys.read(0, RX_TIME), now_before(e, e0) << 16, "empty");
    // Reset mode: now is 0.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
    assert_eq!(sys.read(0, RX_TIME) >> 16, 0, "now in reset mode");
}

/// Pushes `f` on `queue` of node 0, runs `bits` bit times, returns the transmit
/// bits of INT_STATUS and clears every bit.
fn tx_bits_after(sys: &mut Sys, f: &Frame, queue: u32, bits: u64) -> u32 {
    sys.push(0, f, queue);
    sys.run(bits * CPB);
    let s = sys.read(0, INT_STATUS) & TX_BITS;
    sys.write(0, INT_STATUS, 0x1_FFFF);
    s
}

/// Normal mode: each queue's completion or failure sets its channel's bit with
/// tx_done / tx_failure; INT_ENABLE masks the new bits as the others.
#[test]
fn per_channel_transmit_events_in_normal_mode() {
    let mut sys = Sys::new(1);
    let _pa = sys.add_plain(0, true);
    let _pb = sys.add_plain(1, true);
    sys.write(0, INT_ENABLE, 0xFFFF_FFFF);
    assert_eq!(
        sys.read(0, INT_ENABLE),
        0x3_FFFF,
        "18 bits (§12: bus_toggle)"
    );
    sys.write(0, INT_ENABLE, I_TX_DONE_B);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    let f = frame(0x155, false, false, 1, &[0x5A]);
    // Queue A on channel A: tx_done_a only; irq stays 0 (only tx_done_b enabled).
    sys.push(0, &f, 0);
    sys.run(200 * CPB);
    assert!(!sys.nodes[0].out.irq, "tx_done_a masked");
    assert_eq!(sys.read(0, INT_STATUS) & TX_BITS, I_TX_DONE | I_TX_DONE_A);
    sys.write(0, INT_STATUS, 0x1_FFFF);
    // Queue B on channel B: tx_done_b, irq.
    sys.push(0, &f, 1);
    sys.run(200 * CPB);
    assert!(sys.nodes[0].out.irq, "tx_done_b enabled");
    assert_eq!(sys.read(0, INT_STATUS) & TX_BITS, I_TX_DONE | I_TX_DONE_B);
    sys.write(0, INT_STATUS, I_TX_DONE_B);
    sys.run(2);
    assert!(!sys.nodes[0].out.irq, "W1C");

    // Single shot, alone on both buses: the ACK error drops the frame (tx_failed).
    let mut sys = Sys::new(1);
    sys.start(0, SINGLE_SHOT | policy(1) | k(1));
    sys.run(20 * CPB);
    let a = tx_bits_after(&mut sys, &f, 0, 200);
    assert_eq!(a, I_TX_FAILURE | I_TX_FAILURE_A);
    let b = tx_bits_after(&mut sys, &f, 1, 200);
    assert_eq!(b, I_TX_FAILURE | I_TX_FAILURE_B);
}

/// Redundancy mode: a dual_tx message sets tx_done_a then tx_done_b (and one
/// tx_done); a message whose channel A attempt the redundancy manager aborts
/// (k-failed, k = 1, nobody acknowledges on A) sets tx_failure_a, tx_failure
/// (the FSM's wait2 -> idle2) and, delivered on B, tx_done_b and tx_done.
#[test]
fn per_channel_transmit_events_in_redundancy_mode() {
    let f = frame(0x2A5, false, false, 2, &[0xC3, 0x3C]);
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    sys.start(0, REDUNDANCY | DUAL_TX | policy(1) | k(1));
    sys.run(20 * CPB);
    let s = tx_bits_after(&mut sys, &f, 0, 400);
    assert_eq!(s, I_TX_DONE | I_TX_DONE_A | I_TX_DONE_B);
    assert_eq!(
        (sys.plain[pa].received.len(), sys.plain[pb].received.len()),
        (1, 1)
    );

    let mut sys = Sys::new(1);
    let pb = sys.add_plain(1, true);
    sys.start(0, REDUNDANCY | policy(2) | k(1));
    sys.run(20 * CPB);
    let s = tx_bits_after(&mut sys, &f, 0, 600);
    assert_eq!(s, I_TX_FAILURE | I_TX_FAILURE_A | I_TX_DONE | I_TX_DONE_B);
    assert_eq!(sys.plain[pb].received, vec![f]);
}
