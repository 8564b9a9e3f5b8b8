//! The DRCC reference model as a [`DrccEngine`] (engine name `model`): a thin
//! wrapper around [`crate::model::drcc::DrccModel`], the oracle written from the DRCC
//! contract (`drcc_contract.md`) and the DRCC paper.

use super::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use crate::model::drcc::{DrccModel, DrccParams};

/// The DRCC reference model engine.
#[derive(Clone, Debug, Default)]
pub struct DrccModelEngine {
    model: DrccModel,
}

impl DrccModelEngine {
    /// A model engine in its reset state.
    pub fn new() -> Self {
        DrccModelEngine {
            model: DrccModel::new(),
        }
    }

    /// A model engine with `m` DMR mailboxes (generation parameter `M`, 0..16;
    /// dmr_contract.md §2).
    pub fn with_mailboxes(m: usize) -> Self {
        DrccModelEngine {
            model: DrccModel::with_mailboxes(m),
        }
    }

    /// A model engine generated with the sizes of `p` (drcc_contract.md §1.1).
    pub fn with_params(p: &DrccParams) -> Self {
        DrccModelEngine {
            model: DrccModel::with_params(p),
        }
    }
}

impl DrccEngine for DrccModelEngine {
    fn name(&self) -> &'static str {
        "model"
    }

    fn step(&mut self, inputs: &DrccInputs) -> DrccOutputs {
        self.model.step(inputs)
    }
}
