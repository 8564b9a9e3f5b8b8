//! The CiA 701 DMR test plan (seed 001 "Dual-modular Redundancy for CAN
//! networks", Figure 9, Tables 2 and 3; DMR contract §10): four DRCC devices in DMR
//! mode, COS1, COS2, COS3 and COM1 (nodes 0..3), channel A on the default CAN line
//! (DCL, line A) and channel B on the redundant CAN line (RCL, line B), at 125 kbit/s
//! and an 85 % average bus load, and the ten fault markers F1..F10, each present at
//! power-on ("startup failure") and arising at run time, plus a fault-free baseline.
//!
//! - [`marker`]: F1..F10 and what each one does to the network (derived from Tables 2
//!   and 3, contract §10);
//! - [`setup`]: the devices, their identifiers and mailboxes, the DMR configuration and
//!   the time line of a run;
//! - [`load`]: the traffic: frame lengths in bits (stuffing included) and the message
//!   periods that give the 85 % load;
//! - [`probes`]: the DMR probes read every clock (state, ACL, fault flags);
//! - [`run`]: one row on one engine, or on two in lock step;
//! - [`report`]: what a row shows and the Markdown table (`drcc dmr table`).
//!
//! Time base: the simulated clock is 1 MHz and a bit is 8 clocks (`BTR`: BRP 0, so a
//! time quantum is one clock; 1 + TSEG1 5 + TSEG2 2 = 8 quanta), which is 125 kbit/s.
//! One DMR tick is `tick_bits = 125` bit times = 1 ms = 1000 clocks; reports give times
//! in ms (bit times / 125).

pub mod load;
pub mod marker;
pub mod probes;
pub mod report;
pub mod run;
pub mod setup;

pub use marker::{Marker, Onset, PlanFault, Row, DEVICES};
pub use report::{dmr_table, first_copy_cells, row_line, DeviceStatus, RowReport};
pub use run::{run_row, run_row_traced};
pub use setup::PlanConfig;

/// Clocks per bit: 125 kbit/s at a 1 MHz clock (module docs).
pub const CLOCKS_PER_BIT: u64 = 8;

/// Bit times per millisecond at 125 kbit/s (also `DMR_TIME.tick_bits`: 1 ms ticks).
pub const BITS_PER_MS: u64 = 125;

/// Clocks per millisecond.
pub const CLOCKS_PER_MS: u64 = CLOCKS_PER_BIT * BITS_PER_MS;

/// The simulated clock frequency (for VCD time stamps).
pub const CLOCK_HZ: u64 = CLOCKS_PER_MS * 1000;

/// Clocks as milliseconds.
pub fn ms(clocks: u64) -> f64 {
    clocks as f64 / CLOCKS_PER_MS as f64
}
