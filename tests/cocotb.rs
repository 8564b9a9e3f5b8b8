//! The cocotb bench an integrator can copy (`integrations/cocotb/`): two DRCC
//! nodes of `rtl-out/drcc.v` on a dual bus, driven through their Wishbone
//! slaves by cocotbext-wishbone: bring-up, send and receive, line A cut in the
//! middle of the traffic with every frame still delivered exactly once, and
//! refused accesses that change nothing. It runs on Icarus. (On Verilator it
//! needs 5.036 or newer under cocotb 2, and cocotb's Verilator build makes every
//! signal public, which the DRCC's size makes too slow for the suite: not run
//! here yet.)
//!
//! Without cocotb or Icarus the test is skipped with one line, except in CI
//! (`drcc_tools`), where it fails.

use std::path::PathBuf;
use std::process::Command;

/// Runs the bench on `sim` and checks its summary line.
fn bench(sim: &str, python: &PathBuf) {
    let run = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("integrations/cocotb/run.py");
    let build = std::env::temp_dir().join(format!("drcc-cocotb-{sim}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&build);
    let out = Command::new(python)
        .arg(&run)
        .arg(sim)
        .arg(&build)
        .output()
        .expect("python runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.status.success() && text.contains(&format!("cocotb {sim}: 2 passed, 0 failed")),
        "the cocotb bench failed on {sim}:\n{text}"
    );
    let _ = std::fs::remove_dir_all(&build);
}

const INSTALL: &str =
    "pip install cocotb cocotb-bus cocotbext-wishbone (.ci/run installs them into target/py-venv)";

#[test]
fn the_cocotb_bench_passes_on_icarus() {
    if !drcc_tools::need(&drcc_tools::IVERILOG) {
        return;
    }
    if let Some(python) = drcc_tools::python_with(&["cocotb", "cocotbext.wishbone"], INSTALL) {
        bench("icarus", &python);
    }
}
