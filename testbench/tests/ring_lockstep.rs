//! Lock step of whole REDCAN ring runs (`drcc_testbench::ring::lockstep`): the
//! Verilated DRCC nodes and relay modules match the reference model clock by clock
//! (every input and output of every DRCC node, every RCM output) on a 3-node ring
//! with a plain node per section, from power-up (the CanKingdom start-up) to the
//! end of the recovery, through the runs that exercise the most (measured on the
//! model over every fault of the 3-node ring):
//!
//! - distributed, section 1 shorted: the most relay changes (13), error flags on
//!   the stuck-dominant line, a controller restart on every relay change;
//! - distributed, the master (ring node 0) babbling: a transmitter stuck dominant
//!   (about 700 error flags, TEC above 128), the master's relay held;
//! - centralized, ring node 1 crashed: a node without power (its outputs frozen,
//!   its relay falling to rest), the master's scan;
//! - centralized, section 2 open after its plain node: the most error flags
//!   (about 2,700: the nodes cut off the bus transmit without acknowledgement).
//!
//! No ring run measured (every single fault on 3 ring nodes, the shorts and
//! babbling idiots on 6) takes a controller to bus-off: the hosts restart the
//! controller on every relay change.
//!
//! The comparison sees a real difference: two model runs that differ only in a
//! section short diverge, at the onset, on the line the short pulls dominant.
//! A missing Verilator skips the Verilator tests locally and fails them in CI.

use std::time::Instant;

use drcc_cosim::engine::rcm::rcm_engine;
use drcc_cosim::host::reg;
use drcc_cosim::model::field::ERROR_FLAG;
use drcc_cosim::ring::RingSystem;
use drcc_hdl::host::registers::MAP;
use drcc_testbench::dual::drcc_engine;
use drcc_testbench::ring::lockstep::{compare_runs, run_lockstep, Unit};
use drcc_testbench::ring::{RingFault, RingScenario};
use drcc_testbench::EngineKind;

/// Whether the Verilated DRCC and RCM can be built here (else skipped, or failed
/// in CI).
fn verilator_present() -> bool {
    let built = drcc_engine(EngineKind::Verilator)
        .map(|_| ())
        .and_then(|()| rcm_engine("verilator").map(|_| ()));
    drcc_tools::verilated("drcc and rcm tops", built).is_some()
}

/// What a run went through after the fault onset, seen after every clock of the
/// model run.
#[derive(Debug, Default)]
struct Seen {
    /// Error flags started (a node's `chan_a_field` entering ERROR_FLAG).
    error_flags: u32,
    /// Controller restarts: a host's write of `CTRL` with `reset_mode` set.
    restarts: u32,
    /// Relay mode changes since power-up, summed over the RCMs (their `changes`).
    relay_changes: u32,
    /// Per node: the last `chan_a_field`, and whether it was writing `CTRL`.
    was: Vec<(u8, bool)>,
}

impl Seen {
    fn observe(&mut self, sys: &RingSystem, onset: u64) {
        self.was.resize(sys.nodes().len(), (0, false));
        let after = sys.cycle() > onset;
        for (n, was) in sys.nodes().iter().zip(&mut self.was) {
            let (i, field) = (n.inputs, n.outputs.probes.chan_a_field);
            let restart = i.wb_cyc
                && i.wb_stb
                && i.wb_we
                && i.wb_adr == reg::CTRL
                && MAP.field("CTRL", "reset_mode").get(i.wb_dat_w) == 1;
            if after {
                self.error_flags += (field == ERROR_FLAG && was.0 != ERROR_FLAG) as u32;
                self.restarts += (restart && !was.1) as u32;
            }
            *was = (field, restart);
        }
        self.relay_changes = (sys.modules().iter())
            .map(|m| m.outputs.changes as u32)
            .sum();
    }
}

/// `s` on the model and on Verilator in lock step: no divergence on any clock, the
/// ring recovered, and after the onset the run went through error flags (unless
/// `quiet`: a crash causes none), controller restarts and relay changes.
fn model_matches_verilator(s: RingScenario, quiet: bool) {
    if !verilator_present() {
        return;
    }
    let t = Instant::now();
    let mut seen = Seen::default();
    let l = run_lockstep(&s, EngineKind::Model, EngineKind::Verilator, |sys| {
        seen.observe(sys, s.onset_us);
        Ok(())
    })
    .unwrap_or_else(|e| panic!("{s:?}: {e}"));
    seen.was.clear();
    eprintln!(
        "{:?} {:?}: {} clocks in lock step in {:.1} s; {seen:?}",
        s.algorithm,
        s.fault,
        l.clocks,
        t.elapsed().as_secs_f64()
    );
    if let Some(d) = &l.divergence {
        panic!("{:?} {:?}: {d}", s.algorithm, s.fault);
    }
    assert_eq!(l.clocks, s.onset_us + s.after_us, "every clock compared");
    let r = &l.report;
    assert!(r.detected.is_some(), "the fault was detected: {r:?}");
    assert!(r.no_partition && r.single_termination, "recovered: {r:?}");
    assert!(r.last_relay_change.is_some(), "relays switched: {r:?}");
    assert!(seen.relay_changes >= 5, "relays switched: {seen:?}");
    assert!(seen.restarts >= 1, "controllers restarted: {seen:?}");
    assert!(quiet || seen.error_flags >= 1, "error flags: {seen:?}");
}

#[test]
fn distributed_section_short_model_matches_verilator_every_clock() {
    let s = RingScenario::distributed(3, RingFault::SectionShort { section: 1 });
    model_matches_verilator(s, false);
}

#[test]
fn distributed_babbling_master_model_matches_verilator_every_clock() {
    let s = RingScenario::distributed(3, RingFault::Babbling { node: 0 });
    model_matches_verilator(s, false);
}

#[test]
fn centralized_node_crash_model_matches_verilator_every_clock() {
    let s = RingScenario::standard(3, RingFault::Crash { node: 1 });
    model_matches_verilator(s, true);
}

#[test]
fn centralized_section_open_model_matches_verilator_every_clock() {
    let s = RingScenario::standard(
        3,
        RingFault::SectionOpen {
            section: 2,
            point: 1,
        },
    );
    model_matches_verilator(s, false);
}

/// Two model runs, the second with a section short at the onset: the lock step
/// finds them equal up to the onset and names the first difference, a DRCC node's
/// receive pin pulled dominant by the short (1 in the fault-free run, 0 in the
/// other), within the few bit times a stuck-dominant line takes to show.
#[test]
fn runs_that_differ_diverge_where_they_differ() {
    let mut quiet = RingScenario::standard(3, RingFault::None);
    quiet.onset_us = 340_000;
    quiet.after_us = 5_000;
    let short = RingScenario {
        fault: RingFault::SectionShort { section: 1 },
        ..quiet
    };
    let l = compare_runs(
        (&quiet, EngineKind::Model),
        (&short, EngineKind::Model),
        |_| Ok(()),
    )
    .unwrap();
    let d = l.divergence.expect("the runs differ");
    eprintln!("{d}");
    assert!(
        d.cycle >= quiet.onset_us && d.cycle < quiet.onset_us + 13 * 8,
        "at the onset: {d}"
    );
    assert_eq!(l.clocks, d.cycle + 1, "the second run stopped there: {d}");
    assert!(matches!(d.unit, Unit::Node(_)), "{d}");
    assert_eq!((d.signal, d.left, d.right), ("chan_a_rx", 1, 0), "{d}");
    assert_eq!((d.left_engine, d.right_engine), ("model", "model"));
    // The same scenario twice: no divergence, every clock compared.
    let same = compare_runs(
        (&quiet, EngineKind::Model),
        (&quiet, EngineKind::Model),
        |_| Ok(()),
    )
    .unwrap();
    assert!(same.divergence.is_none(), "{:?}", same.divergence);
    assert_eq!(same.clocks, quiet.onset_us + quiet.after_us);
}
