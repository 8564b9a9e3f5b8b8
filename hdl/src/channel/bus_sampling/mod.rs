//! Bus sampling: everything between the CAN pins and the bit timing logic.
pub mod synchronizer;
