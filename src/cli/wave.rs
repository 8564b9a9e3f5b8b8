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
    if ta.unit_fs() != tb.unit_fs() {
        let scale = |t: &drcc_cosim::trace::Trace| format!("{} {}", t.timescale.0, t.timescale.1);
        println!(
            "timescales differ ({} and {}): compared in absolute time, times below in the first file's",
            scale(&ta),
            scale(&tb)
        );
    }
    println!("{report}");
    if report.differs() {
        return Err(CliError::Failed("the waveforms differ".to_string()));
    }
    // equal over the span both cover: a file that ends earlier (a truncated one,
    // or a shorter run) is not equal to the other
    let (end_a, end_b) = (
        ta.end_time.saturating_mul(ta.unit_fs()),
        tb.end_time.saturating_mul(tb.unit_fs()),
    );
    if end_a != end_b {
        let ns = |fs: u64| fs as f64 / 1e6;
        let short = if end_a < end_b { a } else { b };
        return Err(CliError::Failed(format!(
            "the files end at different times ({} at {} ns, {} at {} ns): {} is shorter, \
             truncated or from a shorter run; compare traces of the same run",
            a.display(),
            ns(end_a),
            b.display(),
            ns(end_b),
            short.display()
        )));
    }
    Ok(())
}
