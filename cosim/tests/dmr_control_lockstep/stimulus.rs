//! The stimulus of the DMR control lock-step: a seeded generator, the small
//! configurations, the traffic keys and the channel's protocol state per line.

use drcc_cosim::model::drcc::dmr::DmrBlock;

/// splitmix64: seeded, deterministic.
pub struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 <= p
    }
    pub fn range(&mut self, lo: u64, hi: u64) -> u64 {
        lo + self.below(hi - lo + 1)
    }
}

/// The configuration (from `DmrRegs` in the DRCC); small, so that every timer runs
/// out many times.
#[derive(Clone, Copy, Debug)]
pub struct Cfg {
    pub timeout: u16,
    pub cs_period: u16,
    pub tick_bits: u16,
    pub recovery_delay: u16,
    pub cs_id: [u32; 2],
}

impl Cfg {
    pub fn random(r: &mut Rng) -> Self {
        let dcl = r.range(0x700, 0x7FF) as u32;
        let mut rcl = r.range(0x700, 0x7FF) as u32;
        if rcl == dcl {
            rcl ^= 1;
        }
        Cfg {
            timeout: r.range(2, 12) as u16,
            cs_period: if r.chance(0.3) {
                0
            } else {
                r.range(1, 12) as u16
            },
            tick_bits: r.range(1, 4) as u16,
            recovery_delay: r.range(1, 10) as u16,
            cs_id: [dcl, rcl],
        }
    }

    /// Into the model's register words (§2.1).
    pub fn apply(&self, m: &mut DmrBlock) {
        m.cfg = self.timeout as u32 | (self.cs_period as u32) << 16;
        m.time = self.tick_bits as u32 | (self.recovery_delay as u32) << 16;
        m.cs = self.cs_id[0] | self.cs_id[1] << 16;
    }
}

/// The frame keys of the traffic in the mailbox test (none is a CS identifier).
pub const POOL: [(bool, u32); 4] = [
    (false, 0x100),
    (false, 0x101),
    (true, 0x0123_4567),
    (false, 0x2A5),
];

/// One attempt of a channel: clocks left and whether it ends in `tx_failed`.
#[derive(Clone, Copy, Debug)]
pub struct Attempt {
    pub left: u32,
    pub fail: bool,
}

/// What makes the random inputs of one line follow the channel's protocol.
#[derive(Clone, Copy, Debug, Default)]
pub struct Chan {
    pub att: Option<Attempt>,
    pub err_state: u8,
    /// Clocks left in the present error state (1 or 2).
    pub err_left: u32,
}
