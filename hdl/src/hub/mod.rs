//! The ReCANcentrate hub (ReCANcentrate paper sections 2-5, `hub_contract.md`):
//! input synchronizers and the two-stage AND coupler, the ACK unit (the bus
//! guardian that owns the downlinks), the frame tracker, one guard per port, the
//! Wishbone register block and the `hub` top.
pub mod ack_unit;
pub mod coupler;
// `hub/hub.rs` is the top, named like the other tops (`docs/design.md`, layout).
#[allow(clippy::module_inception)]
pub mod hub;
pub mod port_guard;
pub mod registers;
pub mod tracker;
