//! CiA 701 dual-modular redundancy in the DRCC (`cosim/src/model/dmr_contract.md`):
//! the DMR function's blocks. The DMR registers themselves are in
//! `crate::host::dmr_regs` (the register map is one table).
pub mod engine;
pub mod mailbox_cfg;
pub mod mailbox_state;
