//! Functional coverage: the model's cover points counted over
//! the test suite's workloads (`drcc_testbench::coverage`, the same collection as
//! `drcc coverage`). Every bin defined from the standard, the papers and the
//! contracts is hit, and no name is counted that is not a bin (an illegal FSM
//! transition, an error ISO 11898-1 does not allow where it was seen, or a cover
//! point without a definition).

use drcc_testbench::coverage;

#[test]
fn every_bin_is_hit_and_nothing_unlisted_is_counted() {
    let r = coverage::collect(|w| eprintln!("coverage: {w}")).unwrap_or_else(|e| panic!("{e}"));
    println!("{}", r.table());
    assert!(r.bins.len() >= 120, "{} bins", r.bins.len());
    let unlisted = r.unlisted();
    assert!(unlisted.is_empty(), "counted but not bins: {unlisted:?}");
    let missed: Vec<&str> = r.missed().iter().map(|b| b.name.as_str()).collect();
    assert!(missed.is_empty(), "bins never hit: {missed:?}");
    assert!(!r.unreachable.is_empty());
}
