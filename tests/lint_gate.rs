//! hdl/lint/lint.sh, the gate every emitted file passes, refuses what it says it
//! refuses: a latch, a combinational loop and a net nothing drives, each found by
//! its yosys stage (the fixtures waive Verilator's own warning so that yosys
//! decides), and a missing file with exit 2. Clean files pass: `.ci/run` lints
//! rtl-out/ with it, and tests/generate_config.rs lints configurations with it.
//!
//! Without the tools the test is skipped, except under CI, where it fails.

use std::process::{Command, Output};

fn lint(args: &[&str]) -> Output {
    Command::new("bash")
        .arg(concat!(env!("CARGO_MANIFEST_DIR"), "/hdl/lint/lint.sh"))
        .args(args)
        .output()
        .expect("cannot run bash")
}

fn fixture(name: &str) -> String {
    format!("{}/hdl/lint/fixtures/{name}.v", env!("CARGO_MANIFEST_DIR"))
}

fn text(o: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

#[test]
fn the_lint_gate_refuses_latches_loops_and_undriven_nets() {
    if !drcc_tools::need_all(&[
        drcc_tools::VERILATOR,
        drcc_tools::IVERILOG,
        drcc_tools::YOSYS,
    ]) {
        return;
    }
    // (fixture, what yosys says about it)
    for (name, finding) in [
        ("latch", "proc_dlatch"),
        ("comb_loop", "found logic loop"),
        ("undriven", "is used but has no driver"),
    ] {
        let o = lint(&[&fixture(name)]);
        let t = text(&o);
        assert_eq!(o.status.code(), Some(1), "{name}: {t}");
        assert!(
            t.contains(&format!("lint: {name}: yosys check -assert failed")),
            "{name}: {t}"
        );
        assert!(t.contains(finding), "{name}: yosys names the finding: {t}");
    }
    // one bad file among good ones still fails the run, and the good one is named clean
    let o = lint(&["rcm", &fixture("latch")]);
    let t = text(&o);
    assert_eq!(o.status.code(), Some(1), "{t}");
    assert!(t.contains("lint: rcm: clean"), "{t}");

    let o = lint(&["no_such_top"]);
    let t = text(&o);
    assert_eq!(o.status.code(), Some(2), "{t}");
    assert!(t.contains("rtl-out/no_such_top.v: no such file"), "{t}");
}
