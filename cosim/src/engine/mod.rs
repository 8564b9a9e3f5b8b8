//! One `ChannelEngine` trait, three engines: the reference model (the oracle),
//! rust-hdl's own simulator, and the Verilated RTL (the sign-off).
//!
//! Contract of [`ChannelEngine::step`]: apply `inputs` (they are stable for the
//! whole clock period), produce one rising edge of `clk`, and return the outputs
//! as they are right after that edge. A bus built from engines feeds each node's
//! `rx` in cycle n with the wired-AND of every node's `tx` returned by step n-1.
//! See `crate::model` for the clock-level timing contract.

pub mod drcc;
pub mod drcc_model;
pub mod drcc_rusthdl;
pub mod drcc_verilator;
pub mod hub;
pub mod hub_model;
// Left out of the crate's unit-test build, which no unit test of it needs: its
// table of hub shapes is most of the crate's compile time, and `cargo test`
// would compile it a second time (its lock step is `tests/hub_lockstep.rs`).
#[cfg(not(test))]
pub mod hub_rusthdl;
pub mod hub_verilator;
pub mod model;
pub mod pelican;
pub mod rcm;
pub mod rusthdl;
pub mod verilator;

use crate::frame::Frame;

/// Minimum length of TSEG1 in clocks, `(brp+1) * tseg1`: a node must read back its
/// own bit through the 2-clock receive synchronizer before the sample point
/// (timing contract §6, §10).
pub const MIN_TSEG1_CLOCKS: u32 = 3;

/// Bit-timing configuration, in time quanta (ISO 11898-1, 11.3.1).
///
/// The RTL ports carry `value - 1` for tseg1/tseg2/sjw (see `drcc_hdl::channel::btl`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BitTiming {
    /// Baud-rate prescaler: one time quantum lasts `brp + 1` clocks (0..=1023).
    pub brp: u16,
    /// TSEG1 = PROP_SEG + PHASE_SEG1 in tq (1..=16).
    pub tseg1: u8,
    /// TSEG2 = PHASE_SEG2 in tq (1..=8).
    pub tseg2: u8,
    /// Synchronisation jump width in tq (1..=4).
    pub sjw: u8,
    /// Majority of three samples at the sample point.
    pub triple_sampling: bool,
}

impl Default for BitTiming {
    fn default() -> Self {
        // 8 MHz clock, 1 Mbit/s: 8 tq of one clock, sample point at 75 %.
        BitTiming {
            brp: 0,
            tseg1: 5,
            tseg2: 2,
            sjw: 1,
            triple_sampling: false,
        }
    }
}

impl BitTiming {
    /// Time quanta per bit.
    pub fn tq_per_bit(&self) -> u32 {
        1 + self.tseg1 as u32 + self.tseg2 as u32
    }
    /// Clocks per bit.
    pub fn clocks_per_bit(&self) -> u32 {
        self.tq_per_bit() * (self.brp as u32 + 1)
    }
    /// Checks every field against its legal range, the 8..=25 tq of a bit and the
    /// minimum TSEG1 of [`MIN_TSEG1_CLOCKS`] clocks; the error names the field.
    pub fn validate(&self) -> Result<(), String> {
        let check = |name: &str, v: u8, lo: u8, hi: u8| {
            if v < lo || v > hi {
                Err(format!(
                    "bit timing field `{name}` = {v} is out of range: legal values are {lo}..={hi}"
                ))
            } else {
                Ok(())
            }
        };
        if self.brp > 1023 {
            return Err(format!(
                "bit timing field `brp` = {} is out of range: legal values are 0..=1023",
                self.brp
            ));
        }
        check("tseg1", self.tseg1, 1, 16)?;
        check("tseg2", self.tseg2, 1, 8)?;
        check("sjw", self.sjw, 1, 4)?;
        if self.sjw > self.tseg2 {
            return Err(format!(
                "bit timing field `sjw` = {} exceeds `tseg2` = {}: SJW must not exceed PHASE_SEG2",
                self.sjw, self.tseg2
            ));
        }
        if self.tq_per_bit() < 8 {
            return Err(format!(
                "bit timing has {} tq per bit: ISO 11898-1 needs 8..=25 (raise tseg1/tseg2)",
                self.tq_per_bit()
            ));
        }
        let clocks = (self.brp as u32 + 1) * self.tseg1 as u32;
        if clocks < MIN_TSEG1_CLOCKS {
            return Err(format!(
                "bit timing field `tseg1` = {} is too short: (brp+1) x tseg1 = {clocks} \
                 clock(s), but a node needs at least {MIN_TSEG1_CLOCKS} to read back its own \
                 bit through the 2-clock synchronizer: the legal minimum at brp = {} is \
                 tseg1 = {}",
                self.tseg1,
                self.brp,
                self.min_tseg1()
            ));
        }
        Ok(())
    }
    /// The smallest TSEG1 (tq) that lasts [`MIN_TSEG1_CLOCKS`] clocks at this BRP.
    pub fn min_tseg1(&self) -> u8 {
        MIN_TSEG1_CLOCKS.div_ceil(self.brp as u32 + 1).max(1) as u8
    }
}

/// Operating mode (timing contract §7).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Mode {
    /// ISO 11898-1 operation.
    #[default]
    Normal = 0,
    /// Bus monitoring: completely passive (CanKingdom "Silent").
    ListenOnly = 1,
    /// A recessive ACK slot is accepted (no receiver needed).
    SelfTest = 2,
    /// Internal loop-back: hears only itself, `tx` pin recessive.
    Loopback = 3,
}

impl Mode {
    /// The `cfg_mode` encoding.
    pub fn code(self) -> u8 {
        self as u8
    }
    /// Decode a `cfg_mode` value (two bits).
    pub fn from_code(code: u8) -> Mode {
        match code & 3 {
            0 => Mode::Normal,
            1 => Mode::ListenOnly,
            2 => Mode::SelfTest,
            _ => Mode::Loopback,
        }
    }
}

/// Controller configuration beyond bit timing (captured in reset mode, §6).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ControllerConfig {
    /// Operating mode.
    pub mode: Mode,
    /// Error warning limit (ISO 11898-1 default 96).
    pub ewl: u8,
    /// No automatic retransmission.
    pub single_shot: bool,
}

impl Default for ControllerConfig {
    fn default() -> Self {
        ControllerConfig {
            mode: Mode::Normal,
            ewl: 96,
            single_shot: false,
        }
    }
}

/// Everything a channel samples at one clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChannelInputs {
    /// Synchronous active-high reset.
    pub rst: bool,
    /// The CAN bus as seen by this node's receiver (`true` = recessive).
    pub rx: bool,
    /// Shared bit-timing configuration (captured while `rst`).
    pub timing: BitTiming,
    /// Mode, warning limit, single shot (captured while `rst`).
    pub config: ControllerConfig,
    /// One-clock request: latch `tx_frame` and transmit it.
    pub tx_req: bool,
    /// Frame to transmit; sampled when `tx_req` is high.
    pub tx_frame: Frame,
    /// One-clock request: abort the pending frame (§8).
    pub tx_abort: bool,
    /// Latched with `tx_req`: that frame is single shot (§8).
    pub tx_single: bool,
    /// Error counter reset: TEC = REC = 0, error active, unless bus-off (§4.5).
    pub err_reset: bool,
    /// Bus-off hold: a bus-off node does not count its recovery (§4.5).
    pub boff_hold: bool,
}

/// Named internal signals compared clock by clock in co-simulation.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Probes {
    /// One-clock pulse at the sample point of every bit.
    pub sample_point: bool,
    /// Bus value taken at the last sample point.
    pub sampled_bit: bool,
    /// The frame field the next bit belongs to (encoding in `crate::model::field`).
    pub field: u8,
    /// Transmit error counter (0..=256+).
    pub tec: u16,
    /// Receive error counter.
    pub rec: u8,
    /// 0 error active, 1 error passive, 2 bus-off.
    pub err_state: u8,
    /// The node is transmitter (§4.5, "Roles").
    pub is_tx: bool,
    /// Completed runs of 11 recessive bits in the current bus-off, 0 outside
    /// it (§4.5).
    pub boff_runs: u8,
}

/// Host-visible diagnostics (timing contract §9).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Diagnostics {
    /// TEC or REC at or above the error warning limit.
    pub err_warning: bool,
    /// One-clock pulse: an error was detected and captured.
    pub err_valid: bool,
    /// Kind of the last error: 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK.
    pub err_kind: u8,
    /// Field code at the last error.
    pub err_field: u8,
    /// The node was transmitter at the last error.
    pub err_tx: bool,
    /// Arbitration-lost bit position (0..=31).
    pub alc: u8,
    /// Errors by kind, saturating at 255: bit, stuff, CRC, form, ACK.
    pub cnt_bit: u8,
    pub cnt_stuff: u8,
    pub cnt_crc: u8,
    pub cnt_form: u8,
    pub cnt_ack: u8,
}

/// Everything a channel drives, right after a clock edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChannelOutputs {
    /// The CAN transmit pin (`true` = recessive).
    pub tx: bool,
    /// A frame is latched and not yet sent.
    pub tx_pending: bool,
    /// One-clock pulse: the pending frame was sent successfully (end of EOF).
    pub tx_done: bool,
    /// One-clock pulse: arbitration was lost (the frame stays pending and is retried).
    pub arb_lost: bool,
    /// One-clock pulse: the pending frame was dropped (single shot, abort, or a
    /// request refused in listen-only mode).
    pub tx_failed: bool,
    /// One-clock pulse: `rx_frame` holds a newly received valid frame.
    pub rx_valid: bool,
    /// Last received frame; changes only together with `rx_valid`.
    pub rx_frame: Frame,
    /// Probe signals.
    pub probes: Probes,
    /// Diagnostics registers.
    pub diag: Diagnostics,
}

/// One CAN channel, simulated clock by clock.
pub trait ChannelEngine {
    /// Engine name as the CLI spells it (`model`, `rust-hdl`, `verilator`).
    fn name(&self) -> &'static str;
    /// Apply inputs, clock once, return the outputs after the edge.
    fn step(&mut self, inputs: &ChannelInputs) -> ChannelOutputs;

    /// One clock of a quiet stretch of [`System::run_for`](crate::system::System::run_for),
    /// in which the host raises nothing: the contract of [`ChannelEngine::step`],
    /// with `rst`, `tx_req`, `tx_abort` and `err_reset` low in `inputs`, and, between
    /// two calls with no `step` in between, only `inputs.rx` changing.
    ///
    /// Writes `tx`, `tx_pending` and the pulses (`tx_done`, `arb_lost`, `tx_failed`,
    /// `rx_valid`) of the outputs into `out`, and all of them in a clock where a pulse
    /// is set; the other fields may keep older values until
    /// [`ChannelEngine::complete_outputs`]. Returns whether a pulse is set or
    /// `tx_pending` changed (the host has something to do). The default steps and
    /// writes everything.
    fn step_quiet(&mut self, inputs: &ChannelInputs, out: &mut ChannelOutputs) -> bool {
        let pending = out.tx_pending;
        *out = self.step(inputs);
        out.rx_valid || out.tx_done || out.arb_lost || out.tx_failed || out.tx_pending != pending
    }

    /// Whether [`ChannelEngine::step_quiet`] does less than `step` (a system uses
    /// quiet stretches only when all its engines do). The default: no.
    fn gains_from_quiet(&self) -> bool {
        false
    }

    /// Completes `out`, last written by [`ChannelEngine::step_quiet`], with every
    /// output of the last clock. The default has nothing to add.
    fn complete_outputs(&mut self, out: &mut ChannelOutputs) {
        let _ = out;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tseg1_must_last_three_clocks() {
        let t = |brp, tseg1, tseg2| BitTiming {
            brp,
            tseg1,
            tseg2,
            sjw: 1,
            triple_sampling: false,
        };
        // (brp+1) * tseg1 < 3 is refused, naming the field and the minimum.
        for (brp, tseg1, min) in [(0, 1, 3), (0, 2, 3), (1, 1, 2)] {
            let e = t(brp, tseg1, 8).validate().unwrap_err();
            assert!(
                e.starts_with(&format!("bit timing field `tseg1` = {tseg1} ")),
                "{e}"
            );
            assert!(
                e.ends_with(&format!(
                    "the legal minimum at brp = {brp} is tseg1 = {min}"
                )),
                "{e}"
            );
            assert_eq!(t(brp, tseg1, 8).min_tseg1(), min);
        }
        // The boundary and everything above it is accepted.
        for (brp, tseg1) in [(0, 3), (1, 2), (2, 1), (63, 1)] {
            assert_eq!(
                t(brp, tseg1, 8).validate(),
                Ok(()),
                "brp {brp} tseg1 {tseg1}"
            );
        }
        assert_eq!(BitTiming::default().validate(), Ok(()));
    }

    #[test]
    fn mode_codes_round_trip() {
        for m in [
            Mode::Normal,
            Mode::ListenOnly,
            Mode::SelfTest,
            Mode::Loopback,
        ] {
            assert_eq!(Mode::from_code(m.code()), m);
        }
        assert_eq!(ControllerConfig::default().ewl, 96);
    }
}
