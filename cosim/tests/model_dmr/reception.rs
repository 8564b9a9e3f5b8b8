//! §8: the ACL rule: frames of the passive line wait in the history and are
//! released at an ACL switch, oldest first, each frame delivered once.

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
