//! drcc-hdl: the DRCC hardware, described in rust-hdl, one block per file.
pub mod channel;
pub mod tops;
