//! ISO 16845-1 8.6: the transmit error counter, ISO 11898-1:2015 12.1.4.2
//! rules c, d, f, g and their exceptions, one item per rule.

use super::*;

/// 8.6.19, its edge: the recessive stuff bit after the IDE bit of a base frame,
/// read dominant, is a stuff error outside the arbitration field (ISO
/// 11898-1:2015 10.4.2.3: in base format IDE is control field; 12.1.4.2 rule c
/// exception 2 covers arbitration only): TEC + 8.
pub fn iso_8_6_19_base_ide_stuff_bit_is_not_arbitration(iut: &Iut) {
    // ID ...000, RTR 0, IDE 0: five dominant bits, then a recessive stuff bit.
    let f = base(0x118, &[0x19]);
    let fb = FrameBits::new(&f);
    let p = fb.pos(Field::Ide, 0) + 1;
    assert!(base_ide_stuff_bit(&fb, p));
    corrupt_each(iut, &f, &[p]);
}

/// 8.6.8: ACK error while error active: TEC + 8 at the ACK slot; the flag starts
/// at the ACK delimiter; the retransmission follows the intermission.
pub fn iso_8_6_8_ack_error_active(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for f in [base(0x686, &[8, 6, 8]), ext(0x0868_0868, &[])] {
        let fb = FrameBits::new(&f);
        lt.request(f);
        let run = tx_ack_error(&mut lt, &mut exp, &fb, 2);
        let ack = fb.ack_slot();
        assert_eq!(run.recs[ack - 1].probes.tec, exp.tec - 8);
        assert_eq!(run.recs[ack].probes.tec, exp.tec, "TEC + 8 at the ACK slot");
        assert_eq!(run.recs[ack + 1].label, "ErrFlag 1");
        tx_ok(&mut lt, &mut exp, &fb, 0);
    }
    assert_eq!(exp.tec, 14);
}

/// 8.6.1: the counter part of 8.3.3.
pub fn iso_8_6_1_tec_bit_error_in_active_flag(iut: &Iut) {
    iso_8_3_3_bit_error_in_flag_tx(iut);
}

/// 8.6.2: the counter part of 8.4.4.
pub fn iso_8_6_2_tec_bit_error_in_overload_flag(iut: &Iut) {
    iso_8_4_4_bit_error_in_overload_flag_tx(iut);
}

/// 8.6.3: 16 dominant bits after its active error flag: TEC + 8 at the error, + 8
/// at the 8th and the 16th dominant bit (rule f).
pub fn iso_8_6_3_tec_dominant_after_active_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x080, &[0x80]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    let run = tx_error_with_dominant_after(&mut lt, &mut exp, &fb, 16, 2);
    let at = |k: usize| run.at(&format!("Dominant after flag {k}")).probes.tec;
    assert_eq!(
        (at(7), at(8), at(15), at(16)),
        (8, 16, 16, 24),
        "{}",
        lt.name()
    );
    tx_ok(&mut lt, &mut exp, &fb, 0);
    assert_eq!(exp.tec, 23);
}

/// 8.6.4: 16 dominant bits after its passive error flag: + 8 at the 8th and the
/// 16th (rule f).
pub fn iso_8_6_4_tec_dominant_after_passive_flag(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x084, &[]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    let run = tx_error_with_dominant_after(&mut lt, &mut exp, &fb, 16, 2);
    let at = |k: usize| run.at(&format!("Dominant after flag {k}")).probes.tec;
    assert_eq!(
        (at(7), at(8), at(15), at(16)),
        (135 + 8, 135 + 16, 135 + 16, 135 + 24),
        "{}",
        lt.name()
    );
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.6.5: 23 dominant bits after its overload flag: + 8 at the 8th and the 16th
/// (rule f).
pub fn iso_8_6_5_tec_dominant_after_overload_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x085, &[5]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_ack_error(&mut lt, &mut exp, &fb, 2);
    let mut s = own_frame_then_overload(&fb, 1, 6, 0);
    s.repeat(23, Lt::D, Some(true), "Dominant after flag");
    s.overload_delim().intermission();
    exp.tx_ok();
    let run = lt.run(&s);
    let at = |k: usize| run.at(&format!("Dominant after flag {k}")).probes.tec;
    assert_eq!(
        (at(7), at(8), at(16), at(23)),
        (7, 15, 23, 23),
        "{}",
        lt.name()
    );
    exp.tec_add(16);
    lt.check(&exp, "after the overload frame");
}

/// 8.6.6: bit error, TEC + 8 (see 8.2.1); here in the data field, both values.
pub fn iso_8_6_6_tec_bit_error(iut: &Iut) {
    let f = base(0x086, &[0x0F]);
    let fb = FrameBits::new(&f);
    let pos = [fb.pos(Field::Data, 0), fb.pos(Field::Data, 7)];
    corrupt_each(iut, &f, &pos);
}

/// 8.6.7: form error (dominant CRC delimiter) as transmitter, TEC + 8.
pub fn iso_8_6_7_tec_form_error(iut: &Iut) {
    let f = ext(0x0087_0087, &[7]);
    let fb = FrameBits::new(&f);
    corrupt_each(iut, &f, &[fb.crc_delim(), fb.pos(Field::AckDelim, 0)]);
}

/// 8.6.9 / 8.6.10: form error in its error delimiter and in its overload
/// delimiter, TEC + 8 each.
pub fn iso_8_6_9_tec_delimiter_form_errors(iut: &Iut) {
    iso_8_3_4_form_error_in_delimiter_tx(iut);
    iso_8_4_5_form_error_in_overload_delimiter_tx(iut);
}

/// 8.6.11 / 8.6.12: a successful transmission decrements TEC at EOF bit 7 (base and
/// extended frames); at 0 it stays 0.
pub fn iso_8_6_11_tec_successful_transmission(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    send_ok(&mut lt, &mut exp, &base(0x611, &[]));
    assert_eq!(exp.tec, 0);
    for f in [base(0x611, &[6, 1, 1]), ext(0x0612_0612, &[6, 1, 2])] {
        let fb = FrameBits::new(&f);
        lt.request(f);
        tx_ack_error(&mut lt, &mut exp, &fb, 2);
        let run = tx_ok(&mut lt, &mut exp, &fb, 0);
        assert_eq!(run.recs[fb.eof(6)].probes.tec, exp.tec + 1);
        assert_eq!(run.recs[fb.eof(7)].probes.tec, exp.tec);
    }
    assert_eq!(exp.tec, 14);
}

/// 8.6.13 / 8.6.14: a 13-bit overload flag leaves TEC unchanged (- 1 for the frame
/// only); a 13-bit error flag costs + 8 only.
pub fn iso_8_6_13_tec_13_bit_flags(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x613, &[0x13]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_error_with_dominant_after(&mut lt, &mut exp, &fb, 7, 2);
    assert_eq!(exp.tec, 8);
    let mut s = own_frame_then_overload(&fb, 1, 6, 0);
    s.repeat(7, Lt::D, Some(true), "Dominant after flag");
    s.overload_delim().intermission();
    exp.tx_ok();
    lt.run(&s);
    lt.check(&exp, "after the 13-bit overload flag");
    assert_eq!(exp.tec, 7);
}

/// 8.6.15 / 8.6.16: a dominant last bit of its error delimiter or overload
/// delimiter changes no counter (see 8.4.2).
pub fn iso_8_6_15_tec_unchanged_last_delimiter_bit(iut: &Iut) {
    iso_8_4_2_overload_at_delimiter_bit_8_tx(iut);
}

/// 8.6.17: ACK error while error passive: TEC unchanged (rule c exception 1).
pub fn iso_8_6_17_tec_unchanged_passive_ack_error(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x617, &[0x17]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for k in 0..3 {
        tx_ack_error(&mut lt, &mut exp, &fb, if k == 0 { 2 } else { 0 });
        assert_eq!(exp.tec, 135);
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.6.18: ACK error while error passive followed by a dominant bit during its
/// passive flag (at flag bit 6): TEC + 8 at that bit; the flag then needs 6
/// recessive bits.
pub fn iso_8_6_18_tec_passive_ack_error_then_dominant(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x618, &[0x18]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    let mut s = Script::new();
    s.transmit(&fb, 0..fb.ack_slot() + 1, false, 2);
    s.repeat(5, Lt::R, Some(true), "PassiveFlag");
    s.push(Lt::D, Some(true), "PassiveFlag 6 dominant");
    s.repeat(6, Lt::R, Some(true), "PassiveFlag again");
    exp.tec_add(8);
    s.error_delim();
    interframe_tx(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(
        run.recs[fb.ack_slot()].probes.tec,
        135,
        "no change at the ACK error"
    );
    assert_eq!(run.at("PassiveFlag 5").probes.tec, 135);
    assert_eq!(run.at("PassiveFlag 6 dominant").probes.tec, 143);
    assert_eq!(
        run.at("PassiveFlag again 5").probes.field,
        field::ERROR_FLAG
    );
    assert_eq!(
        run.at("PassiveFlag again 6").probes.field,
        field::ERROR_DELIM
    );
    lt.check(&exp, "after the error frame");
    tx_ok(&mut lt, &mut exp, &fb, 0);
    assert_eq!(exp.tec, 142);
}

/// 8.6.19: stuff error in arbitration on a recessive stuff bit read dominant: TEC
/// unchanged (rule c exception 2).
pub fn iso_8_6_19_tec_unchanged_stuff_error_in_arbitration(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x01A, &[0x19]);
    let fb = FrameBits::new(&f);
    let p = fb.stuff_positions()[0];
    assert!(fb.bits[p].value && fb.in_arbitration(p));
    lt.request(f);
    tx_ack_error(&mut lt, &mut exp, &fb, 2);
    tx_corrupt(&mut lt, &mut exp, &fb, p, 0);
    assert_eq!(exp.tec, 8);
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.6.20: its own successful reception does not change TEC.
pub fn iso_8_6_20_tec_unchanged_by_reception(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x620, &[0x20]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_ack_error(&mut lt, &mut exp, &fb, 2);
    tx_ok(&mut lt, &mut exp, &fb, 0);
    for g in [base(0x111, &[1]), ext(0x0222_2222, &[2, 2])] {
        receive_ok(&mut lt, &mut exp, &FrameBits::new(&g));
        assert_eq!(exp.tec, 7);
    }
}

/// 8.6.21: an error in the frame it receives after losing arbitration does not
/// change TEC (REC + 1); the later successful transmission counts rule g.
pub fn iso_8_6_21_tec_unchanged_error_after_arbitration_lost(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let mine = FrameBits::new(&base(0x051, &[0x80]));
    let theirs = FrameBits::new(&base(0x050, &[0x80]));
    lt.request(mine.frame);
    tx_ack_error(&mut lt, &mut exp, &mine, 2);
    tx_ok(&mut lt, &mut exp, &mine, 0);
    assert_eq!(exp.tec, 7);
    lost_then_error_then_send(&mut lt, &mut exp, &mine, &theirs);
    assert_eq!((exp.tec, exp.rec), (6, 1));
}
