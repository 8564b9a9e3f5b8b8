//! Tests of `drcc_hdl::pelican::armed_capture` against the SJA1000 data
//! sheet's capture registers (6.4.8, 6.4.9: "the register is loaded by the
//! first event after it was read; further events do not change it until the
//! host reads it") and pelican_contract.md P-CAP-1..3 (an event at the read's
//! own edge wins; `rst` arms).

use drcc_hdl::pelican::armed_capture::ArmedCapture;
use rust_hdl::prelude::*;

fn clock(uut: &mut ArmedCapture) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

fn fresh() -> ArmedCapture {
    let mut uut = ArmedCapture::default();
    uut.connect_all();
    uut.pulse.next = false;
    uut.read.next = false;
    uut.value.next = 0u64.into();
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut
}

/// One edge: `event` with `value`, `read` taken; returns the register after it.
fn edge(uut: &mut ArmedCapture, event: Option<u8>, read: bool) -> u8 {
    uut.pulse.next = event.is_some();
    uut.value.next = (event.unwrap_or(0xEE) as u64).into();
    uut.read.next = read;
    clock(uut);
    uut.q.val().to_u64() as u8
}

#[test]
fn the_first_event_after_reset_loads_and_later_ones_wait_for_a_read() {
    let mut uut = fresh();
    assert_eq!(uut.q.val().to_u64(), 0, "rst clears");
    assert_eq!(edge(&mut uut, None, false), 0, "no event, nothing");
    assert_eq!(edge(&mut uut, Some(0x11), false), 0x11, "armed by rst");
    assert_eq!(edge(&mut uut, Some(0x22), false), 0x11, "disarmed");
    assert_eq!(
        edge(&mut uut, None, true),
        0x11,
        "a read re-arms, keeps the value"
    );
    assert_eq!(edge(&mut uut, Some(0x33), false), 0x33, "re-armed");
    assert_eq!(edge(&mut uut, Some(0x44), false), 0x33);
}

/// P-CAP-1: an event at the read's own edge wins: it loads (when armed) and the
/// register stays disarmed; when not armed, the read arms it for the next.
#[test]
fn an_event_at_the_reads_edge_wins() {
    let mut uut = fresh();
    assert_eq!(edge(&mut uut, Some(0x11), true), 0x11, "armed: loads");
    assert_eq!(
        edge(&mut uut, Some(0x22), false),
        0x11,
        "and stays disarmed"
    );
    assert_eq!(
        edge(&mut uut, Some(0x33), true),
        0x11,
        "disarmed: the read arms"
    );
    assert_eq!(edge(&mut uut, Some(0x44), false), 0x44);
}

/// P-CAP-3: `rst` clears and arms.
#[test]
fn rst_clears_and_arms() {
    let mut uut = fresh();
    edge(&mut uut, Some(0x11), false);
    uut.rst.next = true;
    assert_eq!(edge(&mut uut, Some(0x55), false), 0, "rst wins");
    uut.rst.next = false;
    assert_eq!(edge(&mut uut, Some(0x66), false), 0x66, "armed after rst");
}

#[test]
fn armed_capture_synthesizes() {
    let mut uut = ArmedCapture::default();
    uut.connect_all();
    crate::synth_check::yosys_check("armed_capture", &generate_verilog(&uut));
}
