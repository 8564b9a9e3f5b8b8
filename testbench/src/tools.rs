//! The external tools some tests drive as a user would: python-can (the
//! `socketcand` client and `can.LogReader`) and tshark. Each finder returns the
//! tool when it is there; when it is missing, `drcc_tools`' one rule decides:
//! skipped with a message locally, a failure in CI.

use std::path::PathBuf;

/// A Python interpreter that imports python-can: `$DRCC_PYTHON`, else the
/// workspace's `target/py-venv/bin/python` (made by `.ci/run`), else `python3`.
/// None (with a SKIPPED message) when there is none; a panic in CI.
pub fn python_with_can() -> Option<PathBuf> {
    drcc_tools::python_with(
        &["can"],
        "pip install python-can (.ci/run installs it into target/py-venv; or set DRCC_PYTHON)",
    )
}

/// `tshark` when it runs; None (with a SKIPPED message) when it is missing; a
/// panic in CI.
pub fn tshark() -> Option<PathBuf> {
    drcc_tools::need(&drcc_tools::TSHARK).then(|| PathBuf::from(drcc_tools::TSHARK.cmd))
}
