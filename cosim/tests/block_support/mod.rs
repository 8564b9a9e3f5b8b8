//! Shared by the block-level lock-step tests (`dmr_engine_lockstep.rs`,
//! `dmr_rx_lockstep.rs`: a rust-hdl block against its part of the reference model
//! on the same seeded stimulus): the generator, and the settling of a block between
//! clock edges.
#![allow(dead_code)]

use rust_hdl::prelude::*;

/// Settling budget per half clock.
const MAX_SETTLE_ITERS: usize = 400;

/// xorshift64*: deterministic, seeded.
pub struct Rng(u64);

impl Rng {
    /// A generator for `seed` (spread, never the stuck state 0).
    pub fn new(seed: u64) -> Self {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in `0..n`, from the high bits.
    pub fn below(&mut self, n: u64) -> u64 {
        (self.next() >> 11) % n
    }
    /// True with probability 1/n.
    pub fn one_in(&mut self, n: u64) -> bool {
        self.below(n) == 0
    }
    /// True with probability num/den.
    pub fn chance(&mut self, num: u64, den: u64) -> bool {
        self.below(den) < num
    }
}

/// Lets `uut` settle after its inputs or its clock changed.
pub fn settle<B: Block>(uut: &mut B, what: &str) {
    drcc_cosim::engine::rusthdl::settle(uut, MAX_SETTLE_ITERS, what);
}
