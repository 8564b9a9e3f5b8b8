//! §8: the ACL rule: frames of the passive line wait in the history and are
//! released at an ACL switch, oldest first, each frame delivered once; §8.1:
//! first-copy delivery.

use super::*;

#[test]
fn pcl_frames_held_and_released_at_the_acl_switch() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    // timeout 10 ticks x 200 bits = 2000 bits; §8 window must exceed it.
    sys.dmr_times(0, 200, 10, 1000);
    sys.write(0, DEDUP_CFG, 5000);
    sys.mailbox(0, 0, 0, 0, 10); // receive every base frame, limit 10
    sys.start(0);
    sys.run_until(300 * CPB, "the start-up CS frames", |s| {
        s.got(pa, &cs(0x7EA)) == 1 && s.got(pb, &cs(0x7EB)) == 1
    });
    let f: Vec<Frame> = (1..=5)
        .map(|i| frame(0x100 + i, false, 2, &[i as u8, 0x5A]))
        .collect();
    // F1..F3 arrive on the RCL only: the PCL. They wait (not delivered).
    for x in &f[..3] {
        sys.send(pb, *x);
    }
    sys.run(100);
    assert_eq!(rx_count(&mut sys, 0), 0, "PCL frames wait");
    assert_eq!(sys.read(0, DMR_RX_STATS), 3, "pcl_frames 3");
    // §4.2: counter -3, unbalanced for `timeout` ticks -> fault against the DCL
    // (rx), the ACL; the RCL is sound -> switch -> release (§8).
    sys.run_until(15 * 200 * CPB, "the ACL switch", |s| s.probes(0).acl);
    sys.run(200);
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false, true, false, false]);
    assert_eq!(st.acl(), RCL);
    // Oldest first, each once, tagged with their line (1 = RCL).
    let got = sys.drain(0);
    assert_eq!(got, f[..3].iter().map(|x| (*x, 1)).collect::<Vec<_>>());
    assert_eq!(sys.read(0, DMR_RX_STATS), 3 | 3 << 16, "released 3");
    // A late copy on the new PCL (the DCL) is a duplicate of a released frame.
    sys.send(pa, f[0]);
    // The new ACL delivers at once; its copy on the PCL is dropped.
    sys.send(pb, f[3]);
    sys.send(pa, f[3]);
    // A PCL copy first: it waits, the ACL copy delivers it (once).
    sys.send(pa, f[4]);
    sys.run(100);
    assert_eq!(rx_count(&mut sys, 0), 1, "F4 only; F5 waits for the ACL");
    sys.send(pb, f[4]);
    sys.run(100);
    assert_eq!(sys.drain(0), vec![(f[3], 1), (f[4], 1)]);
    assert_eq!(
        sys.read(0, STATS0) & 0xFFFF,
        2,
        "duplicates: F1, F4 on the DCL"
    );
    // pcl_frames: 3 + F1, F4, F5 on the DCL = 6; released 3; expired 0.
    assert_eq!(sys.read(0, DMR_RX_STATS), 6 | 3 << 16);
}

#[test]
fn without_history_the_acl_delivers_and_the_pcl_is_dropped() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    sys.write(0, DEDUP_CFG, 0);
    sys.start(0);
    sys.run(300 * CPB);
    let a = frame(0x11, false, 1, &[1]);
    let b = frame(0x12, false, 1, &[2]);
    sys.send(pa, a);
    sys.send(pb, b);
    sys.send(pb, a);
    sys.run(100);
    // §8 "With window = 0 there is no history: ACL frames are delivered, PCL
    // frames dropped."
    assert_eq!(sys.drain(0), vec![(a, 0)]);
    assert_eq!(sys.read(0, DMR_RX_STATS) & 0xFFFF, 2);
}

/// `CTRL.first_copy` (§8.1; the DRCC contract's `CTRL[19]`).
const FIRST_COPY: u32 = 1 << 19;
/// `OMISSIONS` (drcc_contract.md §3): [15:0] frames only channel B delivered.
const OMISSIONS: u8 = 37;

/// §8.1: with first-copy delivery the first copy from either line reaches the
/// host at once, tagged with its line, and the second is dropped; frames of the
/// PCL are still counted, nothing waits (`released` and `expired` stay 0), a
/// frame only one line carried counts as an omission of the other when its
/// entry expires, and the diagnosis goes on (the DCL that lost a frame is judged
/// and the ACL switches, §4.2, §6).
#[test]
fn first_copy_delivers_either_line_once() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    // timeout 10 ticks x 200 bits = 2000 bits; window 5000 bit times.
    sys.dmr_times(0, 200, 10, 1000);
    sys.write(0, DEDUP_CFG, 5000);
    sys.mailbox(0, 0, 0, 0, 10); // receive every base frame, limit 10
    sys.write(0, CTRL, DMR | FIRST_COPY);
    assert_eq!(sys.read(0, CTRL) & (DMR | FIRST_COPY), DMR | FIRST_COPY);
    sys.run_until(300 * CPB, "the start-up CS frames", |s| {
        s.got(pa, &cs(0x7EA)) == 1 && s.got(pb, &cs(0x7EB)) == 1
    });
    let f: Vec<Frame> = (1..=4)
        .map(|i| frame(0x100 + i, false, 2, &[i as u8, 0xA5]))
        .collect();
    // F1 first on the RCL, the PCL: delivered at once; its DCL copy is dropped.
    sys.send(pb, f[0]);
    sys.run(100);
    assert_eq!(sys.drain(0), vec![(f[0], 1)], "the PCL's first copy");
    sys.send(pa, f[0]);
    sys.run(100);
    assert_eq!(rx_count(&mut sys, 0), 0, "the second copy is dropped");
    // F2 first on the DCL: delivered from it; the RCL copy is dropped.
    sys.send(pa, f[1]);
    sys.send(pb, f[1]);
    sys.run(100);
    assert_eq!(sys.drain(0), vec![(f[1], 0)]);
    // F3 on the RCL only: delivered.
    sys.send(pb, f[2]);
    sys.run(100);
    assert_eq!(sys.drain(0), vec![(f[2], 1)]);
    assert_eq!(sys.read(0, STATS0) & 0xFFFF, 2, "duplicates: F1, F2");
    // pcl_frames: the RCL's F1, F2, F3; released 0, expired 0.
    assert_eq!(sys.read(0, DMR_RX_STATS), 3);
    // F3's missing DCL copy: the counter stays -1 until the timer runs out, a
    // receive fault against the DCL, the ACL; the RCL is sound: the ACL switches.
    sys.run_until(15 * 200 * CPB, "the ACL switch", |s| s.probes(0).acl);
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false, true, false, false]);
    assert_eq!(st.acl(), RCL);
    // After the window a scan expires F3's entry: an omission of the DCL.
    sys.run(5100 * CPB);
    sys.send(pa, f[3]);
    sys.run(100);
    assert_eq!(
        sys.drain(0),
        vec![(f[3], 0)],
        "the new PCL's frame, at once"
    );
    assert_eq!(sys.read(0, OMISSIONS), 1, "F3: only channel B delivered it");
    // pcl_frames: + F4 on the DCL, now the PCL; still nothing released or expired.
    assert_eq!(sys.read(0, DMR_RX_STATS), 4);
}

/// §8.1: without a history (`window = 0`) there is no duplicate removal, so
/// first-copy delivery keeps the ACL rule instead of delivering every frame twice.
#[test]
fn first_copy_without_history_keeps_the_acl_rule() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    sys.write(0, DEDUP_CFG, 0);
    sys.write(0, CTRL, DMR | FIRST_COPY);
    sys.run(300 * CPB);
    let a = frame(0x11, false, 1, &[1]);
    let b = frame(0x12, false, 1, &[2]);
    sys.send(pa, a);
    sys.send(pb, b);
    sys.send(pb, a);
    sys.run(100);
    assert_eq!(sys.drain(0), vec![(a, 0)]);
    assert_eq!(sys.read(0, DMR_RX_STATS) & 0xFFFF, 2);
}
