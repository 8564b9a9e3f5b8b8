//! Receive synchronizer, prescaler and bit timing logic (timing contract §2 and §3;
//! ISO 11898-1:2015 11.3: nominal bit time, hard synchronization,
//! resynchronization with the synchronization jump width, sample point).
//!
//! This file is the contract's §3 algorithm written out verbatim; the comments
//! name the conformance items (ISO 16845-1) each rule serves.

use crate::engine::BitTiming;

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
    brp_cnt: u8,
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
    pub fn clock(&mut self, rx: bool, brp: u8) -> (bool, bool) {
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
        timing: &BitTiming,
        tx: bool,
        hard_sync_enable: bool,
    ) -> BtlEvent {
        let (t1_cfg, t2_cfg) = (timing.tseg1, timing.tseg2);
        let sjw = timing.sjw.min(timing.tseg2);
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
                        let sampled = if timing.triple_sampling {
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
