//! Tests of `drcc_hdl::host::busoff_recovery`: the host's permission and the
//! channel's `boff_hold` of DRCC contract §11.6, against the contract's rule
//! `recover_c <= bo_c && (recover_c || w_c)`, `boff_hold = busoff_manual &&
//! !recover_c`.

use drcc_hdl::host::busoff_recovery::*;
use rust_hdl::prelude::*;

const ACTIVE: u64 = 0;
const PASSIVE: u64 = 1;
const BUS_OFF: u64 = 2;

/// One clock: inputs set before the edge, outputs read after it.
fn clock(uut: &mut BusoffRecovery) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

fn fresh(manual: bool) -> BusoffRecovery {
    let mut uut = BusoffRecovery::default();
    uut.connect_all();
    uut.busoff_manual.next = manual;
    uut.recover.next = false;
    uut.err_state.next = ACTIVE.into();
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    clock(&mut uut);
    uut
}

/// One edge with the given channel state and host write; returns `boff_hold`
/// after it.
fn step(uut: &mut BusoffRecovery, err_state: u64, recover: bool) -> bool {
    uut.err_state.next = err_state.into();
    uut.recover.next = recover;
    clock(uut);
    uut.recover.next = false;
    assert!(simulate(uut, 100));
    uut.boff_hold.val()
}

/// §11.6: with `busoff_manual` a bus-off channel is held until the host's
/// `recover`, from the clock after the write; the permission ends at the
/// first edge after the channel has left bus-off, so the next bus-off is held
/// again.
#[test]
fn a_bus_off_channel_is_held_until_the_host_recovers_it() {
    let mut uut = fresh(true);
    for _ in 0..5 {
        assert!(step(&mut uut, BUS_OFF, false), "held while bus-off");
    }
    assert!(!step(&mut uut, BUS_OFF, true), "released by the write");
    for _ in 0..5 {
        assert!(!step(&mut uut, BUS_OFF, false), "the permission lasts");
    }
    // the channel leaves bus-off: the edge after that sees it active
    assert!(step(&mut uut, ACTIVE, false), "permission ends");
    for _ in 0..3 {
        assert!(
            step(&mut uut, BUS_OFF, false),
            "the next bus-off waits again"
        );
    }
}

/// §11.6: a `recover` for a channel that is not bus-off does nothing.
#[test]
fn recover_outside_bus_off_is_not_remembered() {
    let mut uut = fresh(true);
    for state in [ACTIVE, PASSIVE] {
        step(&mut uut, state, true);
        assert!(
            step(&mut uut, BUS_OFF, false),
            "{state}: no permission kept"
        );
    }
}

/// §11.6: without `busoff_manual` nothing is held, written or not.
#[test]
fn automatic_recovery_never_holds() {
    let mut uut = fresh(false);
    assert!(!step(&mut uut, BUS_OFF, false));
    assert!(!step(&mut uut, BUS_OFF, true));
    assert!(!step(&mut uut, ACTIVE, false));
}

/// `rst` clears the permission.
#[test]
fn reset_clears_the_permission() {
    let mut uut = fresh(true);
    assert!(!step(&mut uut, BUS_OFF, true));
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    assert!(step(&mut uut, BUS_OFF, false));
}

#[test]
fn busoff_recovery_synthesizes() {
    let mut uut = BusoffRecovery::default();
    uut.connect_all();
    crate::synth_check::yosys_check("busoff_recovery", &generate_verilog(&uut));
}
