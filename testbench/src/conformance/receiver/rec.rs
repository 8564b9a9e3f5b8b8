//! ISO 16845-1 7.6: the receive error counter, ISO 11898-1:2015 12.1.4.2 rules
//! a, b, d, e, h, i, k, one item per rule.

use super::*;

/// 7.6.1: the receive error counter part of 7.3.3: REC + 8 exactly at the
/// corrupted flag bit.
pub fn iso_7_6_1_rec_bit_error_in_active_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for b in [1, 3, 6] {
        let before = exp.rec;
        let run = flag_bit_error(&mut lt, &mut exp, b);
        let i = run.find(&format!("ErrFlag {b} forced recessive"));
        assert_eq!(run.recs[i - 1].probes.rec, before + 1, "{}", lt.name());
        assert_eq!(run.recs[i].probes.rec, before + 9, "{}", lt.name());
    }
}

/// 7.6.2: the receive error counter part of 7.4.4 (REC 9 before the frame).
pub fn iso_7_6_2_rec_bit_error_in_overload_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&ext(0x0000_0C0C, &[1]));
    let mut s = overload_after_frame(&fb, 2);
    s.push(Lt::ForceR, Some(false), "OvlFlag 3 forced recessive");
    exp.rx_ok();
    exp.rec_add(8);
    rx_error_tail(&mut s, &exp);
    lt.run(&s);
    lt.check(&exp, "REC 9 - 1 + 8");
    assert_eq!(exp.rec, 16);
}

/// 7.6.3: 16 dominant bits after its active error flag: REC + 1 (error), + 8 at
/// the first (rule b), + 8 at the 8th and the 16th (rule f).
pub fn iso_7_6_3_rec_dominant_after_active_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let run = rx_error(&mut lt, &mut exp, 16);
    let at = |k: usize| run.at(&format!("Dominant after flag {k}")).probes.rec;
    assert_eq!(
        (at(1), at(7), at(8), at(15), at(16)),
        (9, 9, 17, 17, 25),
        "{}: REC after dominant bits 1, 7, 8, 15, 16",
        lt.name()
    );
    assert_eq!(exp.rec, 25);
}

/// 7.6.4: 16 dominant bits after its overload flag: + 8 at the 8th and the 16th
/// (rule f; rule b is for error flags only).
pub fn iso_7_6_4_rec_dominant_after_overload_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x0AA, &[0x0A]));
    let mut s = overload_after_frame(&fb, 6);
    s.repeat(16, Lt::D, Some(true), "Dominant after flag");
    s.overload_delim().intermission();
    exp.rx_ok();
    let run = lt.run(&s);
    let at = |k: usize| run.at(&format!("Dominant after flag {k}")).probes.rec;
    assert_eq!(
        (at(1), at(7), at(8), at(15), at(16)),
        (0, 0, 8, 8, 16),
        "{}: REC after dominant bits 1, 7, 8, 15, 16",
        lt.name()
    );
    exp.rec_add(16);
    lt.check(&exp, "after the overload frame");
}

/// 7.6.11: a dominant first bit after its active error flag: REC + 8 exactly at
/// that bit (rule b), on top of + 1 for the error (rule a); none for a recessive
/// first bit.
pub fn iso_7_6_11_rec_dominant_first_bit_after_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let run = rx_error(&mut lt, &mut exp, 0);
    assert_eq!(run.at("ErrDelim 1").probes.rec, 1, "{}", lt.name());
    let run = rx_error(&mut lt, &mut exp, 1);
    assert_eq!(run.at("ErrFlag 6").probes.rec, 2, "{}", lt.name());
    assert_eq!(
        run.at("Dominant after flag 1").probes.rec,
        10,
        "{}",
        lt.name()
    );
    assert_eq!(exp.rec, 10);
}

/// 7.6.5: ACK-slot bit error, REC + 1 (see 7.2.1).
pub fn iso_7_6_5_rec_ack_bit_error(iut: &Iut) {
    iso_7_2_1_ack_bit_error(iut);
}

/// Checks a form error at bit `label` of `run`: REC `before` + 1 exactly at that
/// bit (rule a, at the sample point where the error is seen), unchanged on the bit
/// before, the error flag from the next bit.
#[track_caller]
fn check_form_error_at(lt: &LowerTester, run: &Run, label: &str, before: u8) {
    let i = run.find(label);
    assert_eq!(
        (run.recs[i - 1].probes.rec, run.recs[i].probes.rec),
        (before, before + 1),
        "{}: REC on the bit before {label} and at it",
        lt.name()
    );
    assert_eq!(run.recs[i + 1].label, "ErrFlag 1");
    assert_eq!(run.recs[i + 1].probes.field, field::ERROR_FLAG);
}

/// 7.6.6: form error in the CRC delimiter: REC + 1 at the delimiter (REC 9 before).
pub fn iso_7_6_6_rec_form_error_crc_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x246, &[0x46]));
    let mut s = Script::new();
    s.receive(&fb, 0..fb.crc_delim(), false);
    s.push(Lt::D, Some(true), "CRC delimiter dominant");
    exp.rec_add(1);
    rx_error_tail(&mut s, &exp);
    let run = lt.run(&s);
    check_form_error_at(&lt, &run, "CRC delimiter dominant", 9);
    lt.check(&exp, "CRC delimiter form error");
    assert_eq!(exp.rec, 10);
}

/// 7.6.7: form error in the ACK delimiter (ACK dominant, ACK delimiter dominant;
/// REC 9 before): REC 8 at the ACK slot (rule h), 9 at the ACK delimiter.
pub fn iso_7_6_7_rec_form_error_ack_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&ext(0x0767_0767, &[0x67]));
    let mut s = Script::new();
    s.receive(&fb, 0..fb.ack_slot() + 1, true);
    s.push(Lt::D, Some(true), "ACK delimiter dominant");
    exp.rx_ok();
    exp.rec_add(1);
    rx_error_tail(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(
        run.recs[fb.ack_slot()].probes.rec,
        8,
        "{}: rule h",
        lt.name()
    );
    check_form_error_at(&lt, &run, "ACK delimiter dominant", 8);
    assert!(run.rx_valid_bits().is_empty());
    lt.check(&exp, "ACK delimiter form error");
    assert_eq!(exp.rec, 9);
}

/// 7.6.8: form error in EOF bits 2, 3 and 5 (REC 9 before each frame): REC - 1 at
/// the ACK slot, + 1 at the dominant EOF bit.
pub fn iso_7_6_8_rec_form_error_eof(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x768, &[0x68]));
    for n in [2u8, 3, 5] {
        lt.set_context(format!("EOF bit {n}"));
        let run = eof_form_error(&mut lt, &mut exp, &fb, n);
        check_form_error_at(&lt, &run, &format!("EOF {n} dominant"), 8);
        assert_eq!(exp.rec, 9);
    }
}

/// 7.6.12: form error in its error delimiter (bits 2 and 7, after an active
/// error flag for a stuff error): REC + 1 at the corrupted bit.
pub fn iso_7_6_12_rec_form_error_error_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for k in [2usize, 7] {
        lt.set_context(format!("error delimiter bit {k}"));
        let before = exp.rec + 1;
        let run = delimiter_form_error(&mut lt, &mut exp, k);
        check_form_error_at(&lt, &run, &format!("ErrDelim {k} dominant"), before);
    }
    assert_eq!(exp.rec, 4);
}

/// 7.6.13: form error in its overload delimiter (bits 2 and 7, overload frame on a
/// dominant EOF bit 7 after a data frame; REC 9 before): REC + 1 at the corrupted
/// bit.
pub fn iso_7_6_13_rec_form_error_overload_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x713, &[0x13]));
    for k in [2usize, 7] {
        lt.set_context(format!("overload delimiter bit {k}"));
        let mut s = overload_after_frame(&fb, 6);
        s.repeat(k - 1, Lt::R, Some(true), "OvlDelim");
        let label = format!("OvlDelim {k} dominant");
        s.push(Lt::D, Some(true), label.clone());
        exp.rx_ok();
        let before = exp.rec;
        exp.rec_add(1);
        rx_error_tail(&mut s, &exp);
        let run = lt.run(&s);
        check_form_error_at(&lt, &run, &label, before);
        lt.check(&exp, "overload delimiter form error");
    }
    assert_eq!(exp.rec, 9);
}

/// 7.6.9: stuff error, REC + 1 (in the identifier, the DLC, the data, the CRC).
pub fn iso_7_6_9_rec_stuff_error(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&stuffing_frames(false)[0]);
    for p in fb.stuff_positions().into_iter().step_by(3) {
        let mut s = Script::new();
        s.receive(&fb, 0..p, false);
        s.push(flipped(fb.bits[p].value), Some(true), "stuff bit inverted");
        exp.rec_add(1);
        rx_error_tail(&mut s, &exp);
        let run = lt.run(&s);
        assert_eq!(
            run.recs[p].probes.rec, exp.rec,
            "REC + 1 at the stuff error"
        );
    }
}

/// 7.6.10: CRC error, REC + 1 at the ACK delimiter (see 7.2.5).
pub fn iso_7_6_10_rec_crc_error(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::with(
        &ext(0x1999_9999, &[0x99; 3]),
        Options {
            crc_xor: 0x4000,
            ..Options::default()
        },
    );
    let mut s = Script::new();
    s.receive(&fb, 0..fb.eof(1), false);
    exp.rec_add(1);
    rx_error_tail(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(
        run.recs[fb.ack_slot()].probes.rec,
        9,
        "no rule h without ACK"
    );
    assert_eq!(run.recs[fb.pos(Field::AckDelim, 0)].probes.rec, 10);
    lt.check(&exp, "after the CRC error");
}

/// 7.6.14: a valid frame decrements REC (9 -> 8 -> 7), at the ACK slot; at 0 it
/// stays 0.
pub fn iso_7_6_14_rec_valid_frame(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x321, &[3, 2, 1]));
    receive_ok(&mut lt, &mut exp, &fb);
    assert_eq!(exp.rec, 0);
    rec_to(&mut lt, &mut exp, 9);
    let run = receive_ok(&mut lt, &mut exp, &fb);
    assert_eq!(run.recs[fb.ack_slot() - 1].probes.rec, 9);
    assert_eq!(run.recs[fb.ack_slot()].probes.rec, 8);
    receive_ok(&mut lt, &mut exp, &fb);
    assert_eq!(exp.rec, 7);
}

/// 7.6.15: with REC > 127 a valid frame sets REC to a value in 119..=127 and the
/// IUT is error active again.
pub fn iso_7_6_15_rec_above_127_valid_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_receiver(iut, 135);
    receive_ok(&mut lt, &mut exp, &FrameBits::new(&ext(0x0135_0135, &[1])));
    assert!((119..=127).contains(&exp.rec));
    assert_eq!(lt.probes().err_state, state::ACTIVE);
}

/// 7.6.16: a dominant last EOF bit does not change REC (9 -> 8 by rule h only).
pub fn iso_7_6_16_rec_unchanged_dominant_last_eof_bit(iut: &Iut) {
    iso_7_1_12_valid_at_eof6_overload_at_eof7(iut);
}

/// 7.6.17: a 13-bit overload flag (its 6 bits and 7 more dominant bits) does not
/// change REC (9 -> 8 by rule h only).
pub fn iso_7_6_17_rec_unchanged_13_bit_overload_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x617, &[0x17]));
    let mut s = overload_after_frame(&fb, 6);
    s.repeat(7, Lt::D, Some(true), "Dominant after flag");
    s.overload_delim().intermission();
    lt.run(&s);
    exp.rx_ok();
    lt.check(&exp, "after the 13-bit overload flag");
    assert_eq!(exp.rec, 8);
}

/// 7.6.18: a 13-bit error flag (its 6 bits and 7 more dominant bits) costs REC
/// plus 1 + 8 only (rule b; rule f needs 8 dominant bits after the flag).
pub fn iso_7_6_18_rec_13_bit_error_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rx_error(&mut lt, &mut exp, 7);
    assert_eq!(exp.rec, 9);
}

/// 7.6.19: a dominant last bit of its error delimiter changes no counter (REC
/// plus 1 for the error only; an overload frame follows).
pub fn iso_7_6_19_rec_unchanged_error_delimiter_bit_8(iut: &Iut) {
    iso_7_4_3_overload_at_delimiter_bit_8(iut);
}

/// 7.6.20: a dominant last bit of its overload delimiter changes no counter.
pub fn iso_7_6_20_rec_unchanged_overload_delimiter_bit_8(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x620, &[]));
    let mut s = overload_after_frame(&fb, 6);
    s.repeat(7, Lt::R, Some(true), "OvlDelim");
    s.push(Lt::D, Some(true), "OvlDelim 8 dominant");
    s.overload_flag().overload_delim().intermission();
    lt.run(&s);
    exp.rx_ok();
    lt.check(&exp, "REC unchanged");
    assert_eq!(exp.rec, 0);
}

/// 7.6.21: its own successful transmission does not change REC: the IUT loses
/// arbitration, gets a stuff error as receiver (REC + 1, TEC unchanged), then
/// sends its frame (TEC unchanged at 0, REC unchanged).
pub fn iso_7_6_21_rec_unchanged_by_own_transmission(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let mine = FrameBits::new(&base(0x7F1, &[0x80]));
    let theirs = FrameBits::new(&base(0x7F0, &[0x80]));
    lost_then_error_then_send(&mut lt, &mut exp, &mine, &theirs);
    assert_eq!((exp.tec, exp.rec), (0, 10));
}

/// The IUT requests `mine`, loses arbitration to `theirs`, whose data field the
/// tester corrupts with a stuff error (the IUT is a receiver: REC + 1); after the
/// error frame the IUT sends `mine`, acknowledged.
pub fn lost_then_error_then_send(
    lt: &mut LowerTester,
    exp: &mut Expected,
    mine: &FrameBits,
    theirs: &FrameBits,
) {
    let k = (0..theirs.len())
        .find(|&i| mine.bits[i].value != theirs.bits[i].value)
        .unwrap();
    let p = theirs
        .stuff_positions()
        .into_iter()
        .find(|&p| theirs.bits[p].field == Field::Data)
        .expect("a stuff bit in the data field");
    lt.request(mine.frame);
    let mut s = Script::new();
    for i in 0..p {
        let expect = if i <= k { mine.bits[i].value } else { true };
        s.push(
            Lt::from_value(theirs.bits[i].value),
            Some(expect),
            theirs.name(i),
        );
    }
    s.bits[0].await_sof = Some(2);
    s.push(
        flipped(theirs.bits[p].value),
        Some(true),
        "stuff bit inverted",
    );
    exp.rec_add(1);
    rx_error_tail(&mut s, exp);
    let run = lt.run(&s);
    assert_eq!(run.arb_lost_bits(), vec![k]);
    lt.check(exp, "after the error in the frame that won arbitration");
    crate::conformance::procedures::tx_ok(lt, exp, mine, 0);
}
