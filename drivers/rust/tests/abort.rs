//! Host transmit abort (contract §11.5, `TX_CMD.abort_a` / `abort_b`) through
//! each driver (`drcc_abort`, `Drcc::abort`).
//!
//! Frames that cannot go out: node 0 is cut from a line ([`Fault::Cut`]: its
//! receiver hears only its own transmitter, node 1 does not hear it), so its
//! channel on that line never gets an ACK and retries its frame forever
//! (error passive after 16 ACK errors, and an error-passive transmitter's ACK
//! errors do not raise its TEC: no bus-off). Retries never raise `tx_failed`.
//!
//! - Normal mode, one queue: with line A cut, 4 frames on queue A and 4 on
//!   queue B. B's frames arrive at node 1 (on B); A's stay queued (count 4:
//!   the head in the channel, 3 behind it). After the abort of A the count
//!   is at most 1 at once (the frame channel A holds) and 0 once the channel
//!   dropped it; that frame ends with `tx_failure` / `tx_failure_a` (never
//!   `tx_done_a`; nothing on B). With the line reconnected none of A's frames
//!   ever arrives at node 1, and a frame queued afterwards does (on A): the
//!   queue works and node 1 hears line A.
//! - Normal mode, both queues in one call: both lines cut, 3 frames on each
//!   queue; both counts drop to 0, `tx_failure_a` and `tx_failure_b`, and
//!   after reconnection nothing arrives.
//! - Redundancy mode: node 0 cut from both lines, 4 messages queued; an abort
//!   keeps the head (count 1, and it stays 1 while the lines are cut); with
//!   the lines reconnected exactly the head arrives at node 1, once. The
//!   drivers take any channel set as the one logical queue: the call is made
//!   with channel B only (a driver that passed `abort_b` through would leave
//!   the count at 4: the hardware ignores `abort_b` in redundancy mode).
//! - DMR mode: the hardware refuses an abort (`illegal`, `wb_err_o`); the
//!   drivers return `DRCC_E_STATE` / `Error::State` without writing: no
//!   refused access, `INT_STATUS.illegal` stays 0.
//! - Version: on a map 1.1 (fake registers) the call returns
//!   `DRCC_E_UNSUPPORTED` / `Error::Unsupported` and writes nothing; on 1.2
//!   it writes `TX_CMD` once.

mod both;
mod common;

use both::{
    drain, node, node_with, send_now, std_frame, wait_bits, wait_until, Kind, Node, E_STATE,
    E_UNSUPPORTED, KINDS,
};
use common::{bus_or_skip, Fake, Sent, FRAME_BITS};
use drcc_driver::{regs, Channel, Channels, Drcc, Error, Mode};
use drcc_driver_sim::{c_call_with_version, CCall, Fault, Line};

fn has(events: u32, mask: u32) -> bool {
    events & mask != 0
}

fn frames(base: u32, n: u8) -> Vec<Sent> {
    (0..n)
        .map(|k| std_frame(base + u32::from(k), &[k, 0xA0 | k]))
        .collect()
}

fn received(n1: &mut dyn Node) -> Vec<(Sent, u8)> {
    drain(n1)
        .into_iter()
        .map(|r| (r.frame, r.channel))
        .collect()
}

fn normal_one_queue(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut n0 = node(&bus, 0, kind, 0);
    let mut n1 = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    bus.borrow_mut().set_fault(0, Line::A, Fault::Cut);
    let (on_a, on_b) = (frames(0x100, 4), frames(0x200, 4));
    for (a, b) in on_a.iter().zip(&on_b) {
        send_now(&bus, n0.as_mut(), a, 0);
        send_now(&bus, n0.as_mut(), b, 1);
    }
    wait_bits(&bus, 6 * FRAME_BITS);
    let st = n0.status();
    assert_eq!(
        (st.txq_a, st.txq_b),
        (4, 0),
        "{kind:?}: A's frames wait for an ACK, B's went out"
    );
    let before = n0.irq_status();
    assert!(has(before, regs::INT_STATUS_TX_DONE_B_MASK), "{kind:?}");
    assert!(
        !has(
            before,
            regs::INT_STATUS_TX_FAILURE_A_MASK | regs::INT_STATUS_TX_DONE_A_MASK
        ),
        "{kind:?}: retries raise no event: {before:#x}"
    );
    let want_b: Vec<(Sent, u8)> = on_b.iter().map(|f| (f.clone(), 1)).collect();
    assert_eq!(received(n1.as_mut()), want_b, "{kind:?}: B's frames");
    n0.irq_ack(u32::MAX);

    assert_eq!(n0.abort(Channels::A), 0, "{kind:?}: abort A");
    let st = n0.status();
    assert!(st.txq_a <= 1, "{kind:?}: only the channel's frame stays");
    assert!(
        wait_until(&bus, 2 * FRAME_BITS, || n0.status().txq_a == 0),
        "{kind:?}: the channel dropped its frame"
    );
    let ev = n0.irq_status();
    assert!(
        has(ev, regs::INT_STATUS_TX_FAILURE_A_MASK) && has(ev, regs::INT_STATUS_TX_FAILURE_MASK),
        "{kind:?}: the aborted frame failed on A: {ev:#x}"
    );
    assert!(
        !has(
            ev,
            regs::INT_STATUS_TX_DONE_A_MASK
                | regs::INT_STATUS_TX_FAILURE_B_MASK
                | regs::INT_STATUS_TX_DONE_B_MASK
                | regs::INT_STATUS_ILLEGAL_MASK
        ),
        "{kind:?}: nothing else: {ev:#x}"
    );

    bus.borrow_mut().set_fault(0, Line::A, Fault::None);
    wait_bits(&bus, 8 * FRAME_BITS);
    assert_eq!(
        received(n1.as_mut()),
        vec![],
        "{kind:?}: no aborted frame ever arrives"
    );
    let later = std_frame(0x0F0, &[7]);
    send_now(&bus, n0.as_mut(), &later, 0);
    wait_bits(&bus, 2 * FRAME_BITS);
    assert_eq!(
        received(n1.as_mut()),
        vec![(later, 0)],
        "{kind:?}: the next frame of queue A"
    );
    assert!(has(n0.irq_status(), regs::INT_STATUS_TX_DONE_A_MASK));
    assert_eq!(n0.status().txq_a, 0);
    assert_eq!(bus.borrow().refused(), 0, "{kind:?}: nothing refused");
}

fn normal_both_queues(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut n0 = node(&bus, 0, kind, 0);
    let mut n1 = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    for line in [Line::A, Line::B] {
        bus.borrow_mut().set_fault(0, line, Fault::Cut);
    }
    for (a, b) in frames(0x300, 3).iter().zip(&frames(0x400, 3)) {
        send_now(&bus, n0.as_mut(), a, 0);
        send_now(&bus, n0.as_mut(), b, 1);
    }
    wait_bits(&bus, 3 * FRAME_BITS);
    let st = n0.status();
    assert_eq!((st.txq_a, st.txq_b), (3, 3), "{kind:?}: nothing went out");
    n0.irq_ack(u32::MAX);

    assert_eq!(n0.abort(Channels::BOTH), 0, "{kind:?}: abort both");
    let st = n0.status();
    assert!(st.txq_a <= 1 && st.txq_b <= 1, "{kind:?}: {st:?}");
    assert!(
        wait_until(&bus, 2 * FRAME_BITS, || {
            let s = n0.status();
            (s.txq_a, s.txq_b) == (0, 0)
        }),
        "{kind:?}: both channels dropped their frames"
    );
    let ev = n0.irq_status();
    assert!(
        has(ev, regs::INT_STATUS_TX_FAILURE_A_MASK) && has(ev, regs::INT_STATUS_TX_FAILURE_B_MASK),
        "{kind:?}: {ev:#x}"
    );
    assert!(
        !has(
            ev,
            regs::INT_STATUS_TX_DONE_A_MASK | regs::INT_STATUS_TX_DONE_B_MASK
        ),
        "{kind:?}: {ev:#x}"
    );
    for line in [Line::A, Line::B] {
        bus.borrow_mut().set_fault(0, line, Fault::None);
    }
    wait_bits(&bus, 8 * FRAME_BITS);
    assert_eq!(received(n1.as_mut()), vec![], "{kind:?}: nothing arrives");
    assert_eq!(bus.borrow().refused(), 0);
}

fn redundancy_keeps_head(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut n0 = node_with(&bus, 0, kind, Mode::Redundancy, false, 0);
    let mut n1 = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    for line in [Line::A, Line::B] {
        bus.borrow_mut().set_fault(0, line, Fault::Cut);
    }
    let msgs = frames(0x500, 4);
    for m in &msgs {
        send_now(&bus, n0.as_mut(), m, 0);
    }
    wait_bits(&bus, 3 * FRAME_BITS);
    assert_eq!(n0.status().txq_a, 4, "{kind:?}: nothing went out");

    // Channel B only: the one logical queue all the same.
    assert_eq!(n0.abort(Channels::B), 0, "{kind:?}: abort");
    assert_eq!(n0.status().txq_a, 1, "{kind:?}: the head stays");
    wait_bits(&bus, 4 * FRAME_BITS);
    assert_eq!(n0.status().txq_a, 1, "{kind:?}: and waits");
    for line in [Line::A, Line::B] {
        bus.borrow_mut().set_fault(0, line, Fault::None);
    }
    assert!(
        wait_until(&bus, 40 * FRAME_BITS, || n0.status().txq_a == 0),
        "{kind:?}: the head was sent"
    );
    wait_bits(&bus, 8 * FRAME_BITS);
    let got: Vec<Sent> = received(n1.as_mut()).into_iter().map(|r| r.0).collect();
    assert_eq!(got, vec![msgs[0].clone()], "{kind:?}: the head, once");
    assert!(has(n0.irq_status(), regs::INT_STATUS_TX_DONE_MASK));
    assert_eq!(bus.borrow().refused(), 0);
}

fn dmr_refused(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut n0 = node_with(&bus, 0, kind, Mode::Dmr, false, 0);
    wait_bits(&bus, 20);
    n0.irq_ack(u32::MAX);
    for ch in [Channels::A, Channels::B, Channels::BOTH] {
        assert_eq!(n0.abort(ch), E_STATE, "{kind:?}: {ch:?}");
    }
    assert_eq!(bus.borrow().refused(), 0, "{kind:?}: nothing written");
    assert!(
        !has(n0.irq_status(), regs::INT_STATUS_ILLEGAL_MASK),
        "{kind:?}: no illegal write"
    );
}

#[test]
fn c_driver_abort_one_queue() {
    normal_one_queue(KINDS[0]);
}

#[test]
fn rust_driver_abort_one_queue() {
    normal_one_queue(KINDS[1]);
}

#[test]
fn c_driver_abort_both_queues() {
    normal_both_queues(KINDS[0]);
}

#[test]
fn rust_driver_abort_both_queues() {
    normal_both_queues(KINDS[1]);
}

#[test]
fn c_driver_abort_in_redundancy_mode_keeps_the_head() {
    redundancy_keeps_head(KINDS[0]);
}

#[test]
fn rust_driver_abort_in_redundancy_mode_keeps_the_head() {
    redundancy_keeps_head(KINDS[1]);
}

#[test]
fn c_driver_abort_in_dmr_mode_is_refused_without_a_write() {
    dmr_refused(KINDS[0]);
}

#[test]
fn rust_driver_abort_in_dmr_mode_is_refused_without_a_write() {
    dmr_refused(KINDS[1]);
}

#[test]
fn both_drivers_need_map_1_2_for_abort() {
    let both = regs::TX_CMD_ABORT_A_MASK | regs::TX_CMD_ABORT_B_MASK;
    for (version, ok) in [(0x100, false), (0x101, false), (0x102, true), (0x103, true)] {
        let mut d = Drcc::new(Fake {
            version,
            writes: vec![],
        })
        .expect("major 1");
        let r = d.abort(Channels::BOTH);
        let writes = d.release().writes;
        if ok {
            assert_eq!(r, Ok(()), "Rust, VERSION {version:#x}");
            assert_eq!(writes, vec![(regs::TX_CMD_OFFSET, both)], "Rust");
        } else {
            assert_eq!(r, Err(Error::Unsupported), "Rust, VERSION {version:#x}");
            assert_eq!(writes, vec![], "Rust: nothing written");
        }
        let c = c_call_with_version(version, 0, CCall::Abort(3));
        assert_eq!(
            c,
            if ok {
                (0, 1, (regs::TX_CMD_OFFSET, both))
            } else {
                (E_UNSUPPORTED, 0, (0, 0))
            },
            "C, VERSION {version:#x}"
        );
    }
    // One channel each (C's DRCC_CH_A 1, DRCC_CH_B 2).
    for (mask, word) in [
        (1, regs::TX_CMD_ABORT_A_MASK),
        (2, regs::TX_CMD_ABORT_B_MASK),
    ] {
        let c = c_call_with_version(0x102, 0, CCall::Abort(mask));
        assert_eq!(c, (0, 1, (regs::TX_CMD_OFFSET, word)), "C, mask {mask}");
    }
    for (ch, word) in [
        (Channel::A, regs::TX_CMD_ABORT_A_MASK),
        (Channel::B, regs::TX_CMD_ABORT_B_MASK),
    ] {
        let mut d = Drcc::new(Fake {
            version: 0x102,
            writes: vec![],
        })
        .expect("major 1");
        assert_eq!(d.abort(ch), Ok(()));
        assert_eq!(
            d.release().writes,
            vec![(regs::TX_CMD_OFFSET, word)],
            "Rust {ch:?}"
        );
    }
    // An empty or unknown channel mask (C only: Rust's Channels is never empty).
    for mask in [0, 4, 7] {
        assert_eq!(c_call_with_version(0x102, 0, CCall::Abort(mask)).0, -1);
        assert_eq!(c_call_with_version(0x102, 0, CCall::Abort(mask)).1, 0);
    }
}
