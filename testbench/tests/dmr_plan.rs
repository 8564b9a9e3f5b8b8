//! The CiA 701 DMR test plan (seed 001 Figure 9, Tables 2 and 3; DMR contract §10) on
//! the Verilated RTL in lock step with the reference model: four DRCC devices COS1,
//! COS2, COS3, COM1 in DMR mode on the DCL and the RCL, 125 kbit/s, 85 % load
//! (`drcc_testbench::dmr`). Eleven of the 21 rows run on both engines with every
//! output of every device compared at every clock (the first divergence fails the
//! row), the other ten on the model here and in lock step in the soak
//! (`in_lock_step_here`); the checks below read the rows' outcome.
//!
//! - Table 3 cell for cell: the RCL startup failures F2, F4, F6, F8, F10 give exactly
//!   the seed's DMR state and ACL of every device (read from `DMR_STATUS` at the end of
//!   the fault window);
//! - no application frame lost or duplicated in any single-fault row (one line always
//!   works), startup and run time, and every device back to "redundancy active"
//!   after the fault without a relapse (§4.2 settling);
//! - the fault-free baseline raises no DMR fault and every device stays "redundancy
//!   active" on the DCL.
//!
//! - rows that reach the rest of the DMR function: F1 at run time (a receive fault
//!   against the ACL, the ACL switch and the release of waiting frames), F9 at run
//!   time (every device loses the DCL at once; CS attempts fail; it returns).
//! - first-copy delivery (`CTRL.first_copy`, DMR contract §8.1) on the same rows:
//!   Table 3's cells as with the ACL rule, nothing lost or duplicated, and no
//!   message later than one frame time against the fault-free run (three of its
//!   rows in lock step here, the other 18 in the soak).
//!
//! Without Verilator (outside CI) the rows run on the model alone, and say so.
//!
//! Besides, the plan's network faults (a node detached from a line, a line
//! short-circuited; `drcc_cosim::dual::fault`) are exercised in redundancy mode,
//! which needs no DMR behaviour.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use drcc_cosim::dual::fault::Detach;
use drcc_cosim::dual::{DualBusSystem, Line};
use drcc_cosim::host::{btr, HostConfig, Policy};
use drcc_cosim::Frame;
use drcc_hdl::host::registers::DmrState;
use drcc_testbench::dmr::load::{schedule, summary};
use drcc_testbench::dmr::{
    run_row, Marker, Onset, PlanConfig, Row, RowReport, CLOCKS_PER_BIT, DEVICES,
};
use drcc_testbench::dual::drcc_engine;
use drcc_testbench::engines::{available, verilator_required};
use drcc_testbench::EngineKind;

/// The engine the plan runs on: the Verilated RTL (in lock step with the model, which
/// `run_row` adds as the plan's oracle), or the model alone where Verilator is
/// missing outside CI.
fn engine() -> EngineKind {
    static KIND: OnceLock<EngineKind> = OnceLock::new();
    *KIND.get_or_init(|| match available(EngineKind::Verilator) {
        Ok(()) => EngineKind::Verilator,
        Err(e) if verilator_required() => panic!("Verilator is required here: {e}"),
        Err(e) => {
            eprintln!("the plan runs on the model alone (no lock step with the RTL): {e}");
            EngineKind::Model
        }
    })
}

/// The rows `.ci/run` runs in lock step with the Verilated RTL: the baseline, the
/// five of Table 3 (a device cut from the RCL or the RCL short-circuited, at
/// startup), F1 and F9 at startup and at run time (a device cut from the DCL, the
/// DCL short-circuited: the ACL switches), and F10 at run time (the RCL lost while
/// the network runs); in Table 3's rows each device in turn is the one cut off.
/// The other ten rows run here on the model, with the same checks, and in lock
/// step in the soak (`soak_every_other_row_in_lock_step_with_the_rtl`): a row in
/// lock step costs about five times a row on the model (12 s against 2.4 s on a
/// 2-core machine).
fn in_lock_step_here(row: Row) -> bool {
    use Marker::*;
    matches!(
        (row.marker, row.onset),
        (None, _)
            | (Some(F2 | F4 | F6 | F8 | F10 | F1 | F9), Onset::Startup)
            | (Some(F1 | F9 | F10), Onset::Runtime)
    )
}

/// The first-copy rows (DMR contract §8.1) `.ci/run` runs in lock step: the
/// baseline (both lines deliver, the first copy wins), F1 at run time (a device
/// cut from the ACL: its frames come only on the PCL, delivered at once, and the
/// ACL still switches) and F9 at run time (the whole ACL lost at once). The
/// others run on the model here, in lock step in the soak.
fn first_copy_in_lock_step_here(row: Row) -> bool {
    use Marker::*;
    matches!(
        (row.marker, row.onset),
        (None, _) | (Some(F1 | F9), Onset::Runtime)
    )
}

/// Each row runs once per test binary and rule (`first_copy`), shared by the
/// tests that look at it: a test asking for a row another test is running waits
/// for it instead of running it too.
fn report_with(row: Row, first_copy: bool) -> RowReport {
    type Cell = Arc<OnceLock<RowReport>>;
    static CACHE: OnceLock<Mutex<HashMap<(Row, bool), Cell>>> = OnceLock::new();
    let cell = CACHE
        .get_or_init(|| Mutex::new(HashMap::new()))
        .lock()
        .unwrap()
        .entry((row, first_copy))
        .or_default()
        .clone();
    cell.get_or_init(|| {
        let (plan, lock_step) = if first_copy {
            (
                PlanConfig::standard().first_copy(),
                first_copy_in_lock_step_here(row),
            )
        } else {
            (PlanConfig::standard(), in_lock_step_here(row))
        };
        let on = if lock_step {
            engine()
        } else {
            EngineKind::Model
        };
        run_row(&plan, row, on, None).unwrap_or_else(|e| panic!("{}: {e}", row.name()))
    })
    .clone()
}

/// A row with the seed's ACL rule.
fn report(row: Row) -> RowReport {
    report_with(row, false)
}

/// Runs `rows` of one rule on two threads (the rows are independent; the other
/// tests of this binary take theirs from the cache).
fn run_all(rows: &[Row], first_copy: bool) {
    std::thread::scope(|s| {
        for half in rows.chunks(rows.len().div_ceil(2)) {
            s.spawn(move || {
                half.iter()
                    .for_each(|&row| drop(report_with(row, first_copy)))
            });
        }
    });
}

fn startup(m: Marker) -> Row {
    Row {
        marker: Some(m),
        onset: Onset::Startup,
    }
}

use DmrState::{RedundancyDisabled as DISABLED, RedundancyPassive as PASSIVE};

/// Seed 001, Table 3 "Acceptance criteria upon RCL startup failure": per fault, the
/// DMR state and ACL of COS1, COS2, COS3, COM1 (every ACL is the DCL).
const TABLE_3: [(Marker, [DmrState; 4]); 5] = [
    (Marker::F2, [DISABLED, PASSIVE, PASSIVE, PASSIVE]),
    (Marker::F4, [PASSIVE, DISABLED, PASSIVE, PASSIVE]),
    (Marker::F6, [PASSIVE, PASSIVE, DISABLED, PASSIVE]),
    (Marker::F8, [PASSIVE, PASSIVE, PASSIVE, DISABLED]),
    (Marker::F10, [DISABLED, DISABLED, DISABLED, DISABLED]),
];

#[test]
fn table_3_rcl_startup_failures_cell_for_cell() {
    let mut differ = Vec::new();
    for (m, states) in TABLE_3 {
        let r = report(startup(m));
        for (d, want) in states.into_iter().enumerate() {
            let got = r.during[d];
            if got.state() != Some(want) || got.acl() != Line::A {
                differ.push(format!(
                    "{} {}: seed {want:?} / DCL, model {} (DMR_STATUS {:#010x})",
                    m.name(),
                    DEVICES[d],
                    got.cell(),
                    got.word
                ));
            }
        }
    }
    assert!(
        differ.is_empty(),
        "cells differing from seed Table 3:\n{}",
        differ.join("\n")
    );
}

#[test]
fn no_single_fault_loses_or_duplicates_a_frame_or_relapses() {
    let rows = Row::all();
    run_all(&rows, false);
    let bad: Vec<String> = rows
        .into_iter()
        .flat_map(|row| problems(&report(row)))
        .collect();
    assert!(
        bad.is_empty(),
        "(receiver, sender, seq):\n{}",
        bad.join("\n")
    );
}

/// First-copy delivery (DMR contract §8.1) on the same 21 rows: every device's
/// DMR state and ACL at the end of the fault window are those of the ACL rule
/// (the seed's Table 3 unchanged: the diagnosis does not depend on the delivery
/// rule), nothing is lost or duplicated, every device is back to "redundancy
/// active" without a relapse, and no message comes later than one frame time
/// (the plan's longest frame, stuff bits and intermission included) after the
/// fault-free first-copy run delivered it.
#[test]
fn first_copy_keeps_table_3_and_loses_no_time() {
    let rows = Row::all();
    run_all(&rows, true);
    run_all(&rows, false);
    let plan = PlanConfig::standard().first_copy();
    let frame_time = summary(&plan, &schedule(&plan)).max_bits * CLOCKS_PER_BIT;
    let base = report_with(Row::BASELINE, true);
    let mut bad = Vec::new();
    for row in rows {
        let (acl, fc) = (report(row), report_with(row, true));
        let name = row.name();
        for (d, (a, f)) in acl.during.iter().zip(&fc.during).enumerate() {
            if a.cell() != f.cell() {
                bad.push(format!(
                    "{name} {}: ACL rule {}, first copy {}",
                    DEVICES[d],
                    a.cell(),
                    f.cell()
                ));
            }
        }
        bad.extend(problems(&fc));
        match fc.extra_latency(&base) {
            Some(late) if late > frame_time as i64 => bad.push(format!(
                "{name}: a message {late} clocks later than without the fault (one frame \
                 time: {frame_time})"
            )),
            Some(_) => {}
            None => bad.push(format!("{name}: no message delivered in both runs")),
        }
    }
    assert!(bad.is_empty(), "first copy:\n{}", bad.join("\n"));
}

/// What is wrong with a row: a frame lost, duplicated, foreign or never pushed,
/// or a device not back to "redundancy active" after the fault, or relapsing.
fn problems(r: &RowReport) -> Vec<String> {
    let mut bad = Vec::new();
    let name = r.row.name();
    // §4.2 settling and §7: after the fault every device is "redundancy
    // active" again and stays so (no false fault when the traffic pauses)
    if r.row.marker.is_some() && (r.recovery().is_none() || r.relapse.is_some()) {
        bad.push(format!(
            "{name}: back to redundancy active {:?} clocks after the removal, relapse {:?}",
            r.recovery(),
            r.relapse
        ));
    }
    if !r.exactly_once() || r.unpushed != 0 {
        bad.push(format!(
            "{name}: {} lost (first {:?}), {} duplicated (first {:?}), {} foreign, {} never pushed",
            r.lost.len(),
            r.lost.first(),
            r.duplicated.len(),
            r.duplicated.first(),
            r.foreign,
            r.unpushed
        ));
    }
    bad
}

/// The soak (scripts/soak.sh): the rows the suite runs on the model alone, in
/// lock step with the Verilated RTL, with the same checks (each rule's).
#[test]
#[ignore = "soak: scripts/soak.sh runs it"]
fn soak_every_other_row_in_lock_step_with_the_rtl() {
    let rows: Vec<(Row, bool)> = Row::all()
        .into_iter()
        .filter(|&r| !in_lock_step_here(r))
        .map(|r| (r, false))
        .chain(
            Row::all()
                .into_iter()
                .filter(|&r| !first_copy_in_lock_step_here(r))
                .map(|r| (r, true)),
        )
        .collect();
    assert_eq!(rows.len(), 10 + 18);
    let reports = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for half in rows.chunks(rows.len().div_ceil(2)) {
            let reports = &reports;
            s.spawn(move || {
                for &(row, first_copy) in half {
                    let plan = if first_copy {
                        PlanConfig::standard().first_copy()
                    } else {
                        PlanConfig::standard()
                    };
                    let r = run_row(&plan, row, engine(), None)
                        .unwrap_or_else(|e| panic!("{}: {e}", row.name()));
                    reports.lock().unwrap().push(r);
                }
            });
        }
    });
    let bad: Vec<String> = reports
        .into_inner()
        .unwrap()
        .iter()
        .flat_map(problems)
        .collect();
    assert!(
        bad.is_empty(),
        "(receiver, sender, seq):\n{}",
        bad.join("\n")
    );
}

#[test]
fn the_baseline_raises_no_dmr_fault() {
    let r = report(Row::BASELINE);
    assert_eq!(r.detection, None, "a fault flag in the fault-free run");
    assert_eq!(r.acl_switch, None);
    assert_eq!(
        r.last_not_active, None,
        "some device left redundancy active"
    );
    for (d, s) in r.during.iter().chain(&r.end).enumerate() {
        assert_eq!(
            (s.state(), s.acl()),
            (Some(DmrState::RedundancyActive), Line::A),
            "{} ({:#010x})",
            DEVICES[d % 4],
            s.word
        );
    }
    assert!(r.exactly_once());
    assert!(r.pushed > 800, "the 85 % load pushes ~900 frames in 1 s");
}

fn runtime(m: Marker) -> Row {
    Row {
        marker: Some(m),
        onset: Onset::Runtime,
    }
}

#[test]
fn f1_at_run_time_switches_cos1_to_the_rcl_for_good() {
    let r = report(runtime(Marker::F1));
    assert!(r.detection.is_some(), "the cut was detected");
    assert!(r.acl_switch.is_some(), "COS1 switched its ACL to the RCL");
    // §6: the switch is non-revertive
    assert_eq!(r.end[0].acl(), Line::B, "COS1 stays on the RCL");
    assert_eq!(
        r.end[1].acl(),
        Line::B,
        "COS2 switched too: COS1's frames were missing on its DCL"
    );
}

#[test]
fn f9_at_run_time_moves_every_device_to_the_rcl_and_the_dcl_returns() {
    let r = report(runtime(Marker::F9));
    for (d, s) in r.during.iter().enumerate() {
        assert_eq!(
            (s.state(), s.acl()),
            (Some(DISABLED), Line::B),
            "{} during the short circuit ({:#010x})",
            DEVICES[d],
            s.word
        );
    }
    assert!(r.recovered.is_some(), "the DCL returned after the fault");
}

// ---- the plan's network faults, in redundancy mode (no DMR behaviour needed) ----

/// Clocks per bit of the redundancy-mode runs (8 one-clock quanta).
const CPB: u64 = 8;

fn redundancy_system(frames: usize) -> DualBusSystem {
    let config = HostConfig {
        btr: btr(0, 5, 2, 1, false, 96),
        redundancy: true,
        policy: Policy::KFailed(2),
        dual_tx: true,
        dedup_window: 2000,
        ..HostConfig::default()
    };
    let engines = (0..4)
        .map(|_| drcc_engine(EngineKind::Model).unwrap())
        .collect();
    let mut sys = DualBusSystem::new(engines, vec![config; 4]).unwrap();
    for n in 0..4 {
        for k in 0..frames {
            let f = Frame {
                id: 0x100 + 0x20 * n as u32 + k as u32 % 0x20,
                ide: false,
                rtr: false,
                dlc: 2,
                data: [n as u8, k as u8, 0, 0, 0, 0, 0, 0],
            };
            sys.node_mut(n)
                .host
                .submit((100 + 600 * k as u64 + 37 * n as u64) * CPB, f, 0);
        }
    }
    sys
}

/// Steps `sys` until its hosts are done and the lines quiet; returns per node
/// whether its auxiliary FSM ever judged channel A failed (left `valid`).
fn run_tracking_a(sys: &mut DualBusSystem) -> Vec<bool> {
    let mut failed = vec![false; 4];
    for _ in 0..20_000 * CPB {
        sys.step();
        for (n, f) in failed.iter_mut().enumerate() {
            *f |= sys.node(n).outputs.probes.aux_a_state != 0;
        }
    }
    assert!(
        sys.run_until_quiet(200 * CPB, 20_000 * CPB),
        "did not settle"
    );
    failed
}

/// Every host got every other host's frames exactly once.
fn assert_exactly_once(sys: &DualBusSystem, frames: usize, what: &str) {
    for (rx, n) in sys.nodes().iter().enumerate() {
        let mut seen = vec![vec![0; frames]; 4];
        for got in &n.host.received {
            seen[got.frame.data[0] as usize][got.frame.data[1] as usize] += 1;
        }
        for (tx, counts) in seen.iter().enumerate() {
            if tx != rx {
                assert!(
                    counts.iter().all(|&c| c == 1),
                    "{what}: node {rx} got node {tx}'s frames {counts:?} times"
                );
            }
        }
    }
}

#[test]
fn a_node_detached_from_line_a_reaches_everyone_over_line_b() {
    let frames = 12;
    let mut sys = redundancy_system(frames);
    sys.detach(
        Line::A,
        Detach {
            node: 0,
            start: 0,
            cycles: u64::MAX,
        },
    )
    .unwrap();
    let worst = run_tracking_a(&mut sys);
    assert_exactly_once(&sys, frames, "node 0 detached from line A");
    // Its stub is open: its channel A hears no acknowledgement, so its own frames
    // fail there (ACK errors) and it leaves channel A; the others never notice.
    assert_eq!(worst, [true, false, false, false]);
    assert!(sys
        .detach(
            Line::B,
            Detach {
                node: 4,
                start: 0,
                cycles: 1
            }
        )
        .is_err());
    assert!(sys
        .detach(
            Line::B,
            Detach {
                node: 1,
                start: 0,
                cycles: 0
            }
        )
        .is_err());
}

#[test]
fn a_short_circuited_line_a_takes_every_node_off_it() {
    let frames = 12;
    let mut sys = redundancy_system(frames);
    sys.short_circuit(Line::A, 0, u64::MAX).unwrap();
    let worst = run_tracking_a(&mut sys);
    assert_exactly_once(&sys, frames, "line A short-circuited");
    // No transmitter ever reads back its dominant bits on line A: bit errors, and
    // every node leaves channel A.
    assert_eq!(worst, [true; 4]);
}
