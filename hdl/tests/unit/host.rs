//! Tests of `drcc_hdl::host`.

mod busoff_recovery;
mod captures;
mod ctrl_check;
mod ctrl_reg;
mod dmr_check;
mod dmr_regs;
mod ecss_regs;
mod filters;
mod hub_registers;
mod map;
mod registers;
mod status_words;
mod wb_slave;
mod wishbone;
