//! Tests of `drcc_hdl::redcan`.

mod rcm;
