//! nextpnr-ice40: places and routes a scan-wrapper netlist on the board's part
//! (seeded, so a run is repeatable), and reads its log: the Fmax after routing,
//! the device utilisation and the critical path.

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Duration;

use serde::{Deserialize, Serialize};

use crate::json::round3;
use crate::report::NoFit;
use crate::tools::{run_logged_within, Ran, NEXTPNR_ICE40};
use crate::Error;

/// The nextpnr log file, in the build directory.
pub const LOG: &str = "nextpnr.log";

/// The placement seed: fixed, so the same netlist gives the same Fmax.
pub const SEED: u32 = 1;

/// What a nextpnr-ice40 log reports.
#[derive(Debug, Clone, PartialEq)]
pub struct NextpnrLog {
    /// Max frequency of the (first) clock after routing, MHz.
    pub fmax_mhz: f64,
    /// The clock constraint, MHz.
    pub constraint_mhz: f64,
    /// Clock net name.
    pub clock: String,
    /// Per resource: used, available (Device utilisation).
    pub utilisation: BTreeMap<String, (u64, u64)>,
    /// The critical path of the clock, if reported.
    pub critical_path: Option<CriticalPath>,
}

/// The critical path nextpnr reports for the clock.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CriticalPath {
    /// Start (a flip-flop, by its RTL name).
    pub from: String,
    /// End.
    pub to: String,
    /// Delay in logic, ns.
    #[serde(serialize_with = "round3")]
    pub logic_ns: f64,
    /// Delay in routing, ns.
    #[serde(serialize_with = "round3")]
    pub routing_ns: f64,
}

impl CriticalPath {
    /// `a -> b: 81.8 ns (32.7 logic + 49.1 routing)`.
    pub fn describe(&self) -> String {
        format!(
            "{} -> {}: {:.1} ns ({:.1} logic + {:.1} routing)",
            self.from,
            self.to,
            self.logic_ns + self.routing_ns,
            self.logic_ns,
            self.routing_ns
        )
    }
}

/// The arguments placing `<module>.json` on the part `device` (nextpnr's
/// device and package options) with the pin constraints `pcf`, writing
/// `<module>.asc` and the log [`LOG`].
pub fn args(device: &[&str], module: &str, pcf: &Path) -> Vec<String> {
    let mut args: Vec<String> = device.iter().map(|s| s.to_string()).collect();
    args.extend([
        "--json".to_string(),
        format!("{module}.json"),
        "--pcf".to_string(),
        pcf.display().to_string(),
        // Only the package pins of the wrapper are constrained.
        "--pcf-allow-unconstrained".to_string(),
        "--asc".to_string(),
        format!("{module}.asc"),
        "--seed".to_string(),
        SEED.to_string(),
        // A missed board clock is reported, not an error: the Fmax is the result.
        "--timing-allow-fail".to_string(),
        "-q".to_string(),
        "--log".to_string(),
        LOG.to_string(),
    ]);
    args
}

/// How long place and route may run by default before the design is reported
/// as not routing (a congested netlist can keep nextpnr's router busy for hours).
pub const DEFAULT_LIMIT: Duration = Duration::from_secs(20 * 60);

/// Places and routes `<module>.json` in `dir`; returns the parsed log, or
/// `Err(NoFit)` inside when nextpnr stopped because the design needs more of a
/// resource than the part has, or was still routing at `limit` (any other
/// failure is an [`Error`]).
pub fn run(
    dir: &Path,
    device: &[&str],
    module: &str,
    pcf: &Path,
    limit: Duration,
) -> Result<Result<NextpnrLog, NoFit>, Error> {
    let _ = std::fs::remove_file(dir.join(LOG));
    let ran = run_logged_within(
        &NEXTPNR_ICE40,
        &args(device, module, pcf),
        dir,
        LOG,
        Some(limit),
    );
    let log = std::fs::read_to_string(dir.join(LOG)).unwrap_or_default();
    match ran {
        Err(e) => match no_fit(&log) {
            Some(nf) => Ok(Err(nf)),
            None => Err(e),
        },
        Ok(Ran::Stopped(after)) => Ok(Err(unrouted(&log, after))),
        Ok(Ran::Finished) => parse_log(&log)
            .map(Ok)
            .map_err(|msg| Error(format!("{}: {msg}", dir.join(LOG).display()))),
    }
}

/// A design stopped while routing: the logic cells placed (from the
/// utilisation block nextpnr logs before placing) and how long it tried.
pub fn unrouted(text: &str, after: Duration) -> NoFit {
    let (used, available) = parse_utilisation(text)
        .get("ICESTORM_LC")
        .copied()
        .unwrap_or((0, 0));
    NoFit {
        resource: "ICESTORM_LC".to_string(),
        used,
        available,
        unrouted_after_s: Some(after.as_secs()),
    }
}

/// The first resource (in nextpnr's order) the design uses more of than the part
/// has, from the utilisation block nextpnr logs before it gives up placing.
pub fn no_fit(text: &str) -> Option<NoFit> {
    let at = text.rfind("Device utilisation:")?;
    text[at..]
        .lines()
        .skip(1)
        .map_while(|l| {
            let body = l.trim_start_matches("Info:").trim();
            let (name, counts) = body.split_once(':')?;
            let (used, total) = counts.split_once('/')?;
            let used: u64 = used.trim().parse().ok()?;
            let total: u64 = total.split_whitespace().next()?.parse().ok()?;
            Some((name.trim().to_string(), used, total))
        })
        .find(|(_, used, total)| used > total)
        .map(|(resource, used, available)| NoFit {
            resource,
            used,
            available,
            unrouted_after_s: None,
        })
}

/// Parses a nextpnr log: the last `Max frequency for clock` line (after
/// routing), the device utilisation and the critical path.
pub fn parse_log(text: &str) -> Result<NextpnrLog, String> {
    let key = "Max frequency for clock '";
    let line = text
        .lines()
        .rev()
        .find(|l| l.contains(key))
        .ok_or_else(|| "no `Max frequency for clock` line in the nextpnr log".to_string())?;
    let rest = &line[line.find(key).expect("found") + key.len()..];
    let (clock, rest) = rest
        .split_once("':")
        .ok_or_else(|| format!("cannot read `{}`", line.trim()))?;
    let fmax_mhz: f64 = rest
        .split_whitespace()
        .next()
        .and_then(|t| t.parse().ok())
        .ok_or_else(|| format!("cannot read the frequency in `{}`", line.trim()))?;
    let constraint_mhz = rest
        .split(" at ")
        .nth(1)
        .and_then(|t| t.split_whitespace().next())
        .and_then(|t| t.parse().ok())
        .unwrap_or(0.0);
    Ok(NextpnrLog {
        fmax_mhz,
        constraint_mhz,
        clock: clock.to_string(),
        utilisation: parse_utilisation(text),
        critical_path: parse_critical_path(text),
    })
}

/// The last `Device utilisation:` block: resource -> (used, available).
fn parse_utilisation(text: &str) -> BTreeMap<String, (u64, u64)> {
    let mut utilisation = BTreeMap::new();
    let Some(at) = text.rfind("Device utilisation:") else {
        return utilisation;
    };
    for l in text[at..].lines().skip(1) {
        let body = l.trim_start_matches("Info:").trim();
        let Some((name, counts)) = body.split_once(':') else {
            break;
        };
        let Some((used, total)) = counts.split_once('/') else {
            break;
        };
        let used: Option<u64> = used.trim().parse().ok();
        let total: Option<u64> = total.split_whitespace().next().and_then(|t| t.parse().ok());
        match (used, total) {
            (Some(u), Some(t)) => {
                utilisation.insert(name.trim().to_string(), (u, t));
            }
            _ => break,
        }
    }
    utilisation
}

/// `dut.cfg_regs.tseg2_q.q_SB_DFFE_Q_2_DFFLC.O` -> `dut.cfg_regs.tseg2_q.q`.
fn rtl_name(cell_pin: &str) -> String {
    let cell = cell_pin.rsplit_once('.').map_or(cell_pin, |(c, _)| c);
    let end = ["_SB_", "$", "_DFFLC", "_LC"]
        .iter()
        .filter_map(|m| cell.find(m))
        .filter(|&i| i > 0)
        .min()
        .unwrap_or(cell.len());
    cell[..end].to_string()
}

/// The last clock critical-path report: its source, its setup end and the
/// logic / routing split.
fn parse_critical_path(text: &str) -> Option<CriticalPath> {
    let at = text.rfind("Critical path report for clock '")?;
    let section: Vec<&str> = text[at..]
        .lines()
        .skip(1)
        .take_while(|l| !l.contains("Critical path report"))
        .collect();
    let word_after = |l: &str, key: &str| -> Option<String> {
        let mut toks = l.split_whitespace();
        toks.find(|t| *t == key)?;
        toks.next().map(str::to_string)
    };
    let from = section.iter().find_map(|l| word_after(l, "Source"))?;
    let to = section.iter().rev().find_map(|l| word_after(l, "Setup"))?;
    let split = section.iter().find(|l| l.contains("ns logic,"))?;
    let nums: Vec<f64> = split
        .split_whitespace()
        .filter_map(|t| t.parse().ok())
        .collect();
    let (&logic_ns, &routing_ns) = (nums.first()?, nums.get(1)?);
    Some(CriticalPath {
        from: rtl_name(&from),
        to: rtl_name(&to),
        logic_ns,
        routing_ns,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Excerpts of nextpnr-ice40 0.4 logs on the UP5K (utilisation of a small
    /// counter; the critical path of can_channel_scan).
    const NEXTPNR_LOG: &str = "\
Info: constraining clock net 'clk' to 12.00 MHz\n\
Info: Device utilisation:\n\
Info: \t         ICESTORM_LC:    19/ 5280     0%\n\
Info: \t        ICESTORM_RAM:     0/   30     0%\n\
Info: \t               SB_IO:     3/   96     3%\n\
Info: \t               SB_GB:     1/    8    12%\n\
\n\
Info: Placed 0 cells based on constraints.\n\
Info: Max frequency for clock 'clk$SB_IO_IN_$glb_clk': 106.54 MHz (PASS at 12.00 MHz)\n\
\n\
Info: Critical path report for clock 'clk$SB_IO_IN_$glb_clk' (posedge -> posedge):\n\
Info: curr total\n\
Info:  1.4  1.4  Source dut.cfg_regs.tseg2_q.q_SB_DFFE_Q_2_DFFLC.O\n\
Info:  1.8  3.2    Net dut.btl__cfg_tseg2[0] budget 0.000000 ns (1,3) -> (1,4)\n\
Info:                Sink $nextpnr_ICESTORM_LC_30.I1\n\
Info:  1.2 78.8  Source dut.bsp.stuff_last_n_SB_LUT4_I1_O_SB_LUT4_O_1_LC.O\n\
Info:  1.8 80.6    Net dut.bsp.stuff_last_n_SB_LUT4_I1_O[0] budget 2.665000 ns (12,9) -> (12,8)\n\
Info:                Sink dut.bsp.tx_bit.q_SB_DFFESS_Q_D_SB_LUT4_O_LC.I0\n\
Info:  1.2 81.8  Setup dut.bsp.tx_bit.q_SB_DFFESS_Q_D_SB_LUT4_O_LC.I0\n\
Info: 32.7 ns logic, 49.1 ns routing\n\
\n\
Info: Critical path report for cross-domain path '<async>' -> 'posedge clk$SB_IO_IN_$glb_clk':\n\
Info:  0.0  0.0  Source scan_in$sb_io.D_IN_0\n\
Info:  1.2  5.1  Setup sin_s_SB_DFF_Q_1_DFFLC.I0\n\
Info: 1.2 ns logic, 3.8 ns routing\n\
Info: Max frequency for clock 'clk$SB_IO_IN_$glb_clk': 103.18 MHz (PASS at 12.00 MHz)\n\
\n\
Info: Program finished normally.\n";

    #[test]
    fn parses_nextpnr_log() {
        let r = parse_log(NEXTPNR_LOG).unwrap();
        // The last Fmax line is the one after routing.
        assert_eq!(r.fmax_mhz, 103.18);
        assert_eq!(r.constraint_mhz, 12.0);
        assert_eq!(r.clock, "clk$SB_IO_IN_$glb_clk");
        assert_eq!(r.utilisation["ICESTORM_LC"], (19, 5280));
        assert_eq!(r.utilisation["SB_IO"], (3, 96));
        assert_eq!(r.utilisation.len(), 4);
        let c = r.critical_path.unwrap();
        assert_eq!(c.from, "dut.cfg_regs.tseg2_q.q");
        assert_eq!(c.to, "dut.bsp.tx_bit.q");
        assert_eq!((c.logic_ns, c.routing_ns), (32.7, 49.1));
        assert_eq!(
            c.describe(),
            "dut.cfg_regs.tseg2_q.q -> dut.bsp.tx_bit.q: 81.8 ns (32.7 logic + 49.1 routing)"
        );
    }

    #[test]
    fn a_failed_constraint_is_read_too() {
        // With --timing-allow-fail a missed clock is a warning, not an error.
        let fail = "Warning: Max frequency for clock 'clk$SB_IO_IN_$glb_clk': 103.18 MHz (FAIL at 300.03 MHz)\n";
        let r = parse_log(fail).unwrap();
        assert_eq!((r.fmax_mhz, r.constraint_mhz), (103.18, 300.03));
        assert!(r.utilisation.is_empty() && r.critical_path.is_none());
        assert!(parse_log("Info: nothing\n").is_err());
    }

    #[test]
    fn arguments_are_seeded_and_name_the_netlist() {
        let a = args(
            &["--up5k", "--package", "sg48"],
            "can_channel_scan",
            Path::new("/w/icebreaker.pcf"),
        );
        let joined = a.join(" ");
        assert!(
            joined.starts_with(
                "--up5k --package sg48 --json can_channel_scan.json --pcf /w/icebreaker.pcf"
            ),
            "{joined}"
        );
        assert!(
            joined.contains("--asc can_channel_scan.asc --seed 1 "),
            "{joined}"
        );
        assert!(joined.ends_with("--log nextpnr.log"), "{joined}");
    }

    /// The log of nextpnr-ice40 0.4 giving up on the UP5K (drcc, 2026-11-25).
    const NO_FIT_LOG: &str = "\
Info: Device utilisation:
Info: \t         ICESTORM_LC:  5308/ 5280   100%
Info: \t        ICESTORM_RAM:    26/   30    86%
Info: \t               SB_IO:    10/   96    10%
Info: \t               SB_GB:     8/    8   100%

Info: Placed 10 cells based on constraints.
ERROR: Failed to expand region (0, 0) |_> (25, 31) of 5308 ICESTORM_LCs
0 warnings, 1 error
";

    #[test]
    fn a_design_over_the_part_is_a_no_fit_naming_the_resource() {
        let nf = no_fit(NO_FIT_LOG).expect("5308 > 5280 logic cells");
        assert_eq!(
            (nf.resource.as_str(), nf.used, nf.available),
            ("ICESTORM_LC", 5308, 5280)
        );
        assert_eq!(nf.describe(), "5308/5280 ICESTORM_LC (100.5 %)");
        // A full resource (8/8 global buffers) is not over the part.
        assert!(no_fit(&NO_FIT_LOG.replace("5308/", "5280/")).is_none());
        // A failure without a utilisation block is not a no-fit.
        assert!(no_fit("ERROR: cannot open file\n").is_none());
    }

    #[test]
    fn a_design_stopped_while_routing_names_the_cells_placed_and_the_time() {
        let log = NO_FIT_LOG.replace("5308/ 5280", "7016/ 7680");
        let nf = unrouted(&log, Duration::from_secs(20 * 60));
        assert_eq!(
            (nf.used, nf.available, nf.unrouted_after_s),
            (7016, 7680, Some(1200))
        );
        assert_eq!(
            nf.describe(),
            "not routed in 20 min (7016/7680 ICESTORM_LC placed)"
        );
    }
}
