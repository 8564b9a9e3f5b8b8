//! RX timestamps (contract §11.2), through each driver on node 1: node 0
//! sends the same frame at known bus clocks (spacings 200, 350 and 500 bit
//! times, longer than the frame, so each goes out as soon as it is queued).
//! Expected, from the bit timing configured (clocks per bit = BRP x (1 +
//! TSEG1 + TSEG2), contract §4.3) and CAN frame arithmetic:
//! - read only after the last frame arrived, the timestamps increase, and
//!   each difference equals the clocks between the sends divided by the
//!   clocks per bit, within 2 bit times;
//! - each frame is stamped after its end: between 58 bit times (SOF to the
//!   6th EOF bit of a 60-bit base frame with 2 data bytes) and 58 + 12 stuff
//!   bits + 3 (queueing and start of frame) after the receiver's `now` read
//!   at the send;
//! - polled as soon as it arrives, `now - rx_time` is at most 2 bit times.

mod both;
mod common;

use both::{drain, node, std_frame, wait_bits, Kind, Node, Rx, KINDS};
use common::{bus_or_skip, BIT, BITRATE, CLOCK_HZ};
use drcc_driver::BitTiming;
use drcc_driver_sim::DualBus;
use std::cell::RefCell;
use std::rc::Rc;

type Bus = Rc<RefCell<DualBus>>;

/// Bit times from SOF to the 6th EOF bit of a base data frame with 2 bytes:
/// SOF 1, id 11, RTR 1, IDE 1, r0 1, DLC 4, data 16, CRC 15, CRC delimiter 1,
/// ACK 1, ACK delimiter 1, EOF bits 1..6.
const TO_EOF6: i64 = 1 + 11 + 1 + 1 + 1 + 4 + 16 + 15 + 1 + 1 + 1 + 6;
/// Most stuff bits in the 50 stuffed bits (SOF through CRC) of that frame.
const MAX_STUFF: i64 = (50 - 1) / 4;

/// Polls node 1 until a frame is there (at most 200 bit times).
fn poll(bus: &Bus, rx: &mut dyn Node, kind: Kind) -> Rx {
    let start = bus.borrow().clock();
    loop {
        if let Some(r) = rx.receive() {
            return r;
        }
        assert!(
            bus.borrow().clock() - start < 200 * BIT,
            "{kind:?}: frame not received"
        );
    }
}

fn run(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let t = BitTiming::calc(CLOCK_HZ, BITRATE).expect("a timing");
    let clocks_per_bit = i64::from(t.brp) * (1 + i64::from(t.tseg1) + i64::from(t.tseg2));
    assert_eq!(clocks_per_bit, i64::from(CLOCK_HZ / BITRATE));
    let mut tx = node(&bus, 0, kind, 0);
    let mut rx = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    let f = std_frame(0x321, &[0xA5, 0x5A]);
    let stamped_after_send = |stamp: u16, now_at_send: u16| {
        let after = i64::from(stamp.wrapping_sub(now_at_send));
        assert!(
            (TO_EOF6..=TO_EOF6 + MAX_STUFF + 3).contains(&after),
            "{kind:?}: stamped {after} bit times after the send"
        );
    };

    // Four frames, read only after the last: the stamps are the arrivals.
    let mut sends = Vec::new();
    for spacing in [200u64, 350, 500, 300] {
        let now_at_send = rx.now();
        sends.push((bus.borrow().clock() as i64, now_at_send));
        assert!(tx.send(&f, 0), "queue empty");
        bus.borrow_mut().tick(spacing * BIT);
    }
    let got = drain(rx.as_mut());
    assert_eq!(got.len(), sends.len(), "{kind:?}: every frame");
    for (r, (_, now_at_send)) in got.iter().zip(&sends) {
        assert_eq!(r.frame, f);
        stamped_after_send(r.stamp, *now_at_send);
    }
    for (g, s) in got.windows(2).zip(sends.windows(2)) {
        let dt = i64::from(g[1].stamp.wrapping_sub(g[0].stamp));
        let expect = (s[1].0 - s[0].0) as f64 / clocks_per_bit as f64;
        assert!(dt > 0, "{kind:?}: timestamps increase");
        assert!(
            (dt as f64 - expect).abs() <= 2.0,
            "{kind:?}: stamps {} -> {} ({dt} bits), sends {expect:.1} bit times apart",
            g[0].stamp,
            g[1].stamp
        );
    }

    // One frame polled as it arrives: now - rx_time is small.
    let now_at_send = rx.now();
    assert!(tx.send(&f, 0), "queue empty");
    let r = poll(&bus, rx.as_mut(), kind);
    let now = rx.now();
    stamped_after_send(r.stamp, now_at_send);
    let age = now.wrapping_sub(r.stamp);
    assert!(
        age <= 2,
        "{kind:?}: now {now} - rx_time {} = {age}",
        r.stamp
    );
    assert_eq!(bus.borrow().refused(), 0);
}

#[test]
fn c_driver_timestamps() {
    run(KINDS[0]);
}

#[test]
fn rust_driver_timestamps() {
    run(KINDS[1]);
}
