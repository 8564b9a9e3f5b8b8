//! Tests of `drcc_hdl::channel::bus_sampling`.

mod synchronizer;
