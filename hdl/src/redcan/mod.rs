//! REDCAN (seed 000): the relay module that closes CAN bus sections into a ring
//! and opens it where the ring must end (`cosim/src/model/ring_contract.md`).
pub mod rcm;
