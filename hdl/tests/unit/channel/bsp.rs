//! Tests of `drcc_hdl::channel::bsp`.

mod bit_stuffing;
mod crc;
mod error_capture;
mod error_decision;
mod error_detection;
mod fault_confinement;
mod fault_confinement_rules;
mod field_decode;
mod frame_crc;
mod protocol;
mod protocol_fsm;
mod rules_decision;
mod rx_frame;
mod sample_lookahead;
mod tx_frame;
mod tx_pin;
mod tx_request;
