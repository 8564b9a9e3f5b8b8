//! REDCAN rings of DRCC nodes (`ring_contract.md`), the centralized algorithm
//! (seed 000 §3) on a CanKingdom King (seed 002): for every fault kind of §3 at
//! every position, on 3 ring nodes with a plain node on every section, the
//! ring ends with every working node on one bus (no partition) and that bus a
//! line terminated once at each end (ring contract §1, §5), within the paper's
//! bound (4 T1 to detect, 2 T2 to scan, T1 = 30 ms, T2 = 500 ms: 1.12 s) plus the
//! settling of the final decisions.

use drcc_testbench::engines::EngineKind;
use drcc_testbench::ring::{run, RingFault, RingScenario};

fn faults(n: usize) -> Vec<RingFault> {
    let mut v = vec![RingFault::None];
    for s in 0..n {
        v.push(RingFault::SectionOpen {
            section: s,
            point: 1,
        });
        v.push(RingFault::SectionShort { section: s });
    }
    // Ring node 0 is the master: the paper leaves its replacement open (a
    // crashed or babbling master is not a row of the centralized algorithm).
    for i in 1..n {
        v.push(RingFault::Babbling { node: i });
        v.push(RingFault::Crash { node: i });
    }
    v
}

fn check(n: usize) {
    for f in faults(n) {
        let s = RingScenario::standard(n, f);
        let r = run(&s, EngineKind::Model).unwrap_or_else(|e| panic!("{f:?}: {e}"));
        let what = format!("{n} ring nodes, {f:?}: {r:?}");
        assert!(r.kingdom_at.is_some(), "the kingdom started: {what}");
        assert!(r.no_partition, "no partition: {what}");
        assert!(
            r.single_termination,
            "one line, terminated once at each end: {what}"
        );
        assert_eq!(r.refused, 0, "{what}");
        if f == RingFault::None {
            assert!(r.detected.is_none() && r.lost.is_empty(), "{what}");
            // The fault-free ring: the master holds both terminations (Fig. 4/5).
            assert_eq!(r.final_modes[0], 1, "{what}");
            assert!(r.final_modes[1..].iter().all(|&m| m == 3), "{what}");
        } else {
            let (_, at) = r.detected.expect("detected");
            assert!(
                at - r.onset <= 4 * 30_000 + 1_000,
                "detection within 4 T1: {what}"
            );
            let rebuilt = r.last_relay_change.map_or(0, |t| t - r.onset);
            assert!(
                rebuilt <= 1_300_000,
                "rebuilt within 4 T1 + 2 T2 + the final lag: {what}"
            );
        }
        // Every working node is reachable at the end.
        for (i, w) in r.working.iter().enumerate() {
            assert!(!w || r.reachable[i], "node {i} reachable: {what}");
        }
    }
}

#[test]
fn three_ring_nodes_recover_from_every_single_fault() {
    check(3);
}
