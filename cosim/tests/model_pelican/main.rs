//! Tests of the PeliCAN view reference model against `pelican_contract.md`
//! (rules P-...) and the SJA1000 datasheet. Expected values come from the
//! contract and the datasheet, never from the model.

#[path = "../model_support/mod.rs"]
mod support;

mod acceptance;
mod busoff;
mod drivers;
mod harness;
mod map;
