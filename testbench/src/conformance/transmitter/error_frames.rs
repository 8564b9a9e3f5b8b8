//! ISO 16845-1 8.3: the transmitter's active error frame (dominant bits after
//! the flag, SOF at intermission bit 3, bit error in the flag, form error in
//! the delimiter).

use super::*;

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
    let (mut s, _) = bit_error_at_r0(&mut exp, &fb, 2);
    s.error_flag(true).error_delim();
    s.repeat(2, Lt::R, Some(true), "Intermission");
    s.push(Lt::D, Some(true), "Intermission 3 dominant");
    s.transmit(&fb, 1..fb.len(), true, 0).intermission();
    exp.tx_ok();
    let run = lt.run(&s);
    assert_eq!(run.tx_done_bits().len(), 1, "{}", lt.name());
    lt.check(&exp, "after the frame");
}

/// Bit error at r0, then the IUT's active flag bit `b` forced recessive: rule d
/// (TEC + 8), a new flag at the next bit.
pub(super) fn tx_flag_bit_error(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    b: usize,
    sof_within: u32,
) -> Run {
    let (mut s, _) = bit_error_at_r0(exp, fb, sof_within);
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
