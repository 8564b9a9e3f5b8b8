//! The external tools some tests drive as a user would: python-can (the
//! `socketcand` client and `can.LogReader`) and tshark. Each finder returns the
//! tool when it is there; when it is missing, `drcc_tools`' one rule decides:
//! skipped with a message locally, a failure in CI.

use std::path::PathBuf;

/// The virtual environment `.ci/run` installs python-can into, relative to the
/// workspace.
pub const PY_VENV: &str = drcc_tools::PY_VENV;

/// A Python interpreter that imports python-can: `$DRCC_PYTHON`, else the
/// workspace's `target/py-venv/bin/python` (made by `.ci/run`), else `python3`.
/// None (with a SKIPPED message) when there is none; a panic in CI.
pub fn python_with_can() -> Option<PathBuf> {
    drcc_tools::python_with(
        &["can"],
        &format!(
            "python3 -m venv {PY_VENV} && {PY_VENV}/bin/pip install python-can` in the \
             workspace (as .ci/run does), or set DRCC_PYTHON to a python that imports `can"
        ),
    )
}

/// `tshark` when it runs; None (with a SKIPPED message) when it is missing; a
/// panic in CI.
pub fn tshark() -> Option<PathBuf> {
    drcc_tools::need(&drcc_tools::TSHARK).then(|| PathBuf::from(drcc_tools::TSHARK.cmd))
}
