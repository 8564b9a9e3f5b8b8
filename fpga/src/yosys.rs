//! yosys: the synthesis scripts (a top alone, a top in its scan wrapper), the
//! run, and the parse of the `stat` report into an [`Area`] (LUTs, flip-flops,
//! carry, BRAM ... counted by the family's cell names).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::target::{Arch, Target};
use crate::tools::{run_logged, YOSYS};
use crate::{write_file, Error};

/// Cell counts of one synthesised netlist, grouped.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Area {
    /// Logic LUTs.
    pub lut: u64,
    /// Flip-flops.
    pub ff: u64,
    /// Carry cells (SB_CARRY: 1 bit; MUXCY: 1 bit; CARRY4: 4 bits).
    pub carry: u64,
    /// Block RAMs.
    pub bram: u64,
    /// LUT RAM and shift-register LUTs (Xilinx).
    pub lutram: u64,
    /// Wide-function multiplexers MUXF5..MUXF8 (Xilinx).
    pub muxf: u64,
    /// DSP / multiplier blocks.
    pub dsp: u64,
    /// Latches (should be none).
    pub latch: u64,
    /// Every cell type and its count.
    pub cells: BTreeMap<String, u64>,
}

impl Area {
    /// Groups yosys cell counts by the cell naming of `arch`.
    pub fn from_cells(arch: Arch, cells: BTreeMap<String, u64>) -> Self {
        let mut a = Area::default();
        for (name, &n) in &cells {
            let s = name.as_str();
            let group = match arch {
                Arch::Ice40 => match s {
                    "SB_LUT4" => Some(&mut a.lut),
                    "SB_CARRY" => Some(&mut a.carry),
                    "SB_MAC16" => Some(&mut a.dsp),
                    _ if s.starts_with("SB_DFF") => Some(&mut a.ff),
                    _ if s.starts_with("SB_RAM40_4K") => Some(&mut a.bram),
                    _ => None,
                },
                Arch::Xilinx => {
                    let lut_n = s.strip_prefix("LUT").is_some_and(|d| {
                        d.len() == 1 && d.chars().all(|c| ('1'..='6').contains(&c))
                    });
                    if lut_n {
                        Some(&mut a.lut)
                    } else if s.starts_with("FD") {
                        Some(&mut a.ff)
                    } else if s.starts_with("LD") {
                        Some(&mut a.latch)
                    } else if s == "CARRY4" || s == "CARRY8" || s == "MUXCY" {
                        Some(&mut a.carry)
                    } else if s.starts_with("RAMB") {
                        Some(&mut a.bram)
                    } else if s.starts_with("RAM") || s.starts_with("SRL") {
                        Some(&mut a.lutram)
                    } else if s.starts_with("MUXF") {
                        Some(&mut a.muxf)
                    } else if s.starts_with("DSP48") || s.starts_with("MULT18X18") {
                        Some(&mut a.dsp)
                    } else {
                        None
                    }
                }
            };
            if let Some(count) = group {
                *count += n;
            }
        }
        a.cells = cells;
        a
    }

    /// The group counts and cells of `self` and `other` together.
    pub fn plus(&self, other: &Area) -> Area {
        let mut cells = self.cells.clone();
        for (c, n) in &other.cells {
            *cells.entry(c.clone()).or_insert(0) += n;
        }
        Area {
            lut: self.lut + other.lut,
            ff: self.ff + other.ff,
            carry: self.carry + other.carry,
            bram: self.bram + other.bram,
            lutram: self.lutram + other.lutram,
            muxf: self.muxf + other.muxf,
            dsp: self.dsp + other.dsp,
            latch: self.latch + other.latch,
            cells,
        }
    }

    /// The group counts of `self` less those of `other` (no cell list): the cost
    /// of a wrapper around a top.
    pub fn minus(&self, other: &Area) -> Area {
        let d = |a: u64, b: u64| a.saturating_sub(b);
        Area {
            lut: d(self.lut, other.lut),
            ff: d(self.ff, other.ff),
            carry: d(self.carry, other.carry),
            bram: d(self.bram, other.bram),
            lutram: d(self.lutram, other.lutram),
            muxf: d(self.muxf, other.muxf),
            dsp: d(self.dsp, other.dsp),
            latch: d(self.latch, other.latch),
            cells: BTreeMap::new(),
        }
    }
}

/// Cell counts of a yosys `stat` report (the last module / hierarchy block).
pub fn parse_stat(text: &str) -> Result<BTreeMap<String, u64>, String> {
    let lines: Vec<&str> = text.lines().collect();
    // yosys <= 0.3x: "Number of cells:  1706"; later: "1706 cells".
    let start = lines
        .iter()
        .rposition(|l| {
            let t = l.trim();
            t.starts_with("Number of cells:")
                || (t.ends_with(" cells") && t.split_whitespace().count() == 2)
        })
        .ok_or_else(|| "no cell count in the yosys statistics".to_string())?;
    let mut cells = BTreeMap::new();
    for l in &lines[start + 1..] {
        let toks: Vec<&str> = l.split_whitespace().collect();
        if toks.len() != 2 {
            break;
        }
        let (name, count) = match (toks[0].parse::<u64>(), toks[1].parse::<u64>()) {
            (Err(_), Ok(n)) => (toks[0], n),
            (Ok(n), Err(_)) => (toks[1], n),
            _ => break,
        };
        *cells.entry(name.to_string()).or_insert(0) += count;
    }
    Ok(cells)
}

/// A path for a yosys script line (quoted if it has spaces).
pub fn quote(p: &Path) -> String {
    let s = p.display().to_string();
    if s.contains(char::is_whitespace) {
        format!("\"{s}\"")
    } else {
        s
    }
}

/// Script synthesising `top` (in the Verilog file `rtl`) alone, out of context.
pub fn top_script(t: &Target, rtl: &Path, top: &str) -> String {
    format!("read_verilog {}\n{} -top {top}\n", quote(rtl), t.synth)
}

/// Script synthesising the scan wrapper `module` (in `wrapper_file`, relative
/// to the build directory) around the top in `rtl`; for a placed family it
/// also writes the netlist `<module>.json` for nextpnr.
pub fn wrapper_script(t: &Target, rtl: &Path, wrapper_file: &str, module: &str) -> String {
    let json_out = if t.pnr.is_some() {
        format!(" -json {module}.json")
    } else {
        String::new()
    };
    format!(
        "read_verilog {}\nread_verilog {wrapper_file}\n{} -top {module}{json_out}\n",
        quote(rtl),
        t.synth
    )
}

/// Runs yosys in `dir` on `script` (written to `<name>.ys`, with a `stat` that
/// goes to `<name>_stat.txt`, log `<name>_yosys.log`); returns the area.
pub fn run(dir: &Path, name: &str, script: &str, arch: Arch) -> Result<Area, Error> {
    let (text, stat_path) = run_stat(dir, name, script)?;
    let cells = parse_stat(&text).map_err(|m| Error(format!("{}: {m}", stat_path.display())))?;
    Ok(Area::from_cells(arch, cells))
}

/// Runs yosys in `dir` on `script` followed by `stat` (files as [`run`]);
/// returns the text of the statistics and the path it was read from.
pub fn run_stat(dir: &Path, name: &str, script: &str) -> Result<(String, PathBuf), Error> {
    let ys = format!("{name}.ys");
    let stat = format!("{name}_stat.txt");
    let log = format!("{name}_yosys.log");
    let full = format!("{script}tee -q -o {stat} stat\n");
    write_file(&dir.join(&ys), &full)?;
    let _ = std::fs::remove_file(dir.join(&stat));
    let _ = std::fs::remove_file(dir.join(&log));
    run_logged(
        &YOSYS,
        &["-q".to_string(), "-l".to_string(), log.clone(), ys],
        dir,
        &log,
    )?;
    let stat_path = dir.join(&stat);
    let text = std::fs::read_to_string(&stat_path).map_err(|e| {
        Error(format!(
            "yosys wrote no statistics ({}): {e}",
            stat_path.display()
        ))
    })?;
    Ok((text, stat_path))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::target::TARGETS;

    /// The statistics yosys 0.23 wrote for can_channel (synth_ice40 -flatten).
    const YOSYS_ICE40_STAT: &str = "\n\
3. Printing statistics.\n\
\n\
=== can_channel ===\n\
\n\
   Number of wires:               1170\n\
   Number of wire bits:           4554\n\
   Number of public wires:        1170\n\
   Number of public wire bits:    4554\n\
   Number of memories:               0\n\
   Number of memory bits:            0\n\
   Number of processes:              0\n\
   Number of cells:               1706\n\
     SB_CARRY                      201\n\
     SB_DFF                          4\n\
     SB_DFFE                       143\n\
     SB_DFFESR                     286\n\
     SB_DFFESS                       5\n\
     SB_DFFSR                       47\n\
     SB_DFFSS                        5\n\
     SB_LUT4                      1015\n\
\n";

    /// yosys 0.23, synth_xilinx -family xc3s -flatten, can_channel.
    const YOSYS_XC3S_STAT: &str = "\
=== can_channel ===\n\
\n\
   Number of wires:               2694\n\
   Number of cells:               3556\n\
     BUFG                            1\n\
     FDRE                          480\n\
     FDSE                           10\n\
     IBUF                          131\n\
     INV                            44\n\
     LUT1                          263\n\
     LUT2                          177\n\
     LUT3                          167\n\
     LUT4                          494\n\
     MUXCY                         162\n\
     MUXF5                         777\n\
     MUXF6                         310\n\
     MUXF7                         143\n\
     MUXF8                          53\n\
     OBUF                          187\n\
     XORCY                         157\n\
\n";

    #[test]
    fn parses_yosys_ice40_stat() {
        let cells = parse_stat(YOSYS_ICE40_STAT).unwrap();
        assert_eq!(cells["SB_LUT4"], 1015);
        assert_eq!(cells.len(), 8);
        let a = Area::from_cells(Arch::Ice40, cells);
        assert_eq!((a.lut, a.ff, a.carry, a.bram), (1015, 490, 201, 0));
        assert_eq!((a.lutram, a.muxf, a.dsp, a.latch), (0, 0, 0, 0));
    }

    #[test]
    fn parses_yosys_xilinx_stat() {
        let a = Area::from_cells(Arch::Xilinx, parse_stat(YOSYS_XC3S_STAT).unwrap());
        assert_eq!(a.lut, 263 + 177 + 167 + 494);
        assert_eq!(a.ff, 490);
        assert_eq!(a.carry, 162);
        assert_eq!(a.muxf, 777 + 310 + 143 + 53);
        assert_eq!((a.bram, a.latch), (0, 0));
        assert_eq!(a.cells["XORCY"], 157);
    }

    #[test]
    fn parses_newer_yosys_stat_layout() {
        let text = "=== t ===\n\n        12 wires\n        3 cells\n         2   SB_LUT4\n         1   SB_DFF\n\n";
        let a = Area::from_cells(Arch::Ice40, parse_stat(text).unwrap());
        assert_eq!((a.lut, a.ff), (2, 1));
        assert!(parse_stat("nothing here\n").is_err());
    }

    #[test]
    fn overhead_is_the_difference_of_the_groups() {
        let top = Area::from_cells(Arch::Ice40, parse_stat(YOSYS_ICE40_STAT).unwrap());
        let mut wrapped = top.clone();
        wrapped.lut += 30;
        wrapped.ff += 200;
        let o = wrapped.minus(&top);
        assert_eq!((o.lut, o.ff, o.carry), (30, 200, 0));
        assert!(o.cells.is_empty());
    }

    #[test]
    fn scripts_name_the_top_and_write_the_netlist_for_nextpnr() {
        let ice40 = &TARGETS[0];
        let xc7 = &TARGETS[3];
        let rtl = Path::new("/w/rtl-out/can_channel.v");
        assert_eq!(
            top_script(xc7, rtl, "can_channel"),
            "read_verilog /w/rtl-out/can_channel.v\nsynth_xilinx -family xc7 -flatten -abc9 -top can_channel\n"
        );
        let w = wrapper_script(ice40, rtl, "can_channel_scan.v", "can_channel_scan");
        assert!(w.ends_with(
            "read_verilog can_channel_scan.v\nsynth_ice40 -flatten -top can_channel_scan -json can_channel_scan.json\n"
        ), "{w}");
        assert!(!wrapper_script(xc7, rtl, "x.v", "x").contains("-json"));
        assert_eq!(quote(Path::new("/a b/c.v")), "\"/a b/c.v\"");
    }
}
