//! The FPGA families the flow targets: for each its yosys synthesis command,
//! its documented board (part, oscillator, constraints file), nextpnr options
//! where there is a place and route, and the area of the reference controller.

use serde::{Deserialize, Deserializer, Serializer};

/// System clock the README recommends for 1 Mbit/s: 16 MHz gives BRP = 0 and
/// 16 time quanta per bit (sample point 13/16 = 81.25 % with TSEG1 = 12,
/// TSEG2 = 3), inside the 8..=25 tq ISO 11898-1 allows.
pub const RECOMMENDED_CLOCK_MHZ: f64 = 16.0;

/// The iCE40 Fmax must be at least this multiple of [`RECOMMENDED_CLOCK_MHZ`].
pub const FMAX_MARGIN: f64 = 2.0;

/// Area reference: the single-channel OpenCores CAN controller (SJA1000
/// compatible), synthesised with the same yosys.
pub const REFERENCE_NAME: &str = "OpenCores CAN (SJA1000-compatible, one channel)";

/// Cell naming of the architecture, for counting LUTs, flip-flops ...
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arch {
    /// Lattice iCE40 (`SB_*` cells).
    Ice40,
    /// Xilinx (`LUTn`, `FD*`, `MUXF*` ... cells).
    Xilinx,
}

/// One FPGA family the flow targets, with its documented board.
#[derive(Debug, PartialEq)]
pub struct Target {
    /// `--target` value.
    pub name: &'static str,
    /// Human name of the family.
    pub family: &'static str,
    /// Cell naming, for the area count.
    pub arch: Arch,
    /// yosys synthesis command, without `-top`.
    pub synth: &'static str,
    /// `-family` value that must appear in `yosys -h synth_xilinx`.
    pub family_option: Option<&'static str>,
    /// LUT kind (for the report).
    pub lut: &'static str,
    /// The documented board.
    pub board: &'static str,
    /// FPGA part on the board.
    pub device: &'static str,
    /// Board oscillator.
    pub clock_mhz: f64,
    /// Constraints file, relative to the workspace.
    pub constraints: &'static str,
    /// nextpnr-ice40 device and package options (iCE40 only).
    pub pnr: Option<&'static [&'static str]>,
    /// Reference (LUTs, FFs) of the OpenCores CAN controller, if measured.
    pub reference: Option<(u64, u64)>,
}

/// The targets, in table order.
pub const TARGETS: &[Target] = &[
    Target {
        name: "ice40",
        family: "Lattice iCE40 UltraPlus",
        arch: Arch::Ice40,
        synth: "synth_ice40 -flatten",
        family_option: None,
        lut: "LUT4",
        board: "iCEBreaker",
        device: "iCE40UP5K-SG48",
        clock_mhz: 12.0,
        constraints: "constraints/ice40/icebreaker.pcf",
        pnr: Some(&["--up5k", "--package", "sg48"]),
        reference: Some((2400, 1460)),
    },
    Target {
        name: "ice40hx",
        family: "Lattice iCE40 HX",
        arch: Arch::Ice40,
        synth: "synth_ice40 -flatten",
        family_option: None,
        lut: "LUT4",
        board: "Lattice iCE40-HX8K Breakout Board",
        device: "iCE40HX8K-CT256",
        clock_mhz: 12.0,
        constraints: "constraints/ice40/hx8k_breakout.pcf",
        pnr: Some(&["--hx8k", "--package", "ct256"]),
        reference: Some((2400, 1460)),
    },
    Target {
        name: "xc3s",
        family: "Xilinx Spartan-3",
        arch: Arch::Xilinx,
        synth: "synth_xilinx -family xc3s -flatten",
        family_option: Some("xc3s"),
        lut: "LUT4",
        board: "Digilent Spartan-3 Starter Board",
        device: "XC3S200-4FT256",
        clock_mhz: 50.0,
        constraints: "constraints/xc3s/s3_starter.ucf",
        pnr: None,
        reference: Some((1710, 630)),
    },
    Target {
        name: "xc7",
        family: "Xilinx Artix-7",
        arch: Arch::Xilinx,
        synth: "synth_xilinx -family xc7 -flatten -abc9",
        family_option: Some("xc7"),
        lut: "LUT6",
        board: "Digilent Arty A7-35T",
        device: "XC7A35TICSG324-1L",
        clock_mhz: 100.0,
        constraints: "constraints/xc7/arty_a7_35t.xdc",
        pnr: None,
        reference: None,
    },
];

impl Target {
    /// The target with this `--target` name.
    pub fn by_name(name: &str) -> Option<&'static Target> {
        TARGETS.iter().find(|t| t.name == name)
    }

    /// The yosys pass of [`Target::synth`] (`synth_ice40`, `synth_xilinx`).
    pub fn synth_pass(&self) -> &'static str {
        self.synth.split_whitespace().next().unwrap_or("")
    }

    /// The carry cell of the family, for the table's carry column.
    pub fn carry_cell(&self) -> &'static str {
        match self.arch {
            Arch::Ice40 => "SB_CARRY",
            Arch::Xilinx if self.family_option == Some("xc7") => "CARRY4",
            Arch::Xilinx => "MUXCY",
        }
    }
}

/// The `--target` names, in table order.
pub fn names() -> Vec<&'static str> {
    TARGETS.iter().map(|t| t.name).collect()
}

/// Serialises a target as its `--target` name (the report's `"target"`).
pub(crate) fn serialize_name<S: Serializer>(t: &&'static Target, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(t.name)
}

/// Reads a target back from its `--target` name.
pub(crate) fn deserialize_name<'de, D: Deserializer<'de>>(
    d: D,
) -> Result<&'static Target, D::Error> {
    let name = String::deserialize(d)?;
    Target::by_name(&name).ok_or_else(|| {
        serde::de::Error::custom(format!(
            "unknown target `{name}`; the targets are {}",
            names().join(", ")
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_are_found_by_name() {
        assert_eq!(names(), ["ice40", "ice40hx", "xc3s", "xc7"]);
        let xc7 = Target::by_name("xc7").unwrap();
        assert_eq!(
            (xc7.synth_pass(), xc7.carry_cell()),
            ("synth_xilinx", "CARRY4")
        );
        let xc3s = Target::by_name("xc3s").unwrap();
        assert_eq!(xc3s.carry_cell(), "MUXCY");
        assert!(Target::by_name("ecp5").is_none());
    }

    #[test]
    fn only_ice40_is_placed_and_routed() {
        for t in TARGETS {
            assert_eq!(t.pnr.is_some(), t.arch == Arch::Ice40, "{}", t.name);
        }
    }
}
