//! The example of `drivers/c/README.md` ("Example"), compiled from the README
//! itself by `drivers/sim/build.rs` and run here as written: `can_start` on
//! node 1 (1 Mbit/s from 16 MHz, a filter for base identifiers
//! 0x120..0x12F), node 0 sends 0x200 (filtered out) and 0x125 (accepted);
//! `can_poll` returns 0x125 with an age of at most 2 bit times after its
//! arrival, then nothing.

mod both;
mod common;

use both::{node, send_now, std_frame, wait_bits, Kind};
use common::{bus_or_skip, port, Sent, BIT, FRAME_BITS};
use drcc_driver_sim::CDriver;

#[test]
fn readme_example_runs() {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = node(&bus, 0, Kind::Rust, 0);
    let mut rx = CDriver::open_readme_example(port(&bus, 1)).expect("can_start");
    wait_bits(&bus, 20);
    send_now(&bus, tx.as_mut(), &std_frame(0x200, &[1]), 0);
    send_now(&bus, tx.as_mut(), &std_frame(0x125, &[2, 3]), 0);
    // Each poll of an empty FIFO is one register read (2 clocks).
    let tries = (3 * FRAME_BITS * BIT / 2) as u32;
    let (age, f) = rx.readme_poll(tries);
    assert!((0..=2).contains(&age), "age {age}");
    assert_eq!(Sent::from_c(&f).0, std_frame(0x125, &[2, 3]));
    let (age, _) = rx.readme_poll(FRAME_BITS as u32);
    assert_eq!(age, -1, "0x200 was filtered out");
}
