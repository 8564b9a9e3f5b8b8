//! The ACK unit (hub contract §4.1, paper section 4): a correct hub never needs
//! it; a hub that passes its own nodes' ACK while coupled (`CTRL.fi_ack_leak`, the
//! paper's "malicious" hub) is caught by it, and without it that ACK would reach
//! the nodes, so two stars that lost each other could each complete frames.

use super::*;

/// One frame from port 0 of a 2x1 hub, ACKed by node port 1 and, if `twin_ack`,
/// by the sublink (port 2), with `CTRL.fi_ack_leak` = `leak`. Returns the bench and
/// the step of the ACK slot's first clock.
fn leak_run(hub: HubModel, leak: bool, twin_ack: bool) -> (Bench, usize) {
    let mut b = Bench::running_hub(hub, 2, 1);
    if leak {
        b.write(CTRL, ACK_INTERDEP | FI_ACK_LEAK);
    }
    let f = encode(0x155, false, false, 1, &[0xC3]);
    let ackers = if twin_ack { 0b110 } else { 0b010 };
    let t0 = b.send(&f, 0, ackers);
    (b, t0 + CPB * f.ack)
}

fn hub() -> HubModel {
    HubModel::new(2, 1).expect("supported shape")
}

/// Node 1's ACK is on the pins during ta..ta+8; it would reach the downlinks at
/// ta+2..ta+10 (§3: 3 edges through the synchronizers and the output register).
fn own_ack_reached_nodes(b: &Bench, ta: usize) -> bool {
    (ta + 2..ta + 10).any(|k| b.log[k].downlink != 0b11)
}

#[test]
fn a_correct_hub_never_needs_the_ack_unit() {
    let (mut b, ta) = leak_run(hub(), false, false);
    assert!(!own_ack_reached_nodes(&b, ta), "ACK interdependence");
    assert_eq!(b.read(ACK_UNIT) & 0xFFFF, 0, "no intervention");
    assert_eq!(b.read(INT_STATUS) & INT_ACK_UNIT, 0);
    let (mut b, ta) = leak_run(hub(), false, true);
    assert!(
        (ta + 2..ta + 10).all(|k| b.log[k].downlink == 0),
        "the twin's ACK passes"
    );
    assert_eq!(b.read(ACK_UNIT) & 0xFFFF, 0);
}

#[test]
fn without_the_unit_a_leaking_hub_passes_its_own_ack() {
    // What the unit exists for: the fault injected, nothing guarding.
    let (b, ta) = leak_run(hub().without_ack_unit(), true, false);
    assert!(
        (ta + 2..ta + 10).all(|k| b.log[k].downlink == 0),
        "the leaking coupler passes node 1's ACK"
    );
}

#[test]
fn the_unit_blocks_a_leaking_hubs_own_ack_once_per_window() {
    let (mut b, ta) = leak_run(hub(), true, false);
    assert!(
        !own_ack_reached_nodes(&b, ta),
        "the unit turned the ACK recessive"
    );
    // The hub itself still sees and forwards its nodes' ACK (only the downlinks
    // are guarded).
    assert!((ta + 2..ta + 10).all(|k| b.log[k].sublink_out == 0));
    assert_eq!(
        b.read(ACK_UNIT) & 0xFFFF,
        1,
        "one window with interventions"
    );
    assert_ne!(b.read(INT_STATUS) & INT_ACK_UNIT, 0);
    // A second frame: a second window.
    let f = encode(0x2AA, false, false, 0, &[]);
    b.send(&f, 0, 0b010);
    assert_eq!(b.read(ACK_UNIT) & 0xFFFF, 2);
    // The twin's ACK is still passed: the unit only removes dominant bits the twin
    // did not send.
    let (mut b, ta) = leak_run(hub(), true, true);
    assert!((ta + 2..ta + 10).all(|k| b.log[k].downlink == 0));
    assert_eq!(b.read(ACK_UNIT) & 0xFFFF, 0);
}

#[test]
fn the_unit_stands_aside_when_the_hub_may_pass_its_own_ack() {
    // Decoupled (paper section 4: each star then runs alone) or ACK
    // interdependence off: the own nodes' ACK is legitimate.
    for (interdep, decouple) in [(false, false), (true, true)] {
        let mut b = Bench::running(2, 1, &[], interdep);
        let ctl = if interdep { ACK_INTERDEP } else { 0 };
        if decouple {
            b.write(CTRL, FORCE_DECOUPLE | ctl);
            b.idle_bits(2);
        }
        b.write(CTRL, FI_ACK_LEAK | ctl);
        let f = encode(0x155, false, false, 1, &[0xC3]);
        let ta = b.send(&f, 0, 0b010) + CPB * f.ack;
        assert!((ta + 2..ta + 10).all(|k| b.log[k].downlink == 0));
        assert_eq!(b.read(ACK_UNIT) & 0xFFFF, 0);
    }
}

#[test]
fn fi_ack_leak_reads_back_and_the_window_is_visible() {
    let mut b = Bench::running(2, 1, &[], true);
    b.write(CTRL, ACK_INTERDEP | FI_ACK_LEAK);
    assert_eq!(b.read(CTRL), ACK_INTERDEP | FI_ACK_LEAK);
    assert_eq!(b.read(ACK_UNIT) >> 16, 0, "no window at bus idle");
    b.write(CTRL, ACK_INTERDEP);
    assert_eq!(b.read(CTRL), ACK_INTERDEP);
}
