//! ISO 16845-1 8.4: overload frames around the IUT's own frame.

use super::*;

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
    s.push(Lt::D, Some(true), "Intermission 3 dominant");
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
