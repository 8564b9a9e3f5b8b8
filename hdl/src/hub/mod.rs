//! The ReCANcentrate hub (ReCANcentrate paper sections 2-5, `hub_contract.md`):
//! input synchronizers and the two-stage AND coupler, the ACK unit (the bus
//! guardian that owns the downlinks), the frame tracker, one guard per port, the
//! Network Reconfiguration Agreement Protocol (its phase machine and the
//! identification-frame transmitter and recogniser), the Wishbone register block
//! with the cfg registers, and the `hub` / `hub_b` top.
pub mod ack_unit;
pub mod config;
pub mod coupler;
pub mod guard_stage;
// `hub/hub.rs` is the top, named like the other tops (`docs/design.md`, layout).
#[allow(clippy::module_inception)]
pub mod hub;
pub mod id_frame;
pub mod nrap;
pub mod nrap_ahead;
pub mod port_guard;
pub mod registers;

pub mod tracker;
