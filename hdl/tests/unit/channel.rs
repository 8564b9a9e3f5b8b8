//! Tests of `drcc_hdl::channel`.

mod bsp;
mod btl;
mod bus_sampling;
mod can_channel;
mod config;
mod sized;
