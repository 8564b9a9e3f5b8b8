//! Small DMR networks reproducing the seed: Table 1 (Figure 5: DEV3 cut from the
//! DCL: DEV3 "Redundancy disabled", DEV1 and DEV2 "Redundancy passive") and
//! Table 3 ("RCL startup failure", the fault markers of §10).

use super::*;

/// `n` DMR devices, each sending its own identifier 0x100 + i and counting it in a
/// transmit mailbox 0, and counting device k's messages in receive mailbox 1 + k. `setup` applies the fault; `rounds` rounds of one message per
/// device follow the start.
fn network(
    n: usize,
    rounds: usize,
    at_power_on: impl Fn(&mut Sys),
    after_start: impl Fn(&mut Sys),
) -> (Sys, Vec<DmrStatus>) {
    let mut sys = Sys::new(n);
    // A bus monitor on each line (a plain node, as the analyser of the seed's
    // test set-up): devices started together send identical CS frames in
    // lock-step, and a frame needs a receiver's acknowledgement.
    sys.add_plain(DCL);
    sys.add_plain(RCL);
    at_power_on(&mut sys);
    for d in 0..n {
        // 100 bits per tick, timeouts of 10 ticks, no recovery within the test.
        sys.dmr_times(d, 100, 10, 5000);
        sys.mailbox(d, 0, (0x100 + d as u32) | MB_TX, 0x7FF, 3);
        // One receive mailbox per other device's message (seed: a counter per
        // mailbox; one mailbox for all would let one sender balance another).
        for k in (0..n).filter(|&k| k != d) {
            sys.mailbox(d, 1 + k as u32, 0x100 + k as u32, 0x7FF, 3);
        }
    }
    for d in 0..n {
        sys.start(d);
    }
    sys.run(400 * CPB);
    after_start(&mut sys);
    for r in 0..rounds {
        for d in 0..n {
            sys.push(d, &frame(0x100 + d as u32, false, 1, &[r as u8]));
        }
        sys.run(400 * CPB);
    }
    let st: Vec<DmrStatus> = (0..n).map(|d| status(&mut sys, d)).collect();
    (sys, st)
}

#[test]
fn seed_table_1_dev3_cut_from_the_dcl() {
    // Figure 5: "the CAN line DCL is interrupted at device DEV3", after start-up.
    let (sys, st) = network(3, 6, |_| {}, |s| s.nodes[2].wire[DCL] = None);
    // DEV3: D3.M1 "has not been sent on DCL (which is the ACL at this time) after
    // expiration of the configured mailbox timeout", so it switches to the RCL:
    // its transmit counter is negative -> DCL, tx -> redundancy disabled.
    assert_eq!(st[2].state(), DISABLED, "DEV3");
    assert!(st[2].flags()[0], "dcl_tx_fault on DEV3");
    assert_eq!((st[2].cause_line(), st[2].acl()), (DCL, RCL));
    // DEV1, DEV2: "detect an error condition by detecting a receive counter
    // difference": D3 frames on the RCL only -> negative -> the DCL, rx.
    for (d, s) in st.iter().enumerate().take(2) {
        assert_eq!(s.state(), PASSIVE, "DEV{}", d + 1);
        assert_eq!(s.flags(), [false, true, false, false], "DEV{}", d + 1);
        assert_eq!(s.acl(), RCL, "DEV{}: the fault was against the ACL", d + 1);
        let p = sys.probes(d);
        assert!(p.dcl_rx_fault && p.dmr_state == PASSIVE && p.acl);
    }
}

#[test]
fn seed_table_3_rcl_startup_failure() {
    // Four devices COS1, COS2, COS3, COM1. F2, F4, F6, F8: device k cut from the
    // RCL at power-on; F10: the RCL short-circuited (§10).
    for fault in [2usize, 4, 6, 8, 10] {
        let (_, st) = network(
            4,
            5,
            |s| {
                if fault == 10 {
                    s.short[RCL] = true;
                } else {
                    s.nodes[fault / 2 - 1].wire[RCL] = None;
                }
            },
            |_| {},
        );
        for (d, s) in st.iter().enumerate() {
            let want = if fault == 10 || d == fault / 2 - 1 {
                DISABLED
            } else {
                PASSIVE
            };
            // Table 3: every row keeps "ACL: DCL" (the faults are on the RCL, the PCL).
            assert_eq!((s.state(), s.acl()), (want, DCL), "F{fault}, device {d}");
            // The disabled ones cannot transmit on the RCL; the passive ones
            // miss the cut device's RCL copies.
            let rcl_tx = want == DISABLED;
            assert_eq!(s.flags()[2], rcl_tx, "F{fault}, device {d}: rcl_tx_fault");
            assert!(
                !s.flags()[0] && !s.flags()[1],
                "F{fault}, device {d}: DCL sound"
            );
        }
    }
}
