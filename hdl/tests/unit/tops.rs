//! Tests of `drcc_hdl::tops`.

use drcc_hdl::tops::Direction;
use drcc_hdl::tops::*;

use drcc_hdl::config::DrccConfig;

mod params;
mod port_docs;
mod readable;
mod shim_table;
mod tests;
