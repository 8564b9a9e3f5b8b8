//! ISO 16845-1 7.4: overload frames (at intermission, at the last EOF bit, at
//! delimiter bit 8, bit and form errors in the overload frame).

use super::*;

/// 7.4.2: see [`iso_7_1_12_valid_at_eof6_overload_at_eof7`]; here with an extended
/// remote frame and REC 0.
pub fn iso_7_4_2_overload_at_last_eof_bit(iut: &Iut) {
    let (mut lt, exp) = start(iut);
    let fb = FrameBits::new(&remote(0x1ABC_DEF0, true, 2));
    let run = lt.run(&eof7_overload_script(&fb));
    assert_eq!(run.rx_valid_bits(), vec![fb.eof(6)]);
    lt.check(&exp, "after the overload frame");
}

/// Intermission bit `bit` (1 or 2) made dominant after bits 1..bit-1 recessive:
/// the IUT's overload flag from the next bit, its delimiter; `then_intermission`
/// adds the 3 intermission bits.
fn dominant_intermission(s: &mut Script, bit: usize, then_intermission: bool) {
    s.repeat(bit - 1, Lt::R, Some(true), "Intermission");
    s.push(Lt::D, Some(true), format!("Intermission {bit} dominant"));
    s.overload_flag().overload_delim();
    if then_intermission {
        s.intermission();
    }
}

/// Checks the overload frame of [`dominant_intermission`] in `run` (the `k`-th
/// dominant intermission bit `bit`): decided at that bit, its flag from the next
/// bit (the IUT's `tx` is checked by the script), REC `rec` there.
#[track_caller]
fn check_overload_after(lt: &LowerTester, run: &Run, bit: usize, k: usize, rec: u8) {
    let label = format!("Intermission {bit} dominant");
    let mut i = run.find(&label);
    for _ in 1..k {
        i = run.find_from(i + 1, &label);
    }
    // The overload frame is decided at the sample point of the dominant bit
    // (contract §4.1: `field` changes there), the flag is on `tx` from the next bit.
    assert_eq!(
        run.recs[i].probes.field,
        field::OVERLOAD_FLAG,
        "{}",
        lt.name()
    );
    assert_ne!(run.recs[i - 1].probes.field, field::OVERLOAD_FLAG);
    let flag = &run.recs[i + 1];
    assert_eq!(flag.label, "OvlFlag 1");
    assert_eq!(
        (flag.probes.field, flag.probes.rec),
        (field::OVERLOAD_FLAG, rec),
        "{}: overload flag from the bit after the dominant intermission bit {bit}, \
         REC unchanged",
        lt.name()
    );
}

/// 7.4.1: a dominant intermission bit 1 or 2 after a data frame starts an
/// overload frame at the next bit; REC changes only by rule h for the frame.
pub fn iso_7_4_1_overload_at_intermission(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x155, &[0x0F]));
    for bit in [1usize, 2] {
        lt.set_context(format!("after a data frame, intermission bit {bit}"));
        let mut s = Script::new();
        s.receive(&fb, 0..fb.len(), true);
        dominant_intermission(&mut s, bit, true);
        exp.rx_ok();
        let run = lt.run(&s);
        assert_eq!(run.rx_valid_bits(), vec![fb.eof(6)], "{}", lt.name());
        check_overload_after(&lt, &run, bit, 1, exp.rec);
        lt.check(&exp, "the overload frame changes no counter");
    }
    assert_eq!(exp.rec, 7);
}

/// 7.4.6: a dominant intermission bit 1 or 2 after an error frame (a stuff error
/// in the data field, error flag, error delimiter) starts an overload frame at
/// the next bit; REC + 1 for the error only.
pub fn iso_7_4_6_overload_at_intermission_after_error_frame(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x746, &[0x00]));
    let p = fb
        .stuff_positions()
        .into_iter()
        .find(|&p| fb.bits[p].field == Field::Data)
        .expect("a stuff bit in the data field");
    for bit in [1usize, 2] {
        lt.set_context(format!("after an error frame, intermission bit {bit}"));
        let mut s = Script::new();
        s.receive(&fb, 0..p, false);
        s.push(flipped(fb.bits[p].value), Some(true), "stuff error");
        exp.rec_add(1);
        s.error_flag(true).error_delim();
        dominant_intermission(&mut s, bit, true);
        let run = lt.run(&s);
        assert!(run.rx_valid_bits().is_empty());
        check_overload_after(&lt, &run, bit, 1, exp.rec);
        lt.check(&exp, "REC + 1 for the stuff error only");
    }
    assert_eq!(exp.rec, 2);
}

/// 7.4.7: a dominant intermission bit 1 or 2 after an overload frame (itself
/// started by a dominant intermission bit 1 after a data frame) starts another
/// overload frame at the next bit; no counter change.
pub fn iso_7_4_7_overload_at_intermission_after_overload_frame(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x747, &[0x47]));
    for bit in [1usize, 2] {
        lt.set_context(format!("after an overload frame, intermission bit {bit}"));
        let mut s = Script::new();
        s.receive(&fb, 0..fb.len(), true);
        dominant_intermission(&mut s, 1, false);
        dominant_intermission(&mut s, bit, true);
        exp.rx_ok();
        let run = lt.run(&s);
        let k = if bit == 1 { 2 } else { 1 };
        check_overload_after(&lt, &run, bit, k, exp.rec);
        lt.check(&exp, "overload frames change no counter");
    }
    assert_eq!(exp.rec, 7);
}

/// 7.4.3 (and 7.6.19, 7.6.20): a dominant 8th bit of an error delimiter and of an
/// overload delimiter starts an overload frame; no counter change.
pub fn iso_7_4_3_overload_at_delimiter_bit_8(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let mut s = rx_stuff_error(&mut exp);
    s.error_flag(true);
    s.repeat(7, Lt::R, Some(true), "ErrDelim");
    s.push(Lt::D, Some(true), "ErrDelim 8 dominant");
    s.overload_flag();
    s.repeat(7, Lt::R, Some(true), "OvlDelim");
    s.push(Lt::D, Some(true), "OvlDelim 8 dominant");
    s.overload_flag().overload_delim().intermission();
    let run = lt.run(&s);
    assert_eq!(run.at("ErrDelim 8 dominant").probes.rec, 1);
    lt.check(&exp, "REC + 1 for the stuff error only");
    receive_ok(&mut lt, &mut exp, &FrameBits::new(&base(0x700, &[])));
}

/// A received frame, a dominant EOF bit 7, and the script up to the end of the
/// IUT's overload flag's bit `upto` (0: just before the flag).
pub(super) fn overload_after_frame(fb: &FrameBits, upto: usize) -> Script {
    let mut s = Script::new();
    s.receive(fb, 0..fb.eof(7), true);
    s.push(Lt::D, Some(true), "EOF 7 dominant");
    for i in 1..=upto {
        s.push(Lt::R, Some(false), format!("OvlFlag {i}"));
    }
    s
}

/// 7.4.4 (and 7.6.2): a bit error in its overload flag (bits 1, 3, 6): error flag
/// from the next bit, REC + 8 (rule e).
pub fn iso_7_4_4_bit_error_in_overload_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x0C0, &[0xC0]));
    for b in [1usize, 3, 6] {
        lt.set_context(format!("overload flag bit {b}"));
        let mut s = overload_after_frame(&fb, b - 1);
        s.push(
            Lt::ForceR,
            Some(false),
            format!("OvlFlag {b} forced recessive"),
        );
        exp.rx_ok();
        exp.rec_add(8);
        rx_error_tail(&mut s, &exp);
        let run = lt.run(&s);
        let i = run.find(&format!("OvlFlag {b} forced recessive"));
        assert_eq!(run.recs[i].probes.rec, exp.rec, "REC + 8 at the bit error");
        assert_eq!(run.recs[i + 1].label, "ErrFlag 1");
        lt.check(&exp, "after the bit error in the overload flag");
    }
}

/// 7.4.5: form error in the overload delimiter (bits 2..=7): error flag from the
/// next bit, REC + 1.
pub fn iso_7_4_5_form_error_in_overload_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x3F3, &[]));
    for k in 2..=7 {
        lt.set_context(format!("overload delimiter bit {k}"));
        let mut s = overload_after_frame(&fb, 6);
        s.repeat(k - 1, Lt::R, Some(true), "OvlDelim");
        s.push(Lt::D, Some(true), format!("OvlDelim {k} dominant"));
        exp.rx_ok();
        exp.rec_add(1);
        rx_error_tail(&mut s, &exp);
        lt.run(&s);
        lt.check(&exp, "after the form error in the overload delimiter");
    }
}
