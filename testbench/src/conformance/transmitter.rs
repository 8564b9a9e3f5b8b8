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

use drcc_cosim::Frame;

use super::bits::{stuffing_frames, Field, FrameBits};
use super::lower_tester::{field, state, Iut, LowerTester, Lt, Run, Script};
use super::procedures::{
    base, ext, interframe_tx, remote, tec_to, tx_ack_error, tx_bit_error, tx_ok, Expected,
};
use super::receiver::{
    data_pattern_frames, lose_arbitration, lost_then_error_then_send, receive_ok, spread_frames,
};
use super::{timing, timing_brp};

fn start(iut: &Iut) -> (LowerTester, Expected) {
    (LowerTester::start(iut, timing()), Expected::default())
}

/// Requests `frame` and lets it through with an ACK (TEC - 1).
fn send_ok(lt: &mut LowerTester, exp: &mut Expected, frame: &Frame) -> Run {
    lt.request(*frame);
    tx_ok(lt, exp, &FrameBits::new(frame), 2)
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

/// 8.1.1 / 8.1.2: base and extended data and remote frames, every DLC 0..=15, a
/// spread of identifiers: the IUT's `tx` equals the tester's encoding bit by bit,
/// `tx_done` at EOF bit 7, TEC stays 0; the same with a prescaler (brp 1).
pub fn iso_8_1_1_base_and_extended_frames(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let mut frames = spread_frames();
    for dlc in 9..=15u8 {
        frames.push(Frame {
            dlc,
            ..base(0x0D0 + dlc as u32, &[dlc; 8])
        });
    }
    for f in &frames {
        lt.set_context(format!("{f}"));
        send_ok(&mut lt, &mut exp, f);
    }
    assert_eq!(lt.tx_done, frames.len() as u32);
    let mut lt = LowerTester::start(iut, timing_brp());
    for f in frames.iter().step_by(3) {
        send_ok(&mut lt, &mut exp, f);
    }
}

/// 8.1.3 / 8.1.4: arbitration lost at every bit of the arbitration field (each
/// base and extended identifier bit, SRR, IDE, RTR): `arb_lost` at that bit,
/// recessive afterwards, the winner received and acknowledged, then the IUT's
/// frame sent right after the intermission.
pub fn iso_8_1_3_arbitration_lost_every_bit(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let mut cases: Vec<(Frame, Frame)> = Vec::new();
    for i in 0..11 {
        cases.push((
            base(0x7FF, &[0x11]),
            base(0x7FF & !(1 << (10 - i)), &[0x22]),
        ));
    }
    cases.push((remote(0x555, false, 1), base(0x555, &[1])));
    let all = 0x1FFF_FFFF;
    for i in 0..29 {
        cases.push((ext(all, &[0x33]), ext(all & !(1 << (28 - i)), &[0x44])));
    }
    cases.push((ext(all, &[]), base(0x7FF, &[])));
    cases.push((ext(all, &[]), remote(0x7FF, false, 0)));
    cases.push((remote(0x0A0A_0A0A, true, 2), ext(0x0A0A_0A0A, &[1, 2])));
    let mut fields = Vec::new();
    for (mine, theirs) in &cases {
        lt.set_context(format!("{mine} against {theirs}"));
        let k = lose_arbitration(&mut lt, &mut exp, mine, theirs);
        fields.push(FrameBits::new(theirs).bits[k].field);
    }
    for f in [
        Field::IdA,
        Field::SrrRtr,
        Field::Ide,
        Field::IdB,
        Field::RtrExt,
    ] {
        assert!(fields.contains(&f), "no arbitration loss in {f:?}");
    }
    assert_eq!(lt.arb_lost, cases.len() as u32);
}

/// 8.1.5: the frame is valid for the transmitter at the end of EOF: `tx_done` at
/// EOF bit 7; a dominant EOF bit 7 (or 6) is an error for the transmitter (flag
/// from the next bit, TEC + 8, no `tx_done`) and the frame is sent again.
pub fn iso_8_1_5_valid_at_end_of_eof(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = ext(0x0815_0815, &[8, 1, 5]);
    send_ok(&mut lt, &mut exp, &f);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_corrupt(&mut lt, &mut exp, &fb, fb.eof(7), 2);
    tx_corrupt(&mut lt, &mut exp, &fb, fb.eof(6), 0);
    tx_ok(&mut lt, &mut exp, &fb, 0);
    assert_eq!(exp.tec, 15);
}

/// 8.1.6 / 8.1.7: frames whose stuff bits follow every field that can carry one
/// (base and extended): the IUT's `tx` carries every stuff bit.
pub fn iso_8_1_6_stuffing_every_field(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for ide in [false, true] {
        for f in stuffing_frames(ide) {
            lt.set_context(format!("{f}"));
            send_ok(&mut lt, &mut exp, &f);
        }
    }
}

/// 8.1.8: with a frame pending, the IUT takes a dominant 3rd intermission bit
/// as SOF and sends its identifier from the next bit (no SOF of its own).
pub fn iso_8_1_8_sof_at_intermission_bit_3(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let theirs = FrameBits::new(&base(0x600, &[6]));
    let mine = FrameBits::new(&base(0x181, &[8, 1, 8]));
    let mut s = Script::new();
    s.receive(&theirs, 0..theirs.len(), true);
    s.request_at(10, mine.frame);
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.push(Lt::D, None, "Intermission 3 dominant");
    s.transmit(&mine, 1..mine.len(), true, 0);
    s.intermission();
    let run = lt.run(&s);
    exp.rx_ok();
    exp.tx_ok();
    assert_eq!(run.tx_done_bits().len(), 1, "{}", lt.name());
    assert_eq!(lt.received, vec![theirs.frame]);
    lt.check(&exp, "after both frames");
}

/// Positions of one bit the IUT drives in every field of `fb`, both polarities
/// where the field has both, outside arbitration losses and the ACK slot.
fn one_bit_per_field(fb: &FrameBits) -> Vec<usize> {
    let mut v = Vec::new();
    for (i, b) in fb.bits.iter().enumerate() {
        let skip = b.stuff
            || matches!(b.field, Field::Sof | Field::AckSlot)
            || (b.value && b.field.is_arbitration());
        if skip {
            continue;
        }
        if !v
            .iter()
            .any(|&j: &usize| fb.bits[j].field == b.field && fb.bits[j].value == b.value)
        {
            v.push(i);
        }
    }
    v
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

/// 8.2.1 / 8.2.2 (and 8.6.6): a bit error in every field the IUT drives (base and
/// extended; dominant identifier bits forced recessive, control, data and CRC bits
/// of both values, CRC delimiter, ACK delimiter, EOF): error flag from the next
/// bit, TEC + 8 at the bit, then a successful retransmission.
pub fn iso_8_2_1_bit_error_every_field(iut: &Iut) {
    for f in [
        base(0x2B5, &[0x0F, 0xF0]),
        ext(0x0AB5_3C21, &[0x5A]),
        remote(0x1C3, false, 3),
    ] {
        let fb = FrameBits::new(&f);
        let pos = one_bit_per_field(&fb);
        let fields: Vec<Field> = pos.iter().map(|&p| fb.bits[p].field).collect();
        for want in [
            Field::IdA,
            Field::Dlc,
            Field::Crc,
            Field::CrcDelim,
            Field::Eof,
        ] {
            assert!(fields.contains(&want));
        }
        corrupt_each(iut, &f, &pos);
    }
}

/// The recessive stuff bit after the IDE bit of a base frame: ISO 11898-1 puts
/// it in the control field (rule c exception 2 does not apply: TEC + 8), the
/// contract in arbitration (no change). Played only by
/// [`strict_8_6_19_base_ide_stuff_bit`].
fn base_ide_stuff_bit(fb: &FrameBits, p: usize) -> bool {
    let b = fb.bits[p];
    b.stuff && b.value && b.field == Field::Ide && !fb.frame.ide
}

fn stuff_bits_tx(iut: &Iut, frames: &[Frame]) {
    for f in frames {
        let fb = FrameBits::new(f);
        let pos: Vec<usize> = fb
            .stuff_positions()
            .into_iter()
            .filter(|&p| !base_ide_stuff_bit(&fb, p))
            .collect();
        corrupt_each(iut, f, &pos);
    }
}

/// Known deviation (see docs/conformance.md): the recessive stuff bit after the
/// IDE bit of a base frame, read dominant, is a stuff error outside the
/// arbitration field (ISO 11898-1:2015 10.4.2.3, 12.1.4.2 c): TEC + 8.
pub fn strict_8_6_19_base_ide_stuff_bit(iut: &Iut) {
    // ID ...000, RTR 0, IDE 0: five dominant bits, then a recessive stuff bit.
    let f = base(0x118, &[0x19]);
    let fb = FrameBits::new(&f);
    let p = fb.pos(Field::Ide, 0) + 1;
    assert!(base_ide_stuff_bit(&fb, p));
    corrupt_each(iut, &f, &[p]);
}

/// Known deviation (see docs/conformance.md): a node with a frame pending that
/// takes a dominant 3rd intermission bit as SOF starts "with the first bit of its
/// identifier without first transmitting a SOF bit" (ISO 11898-1:2015 10.4.6.3):
/// its `tx` stays recessive during that SOF.
pub fn strict_8_1_8_no_sof_bit_when_joining(iut: &Iut) {
    let (mut lt, _) = start(iut);
    let theirs = FrameBits::new(&base(0x600, &[6]));
    let mine = FrameBits::new(&base(0x181, &[8, 1, 8]));
    let mut s = Script::new();
    s.receive(&theirs, 0..theirs.len(), true);
    s.request_at(10, mine.frame);
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.push(Lt::D, Some(true), "Intermission 3 dominant");
    s.transmit(&mine, 1..mine.len(), true, 0);
    s.intermission();
    lt.run(&s);
}

/// 8.2.3 (and 8.6.19): every stuff bit of base frames covering every field
/// inverted: error flag from the next bit; TEC + 8, except a recessive stuff bit
/// of the arbitration field read dominant (rule c exception 2: unchanged).
pub fn iso_8_2_3_stuff_bit_errors_base(iut: &Iut) {
    stuff_bits_tx(iut, &stuffing_frames(false));
}

/// 8.2.4: as 8.2.3 on extended frames.
pub fn iso_8_2_4_stuff_bit_errors_extended(iut: &Iut) {
    stuff_bits_tx(iut, &stuffing_frames(true));
}

/// 8.2.8 (classical adaptation; ISO 16845-1 runs it on a 64-byte FD frame): as
/// 8.2.3 on base frames ID 555h, DLC 8, with the ISO data patterns.
pub fn iso_8_2_8_stuff_bit_errors_data_patterns(iut: &Iut) {
    stuff_bits_tx(iut, &data_pattern_frames());
}

/// 8.2.5 (and 8.6.7): a dominant CRC delimiter, ACK delimiter and EOF bits 1..=7
/// are errors for the transmitter: flag from the next bit, TEC + 8.
pub fn iso_8_2_5_form_errors_tx(iut: &Iut) {
    let f = base(0x5A5, &[0xA5, 0x5A]);
    let fb = FrameBits::new(&f);
    let mut pos = vec![fb.crc_delim(), fb.pos(Field::AckDelim, 0)];
    pos.extend((1..=7).map(|n| fb.eof(n)));
    corrupt_each(iut, &f, &pos);
}

/// 8.2.6 (and 8.6.8): ACK error: recessive ACK slot, error flag from the ACK
/// delimiter, TEC + 8 at the ACK slot while error active.
pub fn iso_8_2_6_ack_error(iut: &Iut) {
    iso_8_6_8_ack_error_active(iut);
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

/// Bit error at r0, then the script of the error frame with `dominant_after`
/// dominant bits after the flag.
fn tx_error_with_dominant_after(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    dominant_after: usize,
    sof_within: u32,
) -> Run {
    let r0 = fb.pos(Field::R0, 0);
    let mut s = Script::new();
    s.transmit(fb, 0..r0, false, sof_within);
    s.push(Lt::ForceR, Some(false), "r0 forced recessive");
    exp.tec_add(8);
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

/// 8.3.1 (and 8.6.14): after its active error flag the transmitter tolerates 1..=7
/// dominant bits; TEC + 8 for the error only (no rule b for transmitters).
pub fn iso_8_3_1_dominant_bits_after_flag_tx(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x031, &[3, 1]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for n in 1..=7 {
        lt.set_context(format!("{n} dominant bits after the flag"));
        tx_error_with_dominant_after(&mut lt, &mut exp, &fb, n, if n == 1 { 2 } else { 0 });
        assert_eq!(exp.tec, 8 * n as u16);
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.3.2: after its error frame, the IUT (frame pending) takes a dominant 3rd
/// intermission bit as SOF and sends its identifier from the next bit.
pub fn iso_8_3_2_sof_at_intermission_bit_3_tx(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x332, &[0x33]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    let r0 = fb.pos(Field::R0, 0);
    let mut s = Script::new();
    s.transmit(&fb, 0..r0, false, 2);
    s.push(Lt::ForceR, Some(false), "r0 forced recessive");
    exp.tec_add(8);
    s.error_flag(true).error_delim();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.push(Lt::D, None, "Intermission 3 dominant");
    s.transmit(&fb, 1..fb.len(), true, 0).intermission();
    exp.tx_ok();
    let run = lt.run(&s);
    assert_eq!(run.tx_done_bits().len(), 1, "{}", lt.name());
    lt.check(&exp, "after the frame");
}

/// Bit error at r0, then the IUT's active flag bit `b` forced recessive: rule d
/// (TEC + 8), a new flag at the next bit.
fn tx_flag_bit_error(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    b: usize,
    sof_within: u32,
) -> Run {
    let r0 = fb.pos(Field::R0, 0);
    let mut s = Script::new();
    s.transmit(fb, 0..r0, false, sof_within);
    s.push(Lt::ForceR, Some(false), "r0 forced recessive");
    exp.tec_add(8);
    assert!(exp.active());
    s.repeat(b - 1, Lt::R, Some(false), "ErrFlag");
    s.push(
        Lt::ForceR,
        Some(false),
        format!("ErrFlag {b} forced recessive"),
    );
    exp.tec_add(8);
    s.error_flag(exp.active()).error_delim();
    interframe_tx(&mut s, exp);
    let run = lt.run(&s);
    let i = run.find(&format!("ErrFlag {b} forced recessive"));
    assert_eq!(
        run.recs[i].probes.tec,
        exp.tec,
        "{}: TEC + 8 at the bit error",
        lt.name()
    );
    assert_eq!(run.recs[i + 1].label, "ErrFlag 1");
    lt.check(exp, "after the bit error in the flag");
    run
}

/// 8.3.3 (and 8.6.1): a bit error in its own active error flag (bits 1, 3, 6)
/// restarts the flag; TEC + 8 + 8.
pub fn iso_8_3_3_bit_error_in_flag_tx(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = ext(0x0333_0333, &[3]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for (k, b) in [1, 3, 6].into_iter().enumerate() {
        tx_flag_bit_error(&mut lt, &mut exp, &fb, b, if k == 0 { 2 } else { 0 });
    }
    assert_eq!(exp.tec, 48);
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.6.1: the counter part of 8.3.3.
pub fn iso_8_6_1_tec_bit_error_in_active_flag(iut: &Iut) {
    iso_8_3_3_bit_error_in_flag_tx(iut);
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
    let r0 = fb.pos(Field::R0, 0);
    let mut s = Script::new();
    s.transmit(fb, 0..r0, false, sof_within);
    s.push(Lt::ForceR, Some(false), "r0 forced recessive");
    exp.tec_add(8);
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

/// 8.3.4 (and 8.6.9): form error in the error delimiter (bits 2..=7): a new flag
/// from the next bit, TEC + 8.
pub fn iso_8_3_4_form_error_in_delimiter_tx(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x344, &[]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for k in 2..=7 {
        lt.set_context(format!("delimiter bit {k}"));
        tx_delimiter_dominant(&mut lt, &mut exp, &fb, k, if k == 2 { 2 } else { 0 });
    }
    assert_eq!(exp.tec, 96);
    tx_ok(&mut lt, &mut exp, &fb, 0);
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

/// 8.4.1: a dominant intermission bit 1 or 2 after its own frame: overload flag at
/// the next bit; TEC - 1 for the frame only.
pub fn iso_8_4_1_overload_after_own_frame(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x441, &[4, 4, 1]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_ack_error(&mut lt, &mut exp, &fb, 2);
    for bit in [1, 2] {
        let mut s = own_frame_then_overload(&fb, bit, 6, 0);
        s.overload_delim().intermission();
        exp.tx_ok();
        let run = lt.run(&s);
        assert_eq!(run.tx_done_bits(), vec![fb.eof(7)]);
        lt.check(&exp, "after the overload frame");
        lt.request(f);
    }
    tx_ok(&mut lt, &mut exp, &fb, 2);
    assert_eq!(exp.tec, 5);
}

/// 8.4.2 (and 8.6.15, 8.6.16): a dominant 8th bit of its error delimiter or of its
/// overload delimiter starts an overload frame; no counter change.
pub fn iso_8_4_2_overload_at_delimiter_bit_8_tx(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = ext(0x0442_0442, &[0x42]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_delimiter_dominant(&mut lt, &mut exp, &fb, 8, 2);
    assert_eq!(exp.tec, 8);
    let mut s = own_frame_then_overload(&fb, 1, 6, 0);
    s.repeat(7, Lt::R, Some(true), "OvlDelim");
    s.push(Lt::D, Some(true), "OvlDelim 8 dominant");
    s.overload_flag().overload_delim().intermission();
    exp.tx_ok();
    lt.run(&s);
    lt.check(&exp, "TEC - 1 for the frame only");
}

/// 8.4.3: after an overload frame, a dominant 3rd intermission bit is the SOF of
/// the IUT's pending frame: it sends its identifier from the next bit.
pub fn iso_8_4_3_dominant_intermission_3_is_sof(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let a = FrameBits::new(&base(0x443, &[1]));
    let b = FrameBits::new(&base(0x0B0, &[2, 3]));
    lt.request(a.frame);
    let mut s = own_frame_then_overload(&a, 1, 6, 2);
    let i = s.len() - 6;
    s.request_at(i, b.frame);
    s.overload_delim();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.push(Lt::D, None, "Intermission 3 dominant");
    s.transmit(&b, 1..b.len(), true, 0).intermission();
    let run = lt.run(&s);
    exp.tx_ok();
    exp.tx_ok();
    assert_eq!(run.tx_done_bits().len(), 2, "{}", lt.name());
    lt.check(&exp, "after both frames");
}

/// 8.4.4 (and 8.6.2): a bit error in its overload flag (bits 1, 3, 6) after its
/// own frame: error flag from the next bit, TEC + 8 (rule d).
pub fn iso_8_4_4_bit_error_in_overload_flag_tx(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x444, &[0x44]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_ack_error(&mut lt, &mut exp, &fb, 2);
    let mut within = 0;
    for b in [1usize, 3, 6] {
        lt.set_context(format!("overload flag bit {b}"));
        let mut s = own_frame_then_overload(&fb, 1, b - 1, within);
        s.push(
            Lt::ForceR,
            Some(false),
            format!("OvlFlag {b} forced recessive"),
        );
        exp.tx_ok();
        exp.tec_add(8);
        s.error_flag(exp.active()).error_delim();
        interframe_tx(&mut s, &exp);
        let run = lt.run(&s);
        let i = run.find(&format!("OvlFlag {b} forced recessive"));
        assert_eq!(run.recs[i].probes.tec, exp.tec, "TEC + 8 at the bit error");
        lt.check(&exp, "after the bit error in the overload flag");
        lt.request(f);
        within = 2;
    }
    assert_eq!(exp.tec, 8 + 3 * 7);
}

/// 8.6.2: the counter part of 8.4.4.
pub fn iso_8_6_2_tec_bit_error_in_overload_flag(iut: &Iut) {
    iso_8_4_4_bit_error_in_overload_flag_tx(iut);
}

/// 8.4.5 (and 8.6.10): form error in its overload delimiter (bits 2..=7) after its
/// own frame: error flag from the next bit, TEC + 8.
pub fn iso_8_4_5_form_error_in_overload_delimiter_tx(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x445, &[]);
    let fb = FrameBits::new(&f);
    for k in 2..=7 {
        lt.set_context(format!("overload delimiter bit {k}"));
        lt.request(f);
        let mut s = own_frame_then_overload(&fb, 2, 6, 2);
        s.repeat(k - 1, Lt::R, Some(true), "OvlDelim");
        s.push(Lt::D, Some(true), format!("OvlDelim {k} dominant"));
        exp.tx_ok();
        exp.tec_add(8);
        s.error_flag(exp.active()).error_delim();
        interframe_tx(&mut s, &exp);
        lt.run(&s);
        lt.check(&exp, "after the form error in the overload delimiter");
    }
    assert_eq!(exp.tec, 43);
}

/// 8.5.1: an error-passive transmitter's passive flag overlapped by another node's
/// active flag (starting 0..=5 bits late) ends after 6 equal bits; TEC + 8 once.
pub fn iso_8_5_1_passive_flag_with_active_flag_from_others(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x551, &[5, 5, 1]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for late in 0..=5usize {
        lt.set_context(format!("active flag {late} bits late"));
        let r0 = fb.pos(Field::R0, 0);
        let mut s = Script::new();
        s.transmit(&fb, 0..r0, false, if late == 0 { 2 } else { 0 });
        s.push(Lt::ForceR, Some(false), "r0 forced recessive");
        exp.tec_add(8);
        s.repeat(late, Lt::R, Some(true), "PassiveFlag R");
        s.repeat(6, Lt::D, Some(true), "Active flag of others");
        s.error_delim();
        interframe_tx(&mut s, &exp);
        let run = lt.run(&s);
        assert_eq!(
            run.at("Active flag of others 6").probes.field,
            field::ERROR_DELIM
        );
        assert_eq!(
            run.at("Active flag of others 5").probes.field,
            field::ERROR_FLAG
        );
        lt.check(&exp, "TEC + 8 once");
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// Passive IUT (frame pending): bit error at r0, passive flag, delimiter,
/// intermission bits 1 and 2; returns the script (the caller continues at
/// intermission bit 3).
fn passive_error_until_intermission_3(
    exp: &mut Expected,
    fb: &FrameBits,
    sof_within: u32,
) -> Script {
    let r0 = fb.pos(Field::R0, 0);
    let mut s = Script::new();
    s.transmit(fb, 0..r0, false, sof_within);
    s.push(Lt::ForceR, Some(false), "r0 forced recessive");
    exp.tec_add(8);
    assert!(!exp.active());
    s.passive_flag("PassiveFlag").error_delim();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s
}

/// 8.5.2: an error-passive transmitter receives a frame whose SOF is the 3rd
/// intermission bit after its error frame (it does not join: suspend is due),
/// then sends its frame without suspend.
pub fn iso_8_5_2_passive_receives_after_error_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let mine = FrameBits::new(&base(0x552, &[2]));
    let theirs = FrameBits::new(&base(0x7FF, &[0xFF]));
    lt.request(mine.frame);
    let mut s = passive_error_until_intermission_3(&mut exp, &mine, 2);
    s.receive(&theirs, 0..theirs.len(), true).intermission();
    s.transmit(&mine, 0..mine.len(), true, 0);
    exp.rx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(lt.received, vec![theirs.frame]);
    assert_eq!(run.tx_done_bits().len(), 1);
    lt.check(&exp, "after both frames");
}

/// 8.5.3: after its passive flag, 1..=7 dominant bits are tolerated; TEC + 8 per
/// error only.
pub fn iso_8_5_3_passive_dominant_bits_in_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x553, &[]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for n in 1..=7 {
        lt.set_context(format!("{n} dominant bits after the passive flag"));
        let before = exp.tec;
        tx_error_with_dominant_after(&mut lt, &mut exp, &fb, n, if n == 1 { 2 } else { 0 });
        assert_eq!(exp.tec, before + 8);
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.4: an error-passive transmitter receives a frame whose SOF falls into its
/// suspend transmission (suspend bit 4), then sends its own frame.
pub fn iso_8_5_4_passive_receives_during_suspend(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let mine = FrameBits::new(&base(0x554, &[4]));
    let theirs = FrameBits::new(&ext(0x1FFF_FFFF, &[]));
    lt.request(mine.frame);
    let mut s = passive_error_until_intermission_3(&mut exp, &mine, 2);
    s.push(Lt::R, Some(true), "Intermission 3");
    s.repeat(3, Lt::R, Some(true), "Suspend");
    s.receive(&theirs, 0..theirs.len(), true).intermission();
    s.transmit(&mine, 0..mine.len(), true, 0);
    exp.rx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    lt.run(&s);
    assert_eq!(lt.received, vec![theirs.frame]);
    lt.check(&exp, "after both frames");
}

/// 8.5.5: an error-passive transmitter waits exactly 8 suspend bits after the
/// intermission of its error frame before its SOF.
pub fn iso_8_5_5_suspend_after_error_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x555, &[5]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    tx_bit_error(&mut lt, &mut exp, &fb, 2);
    let run = tx_ok(&mut lt, &mut exp, &fb, 0);
    assert!(run.recs[0].waited.unwrap() < lt.cpb());
}

/// 8.5.6: suspend transmission after an overload frame that follows its own frame.
pub fn iso_8_5_6_suspend_after_overload_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 136);
    let a = FrameBits::new(&base(0x556, &[6]));
    let b = FrameBits::new(&base(0x0B6, &[]));
    lt.request(a.frame);
    let mut s = own_frame_then_overload(&a, 1, 6, 2);
    let i = s.len() - 6;
    s.request_at(i, b.frame);
    s.overload_delim().intermission().suspend();
    s.transmit(&b, 0..b.len(), true, 0);
    exp.tx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(run.tx_done_bits().len(), 2);
    lt.check(&exp, "after both frames");
}

/// 8.5.7: suspend transmission after its own successful frame.
pub fn iso_8_5_7_suspend_after_own_frame(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 136);
    let a = FrameBits::new(&ext(0x0557_0557, &[7]));
    let b = FrameBits::new(&base(0x0B7, &[7, 7]));
    lt.request(a.frame);
    let mut s = Script::new();
    s.transmit(&a, 0..a.len(), true, 2);
    s.intermission().suspend();
    let i = s.len() - 11;
    s.request_at(i, b.frame);
    s.transmit(&b, 0..b.len(), true, 0);
    exp.tx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    let run = lt.run(&s);
    assert_eq!(run.tx_done_bits().len(), 2);
    lt.check(&exp, "after both frames");
}

/// 8.5.8: an error-passive node that lost arbitration does not suspend: its SOF
/// follows the intermission after the winner's frame.
pub fn iso_8_5_8_no_suspend_after_arbitration_lost(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    lose_arbitration(&mut lt, &mut exp, &base(0x558, &[8]), &base(0x550, &[0]));
}

/// 8.5.9 / 8.5.10: an error-passive node never transmits without its own SOF: a
/// dominant 3rd intermission bit after its error frame, or after its own frame,
/// is another node's SOF, which it receives.
pub fn iso_8_5_9_passive_never_transmits_without_sof(iut: &Iut) {
    // After its error frame.
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let mine = FrameBits::new(&base(0x559, &[9]));
    let theirs = FrameBits::new(&base(0x123, &[1]));
    lt.request(mine.frame);
    let mut s = passive_error_until_intermission_3(&mut exp, &mine, 2);
    s.receive(&theirs, 0..theirs.len(), true).intermission();
    s.transmit(&mine, 0..mine.len(), true, 0);
    exp.rx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    lt.run(&s);
    assert_eq!(lt.received, vec![theirs.frame]);
    // After its own frame (a second frame pending).
    let a = FrameBits::new(&base(0x510, &[1, 0]));
    lt.request(a.frame);
    let mut s = Script::new();
    s.transmit(&a, 0..a.len(), true, 2);
    let i = s.len();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.request_at(i, mine.frame);
    s.receive(&theirs, 0..theirs.len(), true).intermission();
    s.transmit(&mine, 0..mine.len(), true, 0);
    exp.tx_ok();
    exp.rx_ok();
    exp.tx_ok();
    interframe_tx(&mut s, &exp);
    lt.run(&s);
    assert_eq!(lt.received, vec![theirs.frame, theirs.frame]);
    lt.check(&exp, "after the frames");
}

/// 8.5.11: bus-off at TEC > 255; the IUT stays bus-off (recessive, no flag, no
/// ACK for a frame on the bus, which it does not deliver) until 128 occurrences of
/// 11 consecutive recessive bits (a dominant bit restarts the current run), then
/// is error active with TEC = REC = 0 and sends its pending frame.
pub fn iso_8_5_11_bus_off_recovery(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x5B0, &[0xB0]);
    let fb = tec_to(&mut lt, &mut exp, &f, 256);
    assert_eq!(lt.probes().err_state, state::BUS_OFF);
    assert!(lt.probes().tec > 255);
    // Bus after the bit that made the IUT bus-off: the 14 recessive bits of the
    // procedure, 50 more, another node's frame, then recessive bits up to the
    // 128th occurrence of 11 consecutive recessive bits, counted here.
    let other = FrameBits::new(&base(0x001, &[0x00, 0x00]));
    let mut s = Script::new();
    s.repeat(50, Lt::R, Some(true), "BusOff A");
    for i in 0..other.len() {
        s.push(
            Lt::from_value(other.bits[i].value),
            Some(true),
            other.name(i),
        );
    }
    let mut bus: Vec<bool> = vec![true; 14];
    bus.extend(s.bits.iter().map(|b| b.drive == Lt::R));
    let (mut run, mut occurrences) = (0, 0);
    for &b in &bus {
        run = if b { run + 1 } else { 0 };
        if run == 11 {
            run = 0;
            occurrences += 1;
        }
    }
    assert!(occurrences < 128);
    while occurrences < 128 {
        s.push(Lt::R, Some(true), "BusOff B");
        run += 1;
        if run == 11 {
            run = 0;
            occurrences += 1;
        }
    }
    let run = lt.run(&s);
    for (i, r) in run.recs.iter().enumerate() {
        let want = if i + 1 < run.recs.len() {
            state::BUS_OFF
        } else {
            state::ACTIVE
        };
        assert_eq!(
            r.probes.err_state,
            want,
            "{}: error state at bus-off bit {} ({})",
            lt.name(),
            i,
            r.label
        );
    }
    assert!(
        lt.received.is_empty(),
        "{}: no frame while bus-off",
        lt.name()
    );
    exp = Expected::default();
    lt.check(&exp, "after the recovery");
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.12: an error-passive transmitter's passive flag completes only after 6
/// equal consecutive bits.
pub fn iso_8_5_12_passive_flag_tx_six_equal_bits(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x512, &[0x12]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for (k, p) in ["RRRRRR", "DDDDDD", "RRDRRRRRR", "DRRRRRDDDDDD"]
        .into_iter()
        .enumerate()
    {
        lt.set_context(format!("bits during the passive flag: {p}"));
        let r0 = fb.pos(Field::R0, 0);
        let mut s = Script::new();
        s.transmit(&fb, 0..r0, false, if k == 0 { 2 } else { 0 });
        s.push(Lt::ForceR, Some(false), "r0 forced recessive");
        exp.tec_add(8);
        for (i, c) in p.chars().enumerate() {
            let d = if c == 'D' { Lt::D } else { Lt::R };
            s.push(d, Some(true), format!("PassiveFlag {}", i + 1));
        }
        s.error_delim();
        interframe_tx(&mut s, &exp);
        let run = lt.run(&s);
        let first = run.find("PassiveFlag 1");
        let n = p.len();
        assert_eq!(run.recs[first + n - 2].probes.field, field::ERROR_FLAG);
        assert_eq!(run.recs[first + n - 1].probes.field, field::ERROR_DELIM);
        lt.check(&exp, "TEC + 8 per error");
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.13: form error in the delimiter after its passive flag: TEC + 8, a new
/// passive flag.
pub fn iso_8_5_13_passive_form_error_in_delimiter_tx(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x513, &[]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for (i, k) in [2, 4, 7].into_iter().enumerate() {
        tx_delimiter_dominant(&mut lt, &mut exp, &fb, k, if i == 0 { 2 } else { 0 });
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.14: an error-passive transmitter retransmits at most 31 bit times after the
/// error: passive flag (6..=12 bits with another node's active flag starting 0..=6
/// bits late), 8 delimiter, 3 intermission and 8 suspend bits; the SOF comes
/// exactly then.
pub fn iso_8_5_14_retransmission_within_31_bits(iut: &Iut) {
    let (mut lt, mut exp) = passive_transmitter(iut, 128);
    let f = base(0x514, &[0x14]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    for late in 0..=6usize {
        lt.set_context(format!("active flag {late} bits late"));
        let r0 = fb.pos(Field::R0, 0);
        let mut s = Script::new();
        s.transmit(&fb, 0..r0, false, if late == 0 { 2 } else { 0 });
        s.push(Lt::ForceR, Some(false), "r0 forced recessive");
        exp.tec_add(8);
        s.repeat(late, Lt::R, Some(true), "PassiveFlag R");
        s.repeat(6, Lt::D, Some(true), "Active flag of others");
        s.error_delim();
        interframe_tx(&mut s, &exp);
        let n = s.len() - r0;
        let want = if late < 6 { late + 6 } else { 12 } + 8 + 3 + 8;
        assert_eq!(n - 1, want);
        assert!(want <= 31);
        lt.run(&s);
    }
    tx_ok(&mut lt, &mut exp, &fb, 0);
}

/// 8.5.15: the active flag of a transmitter forced recessive bit after bit (TEC 8,
/// 16, .., 128): at 128 the IUT turns passive, its flag is passive and the frame
/// starts again 6 + 8 + 3 + 8 bits after the last forced bit.
pub fn iso_8_5_15_turning_passive_retransmits_after_25_bits(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let f = base(0x515, &[0x80]);
    let fb = FrameBits::new(&f);
    lt.request(f);
    let r0 = fb.pos(Field::R0, 0);
    let mut s = Script::new();
    s.transmit(&fb, 0..r0, false, 2);
    s.push(Lt::ForceR, Some(false), "r0 forced recessive");
    exp.tec_add(8);
    for j in 1..=15 {
        s.push(Lt::ForceR, Some(false), format!("forced {j}"));
        exp.tec_add(8);
    }
    assert_eq!(exp.tec, 128);
    s.passive_flag("PassiveFlag").error_delim();
    interframe_tx(&mut s, &exp);
    let last = s.len();
    let run = lt.run(&s);
    assert_eq!(last - run.find("forced 15") - 1, 25);
    assert_eq!(run.at("forced 14").probes.err_state, state::ACTIVE);
    assert_eq!(run.at("forced 15").probes.err_state, state::PASSIVE);
    lt.check(&exp, "error passive");
    tx_ok(&mut lt, &mut exp, &fb, 0);
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
