//! drcc-fpga: the FPGA flow of `drcc synth`. Synthesises a top of `rtl-out/`
//! with yosys for one FPGA family, and for iCE40 places and routes it with
//! nextpnr-ice40 and packs a bitstream with icepack.
//!
//! Two netlists are synthesised per top and family:
//!
//! - the top alone, out of context (`synth_ice40` / `synth_xilinx -family F`,
//!   flattened): the area of record;
//! - the top inside a generated scan wrapper ([`scan`]): `clk`, `rst` and the
//!   CAN pins on package pins, every other port on a scan chain. Its area minus
//!   the top's is reported as the wrapper overhead.
//!
//! For iCE40 the wrapper is placed and routed on the board
//! (`constraints/ice40/icebreaker.pcf` for the iCEBreaker's UP5K,
//! `hx8k_breakout.pcf` for the HX8K), which gives the Fmax nextpnr reports and
//! a bitstream. The Xilinx families stop after synthesis: there is no
//! place-and-route for them among the Debian tools; `constraints/xc3s` and
//! `constraints/xc7` say how to run ISE / Vivado on the same files.
//!
//! One file per concern, as rust-hdl's `rust-hdl-fpga-support` keeps one per
//! toolchain: [`tools`] (finding and running the programs), [`target`] (the
//! families and boards), [`yosys`], [`nextpnr`], [`icepack`], [`scan`] (the
//! wrapper), [`breakdown`] (the area block by block), [`flow`] (one top on one target), [`report`] (the serde report and
//! its text), [`json`] (its `--json` layout) and [`markdown`] (the generated
//! table and document).

pub mod breakdown;
pub mod flow;
pub mod icepack;
pub mod json;
pub mod markdown;
pub mod nextpnr;
pub mod report;
pub mod scan;
pub mod target;
pub mod tools;
pub mod yosys;

use std::path::Path;

pub use flow::Flow;
pub use report::SynthReport;
pub use target::{Target, TARGETS};
pub use tools::ToolEnv;

/// Why the flow stopped: one message naming the tool, file or input at fault.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error(pub String);

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Error {}

/// Writes `text` to `path` whole or not at all ([`drcc_tools::atomic`]),
/// creating its folder.
pub fn write_file(path: &Path, text: &str) -> Result<(), Error> {
    if let Some(dir) = path.parent() {
        drcc_tools::atomic::create_dir(dir).map_err(Error)?;
    }
    drcc_tools::atomic::write(path, text).map_err(Error)
}
