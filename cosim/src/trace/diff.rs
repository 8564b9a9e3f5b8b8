//! `wave-diff`: compares two VCD traces signal by signal and reports the first
//! time where they differ (signal, both values), optionally restricted to some
//! signals. Times of both files are compared in femtoseconds, so files with
//! different timescales compare correctly; only the time span both files cover
//! is compared.

use std::fmt;

use super::reader::{Trace, TraceSignal};
use super::TimeBase;

/// The first difference found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WaveDifference {
    /// Time in units of the first file's timescale.
    pub time: u64,
    /// Time in femtoseconds.
    pub time_fs: u64,
    /// Full signal name.
    pub signal: String,
    /// Value in the first file (`-` if it has none yet).
    pub a: String,
    /// Value in the second file.
    pub b: String,
    /// Clock cycle, when the first file records its clock (DRCC traces do).
    pub cycle: Option<u64>,
}

/// The outcome of a comparison.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WaveDiffReport {
    /// Names of the signals compared.
    pub compared: Vec<String>,
    /// Signals (within the filter) only the first file has.
    pub only_in_a: Vec<String>,
    /// Signals (within the filter) only the second file has.
    pub only_in_b: Vec<String>,
    /// The earliest difference, if any.
    pub first: Option<WaveDifference>,
    /// The first file's timescale unit, for display (`ns`, ...).
    pub unit: String,
    /// End of the compared span (first file's units).
    pub compared_until: u64,
}

impl WaveDiffReport {
    /// Whether the traces differ (a value, or the set of signals).
    pub fn differs(&self) -> bool {
        self.first.is_some() || !self.only_in_a.is_empty() || !self.only_in_b.is_empty()
    }
}

impl fmt::Display for WaveDiffReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (which, list) in [("first", &self.only_in_a), ("second", &self.only_in_b)] {
            for n in list.iter().take(10) {
                writeln!(f, "only in the {which} file: {n}")?;
            }
            if list.len() > 10 {
                writeln!(
                    f,
                    "... and {} more only in the {which} file",
                    list.len() - 10
                )?;
            }
        }
        match &self.first {
            Some(d) => {
                write!(f, "first difference at {} {}", d.time, self.unit)?;
                if let Some(c) = d.cycle {
                    write!(f, " (clock cycle {c})")?;
                }
                writeln!(f, ": signal `{}`", d.signal)?;
                writeln!(f, "  first file:  {}", d.a)?;
                write!(f, "  second file: {}", d.b)
            }
            None => write!(
                f,
                "no difference in {} signal(s) up to {} {}",
                self.compared.len(),
                self.compared_until,
                self.unit
            ),
        }
    }
}

/// Renders a VCD value for a report: the bits, and hex/decimal when it is a vector
/// of known bits.
fn show(v: Option<&str>) -> String {
    match v {
        None => "-".to_string(),
        Some(s) if s.len() > 1 && s.chars().all(|c| c == '0' || c == '1') => {
            match u128::from_str_radix(s, 2) {
                Ok(n) => format!("b{s} = 0x{n:X} ({n})"),
                Err(_) => format!("b{s}"),
            }
        }
        Some(s) => s.to_string(),
    }
}

/// First time (fs) at which the two signals differ, within `until_fs`.
fn first_diff_fs(
    a: &TraceSignal,
    ua: u64,
    b: &TraceSignal,
    ub: u64,
    until_fs: u64,
) -> Option<(u64, Option<String>, Option<String>)> {
    let (mut i, mut j) = (0, 0);
    let (mut va, mut vb): (Option<&str>, Option<&str>) = (None, None);
    loop {
        let ta = a.changes.get(i).map(|c| c.0.saturating_mul(ua));
        let tb = b.changes.get(j).map(|c| c.0.saturating_mul(ub));
        let t = match (ta, tb) {
            (None, None) => return None,
            (Some(x), None) | (None, Some(x)) => x,
            (Some(x), Some(y)) => x.min(y),
        };
        if t > until_fs {
            return None;
        }
        while i < a.changes.len() && a.changes[i].0.saturating_mul(ua) == t {
            va = Some(&a.changes[i].1);
            i += 1;
        }
        while j < b.changes.len() && b.changes[j].0.saturating_mul(ub) == t {
            vb = Some(&b.changes[j].1);
            j += 1;
        }
        if va != vb {
            return Some((t, va.map(str::to_string), vb.map(str::to_string)));
        }
    }
}

/// Compares two traces. `filter` (empty = every signal) lists signal names or
/// dot-separated suffixes (`node0.tx`, `node1.field`); a filter entry that names
/// no signal in either file is an error.
pub fn first_difference(a: &Trace, b: &Trace, filter: &[String]) -> Result<WaveDiffReport, String> {
    let in_filter = |s: &TraceSignal| filter.is_empty() || filter.iter().any(|p| s.matches(p));
    for p in filter {
        let in_a = a.signals.iter().any(|s| s.matches(p));
        let in_b = b.signals.iter().any(|s| s.matches(p));
        match (in_a, in_b) {
            (false, false) => return Err(format!("signal `{p}` is in neither file")),
            (false, true) => return Err(format!("signal `{p}` is not in the first file")),
            (true, false) => return Err(format!("signal `{p}` is not in the second file")),
            _ => {}
        }
    }
    let (ua, ub) = (a.unit_fs().max(1), b.unit_fs().max(1));
    let until_fs = a
        .end_time
        .saturating_mul(ua)
        .min(b.end_time.saturating_mul(ub));
    let mut report = WaveDiffReport {
        compared: Vec::new(),
        only_in_a: Vec::new(),
        only_in_b: Vec::new(),
        first: None,
        unit: if a.timescale.0 == 1 {
            a.timescale.1.to_string()
        } else {
            format!("x {}{}", a.timescale.0, a.timescale.1)
        },
        compared_until: until_fs / ua,
    };
    let mut best: Option<(u64, String, Option<String>, Option<String>)> = None;
    for sa in a.signals.iter().filter(|s| in_filter(s)) {
        let Some(sb) = b.signal(&sa.name) else {
            report.only_in_a.push(sa.name.clone());
            continue;
        };
        report.compared.push(sa.name.clone());
        if let Some((t, va, vb)) = first_diff_fs(sa, ua, sb, ub, until_fs) {
            if best.as_ref().is_none_or(|b| t < b.0) {
                best = Some((t, sa.name.clone(), va, vb));
            }
        }
    }
    for sb in b.signals.iter().filter(|s| in_filter(s)) {
        if a.signal(&sb.name).is_none() {
            report.only_in_b.push(sb.name.clone());
        }
    }
    if let Some((t, name, va, vb)) = best {
        let time = t / ua;
        report.first = Some(WaveDifference {
            time,
            time_fs: t,
            signal: name,
            a: show(va.as_deref()),
            b: show(vb.as_deref()),
            cycle: a.clock_hz().map(|hz| TimeBase::new(hz).cycle_at(time)),
        });
    }
    Ok(report)
}
