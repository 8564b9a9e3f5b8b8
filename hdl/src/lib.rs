//! drcc-hdl: the DRCC hardware, described in rust-hdl, one block per file.
pub mod bus;
pub mod channel;
pub mod config;
pub mod dmr;
pub mod drcc;
pub mod drcc_core;
pub mod generated;
pub mod host;
pub mod hub;
pub mod memory;
pub mod pelican;
pub mod pins;
pub mod redcan;
pub mod rmb;

pub mod tops;
