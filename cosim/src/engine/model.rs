//! The reference model as a [`ChannelEngine`] (engine name `model`): a thin wrapper
//! around [`crate::model::ChannelModel`], the oracle written from ISO 11898-1 and
//! the clock-level timing contract.

use super::{ChannelEngine, ChannelInputs, ChannelOutputs};
use crate::model::ChannelModel;

/// The reference model engine.
#[derive(Clone, Debug, Default)]
pub struct ModelEngine {
    model: ChannelModel,
}

impl ModelEngine {
    /// A model engine in its reset state.
    pub fn new() -> Self {
        ModelEngine {
            model: ChannelModel::new(),
        }
    }
}

impl ChannelEngine for ModelEngine {
    fn name(&self) -> &'static str {
        "model"
    }

    fn step(&mut self, inputs: &ChannelInputs) -> ChannelOutputs {
        self.model.step(inputs)
    }
}
