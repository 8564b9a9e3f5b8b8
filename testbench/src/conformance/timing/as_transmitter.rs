//! ISO 16845-1 8.7: bit timing of the IUT as transmitter, seen on its own `tx`
//! (sample point, hard synchronisation at SOF, negative phase errors, one
//! synchronisation per bit, no resynchronisation while sending dominant).

use super::*;

/// First data bit `p` of `fb` with the pattern `pat` (values of bits p, p+1, ..;
/// none of them a stuff bit).
fn find_pattern(fb: &FrameBits, pat: &[bool]) -> usize {
    (0..fb.len() - pat.len())
        .find(|&p| {
            pat.iter().enumerate().all(|(k, &v)| {
                let b = fb.bits[p + k];
                b.field == Field::Data && !b.stuff && b.value == v
            })
        })
        .expect("pattern in the data field")
}

/// The IUT transmits `fb` (requested); bits `p..` are replaced by `shaped`
/// (segments, expected IUT value), then the frame goes on from `resume` with an
/// ACK. Returns the records of the whole frame (index = script bit).
fn tx_with_shaped(
    lt: &mut LowerTester,
    exp: &mut Expected,
    fb: &FrameBits,
    p: usize,
    shaped: &[(Vec<(Lt, u32)>, bool)],
    resume: usize,
) -> Run {
    let mut s = Script::new();
    s.transmit(fb, 0..p, true, 2);
    for (k, (segs, v)) in shaped.iter().enumerate() {
        s.push_shaped(segs, Some(*v), format!("shaped {k}"));
    }
    s.transmit(fb, resume..fb.len(), true, 0);
    exp.tx_ok();
    interframe_tx(&mut s, exp);
    let run = lt.run(&s);
    assert_eq!(run.tx_done_bits().len(), 1, "{}: tx_done", lt.name());
    lt.check(exp, "after the frame");
    run
}

/// 8.7.1: the transmitter's sample point: its dominant bit forced recessive after
/// the sample point is no error; from the sample point on it is a bit error.
pub fn iso_8_7_1_sample_point_tx(iut: &Iut) {
    for t in [timing(), timing_wide()] {
        let n = cpb(&t);
        let s1 = t.tseg1 as u32 + 1;
        let fb = FrameBits::new(&base(0x0A1, &[0x5A, 0xA5]));
        let p = find_pattern(&fb, &[false]);
        // Forced recessive after the sample point: no error.
        let mut lt = LowerTester::start(iut, t);
        let mut exp = Expected::default();
        lt.request(fb.frame);
        tx_with_shaped(
            &mut lt,
            &mut exp,
            &fb,
            p,
            &[(vec![(Lt::R, s1), (Lt::ForceR, n - s1)], false)],
            p + 1,
        );
        // From the sample point: bit error, flag from the next bit.
        let mut lt = LowerTester::start(iut, t);
        let mut exp = Expected::default();
        lt.request(fb.frame);
        let mut s = Script::new();
        s.transmit(&fb, 0..p, true, 2);
        s.push_shaped(
            &[(Lt::R, s1 - 1), (Lt::ForceR, n - s1 + 1)],
            Some(false),
            "forced",
        );
        exp.tec_add(8);
        s.error_flag(true).error_delim().intermission();
        lt.run(&s);
        lt.check(&exp, "bit error at the sample point");
        tx_ok(&mut lt, &mut exp, &fb, 0);
    }
}

/// With a frame pending, the IUT receives a frame; intermission bit 2 lasts
/// `bit2` clocks and bit 3 `bit3` clocks, then comes the tester's SOF (one bit).
/// The IUT must hard-synchronise on that SOF edge and send its identifier from
/// the next bit, aligned to the edge (checked bit by bit on the tester's grid).
/// With `sof_from_idle` (the edge after the sample point of intermission bit 3,
/// so the IUT is idle) it must also start its own SOF in the tq after the edge
/// (ISO 16845-1 8.7.3), i.e. on the bus [`LOOP_SYNC`] clocks after the edge.
fn sof_at_intermission_3(iut: &Iut, t: BitTiming, bit2: u32, bit3: u32, sof_from_idle: bool) {
    let mut lt = start_traced(iut, t);
    lt.set_context(format!(
        "intermission bit 2 {bit2} clk, bit 3 {bit3} clk before the SOF"
    ));
    let mut exp = Expected::default();
    let theirs = FrameBits::new(&base(0x700, &[7]));
    let mine = FrameBits::new(&base(0x2C2, &[2]));
    let mut s = Script::new();
    s.receive(&theirs, 0..theirs.len(), true);
    s.request_at(3, mine.frame);
    s.push(Lt::R, Some(true), "Intermission 1");
    s.push_shaped(&[(Lt::R, bit2)], Some(true), "Intermission 2");
    if bit3 > 0 {
        s.push_shaped(&[(Lt::R, bit3)], Some(true), "Intermission 3");
    }
    // Before the sample point of intermission bit 3 the edge is the IUT's SOF and
    // it sends no SOF bit of its own (ISO 11898-1:2015 10.4.6.3): `tx` recessive.
    // From idle it sends its own SOF from the tq after the edge (checked below).
    let own_sof = if sof_from_idle { None } else { Some(true) };
    s.push(Lt::D, own_sof, "SOF");
    s.transmit(&mine, 1..mine.len(), true, 0).intermission();
    let run = lt.run(&s);
    exp.rx_ok();
    exp.tx_ok();
    assert_eq!(run.tx_done_bits().len(), 1, "{}", lt.name());
    lt.check(&exp, "after both frames");
    if sof_from_idle {
        let sof = run.find("SOF");
        assert_tx_edge(&lt, run.recs[sof].start + LOOP_SYNC, false, "its SOF");
    }
}

/// 8.7.2: a node with a frame pending hard-synchronises on a SOF edge before the
/// sample point of the 3rd intermission bit (1 .. tseg1-1 tq into the bit) and
/// sends its first identifier bit one bit time after the edge. Also (contract
/// §4.1, no ISO 16845-1 counterpart): an edge in PHASE_SEG2 of the 2nd
/// intermission bit, after its sample point, is the same SOF.
pub fn iso_8_7_2_hard_sync_sof_before_sample_point_tx(iut: &Iut) {
    for t in [timing(), timing_wide()] {
        let n = cpb(&t);
        for d in 1..t.tseg1 as u32 {
            sof_at_intermission_3(iut, t, n, d, false);
        }
        for e in 1..=t.tseg2 as u32 {
            sof_at_intermission_3(iut, t, n - e, 0, false);
        }
    }
}

/// 8.7.3: with a frame pending, a dominant edge after the sample point of the 3rd
/// intermission bit (the IUT is idle then): the IUT hard-synchronises and starts
/// its SOF in the next tq.
pub fn iso_8_7_3_hard_sync_sof_after_sample_point_tx(iut: &Iut) {
    for t in [timing(), timing_wide()] {
        let n = cpb(&t);
        for d in t.tseg1 as u32 + 1..n {
            sof_at_intermission_3(iut, t, n, d, true);
        }
    }
}

/// Transmitter, recessive bit `p` then dominant bit `p + 1`: the tester pulls the
/// bus dominant `e` tq before the end of bit `p` (a negative phase error while the
/// IUT sends recessive), optionally only for a 1-tq glitch. The IUT's next bit
/// starts at the edge (|e| <= SJW) or SJW tq early (|e| > SJW); the tester follows
/// it, and checks the IUT's dominant bit reaches the bus at that start.
fn tx_negative_edge(iut: &Iut, t: BitTiming, e: u32, glitch: bool) {
    let n = cpb(&t);
    let sjw = t.sjw.min(t.tseg2) as u32;
    let s = e.min(sjw);
    let fb = FrameBits::new(&base(0x3C3, &[0x5A, 0xA5]));
    let p = find_pattern(&fb, &[true, false]);
    let mut lt = start_traced(iut, t);
    lt.set_context(format!("edge {e} tq early, glitch {glitch}"));
    let mut exp = Expected::default();
    lt.request(fb.frame);
    let mut bit_p = vec![(Lt::R, n - e)];
    let next: Vec<(Lt, u32)>;
    if glitch {
        if e > s {
            bit_p.push((Lt::D, 1));
            if e - s > 1 {
                bit_p.push((Lt::R, e - s - 1));
            }
            next = vec![(Lt::R, n)];
        } else {
            next = vec![(Lt::D, 1), (Lt::R, n - 1)];
        }
    } else {
        if e > s {
            bit_p.push((Lt::D, e - s));
        }
        next = vec![(Lt::D, n)];
    }
    let run = tx_with_shaped(
        &mut lt,
        &mut exp,
        &fb,
        p,
        &[(bit_p, true), (next, false)],
        p + 2,
    );
    let start = run.recs[p + 1].start;
    assert_eq!(start, run.recs[p].start + (n - s) as u64);
    let delay = if e <= sjw { LOOP_SYNC } else { LOOP };
    assert_tx_edge(&lt, start + delay, false, "the IUT's next bit");
}

/// 8.7.4: negative phase error |e| <= SJW while transmitting recessive: the IUT's
/// next bit starts at the edge.
pub fn iso_8_7_4_negative_phase_error_within_sjw_tx(iut: &Iut) {
    tx_negative_edge(iut, timing(), 1, false);
    for e in 1..=3 {
        tx_negative_edge(iut, timing_wide(), e, false);
    }
}

/// 8.7.5: negative phase error |e| > SJW while transmitting: PHASE_SEG2 shortened
/// by SJW.
pub fn iso_8_7_5_negative_phase_error_beyond_sjw_tx(iut: &Iut) {
    tx_negative_edge(iut, timing(), 2, false);
    tx_negative_edge(iut, timing_wide(), 4, false);
}

/// 8.7.6: transmitter, only one synchronisation per bit: after resynchronising on
/// a 1-tq glitch at the end of a recessive bit, a second edge at tq 3 of the next
/// recessive bit is not used (the bit after it starts on time).
pub fn iso_8_7_6_one_synchronisation_per_bit_tx(iut: &Iut) {
    let t = timing_wide();
    let n = cpb(&t);
    let fb = FrameBits::new(&base(0x3C3, &[0x5A, 0xA5]));
    let p = find_pattern(&fb, &[true, true, false]);
    let mut lt = start_traced(iut, t);
    let mut exp = Expected::default();
    lt.request(fb.frame);
    let run = tx_with_shaped(
        &mut lt,
        &mut exp,
        &fb,
        p,
        &[
            (vec![(Lt::R, n - 1)], true),
            (
                vec![(Lt::D, 1), (Lt::R, 2), (Lt::D, 2), (Lt::R, n - 5)],
                true,
            ),
        ],
        p + 2,
    );
    let start = run.recs[p + 2].start;
    assert_tx_edge(&lt, start + LOOP, false, "the bit after the second edge");
}

/// 8.7.7: no resynchronisation on a recessive-to-dominant edge while the IUT sends
/// dominant: its dominant bit forced recessive for its first 4 tq (the edge comes
/// 4 tq late) does not move its timing.
pub fn iso_8_7_7_no_resync_while_sending_dominant(iut: &Iut) {
    let t = timing_wide();
    let n = cpb(&t);
    let fb = FrameBits::new(&base(0x3C3, &[0x5A, 0xA5]));
    let p = find_pattern(&fb, &[true, false, true]);
    let mut lt = start_traced(iut, t);
    let mut exp = Expected::default();
    lt.request(fb.frame);
    let run = tx_with_shaped(
        &mut lt,
        &mut exp,
        &fb,
        p + 1,
        &[(vec![(Lt::ForceR, 4), (Lt::R, n - 4)], false)],
        p + 2,
    );
    let start = run.recs[p + 2].start;
    assert_tx_edge(&lt, start + LOOP, true, "the bit after the late edge");
}

/// 8.7.8: a 1-tq dominant glitch after the sample point of a recessive bit the IUT
/// sends, |e| <= SJW before the bit's end: its next bit starts at the glitch.
pub fn iso_8_7_8_edge_after_sample_point_within_sjw_tx(iut: &Iut) {
    tx_negative_edge(iut, timing(), 1, true);
    for e in 1..=3 {
        tx_negative_edge(iut, timing_wide(), e, true);
    }
}

/// 8.7.9: the same with |e| > SJW: its next bit starts SJW tq early.
pub fn iso_8_7_9_edge_after_sample_point_beyond_sjw_tx(iut: &Iut) {
    tx_negative_edge(iut, timing(), 2, true);
    tx_negative_edge(iut, timing_wide(), 4, true);
}
