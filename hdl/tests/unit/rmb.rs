//! Tests of `drcc_hdl::rmb`.

mod aux_fsm;
mod bit_tick;
mod echo;
mod ecss;
mod main_fsm;
mod star;
mod stats;
mod switch_policy;
