//! The host-bus front ends (`cosim/src/model/bus_contract.md`): every register
//! map is served on its Wishbone register port (the tops' `wb_*` ports, with
//! `SEL` and `ERR`); [`apb`] and [`axi_lite`] bridge APB4 and AXI4-Lite to that
//! port, and [`drcc_tops`] and [`hub_tops`] put them in front of the DRCC and
//! the hub.
pub mod apb;
pub mod axi_lite;
pub mod drcc_tops;
pub mod hub_tops;
