//! ISO 16845-1 8.1: valid frame transmission and arbitration (frame formats,
//! arbitration lost at every bit, EOF, stuffing, SOF at intermission bit 3).

use super::*;

/// Sends every frame of `frames`: the IUT's `tx` equals the tester's encoding bit
/// by bit, `tx_done` at EOF bit 7, TEC stays 0; then every third one again on a
/// timing with a prescaler (brp 1), and one at 10 kbit/s from 100 MHz (brp 499).
fn send_all(iut: &Iut, frames: &[Frame]) {
    let (mut lt, mut exp) = start(iut);
    for f in frames {
        lt.set_context(format!("{f}"));
        send_ok(&mut lt, &mut exp, f);
    }
    assert_eq!(lt.tx_done, frames.len() as u32);
    let mut lt = LowerTester::start(iut, timing_brp());
    for f in frames.iter().step_by(3) {
        lt.set_context(format!("brp 1: {f}"));
        send_ok(&mut lt, &mut exp, f);
    }
    // one frame at 10 kbit/s from 100 MHz (brp 499: the prescaler's high bits)
    let mut lt = LowerTester::start(iut, timing_slow());
    let f = &frames[13];
    lt.set_context(format!("brp 499: {f}"));
    send_ok(&mut lt, &mut exp, f);
    assert_eq!(lt.tx_done, 1, "{}: brp 499", lt.name());
    assert_eq!(exp.tec, 0);
}

/// 8.1.1: base data frames with the ISO identifiers (555h, 2AAh, 000h, 7FFh and
/// one more), each with every DLC 0..=8, base remote frames, and DLC 9..=15 (8
/// bytes sent): the IUT's `tx` equals the tester's encoding bit by bit, `tx_done`
/// at EOF bit 7, TEC stays 0; the same with a prescaler (brp 1).
pub fn iso_8_1_1_base_frames(iut: &Iut) {
    let mut frames = iso_id_frames(false);
    for dlc in 9..=15u8 {
        frames.push(Frame {
            dlc,
            ..base(0x0D0 + dlc as u32, &[dlc; 8])
        });
    }
    send_all(iut, &frames);
}

/// 8.1.2: as 8.1.1 with extended frames (identifiers 15555555h, 0AAAAAAAh,
/// 00000000h, 1FFFFFFFh and one more, every DLC 0..=8, remote frames).
pub fn iso_8_1_2_extended_frames(iut: &Iut) {
    let frames = iso_id_frames(true);
    assert!(frames.iter().all(|f| f.ide));
    send_all(iut, &frames);
}

/// Loses arbitration in every case of `cases` (IUT frame, winner): `arb_lost`
/// at the first differing bit, recessive afterwards, the winner received and
/// acknowledged, then the IUT's frame sent right after the intermission. Returns
/// the fields where arbitration was lost.
fn lose_each(iut: &Iut, cases: &[(Frame, Frame)]) -> Vec<Field> {
    let (mut lt, mut exp) = start(iut);
    let mut fields = Vec::new();
    for (mine, theirs) in cases {
        lt.set_context(format!("{mine} against {theirs}"));
        let k = lose_arbitration(&mut lt, &mut exp, mine, theirs);
        fields.push(FrameBits::new(theirs).bits[k].field);
    }
    assert_eq!(lt.arb_lost, cases.len() as u32);
    assert_eq!(lt.tx_done, cases.len() as u32);
    fields
}

/// 8.1.3: arbitration lost in a base frame at every recessive identifier bit (ID
/// 7EFh: the 10 recessive bits; ID 010h: its recessive bit; ID 7FFh: all 11) and
/// at RTR (remote frame against a data frame).
pub fn iso_8_1_3_arbitration_lost_base(iut: &Iut) {
    let mut cases: Vec<(Frame, Frame)> = Vec::new();
    for id in [0x7EFu32, 0x010, 0x7FF] {
        for i in 0..11 {
            if id >> i & 1 == 1 {
                cases.push((base(id, &[0x11]), base(id & !(1 << i), &[0x22])));
            }
        }
    }
    cases.push((remote(0x555, false, 1), base(0x555, &[1])));
    let fields = lose_each(iut, &cases);
    assert_eq!(fields.iter().filter(|&&f| f == Field::IdA).count(), 22);
    assert!(fields.contains(&Field::SrrRtr));
}

/// 8.1.4: arbitration lost in an extended frame at every recessive identifier bit
/// (ID 1FBFFFFFh: 28 bits; 00400000h: its recessive bit; 1FFFFFFFh: all 29), at
/// SRR (against a base data frame), at IDE (against a base remote frame) and at
/// the extended RTR (remote against data).
pub fn iso_8_1_4_arbitration_lost_extended(iut: &Iut) {
    let mut cases: Vec<(Frame, Frame)> = Vec::new();
    for id in [0x1FBF_FFFFu32, 0x0040_0000, 0x1FFF_FFFF] {
        for i in 0..29 {
            if id >> i & 1 == 1 {
                cases.push((ext(id, &[0x33]), ext(id & !(1 << i), &[0x44])));
            }
        }
    }
    cases.push((ext(0x0040_0000, &[]), base(0x0040_0000 >> 18, &[])));
    cases.push((ext(0x0040_0000, &[]), remote(0x0040_0000 >> 18, false, 0)));
    cases.push((remote(0x0A0A_0A0A, true, 2), ext(0x0A0A_0A0A, &[1, 2])));
    let fields = lose_each(iut, &cases);
    for f in [
        Field::IdA,
        Field::SrrRtr,
        Field::Ide,
        Field::IdB,
        Field::RtrExt,
    ] {
        assert!(fields.contains(&f), "no arbitration loss in {f:?}");
    }
    assert_eq!(
        fields
            .iter()
            .filter(|&&f| matches!(f, Field::IdA | Field::IdB))
            .count(),
        28 + 1 + 29
    );
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

/// The ISO 16845-1 8.1.6 (base) and 8.1.7 (extended) stuffing frames and the
/// tester's own frames with stuff bits after every field that can carry one:
/// the IUT's `tx` carries every stuff bit (checked bit by bit).
fn send_stuffing(iut: &Iut, ide: bool) {
    let (mut lt, mut exp) = start(iut);
    let one = |b: u8| [b];
    let mut e1 = [0xE1; 8];
    e1[0] = 0x01;
    let mut frames: Vec<Frame> = if ide {
        vec![
            ext(0x07C3_0F0F, &[0x3C; 8]),
            ext(0x07C0_F0F0, &one(0x00)),
            ext(0x1FB8_0000, &one(0xA0)),
        ]
    } else {
        vec![
            base(0x078, &e1),
            base(0x41F, &one(0x00)),
            base(0x47F, &one(0x1F)),
            base(0x758, &[]),
            base(0x777, &one(0x1F)),
            remote(0x7EF, false, 2),
        ]
    };
    frames.extend(stuffing_frames(ide));
    let mut sites = Vec::new();
    for f in &frames {
        lt.set_context(format!("{f}"));
        sites.extend(FrameBits::new(f).stuff_sites());
        send_ok(&mut lt, &mut exp, f);
    }
    for w in stuff_site_set(ide) {
        assert!(sites.contains(&w), "no stuff bit at {w:?}");
    }
}

/// 8.1.6: base frames with critical stuffing (the ISO table: 078h, 41Fh, 47Fh,
/// 758h, 777h, 7EFh remote; and stuff bits after every field): sent bit-exact.
pub fn iso_8_1_6_stuffing_base(iut: &Iut) {
    send_stuffing(iut, false);
}

/// 8.1.7: as 8.1.6 with extended frames (ISO table: 07C30F0Fh, 07C0F0F0h,
/// 1FB80000h).
pub fn iso_8_1_7_stuffing_extended(iut: &Iut) {
    send_stuffing(iut, true);
}

/// 8.1.8: with a frame pending, the IUT takes a dominant 3rd intermission bit
/// as SOF and sends its identifier from the next bit (no SOF of its own).
/// ISO 11898-1:2015 10.4.6.3: the node takes the dominant 3rd intermission bit as
/// its SOF and starts "with the first bit of its identifier without first
/// transmitting an SOF bit": `tx` stays recessive during that bit (checked).
pub fn iso_8_1_8_sof_at_intermission_bit_3(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let theirs = FrameBits::new(&base(0x600, &[6]));
    let mine = FrameBits::new(&base(0x181, &[8, 1, 8]));
    let mut s = Script::new();
    s.receive(&theirs, 0..theirs.len(), true);
    s.request_at(10, mine.frame);
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.push(Lt::D, Some(true), "Intermission 3 dominant");
    s.transmit(&mine, 1..mine.len(), true, 0);
    s.intermission();
    let run = lt.run(&s);
    exp.rx_ok();
    exp.tx_ok();
    assert_eq!(run.tx_done_bits().len(), 1, "{}", lt.name());
    assert_eq!(lt.received, vec![theirs.frame]);
    lt.check(&exp, "after both frames");
}
