//! The integration tests of the testbench, as one test binary: each module is
//! one file of `tests/` (its own header says what it shows). One binary links
//! once and lets `cargo test` run the tests of every file side by side on the
//! machine's cores, instead of one file's binary after another.
//!
//! `coverage.rs` is a binary of its own: it counts the model's cover points in
//! a process-wide counter, which the tests here would add to.
//! `every_test_file_is_built` below fails when a file of `tests/` is neither a
//! module here nor a test target of `Cargo.toml` (`autotests` is off).

mod campaign;
mod conformance;
mod cosim;
mod dmr_plan;
mod dmr_registers;
mod drcc_cosim;
mod drcc_faults;
mod drcc_paper;
mod drcc_races;
mod drcc_sizes;
mod drcc_small_faults;
mod ecss_policy;
mod err_reset;
mod error_stress;
mod hub_cosim;
mod illegal_config;
mod quiet_stretches;
mod random_traffic;
mod rcm;
mod ring;
mod ring_lockstep;
mod scenario_errors;
mod scenarios;
mod sigrok;
mod star_faults;

/// Every `tests/*.rs` and `tests/*/` is a module of this binary or the
/// coverage binary: with `autotests = false` a new file would otherwise build
/// and run nothing.
#[test]
fn every_test_file_is_built() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let unbuilt = drcc_tools::unbuilt_test_files(&dir, include_str!("suite.rs"), &["coverage"]);
    assert!(
        unbuilt.is_empty(),
        "tests/ files no test target builds: {unbuilt:?}"
    );
}
