//! DRCC memories (contract §6, §7): the TX message buffer, the RX FIFO and the
//! receive writer with its duplicate-removal history; frames enter the TX buffer
//! normalized (`tx_normalize`). Each RAM is a `bram::Bram`
//! (registered read port, collisions declared undefined) so that it maps to
//! block RAM with no read-before-write emulation.
pub mod bram;
pub mod dedup;
pub mod release_scan;
pub mod rx_fifo;
pub mod rx_stats;
pub mod tx_buffer;
pub mod tx_normalize;
