//! ISO 16845-1 7.7: bit timing of the IUT as receiver, seen through the error
//! flag of a stuff error on the probe bit (sample point, hard synchronisation,
//! resynchronisation within and beyond SJW, glitch filtering, ACK timing).

use super::*;

/// The probe frame of the receiver items: ID 7FFh; its first stuff bit is a
/// dominant bit after five recessive bits.
fn probe_frame() -> (FrameBits, usize) {
    let fb = FrameBits::new(&base(0x7FF, &[0x3C, 0xA5]));
    let p = fb.stuff_positions()[0];
    assert!(!fb.bits[p].value && fb.bits[p - 1].value);
    (fb, p)
}

/// One receiver case: the edge of the probe stuff bit moved by `e` tq (positive:
/// late, the recessive bit before it lengthened; negative: early, shortened) after
/// `gap` idle clocks; the stuff bit then dominant for `d` tq. Expected from ISO
/// 11898-1 11.3.2: the IUT's bit starts `start_rel` tq after the edge (0 when the
/// phase error is within SJW; the residual error otherwise), it samples at
/// `start_rel + tseg1`. With `d` covering that tq the frame must be received
/// (checked to the end when the IUT is realigned); with `d` one tq short the IUT
/// must flag a stuff error from its next bit start, to the clock.
fn edge_case(iut: &Iut, t: BitTiming, gap: u32, e: i32, d_offset: i32) {
    let n = cpb(&t) as i32;
    let sjw = t.sjw.min(t.tseg2) as i32;
    let r = e.abs() - e.abs().min(sjw);
    let start_rel = if e > 0 { -r } else { r };
    let sample_rel = start_rel + t.tseg1 as i32;
    let d = sample_rel + d_offset;
    assert!(d > 0 && d < n, "case outside the bit");
    let error = d_offset == 0;
    let ctx = format!(
        "timing {}/{}/{} sjw {}, idle {gap} clk, edge {e:+} tq, dominant {d} tq",
        t.brp, t.tseg1, t.tseg2, t.sjw
    );
    let mut lt = start_traced(iut, t);
    lt.set_context(ctx.clone());
    lt.clocks(Lt::R, gap);
    let (fb, p) = probe_frame();
    let mut s = Script::new();
    s.receive(&fb, 0..p - 1, false);
    s.push_shaped(&[(Lt::R, (n + e) as u32)], Some(true), "moved edge");
    s.push_shaped(
        &[(Lt::D, d as u32), (Lt::R, (n - d) as u32)],
        Some(true),
        "probe stuff bit",
    );
    let run = lt.run(&s);
    let probe = run.last().clone();
    if error {
        lt.clocks(Lt::R, 8 * n as u32);
    } else if r == 0 {
        // Realigned: the rest of the frame is received.
        let mut s = Script::new();
        s.receive(&fb, p + 1..fb.len(), true).intermission();
        let run = lt.run(&s);
        assert_eq!(run.rx_valid_bits().len(), 1, "{}: [{ctx}]", lt.name());
        assert_eq!(lt.received, vec![fb.frame]);
    } else {
        lt.clocks(Lt::R, 4);
    }
    let sampled = lt
        .sample_in(probe.start, probe.end)
        .unwrap_or_else(|| panic!("{}: [{ctx}] no sample point in the probe bit", lt.name()));
    assert_eq!(
        (sampled.bus, sampled.rx_clock - probe.start),
        (error, sample_rel as u64),
        "{}: [{ctx}] (value sampled in the probe bit, its tq after the edge)",
        lt.name()
    );
    if error {
        let edge = probe.start;
        let want = (edge as i64 + (start_rel + n) as i64) as u64 + LOOP;
        let got = dominant_run(&lt, edge).map(|x| x.0);
        assert_eq!(
            got,
            Some(want),
            "{}: [{ctx}] the error flag must start at the IUT's next bit",
            lt.name()
        );
        let (_, len) = dominant_run(&lt, want).unwrap();
        assert_eq!(len, 6 * n as u64, "{}: [{ctx}] a 6-bit flag", lt.name());
        assert_eq!(lt.probes().rec, 1);
    }
}

/// Runs `edge_case` for the error and the no-error variant.
fn edge_pair(iut: &Iut, t: BitTiming, gap: u32, e: i32) {
    edge_case(iut, t, gap, e, 0);
    edge_case(iut, t, gap, e, 1);
}

/// 7.7.1: the sample point is at the end of PHASE_SEG1: a dominant bit that turns
/// recessive right after it is read dominant, one tq earlier recessive (stuff
/// error, flag from the next bit).
pub fn iso_7_7_1_sample_point(iut: &Iut) {
    for t in [timing(), timing_wide()] {
        edge_pair(iut, t, 0, 0);
    }
}

/// 7.7.2: hard synchronisation on SOF: whatever the phase of the idle IUT's bit
/// timing when the SOF edge comes, its sample points follow that edge.
pub fn iso_7_7_2_hard_synchronisation(iut: &Iut) {
    for t in [timing(), timing_wide()] {
        for gap in 0..cpb(&t) {
            edge_pair(iut, t, gap, 0);
        }
    }
}

/// 7.7.3: positive phase error e <= SJW on a recessive-to-dominant edge: the IUT
/// lengthens PHASE_SEG1 by e.
pub fn iso_7_7_3_positive_phase_error_within_sjw(iut: &Iut) {
    edge_pair(iut, timing(), 0, 1);
    for e in 1..=3 {
        edge_pair(iut, timing_wide(), 0, e);
    }
}

/// 7.7.4: positive phase error e > SJW: PHASE_SEG1 lengthened by SJW only.
pub fn iso_7_7_4_positive_phase_error_beyond_sjw(iut: &Iut) {
    for e in 2..=4 {
        edge_pair(iut, timing(), 0, e);
    }
    for e in [4, 6, 8, 10] {
        edge_pair(iut, timing_wide(), 0, e);
    }
}

/// 7.7.5: negative phase error |e| <= SJW: the bit ends at the edge.
pub fn iso_7_7_5_negative_phase_error_within_sjw(iut: &Iut) {
    edge_pair(iut, timing(), 0, -1);
    for e in 1..=3 {
        edge_pair(iut, timing_wide(), 0, -e);
    }
}

/// 7.7.6: negative phase error |e| > SJW: PHASE_SEG2 shortened by SJW only.
pub fn iso_7_7_6_negative_phase_error_beyond_sjw(iut: &Iut) {
    edge_pair(iut, timing(), 0, -2);
    edge_pair(iut, timing_wide(), 0, -4);
}

/// The probe stuff bit after an edge moved by `e` (within SJW), with a second
/// recessive-to-dominant edge 4 tq after the first (dominant 2 tq, recessive 2 tq,
/// dominant until `d` tq): the second edge must not be used (one synchronisation
/// between two sample points), so the sample point stays at tseg1 after the first.
fn second_edge_case(iut: &Iut, e: i32, d: u32) {
    let t = timing_wide();
    let n = cpb(&t);
    let mut lt = start_traced(iut, t);
    lt.set_context(format!(
        "edge {e:+} tq, second edge at 4 tq, dominant until {d} tq"
    ));
    let (fb, p) = probe_frame();
    let mut s = Script::new();
    s.receive(&fb, 0..p - 1, false);
    s.push_shaped(&[(Lt::R, (n as i32 + e) as u32)], Some(true), "moved edge");
    s.push_shaped(
        &[(Lt::D, 2), (Lt::R, 2), (Lt::D, d - 4), (Lt::R, n - d)],
        Some(true),
        "probe stuff bit",
    );
    if d > t.tseg1 as u32 {
        s.receive(&fb, p + 1..fb.len(), true).intermission();
        let run = lt.run(&s);
        assert_eq!(run.rx_valid_bits().len(), 1, "{}", lt.name());
    } else {
        let run = lt.run(&s);
        assert!(
            run.last().bus,
            "{}: the IUT must sample recessive",
            lt.name()
        );
        lt.clocks(Lt::R, 8 * n);
        let want = run.last().start + n as u64 + LOOP;
        assert_eq!(dominant_run(&lt, run.last().start).map(|x| x.0), Some(want));
    }
}

/// 7.7.7: after a resynchronisation on a late edge, a second edge before the
/// sample point is not used.
pub fn iso_7_7_7_one_synchronisation_per_bit(iut: &Iut) {
    let t = timing_wide().tseg1 as u32;
    second_edge_case(iut, 1, t + 1);
    second_edge_case(iut, 1, t);
}

/// 7.7.8: after a resynchronisation on an early edge (the bit restarts there), a
/// second edge before the next sample point is not used.
pub fn iso_7_7_8_one_synchronisation_after_early_edge(iut: &Iut) {
    let t = timing_wide().tseg1 as u32;
    second_edge_case(iut, -1, t + 1);
    second_edge_case(iut, -1, t);
}

/// Idle IUT, dominant pulses `(dominant tq, recessive tq)` on the bus, then
/// recessive; returns whether the IUT left IDLE and whether its `tx` went dominant.
fn glitches(iut: &Iut, t: BitTiming, pulses: &[(u32, u32)]) -> (bool, bool) {
    let mut lt = start_traced(iut, t);
    for &(d, r) in pulses {
        lt.clocks(Lt::D, d);
        lt.clocks(Lt::R, r);
    }
    lt.clocks(Lt::R, 10 * cpb(&t));
    let tr = lt.trace.as_ref().unwrap();
    let left_idle = tr.iter().any(|c| c.out.probes.field != field::IDLE);
    let sent = tr.iter().any(|c| !c.tx);
    (left_idle, sent)
}

/// 7.7.9.1: glitch filtering in idle: a dominant pulse of tseg1 - 1 or tseg1 tq
/// (shorter than SYNC_SEG + TSEG1, so recessive again at the sample point) is not
/// a SOF: the IUT stays idle and silent; one tq longer is a SOF (default and
/// 16-tq timing).
pub fn iso_7_7_9_1_glitch_not_sof(iut: &Iut) {
    for t in [timing(), timing_wide()] {
        let s = t.tseg1 as u32;
        for len in [s - 1, s] {
            assert_eq!(
                glitches(iut, t, &[(len, 1)]),
                (false, false),
                "a {len}-tq pulse is no SOF"
            );
        }
        assert!(
            glitches(iut, t, &[(s + 1, 1)]).0,
            "a {}-tq pulse is a SOF",
            s + 1
        );
    }
}

/// 7.7.9.2: after the hard synchronisation on an edge in idle, no further edge is
/// used before the sample point: the ISO 16845-1 pulse group on the 16-tq timing
/// (tseg1 = PROP + PHASE1 = 11 tq: a first glitch of (11 - 2) / 2 = 4 tq, 2 tq
/// recessive, a second glitch of 4.5 - 1 = 3 tq, 1 + 2 tq recessive, a third glitch
/// of 11 - 2 = 9 tq) leaves the IUT idle and silent: the sample point stays 12 tq
/// after the first edge, where the bus is recessive. The same group with the
/// third glitch 1 tq earlier covers that sample point and is a SOF (the
/// reference that the group is placed at the sample point).
pub fn iso_7_7_9_2_no_resync_after_hard_sync(iut: &Iut) {
    let t = timing_wide();
    let s = t.tseg1 as u32;
    let first = (s - 2) / 2;
    let group = [(first, 2), (first - 1, 3), (s - 2, 1)];
    assert_eq!(group, [(4, 2), (3, 3), (9, 1)]);
    assert_eq!(
        glitches(iut, t, &group),
        (false, false),
        "pulse group after a hard synchronisation"
    );
    let earlier = [(first, 2), (first - 1, 2), (s - 2, 1)];
    assert!(
        glitches(iut, t, &earlier).0,
        "the third glitch over the sample point is a SOF"
    );
}

/// 7.7.10: no synchronisation on a recessive-to-dominant edge when the previous
/// sample was dominant: in a dominant bit after a dominant bit, a 2-tq recessive
/// spike must not move the sample point (the frame is received).
pub fn iso_7_7_10_no_sync_after_dominant_sample(iut: &Iut) {
    let t = timing_wide();
    let n = cpb(&t);
    let fb = FrameBits::new(&base(0x555, &[0x00, 0x81]));
    let i = (1..fb.len())
        .find(|&i| {
            let (a, b) = (fb.bits[i - 1], fb.bits[i]);
            b.field == Field::Data && !a.value && !b.value && !b.stuff && !a.stuff
        })
        .unwrap();
    let mut lt = start_traced(iut, t);
    let mut s = Script::new();
    s.receive(&fb, 0..i, true);
    s.push_shaped(
        &[(Lt::D, 1), (Lt::R, 2), (Lt::D, 9), (Lt::R, n - 12)],
        Some(true),
        "dominant bit with a recessive spike",
    );
    s.receive(&fb, i + 1..fb.len(), true).intermission();
    let run = lt.run(&s);
    assert!(!run.recs[i].bus, "{}: sampled dominant", lt.name());
    assert_eq!(lt.received, vec![fb.frame], "{}", lt.name());
}

/// 7.7.11: the IUT's ACK bit is on the bus for exactly one bit time from the ACK
/// slot's start (plus the loop delay), also after a resynchronisation (the last
/// recessive-to-dominant edge before the CRC delimiter late by 1..=SJW tq).
pub fn iso_7_7_11_ack_timing(iut: &Iut) {
    for t in [timing(), timing_wide()] {
        let n = cpb(&t);
        let fb = FrameBits::new(&base(0x2F1, &[0x11, 0x22]));
        let j = (1..fb.crc_delim())
            .rev()
            .find(|&j| !fb.bits[j].value && fb.bits[j - 1].value)
            .unwrap();
        for e in 0..=t.sjw as u32 {
            let mut lt = start_traced(iut, t);
            lt.set_context(format!("edge before the CRC delimiter late by {e} tq"));
            let mut s = Script::new();
            s.receive(&fb, 0..j - 1, true);
            s.push_shaped(&[(Lt::R, n + e)], Some(true), fb.name(j - 1));
            s.receive(&fb, j..fb.len(), true).intermission();
            let run = lt.run(&s);
            let ack = &run.recs[fb.ack_slot()];
            let want = ack.start + LOOP;
            assert_eq!(
                dominant_run(&lt, ack.start - 1),
                Some((want, n as u64)),
                "{}: ACK on the bus from clock {want} for {n} clocks",
                lt.name()
            );
            assert_eq!(lt.received, vec![fb.frame]);
        }
    }
}
