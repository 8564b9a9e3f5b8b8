//! Tests of `drcc_hdl::host::captures`: the capture and re-arm rules of DRCC
//! contract §10.2, with the expected words built from the register table's
//! field positions (`CAP_A` in `docs/registers.md`), not from the block.

use drcc_hdl::channel::bsp::field::Field;
use drcc_hdl::host::captures::*;
use drcc_hdl::host::registers::MAP;
use rust_hdl::prelude::*;

/// One clock: inputs set before the edge, outputs read after it.
fn clock(uut: &mut Captures) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

fn idle(uut: &mut Captures) {
    uut.rst.next = false;
    uut.err_valid_a.next = false;
    uut.err_valid_b.next = false;
    uut.arb_lost_a.next = false;
    uut.arb_lost_b.next = false;
    uut.rearm_err.next = false;
    uut.rearm_alc.next = false;
    uut.rearm_chan.next = 0.into();
}

/// The word `CAP_x` reads for an error (kind, field code, tx) and an ALC.
fn word(err: Option<(u32, u32, bool)>, alc: Option<u32>) -> u32 {
    let mut w = 0;
    if let Some((kind, field, tx)) = err {
        w |= MAP.field("CAP_A", "err_kind").put(kind)
            | MAP.field("CAP_A", "err_field").put(field)
            | MAP.field("CAP_A", "err_tx").put(tx as u32)
            | MAP.field("CAP_A", "err_valid").put(1);
    }
    if let Some(alc) = alc {
        w |= MAP.field("CAP_A", "alc").put(alc) | MAP.field("CAP_A", "alc_valid").put(1);
    }
    w
}

fn cap_a(uut: &Captures) -> u32 {
    uut.cap_a.val().index() as u32
}

/// §10.2: the first error is held, later ones are not taken until the re-arm;
/// the re-arm alone clears only the valid flag; a capture at the re-arm's edge
/// wins. Channel B's capture is independent of A's events.
#[test]
fn the_first_error_is_held_until_the_interrupt_is_acknowledged() {
    let mut uut = Captures::default();
    uut.connect_all();
    idle(&mut uut);
    uut.rst.next = true;
    clock(&mut uut);
    idle(&mut uut);
    clock(&mut uut);
    assert_eq!(cap_a(&uut), 0, "rst empties the capture");
    // an ACK error (5) as transmitter in the ACK slot (field code 13, timing
    // contract §4.1)
    uut.err_valid_a.next = true;
    uut.err_kind_a.next = 5.into();
    uut.err_field_a.next = Field::AckSlot;
    uut.err_tx_a.next = true;
    assert!(simulate(&mut uut, 100));
    assert!(uut.ev_bus_error.val(), "the error is an interrupt event");
    clock(&mut uut);
    idle(&mut uut);
    let first = word(Some((5, 13, true)), None);
    assert_eq!(cap_a(&uut), first);
    assert_eq!(uut.cap_b.val().index(), 0, "B saw nothing");
    // a bit error (1) in the data field (10) as receiver: not taken
    uut.err_valid_a.next = true;
    uut.err_kind_a.next = 1.into();
    uut.err_field_a.next = Field::Data;
    uut.err_tx_a.next = false;
    clock(&mut uut);
    idle(&mut uut);
    assert_eq!(cap_a(&uut), first, "held until re-armed");
    // re-arm alone: valid clears, the fields stay
    uut.rearm_err.next = true;
    clock(&mut uut);
    idle(&mut uut);
    assert_eq!(cap_a(&uut), first & !MAP.field("CAP_A", "err_valid").mask());
    // an error at the re-arm's edge is taken
    uut.rearm_err.next = true;
    uut.err_valid_a.next = true;
    clock(&mut uut);
    idle(&mut uut);
    assert_eq!(cap_a(&uut), word(Some((1, 10, false)), None));
}

/// §10.2 for the arbitration-lost capture, and the re-arm of one kind leaves
/// the other alone.
#[test]
fn the_first_lost_arbitration_is_held_until_the_interrupt_is_acknowledged() {
    let mut uut = Captures::default();
    uut.connect_all();
    idle(&mut uut);
    uut.rst.next = true;
    clock(&mut uut);
    idle(&mut uut);
    uut.arb_lost_a.next = true;
    uut.alc_a.next = 6.into();
    clock(&mut uut);
    idle(&mut uut);
    assert_eq!(cap_a(&uut), word(None, Some(6)));
    uut.arb_lost_a.next = true;
    uut.alc_a.next = 20.into();
    uut.rearm_err.next = true;
    clock(&mut uut);
    idle(&mut uut);
    assert_eq!(
        cap_a(&uut),
        word(None, Some(6)),
        "held; rearm_err does not touch it"
    );
    uut.arb_lost_a.next = true;
    uut.rearm_alc.next = true;
    clock(&mut uut);
    idle(&mut uut);
    assert_eq!(cap_a(&uut), word(None, Some(20)));
}

/// PeliCAN contract P-X-3: a host view's load of `CAP_A` re-arms channel A's
/// error and arbitration captures, and leaves channel B's held.
#[test]
fn a_view_load_rearms_one_channel() {
    let mut uut = Captures::default();
    uut.connect_all();
    idle(&mut uut);
    uut.rst.next = true;
    clock(&mut uut);
    idle(&mut uut);
    uut.err_valid_a.next = true;
    uut.err_valid_b.next = true;
    uut.err_kind_a.next = 5.into();
    uut.err_kind_b.next = 5.into();
    uut.err_field_a.next = Field::AckSlot;
    uut.err_field_b.next = Field::AckSlot;
    uut.err_tx_a.next = true;
    uut.err_tx_b.next = true;
    uut.arb_lost_a.next = true;
    uut.alc_a.next = 6.into();
    clock(&mut uut);
    idle(&mut uut);
    let held = word(Some((5, 13, true)), Some(6));
    assert_eq!(cap_a(&uut), held);
    let b = uut.cap_b.val().index() as u32;
    assert_eq!(b, word(Some((5, 13, true)), None));
    uut.rearm_chan.next = 1.into();
    clock(&mut uut);
    idle(&mut uut);
    let valid = MAP.field("CAP_A", "err_valid").mask() | MAP.field("CAP_A", "alc_valid").mask();
    assert_eq!(cap_a(&uut), held & !valid, "A re-armed, both kinds");
    assert_eq!(uut.cap_b.val().index() as u32, b, "B held");
}

/// §10.2: `err_warning` is an event in both directions, one clock per change.
#[test]
fn a_warning_change_either_way_is_one_event() {
    let mut uut = Captures::default();
    uut.connect_all();
    idle(&mut uut);
    uut.ew_a.next = false;
    uut.ew_b.next = false;
    uut.rst.next = true;
    clock(&mut uut);
    idle(&mut uut);
    let mut events = vec![];
    for cycle in 0..8 {
        uut.ew_a.next = (2..5).contains(&cycle);
        assert!(simulate(&mut uut, 100));
        events.push(uut.ev_err_warning.val());
        clock(&mut uut);
    }
    assert_eq!(
        events,
        [false, false, true, false, false, true, false, false]
    );
}

#[test]
fn captures_synthesize() {
    let mut uut = Captures::default();
    uut.connect_all();
    crate::synth_check::yosys_check("captures", &generate_verilog(&uut));
}
