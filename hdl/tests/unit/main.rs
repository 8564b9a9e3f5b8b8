//! drcc-hdl's unit tests, one module per source module (`bus::apb` tests
//! `drcc_hdl::bus::apb`). They live outside the library so that `cargo test`
//! compiles drcc-hdl once, not a second time with `cfg(test)`.

mod bus;
mod channel;
mod config;
mod dmr;
mod drcc;
mod host;
mod hub;
mod memory;
mod pelican;
mod pins;
mod redcan;
mod rmb;
mod synth_check;
mod tops;
