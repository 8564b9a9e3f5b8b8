//! ISO 16845-1 items 8.1 to 8.6: the IUT as transmitter (transmission,
//! arbitration, error detection, error and overload frames, the error-passive
//! transmitter, suspend transmission, bus-off recovery, the transmit error
//! counter), plus the DRCC paper's Fig. 5/6 behaviour.
//!
//! Expected counters follow ISO 11898-1:2015 12.1.4.2: a transmitter sending an
//! error flag TEC + 8 (rule c), except for an ACK error while error passive
//! (exception 1: + 8 only if it then reads a dominant bit during its passive flag)
//! and for a stuff error in arbitration on a recessive stuff bit read dominant
//! (exception 2: no change); bit error in its active error flag or overload flag
//! plus 8 (rule d); 8th consecutive dominant bit after a flag (14th after an active
//! error flag or an overload flag) and every further 8th + 8 (rule f); successful
//! transmission - 1 (rule g); bus-off above 255, recovery after 128 occurrences of
//! 11 consecutive recessive bits (rules j, l).
//!
//! One file per ISO 16845-1 group: `transmission` (8.1), `error_detection`
//! (8.2), `error_frames` (8.3), `overload` (8.4), `passive` (8.5), `tec` (8.6);
//! the set-ups several groups share are here.

use drcc_cosim::Frame;

use super::bits::{stuff_site_set, stuffing_frames, Field, FrameBits};
use super::lower_tester::{field, state, Iut, LowerTester, Lt, Run, Script};
use super::procedures::{
    base, ext, interframe_tx, remote, tec_to, tx_ack_error, tx_bit_error, tx_ok, Expected,
};
use super::receiver::{
    data_pattern_frames, iso_id_frames, lose_arbitration, lost_then_error_then_send, receive_ok,
};
use super::{timing, timing_brp, timing_slow};

mod error_detection;
mod error_frames;
mod overload;
mod passive;
mod tec;
mod transmission;
pub use error_detection::*;
pub use error_frames::*;
pub use overload::*;
pub use passive::*;
pub use tec::*;
pub use transmission::*;

fn start(iut: &Iut) -> (LowerTester, Expected) {
    (LowerTester::start(iut, timing()), Expected::default())
}

/// Requests `frame` and lets it through with an ACK (TEC - 1).
fn send_ok(lt: &mut LowerTester, exp: &mut Expected, frame: &Frame) -> Run {
    lt.request(*frame);
    tx_ok(lt, exp, &FrameBits::new(frame), 2)
}

/// The IUT transmits `fb` up to r0 (SOF within `sof_within` bits), which the
/// tester forces recessive: a bit error (ISO 11898-1 10.11.1), TEC + 8 (12.1.4.2
/// rule c). Returns the script, to go on with the error flag, and r0's position.
fn bit_error_at_r0(exp: &mut Expected, fb: &FrameBits, sof_within: u32) -> (Script, usize) {
    let r0 = fb.pos(Field::R0, 0);
    let mut s = Script::new();
    s.transmit(fb, 0..r0, false, sof_within);
    s.push(Lt::ForceR, Some(false), "r0 forced recessive");
    exp.tec_add(8);
    (s, r0)
}

/// A fresh IUT error passive with TEC `tec` (a multiple of 8, >= 128) and nothing
/// pending: ACK errors and bit errors on one frame, which then succeeds (TEC - 1).
fn passive_transmitter(iut: &Iut, tec: u16) -> (LowerTester, Expected) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x0E0, &[0xE0]);
    let fb = tec_to(&mut lt, &mut exp, &f, tec + 8);
    tx_ok(&mut lt, &mut exp, &fb, 0);
    assert_eq!(exp.tec, tec + 7);
    assert_eq!(lt.probes().err_state, state::PASSIVE);
    (lt, exp)
}

/// The IUT transmits `fb` (requested) and the tester inverts its bit `p`: the
/// error flag follows from bit `p + 1`; TEC + 8, or unchanged for a recessive stuff
/// bit of the arbitration field read dominant (rule c exception 2); then the
/// delimiter and the intermission (and suspend when passive).
pub fn tx_corrupt(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    p: usize,
    sof_within: u32,
) -> Run {
    let b = fb.bits[p];
    assert!(
        b.stuff || !(b.value && b.field.is_arbitration()),
        "a recessive arbitration bit read dominant is lost arbitration"
    );
    assert!(b.field != Field::AckSlot);
    let mut s = Script::new();
    s.transmit(fb, 0..p, true, sof_within);
    let drive = if b.value { Lt::D } else { Lt::ForceR };
    s.push(drive, Some(b.value), format!("{} inverted", fb.name(p)));
    let exception2 = b.stuff && b.value && fb.in_arbitration(p);
    if !exception2 {
        exp.tec_add(8);
    }
    s.error_flag(exp.active()).error_delim();
    interframe_tx(&mut s, exp);
    let run = lt.run(&s);
    assert_eq!(
        run.recs[p + 1].label,
        "ErrFlag 1",
        "{}: the flag starts at the next bit",
        lt.name()
    );
    assert_eq!(
        run.recs[p].probes.tec,
        exp.tec,
        "{}: TEC at the error",
        lt.name()
    );
    assert!(run.tx_done_bits().is_empty());
    lt.check(exp, &format!("after inverting {}", fb.name(p)));
    run
}

/// Every position of `pos` inverted in turn on `frame`, each on a fresh IUT whose
/// retransmission then succeeds.
fn corrupt_each(iut: &Iut, frame: &Frame, pos: &[usize]) {
    let fb = FrameBits::new(frame);
    for &p in pos {
        let (mut lt, mut exp) = start(iut);
        lt.set_context(format!("{frame}, bit {p} ({})", fb.name(p)));
        lt.request(*frame);
        tx_corrupt(&mut lt, &mut exp, &fb, p, 2);
        tx_ok(&mut lt, &mut exp, &fb, 0);
    }
}

/// Bit error at r0, then the script of the error frame with `dominant_after`
/// dominant bits after the flag.
fn tx_error_with_dominant_after(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    dominant_after: usize,
    sof_within: u32,
) -> Run {
    let (mut s, _) = bit_error_at_r0(exp, fb, sof_within);
    s.error_flag(exp.active());
    s.repeat(dominant_after, Lt::D, Some(true), "Dominant after flag");
    for _ in 0..dominant_after / 8 {
        exp.tec_add(8);
    }
    s.error_delim();
    interframe_tx(&mut s, exp);
    let run = lt.run(&s);
    lt.check(exp, "after the error frame");
    run
}

/// Bit error at r0, then a dominant bit at error delimiter bit `k` (2..=7): form
/// error, TEC + 8, a new flag; or `k` = 8: an overload frame, no change.
fn tx_delimiter_dominant(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    k: usize,
    sof_within: u32,
) -> Run {
    let (mut s, _) = bit_error_at_r0(exp, fb, sof_within);
    s.error_flag(exp.active());
    s.repeat(k - 1, Lt::R, Some(true), "ErrDelim");
    s.push(Lt::D, Some(true), format!("ErrDelim {k} dominant"));
    if k == 8 {
        s.overload_flag().overload_delim();
    } else {
        exp.tec_add(8);
        s.error_flag(exp.active()).error_delim();
    }
    interframe_tx(&mut s, exp);
    let run = lt.run(&s);
    lt.check(exp, &format!("after a dominant error delimiter bit {k}"));
    run
}

/// The IUT sends `fb` (requested) with an ACK; the tester makes intermission bit
/// `bit` (1 or 2) dominant: overload flag from the next bit. Returns the script
/// up to the end of the IUT's overload flag's bit `upto`.
fn own_frame_then_overload(fb: &FrameBits, bit: usize, upto: usize, sof_within: u32) -> Script {
    let mut s = Script::new();
    s.transmit(fb, 0..fb.len(), true, sof_within);
    s.repeat(bit - 1, Lt::R, Some(true), "Intermission");
    s.push(Lt::D, Some(true), format!("Intermission {bit} dominant"));
    for i in 1..=upto {
        s.push(Lt::R, Some(false), format!("OvlFlag {i}"));
    }
    s
}

/// DRCC paper, Fig. 5/6: a lone transmitter nobody acknowledges. TEC 0, 8, ..,
/// 128 (one ACK error per attempt), error passive exactly when TEC reaches 128,
/// then TEC stays 128 while passive (a passive ACK error does not count); passive
/// attempts are separated by the suspend transmission.
pub fn drcc_fig5_lone_transmitter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x5A5, &[0xD2, 0xCC]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    let mut seen = vec![lt.probes().tec];
    for attempt in 1..=22u16 {
        let run = tx_ack_error(&mut lt, &mut exp, &fb, if attempt == 1 { 2 } else { 0 });
        let at_ack = run.recs[fb.ack_slot()].probes;
        let want_tec = (8 * attempt).min(128);
        assert_eq!(at_ack.tec, want_tec, "{}: attempt {attempt}", lt.name());
        let want_state = if want_tec >= 128 {
            state::PASSIVE
        } else {
            state::ACTIVE
        };
        assert_eq!(
            at_ack.err_state,
            want_state,
            "{}: attempt {attempt}",
            lt.name()
        );
        assert_eq!(
            run.recs[fb.ack_slot() - 1].probes.err_state,
            if attempt <= 16 {
                state::ACTIVE
            } else {
                state::PASSIVE
            }
        );
        seen.push(at_ack.tec);
    }
    let want: Vec<u16> = (0..=22u16).map(|k| (8 * k).min(128)).collect();
    assert_eq!(seen, want);
    assert!(lt.outputs().tx_pending);
}
