//! Bit-rate solver: from a clock frequency and a bit rate, choose the bit timing
//! (BRP, TSEG1, TSEG2, SJW).
//!
//! Rules: the bit must be an exact number of clocks, `(BRP+1) * tq` with
//! 8..=25 time quanta per bit (ISO 11898-1, 11.3.1), TSEG1 1..=16, TSEG2 1..=8,
//! the sample point `(1 + TSEG1) / tq` within 75 %..87.5 % (nearest to 80 %), and
//! `(BRP+1) * TSEG1 >= 3` clocks (the timing contract's minimum for a node to read
//! back its own bit). Among the solutions, the one with the most time quanta per
//! bit (the finest resynchronisation) wins; SJW = min(4, TSEG2).

use drcc_cosim::BitTiming;

/// The largest prescaler value: BRP is 10 bits wide (timing contract §1), so
/// 10 kbit/s is reachable at 100 MHz (BRP 499, 20 tq).
pub const BRP_MAX: u32 = 1023;

/// Lowest and highest sample point accepted, in per mille.
pub const SAMPLE_POINT_RANGE: (u32, u32) = (750, 875);
/// Preferred sample point, per mille.
pub const SAMPLE_POINT_TARGET: u32 = 800;

/// The best segment split of `tq` time quanta, if any meets the rules.
fn split(tq: u32, brp: u32) -> Option<BitTiming> {
    let mut best: Option<(u32, BitTiming)> = None;
    for tseg2 in 1..=8u32 {
        if tseg2 + 2 > tq {
            break;
        }
        let tseg1 = tq - 1 - tseg2;
        if !(1..=16).contains(&tseg1) || (brp + 1) * tseg1 < 3 {
            continue;
        }
        let sp = (1 + tseg1) * 1000 / tq;
        let sp_exact = (1 + tseg1) * 1000;
        if sp_exact < SAMPLE_POINT_RANGE.0 * tq || sp_exact > SAMPLE_POINT_RANGE.1 * tq {
            continue;
        }
        let dist = sp.abs_diff(SAMPLE_POINT_TARGET);
        let t = BitTiming {
            brp: brp as u16,
            tseg1: tseg1 as u8,
            tseg2: tseg2 as u8,
            sjw: tseg2.min(4) as u8,
            triple_sampling: false,
        };
        if best.as_ref().is_none_or(|(d, _)| dist < *d) {
            best = Some((dist, t));
        }
    }
    best.map(|(_, t)| t)
}

/// Chooses a bit timing for `bitrate` bit/s from a `clock_hz` clock.
pub fn solve(clock_hz: u64, bitrate: u64) -> Result<BitTiming, String> {
    if bitrate == 0 {
        return Err("`bitrate` must be at least 1 bit/s".to_string());
    }
    if clock_hz == 0 {
        return Err("`clock_hz` must be at least 1 Hz".to_string());
    }
    if !clock_hz.is_multiple_of(bitrate) {
        return Err(format!(
            "cannot reach {bitrate} bit/s from a {clock_hz} Hz clock: a bit must last a whole \
             number of clocks ({clock_hz} / {bitrate} is not an integer){}",
            suggestion(clock_hz, bitrate)
        ));
    }
    let clocks = clock_hz / bitrate;
    for tq in (8..=25u64).rev() {
        if !clocks.is_multiple_of(tq) {
            continue;
        }
        let brp = clocks / tq - 1;
        if brp > BRP_MAX as u64 {
            continue;
        }
        if let Some(t) = split(tq as u32, brp as u32) {
            return Ok(t);
        }
    }
    Err(format!(
        "cannot reach {bitrate} bit/s from a {clock_hz} Hz clock: {clocks} clocks per bit \
         cannot be split as (brp+1) x tq with brp 0..={BRP_MAX}, 8..=25 tq per bit and a sample \
         point of 75..87.5 %{}; or give [timing] explicitly",
        suggestion(clock_hz, bitrate)
    ))
}

/// "; nearest reachable: X and Y bit/s" (or nothing).
fn suggestion(clock_hz: u64, bitrate: u64) -> String {
    let mut reachable: Vec<u64> = Vec::new();
    for brp in 0..=BRP_MAX as u64 {
        for tq in 8..=25u64 {
            let clocks = (brp + 1) * tq;
            if clock_hz.is_multiple_of(clocks) && split(tq as u32, brp as u32).is_some() {
                reachable.push(clock_hz / clocks);
            }
        }
    }
    let below = reachable.iter().filter(|&&r| r < bitrate).max();
    let above = reachable.iter().filter(|&&r| r > bitrate).min();
    match (below, above) {
        (Some(b), Some(a)) => format!("; nearest reachable rates: {b} and {a} bit/s"),
        (Some(x), None) | (None, Some(x)) => format!("; nearest reachable rate: {x} bit/s"),
        (None, None) => String::new(),
    }
}

/// Sample point of a timing in percent.
pub fn sample_point_percent(t: &BitTiming) -> f64 {
    (1 + t.tseg1 as u32) as f64 * 100.0 / t.tq_per_bit() as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn common_rates() {
        let cases = [
            (8_000_000, 1_000_000, (0, 5, 2)),
            (8_000_000, 500_000, (0, 12, 3)),
            (8_000_000, 125_000, (3, 12, 3)),
            (24_000_000, 1_000_000, (1, 9, 2)),
            (24_000_000, 500_000, (2, 12, 3)),
            (24_000_000, 125_000, (11, 12, 3)),
            // BRP past 6 bits: 10 kbit/s at 100 MHz is 10,000 clocks a bit; 25
            // tq cannot place the sample point in 75..87.5 % with TSEG1 <= 16,
            // 24..21 do not divide 10,000, so 20 tq of 500 clocks (BRP 499),
            // sample point 16/20 = 80 %.
            (100_000_000, 10_000, (499, 15, 4)),
            (8_000_000, 10_000, (39, 15, 4)),
        ];
        for (clk, rate, (brp, t1, t2)) in cases {
            let t = solve(clk, rate).unwrap();
            assert_eq!((t.brp, t.tseg1, t.tseg2), (brp, t1, t2), "{clk} {rate}");
            assert_eq!(clk / rate, t.clocks_per_bit() as u64);
            t.validate().unwrap();
            let sp = sample_point_percent(&t);
            assert!((75.0..=87.5).contains(&sp), "{sp}");
            assert_eq!(t.sjw, t.tseg2.min(4));
        }
    }

    #[test]
    fn impossible_rates_are_explained() {
        let e = solve(8_000_000, 300_000).unwrap_err();
        assert!(e.contains("not an integer"), "{e}");
        assert!(e.contains("nearest reachable"), "{e}");
        let e = solve(8_000_000, 2_000_000).unwrap_err();
        assert!(e.contains("4 clocks per bit"), "{e}");
        assert!(e.contains("1000000"), "{e}");
        assert!(solve(8_000_000, 0).is_err());
        // 100,000 clocks a bit need BRP 4999 at 20 tq: past BRP_MAX
        let e = solve(100_000_000, 1_000).unwrap_err();
        assert!(e.contains("brp 0..=1023"), "{e}");
    }
}
