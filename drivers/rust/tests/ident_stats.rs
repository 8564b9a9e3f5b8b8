//! Identification, clearing the statistics and the per-channel transmit
//! events, through each driver.
//!
//! - VERSION / SIZES: the default top `drcc` reads version 1.3 (contract
//!   §10.1, §11; §11.6 made it 3) and the sizes of contract §1.1: RX FIFO 32, TX queues 8,
//!   history 32, 16 mailboxes, DMR, and star mode (only `drcc_small` is built
//!   without it).
//! - a map whose major version is not 1 is refused by both drivers' init
//!   (fake registers: major 0 is a map before VERSION existed, major 2 a
//!   future one); any minor of major 1 is accepted (minors only add).
//! - STATS_CLR (§11.4): node 1 never drains its RX FIFO while node 0 sends
//!   F + 3 frames, so exactly 3 are lost to overruns; after the clear the
//!   count reads 0, and the next lost frame counts 1 again.
//! - tx_done_a / tx_done_b (§11.3): in normal mode a frame of queue B sets
//!   tx_done_b (not tx_done_a), one of queue A sets tx_done_a (not tx_done_b).
//!   With single-shot transmission and nobody to acknowledge (node 1 left in
//!   reset mode), the frame's one attempt fails and it is dropped:
//!   tx_failure_b for queue B, tx_failure_a for queue A, never tx_done.

mod both;
mod common;

use both::{node, send_now, single_shot_node, std_frame, wait_bits, Kind, KINDS};
use common::{bus_or_skip, FRAME_BITS};
use drcc_driver::{regs, Drcc, Error, Ident, Registers};
use drcc_driver_sim::c_init_with_version;

/// The default top's VERSION and SIZES (contract §1.1, §10.1; minor 5: the ECSS bus selection, §12).
const DEFAULT_TOP: Ident = Ident {
    major: 1,
    minor: 5,
    rx_fifo_depth: 32,
    tx_queue_depth: 8,
    history: 32,
    mailboxes: 16,
    dmr: true,
    star: true,
};

fn identification(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let n = node(&bus, 0, kind, 0);
    assert_eq!(n.ident(), DEFAULT_TOP, "{kind:?}");
}

/// Registers where `ID` reads "DRCC", `VERSION` reads `.0`, `SIZES` the
/// default top's and everything else 0.
struct FakeRegs(u32);

impl Registers for FakeRegs {
    fn read32(&mut self, offset: u32) -> u32 {
        match offset {
            regs::ID_OFFSET => regs::ID_VALUE,
            regs::VERSION_OFFSET => self.0,
            regs::SIZES_OFFSET => regs::SIZES_RESET,
            _ => 0,
        }
    }
    fn write32(&mut self, _: u32, _: u32) {}
}

/// DRCC_E_VERSION of the C driver.
const C_E_VERSION: i32 = -8;

#[test]
fn both_drivers_refuse_a_major_version_other_than_1() {
    for (version, ok) in [
        (0x000, false),
        (0x200, false),
        (0x201, false),
        (0x100, true),
        (0x1FF, true),
    ] {
        let rust = Drcc::new(FakeRegs(version)).map(|_| ());
        let want = if ok { Ok(()) } else { Err(Error::Version) };
        assert_eq!(rust, want, "Rust, VERSION {version:#x}");
        let c = c_init_with_version(version);
        assert_eq!(
            c,
            if ok { 0 } else { C_E_VERSION },
            "C, VERSION {version:#x}"
        );
    }
}

fn stats_clear(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = node(&bus, 0, kind, 0);
    let mut rx = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    let fifo = u64::from(DEFAULT_TOP.rx_fifo_depth);
    for k in 0..fifo + 3 {
        send_now(&bus, tx.as_mut(), &std_frame(0x200 + k as u32, &[]), 0);
    }
    wait_bits(&bus, 4 * FRAME_BITS);
    assert_eq!(rx.overruns(), 3, "{kind:?}: F + 3 frames, 3 overruns");
    rx.clear_stats();
    assert_eq!(rx.overruns(), 0, "{kind:?}: cleared");
    send_now(&bus, tx.as_mut(), &std_frame(0x300, &[]), 0);
    wait_bits(&bus, 2 * FRAME_BITS);
    assert_eq!(rx.overruns(), 1, "{kind:?}: counting again after the clear");
}

fn tx_done_per_channel(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = node(&bus, 0, kind, 0);
    let _rx = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    tx.irq_ack(u32::MAX);
    let (a, b) = (
        regs::INT_STATUS_TX_DONE_A_MASK,
        regs::INT_STATUS_TX_DONE_B_MASK,
    );
    send_now(&bus, tx.as_mut(), &std_frame(0x10, &[1]), 1);
    wait_bits(&bus, 2 * FRAME_BITS);
    let ev = tx.isr().events;
    assert_eq!(
        ev & (a | b),
        b,
        "{kind:?}: queue B: tx_done_b only ({ev:#x})"
    );
    assert!(ev & regs::INT_STATUS_TX_DONE_MASK != 0);
    send_now(&bus, tx.as_mut(), &std_frame(0x11, &[2]), 0);
    wait_bits(&bus, 2 * FRAME_BITS);
    let ev = tx.isr().events;
    assert_eq!(
        ev & (a | b),
        a,
        "{kind:?}: queue A: tx_done_a only ({ev:#x})"
    );
}

fn tx_failure_per_channel(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = single_shot_node(&bus, 0, kind);
    wait_bits(&bus, 20);
    tx.irq_ack(u32::MAX);
    let (a, b) = (
        regs::INT_STATUS_TX_FAILURE_A_MASK,
        regs::INT_STATUS_TX_FAILURE_B_MASK,
    );
    let done = regs::INT_STATUS_TX_DONE_MASK
        | regs::INT_STATUS_TX_DONE_A_MASK
        | regs::INT_STATUS_TX_DONE_B_MASK;
    for (queue, want) in [(1, b), (0, a)] {
        send_now(&bus, tx.as_mut(), &std_frame(0x12, &[3]), queue);
        wait_bits(&bus, 2 * FRAME_BITS);
        let ev = tx.isr().events;
        assert_eq!(ev & (a | b), want, "{kind:?}: queue {queue} ({ev:#x})");
        assert!(ev & regs::INT_STATUS_TX_FAILURE_MASK != 0, "{kind:?}");
        assert_eq!(ev & done, 0, "{kind:?}: nothing was sent");
    }
}

#[test]
fn c_driver_tx_failure_per_channel() {
    tx_failure_per_channel(KINDS[0]);
}

#[test]
fn rust_driver_tx_failure_per_channel() {
    tx_failure_per_channel(KINDS[1]);
}

#[test]
fn c_driver_identification() {
    identification(KINDS[0]);
}

#[test]
fn rust_driver_identification() {
    identification(KINDS[1]);
}

#[test]
fn c_driver_stats_clear() {
    stats_clear(KINDS[0]);
}

#[test]
fn rust_driver_stats_clear() {
    stats_clear(KINDS[1]);
}

#[test]
fn c_driver_tx_done_per_channel() {
    tx_done_per_channel(KINDS[0]);
}

#[test]
fn rust_driver_tx_done_per_channel() {
    tx_done_per_channel(KINDS[1]);
}
