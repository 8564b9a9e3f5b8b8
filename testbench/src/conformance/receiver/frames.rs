//! ISO 16845-1 7.1: valid frame reception (frame formats, arbitration lost,
//! reserved bits, DLC above 8, back-to-back frames, stuffing, EOF bit 6/7).

use super::*;

/// Receives every frame of `frames` (ACK in the ACK slot only, `rx_valid` at EOF
/// bit 6 with the frame, REC unchanged at 0), then every third one again on a
/// timing with a prescaler (brp 1).
fn receive_all(iut: &Iut, frames: &[Frame]) {
    let (mut lt, mut exp) = start(iut);
    for f in frames {
        lt.set_context(format!("{f}"));
        receive_ok(&mut lt, &mut exp, &FrameBits::new(f));
    }
    let want: Vec<Frame> = frames.iter().map(|f| f.normalized()).collect();
    assert_eq!(lt.received, want, "{}: frames delivered", lt.name());
    let mut lt = LowerTester::start(iut, timing_brp());
    let mut exp = Expected::default();
    for f in frames.iter().step_by(3) {
        lt.set_context(format!("brp 1: {f}"));
        receive_ok(&mut lt, &mut exp, &FrameBits::new(f));
    }
    // one frame at 10 kbit/s from 100 MHz (brp 499: the prescaler's high bits)
    let mut lt = LowerTester::start(iut, timing_slow());
    let mut exp = Expected::default();
    let f = &frames[13];
    lt.set_context(format!("brp 499: {f}"));
    receive_ok(&mut lt, &mut exp, &FrameBits::new(f));
    assert_eq!(lt.received, vec![f.normalized()], "{}: brp 499", lt.name());
}

/// 7.1.1: base data frames with the ISO identifiers (555h, 2AAh, 000h, 7FFh and
/// one more), each with every DLC 0..=8, and base remote frames: ACK in the ACK
/// slot only, `rx_valid` at EOF bit 6 with the frame, REC unchanged; the same on a
/// timing with a prescaler (brp 1), and one frame at 10 kbit/s from 100 MHz (brp
/// 499).
pub fn iso_7_1_1_base_frames(iut: &Iut) {
    let frames = iso_id_frames(false);
    assert!(frames.iter().all(|f| !f.ide) && frames.len() == 49);
    receive_all(iut, &frames);
}

/// 7.1.2: as 7.1.1 with extended frames (identifiers 15555555h, 0AAAAAAAh,
/// 00000000h, 1FFFFFFFh and one more, every DLC 0..=8, remote frames).
pub fn iso_7_1_2_extended_frames(iut: &Iut) {
    let frames = iso_id_frames(true);
    assert!(frames.iter().all(|f| f.ide) && frames.len() == 49);
    receive_all(iut, &frames);
}

/// The IUT requests `mine`, the tester sends `theirs` from the same SOF; `theirs`
/// wins at the first bit where the two differ. Checks `arb_lost` at that bit, the
/// IUT recessive afterwards except its ACK, `theirs` delivered at EOF 6, and then
/// the IUT's retransmission right after the intermission (`tx_done`).
pub fn lose_arbitration(
    lt: &mut LowerTester,
    exp: &mut Expected,
    mine: &Frame,
    theirs: &Frame,
) -> usize {
    let (m, t) = (FrameBits::new(mine), FrameBits::new(theirs));
    let k = (0..t.len())
        .find(|&i| m.bits[i].value != t.bits[i].value)
        .expect("frames differ");
    assert!(
        m.bits[k].value && !t.bits[k].value && m.bits[k].field.is_arbitration(),
        "{mine} must lose to {theirs} in the arbitration field"
    );
    lt.request(*mine);
    let mut s = Script::new();
    for i in 0..t.len() {
        let expect = if i <= k {
            m.bits[i].value
        } else {
            t.bits[i].field != Field::AckSlot
        };
        s.push(Lt::from_value(t.bits[i].value), Some(expect), t.name(i));
    }
    s.bits[0].await_sof = Some(2);
    s.intermission();
    let run = lt.run(&s);
    assert_eq!(
        run.arb_lost_bits(),
        vec![k],
        "{}: arb_lost must pulse once, at bit {k} ({}) of {mine} against {theirs}",
        lt.name(),
        t.name(k)
    );
    assert_eq!(
        run.rx_valid_bits(),
        vec![t.eof(6)],
        "{}: rx_valid",
        lt.name()
    );
    assert_eq!(run.recs[t.eof(6)].rx_frame, Some(t.frame));
    let prior = exp.rec;
    exp.rx_ok();
    check_after_rx_ok(lt, exp, prior, "after losing arbitration");
    // Not suspended (it lost arbitration): its SOF follows the intermission.
    crate::conformance::procedures::tx_ok(lt, exp, &m, 0);
    k
}

/// 7.1.3: the IUT receives the frame that wins arbitration against its own
/// (lost at the last base identifier bit, at SRR against a base data frame, at
/// IDE against a base remote frame) and sends its frame afterwards.
pub fn iso_7_1_3_receives_while_losing_arbitration(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let cases = [
        (base(0x123, &[1, 2]), base(0x122, &[3])),
        (ext(0x1234_5678, &[9]), base(0x1234_5678 >> 18, &[7, 7])),
        (
            ext(0x1234_5678, &[]),
            Frame {
                rtr: true,
                ..base(0x1234_5678 >> 18, &[])
            },
        ),
        (base(0x7F0, &[0xAA; 8]), base(0x0F0, &[0x55; 3])),
    ];
    for (mine, theirs) in cases {
        lt.set_context(format!("{mine} against {theirs}"));
        lose_arbitration(&mut lt, &mut exp, &mine, &theirs);
    }
}

/// 7.1.4: a base frame whose r0 bit (the FDF position of ISO 11898-1:2015) is
/// recessive is accepted: ACK sent, frame delivered at EOF bit 6, no error (data
/// and remote frames, DLC 0, 1 and 8).
pub fn iso_7_1_4_base_r0_recessive(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let r0 = Options {
        r0: true,
        ..Options::default()
    };
    for f in [
        base(0x3A5, &[0x11]),
        base(0x000, &[]),
        base(0x7FF, &[0xFF; 8]),
        remote(0x2AA, false, 4),
    ] {
        lt.set_context(format!("{f} with r0 recessive"));
        let fb = FrameBits::with(&f, r0);
        assert!(fb.bits[fb.pos(Field::R0, 0)].value);
        receive_ok(&mut lt, &mut exp, &fb);
    }
    assert_eq!(lt.received.len(), 4);
}

/// 7.1.5: an extended frame with any non-nominal combination of SRR, r1 (the FDF
/// position) and r0 is accepted: the seven combinations of ISO 16845-1 (SRR, r0,
/// FDF) = 111, 110, 101, 011, 010, 001, 000, on data and remote frames.
pub fn iso_7_1_5_extended_srr_r1_r0(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let combos = [
        (true, true, true),
        (true, true, false),
        (true, false, true),
        (false, true, true),
        (false, true, false),
        (false, false, true),
        (false, false, false),
    ];
    for (k, (srr, r0, r1)) in combos.into_iter().enumerate() {
        let f = if k % 2 == 0 {
            ext(0x0ABC_DEF0 ^ k as u32, &[0x22, k as u8])
        } else {
            remote(0x1555_0000 | k as u32, true, 3)
        };
        let opt = Options {
            srr,
            r1,
            r0,
            crc_xor: 0,
        };
        lt.set_context(format!("{f} SRR {srr} r1 {r1} r0 {r0}"));
        let fb = FrameBits::with(&f, opt);
        let got = [Field::SrrRtr, Field::R1, Field::R0].map(|fl| fb.bits[fb.pos(fl, 0)].value);
        assert_eq!(got, [srr, r1, r0]);
        receive_ok(&mut lt, &mut exp, &fb);
    }
    assert_eq!(lt.received.len(), combos.len());
}

/// 7.1.8: DLC 9..=15 is accepted; 8 data bytes are transferred and the DLC is
/// passed as received.
pub fn iso_7_1_8_dlc_greater_than_8(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for dlc in 9..=15u8 {
        let f = Frame {
            id: 0x100 + dlc as u32,
            dlc,
            data: [dlc, 1, 2, 3, 4, 5, 6, 0xF0 | dlc],
            ..Frame::default()
        };
        let run = receive_ok(&mut lt, &mut exp, &FrameBits::new(&f));
        let got = run.recs.iter().find_map(|r| r.rx_frame).unwrap();
        assert_eq!((got.dlc, got.data), (dlc, f.data), "{}", lt.name());
    }
    let f = Frame {
        ide: true,
        id: 0x1F0F_0F0F,
        ..base(0, &[0xC3; 8])
    };
    let f = Frame { dlc: 15, ..f };
    receive_ok(&mut lt, &mut exp, &FrameBits::new(&f));
}

/// 7.1.9: frames back to back, each SOF right after the 3rd intermission bit.
pub fn iso_7_1_9_back_to_back_frames(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let frames = [
        base(0x001, &[1]),
        ext(0x1000_0000, &[2, 3]),
        remote(0x7FF, false, 8),
        base(0x000, &[]),
    ];
    for f in &frames {
        receive_ok(&mut lt, &mut exp, &FrameBits::new(f));
    }
    assert_eq!(
        lt.received,
        frames.iter().map(|f| f.normalized()).collect::<Vec<_>>()
    );
}

/// The classical frames of the ISO 16845-1 7.1.10 (base) and 7.1.11 (extended)
/// tables: identifier, the control bits (RTR, r1, r0, DLC) and the data, with the
/// reserved bits the table sets.
pub fn iso_stuffing_table(ide: bool) -> Vec<(Frame, Options)> {
    // (id, rtr, r1, r0, dlc, data)
    type Row = (u32, bool, bool, bool, u8, [u8; 8]);
    let mut e1 = [0xE1; 8];
    e1[0] = 0x01;
    let one = |b: u8| [b, 0, 0, 0, 0, 0, 0, 0];
    let rows: Vec<Row> = if ide {
        vec![
            (0x07C3_0F0F, false, false, false, 8, [0x3C; 8]),
            (0x07C0_F0F0, false, false, false, 1, one(0x00)),
            (0x01E3_1717, false, false, true, 15, [0x0F; 8]),
            (
                0x01E0_0FF0,
                false,
                true,
                true,
                12,
                [0x1F, 0x0F, 0xE0, 0xF0, 0x7F, 0xE0, 0xFF, 0x20],
            ),
            (0x1FB8_0000, false, false, false, 1, one(0xA0)),
            (0x00BC_540F, true, true, false, 0, [0; 8]),
            (0x155D_5557, true, true, true, 15, [0; 8]),
        ]
    } else {
        vec![
            (0x078, false, false, false, 8, e1),
            (0x41F, false, false, false, 1, one(0x00)),
            (0x707, false, false, true, 15, [0x0F; 8]),
            (0x360, false, false, true, 0, [0; 8]),
            (0x730, false, false, true, 0, [0; 8]),
            (0x47F, false, false, false, 1, one(0x1F)),
            (0x758, false, false, false, 0, [0; 8]),
            (0x777, false, false, false, 1, one(0x1F)),
            (0x7EF, true, false, false, 2, [0; 8]),
            (0x3EA, true, false, true, 15, [0; 8]),
        ]
    };
    rows.into_iter()
        .map(|(id, rtr, r1, r0, dlc, data)| {
            let f = Frame {
                id,
                ide,
                rtr,
                dlc,
                data: if rtr { [0; 8] } else { data },
            };
            let opt = Options {
                r1,
                r0,
                ..Options::default()
            };
            (f, opt)
        })
        .collect()
}

/// Receives the ISO 16845-1 stuffing table of the format and the tester's own
/// stuffing frames (stuff bits after every field that can carry one, including
/// the stuff bit after the last CRC bit): no error, every frame delivered.
fn receive_stuffing(iut: &Iut, ide: bool) {
    let (mut lt, mut exp) = start(iut);
    let mut frames: Vec<(Frame, Options)> = iso_stuffing_table(ide);
    frames.extend(
        stuffing_frames(ide)
            .into_iter()
            .map(|f| (f, Options::default())),
    );
    let mut sites = Vec::new();
    for (f, opt) in &frames {
        lt.set_context(format!("{f} {opt:?}"));
        let fb = FrameBits::with(f, *opt);
        sites.extend(fb.stuff_sites());
        receive_ok(&mut lt, &mut exp, &fb);
    }
    for w in stuff_site_set(ide) {
        assert!(sites.contains(&w), "no stuff bit at {w:?}");
    }
    assert_eq!(lt.received.len(), frames.len(), "{}", lt.name());
}

/// 7.1.10: base frames with critical stuffing: the ISO 16845-1 table (IDs 078h,
/// 41Fh, 707h, ..., with r0 and DLC values of the table) and frames whose stuff
/// bits follow every field that can carry one (including the stuff bit after the
/// last CRC bit) are received without error.
pub fn iso_7_1_10_stuffing_base(iut: &Iut) {
    receive_stuffing(iut, false);
}

/// 7.1.11: as 7.1.10 with extended frames (ISO table: 07C30F0Fh, 07C0F0F0h, ...,
/// with its SRR/r1/r0/DLC values).
pub fn iso_7_1_11_stuffing_extended(iut: &Iut) {
    receive_stuffing(iut, true);
}

/// A frame with a dominant EOF bit 7: delivered at EOF 6, then an overload flag
/// from the next bit, the overload delimiter and the intermission.
pub(super) fn eof7_overload_script(fb: &FrameBits) -> Script {
    let mut s = Script::new();
    s.receive(fb, 0..fb.eof(7), true);
    s.push(Lt::D, Some(true), "EOF 7 dominant");
    s.overload_flag().overload_delim().intermission();
    s
}

/// 7.1.12 (and 7.4.2, 7.6.16): the frame is valid at the last but one EOF bit;
/// a dominant last EOF bit starts an overload frame at the next bit and changes
/// no counter (REC 9 before: 8 after, rule h only).
pub fn iso_7_1_12_valid_at_eof6_overload_at_eof7(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x2C4, &[0xDE, 0xAD]));
    let run = lt.run(&eof7_overload_script(&fb));
    assert_eq!(run.rx_valid_bits(), vec![fb.eof(6)], "{}", lt.name());
    assert_eq!(run.recs[fb.eof(6)].rx_frame, Some(fb.frame));
    assert_eq!(run.recs[fb.eof(7)].probes.field, field::OVERLOAD_FLAG);
    exp.rx_ok();
    lt.check(&exp, "after the overload frame");
    assert_eq!(exp.rec, 8);
    // The next frame is received normally.
    receive_ok(&mut lt, &mut exp, &FrameBits::new(&base(0x2C5, &[])));
}
