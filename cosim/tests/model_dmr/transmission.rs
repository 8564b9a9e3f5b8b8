//! §5: both lines send every host message from the one queue; the host gets one
//! `tx_done` per message (at its first copy); the faulty line's copies are deleted
//! and it returns after recovery with only the messages queued since.

use super::*;

/// Node 0 with a plain partner per line and a transmit mailbox 0 for 0x300..0x3FF.
fn sender(tick_bits: u32, timeout: u32, recovery: u32) -> (Sys, usize, usize) {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    sys.dmr_times(0, tick_bits, timeout, recovery);
    sys.mailbox(0, 0, 0x300 | MB_TX, 0x700, 10);
    sys.start(0);
    sys.run_until(300 * CPB, "the start-up CS frames", |s| {
        s.got(pa, &cs(0x7EA)) == 1 && s.got(pb, &cs(0x7EB)) == 1
    });
    sys.run(20 * CPB);
    sys.write(0, INT_STATUS, 0x1FF);
    (sys, pa, pb)
}

#[test]
fn both_lines_send_at_once_and_the_host_gets_one_tx_done() {
    let (mut sys, pa, pb) = sender(1000, 20, 1000);
    let f = frame(0x301, false, 3, &[1, 2, 3]);
    sys.push(0, &f);
    sys.run_until(200 * CPB, "both copies", |s| {
        s.got(pa, &f) == 1 && s.got(pb, &f) == 1
    });
    sys.run(20 * CPB);
    // One tx_done (a bit set once), never tx_failure in DMR mode (§2.1).
    assert_eq!(
        sys.read(0, INT_STATUS) & (I_TX_DONE | I_TX_FAILURE),
        I_TX_DONE
    );
    sys.write(0, INT_STATUS, I_TX_DONE);
    sys.run(200 * CPB);
    assert_eq!(sys.read(0, INT_STATUS) & I_TX_DONE, 0, "no second tx_done");
    assert_eq!(
        (sys.got(pa, &f), sys.got(pb, &f)),
        (1, 1),
        "one copy per line"
    );
    assert_eq!(txq_count(&mut sys, 0), 0, "both lines sent it: freed");
    // §4.1: one TX per line -> +1 -1 = balanced, timer stopped.
    assert_eq!(mb_state(&mut sys, 0, 0), (0, 0));
}

#[test]
fn first_copy_completes_the_message_second_copy_only_counts() {
    let (mut sys, pa, pb) = sender(1000, 20, 1000);
    // The RCL is busy with a long frame of another node: the RCL copy waits.
    let other = frame(0x100, false, 8, &[0xAA; 8]);
    sys.plain[pb].req = Some(other);
    sys.run(8 * CPB);
    let f = frame(0x302, false, 0, &[]);
    sys.push(0, &f);
    assert_eq!(txq_count(&mut sys, 0), 1);
    sys.run_until(200 * CPB, "the DCL copy", |s| s.got(pa, &f) == 1);
    assert_eq!(sys.got(pb, &f), 0, "the RCL copy still waits");
    // tx_done comes one bit after the receivers' rx_valid (EOF bit 7, §C).
    sys.run(3 * CPB);
    assert_eq!(sys.read(0, INT_STATUS) & I_TX_DONE, I_TX_DONE, "first copy");
    sys.write(0, INT_STATUS, I_TX_DONE);
    // The queue holds the message for the lagging line (§5: `p` = min offset).
    assert_eq!(txq_count(&mut sys, 0), 1);
    assert_eq!(mb_state(&mut sys, 0, 0).0, 1, "TX(DCL) counted");
    sys.run_until(300 * CPB, "the RCL copy", |s| s.got(pb, &f) == 1);
    sys.run(20 * CPB);
    assert_eq!(
        sys.read(0, INT_STATUS) & I_TX_DONE,
        0,
        "the second copy is silent"
    );
    assert_eq!(txq_count(&mut sys, 0), 0);
    assert_eq!(mb_state(&mut sys, 0, 0), (0, 0), "TX(RCL) balanced it");
}

#[test]
fn faulty_line_copies_are_deleted_and_it_returns_after_recovery() {
    const RECOVERY: u64 = 40;
    let (mut sys, pa, pb) = sender(200, 8, RECOVERY as u32);
    // Cut the RCL at the device: its transceiver hears only itself, no ACK.
    sys.nodes[0].wire[RCL] = None;
    let m: Vec<Frame> = (1..=3)
        .map(|i| frame(0x300 + i, false, 1, &[i as u8]))
        .collect();
    for f in &m {
        sys.push(0, f);
    }
    sys.run_until(600 * CPB, "the DCL copies", |s| {
        m.iter().all(|f| s.got(pa, f) == 1)
    });
    sys.run(10 * CPB);
    // Held for the RCL, which is stuck on its first copy.
    assert_eq!(txq_count(&mut sys, 0), 3);
    assert_eq!(mb_state(&mut sys, 0, 0).0, 3, "three TX(DCL), no TX(RCL)");
    // §4.2: the counter stays unbalanced for `timeout` ticks -> TIMEOUT; positive
    // -> the RCL; a transmit mailbox -> rcl_tx_fault: redundancy disabled.
    sys.run_until(20 * 200 * CPB, "the tx fault", |s| s.probes(0).rcl_tx_fault);
    sys.run(10);
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false, false, true, false]);
    assert_eq!(
        (st.cause(), st.cause_line(), st.cause_mb()),
        (TIMEOUT, RCL, 0)
    );
    assert_eq!(
        (st.state(), st.acl()),
        (DISABLED, DCL),
        "the PCL failed: no switch"
    );
    // Deletion: the RCL's pending copies are gone, the queue is free.
    assert_eq!(txq_count(&mut sys, 0), 0);
    // Its attempt was aborted: the RCL pin goes quiet (after the running attempt).
    sys.run(40 * CPB);
    for _ in 0..100 * CPB {
        sys.step();
        assert!(sys.nodes[0].out.chan_b_tx, "no more attempts on the RCL");
    }
    // A message sent while the RCL is faulty: DCL only, completes at once, and
    // §4.1: transfers do not count while a line has tx_fault.
    let m4 = frame(0x304, false, 0, &[]);
    sys.push(0, &m4);
    sys.run_until(200 * CPB, "m4 on the DCL", |s| s.got(pa, &m4) == 1);
    sys.run(10);
    assert_eq!(txq_count(&mut sys, 0), 0);
    // §4.2 debt: the timeout kept the counter (the RCL owes its three copies),
    // and m4 did not count; REQ(DCL) still loads the timer, but an owed mailbox
    // is judged only by a deviation.
    assert_eq!(mb_state(&mut sys, 0, 0).0, 3);
    assert_eq!(status(&mut sys, 0).flags(), [false, false, true, false]);
    // Repair the RCL; after `recovery_delay` ticks the line restarts and sends its
    // CS frame; success clears the flag (§7).
    sys.nodes[0].wire[RCL] = Some(RCL);
    sys.run_until((RECOVERY + 5) * 200 * CPB, "the recovery CS frame", |s| {
        s.got(pb, &cs(0x7EB)) == 2
    });
    sys.run(20 * CPB);
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false; 4]);
    assert_eq!((st.state(), st.acl()), (ACTIVE, DCL));
    // Return: the RCL sends only what is queued from now on.
    let m5 = frame(0x305, false, 0, &[]);
    sys.push(0, &m5);
    sys.run_until(200 * CPB, "m5 on both lines", |s| {
        s.got(pa, &m5) == 1 && s.got(pb, &m5) == 1
    });
    for f in m.iter().chain([&m4]) {
        assert_eq!(sys.got(pb, f), 0, "{f:?} was deleted from the RCL");
    }
    sys.run(20 * CPB);
    assert_eq!(
        mb_state(&mut sys, 0, 0),
        (0, 0),
        "both copies counted again"
    );
}

/// §4.2 settling of a transmit mailbox: a recovery clears the counters while the
/// device's own frame has gone out on the DCL and still waits on the RCL (busy
/// with frames no mailbox counts), so the RCL copy unbalances the cleared
/// counter. Its first timeout re-balances it: no fault against the DCL, which
/// carried the frame. (A transmit mailbox that did not settle judged the DCL
/// here, and the deletion of §5 then sent the device's frames on the RCL only.)
#[test]
fn a_transmit_mailbox_settles_after_a_recovery_between_two_copies() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    // Ticks of 100 bit times, a 20-tick timeout, a 10-tick recovery delay.
    sys.dmr_times(0, 100, 20, 10);
    sys.mailbox(0, 0, 0x300 | MB_TX, 0x700, 10);
    sys.mailbox(0, 1, 0x100, 0x700, 10);
    sys.start(0);
    sys.run_until(300 * CPB, "the start-up CS frames", |s| {
        s.got(pa, &cs(0x7EA)) == 1 && s.got(pb, &cs(0x7EB)) == 1
    });
    sys.run(20 * CPB);
    // A receive fault against the DCL: a frame of mailbox 1 on the RCL only.
    sys.send(pb, frame(0x101, false, 0, &[]));
    sys.run_until(30 * 100 * CPB, "dcl_rx_fault", |s| s.probes(0).dcl_rx_fault);
    // The RCL busy with 14 frames of 0x050 (no mailbox; it wins arbitration), the
    // device's own frame pushed at once: its DCL copy goes now, its RCL copy after
    // them, and the DCL's recovery (10 ticks, then the CS frame) comes between.
    let filler = frame(0x050, false, 8, &[0x55; 8]);
    let f = frame(0x301, false, 1, &[7]);
    let mut fillers = 1;
    let mut done = sys.plain[pb].done;
    sys.plain[pb].req = Some(filler);
    sys.push(0, &f);
    let (mut dcl_copy, mut recovered, mut rcl_copy) = (None, None, None);
    let end = sys.clock + 60 * 100 * CPB;
    while sys.clock < end {
        sys.step();
        if sys.plain[pb].done > done {
            done = sys.plain[pb].done;
            if fillers < 14 {
                sys.plain[pb].req = Some(filler);
                fillers += 1;
            }
        }
        let p = sys.probes(0);
        assert!(
            !p.dcl_tx_fault && !p.rcl_tx_fault,
            "a transmit fault at clock {}",
            sys.clock
        );
        if dcl_copy.is_none() && sys.got(pa, &f) == 1 {
            dcl_copy = Some(sys.clock);
        }
        if recovered.is_none() && !p.dcl_rx_fault {
            recovered = Some(sys.clock);
        }
        if rcl_copy.is_none() && sys.got(pb, &f) == 1 {
            rcl_copy = Some(sys.clock);
        }
    }
    let (d, r, c) = (
        dcl_copy.expect("the DCL copy"),
        recovered.expect("the recovery"),
        rcl_copy.expect("the RCL copy"),
    );
    assert!(
        d < r && r < c,
        "the recovery between the two copies: {d} {r} {c}"
    );
    // 60 ticks: well past the RCL copy's timeout (20 ticks), re-balanced.
    assert!(end > c + 25 * 100 * CPB);
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false; 4], "no line judged");
    // Active again; the receive fault against the ACL had switched it (§6).
    assert_eq!((st.state(), st.acl()), (ACTIVE, RCL));
    // Re-balanced (§4.2: counter 0, no debt); the timer may still run down a
    // REQ's load (§4.1), which judges nothing at a balanced counter.
    assert_eq!(mb_state(&mut sys, 0, 0).0, 0, "re-balanced");
}
