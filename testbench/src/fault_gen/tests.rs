//! The fault planner's plans: deterministic, inside their window, and of every
//! kind.

use super::*;
use crate::random::Traffic;

#[test]
fn plans_are_deterministic_and_inside_the_window() {
    let sc = Traffic::new(7, 60, 8_000_000, 1_000_000)
        .scenario()
        .unwrap();
    let cpb = sc.clocks_per_bit();
    let mut params = FaultParams::new(9, 30 * cpb, 3000 * cpb);
    params.forced = vec![(0.5, FaultEvent::BusOff)];
    let a = plan(&sc, &params).unwrap();
    let b = plan(&sc, &params).unwrap();
    assert_eq!(a.faults, b.faults);
    assert!(a.faults.len() > 20, "{}", a.faults.len());
    assert!(a.faults.iter().all(|f| f.start >= 30 * cpb && f.cycles > 0));
    assert!(a.faults.windows(2).all(|w| w[0].start <= w[1].start));
    assert_eq!(a.end, a.faults.iter().map(|f| f.end()).max().unwrap());
    assert!(a.count(FaultEvent::BusOff) >= 1);
    assert!(a.planner_bus_offs >= 1, "{}", a.summary());
}
