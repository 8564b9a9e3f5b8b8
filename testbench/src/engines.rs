//! Engine selection by name (`model`, `rust-hdl`, `verilator`) and construction,
//! with install hints when an engine is not available.

use std::fmt;
use std::str::FromStr;

use drcc_cosim::engine::model::ModelEngine;
use drcc_cosim::engine::rusthdl::RustHdlEngine;
use drcc_cosim::engine::verilator::VerilatorEngine;
use drcc_cosim::ChannelEngine;

/// How to get Verilator.
pub const VERILATOR_HINT: &str = "install it with `apt-get install verilator`";

/// One of the three engines.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EngineKind {
    /// The Rust reference model (the oracle).
    Model,
    /// rust-hdl's simulator running the hdl blocks.
    RustHdl,
    /// The emitted Verilog, verilated.
    Verilator,
}

impl EngineKind {
    /// Every engine, in the order reports list them.
    pub const ALL: [EngineKind; 3] = [
        EngineKind::Model,
        EngineKind::RustHdl,
        EngineKind::Verilator,
    ];

    /// The name as the CLI spells it.
    pub fn name(self) -> &'static str {
        match self {
            EngineKind::Model => "model",
            EngineKind::RustHdl => "rust-hdl",
            EngineKind::Verilator => "verilator",
        }
    }
}

impl fmt::Display for EngineKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for EngineKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.trim().to_ascii_lowercase().as_str() {
            "model" => Ok(EngineKind::Model),
            "rust-hdl" | "rusthdl" | "rust_hdl" => Ok(EngineKind::RustHdl),
            "verilator" => Ok(EngineKind::Verilator),
            other => Err(format!(
                "unknown engine {other:?}: the engines are model, rust-hdl, verilator"
            )),
        }
    }
}

/// Builds one engine of the given kind.
pub fn make_engine(kind: EngineKind) -> Result<Box<dyn ChannelEngine>, String> {
    match kind {
        EngineKind::Model => Ok(Box::new(ModelEngine::new())),
        EngineKind::RustHdl => Ok(Box::new(RustHdlEngine::new())),
        EngineKind::Verilator => match VerilatorEngine::new() {
            Ok(e) => Ok(Box::new(e)),
            Err(e) if e.contains(VERILATOR_HINT) => {
                Err(format!("the Verilator engine is not available: {e}"))
            }
            Err(e) => Err(format!(
                "the Verilator engine is not available: {e} ({VERILATOR_HINT})"
            )),
        },
    }
}

/// Whether the engine can be built here (Verilator may be missing).
pub fn available(kind: EngineKind) -> Result<(), String> {
    make_engine(kind).map(|_| ())
}

/// Whether a missing Verilator must fail instead of being skipped: the one rule
/// of `verilator_sys::required` (`DRCC_REQUIRE_VERILATOR` or `CI` set to anything
/// but empty, `0`, `false`, `no` or `off`).
pub use drcc_cosim::engine::verilator::verilator_required;

/// The engine to run in lock step with the model: Verilator when `probe` (the
/// Verilated top's constructor, `what` its name) succeeds; without it, a panic
/// where Verilator is required (CI) and the model alone elsewhere, said on
/// stderr.
pub fn lockstep_engine(
    what: &str,
    probe: impl FnOnce() -> Result<(), String>,
) -> Option<EngineKind> {
    match probe() {
        Ok(()) => Some(EngineKind::Verilator),
        Err(e) if verilator_required() => panic!("the Verilated {what} is required in CI: {e}"),
        Err(e) => {
            eprintln!("model only, no lock step with the RTL: {e}");
            None
        }
    }
}
