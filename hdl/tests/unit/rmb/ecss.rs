//! Tests of `drcc_hdl::rmb::ecss`: the bus selection of DRCC contract §12.2,
//! with a bit time of four clocks (a tick at every clock that is a multiple
//! of 4), so that a period ends one clock after its last tick (rule 3).

use drcc_hdl::rmb::ecss::*;
use rust_hdl::prelude::*;

const HB: u64 = 0x701;

/// The selection with its missed-heartbeat clock, wired as the core wires them.
struct Pair {
    sel: BusSelect,
    hbc: HbClock,
}

impl std::ops::Deref for Pair {
    type Target = BusSelect;
    fn deref(&self) -> &BusSelect {
        &self.sel
    }
}

impl std::ops::DerefMut for Pair {
    fn deref_mut(&mut self) -> &mut BusSelect {
        &mut self.sel
    }
}

/// The combinational values before the next edge.
fn settle(uut: &mut Pair) {
    uut.sel.hb_cnt.next = uut.hbc.count.val();
    assert!(simulate(&mut uut.sel, 100));
    uut.hbc.restart.next = uut.sel.clock_restart.val();
    uut.hbc.run.next = uut.sel.clock_run.val();
    assert!(simulate(&mut uut.hbc, 100));
}

/// Edge `clk` (counted from 1 after the reset): the tick is set before it.
fn clock(uut: &mut Pair, clk: u64) {
    uut.hbc.tick.next = clk.is_multiple_of(4);
    settle(uut);
    for level in [false, true] {
        uut.sel.clk.next = Clock::from(level);
        uut.hbc.clk.next = Clock::from(level);
        assert!(simulate(&mut uut.sel, 100));
        assert!(simulate(&mut uut.hbc, 100));
    }
    settle(uut);
}

/// A selection with ttoggle `t`, ntoggle `n`, a period of `p` bit times,
/// bdefault A, running from edge 1 on.
fn fresh(t: u64, n: u64, p: u64) -> Pair {
    let mut uut = Pair {
        sel: BusSelect::default(),
        hbc: HbClock::default(),
    };
    uut.sel.connect_all();
    uut.hbc.connect_all();
    uut.rst.next = true;
    clock(&mut uut, 1);
    uut.rst.next = false;
    uut.ttoggle.next = t.into();
    uut.ntoggle.next = n.into();
    uut.period.next = p.into();
    uut.hb.next = HB.into();
    uut.on.next = true;
    uut
}

/// `(bus, no_master)` from `ECSS_STATUS` (its `ctoggle` is ToggleCount's).
fn status(uut: &Pair) -> (bool, bool) {
    let w = uut.word.val().index() as u64;
    assert_eq!(w & 0xFF, 0, "ctoggle is not the selection's");
    (w >> 8 & 1 == 1, w >> 9 & 1 == 1)
}

/// Runs edges `from..=to`, with `rx` choosing the receptions before each;
/// returns the edges with an event (`ev_toggle` is combinational: read before
/// the edge) and the toggles counted.
fn run(
    uut: &mut Pair,
    from: u64,
    to: u64,
    mut rx: impl FnMut(&mut BusSelect, u64),
) -> (Vec<u64>, u32) {
    let (mut events, mut toggles) = (vec![], 0);
    for clk in from..=to {
        rx(&mut uut.sel, clk);
        uut.hbc.tick.next = clk.is_multiple_of(4);
        settle(uut);
        if uut.ev_toggle.val() {
            events.push(clk);
        }
        toggles += uut.toggled.val() as u32;
        clock(uut, clk);
    }
    (events, toggles)
}

/// With no heartbeat the node toggles `ttoggle x period` bit times after the
/// start (one clock after that many ticks), `ntoggle` times, then gives up
/// one search later and stays.
#[test]
fn silence_toggles_ntoggle_times_then_stays() {
    let (t, n, p) = (2, 3, 5);
    let mut uut = fresh(t, n, p);
    let (events, toggles) = run(&mut uut, 1, 170, |_, _| {});
    // the 10th, 20th, 30th and 40th ticks are at edges 40, 80, 120, 160
    assert_eq!(events, vec![41, 81, 121, 161], "t x p = 10 bit times apart");
    assert_eq!(toggles, 3, "ntoggle toggles, the fourth event is giving up");
    assert_eq!(
        status(&uut),
        (true, true),
        "on B after three toggles, given up"
    );
}

/// A heartbeat on the bus in use restarts the clock and re-arms the bound; a
/// remote frame or another identifier is no heartbeat.
#[test]
fn heartbeats_on_the_bus_in_use_hold_it() {
    let mut uut = fresh(2, 1, 5);
    // a heartbeat every 9 bit times (36 clocks) < 10: no toggle
    let (events, _) = run(&mut uut, 1, 180, |u, clk| {
        u.rx_valid_a.next = clk.is_multiple_of(36);
        u.key_a.next = HB.into();
    });
    assert!(
        events.is_empty(),
        "heartbeats in time: no toggle ({events:?})"
    );
    // then a remote frame and another identifier at every clock: silence
    let (events, toggles) = run(&mut uut, 181, 230, |u, clk| {
        u.rx_valid_a.next = true;
        u.key_a.next = if clk.is_multiple_of(2) {
            (1u64 << 30 | HB).into()
        } else {
            0x702u64.into()
        };
    });
    // the last heartbeat at edge 180; its 10th tick after at edge 220
    assert_eq!((events, toggles), (vec![221], 1));
}

/// After giving up, a heartbeat on the other bus brings the node there at
/// once; before, it does not.
#[test]
fn a_node_that_gave_up_follows_the_master_to_the_other_bus() {
    let mut uut = fresh(1, 0, 4);
    let (events, _) = run(&mut uut, 1, 17, |u, clk| {
        u.rx_valid_b.next = clk == 2;
        u.key_b.next = HB.into();
    });
    assert_eq!(
        events,
        vec![17],
        "ntoggle 0: gives up one period after the start"
    );
    assert_eq!(
        status(&uut),
        (false, true),
        "gave up on A, the heartbeat on B ignored"
    );
    let (events, toggles) = run(&mut uut, 18, 18, |u, _| u.rx_valid_b.next = true);
    assert_eq!(
        (events, toggles),
        (vec![18], 1),
        "the heartbeat on B toggles at once"
    );
    assert_eq!(status(&uut), (true, false));
}

/// Ctoggle counts toggles, saturates at 255, and a clear wins over a toggle.
#[test]
fn toggle_count_saturates_and_clears() {
    let mut uut = ToggleCount::default();
    uut.connect_all();
    uut.clear.next = true;
    clock_count(&mut uut);
    uut.clear.next = false;
    uut.toggled.next = true;
    for _ in 0..300 {
        clock_count(&mut uut);
    }
    assert_eq!(uut.count.val().index(), 255);
    uut.clear.next = true;
    clock_count(&mut uut);
    assert_eq!(uut.count.val().index(), 0, "the clear wins");
}

fn clock_count(uut: &mut ToggleCount) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

#[test]
fn bus_select_synthesizes() {
    let mut uut = BusSelect::default();
    uut.connect_all();
    crate::synth_check::yosys_check("bus_select", &generate_verilog(&uut));
    let mut uut = HbClock::default();
    uut.connect_all();
    crate::synth_check::yosys_check("hb_clock", &generate_verilog(&uut));
}
