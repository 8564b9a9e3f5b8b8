//! Redundancy mode on the Verilated dual bus: a line A fault starts in the
//! middle of the traffic, during a frame on line A, and every frame still
//! arrives exactly once at node 1, drained by its driver's interrupt handler.
//! Faults: node 0 (the sender) cut from line A (an open stub: it hears only
//! itself), with and without `dual_tx`; line A stuck dominant for both nodes,
//! with `dual_tx`. docs/drcc.md promises it: in redundancy mode the host sees
//! one logical controller, a failed channel is left for the other (k-failed
//! policy, k = 1: after one failed attempt; a line stuck dominant at the
//! latest after the stall limit), frames from both channels reach the host
//! once (duplicate removal), and `dual_tx` sends every message on A and then
//! on B. The recovery time is short, so the sender also goes back to A while
//! the fault lasts and leaves it again ("a wrong guess costs one failed
//! attempt ... it never loses or duplicates a message").
//!
//! The oracle is the frames sent, in order (one logical queue). Beyond it, the
//! tests check what the docs say must have happened for that: the first frame
//! came on channel A (idle1 is channel A), the last on channel B (line A no
//! longer joins the nodes), and the sender's STATS1 counts a channel switch.

mod common;

use common::{
    bus_or_skip, c_isr, c_send, exchange, frames, port, rust_isr, rust_send, Budget, Regs, Sent,
    BIT, BITRATE, CLOCK_HZ, FRAME_BITS,
};
use drcc_driver::{regs, BitTiming, Config, Drcc, Mode, Policy};
use drcc_driver_sim::{CConfig, CDriver, DualBus, Fault, Line, C_MODE_REDUNDANCY};
use std::cell::RefCell;
use std::rc::Rc;

/// Receivers' interrupts: rx and overrun.
const RX_IRQS: u32 = regs::INT_ENABLE_RX_MASK | regs::INT_ENABLE_OVERRUN_MASK;
/// Stall limit, recovery and duplicate window, in bit times. The recovery is
/// short so that the sender's channel A is judged valid again and tried once
/// more (and fails again) while frames are still being sent.
const STALL_BITS: u16 = 300;
const RECOVERY_BITS: u16 = 400;
const WINDOW_BITS: u16 = 2000;

/// The frames, twice over with the second round's first byte or identifier
/// changed, so the traffic outlasts the recovery time (all distinct).
fn traffic() -> Vec<Sent> {
    let mut all = frames();
    for mut f in frames() {
        if f.data.is_empty() {
            f.id ^= 0x10;
        } else {
            f.data[0] ^= 0x80;
        }
        all.push(f);
    }
    all
}

fn rust_node(bus: &Rc<RefCell<DualBus>>, node: usize, dual_tx: bool) -> Drcc<Regs> {
    let mut d = Drcc::new(Regs(port(bus, node))).expect("the DRCC answers");
    let cfg = Config {
        timing: BitTiming::calc(CLOCK_HZ, BITRATE).expect("16 clocks a bit"),
        mode: Mode::Redundancy,
        policy: Policy::KFailed,
        k: 1,
        dual_tx,
        stall_limit: STALL_BITS,
        recovery_bits: RECOVERY_BITS,
        dedup_window: WINDOW_BITS,
        int_enable: RX_IRQS,
        ..Config::default()
    };
    d.configure(&cfg).expect("configure");
    d
}

fn c_node(bus: &Rc<RefCell<DualBus>>, node: usize, dual_tx: bool) -> CDriver {
    let mut c = CDriver::open(port(bus, node)).expect("drcc_init finds the DRCC");
    let rc = c.configure(&CConfig {
        clock_hz: CLOCK_HZ,
        bitrate: BITRATE,
        mode: C_MODE_REDUNDANCY,
        policy: regs::CTRL_POLICY_K_FAILED,
        k: 1,
        dual_tx,
        stall_limit: STALL_BITS,
        recovery_bits: RECOVERY_BITS,
        dedup_window: WINDOW_BITS,
        int_enable: RX_IRQS,
    });
    assert_eq!(rc, 0, "drcc_configure");
    c
}

/// Applies `fault` to line A once node 1 received `after` frames and node 0
/// has driven line A dominant for 40 clocks since then: in the middle of a frame.
fn fault_mid_frame(
    after: usize,
    fault: fn(&mut DualBus),
) -> impl FnMut(&mut DualBus, usize) -> Option<u64> {
    let mut dominant = 0;
    let mut cut_at = None;
    move |bus, received| {
        if cut_at.is_none() && received >= after {
            if bus.out(0).chan_a_tx == 0 {
                dominant += 1;
            }
            if dominant == 40 {
                fault(bus);
                cut_at = Some(bus.clock());
            }
        }
        cut_at
    }
}

/// Node 0 cut from line A (an open stub: it hears only itself, node 1 does not hear it).
fn cut_node0(bus: &mut DualBus) {
    bus.set_fault(0, Line::A, Fault::Cut);
}

/// Line A stuck dominant: both receivers read dominant.
fn line_a_stuck_dominant(bus: &mut DualBus) {
    bus.set_fault(0, Line::A, Fault::StuckDominant);
    bus.set_fault(1, Line::A, Fault::StuckDominant);
}

/// Runs the traffic with `fault` on line A after 3 frames arrived; returns
/// what node 1 received and whether (and when) the fault began.
fn run(
    bus: &Rc<RefCell<DualBus>>,
    fault: fn(&mut DualBus),
    send: impl FnMut(&Sent) -> bool,
    isr: impl FnMut() -> Vec<(Sent, u8)>,
) -> (Vec<(Sent, u8)>, Option<u64>) {
    bus.borrow_mut().tick(20 * BIT); // bus integration
    let mut cut = fault_mid_frame(3, fault);
    let mut cut_at = None;
    let got = exchange(
        bus,
        1,
        &traffic(),
        send,
        isr,
        |b, received| cut_at = cut(b, received),
        Budget {
            settle_bits: 6 * FRAME_BITS,
            budget_bits: 80 * FRAME_BITS,
        },
    );
    (got, cut_at)
}

fn check(got: &[(Sent, u8)], cut_at: Option<u64>, bus: &Rc<RefCell<DualBus>>) {
    assert!(
        cut_at.is_some(),
        "the line A fault began during the traffic"
    );
    let frames: Vec<Sent> = got.iter().map(|(f, _)| f.clone()).collect();
    assert_eq!(
        frames,
        traffic(),
        "every frame exactly once, in order, intact"
    );
    assert_eq!(got[0].1, 0, "before the fault: channel A");
    assert_eq!(got[got.len() - 1].1, 1, "after the fault: channel B");
    assert_eq!(bus.borrow().refused(), 0, "no register access was refused");
}

#[test]
fn dual_tx_hides_a_line_a_cut_c_sender_rust_receiver() {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = c_node(&bus, 0, true);
    let mut rx = rust_node(&bus, 1, true);
    let (got, cut_at) = run(&bus, cut_node0, c_send(&mut tx), rust_isr(&mut rx));
    check(&got, cut_at, &bus);
    let (_, switches) = tx.stats();
    assert!(
        switches >= 1,
        "the sender left channel A: STATS1.switches {switches}"
    );
    assert!(
        rx.stats().duplicates >= 1,
        "before the cut the B copies were dropped as duplicates"
    );
}

#[test]
fn failover_hides_a_line_a_cut_rust_sender_c_receiver() {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = rust_node(&bus, 0, false);
    let mut rx = c_node(&bus, 1, false);
    let (got, cut_at) = run(&bus, cut_node0, rust_send(&mut tx), c_isr(&mut rx));
    check(&got, cut_at, &bus);
    let stats = tx.stats();
    assert!(stats.switches >= 1, "the sender left channel A: {stats:?}");
}

#[test]
fn dual_tx_hides_line_a_stuck_dominant_rust_to_rust() {
    // Line A stuck dominant mid-frame: no frame can start on A, so channel A
    // fails on its errors or, at the latest, the stall limit (docs/drcc.md).
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = rust_node(&bus, 0, true);
    let mut rx = rust_node(&bus, 1, true);
    let (got, cut_at) = run(
        &bus,
        line_a_stuck_dominant,
        rust_send(&mut tx),
        rust_isr(&mut rx),
    );
    check(&got, cut_at, &bus);
    let stats = tx.stats();
    assert!(stats.switches >= 1, "the sender left channel A: {stats:?}");
}
