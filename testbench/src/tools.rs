//! The external tools some tests drive as a user would: python-can (the
//! `socketcand` client and `can.LogReader`) and tshark. Each finder returns the
//! tool when it is there; when it is missing it skips with a message locally and
//! fails in CI (same rule as Verilator: [`crate::engines::tools_required`]).

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::engines::tools_required;

/// The virtual environment `.ci/run` installs python-can into, relative to the
/// workspace.
pub const PY_VENV: &str = "target/py-venv";

/// Whether `python` runs and imports `can`.
fn imports_can(python: &Path) -> bool {
    Command::new(python)
        .args(["-c", "import can"])
        .output()
        .is_ok_and(|o| o.status.success())
}

/// A Python interpreter that imports python-can: `$DRCC_PYTHON`, else the
/// workspace's `target/py-venv/bin/python` (made by `.ci/run`), else `python3`.
/// None (with a SKIPPED message) when there is none; a panic in CI.
pub fn python_with_can() -> Option<PathBuf> {
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let candidates = std::env::var_os("DRCC_PYTHON")
        .map(PathBuf::from)
        .into_iter()
        .chain([
            workspace.join(PY_VENV).join("bin/python"),
            PathBuf::from("python3"),
        ]);
    for p in candidates {
        if imports_can(&p) {
            return Some(p);
        }
    }
    let how = format!(
        "python-can is required: `python3 -m venv {PY_VENV} && {PY_VENV}/bin/pip install \
         python-can` in the workspace (as .ci/run does), or set DRCC_PYTHON to a python that \
         imports `can`"
    );
    assert!(!tools_required(), "{how}");
    eprintln!("SKIPPED: {how}");
    None
}

/// `tshark` when it runs; None (with a SKIPPED message) when it is missing; a
/// panic in CI.
pub fn tshark() -> Option<PathBuf> {
    let ok = Command::new("tshark")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if ok {
        return Some(PathBuf::from("tshark"));
    }
    let how = "tshark is required: install it with `apt-get install tshark`";
    assert!(!tools_required(), "{how}");
    eprintln!("SKIPPED: {how}");
    None
}
