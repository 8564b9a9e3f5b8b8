//! The DRCC's sizes as Verilog parameters (drcc_contract.md §1.1), as an
//! integrator uses them: overridden within their offer, the emitted tops stay
//! lint-clean (Verilator -Wall with the waivers, Icarus); outside it, Verilator,
//! Icarus and yosys each stop elaboration with a message naming the parameter and
//! its offer. That an overridden top is the configuration it names is checked on
//! the text (hdl/src/tops/params.rs: `drcc_m0` with small's values is
//! `drcc_small`, which the lock-step suite proves).
//!
//! Without the tools the test is skipped with one line, except in CI
//! (`drcc_tools::need_all`), where it fails.

use std::path::PathBuf;
use std::process::{Command, Output};

use drcc_tools::{IVERILOG, VERILATOR, YOSYS};

fn rtl(top: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("rtl-out")
        .join(format!("{top}.v"))
        .to_string_lossy()
        .into_owned()
}

fn waivers() -> String {
    concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/hdl/lint/verilator_waivers.vlt"
    )
    .to_string()
}

fn text(out: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

fn verilator(top: &str, overrides: &[(&str, usize)]) -> Output {
    let mut cmd = Command::new("verilator");
    cmd.args(["--lint-only", "-Wall"])
        .arg(waivers())
        .arg(rtl(top))
        .args(["--top-module", top]);
    for (k, v) in overrides {
        cmd.arg(format!("-G{k}={v}"));
    }
    cmd.output().expect("verilator runs")
}

fn iverilog(top: &str, overrides: &[(&str, usize)]) -> Output {
    let vvp = std::env::temp_dir().join(format!("drcc-params-{}-{top}.vvp", std::process::id()));
    let mut cmd = Command::new("iverilog");
    cmd.args(["-g2005", "-o"]).arg(&vvp).args(["-s", top]);
    for (k, v) in overrides {
        cmd.arg(format!("-P{top}.{k}={v}"));
    }
    let out = cmd.arg(rtl(top)).output().expect("iverilog runs");
    let _ = std::fs::remove_file(vvp);
    out
}

/// Every size at the smallest value it offers, and the modes off: the corner
/// farthest from the generated defaults.
#[test]
fn overridden_sizes_lint_clean() {
    if !drcc_tools::need_all(&[VERILATOR, IVERILOG]) {
        return;
    }
    let smallest: &[(&str, &[(&str, usize)])] = &[
        (
            "drcc",
            &[
                ("RX_FIFO_DEPTH", 4),
                ("TX_QUEUE_DEPTH", 2),
                ("HISTORY", 4),
                ("STAR", 0),
            ],
        ),
        (
            "drcc_m0",
            &[
                ("RX_FIFO_DEPTH", 4),
                ("TX_QUEUE_DEPTH", 2),
                ("HISTORY", 4),
                ("DMR", 0),
                ("STAR", 0),
            ],
        ),
        (
            "drcc_small",
            &[
                ("RX_FIFO_DEPTH", 32),
                ("TX_QUEUE_DEPTH", 8),
                ("HISTORY", 32),
                ("DMR", 1),
                ("STAR", 1),
            ],
        ),
    ];
    for (top, values) in smallest {
        let out = verilator(top, values);
        assert!(
            out.status.success(),
            "{top} {values:?}: verilator:\n{}",
            text(&out)
        );
        let out = iverilog(top, values);
        assert!(
            out.status.success(),
            "{top} {values:?}: iverilog:\n{}",
            text(&out)
        );
    }
}

/// A value outside the offer is refused by every tool, naming the rule.
#[test]
fn a_size_outside_its_offer_stops_elaboration_naming_it() {
    if !drcc_tools::need_all(&[VERILATOR, IVERILOG, YOSYS]) {
        return;
    }
    let out = verilator("drcc_m0", &[("RX_FIFO_DEPTH", 12)]);
    assert!(!out.status.success(), "verilator took RX_FIFO_DEPTH = 12");
    assert!(
        text(&out).contains("RX_FIFO_DEPTH_must_be_4_8_16_or_32"),
        "{}",
        text(&out)
    );
    let out = iverilog("drcc", &[("TX_QUEUE_DEPTH", 16)]);
    assert!(!out.status.success(), "iverilog took TX_QUEUE_DEPTH = 16");
    assert!(
        text(&out).contains("TX_QUEUE_DEPTH_must_be_2_4_or_8"),
        "{}",
        text(&out)
    );
    let out = Command::new("yosys")
        .args([
            "-q",
            "-p",
            &format!(
                "read_verilog {}; chparam -set HISTORY 64 drcc_small; hierarchy -check -top drcc_small",
                rtl("drcc_small")
            ),
        ])
        .output()
        .expect("yosys runs");
    assert!(!out.status.success(), "yosys took HISTORY = 64");
    assert!(
        text(&out).contains("HISTORY_must_be_4_8_16_or_32"),
        "{}",
        text(&out)
    );
}
