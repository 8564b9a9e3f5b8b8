//! ISO 16845-1 7.3: the receiver's active error frame (dominant bits after the
//! flag, SOF at intermission bit 3, bit error in the flag, form error in the
//! delimiter).

use super::*;

/// 7.3.1 (and 7.6.11, 7.6.18): after its active error flag the IUT tolerates 1 to 7
/// dominant bits, then needs the 8 recessive delimiter bits; REC + 1 + 8 (rule b).
pub fn iso_7_3_1_dominant_bits_after_active_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for n in 1..=7 {
        lt.set_context(format!("{n} dominant bits after the flag"));
        let before = exp.rec;
        let run = rx_error(&mut lt, &mut exp, n);
        assert_eq!(exp.rec, before + 9);
        assert_eq!(run.at("ErrDelim 8").probes.field, field::INTERMISSION);
        assert_eq!(run.at("Intermission 3").probes.field, field::IDLE);
    }
}

/// 7.3.2: after an error frame, a SOF at the 3rd intermission bit is accepted.
pub fn iso_7_3_2_sof_at_intermission_bit_3(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x444, &[0x44]));
    let mut s = rx_stuff_error(&mut exp);
    s.error_flag(true).error_delim();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.receive(&fb, 0..fb.len(), true).intermission();
    let run = lt.run(&s);
    exp.rx_ok();
    assert_eq!(lt.received, vec![fb.frame], "{}", lt.name());
    assert_eq!(run.rx_valid_bits().len(), 1);
    lt.check(&exp, "after the frame");
}

/// Stuff error, then the flag bit `b` (1..=6) of the IUT's active error flag
/// forced recessive: bit error (REC + 8, rule e), a new flag from the next bit.
pub(super) fn flag_bit_error(lt: &mut LowerTester, exp: &mut Expected, b: usize) -> Run {
    let mut s = rx_stuff_error(exp);
    assert!(exp.active());
    for i in 1..b {
        s.push(Lt::R, Some(false), format!("ErrFlag {i}"));
    }
    s.push(
        Lt::ForceR,
        Some(false),
        format!("ErrFlag {b} forced recessive"),
    );
    exp.rec_add(8);
    s.error_flag(exp.active());
    s.error_delim().intermission();
    let run = lt.run(&s);
    lt.check(exp, &format!("after a bit error in flag bit {b}"));
    run
}

/// 7.3.3 (and 7.6.1): a bit error in its own active error flag (bits 1, 3, 6)
/// restarts the flag at the next bit; REC + 1 + 8.
pub fn iso_7_3_3_bit_error_in_active_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for b in [1, 3, 6] {
        let before = exp.rec;
        flag_bit_error(&mut lt, &mut exp, b);
        assert_eq!(exp.rec, before + 9);
    }
}

/// Stuff error, then a dominant bit at error delimiter bit `k` (2..=7): form
/// error, REC + 1, new flag from the next bit.
pub(super) fn delimiter_form_error(lt: &mut LowerTester, exp: &mut Expected, k: usize) -> Run {
    let mut s = rx_stuff_error(exp);
    s.error_flag(exp.active());
    s.repeat(k - 1, Lt::R, Some(true), "ErrDelim");
    s.push(Lt::D, Some(true), format!("ErrDelim {k} dominant"));
    exp.rec_add(1);
    rx_error_tail(&mut s, exp);
    let run = lt.run(&s);
    lt.check(exp, &format!("after a form error at delimiter bit {k}"));
    run
}

/// 7.3.4: form error in the error delimiter (bits 2..=7): a new error flag from
/// the next bit, REC + 1.
pub fn iso_7_3_4_form_error_in_error_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for k in 2..=7 {
        lt.set_context(format!("delimiter bit {k}"));
        delimiter_form_error(&mut lt, &mut exp, k);
    }
    assert_eq!(exp.rec, 12);
}
