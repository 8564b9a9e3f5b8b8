#![doc = include_str!("timing_contract.md")]
//!
//! ## The reference model
//!
//! [`ChannelModel`] is the oracle: one classical CAN 2.0B channel (ISO 11898-1:2015,
//! classical CAN only) written from the standard and the contract above, clock by
//! clock. It is built from the synchronizer and bit timing logic (`btl`, §2 and §3;
//! ISO 11898-1 11.3) and the bit stream processor (`bsp`, §4, §7 to §9; ISO 11898-1
//! clauses 10 and 12). The field codes of §4.1 are in [`field`], the CRC in [`crc`].
//! The configuration (§6) is captured at reset edges and held while running.
//!
//! Speed: when the prescaler does not tick, a step moves only the synchronizer and
//! the prescaler; the frame is kept as integers.

pub mod bsp;
pub mod btl;
pub mod bus;
pub mod coverage;
pub mod crc;
pub mod drcc;
pub mod field;
pub mod hub;
pub mod pelican;
pub mod rcm;

use crate::engine::{ChannelInputs, ChannelOutputs, Diagnostics, Mode, Probes};
use bsp::Bsp;
use btl::{Btl, BtlEvent, Timing};

/// One CAN channel: configuration registers, synchronizer, prescaler, bit timing
/// logic, bit stream processor.
///
/// A new model is in reset mode: its first edge captures the configuration inputs
/// (contract §6, "every engine starts in reset") whether or not `rst` is high
/// there; from then on they are captured only at edges with `rst = 1`.
#[derive(Clone, Debug)]
pub struct ChannelModel {
    btl: Btl,
    bsp: Bsp,
    /// `sample_point` register (one clock after a SAMPLE edge).
    sample_point: bool,
    // Configuration registers (§6).
    timing: Timing,
    ewl: u8,
    loopback: bool,
    /// The configuration registers have been loaded (first edge or a reset edge).
    configured: bool,
    /// Every edge takes the slow path (`step_special`): not yet configured, or
    /// LOOPBACK.
    special: bool,
}

impl Default for ChannelModel {
    fn default() -> Self {
        Self::new()
    }
}

impl ChannelModel {
    /// A channel in its reset state, configuration not yet captured.
    pub fn new() -> Self {
        ChannelModel {
            btl: Btl::new(),
            bsp: Bsp::new(),
            sample_point: false,
            timing: Timing::default(),
            ewl: 96,
            loopback: false,
            configured: false,
            special: true,
        }
    }

    /// The state after a reset edge: every register at its reset value, the
    /// configuration registers loaded from `inputs` (§6).
    fn reset(inputs: &ChannelInputs) -> Self {
        let c = &inputs.config;
        ChannelModel {
            btl: Btl::new(),
            bsp: Bsp::with_config(c.mode, c.single_shot),
            sample_point: false,
            timing: Timing::capture(&inputs.timing),
            ewl: c.ewl,
            loopback: c.mode == Mode::Loopback,
            configured: true,
            special: c.mode == Mode::Loopback,
        }
    }

    /// The captured (clamped) bit timing.
    pub fn timing(&self) -> &Timing {
        &self.timing
    }

    /// Apply `inputs` for one clock period, make one rising edge, return the
    /// outputs right after it (contract §1).
    ///
    /// Speed: the common edge (no reset, no abort, not LOOPBACK) takes one test;
    /// everything else goes through the out-of-line `step_special`.
    #[inline]
    pub fn step(&mut self, inputs: &ChannelInputs) -> ChannelOutputs {
        self.clock(inputs);
        self.outputs()
    }

    /// [`Self::step`] without its return value: a caller that keeps the outputs
    /// in a field of its own assigns [`Self::outputs`] there, which the compiler
    /// builds in place instead of copying a returned struct.
    pub fn clock(&mut self, inputs: &ChannelInputs) {
        // Bitwise `|` on bools: one test instead of four branches.
        if inputs.rst | inputs.tx_abort | inputs.err_reset | self.special | self.bsp.abort_pending()
        {
            self.step_special(inputs);
        } else {
            self.edge(inputs, inputs.rx, false);
        }
    }

    /// Reset edges, the first edge of a new model, `tx_abort` or a remembered
    /// abort, `err_reset`, LOOPBACK.
    #[cold]
    #[inline(never)]
    fn step_special(&mut self, inputs: &ChannelInputs) {
        if inputs.rst || !self.configured {
            // A reset edge (§6); power-up is reset mode, so a new model's first
            // edge loads the configuration too, then runs normally if `rst` is low.
            *self = ChannelModel::reset(inputs);
            if inputs.rst {
                return;
            }
        }
        // §7 LOOPBACK: the synchronizer's first stage takes the own `tx` register.
        let rx = if self.loopback {
            self.bsp.tx()
        } else {
            inputs.rx
        };
        let abort = inputs.tx_abort || self.bsp.abort_pending();
        self.edge(inputs, rx, abort);
        // §4.5: the counter reset is applied after the edge's counting rules.
        if inputs.err_reset {
            self.bsp.err_reset();
        }
    }

    /// One edge of a configured channel out of reset; `rx` is what enters the
    /// synchronizer, `abort` a `tx_abort` or remembered abort (§8).
    #[inline(always)]
    fn edge(&mut self, inputs: &ChannelInputs, rx: bool, abort: bool) {
        self.sample_point = false;
        self.bsp.clear_pulses();
        // tx_req is judged against tx_pending before the edge (contract §4.4).
        let request = inputs.tx_req && !self.bsp.tx_pending();
        // §8: an abort is judged on the state before the edge, before the SOF
        // decisions of this edge.
        if abort {
            self.bsp.abort();
        }
        let (rx_s, tick) = self.btl.clock(rx, self.timing.brp);
        if tick {
            let hard_sync_enable = self.bsp.hard_sync_enable();
            match self
                .btl
                .tick(rx_s, &self.timing, self.bsp.tx(), hard_sync_enable)
            {
                BtlEvent::None => {}
                BtlEvent::Sample(b) => {
                    self.sample_point = true;
                    self.bsp.sample(b, inputs.boff_hold);
                }
                BtlEvent::BitStart { hard } => self.bsp.bit_start(hard),
            }
        }
        if request {
            self.bsp.latch(&inputs.tx_frame, inputs.tx_single);
        }
    }

    /// The output registers.
    #[inline]
    pub fn outputs(&self) -> ChannelOutputs {
        let (tx_done, arb_lost, rx_valid, tx_failed) = self.bsp.pulses();
        let counters = self.bsp.counters();
        let d = self.bsp.diag();
        ChannelOutputs {
            // §7 LOOPBACK: the pin stays recessive.
            tx: self.bsp.tx() | self.loopback,
            tx_pending: self.bsp.tx_pending(),
            tx_done,
            arb_lost,
            tx_failed,
            rx_valid,
            rx_frame: *self.bsp.rx_frame(),
            probes: Probes {
                sample_point: self.sample_point,
                sampled_bit: self.btl.last_sample(),
                field: self.bsp.field(),
                tec: counters.tec(),
                rec: counters.rec(),
                err_state: counters.state(),
                is_tx: self.bsp.is_tx(),
                boff_runs: self.bsp.boff_runs(),
            },
            diag: Diagnostics {
                err_warning: counters.tec() >= self.ewl as u16 || counters.rec() >= self.ewl,
                err_valid: d.err_valid,
                err_kind: d.err_kind,
                err_field: d.err_field,
                err_tx: d.err_tx,
                alc: d.alc,
                cnt_bit: d.counts[0],
                cnt_stuff: d.counts[1],
                cnt_crc: d.counts[2],
                cnt_form: d.counts[3],
                cnt_ack: d.counts[4],
            },
        }
    }
}
