//! Host interface of the DRCC top: the register map (the one source of truth)
//! and the Wishbone B4 classic register block that decodes it.
pub mod registers;
pub mod wishbone;
