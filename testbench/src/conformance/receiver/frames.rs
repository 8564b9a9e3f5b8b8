//! ISO 16845-1 7.1: valid frame reception (frame formats, arbitration lost,
//! reserved bits, DLC above 8, back-to-back frames, stuffing, EOF bit 6/7).

use super::*;

/// 7.1.1 / 7.1.2: base and extended data and remote frames, every DLC 0..=8, a
/// spread of identifiers: ACK in the ACK slot only, `rx_valid` at EOF bit 6 with
/// the frame, REC unchanged; the same on a timing with a prescaler (brp 1).
pub fn iso_7_1_1_base_and_extended_frames(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for f in spread_frames() {
        receive_ok(&mut lt, &mut exp, &FrameBits::new(&f));
    }
    assert_eq!(lt.received.len(), spread_frames().len());
    let mut lt = LowerTester::start(iut, timing_brp());
    let mut exp = Expected::default();
    for f in spread_frames().iter().step_by(3) {
        receive_ok(&mut lt, &mut exp, &FrameBits::new(f));
    }
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

/// 7.1.4 / 7.1.5: either value of r0, r1 and SRR is accepted (frame delivered,
/// ACK sent, no error).
pub fn iso_7_1_4_reserved_bits_and_srr(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let o = Options::default();
    let cases = [
        (base(0x3A5, &[0x11]), Options { r0: true, ..o }),
        (ext(0x0ABC_DEF0, &[0x22, 0x33]), Options { r0: true, ..o }),
        (ext(0x0ABC_DEF0, &[0x22]), Options { r1: true, ..o }),
        (
            ext(0x1555_0000, &[]),
            Options {
                r1: true,
                r0: true,
                ..o
            },
        ),
        (ext(0x0000_1234, &[0xFF; 8]), Options { srr: false, ..o }),
        (
            remote(0x1FFF_0000, true, 3),
            Options {
                srr: false,
                r1: true,
                r0: true,
                ..o
            },
        ),
    ];
    for (f, opt) in cases {
        lt.set_context(format!("{f} {opt:?}"));
        receive_ok(&mut lt, &mut exp, &FrameBits::with(&f, opt));
    }
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

/// 7.1.10 / 7.1.11: frames whose stuff bits follow every field that can carry one
/// (base and extended, including the stuff bit after the last CRC bit) are
/// received without error.
pub fn iso_7_1_10_stuffing_every_field(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for ide in [false, true] {
        for f in stuffing_frames(ide) {
            receive_ok(&mut lt, &mut exp, &FrameBits::new(&f));
        }
    }
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
