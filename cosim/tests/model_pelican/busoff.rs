//! §8 bus-off in `single_a` with `pelican_busoff` "sja1000" and "auto".

use crate::harness::*;
use drcc_cosim::Frame;

/// Drive the DUT to bus-off: line A's receive is cut (the DUT hears only
/// recessive), so every dominant bit it sends is a bit error and TEC climbs by
/// 8 per attempt to 256 (no ACK-error exception applies to bit errors).
fn to_busoff(n: &mut Net) {
    n.linux_start(0xFF, 0x00);
    n.load_tx(&Frame::base(0x555, &[0xFF, 0x00]));
    n.cut[0] = true;
    n.w(1, 0x01);
    n.until(3000 * BIT, |n| n.dut.read(2) & 0x80 != 0);
}

/// P-BO-1, P-BO-2, P-ERR-1, P-BO-4: RM set, EI, TXERR counts down, the
/// restart by clearing RM takes 128 x 11 recessive bits.
#[test]
fn busoff_sja1000_hold_and_restart() {
    let mut n = Net::keyed(single_a(4, true));
    to_busoff(&mut n);
    n.idle(2);
    assert_eq!(n.r(0) & 1, 1, "P-BO-1: RM set by bus-off");
    let sr = n.r(2);
    assert_eq!(sr & 0x84, 0x84, "BS and TBS (message dropped)");
    assert_eq!(sr & 0x08, 0, "P-BO-1: TCS stays 0");
    assert_eq!(n.r(3) & 0x04, 0x04, "P-BO-2: EI");
    assert_eq!(n.r(15), 127, "P-ERR-1: TXERR = 127 while held");
    n.cut[0] = false;
    n.idle(200 * BIT);
    assert_eq!(n.r(15), 127, "P-BO-3: the hold does not count runs");
    n.w(0, 0x00);
    let t0 = n.clock;
    n.idle(20 * 11 * BIT);
    let tx = n.r(15);
    assert!(
        (105..=108).contains(&tx),
        "P-ERR-1: TXERR = 127 - runs, got {tx}"
    );
    n.until(200 * 11 * BIT, |n| n.dut.read(2) & 0x80 == 0);
    let bits = (n.clock - t0) / BIT;
    // The hold stops the count of runs; a run already begun may complete in
    // the hold's last bits (the contract says the count holds, not the run).
    assert!(bits >= 127 * 11, "P-BO-5: full recovery, took {bits} bits");
    assert!(
        bits < 128 * 11 + 20,
        "recovery ends after 128 runs, took {bits}"
    );
    n.idle(3);
    assert_eq!(n.r(3) & 0x04, 0x04, "P-IR-5: EI at the end of bus-off");
    assert_eq!(n.r(15), 0);
}

/// P-BO-7: "auto" keeps RM 0 and recovers by itself, EI at both ends.
#[test]
fn busoff_auto_recovers() {
    let mut n = Net::keyed(single_a(4, false));
    to_busoff(&mut n);
    n.idle(2);
    assert_eq!(n.r(0) & 1, 0, "P-BO-7: RM not set");
    assert_eq!(n.r(3) & 0x04, 0x04, "EI at bus-off");
    n.cut[0] = false;
    n.until(200 * 11 * BIT, |n| n.dut.read(2) & 0x80 == 0);
    n.idle(3);
    assert_eq!(n.r(3) & 0x04, 0x04, "EI at recovery");
}

/// P-ERR-2 / P-BO-5: TXERR writes while held are ignored with XIR.ign.
#[test]
fn busoff_txerr_write_ignored() {
    let mut n = Net::keyed(single_a(4, true));
    to_busoff(&mut n);
    n.idle(2);
    n.w(15, 0);
    assert_eq!(n.r(15), 127);
    assert_eq!(n.r(120) & 0x80, 0x80, "XIR.ign");
}
