//! Tests of `drcc_hdl::pelican`.

mod acceptance_filter;
mod ecc_code;
