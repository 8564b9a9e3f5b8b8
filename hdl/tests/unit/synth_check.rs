//! The synthesis check beside every block (`*_synthesizes` tests): yosys reads
//! the block's emitted Verilog and must accept it. Without yosys the check is
//! skipped with one line on a developer's machine and fails in CI
//! (`drcc_tools::need`), so `cargo test` passes on a machine with Rust alone.

use rust_hdl::prelude::yosys_validate;

/// Runs yosys on `verilog` (the top named `name`) when yosys is present, or
/// skips as `drcc_tools::need` rules; panics with yosys's complaint when it
/// rejects the Verilog.
pub fn yosys_check(name: &str, verilog: &str) {
    if drcc_tools::need(&drcc_tools::YOSYS) {
        if let Err(e) = yosys_validate(name, verilog) {
            panic!("yosys rejects {name}: {e:?}");
        }
    }
}
