//! `drcc wave-diff A.vcd B.vcd [--signal S ...]`: the first difference between
//! two VCD files.

use std::path::Path;

use drcc_cosim::trace::{first_difference, read_vcd};

use super::{CliError, CliResult};

/// Runs the command: exit 0 if equal, 1 if they differ, 2 on errors.
pub fn diff(a: &Path, b: &Path, signals: &[String]) -> CliResult {
    let ta = read_vcd(a)?;
    let tb = read_vcd(b)?;
    let report = first_difference(&ta, &tb, signals)?;
    println!("first file:  {}", a.display());
    println!("second file: {}", b.display());
    println!("{report}");
    if report.differs() {
        Err(CliError::Failed("the waveforms differ".to_string()))
    } else {
        Ok(())
    }
}
