//! Tests of `drcc_hdl::rmb::ecss`: the bus selection of DRCC contract §12.2,
//! one tick per clock so that bit times are clocks.

use drcc_hdl::rmb::ecss::*;
use rust_hdl::prelude::*;

const HB: u64 = 0x701;

fn clock(uut: &mut BusSelect) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

/// A selection with ttoggle `t`, ntoggle `n`, a period of `p` bit times,
/// bdefault A, running from the next edge on.
fn fresh(t: u64, n: u64, p: u64) -> BusSelect {
    let mut uut = BusSelect::default();
    uut.connect_all();
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut.ttoggle.next = t.into();
    uut.ntoggle.next = n.into();
    uut.period.next = p.into();
    uut.hb.next = HB.into();
    uut.tick.next = true;
    uut.on.next = true;
    uut
}

fn status(uut: &BusSelect) -> (u64, bool, bool) {
    let w = uut.word.val().index() as u64;
    (w & 0xFF, w >> 8 & 1 == 1, w >> 9 & 1 == 1)
}

/// With no heartbeat the node toggles every `ttoggle x period` bit times,
/// `ntoggle` times, then gives up (one more `ttoggle x period`) and stays.
#[test]
fn silence_toggles_ntoggle_times_then_stays() {
    let (t, n, p) = (2, 3, 5);
    let mut uut = fresh(t, n, p);
    let mut events = vec![];
    for clk in 1..=60u64 {
        clock(&mut uut);
        // `ev_toggle` is combinational: after edge `clk` it tells of edge `clk + 1`
        if uut.ev_toggle.val() {
            events.push(clk + 1);
        }
    }
    let at = events;
    assert_eq!(at, vec![10, 20, 30, 40], "toggles at t x p = 10 bit times, then gives up");
    let (ctoggle, bus, no_master) = status(&uut);
    assert_eq!((ctoggle, bus, no_master), (3, true, true));
}

/// A heartbeat on the bus in use restarts the clock and re-arms the bound; a
/// remote frame or another identifier is no heartbeat.
#[test]
fn heartbeats_on_the_bus_in_use_hold_it() {
    let mut uut = fresh(2, 1, 5);
    for clk in 1..=45u64 {
        uut.rx_valid_a.next = clk % 9 == 0;
        uut.key_a.next = HB.into();
        clock(&mut uut);
        assert!(!uut.ev_toggle.val(), "a heartbeat every 9 < 10 bit times: no toggle");
    }
    uut.rx_valid_a.next = false;
    let mut first = None;
    for clk in 1..=30u64 {
        // a remote frame and another identifier every bit time: still silence
        uut.rx_valid_a.next = true;
        uut.key_a.next = if clk % 2 == 0 { (1u64 << 30 | HB).into() } else { 0x702u64.into() };
        clock(&mut uut);
        if uut.ev_toggle.val() && first.is_none() {
            first = Some(clk + 1);
        }
    }
    assert_eq!(first, Some(10), "toggles 10 bit times after the last heartbeat (edge 45)");
}

/// After giving up, a heartbeat on the other bus brings the node there at
/// once; before, it does not.
#[test]
fn a_node_that_gave_up_follows_the_master_to_the_other_bus() {
    let mut uut = fresh(1, 0, 4);
    uut.rx_valid_b.next = true;
    uut.key_b.next = HB.into();
    clock(&mut uut);
    assert!(!status(&uut).1, "a heartbeat on B before giving up: stays on A");
    uut.rx_valid_b.next = false;
    for _ in 0..4 {
        clock(&mut uut);
    }
    assert_eq!(status(&uut), (0, false, true), "ntoggle 0: gave up on A");
    uut.rx_valid_b.next = true;
    assert!(simulate(&mut uut, 100));
    assert!(uut.ev_toggle.val(), "the heartbeat on B toggles at this edge");
    clock(&mut uut);
    assert_eq!(status(&uut), (1, true, false));
}

#[test]
fn bus_select_synthesizes() {
    let mut uut = BusSelect::default();
    uut.connect_all();
    crate::synth_check::yosys_check("bus_select", &generate_verilog(&uut));
}
