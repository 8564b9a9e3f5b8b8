//! Random traffic on the reference model: for 125 k, 500 k and 1 Mbit/s from 8 MHz
//! and 24 MHz clocks (brp 0 to 11), hundreds of random frames (base/extended,
//! data/remote, DLC 0..=15, random data, two or three nodes starting at the same
//! clock) are each sent once and delivered once to every other node.

use drcc_testbench::random::Traffic;
use drcc_testbench::run::run;
use drcc_testbench::EngineKind;

fn random_on_model(seed: u64, clock_hz: u64, bitrate: u64, frames: usize) {
    let sc = Traffic::new(seed, frames, clock_hz, bitrate)
        .scenario()
        .unwrap();
    let r = run(&sc, EngineKind::Model).unwrap();
    assert!(
        r.passed(),
        "{} ({:?}):\n  {}\nreproduce: save Scenario::to_toml() and run `drcc sim`",
        sc.description,
        sc.timing,
        r.problems
            .iter()
            .take(20)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n  ")
    );
    assert!(r.outcome.is_idle());
    assert_eq!(r.sent.len(), frames);
    assert_eq!(r.deliveries.len(), 2 * frames);
    assert!(
        r.arb_lost > frames / 10,
        "only {} arbitrations lost",
        r.arb_lost
    );
}

#[test]
fn random_8mhz_125k() {
    random_on_model(1, 8_000_000, 125_000, 300);
}

#[test]
fn random_8mhz_500k() {
    random_on_model(2, 8_000_000, 500_000, 300);
}

#[test]
fn random_8mhz_1m() {
    random_on_model(3, 8_000_000, 1_000_000, 500);
}

#[test]
fn random_24mhz_125k() {
    random_on_model(4, 24_000_000, 125_000, 200);
}

#[test]
fn random_24mhz_500k() {
    random_on_model(5, 24_000_000, 500_000, 300);
}

#[test]
fn random_24mhz_1m() {
    random_on_model(6, 24_000_000, 1_000_000, 500);
}
