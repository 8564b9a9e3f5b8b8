//! ISO 16845-1 7.2: error detection by the receiver (ACK bit error, stuff, CRC
//! and form errors, dominant EOF bit 6).

use super::*;

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
pub(super) fn eof_form_error(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    n: u8,
) -> Run {
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
