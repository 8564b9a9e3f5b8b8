//! The report of one top on one target: a serde struct (what `--json` prints,
//! what tests read back) and its plain-text rendering.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize, Serializer};

use crate::breakdown::Breakdown;
use crate::json::round3;

use crate::nextpnr::CriticalPath;
use crate::target::{Target, FMAX_MARGIN, RECOMMENDED_CLOCK_MHZ, REFERENCE_NAME};
use crate::yosys::Area;

/// One top on one target. The fields after `note` are present when the family
/// could be synthesised (`unsupported` is absent).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SynthReport {
    /// Top name.
    pub top: String,
    /// The target (serialised as its `--target` name).
    #[serde(
        serialize_with = "crate::target::serialize_name",
        deserialize_with = "crate::target::deserialize_name"
    )]
    pub target: &'static Target,
    /// Human name of the family.
    pub family: String,
    /// yosys version.
    pub yosys: String,
    /// yosys synthesis command.
    pub synth: String,
    /// The documented board.
    pub board: String,
    /// FPGA part on the board.
    pub device: String,
    /// Board oscillator, MHz.
    #[serde(serialize_with = "round3")]
    pub board_clock_mhz: f64,
    /// Constraints file, relative to the workspace.
    pub constraints: String,
    /// [`RECOMMENDED_CLOCK_MHZ`].
    #[serde(serialize_with = "round3")]
    pub recommended_clock_mhz: f64,
    /// Why the family cannot be synthesised by this yosys.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unsupported: Option<String>,
    /// A remark on the flow (e.g. the yosys family is experimental).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// The numbers (absent when `unsupported`).
    #[serde(flatten)]
    pub measured: Option<Measured>,
}

/// The numbers of a synthesised top.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Measured {
    /// The top alone, out of context.
    pub top_area: Area,
    /// The scan wrapper with the top inside.
    pub wrapper_area: Area,
    /// `wrapper_area - top_area`, per group.
    pub wrapper_overhead: Area,
    /// Scan chain lengths and CAN pins.
    pub wrapper: WrapperSummary,
    /// The OpenCores CAN controller on this family, if measured.
    pub reference: Option<Reference>,
    /// iCE40 place and route (none for the Xilinx families, or when the design
    /// does not fit the part).
    pub pnr: Option<Pnr>,
    /// The design does not fit the board's part: nextpnr stopped, this says why.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub no_fit: Option<NoFit>,
    /// The top's area block by block ([`crate::breakdown`]), when asked for.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub breakdown: Option<Breakdown>,
    /// Build directory (netlists, logs, the wrapper, the bitstream).
    pub build_dir: PathBuf,
}

/// The scan wrapper, in numbers.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct WrapperSummary {
    /// Module name: `<top>_scan`.
    pub module: String,
    /// Bits of the input chain.
    pub scan_in_bits: usize,
    /// Bits of the output chain.
    pub scan_out_bits: usize,
    /// CAN pin pairs on package pins.
    pub can_pins: usize,
}

/// The area reference and the top's size relative to it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Reference {
    /// [`REFERENCE_NAME`].
    pub name: String,
    /// Its LUTs.
    pub lut: u64,
    /// Its flip-flops.
    pub ff: u64,
    /// Top LUTs / reference LUTs.
    #[serde(serialize_with = "round3")]
    pub lut_ratio: f64,
    /// Top FFs / reference FFs.
    #[serde(serialize_with = "round3")]
    pub ff_ratio: f64,
}

impl Reference {
    /// The reference of `t`, if measured, against the top's area `a`.
    pub fn of(t: &Target, a: &Area) -> Option<Reference> {
        let (lut, ff) = t.reference?;
        Some(Reference {
            name: REFERENCE_NAME.to_string(),
            lut,
            ff,
            lut_ratio: ratio(a.lut, lut),
            ff_ratio: ratio(a.ff, ff),
        })
    }
}

/// A design that does not fit the part: the first resource nextpnr had too few of.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct NoFit {
    /// nextpnr's resource name (`ICESTORM_LC`, `ICESTORM_RAM` ...).
    pub resource: String,
    /// How many the wrapper netlist needs.
    pub used: u64,
    /// How many the part has.
    pub available: u64,
    /// Set when the part has room for the logic but nextpnr was still routing
    /// when the flow's time limit stopped it: the seconds it ran.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unrouted_after_s: Option<u64>,
}

impl NoFit {
    /// `5308/5280 ICESTORM_LC (100.5 %)`, or for a design stopped while routing
    /// `not routed in 20 min (7016/7680 ICESTORM_LC placed)`.
    pub fn describe(&self) -> String {
        let cells = format!("{}/{} {}", self.used, self.available, self.resource);
        match self.unrouted_after_s {
            Some(s) => format!("not routed in {} min ({cells} placed)", s.div_ceil(60)),
            None => format!(
                "{cells} ({:.1} %)",
                100.0 * ratio(self.used, self.available)
            ),
        }
    }
}

/// Place and route (nextpnr-ice40) and the bitstream.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Pnr {
    /// `nextpnr-ice40`.
    pub tool: String,
    /// Its version.
    pub version: String,
    /// Fmax of the clock after routing, MHz.
    #[serde(serialize_with = "round3")]
    pub fmax_mhz: f64,
    /// The clock constraint (the board oscillator), MHz.
    #[serde(serialize_with = "round3")]
    pub constraint_mhz: f64,
    /// Clock net name.
    pub clock: String,
    /// `fmax_mhz / RECOMMENDED_CLOCK_MHZ`.
    #[serde(serialize_with = "round3")]
    pub fmax_over_recommended: f64,
    /// Per resource: used, available (only resources in use are written).
    #[serde(serialize_with = "used_only")]
    pub utilisation: std::collections::BTreeMap<String, (u64, u64)>,
    /// The critical path of the clock.
    pub critical_path: Option<CriticalPath>,
    /// The bitstream icepack wrote.
    pub bitstream: PathBuf,
}

impl Pnr {
    /// `u/n logic cells (p %)`, if nextpnr reported the logic cells.
    pub fn logic_cells(&self) -> Option<String> {
        let (u, n) = self.utilisation.get("ICESTORM_LC")?;
        Some(format!(
            "{u}/{n} logic cells ({:.0} %)",
            100.0 * *u as f64 / *n as f64
        ))
    }

    /// Whether the Fmax has [`FMAX_MARGIN`] over the recommended clock.
    pub fn has_margin(&self) -> bool {
        self.fmax_mhz >= FMAX_MARGIN * RECOMMENDED_CLOCK_MHZ
    }

    /// Whether the routed design meets the board clock.
    pub fn meets_board_clock(&self) -> bool {
        self.fmax_mhz >= self.constraint_mhz
    }
}

/// `a / b`, 0 when `b` is 0.
pub fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

fn used_only<S: Serializer>(
    u: &std::collections::BTreeMap<String, (u64, u64)>,
    s: S,
) -> Result<S::Ok, S::Error> {
    s.collect_map(u.iter().filter(|(_, (used, _))| *used > 0))
}

/// `12` for a whole number of MHz, else two decimals.
pub fn fmt_mhz(x: f64) -> String {
    if (x - x.round()).abs() < 1e-9 {
        format!("{}", x.round() as i64)
    } else {
        format!("{x:.2}")
    }
}

impl SynthReport {
    /// The human-readable report `drcc synth` prints.
    pub fn text(&self) -> String {
        let t = self.target;
        let mut s = String::new();
        let _ = writeln!(s, "{} on {} ({})", self.top, t.name, t.family);
        let Some(m) = &self.measured else {
            let why = self.unsupported.as_deref().unwrap_or("no numbers");
            let _ = writeln!(s, "  NOT SUPPORTED: {why}; no numbers for this family");
            return s;
        };
        let _ = writeln!(
            s,
            "  board: {} ({}, {} MHz oscillator), constraints {}",
            t.board,
            t.device,
            fmt_mhz(t.clock_mhz),
            t.constraints
        );
        if let Some(n) = &self.note {
            let _ = writeln!(s, "  note: {n}");
        }
        let a = &m.top_area;
        let _ = writeln!(
            s,
            "  {} alone (yosys `{}`, out of context):",
            self.top, t.synth
        );
        let _ = writeln!(
            s,
            "    {} {}   FF {}   carry {}   BRAM {}{}",
            t.lut,
            a.lut,
            a.ff,
            a.carry,
            a.bram,
            extras(a)
        );
        let _ = writeln!(s, "    cells: {}", cell_list(a));
        let (w, o) = (&m.wrapper, &m.wrapper_overhead);
        let _ = writeln!(
            s,
            "  scan wrapper {} ({} input bits, {} output bits, {} CAN pin pair(s)): total {} {} FF {}; overhead {} +{} FF +{}",
            w.module,
            w.scan_in_bits,
            w.scan_out_bits,
            w.can_pins,
            t.lut,
            m.wrapper_area.lut,
            m.wrapper_area.ff,
            t.lut,
            o.lut,
            o.ff
        );
        if let Some(r) = &m.reference {
            let _ = writeln!(
                s,
                "  vs {} on {}: about {} {} + {} FF -> {:.2}x the LUTs, {:.2}x the FFs",
                r.name,
                t.name,
                r.lut,
                t.lut,
                r.ff,
                ratio(a.lut, r.lut),
                ratio(a.ff, r.ff)
            );
        }
        if let Some(b) = &m.breakdown {
            s.push_str(&b.text(t.lut, a, m.reference.as_ref().map(|r| r.lut)));
        }
        match (&m.pnr, &m.no_fit) {
            (Some(p), _) => pnr_text(&mut s, p),
            (None, Some(nf)) if nf.unrouted_after_s.is_some() => {
                let _ = writeln!(
                    s,
                    "  place and route: DOES NOT ROUTE on the {}: {}",
                    t.device,
                    nf.describe()
                );
            }
            (None, Some(nf)) => {
                let _ = writeln!(
                    s,
                    "  place and route: DOES NOT FIT the {}: the scan wrapper needs {}",
                    t.device,
                    nf.describe()
                );
            }
            (None, None) => {
                let _ = writeln!(
                    s,
                    "  place and route: not run (no {} place-and-route among the Debian tools; see {})",
                    t.family,
                    Path::new(t.constraints)
                        .parent()
                        .map(|p| p.join("README.md").display().to_string())
                        .unwrap_or_default()
                );
            }
        }
        let _ = writeln!(s, "  build directory: {}", m.build_dir.display());
        s
    }
}

fn pnr_text(s: &mut String, p: &Pnr) {
    if let Some(cells) = p.logic_cells() {
        let _ = writeln!(s, "  place and route (nextpnr-ice40, wrapper): {cells}");
    }
    let verdict = if p.has_margin() {
        "ok"
    } else {
        "BELOW the required margin"
    };
    let board = if p.meets_board_clock() {
        "met"
    } else {
        "NOT met: the bitstream is not timing-clean at the board clock"
    };
    let _ = writeln!(
        s,
        "  Fmax {:.2} MHz; board clock {} MHz: {board}",
        p.fmax_mhz,
        fmt_mhz(p.constraint_mhz)
    );
    let _ = writeln!(
        s,
        "  Fmax = {:.2}x the recommended {} MHz for 1 Mbit/s (need >= {}x: {verdict})",
        p.fmax_mhz / RECOMMENDED_CLOCK_MHZ,
        fmt_mhz(RECOMMENDED_CLOCK_MHZ),
        FMAX_MARGIN
    );
    if let Some(c) = &p.critical_path {
        let _ = writeln!(s, "  critical path: {}", c.describe());
    }
    let _ = writeln!(s, "  bitstream: {}", p.bitstream.display());
}

/// The Xilinx-only groups, where non-zero.
fn extras(a: &Area) -> String {
    let mut s = String::new();
    for (n, what) in [
        (a.lutram, "LUT-RAM/SRL"),
        (a.muxf, "MUXF5-8"),
        (a.dsp, "DSP"),
        (a.latch, "LATCH"),
    ] {
        if n > 0 {
            let _ = write!(s, "   {what} {n}");
        }
    }
    s
}

fn cell_list(a: &Area) -> String {
    a.cells
        .iter()
        .map(|(k, v)| format!("{k} {v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::target::Arch;

    /// A report as the flow makes it for can_channel on the iCEBreaker, with the
    /// cell counts of the yosys 0.23 statistics in `yosys.rs`.
    pub(crate) fn sample(target: &str) -> SynthReport {
        let t = Target::by_name(target).unwrap();
        let cells = [
            ("SB_CARRY", 201),
            ("SB_DFFE", 143),
            ("SB_DFFESR", 347),
            ("SB_LUT4", 1015),
        ]
        .iter()
        .map(|(k, v)| (k.to_string(), *v))
        .collect();
        let top_area = Area::from_cells(Arch::Ice40, cells);
        let mut wrapper_area = top_area.clone();
        wrapper_area.lut += 100;
        wrapper_area.ff += 400;
        let pnr = t.pnr.map(|_| Pnr {
            tool: "nextpnr-ice40".to_string(),
            version: "0.4-1+b1".to_string(),
            fmax_mhz: 40.06,
            constraint_mhz: 12.0,
            clock: "clk$SB_IO_IN_$glb_clk".to_string(),
            fmax_over_recommended: 40.06 / RECOMMENDED_CLOCK_MHZ,
            utilisation: [
                ("ICESTORM_LC".to_string(), (2100, 5280)),
                ("ICESTORM_RAM".to_string(), (0, 30)),
            ]
            .into_iter()
            .collect(),
            critical_path: Some(CriticalPath {
                from: "dut.a".to_string(),
                to: "dut.b".to_string(),
                logic_ns: 9.5,
                routing_ns: 15.46,
            }),
            bitstream: PathBuf::from("/b/can_channel_scan.bin"),
        });
        SynthReport {
            top: "can_channel".to_string(),
            target: t,
            family: t.family.to_string(),
            yosys: "0.23".to_string(),
            synth: t.synth.to_string(),
            board: t.board.to_string(),
            device: t.device.to_string(),
            board_clock_mhz: t.clock_mhz,
            constraints: t.constraints.to_string(),
            recommended_clock_mhz: RECOMMENDED_CLOCK_MHZ,
            unsupported: None,
            note: None,
            measured: Some(Measured {
                reference: Reference::of(t, &top_area),
                wrapper_overhead: wrapper_area.minus(&top_area),
                top_area,
                wrapper_area,
                wrapper: WrapperSummary {
                    module: "can_channel_scan".to_string(),
                    scan_in_bits: 120,
                    scan_out_bits: 150,
                    can_pins: 1,
                },
                pnr,
                no_fit: None,
                breakdown: None,
                build_dir: PathBuf::from("/b"),
            }),
        }
    }

    #[test]
    fn json_round_trips_and_keeps_the_field_names() {
        let r = sample("ice40");
        let json = serde_json::to_string(&r).unwrap();
        let v: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert_eq!(v["target"], "ice40");
        assert_eq!(v["top_area"]["lut"], 1015);
        assert_eq!(v["top_area"]["ff"], 490);
        assert_eq!(v["wrapper_overhead"]["ff"], 400);
        assert_eq!(v["wrapper"]["can_pins"], 1);
        // 1015 / 2400 = 0.42291..., written with three decimals.
        assert_eq!(v["reference"]["lut_ratio"], 0.423);
        assert_eq!(v["pnr"]["fmax_over_recommended"], 2.504);
        // Unused resources are left out.
        assert!(v["pnr"]["utilisation"].get("ICESTORM_RAM").is_none());
        assert_eq!(v["pnr"]["utilisation"]["ICESTORM_LC"][0], 2100);
        let back: SynthReport = serde_json::from_str(&json).unwrap();
        assert_eq!(
            back.measured.as_ref().unwrap().top_area,
            r.measured.as_ref().unwrap().top_area
        );
        assert_eq!(back.target.name, "ice40");
    }

    #[test]
    fn unsupported_family_has_no_numbers() {
        let mut r = sample("xc3s");
        r.unsupported = Some("yosys 0.9: `synth_xilinx` does not support `-family xc3s`".into());
        r.measured = None;
        let json = serde_json::to_string(&r).unwrap();
        let v: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert!(
            v.get("top_area").is_none() && v.get("pnr").is_none(),
            "{json}"
        );
        let back: SynthReport = serde_json::from_str(&json).unwrap();
        assert!(back.measured.is_none());
        assert!(r.text().contains("NOT SUPPORTED: yosys 0.9"));
        // Supported but not placed: pnr is written as null.
        let v = serde_json::to_value(sample("xc7")).unwrap();
        assert!(v["pnr"].is_null() && v["reference"].is_null());
    }

    #[test]
    fn text_report_gives_area_fmax_and_margin() {
        let text = sample("ice40").text();
        assert!(
            text.contains("    LUT4 1015   FF 490   carry 201   BRAM 0\n"),
            "{text}"
        );
        assert!(text.contains("2100/5280 logic cells (40 %)"), "{text}");
        // 40.06 MHz >= 2 x 16 MHz; >= the 12 MHz board clock.
        assert!(
            text.contains("Fmax 40.06 MHz; board clock 12 MHz: met"),
            "{text}"
        );
        assert!(
            text.contains("Fmax = 2.50x the recommended 16 MHz for 1 Mbit/s (need >= 2x: ok)"),
            "{text}"
        );
        let xc7 = sample("xc7").text();
        assert!(xc7.contains("place and route: not run"), "{xc7}");
        assert!(xc7.contains("constraints/xc7/README.md"), "{xc7}");
    }

    #[test]
    fn an_fmax_below_the_margin_is_flagged() {
        let mut r = sample("ice40");
        let p = r.measured.as_mut().unwrap().pnr.as_mut().unwrap();
        p.fmax_mhz = 20.0;
        assert!(!p.has_margin() && p.meets_board_clock());
        assert!(r.text().contains("BELOW the required margin"));
    }
}
