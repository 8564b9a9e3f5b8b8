//! DMR mode on the Verilated RTL, in lock step with the reference model (DMR contract;
//! CiA 701 as in seed 001): rows of the seed's test plan (four devices COS1, COS2,
//! COS3, COM1 and a monitor on the DCL and the RCL, 125 kbit/s, 85 % load, 1.1 s)
//! whose faults reach every part of the DMR function, every output of every device
//! compared at every clock (`drcc_testbench::dmr::run_row` stops at the first
//! divergence). The whole table runs the same way with
//! `drcc dmr table --engine verilator`.
//!
//! - F2 at power-on (COS1 cut from the RCL): the power-on connection service, a
//!   transmit fault and the deletion of the RCL copies on COS1, receive faults on the
//!   others, recovery with restart and CS frame; seed Table 3's row;
//! - F1 at run time (COS1 cut from the DCL): a receive fault against the ACL, the
//!   ACL switch and the release of the waiting PCL frames;
//! - F9 at run time (the DCL short-circuited): every device loses its ACL at once,
//!   CS attempts fail, the line returns after the fault.

use drcc_cosim::dual::Line;
use drcc_hdl::host::registers::DmrState;
use drcc_testbench::dmr::{run_row, Marker, Onset, PlanConfig, Row, RowReport, DEVICES};
use drcc_testbench::engines::verilator_required;
use drcc_testbench::EngineKind;

/// The row on the Verilated RTL in lock step with the model, or `None` outside CI
/// without Verilator (said on stderr).
fn cosim(marker: Marker, onset: Onset) -> Option<RowReport> {
    let row = Row {
        marker: Some(marker),
        onset,
    };
    match run_row(&PlanConfig::standard(), row, EngineKind::Verilator, None) {
        Ok(r) => Some(r),
        Err(e) if e.contains("divergence") || verilator_required() => {
            panic!("{}: {e}", row.name())
        }
        Err(e) => {
            eprintln!("skipped outside CI: {e}");
            None
        }
    }
}

fn assert_exactly_once(r: &RowReport) {
    assert!(
        r.exactly_once() && r.unpushed == 0,
        "{}: {} lost, {} duplicated, {} foreign",
        r.row.name(),
        r.lost.len(),
        r.duplicated.len(),
        r.foreign
    );
}

#[test]
fn f2_at_power_on_matches_the_model_and_seed_table_3() {
    let Some(r) = cosim(Marker::F2, Onset::Startup) else {
        return;
    };
    assert_exactly_once(&r);
    // seed Table 3, row F2: COS1 redundancy disabled, the others passive, ACL = DCL
    let want = [
        DmrState::RedundancyDisabled,
        DmrState::RedundancyPassive,
        DmrState::RedundancyPassive,
        DmrState::RedundancyPassive,
    ];
    for (d, w) in want.into_iter().enumerate() {
        assert_eq!(
            (r.during[d].state(), r.during[d].acl()),
            (Some(w), Line::A),
            "{} ({:#010x})",
            DEVICES[d],
            r.during[d].word
        );
    }
    assert!(r.recovered.is_some(), "the RCL returned after the fault");
}

#[test]
fn f1_at_run_time_switches_the_acl_and_matches_the_model() {
    let Some(r) = cosim(Marker::F1, Onset::Runtime) else {
        return;
    };
    assert_exactly_once(&r);
    assert!(r.detection.is_some(), "the cut was detected");
    assert!(r.acl_switch.is_some(), "COS1 switched its ACL to the RCL");
    // §6: the switch is non-revertive
    assert_eq!(r.end[0].acl(), Line::B, "COS1 stays on the RCL");
}

#[test]
fn f9_at_run_time_moves_every_device_to_the_rcl_and_matches_the_model() {
    let Some(r) = cosim(Marker::F9, Onset::Runtime) else {
        return;
    };
    assert_exactly_once(&r);
    for (d, s) in r.during.iter().enumerate() {
        assert_eq!(
            (s.state(), s.acl()),
            (Some(DmrState::RedundancyDisabled), Line::B),
            "{} during the short circuit ({:#010x})",
            DEVICES[d],
            s.word
        );
    }
    assert!(r.recovered.is_some(), "the DCL returned after the fault");
}
