//! ISO 16845-1 items 7.7 (receiver) and 8.7 (transmitter): bit timing — sample
//! point, hard synchronisation, resynchronisation with positive and negative phase
//! errors within and beyond SJW, one synchronisation per bit, no synchronisation
//! after a dominant sample or while sending dominant, glitch filtering in idle.
//!
//! All items run with brp 0, so one time quantum is one clock and the tester can
//! put an edge at every tq boundary: the default timing (8 tq, SJW 1) and a 16-tq
//! timing with SJW 3 ([`super::timing_wide`]). Positions are in tq counted from
//! the tester's bit start, which the IUT takes as its SYNC_SEG (the 2-clock
//! synchronizer delay is the same for every edge). The IUT's own bit reaches the
//! bus [`LOOP`] clocks after the tester clock it takes as that bit's SYNC_SEG
//! (contract §2 and §3: the edge reaches the bit timing logic 2 clocks late, `tx`
//! is loaded at the `bit_start` edge that ends the previous bit).
//!
//! The probe used by the receiver items is the first stuff bit of a frame with
//! identifier 7FFh: a dominant stuff bit after five recessive bits. The tester
//! moves its edge (lengthens or shortens the recessive bit before it) and keeps it
//! dominant for exactly `d` tq: the IUT samples dominant iff its sample point
//! falls inside, and a recessive sample is a stuff error whose error flag shows,
//! to the clock, where the IUT's next bit starts.

use drcc_cosim::BitTiming;

use super::bits::{Field, FrameBits};
use super::lower_tester::{field, ClockRecord, Iut, LowerTester, Lt, Script};
use super::procedures::{base, interframe_tx, tx_ok, Expected};
use super::{timing, timing_wide};

/// Clocks from the tester clock the IUT takes as a bit's SYNC_SEG to the IUT's
/// `tx` of that bit on the bus (brp 0), for a bit that starts at the end of the
/// previous bit's PHASE_SEG2.
pub const LOOP: u64 = 2;

/// The same for a bit whose SYNC_SEG is the time quantum in which the edge was
/// seen (hard synchronisation, or a resynchronisation in PHASE_SEG2 with
/// |e| <= SJW): `tx` changes at the end of that tq (contract §3, `bit_start`).
pub const LOOP_SYNC: u64 = LOOP + 1;

fn cpb(t: &BitTiming) -> u32 {
    t.clocks_per_bit()
}

fn start_traced(iut: &Iut, t: BitTiming) -> LowerTester {
    let mut lt = LowerTester::start(iut, t);
    lt.trace = Some(Vec::new());
    lt
}

/// The IUT's `tx` on the bus at tester clock `clock` (needs the trace).
fn tx_at(lt: &LowerTester, clock: u64) -> bool {
    let t = lt.trace.as_ref().expect("trace");
    let first = t[0].clock;
    t[(clock - first) as usize].tx
}

/// The first clock at or after `from` where the IUT's `tx` is dominant, and how
/// many clocks it stays dominant.
fn dominant_run(lt: &LowerTester, from: u64) -> Option<(u64, u64)> {
    let t: &Vec<ClockRecord> = lt.trace.as_ref().expect("trace");
    let first = t[0].clock;
    let start = t[(from - first) as usize..].iter().find(|c| !c.tx)?.clock;
    let len = t[(start - first) as usize..]
        .iter()
        .take_while(|c| !c.tx)
        .count() as u64;
    Some((start, len))
}

/// Asserts that the IUT's `tx` changes to `value` exactly at `clock`.
#[track_caller]
fn assert_tx_edge(lt: &LowerTester, clock: u64, value: bool, what: &str) {
    assert!(
        tx_at(lt, clock - 1) != value && tx_at(lt, clock) == value,
        "{}: {what}: the IUT's tx should turn {} at clock {clock} (tx at {}..={}: {:?})",
        lt.name(),
        if value { "recessive" } else { "dominant" },
        clock - 3,
        clock + 3,
        (clock - 3..=clock + 3)
            .map(|c| tx_at(lt, c))
            .collect::<Vec<_>>()
    );
}

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

/// 7.7.9: glitch filtering in idle: a dominant pulse shorter than SYNC_SEG +
/// TSEG1 is not a SOF (the IUT stays idle and silent), one tq longer is; after a
/// hard synchronisation no further edge is used before the sample point (pulse
/// group of ISO 16845-1 7.7.9.2 on the 16-tq timing: 4 dominant, 2 recessive, 3
/// dominant, 3 recessive, 9 dominant tq).
pub fn iso_7_7_9_glitch_filtering(iut: &Iut) {
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
    let group = [(4, 2), (3, 3), (9, 1)];
    assert_eq!(
        glitches(iut, timing_wide(), &group),
        (false, false),
        "pulse group"
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
) -> super::lower_tester::Run {
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
        s.push_shaped(&[(Lt::R, bit3)], None, "Intermission 3");
    }
    s.push(Lt::D, None, "SOF");
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
