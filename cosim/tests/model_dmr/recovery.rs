//! §6, §7: the connection service (start-up CS frames, good / bad counts with a
//! swapped wiring, periodic CS), bus-off -> tx_fault with an ACL switch, and the
//! recovery after `recovery_delay` with a restart and a CS frame.

use super::*;

#[test]
fn cs_frames_at_start_and_good_counts() {
    let mut sys = Sys::new(2);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    sys.mailbox(0, 0, 0, 0, 3); // receive every base frame
    sys.start(0);
    // §7: power-on is the first recovery: each line sends its CS frame at once.
    sys.run_until(300 * CPB, "node 0's CS frames", |s| {
        s.got(pa, &cs(0x7EA)) == 1 && s.got(pb, &cs(0x7EB)) == 1
    });
    assert_eq!(sys.got(pa, &cs(0x7EB)), 0, "each line its own identifier");
    sys.start(1);
    sys.run(300 * CPB);
    // Node 0 heard node 1's CS frames: DCL good 1, RCL good 1.
    assert_eq!(sys.read(0, DMR_CS_COUNT), 1 | 1 << 16);
    assert_eq!(
        sys.read(1, DMR_CS_COUNT),
        0,
        "node 0's came before node 1 ran"
    );
    // CS frames never reach the host nor a mailbox.
    assert_eq!(rx_count(&mut sys, 0), 0);
    assert_eq!(mb_state(&mut sys, 0, 0), (0, 0));
    assert_eq!(status(&mut sys, 0).0 & 0x7F, 0);
}

#[test]
fn swapped_wiring_counts_bad() {
    let mut sys = Sys::new(2);
    sys.add_plain(DCL);
    sys.add_plain(RCL);
    // Node 1's DCL pins on the RCL cable and vice versa.
    sys.nodes[1].wire = [Some(RCL), Some(DCL)];
    sys.start(0);
    sys.run(300 * CPB);
    sys.start(1);
    sys.run(300 * CPB);
    // Node 1 sends cs_id_dcl on the RCL cable: node 0's RCL sees the DCL's
    // identifier -> RCL bad; and cs_id_rcl on the DCL cable -> DCL bad.
    assert_eq!(sys.read(0, DMR_CS_COUNT), 1 << 8 | 1 << 24);
    // Periodic CS from node 0 (cs_period): node 1 counts them bad too.
    assert_eq!(sys.read(1, DMR_CS_COUNT), 0);
}

#[test]
fn periodic_cs_every_cs_period_ticks() {
    const P: u64 = 4;
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    sys.dmr_times(0, 200, 10, 1000);
    sys.write(0, DMR_CFG, 10 | (P as u32) << 16);
    sys.start(0);
    sys.run_ticks(0, 3 * P);
    sys.run(100 * CPB);
    // One at start, one every `cs_period` ticks on each line (§7).
    assert_eq!((sys.got(pa, &cs(0x7EA)), sys.got(pb, &cs(0x7EB))), (4, 4));
}

#[test]
fn bus_off_sets_tx_fault_switches_the_acl_and_recovers() {
    const RECOVERY: u64 = 30;
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(DCL);
    let pb = sys.add_plain(RCL);
    sys.dmr_times(0, 100, 10, RECOVERY as u32);
    sys.write(0, INT_ENABLE, I_DMR);
    sys.start(0);
    sys.run_until(300 * CPB, "the start-up CS frames", |s| {
        s.got(pa, &cs(0x7EA)) == 1 && s.got(pb, &cs(0x7EB)) == 1
    });
    sys.write(0, INT_STATUS, 0x1FF);
    // The DCL short-circuited: every node reads recessive, the transmitter's
    // dominant bits fail until it is bus-off.
    sys.short[DCL] = true;
    let f = frame(0x123, false, 1, &[9]);
    sys.push(0, &f);
    sys.run_until(2000 * CPB, "bus-off", |s| s.probes(0).dcl_tx_fault);
    let t0 = sys.nodes[0].ticks;
    sys.short[DCL] = false;
    assert_eq!(
        sys.probes(0).chan_a_err_state,
        2,
        "the DCL channel is bus-off"
    );
    let p = sys.probes(0);
    // §6: bus-off -> tx_fault; the DCL was the ACL and the RCL is sound -> switch.
    // (`dmr_state` is loaded from the flags one edge later.)
    assert!(p.acl);
    sys.run(10);
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [true, false, false, false]);
    assert_eq!((st.cause(), st.cause_line()), (BUSOFF, DCL));
    assert_eq!((st.state(), st.acl()), (DISABLED, RCL));
    assert_eq!((st.state_changes(), st.acl_switches()), (1, 1));
    assert_ne!(sys.read(0, INT_STATUS) & I_DMR, 0);
    // The message still reaches the network, on the RCL, with one tx_done.
    sys.run_until(200 * CPB, "the RCL copy", |s| s.got(pb, &f) == 1);
    sys.run(10);
    assert_ne!(sys.read(0, INT_STATUS) & I_TX_DONE, 0);
    assert_eq!(txq_count(&mut sys, 0), 0);
    // §7 recovery: `rec_timer` = recovery_delay counts DMR ticks; at 0 the line
    // restarts and sends its CS frame (the bus-off recovery, 128 x 11 bits, is
    // over long before: 30 ticks are 3000 bits).
    sys.run_until((RECOVERY + 3) * 100 * CPB, "the recovery CS frame", |s| {
        s.got(pa, &cs(0x7EA)) == 2
    });
    assert_eq!(
        sys.nodes[0].ticks - t0,
        RECOVERY,
        "CS in the tick after the delay"
    );
    sys.run(10);
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false; 4], "CS success clears the flags");
    // Non-revertive: the RCL stays the ACL.
    assert_eq!((st.state(), st.acl()), (ACTIVE, RCL));
    assert_eq!((st.state_changes(), st.acl_switches()), (2, 1));
    assert_eq!(
        sys.read(0, 8) >> 24 & 3,
        0,
        "the DCL channel is error active"
    );
}

#[test]
fn cs_attempt_without_ack_fails_after_timeout() {
    // A device whose RCL stub is cut at power-on (the seed's Table 3, F2 for one
    // device): its RCL CS frame is never acknowledged -> CS failed after `timeout`.
    const TO: u64 = 5;
    let mut sys = Sys::new(1);
    sys.add_plain(DCL);
    sys.add_plain(RCL);
    sys.nodes[0].wire[RCL] = None;
    sys.dmr_times(0, 100, TO as u32, 1000);
    sys.start(0);
    sys.run_ticks(0, TO - 1);
    sys.run(10);
    assert_eq!(status(&mut sys, 0).flags(), [false; 4], "still trying");
    sys.run_ticks(0, 1);
    sys.run(10);
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [false, false, true, false]);
    assert_eq!((st.cause(), st.cause_line()), (CS_FAILED, RCL));
    assert_eq!((st.state(), st.acl()), (DISABLED, DCL));
}

#[test]
fn both_lines_cut_is_network_disconnected() {
    let mut sys = Sys::new(1);
    sys.nodes[0].wire = [None, None];
    sys.dmr_times(0, 100, 5, 1000);
    sys.start(0);
    sys.run_ticks(0, 6);
    sys.run(10);
    // §6: both tx_fault -> network disconnected. The fault against the ACL (DCL)
    // finds the other line flagged (or flagged at the same edge): no switch.
    let st = status(&mut sys, 0);
    assert_eq!(st.flags(), [true, false, true, false]);
    assert_eq!((st.state(), st.acl()), (DISCONNECTED, DCL));
    // Messages wait in the queue; pushes are accepted until it is full (§5).
    for i in 0..8 {
        sys.push(0, &frame(0x10 + i, false, 0, &[]));
    }
    assert_eq!(txq_count(&mut sys, 0), 8);
    assert!(sys.refused(0, TX_CMD, 1), "the ninth push");
}
