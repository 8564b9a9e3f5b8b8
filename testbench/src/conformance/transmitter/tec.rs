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

/// Asserts TEC `before` on the bit before `label` in `run` and `before + 8` at it,
/// and the error flag from the next bit.
#[track_caller]
fn check_tec_step_at(lt: &LowerTester, run: &Run, label: &str, before: u16) {
    let i = run.find(label);
    assert_eq!(
        (run.recs[i - 1].probes.tec, run.recs[i].probes.tec),
        (before, before + 8),
        "{}: TEC on the bit before {label} and at it",
        lt.name()
    );
    assert_eq!(run.recs[i + 1].label, "ErrFlag 1", "{}", lt.name());
}

/// 8.6.9: form error in its error delimiter (bits 2, 4 and 7, after a bit error
/// in its frame): TEC + 8 exactly at the corrupted bit, a new flag from the next.
pub fn iso_8_6_9_tec_error_delimiter_form_error(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x669, &[0x69]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for (n, k) in [2usize, 4, 7].into_iter().enumerate() {
        lt.set_context(format!("error delimiter bit {k}"));
        let before = exp.tec + 8;
        let run = tx_delimiter_dominant(&mut lt, &mut exp, &fb, k, if n == 0 { 2 } else { 0 });
        check_tec_step_at(&lt, &run, &format!("ErrDelim {k} dominant"), before);
    }
    assert_eq!(exp.tec, 48);
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.6.10: form error in its overload delimiter (bits 2 and 7; overload frame on
/// a dominant intermission bit 1 after its own frame): TEC + 8 exactly at the
/// corrupted bit.
pub fn iso_8_6_10_tec_overload_delimiter_form_error(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x66A, &[0x6A]);
    let fb = FrameBits::new(&f);
    for k in [2usize, 7] {
        lt.set_context(format!("overload delimiter bit {k}"));
        lt.request(f);
        let mut s = own_frame_then_overload(&fb, 1, 6, 2);
        s.repeat(k - 1, Lt::R, Some(true), "OvlDelim");
        let label = format!("OvlDelim {k} dominant");
        s.push(Lt::D, Some(true), label.clone());
        exp.tx_ok();
        let before = exp.tec;
        exp.tec_add(8);
        s.error_flag(exp.active()).error_delim();
        interframe_tx(&mut s, &exp);
        let run = lt.run(&s);
        assert_eq!(run.tx_done_bits(), vec![fb.eof(7)]);
        check_tec_step_at(&lt, &run, &label, before);
        lt.check(&exp, "after the form error in the overload delimiter");
    }
    assert_eq!(exp.tec, 15);
}

/// 8.6.11: an error-active IUT decrements TEC at EOF bit 7 of a successful
/// transmission (base and extended frames, TEC 8 before); at 0 it stays 0.
pub fn iso_8_6_11_tec_successful_transmission_active(iut: &Iut) {
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
        assert_eq!(run.recs[fb.eof(7)].probes.err_state, state::ACTIVE);
    }
    assert_eq!(exp.tec, 14);
}

/// 8.6.12: an error-passive IUT decrements TEC at EOF bit 7 of a successful
/// transmission: TEC 135 (passive), then 8 frames: 134, .., 128 passive (each
/// followed by suspend transmission), 127 error active.
pub fn iso_8_6_12_tec_successful_transmission_passive(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    assert_eq!(exp.tec, 135);
    for k in 0..8u32 {
        let f = base(0x612 + k, &[k as u8]);
        let fb = FrameBits::new(&f);
        lt.set_context(format!("frame {k}, TEC {} before", exp.tec));
        let before = exp.tec;
        lt.request(f);
        // Suspend is part of the previous frame's interframe space.
        let run = tx_ok(&mut lt, &mut exp, &fb, 2);
        let (at6, at7) = (run.recs[fb.eof(6)].probes, run.recs[fb.eof(7)].probes);
        assert_eq!((at6.tec, at7.tec), (before, before - 1), "{}", lt.name());
        assert_eq!(at6.err_state, state::PASSIVE);
        let want = if before > 128 {
            state::PASSIVE
        } else {
            state::ACTIVE
        };
        assert_eq!(at7.err_state, want, "{}: state at EOF 7", lt.name());
    }
    assert_eq!(exp.tec, 127);
}

/// 8.6.13: a 13-bit overload flag (a dominant intermission bit 1 after its own
/// frame, its 6-bit overload flag and 7 more dominant bits) leaves TEC unchanged:
/// TEC 8 before the frame, 7 after it (rule g only), at every dominant bit and
/// after the overload frame.
pub fn iso_8_6_13_tec_13_bit_overload_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x613, &[0x13]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_ack_error(&mut lt, &mut exp, &fb, 2);
    assert_eq!(exp.tec, 8);
    let mut s = own_frame_then_overload(&fb, 1, 6, 0);
    s.repeat(7, Lt::D, Some(true), "Dominant after flag");
    s.overload_delim().intermission();
    exp.tx_ok();
    let run = lt.run(&s);
    let first = run.find("Intermission 1 dominant");
    for r in &run.recs[first..] {
        assert_eq!(r.probes.tec, 7, "{}: TEC at {}", lt.name(), r.label);
    }
    lt.check(&exp, "after the 13-bit overload flag");
    assert_eq!(exp.tec, 7);
}

/// 8.6.14: a 13-bit error flag (a bit error on a dominant data bit, its 6-bit
/// active flag and 7 more dominant bits): TEC 8 for the error, unchanged at every
/// further dominant bit (rule f needs 8); the retransmission then gives 7.
pub fn iso_8_6_14_tec_13_bit_error_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x614, &[0x0F]);
    let fb = FrameBits::new(&f);
    let p = fb.pos(Field::Data, 0);
    assert!(!fb.bits[p].value);
    lt.request(f);
    let mut s = Script::new();
    s.transmit(&fb, 0..p, false, 2);
    s.push(Lt::ForceR, Some(false), "Data 0 forced recessive");
    exp.tec_add(8);
    s.active_flag("ErrFlag");
    s.repeat(7, Lt::D, Some(true), "Dominant after flag");
    s.error_delim().intermission();
    let run = lt.run(&s);
    for r in &run.recs[p..] {
        assert_eq!(r.probes.tec, 8, "{}: TEC at {}", lt.name(), r.label);
    }
    lt.check(&exp, "after the 13-bit error flag");
    tx_ok(&mut lt, &mut exp, &fb, 0);
    assert_eq!(exp.tec, 7);
}

/// 8.6.15: a dominant last bit of its overload delimiter (overload frame after
/// its own frame, TEC 8 before the frame) starts an overload frame and changes no
/// counter: TEC 7 (rule g only) at that bit and after.
pub fn iso_8_6_15_tec_unchanged_overload_delimiter_bit_8(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x615, &[0x15]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_ack_error(&mut lt, &mut exp, &fb, 2);
    let mut s = own_frame_then_overload(&fb, 1, 6, 0);
    s.repeat(7, Lt::R, Some(true), "OvlDelim");
    s.push(Lt::D, Some(true), "OvlDelim 8 dominant");
    s.overload_flag().overload_delim().intermission();
    exp.tx_ok();
    let run = lt.run(&s);
    let i = run.find("OvlDelim 8 dominant");
    assert_eq!(run.recs[i].probes.tec, 7, "{}", lt.name());
    assert_eq!(run.recs[i].probes.field, field::OVERLOAD_FLAG);
    assert_eq!(run.recs[i + 1].probes.tec, 7);
    lt.check(&exp, "TEC - 1 for the frame only");
    assert_eq!(exp.tec, 7);
}

/// 8.6.16: a dominant last bit of its error delimiter (after a bit error: TEC 8)
/// starts an overload frame and changes no counter: TEC 8 at that bit and after.
pub fn iso_8_6_16_tec_unchanged_error_delimiter_bit_8(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x616, &[0x16]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    let run = tx_delimiter_dominant(&mut lt, &mut exp, &fb, 8, 2);
    let i = run.find("ErrDelim 8 dominant");
    assert_eq!(
        (run.recs[i - 1].probes.tec, run.recs[i].probes.tec),
        (8, 8),
        "{}",
        lt.name()
    );
    assert_eq!(run.recs[i].probes.field, field::OVERLOAD_FLAG);
    assert_eq!(run.last().probes.tec, 8);
    assert_eq!(exp.tec, 8);
    tx_ok(&mut lt, &mut exp, &fb, 0);
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
    // The first stuff bit of identifier 01Ah (inside the identifier), and the
    // stuff bit after the last bit of identifier 2A0h (five dominant identifier
    // bits end it: the stuff bit sits between the identifier and RTR, still in
    // arbitration).
    let first = |fb: &FrameBits| fb.stuff_positions()[0];
    let after_id = |fb: &FrameBits| {
        fb.stuff_positions()
            .into_iter()
            .find(|&p| fb.bits[p + 1].field == Field::SrrRtr)
            .expect("a stuff bit right before RTR")
    };
    type StuffBit = fn(&FrameBits) -> usize;
    let cases: [(u32, StuffBit); 2] = [(0x01A, first), (0x2A0, after_id)];
    for (id, at) in cases {
        let (mut lt, mut exp) = start(iut);
        let f = base(id, &[0x19]);
        let fb = FrameBits::new(&f);
        let p = at(&fb);
        assert!(
            fb.bits[p].value && fb.in_arbitration(p),
            "{id:03X}h bit {p}"
        );
        lt.request(f);
        tx_ack_error(&mut lt, &mut exp, &fb, 2);
        tx_corrupt(&mut lt, &mut exp, &fb, p, 0);
        assert_eq!(exp.tec, 8);
        tx_ok(&mut lt, &mut exp, &fb, 0);
    }
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
