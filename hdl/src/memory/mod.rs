//! DRCC memories (contract §6, §7): the TX message buffer, the RX FIFO and the
//! receive writer with its duplicate-removal history. Each RAM is rust-hdl's
//! `RAM` (registered read port) so that it maps to block RAM.
pub mod dedup;
pub mod rx_fifo;
pub mod tx_buffer;
