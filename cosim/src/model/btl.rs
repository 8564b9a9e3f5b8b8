//! Receive synchronizer, prescaler and bit timing logic (timing contract §2 and §3;
//! ISO 11898-1:2015 11.3: nominal bit time, hard synchronization,
//! resynchronization with the synchronization jump width, sample point).
//!
//! This file is the contract's §3 algorithm written out verbatim; the comments
//! name the conformance items (ISO 16845-1) each rule serves. The configuration it
//! runs with is the one captured in reset mode, clamped as contract §6 says
//! ([`Timing::capture`]).

use crate::engine::BitTiming;

/// Bit timing as captured in reset mode, with every value clamped to what the
/// ports can carry and to ISO 11898-1 (contract §6).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Timing {
    /// Prescaler: a time quantum lasts `brp + 1` clocks (0..=1023).
    pub brp: u16,
    /// `T1'`: TSEG1 lengthened to at least `7 - T2` tq and 3 clocks.
    pub t1: u8,
    /// `T2`: TSEG2 (1..=8).
    pub t2: u8,
    /// `SJW' = min(SJW, T2)`.
    pub sjw: u8,
    /// Majority of three samples.
    pub triple: bool,
}

impl Default for Timing {
    fn default() -> Self {
        Timing::capture(&BitTiming::default())
    }
}

impl Timing {
    /// The configuration registers loaded at a reset edge (contract §6). Fields
    /// first take the range of their port (`brp` 10 bits, `tseg1 - 1` 4 bits,
    /// `tseg2 - 1` 3 bits, `sjw - 1` 2 bits; out-of-range struct values saturate),
    /// then the ISO 11898-1 clamps: `SJW' = min(SJW, T2)`,
    /// `T1' = max(T1, 7 - T2, M)` with `M` = 3 for BRP 0, 2 for BRP 1, else 1, so a
    /// bit has at least 8 tq and TSEG1 lasts at least 3 clocks.
    pub fn capture(t: &BitTiming) -> Self {
        let brp = t.brp.min(1023);
        let t1 = t.tseg1.clamp(1, 16);
        let t2 = t.tseg2.clamp(1, 8);
        let sjw = t.sjw.clamp(1, 4).min(t2);
        let m = match brp {
            0 => 3,
            1 => 2,
            _ => 1,
        };
        Timing {
            brp,
            t1: t1.max(7u8.saturating_sub(t2)).max(m),
            t2,
            sjw,
            triple: t.triple_sampling,
        }
    }

    /// Time quanta per bit with the clamped values.
    pub fn tq_per_bit(&self) -> u32 {
        1 + self.t1 as u32 + self.t2 as u32
    }

    /// Clocks per bit with the clamped values.
    pub fn clocks_per_bit(&self) -> u32 {
        self.tq_per_bit() * (self.brp as u32 + 1)
    }
}

/// Segment of the bit the current time quantum belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Seg {
    Sync,
    Tseg1,
    Tseg2,
}

/// What the bit timing logic did at one clock edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BtlEvent {
    /// Nothing for the bit stream processor.
    None,
    /// Sample point with the sampled bus value (`true` = recessive).
    Sample(bool),
    /// A new bit begins on `tx`; `hard` tells whether a hard synchronization caused it.
    BitStart { hard: bool },
}

/// State of the synchronizer, the prescaler and the bit timing logic.
#[derive(Clone, Debug)]
pub struct Btl {
    rx_meta: bool,
    rx_s: bool,
    brp_cnt: u16,
    seg: Seg,
    q: u8,
    t1: u8,
    t2: u8,
    rx_prev: bool,
    rx_prev2: bool,
    last_sample: bool,
    synced: bool,
}

impl Default for Btl {
    fn default() -> Self {
        Self::new()
    }
}

impl Btl {
    /// Reset state (contract §2, §3).
    pub fn new() -> Self {
        Btl {
            rx_meta: true,
            rx_s: true,
            brp_cnt: 0,
            seg: Seg::Sync,
            q: 0,
            t1: 0,
            t2: 0,
            rx_prev: true,
            rx_prev2: true,
            last_sample: true,
            synced: false,
        }
    }

    /// Value taken at the last sample point (`sampled_bit` probe).
    #[inline]
    pub fn last_sample(&self) -> bool {
        self.last_sample
    }

    /// One clock edge of the synchronizer and the prescaler. Returns `rx_s` as it
    /// was *before* the edge (the value the bit timing logic uses) and `tick`.
    #[inline]
    pub fn clock(&mut self, rx: bool, brp: u16) -> (bool, bool) {
        let rx_s = self.rx_s;
        self.rx_s = self.rx_meta;
        self.rx_meta = rx;
        let tick = self.brp_cnt >= brp;
        self.brp_cnt = if tick { 0 } else { self.brp_cnt + 1 };
        (rx_s, tick)
    }

    /// The bit timing logic at a tick (the current time quantum ends).
    ///
    /// `rx_s` is the synchronized bus value before the edge, `tx` the channel's own
    /// `tx` register before the edge, `hard_sync_enable` the BSP's permission for a
    /// hard synchronization (contract §4.1).
    #[inline]
    pub fn tick(
        &mut self,
        rx_s: bool,
        timing: &Timing,
        tx: bool,
        hard_sync_enable: bool,
    ) -> BtlEvent {
        let (t1_cfg, t2_cfg, sjw) = (timing.t1, timing.t2, timing.sjw);
        // Only recessive-to-dominant edges synchronize (ISO 11898-1 11.3.2).
        let edge = self.rx_prev && !rx_s;
        // 7.7.10: no synchronization when the bus equals the previous sample;
        // 7.7.7: only one synchronization between two sample points.
        let sync_ok = edge && self.last_sample && !self.synced;
        let hard = sync_ok && hard_sync_enable;
        // 8.7.7: no resynchronization while the node itself sends dominant.
        let resync = sync_ok && !hard && tx;
        let mut event = BtlEvent::None;

        if hard {
            // Hard synchronization: this tq becomes SYNC_SEG of a new bit.
            self.seg = Seg::Tseg1;
            self.q = 0;
            self.t1 = t1_cfg;
            self.t2 = t2_cfg;
            self.synced = true;
            event = BtlEvent::BitStart { hard: true };
        } else {
            match self.seg {
                Seg::Sync => {
                    // Edge inside SYNC_SEG: phase error 0.
                    self.seg = Seg::Tseg1;
                    self.q = 0;
                    self.t1 = t1_cfg;
                    self.t2 = t2_cfg;
                    if resync {
                        self.synced = true;
                    }
                }
                Seg::Tseg1 => {
                    // Positive phase error e = q + 1: lengthen TSEG1 by min(e, SJW').
                    if resync {
                        self.t1 = self.t1.wrapping_add((self.q + 1).min(sjw));
                        self.synced = true;
                    }
                    if self.q + 1 >= self.t1 {
                        let sampled = if timing.triple {
                            majority(self.rx_prev2, self.rx_prev, rx_s)
                        } else {
                            rx_s
                        };
                        self.last_sample = sampled;
                        self.synced = false;
                        self.seg = Seg::Tseg2;
                        self.q = 0;
                        event = BtlEvent::Sample(sampled);
                    } else {
                        self.q += 1;
                    }
                }
                Seg::Tseg2 => {
                    // Negative phase error |e| = t2 - q.
                    if resync && self.t2.saturating_sub(self.q) <= sjw {
                        // |e| <= SJW': this tq becomes SYNC_SEG of the next bit.
                        self.seg = Seg::Tseg1;
                        self.q = 0;
                        self.t1 = t1_cfg;
                        self.t2 = t2_cfg;
                        self.synced = true;
                        event = BtlEvent::BitStart { hard: false };
                    } else {
                        if resync {
                            // |e| > SJW': shorten TSEG2 by SJW'.
                            self.t2 -= sjw;
                            self.synced = true;
                        }
                        if self.q + 1 >= self.t2 {
                            self.seg = Seg::Sync;
                            self.q = 0;
                            event = BtlEvent::BitStart { hard: false };
                        } else {
                            self.q += 1;
                        }
                    }
                }
            }
        }
        self.rx_prev2 = self.rx_prev;
        self.rx_prev = rx_s;
        event
    }
}

/// Majority of three samples (triple sampling).
#[inline]
fn majority(a: bool, b: bool, c: bool) -> bool {
    if a {
        b || c
    } else {
        b && c
    }
}
