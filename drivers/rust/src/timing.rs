//! Bit timing: the search for an exact setting from the module clock and the
//! bit rate (sample point near 87.5 %), and the `BTR` word it encodes to.

use crate::regs::{self, put};
use crate::Error;

/// One bit timing in real units (the register holds minus-one codes).
///
/// One bit is `brp x (1 + tseg1 + tseg2)` clocks; the sample point is at the
/// end of `tseg1` (ISO 11898-1 11.3: SYNC_SEG, PROP_SEG + PHASE_SEG1, PHASE_SEG2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BitTiming {
    /// Prescaler: one time quantum is `brp` clocks, 1..=1024.
    pub brp: u16,
    /// PROP_SEG + PHASE_SEG1 in time quanta, 1..=16.
    pub tseg1: u8,
    /// PHASE_SEG2 in time quanta, 1..=8.
    pub tseg2: u8,
    /// Resynchronisation jump width in time quanta, 1..=4.
    pub sjw: u8,
    /// Three samples per bit.
    pub triple: bool,
}

const BRP_MAX: u32 = 1024;
const TQ_MIN: u32 = 8;
const TQ_MAX: u32 = 25;
const TSEG1_MAX: u32 = 16;
const TSEG2_MIN: u32 = 2;
const TSEG2_MAX: u32 = 8;
const SJW_MAX: u32 = 4;

impl BitTiming {
    /// The timing the `BTR` reset value encodes (1 Mbit/s at 8 MHz: 8 quanta
    /// of one clock, sample point 75 %).
    pub const RESET: BitTiming = BitTiming {
        brp: 1,
        tseg1: 5,
        tseg2: 2,
        sjw: 1,
        triple: false,
    };

    /// A timing that gives exactly `bitrate` from `clock_hz`: 8..=25 quanta per
    /// bit, TSEG2 2..=8 (ISO 11898-1's information processing time), TSEG1
    /// 1..=16 and at least 3 clocks, the sample point as near 87.5 % as possible
    /// (ties: the smaller prescaler), SJW = min(4, TSEG2). The same search as
    /// the C driver's `drcc_calc_bit_timing`. [`Error::NoTiming`] if none.
    pub fn calc(clock_hz: u32, bitrate: u32) -> Result<BitTiming, Error> {
        if bitrate == 0 || clock_hz == 0 || !clock_hz.is_multiple_of(bitrate) {
            return Err(Error::NoTiming);
        }
        let clocks = clock_hz / bitrate;
        // Best so far: sample-point error |8 (1 + tseg1) - 7 n| / (8 n), as (err, n).
        let mut best: Option<(u32, u32, BitTiming)> = None;
        for p in 1..=BRP_MAX.min(clocks) {
            if !clocks.is_multiple_of(p) {
                continue;
            }
            let n = clocks / p;
            if !(TQ_MIN..=TQ_MAX).contains(&n) {
                continue;
            }
            for t2 in TSEG2_MIN..=TSEG2_MAX {
                if n < t2 + 2 {
                    break;
                }
                let t1 = n - 1 - t2;
                if t1 > TSEG1_MAX || t1 * p < 3 {
                    continue;
                }
                let err = (8 * (1 + t1)).abs_diff(7 * n);
                let better = match best {
                    None => true,
                    Some((best_err, best_n, _)) => err * best_n < best_err * n,
                };
                if better {
                    let timing = BitTiming {
                        brp: p as u16,
                        tseg1: t1 as u8,
                        tseg2: t2 as u8,
                        sjw: t2.min(SJW_MAX) as u8,
                        triple: false,
                    };
                    best = Some((err, n, timing));
                }
            }
        }
        best.map(|(_, _, t)| t).ok_or(Error::NoTiming)
    }

    /// Whether every field is inside the register's range.
    pub fn is_valid(&self) -> bool {
        (1..=BRP_MAX).contains(&u32::from(self.brp))
            && (1..=TSEG1_MAX as u8).contains(&self.tseg1)
            && (1..=TSEG2_MAX as u8).contains(&self.tseg2)
            && (1..=SJW_MAX as u8).contains(&self.sjw)
    }

    /// Time quanta per bit.
    pub fn quanta(&self) -> u32 {
        1 + u32::from(self.tseg1) + u32::from(self.tseg2)
    }

    /// Clocks per bit.
    pub fn clocks_per_bit(&self) -> u32 {
        u32::from(self.brp) * self.quanta()
    }

    /// The `BTR` word with the error warning limit `ewl`; [`Error::Invalid`]
    /// if a field is out of range.
    pub fn btr(&self, ewl: u8) -> Result<u32, Error> {
        if !self.is_valid() {
            return Err(Error::Invalid);
        }
        let brp = u32::from(self.brp) - 1;
        Ok(put(regs::BTR_BRP_MASK, regs::BTR_BRP_SHIFT, brp & 0x3F)
            | put(regs::BTR_BRP_EXT_MASK, regs::BTR_BRP_EXT_SHIFT, brp >> 6)
            | put(
                regs::BTR_TSEG1_MASK,
                regs::BTR_TSEG1_SHIFT,
                u32::from(self.tseg1) - 1,
            )
            | put(
                regs::BTR_TSEG2_MASK,
                regs::BTR_TSEG2_SHIFT,
                u32::from(self.tseg2) - 1,
            )
            | put(
                regs::BTR_SJW_MASK,
                regs::BTR_SJW_SHIFT,
                u32::from(self.sjw) - 1,
            )
            | put(
                regs::BTR_TRIPLE_MASK,
                regs::BTR_TRIPLE_SHIFT,
                u32::from(self.triple),
            )
            | put(regs::BTR_EWL_MASK, regs::BTR_EWL_SHIFT, u32::from(ewl)))
    }
}
