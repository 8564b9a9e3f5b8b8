//! ISO 16845-1 items 7.7 (receiver) and 8.7 (transmitter): bit timing — sample
//! point, hard synchronisation, resynchronisation with positive and negative phase
//! errors within and beyond SJW, one synchronisation per bit, no synchronisation
//! after a dominant sample or while sending dominant, glitch filtering in idle.
//!
//! All items run with brp 0, so one time quantum is one clock and the tester can
//! put an edge at every tq boundary: the default timing (8 tq, SJW 1) and a 16-tq
//! timing with SJW 3 ([`super::timing_wide`]). Positions are in tq counted from
//! the tester's bit start, which the IUT takes as its SYNC_SEG (the 2-clock
//! synchronizer delay is the same for every edge). The IUT's own bit reaches the
//! bus [`LOOP`] clocks after the tester clock it takes as that bit's SYNC_SEG
//! (contract §2 and §3: the edge reaches the bit timing logic 2 clocks late, `tx`
//! is loaded at the `bit_start` edge that ends the previous bit).
//!
//! The probe used by the receiver items is the first stuff bit of a frame with
//! identifier 7FFh: a dominant stuff bit after five recessive bits. The tester
//! moves its edge (lengthens or shortens the recessive bit before it) and keeps it
//! dominant for exactly `d` tq: the IUT samples dominant iff its sample point
//! falls inside, and a recessive sample is a stuff error whose error flag shows,
//! to the clock, where the IUT's next bit starts.
//!
//! The receiver items are in `as_receiver`, the transmitter items in
//! `as_transmitter`; the clock-level helpers both use are here.

use drcc_cosim::BitTiming;

use super::bits::{Field, FrameBits};
use super::lower_tester::{field, ClockRecord, Iut, LowerTester, Lt, Run, Script};
use super::procedures::{base, interframe_tx, tx_ok, Expected};
use super::{timing, timing_wide};

mod as_receiver;
mod as_transmitter;
pub use as_receiver::*;
pub use as_transmitter::*;

/// Clocks from the tester clock the IUT takes as a bit's SYNC_SEG to the IUT's
/// `tx` of that bit on the bus (brp 0), for a bit that starts at the end of the
/// previous bit's PHASE_SEG2.
pub const LOOP: u64 = 2;

/// The same for a bit whose SYNC_SEG is the time quantum in which the edge was
/// seen (hard synchronisation, or a resynchronisation in PHASE_SEG2 with
/// |e| <= SJW): `tx` changes at the end of that tq (contract §3, `bit_start`).
pub const LOOP_SYNC: u64 = LOOP + 1;

fn cpb(t: &BitTiming) -> u32 {
    t.clocks_per_bit()
}

fn start_traced(iut: &Iut, t: BitTiming) -> LowerTester {
    let mut lt = LowerTester::start(iut, t);
    lt.trace = Some(Vec::new());
    lt
}

/// The IUT's `tx` on the bus at tester clock `clock` (needs the trace).
fn tx_at(lt: &LowerTester, clock: u64) -> bool {
    let t = lt.trace.as_ref().expect("trace");
    let first = t[0].clock;
    t[(clock - first) as usize].tx
}

/// The first clock at or after `from` where the IUT's `tx` is dominant, and how
/// many clocks it stays dominant.
fn dominant_run(lt: &LowerTester, from: u64) -> Option<(u64, u64)> {
    let t: &Vec<ClockRecord> = lt.trace.as_ref().expect("trace");
    let first = t[0].clock;
    let start = t[(from - first) as usize..].iter().find(|c| !c.tx)?.clock;
    let len = t[(start - first) as usize..]
        .iter()
        .take_while(|c| !c.tx)
        .count() as u64;
    Some((start, len))
}

/// Asserts that the IUT's `tx` changes to `value` exactly at `clock`.
#[track_caller]
fn assert_tx_edge(lt: &LowerTester, clock: u64, value: bool, what: &str) {
    assert!(
        tx_at(lt, clock - 1) != value && tx_at(lt, clock) == value,
        "{}: {what}: the IUT's tx should turn {} at clock {clock} (tx at {}..={}: {:?})",
        lt.name(),
        if value { "recessive" } else { "dominant" },
        clock - 3,
        clock + 3,
        (clock - 3..=clock + 3)
            .map(|c| tx_at(lt, c))
            .collect::<Vec<_>>()
    );
}
