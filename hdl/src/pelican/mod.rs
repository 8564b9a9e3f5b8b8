//! The SJA1000 (PeliCAN) host view of the DRCC (`cosim/src/model/pelican_contract.md`,
//! user's page `docs/pelican.md`): its blocks, one concern each.

pub mod acceptance_filter;
pub mod armed_capture;
pub mod byte_lanes;
pub mod ecc_code;
pub mod interrupts;
pub mod logical;
pub mod mode_control;
pub mod rbsa;
pub mod rx_window;
pub mod tx_frame_buffer;
