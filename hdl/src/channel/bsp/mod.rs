//! Bit stream processor: frame coding and decoding, stuffing, CRC, arbitration,
//! acknowledgement, error and overload frames (ISO 11898-1 clauses 10 and 12).
pub mod crc;
pub mod fault_confinement;
pub mod field;
pub mod protocol;
