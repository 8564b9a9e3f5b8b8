//! Host interface of the tops: the register-map tables (the one source of truth
//! of the DRCC's and the hub's maps, with the generators of their documents and
//! C headers), the Wishbone B4 classic slave both register blocks instantiate,
//! and the DRCC's register block.
pub mod busoff_recovery;
pub mod captures;
pub mod codes;
pub mod ctrl_check;
pub mod ctrl_reg;
pub mod dmr_check;
pub mod dmr_registers;
pub mod dmr_regs;
pub mod ecss_registers;
pub mod ecss_regs;
pub mod filters;
pub mod generate;
pub mod hub_registers;
pub mod map;
mod register_fields;
pub mod registers;
pub mod status_words;
pub mod wb_slave;
pub mod wishbone;
