//! Frames across the Verilated dual bus, in normal mode: the C driver to the C
//! driver, the Rust driver to the Rust driver, and each to the other. Node 0
//! sends the frames of `common::frames()` (base, extended, remote, DLC 0 and
//! 8), alternating its two TX queues; node 1 receives them only through its
//! driver's interrupt handler, called when its `irq` is high. The oracle is
//! the frames sent: each arrives exactly once, intact, in the order of its
//! queue, tagged with the channel of that queue, and no register access of
//! either driver is refused.

mod common;

use common::{
    bus_or_skip, c_isr, c_send, exchange, frames, port, queue_of, rust_isr, rust_send, Budget,
    Regs, Sent, BIT, BITRATE, CLOCK_HZ, FRAME_BITS,
};
use drcc_driver::{BitTiming, Config, Drcc, Mode};
use drcc_driver_sim::{CConfig, CDriver, DualBus, C_MODE_NORMAL};
use std::cell::RefCell;
use std::rc::Rc;

/// INT_ENABLE of the receivers: rx and overrun.
const RX_IRQS: u32 =
    drcc_driver::regs::INT_ENABLE_RX_MASK | drcc_driver::regs::INT_ENABLE_OVERRUN_MASK;

fn c_driver(bus: &Rc<RefCell<DualBus>>, node: usize) -> CDriver {
    let mut c = CDriver::open(port(bus, node)).expect("drcc_init finds the DRCC");
    let rc = c.configure(&CConfig {
        clock_hz: CLOCK_HZ,
        bitrate: BITRATE,
        mode: C_MODE_NORMAL,
        policy: drcc_driver::regs::CTRL_POLICY_ERROR_PASSIVE,
        k: 1,
        dual_tx: false,
        stall_limit: 0,
        recovery_bits: 1024,
        dedup_window: 1024,
        int_enable: RX_IRQS,
    });
    assert_eq!(rc, 0, "drcc_configure");
    c
}

fn rust_driver(bus: &Rc<RefCell<DualBus>>, node: usize) -> Drcc<Regs> {
    let mut d = Drcc::new(Regs(port(bus, node))).expect("the DRCC answers");
    let cfg = Config {
        timing: BitTiming::calc(CLOCK_HZ, BITRATE).expect("16 clocks a bit"),
        mode: Mode::Normal,
        int_enable: RX_IRQS,
        ..Config::default()
    };
    d.configure(&cfg).expect("configure");
    d
}

/// Both nodes configured: 20 bit times for bus integration (11 recessive bits).
fn integrate(bus: &Rc<RefCell<DualBus>>) {
    bus.borrow_mut().tick(20 * BIT);
}

/// The frames of queue `q` in the order sent, tagged with channel `q`.
fn expected_on(q: u32) -> Vec<(Sent, u8)> {
    frames()
        .into_iter()
        .enumerate()
        .filter(|(k, _)| queue_of(*k) == q)
        .map(|(_, f)| (f, q as u8))
        .collect()
}

/// Checks `got` against the frames sent: per channel, exactly the frames of
/// that queue in order; nothing else.
fn check(got: &[(Sent, u8)], bus: &Rc<RefCell<DualBus>>) {
    for q in 0..2u32 {
        let on_q: Vec<_> = got
            .iter()
            .filter(|(_, c)| u32::from(*c) == q)
            .cloned()
            .collect();
        assert_eq!(on_q, expected_on(q), "frames received on channel {q}");
    }
    assert_eq!(
        got.len(),
        frames().len(),
        "every frame exactly once: {got:#?}"
    );
    assert_eq!(bus.borrow().refused(), 0, "no register access was refused");
}

const BUDGET: Budget = Budget {
    settle_bits: 2 * FRAME_BITS,
    budget_bits: 12 * FRAME_BITS,
};

#[test]
fn c_driver_to_c_driver() {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = c_driver(&bus, 0);
    let mut rx = c_driver(&bus, 1);
    integrate(&bus);
    let sent = frames();
    let got = exchange(
        &bus,
        1,
        &sent,
        c_send(&mut tx),
        c_isr(&mut rx),
        |_, _| {},
        BUDGET,
    );
    check(&got, &bus);
}

#[test]
fn rust_driver_to_rust_driver() {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = rust_driver(&bus, 0);
    let mut rx = rust_driver(&bus, 1);
    integrate(&bus);
    let sent = frames();
    let got = exchange(
        &bus,
        1,
        &sent,
        rust_send(&mut tx),
        rust_isr(&mut rx),
        |_, _| {},
        BUDGET,
    );
    check(&got, &bus);
}

#[test]
fn c_driver_to_rust_driver() {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = c_driver(&bus, 0);
    let mut rx = rust_driver(&bus, 1);
    integrate(&bus);
    let sent = frames();
    let got = exchange(
        &bus,
        1,
        &sent,
        c_send(&mut tx),
        rust_isr(&mut rx),
        |_, _| {},
        BUDGET,
    );
    check(&got, &bus);
}

#[test]
fn rust_driver_to_c_driver() {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = rust_driver(&bus, 0);
    let mut rx = c_driver(&bus, 1);
    integrate(&bus);
    let sent = frames();
    let got = exchange(
        &bus,
        1,
        &sent,
        rust_send(&mut tx),
        c_isr(&mut rx),
        |_, _| {},
        BUDGET,
    );
    check(&got, &bus);
}
