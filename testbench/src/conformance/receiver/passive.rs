//! ISO 16845-1 7.5: the error-passive receiver (passive flags of six equal
//! bits, staying passive, turning passive).

use super::*;

/// Brings a fresh IUT to REC `target` >= 128 (error passive).
pub(super) fn passive_receiver(iut: &Iut, target: u8) -> (LowerTester, Expected) {
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
    let fb = FrameBits::new(&base(0x2A2, &[0x2A]));
    let mut s = rx_stuff_error(exp);
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
    let mut s = rx_stuff_error(&mut exp);
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
