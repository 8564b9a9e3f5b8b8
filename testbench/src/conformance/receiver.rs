//! ISO 16845-1 items 7.1 to 7.6: the IUT as receiver (valid frames, error
//! detection, error and overload frames, the error-passive receiver, the receive
//! error counter). One public function per ISO 16845-1 item or item group, named
//! after it; each takes an IUT factory and panics on the first deviation.
//!
//! Expected counters follow ISO 11898-1:2015 12.1.4.2: a receiver detecting an
//! error REC + 1 (rule a); dominant first bit after its error flag + 8 (rule b);
//! bit error in its active error flag or overload flag + 8 (rule e); 8th
//! consecutive dominant bit after a flag (14th after an active error flag or an
//! overload flag) and every further 8th + 8 (rule f); successful reception (ACK
//! sent and read back) - 1, from above 127 to a value in 119..=127 (rule h).

use drcc_cosim::Frame;

use super::bits::{stuffing_frames, Field, FrameBits, Options};
use super::lower_tester::{field, state, Iut, LowerTester, Lt, Run, Script};
use super::procedures::{base, ext, rec_to, remote, rx_error, rx_error_frame, Expected};
use super::{timing, timing_brp};

fn start(iut: &Iut) -> (LowerTester, Expected) {
    (LowerTester::start(iut, timing()), Expected::default())
}

/// Checks the counters after a frame the IUT acknowledged (rule h); `prior` is
/// REC before it: from above 127 any value in 119..=127 is correct.
#[track_caller]
pub fn check_after_rx_ok(lt: &LowerTester, exp: &mut Expected, prior: u8, what: &str) {
    if prior > 127 {
        let r = lt.probes().rec;
        assert!(
            (119..=127).contains(&r),
            "{}: {what}: REC {r} after a valid frame with REC {prior} before; \
             ISO 11898-1 12.1.4.2 h needs 119..=127",
            lt.name()
        );
        exp.rec = r;
    }
    lt.check(exp, what);
}

/// The tester sends `fb` without error, then the intermission: the IUT must be
/// recessive except for its ACK, deliver the frame at EOF bit 6 and count rule h.
pub fn receive_ok(lt: &mut LowerTester, exp: &mut Expected, fb: &FrameBits) -> Run {
    let prior = exp.rec;
    let mut s = Script::new();
    s.receive(fb, 0..fb.len(), true).intermission();
    let run = lt.run(&s);
    exp.rx_ok();
    assert_eq!(
        run.rx_valid_bits(),
        vec![fb.eof(6)],
        "{}: rx_valid must pulse once, at EOF bit 6 (frame {})",
        lt.name(),
        fb.frame
    );
    assert_eq!(
        run.recs[fb.eof(6)].rx_frame,
        Some(fb.frame),
        "{}: rx_frame",
        lt.name()
    );
    check_after_rx_ok(lt, exp, prior, &format!("after receiving {}", fb.frame));
    run
}

/// The flag, delimiter and intermission after an error the IUT (receiver) detects
/// at the previous bit; `exp` already counts the error.
fn rx_error_tail(s: &mut Script, exp: &Expected) {
    s.error_flag(exp.active()).error_delim().intermission();
}

/// Value of `b` inverted, as the tester's drive (the IUT is a receiver, so its own
/// `tx` is recessive and a dominant bit can be turned recessive with `R`).
fn flipped(v: bool) -> Lt {
    Lt::from_value(!v)
}

/// Base and extended data and remote frames: every DLC 0..=8, a spread of identifiers.
pub fn spread_frames() -> Vec<Frame> {
    let data = [0x00, 0xFF, 0x55, 0xAA, 0x0F, 0xF0, 0x81, 0x7E];
    let base_ids = [
        0x000, 0x7FF, 0x555, 0x2AA, 0x123, 0x400, 0x001, 0x3FF, 0x7FE,
    ];
    let ext_ids = [
        0x0000_0000,
        0x1FFF_FFFF,
        0x1555_5555,
        0x0AAA_AAAA,
        0x1234_5678,
        0x0004_0000,
        0x1FFC_0000,
        0x0003_FFFF,
        0x1000_0001,
    ];
    let mut v = Vec::new();
    for (k, &id) in base_ids.iter().enumerate() {
        v.push(base(id, &data[..k.min(8)]));
    }
    for (k, &id) in ext_ids.iter().enumerate() {
        v.push(ext(id, &data[(8 - k.min(8))..]));
    }
    for dlc in [0u8, 1, 4, 8] {
        v.push(remote(0x5A5, false, dlc));
        v.push(remote(0x0A5A_5A5A, true, dlc));
    }
    v
}

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
    super::procedures::tx_ok(lt, exp, &m, 0);
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
fn eof7_overload_script(fb: &FrameBits) -> Script {
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

/// 7.4.2: see [`iso_7_1_12_valid_at_eof6_overload_at_eof7`]; here with an extended
/// remote frame and REC 0.
pub fn iso_7_4_2_overload_at_last_eof_bit(iut: &Iut) {
    let (mut lt, exp) = start(iut);
    let fb = FrameBits::new(&remote(0x1ABC_DEF0, true, 2));
    let run = lt.run(&eof7_overload_script(&fb));
    assert_eq!(run.rx_valid_bits(), vec![fb.eof(6)]);
    lt.check(&exp, "after the overload frame");
}

/// 7.2.1 (and 7.6.5): the IUT's ACK read back recessive is a bit error: error flag
/// from the ACK delimiter, REC + 1, no frame.
pub fn iso_7_2_1_ack_bit_error(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for f in [base(0x0F0, &[1, 2, 3]), ext(0x0F0F_0F0F, &[])] {
        let fb = FrameBits::new(&f);
        let mut s = Script::new();
        s.receive(&fb, 0..fb.ack_slot(), true);
        s.push(Lt::ForceR, Some(false), "ACK forced recessive");
        exp.rec_add(1);
        rx_error_tail(&mut s, &exp);
        let run = lt.run(&s);
        assert!(run.rx_valid_bits().is_empty());
        lt.check(&exp, "after the ACK bit error");
    }
    assert_eq!(exp.rec, 2);
    assert!(lt.received.is_empty());
}

/// Plays every frame of `frames` once per stuff bit, with that stuff bit inverted:
/// stuff error, error flag from the next bit, REC + 1 each time (a fresh IUT per
/// frame), no frame delivered.
fn stuff_error_everywhere(iut: &Iut, frames: &[Frame]) {
    for f in frames {
        let (mut lt, mut exp) = start(iut);
        let fb = FrameBits::new(f);
        for p in fb.stuff_positions() {
            lt.set_context(format!("{f}, stuff bit {p} ({})", fb.name(p)));
            let mut s = Script::new();
            s.receive(&fb, 0..p, false);
            s.push(flipped(fb.bits[p].value), Some(true), "stuff bit inverted");
            exp.rec_add(1);
            rx_error_tail(&mut s, &exp);
            let run = lt.run(&s);
            assert!(run.rx_valid_bits().is_empty());
            assert_eq!(run.recs[p + 1].label, "ErrFlag 1");
            lt.check(&exp, "after the stuff error");
        }
        assert!(lt.received.is_empty());
    }
}

/// 7.2.2: stuff error at every stuff bit of base frames covering every field.
pub fn iso_7_2_2_stuff_error_base(iut: &Iut) {
    stuff_error_everywhere(iut, &stuffing_frames(false));
}

/// 7.2.3: stuff error at every stuff bit of extended frames covering every field.
pub fn iso_7_2_3_stuff_error_extended(iut: &Iut) {
    stuff_error_everywhere(iut, &stuffing_frames(true));
}

/// 7.2.4 (classical adaptation; ISO 16845-1 runs it on a 64-byte FD frame): stuff
/// error at every stuff bit of base frames ID 555h, DLC 8, with the ISO data
/// patterns (byte 0, bytes 1..7).
pub fn iso_7_2_4_stuff_error_data_patterns(iut: &Iut) {
    stuff_error_everywhere(iut, &data_pattern_frames());
}

/// The data patterns of ISO 16845-1 7.2.4 / 8.2.8 on classical 8-byte frames.
pub fn data_pattern_frames() -> Vec<Frame> {
    [
        (0x10, 0x78),
        (0x78, 0x3C),
        (0x34, 0x1E),
        (0x12, 0x0F),
        (0x0F, 0x87),
        (0x17, 0xC3),
        (0x43, 0xE1),
        (0x21, 0xF0),
    ]
    .iter()
    .map(|&(first, rest)| {
        let mut d = [rest; 8];
        d[0] = first;
        base(0x555, &d)
    })
    .collect()
}

/// 7.2.5 (and 7.6.10): a CRC error is signalled from the bit after the ACK
/// delimiter; the IUT sends no ACK and takes another node's dominant ACK without
/// error; REC + 1.
pub fn iso_7_2_5_crc_error_position(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let frames = [base(0x6B1, &[0x12, 0x34]), ext(0x0155_AA00, &[0xF0; 8])];
    for (k, f) in frames.iter().enumerate() {
        for bit in [0u16, 7, 14] {
            let fb = FrameBits::with(
                f,
                Options {
                    crc_xor: 1 << bit,
                    ..Options::default()
                },
            );
            lt.set_context(format!(
                "{f}, CRC bit {bit} inverted, other ACK: {}",
                k == 0
            ));
            let mut s = Script::new();
            s.receive(&fb, 0..fb.eof(1), false);
            if k == 0 {
                s.bits[fb.ack_slot()].drive = Lt::D;
            }
            exp.rec_add(1);
            rx_error_tail(&mut s, &exp);
            let run = lt.run(&s);
            assert_eq!(run.recs[fb.eof(1)].label, "ErrFlag 1");
            assert!(run.rx_valid_bits().is_empty());
            lt.check(&exp, "after the CRC error");
        }
    }
}

/// 7.2.6: wrong CRC and a dominant CRC delimiter: one 6-bit error flag from the
/// ACK slot (form error), no second flag for the CRC error, REC + 1.
pub fn iso_7_2_6_crc_and_form_error_one_flag(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::with(
        &base(0x3C3, &[0x99]),
        Options {
            crc_xor: 0x0100,
            ..Options::default()
        },
    );
    let mut s = Script::new();
    s.receive(&fb, 0..fb.crc_delim(), false);
    s.push(Lt::D, Some(true), "CRC delimiter dominant");
    exp.rec_add(1);
    rx_error_tail(&mut s, &exp);
    lt.run(&s);
    lt.check(&exp, "one error for CRC plus form error");
}

/// 7.2.7: form error on the CRC delimiter: error flag from the ACK slot, REC + 1.
pub fn iso_7_2_7_form_error_crc_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    for f in [base(0x011, &[0x80]), ext(0x1F00_00FF, &[])] {
        let fb = FrameBits::new(&f);
        let mut s = Script::new();
        s.receive(&fb, 0..fb.crc_delim(), false);
        s.push(Lt::D, Some(true), "CRC delimiter dominant");
        exp.rec_add(1);
        rx_error_tail(&mut s, &exp);
        let run = lt.run(&s);
        assert_eq!(run.recs[fb.ack_slot()].label, "ErrFlag 1");
        lt.check(&exp, "after the form error");
    }
}

/// 7.2.9: form error on the ACK delimiter: error flag from EOF bit 1; REC - 1 for
/// the ACK (rule h), + 1 for the error (REC 9 before: 9 after).
pub fn iso_7_2_9_form_error_ack_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x7A0, &[1, 2, 3, 4]));
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
        "rule h at the ACK slot"
    );
    lt.check(&exp, "after the form error");
    assert_eq!(exp.rec, 9);
}

/// Form error at EOF bit `n` (1..=6) of a received frame.
fn eof_form_error(lt: &mut LowerTester, exp: &mut Expected, fb: &FrameBits, n: u8) -> Run {
    let mut s = Script::new();
    s.receive(fb, 0..fb.eof(n), true);
    s.push(Lt::D, Some(true), format!("EOF {n} dominant"));
    exp.rx_ok();
    exp.rec_add(1);
    rx_error_tail(&mut s, exp);
    let run = lt.run(&s);
    assert!(
        run.rx_valid_bits().is_empty(),
        "{}: no frame may be delivered with a dominant EOF bit {n}",
        lt.name()
    );
    lt.check(exp, &format!("after the form error at EOF bit {n}"));
    run
}

/// 7.2.10: form error at each of the EOF bits 1..=6: error flag from the next bit,
/// no frame, REC - 1 (ACK) + 1 (error).
pub fn iso_7_2_10_form_error_eof(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&ext(0x0246_8ACE, &[0x5A]));
    for n in 1..=6 {
        lt.set_context(format!("EOF bit {n}"));
        eof_form_error(&mut lt, &mut exp, &fb, n);
        assert_eq!(exp.rec, 9);
    }
    assert!(lt.received.is_empty());
}

/// 7.2.11: a dominant 6th EOF bit makes the frame invalid for the receiver (no
/// `rx_valid`; error flag from EOF bit 7).
pub fn iso_7_2_11_dominant_eof6_invalid(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x001, &[0xFF, 0x00]));
    let run = eof_form_error(&mut lt, &mut exp, &fb, 6);
    assert_eq!(run.recs[fb.eof(7)].label, "ErrFlag 1");
    assert!(lt.received.is_empty());
    // A following frame is received.
    receive_ok(&mut lt, &mut exp, &fb);
}

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
    let e = rx_error_frame();
    let mut s = Script::new();
    s.receive(&e, 0..5, false);
    s.push(Lt::D, Some(true), "stuff error");
    exp.rec_add(1);
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
fn flag_bit_error(lt: &mut LowerTester, exp: &mut Expected, b: usize) -> Run {
    let e = rx_error_frame();
    let mut s = Script::new();
    s.receive(&e, 0..5, false);
    s.push(Lt::D, Some(true), "stuff error");
    exp.rec_add(1);
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

/// Stuff error, then a dominant bit at error delimiter bit `k` (2..=7): form
/// error, REC + 1, new flag from the next bit.
fn delimiter_form_error(lt: &mut LowerTester, exp: &mut Expected, k: usize) -> Run {
    let e = rx_error_frame();
    let mut s = Script::new();
    s.receive(&e, 0..5, false);
    s.push(Lt::D, Some(true), "stuff error");
    exp.rec_add(1);
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

/// 7.4.1 / 7.4.6 / 7.4.7: a dominant bit at intermission bit 1 or 2 starts an
/// overload frame at the next bit, after a data frame, after an error frame and
/// after an overload frame; REC unchanged.
pub fn iso_7_4_1_overload_at_intermission(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let fb = FrameBits::new(&base(0x155, &[0x0F]));
    for bit in [1usize, 2] {
        // After a data frame.
        lt.set_context(format!("after a data frame, intermission bit {bit}"));
        let mut s = Script::new();
        s.receive(&fb, 0..fb.len(), true);
        s.repeat(bit - 1, Lt::R, Some(true), "Intermission");
        s.push(Lt::D, Some(true), format!("Intermission {bit} dominant"));
        s.overload_flag().overload_delim();
        // After the overload frame: dominant intermission bit again.
        s.repeat(bit - 1, Lt::R, Some(true), "Intermission");
        s.push(Lt::D, Some(true), format!("Intermission {bit} dominant"));
        s.overload_flag().overload_delim().intermission();
        exp.rx_ok();
        let run = lt.run(&s);
        assert_eq!(run.rx_valid_bits().len(), 1);
        lt.check(&exp, "overload frames change no counter");
        // After an error frame.
        lt.set_context(format!("after an error frame, intermission bit {bit}"));
        let e = rx_error_frame();
        let mut s = Script::new();
        s.receive(&e, 0..5, false);
        s.push(Lt::D, Some(true), "stuff error");
        exp.rec_add(1);
        s.error_flag(true).error_delim();
        s.repeat(bit - 1, Lt::R, Some(true), "Intermission");
        s.push(Lt::D, Some(true), format!("Intermission {bit} dominant"));
        s.overload_flag().overload_delim().intermission();
        lt.run(&s);
        lt.check(&exp, "after the error and overload frames");
    }
}

/// 7.4.3 (and 7.6.19, 7.6.20): a dominant 8th bit of an error delimiter and of an
/// overload delimiter starts an overload frame; no counter change.
pub fn iso_7_4_3_overload_at_delimiter_bit_8(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let e = rx_error_frame();
    let mut s = Script::new();
    s.receive(&e, 0..5, false);
    s.push(Lt::D, Some(true), "stuff error");
    exp.rec_add(1);
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
fn overload_after_frame(fb: &FrameBits, upto: usize) -> Script {
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

/// Brings a fresh IUT to REC `target` >= 128 (error passive).
fn passive_receiver(iut: &Iut, target: u8) -> (LowerTester, Expected) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, target);
    assert_eq!(lt.probes().err_state, state::PASSIVE);
    (lt, exp)
}

/// Passive receiver: stuff error, then the tester's `during` bits while the IUT's
/// passive flag is running, which must complete at the last of them (6 equal
/// bits, counting restarted at every change); checks the `field` probe bit by bit,
/// the 8-bit delimiter and a SOF at intermission bit 3.
fn passive_flag_pattern(lt: &mut LowerTester, exp: &mut Expected, during: &[Lt]) {
    let e = rx_error_frame();
    let fb = FrameBits::new(&base(0x2A2, &[0x2A]));
    let mut s = Script::new();
    s.receive(&e, 0..5, false);
    s.push(Lt::D, Some(true), "stuff error");
    exp.rec_add(1);
    for (i, &d) in during.iter().enumerate() {
        s.push(d, Some(true), format!("PassiveFlag {}", i + 1));
    }
    s.error_delim();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.receive(&fb, 0..fb.len(), true).intermission();
    let prior = exp.rec;
    let run = lt.run(&s);
    let first = run.find("PassiveFlag 1");
    for i in first..first + during.len() - 1 {
        assert_eq!(
            run.recs[i].probes.field,
            field::ERROR_FLAG,
            "{}: passive flag {:?} ended early at its bit {}",
            lt.name(),
            during,
            i - first + 1
        );
    }
    assert_eq!(
        run.recs[first + during.len() - 1].probes.field,
        field::ERROR_DELIM,
        "{}: passive flag {:?} must end after its last bit",
        lt.name(),
        during
    );
    assert_eq!(lt.received.last(), Some(&fb.frame), "{}", lt.name());
    exp.rx_ok();
    check_after_rx_ok(lt, exp, prior, "after the frame");
    rec_to(lt, exp, 130);
}

fn pattern(s: &str) -> Vec<Lt> {
    s.chars()
        .map(|c| if c == 'D' { Lt::D } else { Lt::R })
        .collect()
}

/// 7.5.1: an error-passive receiver's passive error flag completes only after 6
/// equal consecutive bits (recessive or dominant).
pub fn iso_7_5_1_passive_flag_six_equal_bits(iut: &Iut) {
    let (mut lt, mut exp) = passive_receiver(iut, 130);
    for p in ["RRRRRR", "DDDDDD", "DDDRRRRRR", "RRRDDDDDD"] {
        lt.set_context(format!("bits during the passive flag: {p}"));
        passive_flag_pattern(&mut lt, &mut exp, &pattern(p));
    }
}

/// 7.5.5: the passive flag's count of equal bits restarts at every change.
pub fn iso_7_5_5_passive_flag_restarts(iut: &Iut) {
    let (mut lt, mut exp) = passive_receiver(iut, 130);
    for p in [
        "DRRRRRR",
        "RRDRRRRRR",
        "RRRRRDRRRRRR",
        "DRDRDRRRRRR",
        "RRRRRDDDDDD",
    ] {
        lt.set_context(format!("bits during the passive flag: {p}"));
        passive_flag_pattern(&mut lt, &mut exp, &pattern(p));
    }
}

/// 7.5.2: an error-passive receiver accepts a SOF at the 3rd intermission bit
/// after its passive error frame.
pub fn iso_7_5_2_passive_sof_at_intermission_bit_3(iut: &Iut) {
    let (mut lt, mut exp) = passive_receiver(iut, 130);
    passive_flag_pattern(&mut lt, &mut exp, &pattern("RRRRRR"));
}

/// 7.5.3: after its passive flag the IUT tolerates 1..=7 dominant bits; REC + 1 + 8.
pub fn iso_7_5_3_passive_dominant_bits_after_flag(iut: &Iut) {
    let (mut lt, mut exp) = passive_receiver(iut, 128);
    for n in 1..=7 {
        lt.set_context(format!("{n} dominant bits after the passive flag"));
        let before = exp.rec;
        let run = rx_error(&mut lt, &mut exp, n);
        assert_eq!(exp.rec as u16, before as u16 + 9);
        assert_eq!(run.at("ErrDelim 8").probes.field, field::INTERMISSION);
    }
}

/// 7.5.4: an error-passive receiver stays error passive while errors go on.
pub fn iso_7_5_4_stays_passive(iut: &Iut) {
    let (mut lt, mut exp) = passive_receiver(iut, 128);
    for n in [0, 1, 0, 3] {
        rx_error(&mut lt, &mut exp, n);
        assert_eq!(lt.probes().err_state, state::PASSIVE);
    }
}

/// 7.5.6: form error in the delimiter after a passive flag: a new passive flag,
/// REC + 1.
pub fn iso_7_5_6_passive_form_error_in_delimiter(iut: &Iut) {
    let (mut lt, mut exp) = passive_receiver(iut, 128);
    for k in [2, 5, 7] {
        lt.set_context(format!("delimiter bit {k}"));
        delimiter_form_error(&mut lt, &mut exp, k);
    }
}

/// 7.5.7: the error flag is forced recessive bit after bit (REC 1, 9, .., 121,
/// 129): at REC >= 128 the IUT turns error passive and its next flag is passive;
/// it still acknowledges the next frame (REC back to 119..=127, error active).
pub fn iso_7_5_7_active_to_passive(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    let e = rx_error_frame();
    let mut s = Script::new();
    s.receive(&e, 0..5, false);
    s.push(Lt::D, Some(true), "stuff error");
    exp.rec_add(1);
    for j in 1..=16 {
        s.push(Lt::ForceR, Some(false), format!("forced {j}"));
        exp.rec_add(8);
    }
    assert_eq!(exp.rec, 129);
    s.passive_flag("PassiveFlag").error_delim().intermission();
    let run = lt.run(&s);
    for j in 1..=16u8 {
        let r = run.at(&format!("forced {j}"));
        let want_state = if j < 16 {
            state::ACTIVE
        } else {
            state::PASSIVE
        };
        assert_eq!(
            (r.probes.rec, r.probes.err_state),
            (1 + 8 * j, want_state),
            "{}: at the forced bit {j}",
            lt.name()
        );
    }
    lt.check(&exp, "error passive");
    let prior = exp.rec;
    let fb = FrameBits::new(&base(0x5F5, &[0x77]));
    let mut s = Script::new();
    s.receive(&fb, 0..fb.len(), true).intermission();
    lt.run(&s);
    exp.rx_ok();
    check_after_rx_ok(&lt, &mut exp, prior, "after the valid frame");
    assert_eq!(lt.received, vec![fb.frame]);
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

/// 7.6.6 / 7.6.7 / 7.6.8 / 7.6.12 / 7.6.13: a form error costs a receiver REC + 1
/// in the CRC delimiter, the ACK delimiter, EOF, the error delimiter and the
/// overload delimiter (REC 9 before; rule h for the frames it acknowledged).
pub fn iso_7_6_6_rec_form_errors(iut: &Iut) {
    let (mut lt, mut exp) = start(iut);
    rec_to(&mut lt, &mut exp, 9);
    let fb = FrameBits::new(&base(0x246, &[0x46]));
    // CRC delimiter.
    let mut s = Script::new();
    s.receive(&fb, 0..fb.crc_delim(), false);
    s.push(Lt::D, Some(true), "CRC delimiter dominant");
    exp.rec_add(1);
    rx_error_tail(&mut s, &exp);
    lt.run(&s);
    lt.check(&exp, "CRC delimiter form error");
    assert_eq!(exp.rec, 10);
    // ACK delimiter.
    let mut s = Script::new();
    s.receive(&fb, 0..fb.ack_slot() + 1, true);
    s.push(Lt::D, Some(true), "ACK delimiter dominant");
    exp.rx_ok();
    exp.rec_add(1);
    rx_error_tail(&mut s, &exp);
    lt.run(&s);
    lt.check(&exp, "ACK delimiter form error");
    // EOF bit 3.
    eof_form_error(&mut lt, &mut exp, &fb, 3);
    assert_eq!(exp.rec, 10);
    // Error delimiter bit 4.
    delimiter_form_error(&mut lt, &mut exp, 4);
    assert_eq!(exp.rec, 12);
    // Overload delimiter bit 5.
    let mut s = overload_after_frame(&fb, 6);
    s.repeat(4, Lt::R, Some(true), "OvlDelim");
    s.push(Lt::D, Some(true), "OvlDelim 5 dominant");
    exp.rx_ok();
    exp.rec_add(1);
    rx_error_tail(&mut s, &exp);
    lt.run(&s);
    lt.check(&exp, "overload delimiter form error");
    assert_eq!(exp.rec, 12);
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
    super::procedures::tx_ok(lt, exp, mine, 0);
}
