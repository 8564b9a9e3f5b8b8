//! Tests of `drcc_hdl::memory`.

mod dedup;
mod release_scan;
mod rx_fifo;
mod rx_stats;
mod tx_buffer;
mod tx_normalize;
