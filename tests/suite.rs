//! The command line's integration tests, as one test binary: each module is one
//! file of `tests/` (its own header says what it shows). One binary links once
//! and lets `cargo test` run the tests of every file side by side on the
//! machine's cores, instead of one file's binary after another.
//! `every_test_file_is_built` below fails when a file of `tests/` is not a
//! module here (`autotests` is off in `Cargo.toml`).

mod bad_input;
mod cocotb;
mod doc_links;
mod fusesoc;
mod generate_config;
mod generated_files;
mod lint_gate;
mod litex;
mod power_up;
mod serve;
mod synth;
mod traffic;
mod verilog_params;

/// Every `tests/*.rs` is a module of this binary: with `autotests = false` a new
/// file would otherwise build and run nothing.
#[test]
fn every_test_file_is_built() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let unbuilt = drcc_tools::unbuilt_test_files(&dir, include_str!("suite.rs"), &[]);
    assert!(
        unbuilt.is_empty(),
        "tests/ files no test target builds: {unbuilt:?}"
    );
}
