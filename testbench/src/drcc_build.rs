//! Which generated DRCC a testbench's nodes are (drcc_contract.md §1.1): the
//! default `drcc` or the `drcc_small` configuration, on the model (constructed
//! with the configuration's sizes) and on the Verilated RTL of that top.

use drcc_cosim::engine::drcc::DrccEngine;
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::engine::drcc_verilator::DrccSmallVerilatorEngine;
use drcc_cosim::model::drcc::DrccParams;

use crate::dual::drcc_engine;
use crate::engines::{EngineKind, VERILATOR_HINT};

/// A DRCC configuration with an emitted top.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DrccBuild {
    /// `rtl-out/drcc.v`: M = 16, RX FIFO 32, TX queues 8, history 32.
    #[default]
    Default,
    /// `rtl-out/drcc_small.v`: M = 0, RX FIFO 8, TX queues 4, history 16.
    Small,
}

impl DrccBuild {
    /// The top's name.
    pub fn name(self) -> &'static str {
        match self {
            DrccBuild::Default => "drcc",
            DrccBuild::Small => "drcc_small",
        }
    }

    /// The sizes the reference model is built with.
    pub fn params(self) -> DrccParams {
        match self {
            DrccBuild::Default => DrccParams::DEFAULT,
            DrccBuild::Small => DrccParams::SMALL,
        }
    }

    /// A DRCC engine of this configuration; Verilator missing is an error that
    /// says how to install it.
    pub fn engine(self, kind: EngineKind) -> Result<Box<dyn DrccEngine>, String> {
        match (self, kind) {
            (DrccBuild::Default, k) => drcc_engine(k),
            (DrccBuild::Small, EngineKind::Model) => {
                Ok(Box::new(DrccModelEngine::with_params(&self.params())))
            }
            (DrccBuild::Small, EngineKind::Verilator) => DrccSmallVerilatorEngine::new()
                .map(|e| Box::new(e) as Box<dyn DrccEngine>)
                .map_err(|e| format!("{e}; {VERILATOR_HINT}")),
            (DrccBuild::Small, EngineKind::RustHdl) => drcc_engine(EngineKind::RustHdl),
        }
    }
}
