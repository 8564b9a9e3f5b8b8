//! The JSON of `drcc synth --json`, written by serde_json in the layout the
//! reports have always had: one report an object on one line, `", "` and `": "`
//! between items, numbers with at most three decimals and no `.0`, several
//! reports as an array with one report a line.

use std::io;

use serde::{Serialize, Serializer};
use serde_json::ser::Formatter;

use crate::report::SynthReport;
use crate::Error;

/// serde_json's compact layout with a space after `,` and `:`, and numbers as
/// the reports write them.
struct Spaced;

impl Formatter for Spaced {
    fn begin_array_value<W: ?Sized + io::Write>(
        &mut self,
        w: &mut W,
        first: bool,
    ) -> io::Result<()> {
        if first {
            Ok(())
        } else {
            w.write_all(b", ")
        }
    }

    fn begin_object_key<W: ?Sized + io::Write>(
        &mut self,
        w: &mut W,
        first: bool,
    ) -> io::Result<()> {
        if first {
            Ok(())
        } else {
            w.write_all(b", ")
        }
    }

    fn begin_object_value<W: ?Sized + io::Write>(&mut self, w: &mut W) -> io::Result<()> {
        w.write_all(b": ")
    }

    fn write_f64<W: ?Sized + io::Write>(&mut self, w: &mut W, x: f64) -> io::Result<()> {
        w.write_all(number(x).as_bytes())
    }
}

/// `12.0` -> `12`, `0.42291` -> `0.423`: three decimals at most.
fn number(x: f64) -> String {
    let s = format!("{x:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s.is_empty() || s == "-" || s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// Serialises a number with three decimals at most (a non-finite one as
/// `null`), whatever the JSON writer.
pub(crate) fn round3<S: Serializer>(x: &f64, s: S) -> Result<S::Ok, S::Error> {
    if x.is_finite() {
        s.serialize_f64(number(*x).parse().unwrap_or(*x))
    } else {
        s.serialize_none()
    }
}

/// One value on one line.
pub fn to_line<T: Serialize>(value: &T) -> Result<String, Error> {
    let mut out = Vec::new();
    let mut ser = serde_json::Serializer::with_formatter(&mut out, Spaced);
    value
        .serialize(&mut ser)
        .map_err(|e| Error(format!("cannot write the report: {e}")))?;
    String::from_utf8(out).map_err(|e| Error(format!("cannot write the report: {e}")))
}

/// The `--json` output: one report as an object, several (or `--all`) as an
/// array with one report a line.
pub fn reports(reports: &[SynthReport], as_list: bool) -> Result<String, Error> {
    if let (false, [one]) = (as_list, reports) {
        return to_line(one);
    }
    let lines: Vec<String> = reports.iter().map(to_line).collect::<Result<_, _>>()?;
    Ok(format!("[\n{}\n]", lines.join(",\n")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::tests::sample;

    #[test]
    fn numbers_have_three_decimals_at_most() {
        assert_eq!(number(12.0), "12");
        assert_eq!(number(1015.0 / 2400.0), "0.423");
        assert_eq!(number(103.18), "103.18");
        assert_eq!(number(-0.0001), "0");
    }

    #[test]
    fn one_report_is_one_line_in_the_old_layout() {
        let line = to_line(&sample("ice40")).unwrap();
        assert!(!line.contains('\n'), "{line}");
        assert!(
            line.starts_with("{\"top\": \"can_channel\", \"target\": \"ice40\", \"family\": \"Lattice iCE40 UltraPlus\", \"yosys\": \"0.23\""),
            "{line}"
        );
        assert!(line.contains("\"board_clock_mhz\": 12, "), "{line}");
        assert!(
            line.contains("\"top_area\": {\"lut\": 1015, \"ff\": 490, \"carry\": 201, \"bram\": 0, \"lutram\": 0, \"muxf\": 0, \"dsp\": 0, \"latch\": 0, \"cells\": {\"SB_CARRY\": 201, "),
            "{line}"
        );
        assert!(line.contains("\"cells\": {}}"), "{line}");
        assert!(
            line.contains("\"lut_ratio\": 0.423, \"ff_ratio\": 0.336}"),
            "{line}"
        );
        assert!(
            line.contains("\"utilisation\": {\"ICESTORM_LC\": [2100, 5280]}"),
            "{line}"
        );
        assert!(line.ends_with("\"build_dir\": \"/b\"}"), "{line}");
        let back: SynthReport = serde_json::from_str(&line).unwrap();
        assert_eq!(back.measured.unwrap().top_area.ff, 490);
    }

    #[test]
    fn several_reports_are_an_array_one_a_line() {
        let both = reports(&[sample("ice40"), sample("xc7")], true).unwrap();
        let lines: Vec<&str> = both.lines().collect();
        assert_eq!((lines.len(), lines[0], lines[3]), (4, "[", "]"));
        assert!(lines[1].ends_with("},") && lines[2].ends_with('}'));
        let back: Vec<SynthReport> = serde_json::from_str(&both).unwrap();
        assert_eq!(back[1].target.name, "xc7");
        // A single report asked for alone is the object itself.
        assert!(reports(&[sample("xc7")], false).unwrap().starts_with('{'));
        assert!(reports(&[sample("xc7")], true).unwrap().starts_with("[\n{"));
    }
}
