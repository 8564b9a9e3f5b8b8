//! ISO 16845-1 8.1: valid frame transmission and arbitration (frame formats,
//! arbitration lost at every bit, EOF, stuffing, SOF at intermission bit 3).

use super::*;

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
