//! CiA 701 dual-modular redundancy in the DRCC (`cosim/src/model/dmr_contract.md`):
//! the DMR function's blocks. The DMR registers themselves are in
//! `crate::host::dmr_regs` (the register map is one table).
pub mod control;
pub mod cs_rx;
pub mod engine;
pub mod if_mailboxes;
pub mod line;
pub mod mailbox_cfg;
pub mod mailbox_state;
pub mod offsets;
pub mod sat_count;
pub mod status;
pub mod time_base;
