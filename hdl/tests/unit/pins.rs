//! Tests of `drcc_hdl::pins`.

mod recessive_reg;
mod sync_cell;
