//! The flip-flops at the CAN pins, where an FPGA flow needs more than a plain
//! register: the transmit registers are recessive from configuration on, before
//! any clock or reset ([`RecessiveReg`]), and the receive synchronizers carry the
//! attributes vendor tools use to find and place synchronizer flip-flops
//! ([`SyncCell`]).

pub mod recessive_reg;
pub mod sync_cell;

pub use recessive_reg::RecessiveReg;
pub use sync_cell::SyncCell;
