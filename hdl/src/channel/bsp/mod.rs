//! Bit stream processor: frame coding and decoding, stuffing, CRC, arbitration,
//! acknowledgement, error and overload frames (ISO 11898-1 clauses 10 and 12).
//! `protocol` wires the units; each other file is one unit.
pub mod bit_stuffing;
pub mod crc;
pub mod error_capture;
pub mod error_decision;
pub mod error_detection;
pub mod fault_confinement;
pub mod fault_confinement_rules;
pub mod field;
pub mod field_decode;
pub mod frame_crc;
pub mod protocol;
pub mod protocol_fsm;
pub mod rules_decision;
pub mod rx_frame;
pub mod sample_lookahead;
pub mod tx_frame;
pub mod tx_pin;
pub mod tx_request;
