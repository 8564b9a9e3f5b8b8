//! Tests of `drcc_hdl::hub`.

mod ack_unit;
mod config;
mod coupler;
mod guard_stage;
#[allow(clippy::module_inception)]
mod hub;
mod id_frame;
mod nrap;
mod nrap_ahead;
mod port_guard;
mod registers;
mod star_tests;
mod tracker;
