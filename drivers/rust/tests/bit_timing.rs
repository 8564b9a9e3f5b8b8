//! Bit-timing calculation of both drivers (Rust `BitTiming::calc`, C
//! `drcc_calc_bit_timing`) against settings worked out by hand with the
//! ISO 11898-1 bit-time arithmetic (11.3.1): one bit = SYNC_SEG (1 tq) + TSEG1
//! (PROP_SEG + PHASE_SEG1) + TSEG2 (PHASE_SEG2) quanta; a quantum is BRP
//! clocks; the sample point is at the end of TSEG1, (1 + TSEG1) / N of the bit
//! for N = 1 + TSEG1 + TSEG2 quanta. The drivers' rules (drcc.h): N in 8..25
//! (ISO's programmable range), TSEG1 1..16 and TSEG2 2..8 (the register fields;
//! PHASE_SEG2 >= the 2 tq information processing time), BRP 1..1024, the bit
//! rate exact, the sample point nearest 87.5 %, SJW = min(4, TSEG2). The BTR
//! words follow docs/registers.md: brp = BRP-1 in [5:0] and [27:24], tseg1-1
//! in [9:6], tseg2-1 in [12:10], sjw-1 in [14:13], ewl in [23:16].

use drcc_driver::{BitTiming, Error};
use drcc_driver_sim::{c_btr_encode, c_calc_bit_timing, CBitTiming};

/// DRCC_E_NO_TIMING of the C driver.
const C_NO_TIMING: i32 = -2;

fn t(brp: u16, tseg1: u8, tseg2: u8, sjw: u8) -> BitTiming {
    BitTiming {
        brp,
        tseg1,
        tseg2,
        sjw,
        triple: false,
    }
}

/// Both drivers give `want` for (clock, rate), and the BTR word `btr` (ewl 96).
fn check(clock: u32, rate: u32, want: BitTiming, btr: u32) {
    let rust = BitTiming::calc(clock, rate).expect("an exact setting exists");
    assert_eq!(rust, want, "Rust driver, {clock} Hz, {rate} bit/s");
    assert_eq!(rust.clocks_per_bit(), clock / rate, "the bit rate is exact");
    assert_eq!(rust.btr(96), Ok(btr), "Rust BTR word");
    let c = c_calc_bit_timing(clock, rate).expect("C: an exact setting exists");
    let want_c = CBitTiming {
        brp: want.brp,
        tseg1: want.tseg1,
        tseg2: want.tseg2,
        sjw: want.sjw,
        triple: 0,
    };
    assert_eq!(c, want_c, "C driver, {clock} Hz, {rate} bit/s");
    assert_eq!(c_btr_encode(&c, 96), btr, "C BTR word");
}

#[test]
fn sixteen_clocks_per_bit_gives_87_5_percent_with_one_clock_quanta() {
    // 16 MHz / 1 Mbit/s = 16 clocks a bit. BRP 1 -> N = 16; BRP 2 -> N = 8 (BRP 4,
    // 8, 16 give N < 8). N = 16: TSEG2 2, TSEG1 13: (1 + 13) / 16 = 87.5 % exactly.
    // N = 8 can reach only (1 + 5) / 8 = 75 % (TSEG2 >= 2). SJW = min(4, 2) = 2.
    // BTR = brp 0 | (13-1) << 6 = 0x300 | (2-1) << 10 = 0x400 | (2-1) << 13 = 0x2000
    //       | 96 << 16 = 0x600000  ->  0x00602700.
    check(16_000_000, 1_000_000, t(1, 13, 2, 2), 0x0060_2700);
}

#[test]
fn readme_rate_500k_from_48_mhz() {
    // 48 MHz / 500 kbit/s = 96 clocks. Divisors giving N in 8..25: BRP 4 (N 24),
    // 6 (N 16), 8 (N 12), 12 (N 8). N 24: TSEG1 <= 16 caps the sample point at
    // 17/24 = 70.8 %; N 16: 14/16 = 87.5 % exactly; N 12: 10/12 = 83.3 %; N 8: 75 %.
    // -> BRP 6, TSEG1 13, TSEG2 2, SJW 2.
    // BTR = (6-1) = 0x5 | 0x300 | 0x400 | 0x2000 | 0x600000 = 0x00602705.
    check(48_000_000, 500_000, t(6, 13, 2, 2), 0x0060_2705);
}

#[test]
fn rate_125k_from_8_mhz() {
    // 8 MHz / 125 kbit/s = 64 clocks: BRP 4 (N 16) or 8 (N 8). N 16 reaches
    // 87.5 % (TSEG1 13, TSEG2 2). BTR = 3 | 0x300 | 0x400 | 0x2000 | 0x600000 = 0x00602703.
    check(8_000_000, 125_000, t(4, 13, 2, 2), 0x0060_2703);
}

#[test]
fn prescaler_above_63_uses_brp_ext() {
    // 100 MHz / 10 kbit/s = 10000 clocks = 2^4 * 5^4. N in 8..25 dividing it
    // with BRP = 10000 / N <= 1024: N 10 (BRP 1000), 16 (625), 20 (500), 25 (400);
    // only N = 16 reaches 87.5 % exactly (TSEG1 13, TSEG2 2).
    // BRP - 1 = 624 = 9 * 64 + 48: brp = 48 = 0x30, brp_ext = 9 -> 0x09000000.
    // BTR = 0x09000000 | 0x30 | 0x300 | 0x400 | 0x2000 | 0x600000 = 0x09602730.
    check(100_000_000, 10_000, t(625, 13, 2, 2), 0x0960_2730);
}

#[test]
fn eight_quanta_cannot_reach_87_5_percent() {
    // 1 MHz / 125 kbit/s = 8 clocks: only BRP 1, N 8. TSEG2 >= 2 leaves TSEG1 <= 5:
    // (1 + 5) / 8 = 75 %. TSEG1 = 5 clocks >= 3. SJW = 2.
    // BTR = 0 | (5-1) << 6 = 0x100 | 0x400 | 0x2000 | 0x600000 = 0x00602500.
    check(1_000_000, 125_000, t(1, 5, 2, 2), 0x0060_2500);
}

#[test]
fn tseg1_limit_moves_the_sample_point_earlier() {
    // 20 MHz / 1 Mbit/s = 20 clocks: BRP 1 (N 20) or 2 (N 10). N 20: 87.5 % would
    // be 17.5 tq; TSEG1 <= 16 gives 1 + 16 = 17 tq (TSEG2 3): 85 %, error
    // |8*17 - 7*20| / (8*20) = 4/160. N 10: TSEG2 >= 2 gives 8 tq: 80 %, error
    // |8*8 - 7*10| / 80 = 6/80 = 12/160. -> BRP 1, TSEG1 16, TSEG2 3, SJW 3.
    // BTR = (16-1) << 6 = 0x3C0 | (3-1) << 10 = 0x800 | (3-1) << 13 = 0x4000
    //       | 0x600000 = 0x00604BC0.
    check(20_000_000, 1_000_000, t(1, 16, 3, 3), 0x0060_4BC0);
}

#[test]
fn impossible_rates_are_errors() {
    for (clock, rate, why) in [
        (
            16_000_000,
            3_000_000,
            "16 MHz / 3 Mbit/s is 5.33 clocks: not a whole number",
        ),
        (
            7_000_000,
            1_000_000,
            "7 clocks a bit: N = 7 < 8 with BRP 1, N = 1 with BRP 7",
        ),
        (
            29_000_000,
            1_000_000,
            "29 clocks, a prime above 25: N = 29 or 1",
        ),
        (
            200_000_000,
            5_000,
            "40000 clocks need N >= 40000 / 1024 = 39.1 > 25",
        ),
        (16_000_000, 0, "bit rate 0"),
    ] {
        assert_eq!(
            BitTiming::calc(clock, rate),
            Err(Error::NoTiming),
            "Rust: {why}"
        );
        assert_eq!(c_calc_bit_timing(clock, rate), Err(C_NO_TIMING), "C: {why}");
    }
}

#[test]
fn btr_of_the_reset_timing_is_the_reset_value() {
    // docs/registers.md: BTR resets to 0x00600500 = brp 0, tseg1 4, tseg2 1, sjw 0,
    // ewl 96, i.e. BRP 1, TSEG1 5, TSEG2 2, SJW 1 in real units.
    assert_eq!(BitTiming::RESET.btr(96), Ok(0x0060_0500));
    assert_eq!(BitTiming::RESET.btr(96), Ok(drcc_driver::regs::BTR_RESET));
    let out_of_range = t(1, 17, 2, 1);
    assert_eq!(
        out_of_range.btr(96),
        Err(Error::Invalid),
        "TSEG1 17 does not fit 4 bits"
    );
}
