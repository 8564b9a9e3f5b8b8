//! Acceptance filters (contract §11.1), through each driver on node 1 while
//! node 0 sends: with a base filter (exact 0x123) and an extended filter
//! (0x1ABCDE00, low 8 bits free) exactly the frames that match arrive: not an
//! extended frame whose low 11 bits equal the base filter's identifier, not a
//! base frame differing in one compared bit. With the filters cleared every
//! frame arrives. The expected sets are stated per frame from the filter
//! definitions (a mask bit 1 = compare; the format must match).

mod both;
mod common;

use both::{drain, ext_frame, node, send_now, std_frame, wait_bits, Kind, Rx, KINDS};
use common::{bus_or_skip, Sent, FRAME_BITS};

/// The frames node 0 sends, each with whether the two filters pass it.
fn frames() -> Vec<(Sent, bool)> {
    let remote = Sent {
        rtr: true,
        dlc: 2,
        ..std_frame(0x123, &[])
    };
    vec![
        (std_frame(0x123, &[1, 2]), true),             // filter 0, exact
        (std_frame(0x124, &[3]), false),               // one compared bit differs
        (ext_frame(0x123, &[4]), false),               // extended, low 11 bits 0x123
        (ext_frame(0x1ABC_DE42, &[5, 6]), true),       // filter 1, free low bits
        (std_frame(0x523, &[7]), false),               // bit 10 differs
        (ext_frame(0x1ABC_DF42, &[8]), false),         // bit 8 is compared
        (remote, true),                                // rtr not compared
        (ext_frame(0x1ABC_DE00, &[]), true),           // filter 1, exact
        (std_frame(0x1ABC_DE00 & 0x7FF, &[9]), false), // filter 1's low bits, base
    ]
}

fn run(kind: Kind) {
    let Some(bus) = bus_or_skip() else { return };
    let mut tx = node(&bus, 0, kind, 0);
    let mut rx = node(&bus, 1, kind, 0);
    wait_bits(&bus, 20);
    rx.set_filter(0, Some((0x123, 0x7FF, false)));
    rx.set_filter(1, Some((0x1ABC_DE00, 0x1FFF_FF00, true)));
    wait_bits(&bus, 20); // node 1 left reset mode: bus integration again
    let all = frames();
    let send_all = |tx: &mut dyn both::Node| {
        for (f, _) in &all {
            send_now(&bus, tx, f, 0);
        }
        wait_bits(&bus, (all.len() as u64 + 2) * FRAME_BITS);
    };
    send_all(tx.as_mut());
    let got: Vec<Sent> = drain(rx.as_mut())
        .into_iter()
        .map(|r: Rx| r.frame)
        .collect();
    let want: Vec<Sent> = all
        .iter()
        .filter(|(_, p)| *p)
        .map(|(f, _)| f.clone())
        .collect();
    assert_eq!(got, want, "{kind:?}: exactly the matching frames");

    rx.clear_filters();
    wait_bits(&bus, 20);
    send_all(tx.as_mut());
    let got: Vec<Sent> = drain(rx.as_mut()).into_iter().map(|r| r.frame).collect();
    let want: Vec<Sent> = all.iter().map(|(f, _)| f.clone()).collect();
    assert_eq!(got, want, "{kind:?}: filters cleared, every frame");
    assert_eq!(bus.borrow().refused(), 0, "no register access refused");
}

#[test]
fn c_driver_filters() {
    run(KINDS[0]);
}

#[test]
fn rust_driver_filters() {
    run(KINDS[1]);
}
