//! Error and arbitration-lost captures (contract §10.2) through each driver.
//!
//! Arbitration: node 0 sends a long frame; while it is on the bus node 0
//! queues a contender behind it and node 1 queues its own, so both start
//! together after the intermission. Node 1 (the higher identifier) loses at
//! the first identifier bit where its 1 meets node 0's 0: ALC = 10 - (the
//! highest differing bit) for base identifiers (bit i of the 11, most
//! significant first, is ALC i); an extended frame whose base bits equal a
//! base data frame's loses at SRR (ALC 11). The first loss is held while a
//! second one happens, read by the interrupt handler, re-armed by its
//! acknowledgement, and the next loss is captured.
//!
//! Bus error: node 1 stays in reset mode (never acknowledges), so node 0's
//! frame meets an ACK error as transmitter in the ACK slot (kind 5, field 13,
//! `err_tx`). The capture is held while the frame is retried (an arb_lost
//! acknowledgement does not re-arm it), the handler reports it, its
//! acknowledgement re-arms it (`err_valid` 0 right after), and the next retry
//! is captured again. With EWL 96 and TEC + 8 per ACK error (ISO 11898-1
//! rule c), the 12th error crosses the warning limit: `err_warning` is not
//! raised after the first error and is after 16.

mod both;
mod common;

use both::{ext_frame, node, send_now, std_frame, wait_bits, Kind, KINDS};
use common::{bus_or_skip, FRAME_BITS};
use drcc_driver::{regs, Capture};

/// ALC of the loser of two base identifiers (contract §C.9 numbering).
fn alc_base(a: u32, b: u32) -> u8 {
    let highest = 31 - (a ^ b).leading_zeros();
    (10 - highest) as u8
}

const SRR_ALC: u8 = 11;

/// One contest: node 0's long frame, then node 0's `win` and node 1's `lose`
/// queued while it is on the bus.
fn contest(
    bus: &std::rc::Rc<std::cell::RefCell<drcc_driver_sim::DualBus>>,
    n0: &mut dyn both::Node,
    n1: &mut dyn both::Node,
    win: &common::Sent,
    lose: &common::Sent,
) {
    send_now(bus, n0, &std_frame(0x7F0, &[0x55; 8]), 0);
    wait_bits(bus, 10);
    send_now(bus, n0, win, 0);
    send_now(bus, n1, lose, 0);
    wait_bits(bus, 4 * FRAME_BITS);
}

fn arbitration(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let irqs = regs::INT_ENABLE_ARB_LOST_MASK;
    let mut n0 = node(&bus, 0, kind, irqs);
    let mut n1 = node(&bus, 1, kind, irqs);
    wait_bits(&bus, 20);
    let (a, b) = (0x100, 0x140);
    let first = alc_base(a, b);
    assert_eq!(
        first, 4,
        "0x100 and 0x140 differ first at bit 6, the 5th sent"
    );
    contest(
        &bus,
        n0.as_mut(),
        n1.as_mut(),
        &std_frame(a, &[1]),
        &std_frame(b, &[2]),
    );
    let (cap_a, cap_b) = n1.captures();
    assert!(cap_a.alc_valid && cap_a.alc == first, "{kind:?}: {cap_a:?}");
    assert!(!cap_b.alc_valid, "{kind:?}: channel B lost nothing");
    assert!(!n0.captures().0.alc_valid, "{kind:?}: node 0 never lost");

    // A second loss, at SRR, while the first is held.
    let ext = ext_frame(0x100 << 18 | 5, &[3]);
    contest(
        &bus,
        n0.as_mut(),
        n1.as_mut(),
        &std_frame(0x100, &[4]),
        &ext,
    );
    let held = n1.captures().0;
    assert!(
        held.alc_valid && held.alc == first,
        "{kind:?}: first loss held: {held:?}"
    );
    let isr = n1.isr();
    assert!(
        isr.events & regs::INT_STATUS_ARB_LOST_MASK != 0,
        "{kind:?}: arb_lost"
    );
    assert_eq!(
        isr.cap_a, held,
        "{kind:?}: the handler reads the held capture"
    );
    assert!(
        !n1.captures().0.alc_valid,
        "{kind:?}: re-armed by the acknowledgement"
    );

    contest(
        &bus,
        n0.as_mut(),
        n1.as_mut(),
        &std_frame(0x100, &[4]),
        &ext,
    );
    let next = n1.captures().0;
    assert!(next.alc_valid && next.alc == SRR_ALC, "{kind:?}: {next:?}");
    assert_eq!(bus.borrow().refused(), 0);
}

fn bus_error(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut n0 = node(&bus, 0, kind, regs::INT_ENABLE_BUS_ERROR_MASK);
    // Node 1 is left in reset mode: nobody acknowledges.
    wait_bits(&bus, 20);
    n0.irq_ack(u32::MAX);
    assert!(n0.send(&std_frame(0x0AB, &[1, 2]), 0));
    // Until the first error is captured (one frame up to its ACK slot).
    let mut waited = 0;
    while !n0.captures().0.err_valid {
        wait_bits(&bus, 1);
        waited += 1;
        assert!(waited < FRAME_BITS, "{kind:?}: no error captured");
    }
    let want = Capture {
        err_valid: true,
        err_kind: Capture::ERR_ACK,
        err_field: Capture::FIELD_ACK_SLOT,
        err_tx: true,
        ..Capture::default()
    };
    let (cap_a, cap_b) = n0.captures();
    assert_eq!(cap_a, want, "{kind:?}: ACK error as transmitter");
    assert!(!cap_b.err_valid, "{kind:?}: channel B idle");
    let st = n0.irq_status();
    assert!(
        st & regs::INT_STATUS_BUS_ERROR_MASK != 0,
        "{kind:?}: bus_error"
    );
    assert!(
        st & regs::INT_STATUS_ERR_WARNING_MASK == 0,
        "{kind:?}: TEC 8 < 96"
    );

    // Retries: more ACK errors; an arb_lost acknowledgement does not re-arm.
    wait_bits(&bus, 16 * FRAME_BITS);
    n0.rearm(false, true);
    assert_eq!(n0.captures().0, want, "{kind:?}: held");
    let isr = n0.isr();
    assert!(isr.events & regs::INT_STATUS_BUS_ERROR_MASK != 0);
    assert!(
        isr.events & regs::INT_STATUS_ERR_WARNING_MASK != 0,
        "{kind:?}: TEC reached the warning limit"
    );
    assert_eq!(
        isr.cap_a, want,
        "{kind:?}: the handler reads the held capture"
    );
    assert!(!n0.captures().0.err_valid, "{kind:?}: re-armed");
    wait_bits(&bus, 2 * FRAME_BITS);
    assert_eq!(n0.captures().0, want, "{kind:?}: the next retry captured");
    n0.rearm(true, false);
    assert!(!n0.captures().0.err_valid, "{kind:?}: re-armed again");
}

#[test]
fn c_driver_arbitration_lost_capture() {
    arbitration(KINDS[0]);
}

#[test]
fn rust_driver_arbitration_lost_capture() {
    arbitration(KINDS[1]);
}

#[test]
fn c_driver_bus_error_capture() {
    bus_error(KINDS[0]);
}

#[test]
fn rust_driver_bus_error_capture() {
    bus_error(KINDS[1]);
}
