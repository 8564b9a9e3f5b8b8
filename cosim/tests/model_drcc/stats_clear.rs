//! Clearing the statistics (contract §11.4): a `STATS_CLR` write with bit 0 = 1
//! clears `STATS0`, `STATS1`, `OMISSIONS`, `DMR_RX_STATS` and the failures and
//! recoveries counts of `AUX_A` / `AUX_B` at its edge, the clear winning over an
//! event at the same edge; everything else is kept. The counts are produced by
//! scenarios whose results follow from §4.3, §5 and §7, worked out in comments.

use super::filters::{send, send_all, OMISSIONS, STATS_CLR};
use super::*;

/// Redundancy-mode receptions with F = 4 and window 200: two duplicates' worth
/// of pairs, one omission per channel and one overrun; STATS_CLR 0 does nothing,
/// STATS_CLR 1 clears STATS0 and OMISSIONS and leaves the FIFO as it is.
#[test]
fn stats_clr_clears_the_reception_counts() {
    let p = DrccParams {
        rx_fifo_depth: 4,
        ..DrccParams::DEFAULT
    };
    let mut sys = Sys::with_params(1, &p);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    sys.write(0, DEDUP_CFG, 200);
    sys.start(0, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let f: Vec<Frame> = (1..=5)
        .map(|i| frame(0x100 + i, false, false, 1, &[i as u8]))
        .collect();
    // f1 on both: delivered from A, B's copy a duplicate (1).
    send_all(&mut sys, &[(pa, f[0]), (pb, f[0])]);
    // f2 on A only; 300 bits later (> 200) f3 on B only: its scan expires f2's
    // unmatched entry, an omission of B ([31:16]).
    send(&mut sys, pa, &f[1]);
    sys.run(300 * CPB);
    send(&mut sys, pb, &f[2]);
    // 300 bits later f4 on both: f3's entry expires, an omission of A ([15:0]);
    // f4 is the fourth frame in the FIFO, its copy a duplicate (2).
    sys.run(300 * CPB);
    send_all(&mut sys, &[(pa, f[3]), (pb, f[3])]);
    // f5 on both: A's copy overruns the full FIFO (its history entry is still
    // written, §7), B's copy is a duplicate (3).
    send_all(&mut sys, &[(pa, f[4]), (pb, f[4])]);
    let stats0 = 3 | 1 << 16;
    let omissions = 1 | 1 << 16;
    assert_eq!(sys.read(0, STATS0), stats0);
    assert_eq!(sys.read(0, OMISSIONS), omissions);
    let times = sys.read(0, TIMES);

    sys.write(0, STATS_CLR, 0xFFFF_FFFE);
    assert_eq!(sys.read(0, STATS0), stats0, "bit 0 = 0 does nothing");
    assert_eq!(sys.read(0, OMISSIONS), omissions);
    sys.write(0, STATS_CLR, 1);
    assert_eq!(sys.read(0, STATS0), 0, "duplicates and overruns cleared");
    assert_eq!(sys.read(0, OMISSIONS), 0, "omissions cleared");
    assert_eq!(sys.read(0, TIMES), times, "TIMES kept");
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0, "never refused");
    // The FIFO is not a statistic: f1..f4, in order.
    let got: Vec<(Frame, u32)> = (0..4).filter_map(|_| sys.pop(0)).collect();
    assert_eq!(
        got,
        vec![(f[0], 0), (f[1], 0), (f[2], 1), (f[3], 0)],
        "FIFO kept"
    );
    // The counts go on from 0: another pair, one duplicate.
    let g = frame(0x1FF, false, false, 0, &[]);
    send_all(&mut sys, &[(pa, g), (pb, g)]);
    assert_eq!(sys.read(0, STATS0), 1);
}

/// The paper's Fig. 5-7 scenario (error-passive policy, nobody acknowledges on
/// A): one failure and one recovery of channel A, two switch events (failover
/// 0 -> 1 and 1 -> 0, §4.3), TIMES set. Then a second message fails twice on A
/// (failed attempts 2, below error passive). STATS_CLR clears STATS1 and AUX_A's
/// failures and recoveries; it keeps the failed attempts, the latched cause, the
/// state and TIMES.
#[test]
fn stats_clr_clears_switches_and_aux_counts_and_keeps_the_rest() {
    let mut sys = Sys::new(1);
    let pb = sys.add_plain(1, true);
    sys.start(0, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let f = frame(0x2A5, false, false, 2, &[0xC3, 0x3C]);
    sys.push(0, &f, 0);
    sys.run(4000 * CPB);
    assert_eq!(sys.plain[pb].received, vec![f]);
    // STATS1: switches 2, recoveries 1.
    assert_eq!(sys.read(0, STATS1), 2 | 1 << 16);
    // AUX_A: valid, cause error passive ([2]), failures 1, recoveries 1.
    let aux_a = sys.read(0, AUX_A);
    assert_eq!(aux_a, 1 << 2 | 1 << 16 | 1 << 24);
    let times = sys.read(0, TIMES);
    assert_ne!(times >> 16, 0, "switch_time");

    // Channel A again: every attempt an ACK error; after the second (TEC 16),
    // failed attempts 2.
    sys.push(0, &f, 0);
    let mut clocks = 0;
    while sys.nodes[0].out.probes.chan_a_bsp_tx_err_cnt < 16 {
        sys.step();
        clocks += 1;
        assert!(clocks < 400 * CPB, "two ACK errors on A");
    }
    sys.run(2);
    assert_eq!(sys.read(0, AUX_A), aux_a | 2 << 8, "failed attempts 2");
    sys.write(0, STATS_CLR, 1);
    assert_eq!(sys.read(0, STATS1), 0, "switches and recoveries cleared");
    assert_eq!(
        sys.read(0, AUX_A),
        1 << 2 | 2 << 8,
        "failures and recoveries cleared; state, cause, failed attempts kept"
    );
    assert_eq!(sys.read(0, TIMES), times, "TIMES kept");
    assert_eq!(sys.read(0, AUX_B), 0);
}

/// Node 0 (normal mode, F = 4, INT_ENABLE = overrun) holds four frames; plain
/// node A has just been asked for a fifth: it will overrun.
fn overrun_setup() -> Sys {
    let p = DrccParams {
        rx_fifo_depth: 4,
        ..DrccParams::DEFAULT
    };
    let mut sys = Sys::with_params(1, &p);
    let pa = sys.add_plain(0, true);
    sys.write(0, INT_ENABLE, I_OVERRUN);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    for id in 0..4 {
        send(&mut sys, pa, &frame(0x300 + id, false, false, 0, &[]));
    }
    sys.plain[pa].req = Some(frame(0x304, false, false, 0, &[]));
    sys
}

/// From `overrun_setup`, a STATS_CLR write taken at the `at`-th step, then the
/// rest of the frame; returns (STATS0.overruns, INT_STATUS.overrun).
fn clear_at(at: u64) -> (u32, u32) {
    let mut sys = overrun_setup();
    sys.run(at - 1);
    sys.nodes[0].wb = DrccInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: STATS_CLR,
        wb_dat_w: 1,
        wb_sel: 0xF,
        ..Default::default()
    };
    sys.step();
    assert!(sys.nodes[0].out.wb_ack);
    sys.nodes[0].wb = DrccInputs::default();
    sys.run(100 * CPB);
    (
        sys.read(0, STATS0) >> 16,
        sys.read(0, INT_STATUS) & I_OVERRUN,
    )
}

/// §11.4: "An event at the same edge is lost (the clear wins)". The overrun's
/// edge is the one that sets INT_STATUS.overrun (irq one edge later, §8).
#[test]
fn stats_clr_at_the_edge_of_a_count_wins() {
    let mut sys = overrun_setup();
    let mut steps = 0;
    while !sys.nodes[0].out.irq {
        sys.step();
        steps += 1;
        assert!(steps < 200 * CPB, "the fifth frame overruns");
    }
    let edge = steps - 1;
    sys.run(100 * CPB);
    assert_eq!(sys.read(0, STATS0) >> 16, 1, "one overrun without a clear");
    // One edge before: cleared, then counted.
    assert_eq!(clear_at(edge - 1), (1, I_OVERRUN));
    // At the overrun's edge: the clear wins; the interrupt is not a count.
    assert_eq!(clear_at(edge), (0, I_OVERRUN));
    // One edge after: counted, then cleared.
    assert_eq!(clear_at(edge + 1), (0, I_OVERRUN));
}
