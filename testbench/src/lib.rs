//! drcc-testbench: what the product is tested and measured with. The scenario
//! format and its loader, the bit-rate solver, random traffic, the scenario
//! runner (on one engine or co-simulated on two); the fault scenarios of the
//! dual bus, the star, DMR and the ECSS policy; the DRCC paper's experiment, the
//! ISO 16845-1 conformance suite, the fault campaigns and the coverage; the
//! REDCAN ring runs (their hosts run the `cankingdom` and `redcan` crates); the
//! networks `drcc serve` serves (`served`, for the `drcc-serve` server); and the
//! engine benchmark. Scenario files live in `scenarios/`, integration tests in
//! `tests/`.

pub mod bench;
pub mod bitrate;
pub mod campaign;
pub mod conformance;
pub mod coverage;
pub mod delivery;
pub mod dmr;
pub mod drcc_build;
pub mod dual;
pub mod ecss;
pub mod engines;
pub mod fault_gen;
pub mod hub_stim;
pub mod paper;
pub mod random;
pub mod ring;
pub mod run;
pub mod scenario;
pub mod served;
pub mod star;
pub mod tools;

pub use engines::EngineKind;
pub use scenario::{Scenario, ScenarioError};

/// The directory of the bundled scenario files.
pub fn scenarios_dir() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios")
}
