//! Tests of `drcc_hdl::pelican`.

mod acceptance_filter;
mod armed_capture;
mod byte_lanes;
mod config_regs;
mod ecc_code;
mod extension;
mod interrupts;
mod logical;
mod mode_control;
mod native_window;
mod rbsa;
mod rx_window;
mod tx_frame_buffer;
