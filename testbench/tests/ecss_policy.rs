//! The ECSS bus selection (DRCC contract §12) on a dual bus: a redundancy
//! master (node 0) and three nodes that follow its heartbeat
//! (`drcc redundancy ecss`). What ECSS-E-ST-50-15C's bus selection asks:
//! a node follows the master to the other bus within `Ttoggle` heartbeat
//! periods of a fault; `Ctoggle` counts the toggles; `Ntoggle` bounds the
//! toggling when the master is silent; and nothing is lost, since the
//! controller keeps retransmitting a frame until the switch moves it (Table 1's
//! abort and resend). The model and the Verilated RTL run in lock step (a
//! divergence fails), and the refusals of §12.1 are compared register by
//! register on both.

use drcc_cosim::dual::DualBusSystem;
use drcc_cosim::engine::drcc_verilator::DrccVerilatorEngine;
use drcc_cosim::host::{reg, HostConfig};
use drcc_hdl::host::registers::MAP;
use drcc_testbench::drcc_build::DrccBuild;
use drcc_testbench::ecss::{run_ecss, EcssFault, EcssReport, EcssScenario};
use drcc_testbench::engines::lockstep_engine;
use drcc_testbench::EngineKind;

fn cosim_engine() -> Option<EngineKind> {
    lockstep_engine("DRCC", || DrccVerilatorEngine::new().map(|_| ()))
}

fn run(s: &EcssScenario) -> EcssReport {
    let r = run_ecss(s, EngineKind::Model, cosim_engine()).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        r.exactly_once(),
        "{}: missing {:?}, duplicates {:?}",
        s.label(),
        r.missing,
        r.duplicates
    );
    assert!(
        r.expected > 200,
        "{}: the traffic ran ({} expected)",
        s.label(),
        r.expected
    );
    r
}

const FOLLOWERS: std::ops::Range<usize> = 1..4;

/// A line fault that silences the master on line A: it fails over to B, every
/// node follows `Ttoggle x consumer time` after the master's last heartbeat on
/// A (less the one or two bit times by which a receiver validates a frame
/// before its transmitter, plus at most one frame and its error frame when the
/// node's own attempt on A must end first), and all come back to A after the
/// fault: two toggles each, nothing lost.
#[test]
fn nodes_follow_the_master_through_line_faults() {
    for fault in [EcssFault::AStuckDominant, EcssFault::AStuckRecessive] {
        let s = EcssScenario::standard(fault);
        let r = run(&s);
        let bound = s.toggle_bound_bits();
        for n in FOLLOWERS {
            let follow = r
                .follow_bits(n)
                .unwrap_or_else(|| panic!("{fault:?}: node {n} never moved"));
            assert!(
                (bound - 3..=bound + 160).contains(&follow),
                "{fault:?}: node {n} moved {follow} bit times after the master's last heartbeat on A (Ttoggle x consumer time = {bound})"
            );
            assert_eq!(
                r.status(n, "ctoggle"),
                2,
                "{fault:?}: node {n} went to B and back"
            );
            assert_eq!(
                r.moves[n].len(),
                2,
                "{fault:?}: node {n}'s traffic moved twice"
            );
            assert_eq!(r.status(n, "bus"), 0, "{fault:?}: node {n} ends on A");
            assert_eq!(r.status(n, "no_master"), 0);
        }
    }
}

/// Without a fault nothing toggles.
#[test]
fn no_fault_no_toggle() {
    let r = run(&EcssScenario::standard(EcssFault::None));
    for n in FOLLOWERS {
        assert_eq!(r.status(n, "ctoggle"), 0);
        assert!(r.moves[n].is_empty());
    }
}

/// A master that falls silent: every node toggles exactly `Ntoggle` times,
/// `Ttoggle x consumer time` apart, then gives up (`no_master`) and stays; with
/// `Ntoggle` 0 it never toggles. The nodes' own traffic is delivered
/// throughout (each hears both buses).
#[test]
fn ntoggle_bounds_the_search_for_a_silent_master() {
    for ntoggle in [3u8, 0] {
        let s = EcssScenario {
            ntoggle,
            ..EcssScenario::standard(EcssFault::MasterSilent)
        };
        let r = run(&s);
        let bound = s.toggle_bound_bits();
        for n in FOLLOWERS {
            assert_eq!(
                r.status(n, "ctoggle"),
                ntoggle as u32,
                "{}: node {n}",
                s.label()
            );
            assert_eq!(
                r.moves[n].len(),
                ntoggle as usize,
                "{}: node {n}",
                s.label()
            );
            assert_eq!(
                r.status(n, "no_master"),
                1,
                "{}: node {n} gave up",
                s.label()
            );
            for w in r.moves[n].windows(2) {
                let apart = (w[1] - w[0]) / drcc_testbench::dual::CLOCKS_PER_BIT;
                assert!(
                    (bound - 160..=bound + 160).contains(&apart),
                    "{}: node {n}'s toggles {apart} bit times apart (Ttoggle x consumer time = {bound})",
                    s.label()
                );
            }
        }
    }
}

/// §12.1's refusals on the model and the Verilated RTL in lock step: each
/// illegal write sets `INT_STATUS.illegal` and leaves the register as it was;
/// the legal ones are stored.
#[test]
fn illegal_ecss_values_are_refused_on_both_engines() {
    let kinds: Vec<EngineKind> = std::iter::once(EngineKind::Model)
        .chain(cosim_engine())
        .collect();
    let put = |r: &str, f: &str, v: u32| MAP.field(r, f).put(v);
    let illegal = MAP.field("INT_STATUS", "illegal").put(1);
    let legal_cfg = put("ECSS_CFG", "ttoggle", 2) | put("ECSS_CFG", "ntoggle", 4);
    // (register, value, refused)
    let writes = [
        (reg::ECSS_CFG, legal_cfg, false),
        (reg::ECSS_CFG, put("ECSS_CFG", "ntoggle", 1), true), // ttoggle 0
        (reg::ECSS_CFG, 5 | 0x100 << 8, true),                // ntoggle 256
        (reg::ECSS_CFG, 5 | 1 << 27, true),                   // reserved
        (reg::ECSS_HB, 0x3 << 30 | 0x701, true),
        (reg::ECSS_HB, 0x123, false),
        (reg::ECSS_PERIOD, 0, true),
        (reg::ECSS_PERIOD, 1 << 24 | 7, true),
        (reg::ECSS_PERIOD, 7, false),
        (reg::ECSS_STATUS, 0, true), // read-only
    ];
    let mut results = vec![];
    for kind in kinds {
        let engines = vec![DrccBuild::Default.engine(kind).unwrap()];
        let cfg = HostConfig::default();
        let mut sys = DualBusSystem::new(engines, vec![cfg]).unwrap();
        // stay in reset mode: the ECSS registers are cfg
        let ctrl_reset = cfg.ctrl(true);
        sys.node_mut(0).host.write(reg::CTRL, ctrl_reset);
        let mut expect = vec![];
        let mut stored = [3 | 3 << 8, 0x701, 100_000];
        for &(r, v, refused) in &writes {
            sys.node_mut(0).host.write(reg::INT_STATUS, u32::MAX);
            sys.node_mut(0).host.write(r, v);
            sys.node_mut(0).host.read(reg::INT_STATUS);
            sys.node_mut(0).host.read(r.min(reg::ECSS_PERIOD));
            if !refused {
                stored[(r - reg::ECSS_CFG) as usize] = v;
            }
            expect.push((
                refused,
                stored[(r.min(reg::ECSS_PERIOD) - reg::ECSS_CFG) as usize],
            ));
        }
        let mut clocks = 0;
        while sys.node(0).host.reads.len() < 2 * writes.len() {
            sys.step();
            clocks += 1;
            assert!(clocks < 100_000, "{kind}: the host did not finish");
        }
        let got: Vec<(bool, u32)> = sys.node(0).host.reads[..]
            .chunks(2)
            .map(|p| (p[0].value & illegal != 0, p[1].value))
            .collect();
        assert_eq!(got, expect, "{kind}: (refused, stored) after each write");
        results.push(got);
    }
    assert!(
        results.windows(2).all(|w| w[0] == w[1]),
        "the engines agree"
    );
}
