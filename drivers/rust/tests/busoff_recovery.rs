//! Manual bus-off recovery (contract §11.6: `CTRL.busoff_manual`,
//! `TX_CMD.recover_a` / `recover_b`) through each driver
//! (`drcc_config.busoff_manual` + `drcc_recover`, `Config::busoff_manual` +
//! `Drcc::recover`).
//!
//! Bus-off needs a real fault: a node alone without ACK only goes error
//! passive (ISO 11898-1: an error-passive transmitter's ACK errors do not
//! raise its TEC). Here node 0 sends a frame on line A and, once it is past
//! arbitration (in arbitration a recessive bit read dominant is a lost
//! arbitration, not an error), its receiver on line A is stuck dominant
//! ([`Fault::StuckDominant`]): the next recessive data bit it sends is a bit
//! error, and after its error flag
//! it never sees the recessive delimiter, so every 8 dominant bits raise its
//! TEC by 8 (ISO 11898-1 12.1.4.2) until it exceeds 255: bus-off
//! (`err_state` 2). The fault is then removed: the line reads recessive,
//! which is what the recovery counts (128 runs of 11 recessive bits).
//!
//! - With `busoff_manual`: a recover call made earlier, while the channel was
//!   error active, gives no permission (it is taken only from a bus-off
//!   channel). The channel stays bus-off for 3 x 128 x 11 bit times with the
//!   line recessive, its frame still queued, nothing at node 1. A recover of
//!   channel B does not release A (1,500 more bit times). After the recover
//!   of A the channel is error active again no earlier than 1,408 recessive
//!   samples after the write (the first sample at most one bit after it, so
//!   more than 1,407 bit times) and at most 4 bit times (plus the polling)
//!   later; the frame it held then arrives at node 1 on A and the queue
//!   empties with `tx_done_a`.
//! - Without it: after the fault is removed the channel recovers by itself,
//!   in the same 1,408 samples, and its frame arrives.
//! - Version: a map 1.2 (fake registers) refuses `recover` and a
//!   configuration with `busoff_manual` (`DRCC_E_UNSUPPORTED` /
//!   `Error::Unsupported`) without writing; 1.3 writes `TX_CMD` once.

mod both;
mod common;

use both::{
    drain, node, node_with, send_now, std_frame, wait_bits, wait_until, Kind, Node, E_UNSUPPORTED,
    KINDS,
};
use common::{bus_or_skip, Fake, BIT, FRAME_BITS};
use drcc_driver::{regs, Channels, Config, Drcc, Error, Mode};
use drcc_driver_sim::{c_call_with_version, CCall, DualBus, Fault, Line};
use std::cell::RefCell;
use std::rc::Rc;

type Bus = Rc<RefCell<DualBus>>;

/// ISO 11898-1: 128 runs of 11 recessive bits.
const RECOVERY_BITS: u64 = 128 * 11;

/// The channel's `field` probe (contract §C.4.1) of the data field.
const FIELD_DATA: u8 = 10;

/// Sends [`frame`] on node 0's queue A and, once it is past arbitration (its
/// channel A's next field is DATA), sticks node 0's receiver on line A
/// dominant until channel A is bus-off; then removes the fault. Returns the
/// bus clock at which the fault was removed.
fn drive_bus_off(bus: &Bus, n0: &mut dyn Node, kind: Kind) -> u64 {
    send_now(bus, n0, &frame(), 0);
    let mut waited = 0;
    while bus.borrow().out(0).chan_a_field != FIELD_DATA {
        bus.borrow_mut().tick(1);
        waited += 1;
        assert!(waited < 60 * BIT, "{kind:?}: node 0 never reached DATA");
    }
    bus.borrow_mut().set_fault(0, Line::A, Fault::StuckDominant);
    let mut bits = 0;
    while n0.status().a.err_state != 2 {
        wait_bits(bus, 1);
        bits += 1;
        assert!(bits < 1_000, "{kind:?}: channel A never went bus-off");
    }
    bus.borrow_mut().set_fault(0, Line::A, Fault::None);
    bus.borrow().clock()
}

fn frame() -> common::Sent {
    std_frame(0x2C5, &[0xB0, 0x0F, 0xF0])
}

/// Polls channel A's `err_state` once a bit time until it is 0; the bus
/// clock of the read that saw it, or `None` after `bits` bit times.
fn until_active(bus: &Bus, n0: &mut dyn Node, bits: u64) -> Option<u64> {
    wait_until(bus, bits, || n0.status().a.err_state == 0).then(|| bus.borrow().clock())
}

/// The recovery took 1,408 recessive samples: more than 1,407 bit times
/// after `from`, and at most 4 bit times more (plus one poll: a bit time
/// and the status reads).
fn assert_recovery_time(kind: Kind, from: u64, at: u64) {
    let elapsed = at - from;
    assert!(
        elapsed > (RECOVERY_BITS - 1) * BIT,
        "{kind:?}: error active after {elapsed} clocks, before 128 x 11 bits"
    );
    assert!(
        elapsed <= (RECOVERY_BITS + 4 + 1) * BIT + 16,
        "{kind:?}: error active only after {elapsed} clocks"
    );
}

fn assert_delivered(bus: &Bus, n0: &mut dyn Node, n1: &mut dyn Node, kind: Kind) {
    wait_bits(bus, 2 * FRAME_BITS);
    let got: Vec<_> = drain(n1)
        .into_iter()
        .map(|r| (r.frame, r.channel))
        .collect();
    assert_eq!(got, vec![(frame(), 0)], "{kind:?}: the held frame, on A");
    assert_eq!(n0.status().txq_a, 0, "{kind:?}: queue A empty");
    assert!(n0.irq_status() & regs::INT_STATUS_TX_DONE_A_MASK != 0);
    let st = n0.status();
    assert_eq!((st.a.err_state, st.a.tec), (0, 0), "{kind:?}: {st:?}");
}

fn manual(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut n0 = node_with(&bus, 0, kind, Mode::Normal, true, 0);
    let mut n1 = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    // Not bus-off: no permission is taken.
    assert_eq!(n0.recover(Channels::A), 0, "{kind:?}: recover");
    wait_bits(&bus, 20);
    n0.irq_ack(u32::MAX);
    drive_bus_off(&bus, n0.as_mut(), kind);
    assert!(
        n0.irq_status() & regs::INT_STATUS_ERR_STATE_MASK != 0,
        "{kind:?}: err_state event"
    );

    for _ in 0..3 * RECOVERY_BITS / 100 {
        wait_bits(&bus, 100);
        let st = n0.status();
        assert_eq!(st.a.err_state, 2, "{kind:?}: held bus-off");
        assert_eq!(st.txq_a, 1, "{kind:?}: its frame stays queued");
    }
    assert!(drain(n1.as_mut()).is_empty(), "{kind:?}: nothing sent");

    assert_eq!(n0.recover(Channels::B), 0, "{kind:?}: recover B");
    wait_bits(&bus, RECOVERY_BITS + 100);
    assert_eq!(
        n0.status().a.err_state,
        2,
        "{kind:?}: B's permission is not A's"
    );

    let from = bus.borrow().clock();
    assert_eq!(n0.recover(Channels::A), 0, "{kind:?}: recover A");
    let at = until_active(&bus, n0.as_mut(), 2 * RECOVERY_BITS)
        .unwrap_or_else(|| panic!("{kind:?}: channel A never recovered"));
    assert_recovery_time(kind, from, at);
    assert_delivered(&bus, n0.as_mut(), n1.as_mut(), kind);
    assert_eq!(bus.borrow().refused(), 0, "{kind:?}: nothing refused");
}

fn automatic(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut n0 = node_with(&bus, 0, kind, Mode::Normal, false, 0);
    let mut n1 = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    let from = drive_bus_off(&bus, n0.as_mut(), kind);
    let at = until_active(&bus, n0.as_mut(), 2 * RECOVERY_BITS)
        .unwrap_or_else(|| panic!("{kind:?}: channel A never recovered"));
    assert_recovery_time(kind, from, at);
    assert_delivered(&bus, n0.as_mut(), n1.as_mut(), kind);
    assert_eq!(bus.borrow().refused(), 0);
}

#[test]
fn c_driver_manual_bus_off_recovery() {
    manual(KINDS[0]);
}

#[test]
fn rust_driver_manual_bus_off_recovery() {
    manual(KINDS[1]);
}

#[test]
fn c_driver_automatic_bus_off_recovery() {
    automatic(KINDS[0]);
}

#[test]
fn rust_driver_automatic_bus_off_recovery() {
    automatic(KINDS[1]);
}

fn fake(version: u32) -> Drcc<Fake> {
    Drcc::new(Fake {
        version,
        writes: vec![],
    })
    .expect("major 1")
}

#[test]
fn both_drivers_need_map_1_3_for_manual_recovery() {
    let cases = [
        (Channels::A, 1, regs::TX_CMD_RECOVER_A_MASK),
        (Channels::B, 2, regs::TX_CMD_RECOVER_B_MASK),
        (
            Channels::BOTH,
            3,
            regs::TX_CMD_RECOVER_A_MASK | regs::TX_CMD_RECOVER_B_MASK,
        ),
    ];
    for (channels, mask, word) in cases {
        for (version, ok) in [(0x101, false), (0x102, false), (0x103, true), (0x104, true)] {
            let mut d = fake(version);
            let r = d.recover(channels);
            let writes = d.release().writes;
            if ok {
                assert_eq!(r, Ok(()), "Rust, VERSION {version:#x}");
                assert_eq!(
                    writes,
                    vec![(regs::TX_CMD_OFFSET, word)],
                    "Rust {channels:?}"
                );
            } else {
                assert_eq!(r, Err(Error::Unsupported), "Rust, VERSION {version:#x}");
                assert_eq!(writes, vec![], "Rust: nothing written");
            }
            let c = c_call_with_version(version, 0, CCall::Recover(mask));
            assert_eq!(
                c,
                if ok {
                    (0, 1, (regs::TX_CMD_OFFSET, word))
                } else {
                    (E_UNSUPPORTED, 0, (0, 0))
                },
                "C, VERSION {version:#x}, mask {mask}"
            );
        }
    }
    for mask in [0, 4, 8] {
        let (rc, writes, _) = c_call_with_version(0x103, 0, CCall::Recover(mask));
        assert_eq!((rc, writes), (-1, 0), "C, mask {mask}");
    }

    // busoff_manual in the configuration: refused before any write below 1.3.
    let cfg = Config {
        busoff_manual: true,
        ..Config::default()
    };
    let mut d = fake(0x102);
    assert_eq!(d.configure(&cfg), Err(Error::Unsupported));
    assert_eq!(d.release().writes, vec![], "Rust: nothing written");
    assert_eq!(
        c_call_with_version(0x102, 0, CCall::Configure(true)),
        (E_UNSUPPORTED, 0, (0, 0))
    );
    // Without it, or on 1.3, configure goes on (these fake registers never
    // enter reset mode, so it stops there: Refused after the CTRL write).
    for (version, manual) in [(0x102, false), (0x103, true)] {
        let mut d = fake(version);
        let cfg = Config {
            busoff_manual: manual,
            ..Config::default()
        };
        assert_eq!(d.configure(&cfg), Err(Error::Refused));
        let reset_mode = (regs::CTRL_OFFSET, regs::CTRL_RESET_MODE_MASK);
        assert_eq!(d.release().writes, vec![reset_mode], "Rust: reset mode");
        assert_eq!(
            c_call_with_version(version, 0, CCall::Configure(manual)),
            (-4, 1, reset_mode),
            "C, VERSION {version:#x}"
        );
    }
}
