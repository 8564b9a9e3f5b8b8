//! The DRCC reference model as a [`DrccEngine`] (engine name `model`): a thin
//! wrapper around [`crate::model::drcc::DrccModel`], the oracle written from the DRCC
//! contract (`drcc_contract.md`) and the DRCC paper.

use super::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use crate::model::drcc::DrccModel;

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
}

impl DrccEngine for DrccModelEngine {
    fn name(&self) -> &'static str {
        "model"
    }

    fn step(&mut self, inputs: &DrccInputs) -> DrccOutputs {
        self.model.step(inputs)
    }
}
