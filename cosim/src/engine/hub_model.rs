//! The hub reference model as a [`HubEngine`] (engine name `model`): a thin wrapper
//! around [`crate::model::hub::HubModel`], the oracle written from the hub contract
//! (`hub_contract.md`).

use super::hub::{HubEngine, HubInputs, HubOutputs};
use crate::model::hub::HubModel;

/// The hub reference model engine.
#[derive(Clone, Debug)]
pub struct HubModelEngine {
    model: HubModel,
}

impl HubModelEngine {
    /// A model engine with `n` node ports (2..=8) and `m` interlinks (1..=4) in its
    /// reset state; other shapes are refused with a message naming the ranges.
    pub fn new(n: usize, m: usize) -> Result<Self, String> {
        Self::new_hub(0, n, m)
    }

    /// Hub `hub_id` (0 = A, `hub.v`; 1 = B, `hub_b.v`): the identification frame it
    /// sends (hub contract §9.1).
    pub fn new_hub(hub_id: u8, n: usize, m: usize) -> Result<Self, String> {
        Ok(HubModelEngine {
            model: HubModel::new_hub(hub_id, n, m)?,
        })
    }

    /// The same without the ACK unit (hub contract §4.1): not a configuration of
    /// the RTL, which always has it; it shows what a faulty hub does unguarded.
    pub fn without_ack_unit(hub_id: u8, n: usize, m: usize) -> Result<Self, String> {
        Ok(HubModelEngine {
            model: HubModel::new_hub(hub_id, n, m)?.without_ack_unit(),
        })
    }

    /// The model inside (guard and tracker state for tests).
    pub fn model(&self) -> &HubModel {
        &self.model
    }
}

impl HubEngine for HubModelEngine {
    fn name(&self) -> &'static str {
        "model"
    }

    fn shape(&self) -> (usize, usize) {
        self.model.shape()
    }

    fn step(&mut self, inputs: &HubInputs) -> HubOutputs {
        self.model.step(inputs)
    }
}
