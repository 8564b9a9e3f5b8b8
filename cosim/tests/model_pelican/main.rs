//! Tests of the PeliCAN view reference model against `pelican_contract.md`
//! (rules P-...) and the SJA1000 datasheet. Expected values come from the
//! contract and the datasheet, never from the model.

#[path = "../model_support/mod.rs"]
mod support;

mod acceptance;
mod busoff;
mod conformance;
mod drivers;
mod harness;
mod map;
mod side_by_side;
mod sja1000_ref;

/// Nothing runs beside the model here (the lock step, `pelican_lockstep.rs`,
/// runs the RTL).
mod shadow {
    use drcc_cosim::model::pelican::{PelicanInputs, PelicanModel, PelicanParams};

    #[derive(Clone)]
    pub struct Shadow;

    impl Shadow {
        pub fn new(_: &PelicanParams) -> Self {
            Shadow
        }

        /// No other top: every key is the model's own.
        pub fn keyed(_: &PelicanParams) -> Option<(PelicanParams, Self)> {
            None
        }

        pub fn edge(&mut self, _: &PelicanInputs, _: &PelicanModel) {}
    }
}
