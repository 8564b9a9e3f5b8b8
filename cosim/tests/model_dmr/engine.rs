//! §4: mailbox matching, the counter step and timer rule, the evaluation verdicts
//! with the sign -> line rule, and the engine schedule (`M + 2` clocks per event).

use super::*;

/// One DMR device (node 0) with a plain partner on each line, started after
/// `setup`; returns (sys, plain on the DCL, plain on the RCL) once the start-up
/// CS frames are through.
fn device(m: usize, setup: impl FnOnce(&mut Sys)) -> (Sys, usize, usize) {
    let mut sys = Sys::with_mailboxes(1, m);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    setup(&mut sys);
    sys.start(0);
    // §7: each line sends its CS frame as soon as its channel leaves reset.
    sys.run_until(300 * CPB, "the start-up CS frames", |s| {
        s.got(pa, &cs(0x7EA)) == 1 && s.got(pb, &cs(0x7EB)) == 1
    });
    sys.run(20 * CPB);
    (sys, pa, pb)
}

#[test]
fn mailbox_match_lowest_index_mask_ide_direction() {
    let (mut sys, pa, pb) = device(16, |s| {
        s.dmr_times(0, 60000, 20, 1000); // no DMR tick during the test
        s.mailbox(0, 0, 0x100, 0x7F0, 3); // receive 0x100..0x10F
        s.mailbox(0, 1, 0x105, 0x7FF, 3); // receive 0x105 (shadowed by 0)
        s.mailbox(0, 2, 0x105 | MB_TX, 0x7FF, 3); // transmit 0x105
        s.mailbox(0, 3, 0x105 | MB_IDE, 0x1FFF_FFFF, 3); // receive extended 0x105
        s.mailbox(0, 4, 0x205, 0x7FF, 3); // receive 0x205
        s.mailbox(0, 5, 0x005, 0x00F, 3); // receive any base id ending in 5
    });
    // §4.1: an event is counted by the lowest-numbered mailbox it matches.
    sys.send(pa, frame(0x105, false, 1, &[1])); // mb 0 (mb 1, 5 also match)
    sys.send(pb, frame(0x105, true, 0, &[])); // mb 3 only (ide), RCL: -1
    sys.send(pa, frame(0x305, false, 0, &[])); // mb 5 only (mask 0x00F)
    sys.send(pa, frame(0x333, false, 0, &[])); // no mailbox
    sys.run(40);
    let want: [(i8, u16); 6] = [(1, 20), (0, 0), (0, 0), (-1, 20), (0, 0), (1, 20)];
    for (i, w) in want.iter().enumerate() {
        assert_eq!(mb_state(&mut sys, 0, i as u32), *w, "mailbox {i}");
    }
}

#[test]
fn counter_step_and_timer_rule() {
    const TO: u16 = 20;
    let (mut sys, pa, pb) = device(16, |s| {
        s.dmr_times(0, 1000, TO as u32, 1000);
        s.mailbox(0, 0, 0x123, 0x7FF, 10);
    });
    let f = frame(0x123, false, 0, &[]);
    // Align just after an evaluation: one tick is 1000 bits, a frame about 50.
    sys.run_ticks(0, 1);
    sys.run(40);
    sys.send(pa, f);
    sys.run(40);
    // DCL copy: c' = +1; c was 0 -> the timer starts at `timeout`.
    assert_eq!(mb_state(&mut sys, 0, 0), (1, TO));
    // Two evaluations: t' = timer - 1 each (§4.2 step 3).
    sys.run_ticks(0, 2);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 0), (1, TO - 2));
    // Another DCL copy: |c'| = 2 > |c| = 1 -> timer unchanged (the leading line).
    sys.send(pa, f);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 0), (2, TO - 2));
    // An RCL copy: |c'| = 1 < 2 -> the lagging line delivered: timer restarts.
    sys.send(pb, f);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 0), (1, TO));
    // Balanced: c' = 0 -> timer stopped.
    sys.send(pb, f);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 0), (0, 0));
    assert_eq!(status(&mut sys, 0).0 & 0x7F, 0, "no fault, active, ACL DCL");
}

#[test]
fn deviation_verdict_against_the_rcl_on_a_positive_counter() {
    let (mut sys, pa, _) = device(16, |s| {
        s.dmr_times(0, 1000, 50, 1000);
        s.mailbox(0, 2, 0x040, 0x7F0, 3); // receive 0x040..0x04F, limit 3
    });
    sys.run_ticks(0, 1);
    sys.run(40);
    for i in 0..3 {
        sys.send(pa, frame(0x040 + i, false, 0, &[]));
    }
    sys.run_ticks(0, 1);
    sys.run(40);
    // |3| is not > limit 3 and the timer runs: no verdict.
    assert_eq!(mb_state(&mut sys, 0, 2), (3, 49));
    assert_eq!(status(&mut sys, 0).flags(), [false; 4]);
    sys.send(pa, frame(0x041, false, 0, &[]));
    sys.run_ticks(0, 1);
    sys.run(40);
    // §4.2 rule 1: |4| > 3 -> DEVIATION; positive: "more messages have been
    // transferred over DCL, hence the RCL is faulty"; a receive mailbox -> rx.
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false, false, false, true], "rcl_rx_fault");
    assert_eq!(
        (st.cause(), st.cause_line(), st.cause_mb()),
        (DEVIATION, RCL, 2)
    );
    assert_eq!(
        st.state(),
        PASSIVE,
        "§6: an rx fault only -> redundancy passive"
    );
    assert_eq!(st.acl(), DCL, "a fault against the PCL does not switch");
    assert_eq!(
        mb_state(&mut sys, 0, 2),
        (0, 0),
        "counter and timer cleared"
    );
    let p = sys.probes(0);
    assert!(p.rcl_rx_fault && !p.dcl_rx_fault && p.dmr_state == PASSIVE && !p.acl);
}

#[test]
fn timeout_verdict_against_the_dcl_on_a_negative_counter_switches_the_acl() {
    // (power-on does not settle, §4.2: the first timeout is judged)
    const TO: u64 = 6;
    let (mut sys, _, pb) = device(16, |s| {
        s.dmr_times(0, 1000, TO as u32, 1000);
        s.mailbox(0, 7, 0x0, 0x0, 3); // receive every base frame
        s.write(0, INT_ENABLE, I_DMR);
    });
    sys.write(0, INT_STATUS, 0x1FF);
    sys.run_ticks(0, 1);
    sys.run(40);
    sys.send(pb, frame(0x77, false, 2, &[1, 2]));
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 7), (-1, TO as u16));
    // §4.2 rule 2: the fault comes at the evaluation where t' = timer - 1 = 0,
    // i.e. the `timeout`-th evaluation after the load.
    sys.run_ticks(0, TO - 1);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 7), (-1, 1));
    assert_eq!(status(&mut sys, 0).flags(), [false; 4]);
    sys.run_ticks(0, 1);
    sys.run(40);
    // Negative: the DCL is faulty; a receive mailbox -> dcl_rx_fault. The DCL is
    // the ACL and the RCL has no flag -> the ACL switches to the RCL (§6).
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false, true, false, false]);
    assert_eq!(
        (st.cause(), st.cause_line(), st.cause_mb()),
        (TIMEOUT, DCL, 7)
    );
    assert_eq!((st.state(), st.acl()), (PASSIVE, RCL));
    assert_eq!((st.state_changes(), st.acl_switches()), (1, 1));
    assert_ne!(sys.read(0, INT_STATUS) & I_DMR, 0, "INT_STATUS.dmr");
    assert!(sys.nodes[0].out.irq, "INT_ENABLE.dmr -> irq");
}

/// §4.2 debt: a timeout keeps the counter. A copy that comes later than the
/// timeout pays the judged line's debt back instead of starting an imbalance
/// that the next expiry would judge against the other line (which carried every
/// frame); while the debt is owed no copy starts the timer and only a deviation
/// judges.
#[test]
fn a_late_copy_pays_the_debt_of_a_timeout_instead_of_judging_the_other_line() {
    const TO: u64 = 6;
    let (mut sys, pa, pb) = device(16, |s| {
        s.dmr_times(0, 1000, TO as u32, 1000);
        s.mailbox(0, 7, 0x0, 0x0, 3); // receive every base frame, limit 3
    });
    sys.run_ticks(0, 1);
    sys.run(40);
    let f = frame(0x77, false, 2, &[1, 2]);
    sys.send(pb, f);
    sys.run_ticks(0, TO);
    sys.run(40);
    // The timeout judged the DCL; the counter is kept as its debt, the timer stopped.
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false, true, false, false], "dcl_rx_fault only");
    assert_eq!((st.cause(), st.cause_line()), (TIMEOUT, DCL));
    assert_eq!(mb_state(&mut sys, 0, 7), (-1, 0), "the debt: counter kept");
    // No second timeout while it is owed, however long.
    sys.run_ticks(0, 2 * TO);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 7), (-1, 0));
    // The late DCL copy pays it back: balanced, timer stopped.
    sys.send(pa, f);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 7), (0, 0));
    sys.run_ticks(0, 2 * TO);
    sys.run(40);
    let st = status(&mut sys, 0);
    assert_eq!(
        st.flags(),
        [false, true, false, false],
        "the sound RCL is never judged"
    );
    // Paid off: the next copy starts the timer again (§4.1).
    sys.send(pb, f);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 7), (-1, TO as u16));
}

/// §4.2 debt: while owed, copies of the other line move the counter without a
/// timer, and a line that keeps losing copies is judged by the deviation, which
/// clears the counter and the debt.
#[test]
fn an_owed_mailbox_is_judged_again_only_by_the_deviation() {
    const TO: u64 = 6;
    let (mut sys, _, pb) = device(16, |s| {
        s.dmr_times(0, 1000, TO as u32, 1000);
        s.mailbox(0, 7, 0x0, 0x0, 3);
    });
    sys.run_ticks(0, 1);
    sys.run(40);
    sys.send(pb, frame(0x70, false, 0, &[]));
    sys.run_ticks(0, TO);
    sys.run(40);
    assert_eq!(mb_state(&mut sys, 0, 7), (-1, 0));
    for (i, want) in [(1u32, -2i8), (2, -3)] {
        sys.send(pb, frame(0x70 + i, false, 0, &[]));
        sys.run_ticks(0, 2 * TO);
        sys.run(40);
        assert_eq!(mb_state(&mut sys, 0, 7), (want, 0), "no timer while owed");
    }
    let before = status(&mut sys, 0);
    assert_eq!((before.cause(), before.cause_line()), (TIMEOUT, DCL));
    sys.send(pb, frame(0x73, false, 0, &[]));
    sys.run_ticks(0, 1);
    sys.run(40);
    // |-4| > 3: DEVIATION against the DCL; counter and debt cleared.
    let st = status(&mut sys, 0);
    assert_eq!((st.cause(), st.cause_line()), (DEVIATION, DCL));
    assert_eq!(st.flags(), [false, true, false, false]);
    assert_eq!(mb_state(&mut sys, 0, 7), (0, 0));
    sys.send(pb, frame(0x74, false, 0, &[]));
    sys.run(40);
    assert_eq!(
        mb_state(&mut sys, 0, 7),
        (-1, TO as u16),
        "the timer runs again"
    );
}

/// The clock at which the DRCC's channel delivered the frame (a plain receiver on
/// the same line delivers it at the same clock) and every MB_STATE read of
/// mailbox 0 after it, as (request clock - that clock, counter).
fn counter_seen(m: usize, phase: u64) -> Vec<(u64, i8)> {
    let (mut sys, pa, _) = device(m, |s| {
        s.dmr_times(0, 60000, 20, 1000);
        s.mailbox(0, 0, 0x0, 0x0, 3);
    });
    let pr = sys.add_plain(DCL);
    sys.run(20 * CPB);
    sys.write(0, MB_SEL, 0);
    sys.plain[pa].req = Some(frame(0x12, false, 0, &[]));
    sys.run_until(200 * CPB, "the frame", |s| !s.plain[pr].received.is_empty());
    let r = sys.plain[pr].received[0].0;
    sys.run(phase);
    let mut seen = Vec::new();
    while sys.clock < r + m as u64 + 12 {
        let at = sys.clock + 1; // the edge that takes the request
        let v = sys.read(0, MB_STATE) as u8 as i8;
        seen.push((at - r, v));
    }
    seen
}

#[test]
fn an_event_is_served_in_m_plus_2_clocks() {
    for m in [16usize, 3] {
        // rx_valid after edge R; pend_rx set at edge R+1 (§4.3: the edge where the
        // pre-edge value shows it); the job runs M+2 edges (IDLE, M x SCAN,
        // UPDATE) and updates the mailbox at edge R+M+3, so a read taken at edge
        // R+M+3 returns the old value and one taken at R+M+4 the new one.
        let mut all = counter_seen(m, 0);
        all.extend(counter_seen(m, 1));
        let n = m as u64;
        assert!(
            all.iter().any(|&(d, _)| d == n + 3),
            "M = {m}: read at R+M+3"
        );
        assert!(
            all.iter().any(|&(d, _)| d == n + 4),
            "M = {m}: read at R+M+4"
        );
        for (d, v) in all {
            assert_eq!(v, (d >= n + 4) as i8, "M = {m}: read at R+{d}");
        }
    }
}

#[test]
fn no_mailboxes_no_counting() {
    // §2: with M = 0 there are no mailboxes; the window is refused.
    let (mut sys, pa, _) = device(0, |s| s.dmr_times(0, 100, 3, 1000));
    sys.send(pa, frame(0x12, false, 0, &[]));
    sys.run_ticks(0, 5);
    assert_eq!(status(&mut sys, 0).0 & 0x7F, 0, "nothing judged");
    assert!(sys.refused(0, MB_SEL, 0));
    assert_eq!(sys.read(0, MB_STATE), 0);
}

/// Every MB_STATE timer read of the last mailbox after a DMR tick, as (request
/// clock - tick clock, timer), reading from `phase` clocks after the tick.
fn timer_seen(m: usize, phase: u64) -> Vec<(u64, u16)> {
    let (mut sys, pa, _) = device(m, |s| {
        s.dmr_times(0, 500, 40, 1000);
        s.mailbox(0, m as u32 - 1, 0x0, 0x0, 3);
    });
    sys.write(0, MB_SEL, m as u32 - 1);
    sys.send(pa, frame(0x12, false, 0, &[]));
    sys.run(40);
    let t = sys.nodes[0].ticks;
    sys.run_until(600 * CPB, "a tick", |s| s.nodes[0].ticks > t);
    let tick = sys.nodes[0].last_tick;
    let before = sys.read(0, MB_STATE) >> 16;
    sys.run(phase);
    let mut seen = vec![(1, before as u16)];
    while sys.clock < tick + m as u64 + 10 {
        let at = sys.clock + 1;
        seen.push((at - tick, (sys.read(0, MB_STATE) >> 16) as u16));
    }
    seen
}

#[test]
fn an_evaluation_visits_mailbox_i_at_m_plus_1_clocks() {
    for m in [16usize, 5] {
        // `dmr_tick` after edge T; pend_eval set at T+1 (§4.3), taken at T+2 (the
        // engine is idle), EVAL of mailbox i at edge T+3+i: the last mailbox
        // (i = M-1) at T+M+2, the evaluation's (M+1)-th edge. A read taken at
        // T+M+2 sees the old timer, one at T+M+3 the decremented one.
        let mut all = timer_seen(m, 0);
        all.extend(timer_seen(m, 1));
        let n = m as u64;
        let old = all[0].1;
        assert!(old > 1, "the timer runs");
        assert!(all.iter().any(|&(d, _)| d == n + 2));
        assert!(all.iter().any(|&(d, _)| d == n + 3));
        for (d, v) in all {
            let want = if d >= n + 3 { old - 1 } else { old };
            assert_eq!(v, want, "M = {m}: read at T+{d}");
        }
    }
}

#[test]
fn dmr_tick_every_tick_bits_nominal_bits() {
    // §3: `tb_cnt` counts nominal bit ticks and wraps at tick_bits - 1; the
    // `dmr_tick` register pulses at the wrap: one pulse per tick_bits x 8 clocks.
    let (mut sys, _, _) = device(16, |s| s.dmr_times(0, 37, 20, 1000));
    let mut at = Vec::new();
    while at.len() < 4 {
        sys.step();
        if sys.probes(0).dmr_tick {
            at.push(sys.clock);
        }
    }
    // (A pulse longer than one clock would show as two entries one clock apart.)
    for w in at.windows(2) {
        assert_eq!(w[1] - w[0], 37 * CPB);
    }
    // Outside DMR mode the probe stays 0 (§9).
    sys.write(0, CTRL, RESET_MODE);
    for _ in 0..100 * CPB {
        sys.step();
        assert!(!sys.probes(0).dmr_tick);
    }
}
