//! Tests of `drcc_hdl::drcc`.

use drcc_hdl::drcc::*;
use rust_hdl::prelude::*;

mod tests;
