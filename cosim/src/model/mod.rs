#![doc = include_str!("timing_contract.md")]
//!
//! ## The reference model
//!
//! [`ChannelModel`] is the oracle: one classical CAN 2.0B channel (ISO 11898-1:2015,
//! classical CAN only) written from the standard and the contract above, clock by
//! clock. It is built from the synchronizer and bit timing logic (`btl`, §2 and §3;
//! ISO 11898-1 11.3) and the bit stream processor (`bsp`, §4; ISO 11898-1 clauses 10
//! and 12). The field codes of §4.1 are in [`field`], the CRC in [`crc`].
//!
//! Speed: when the prescaler does not tick, a step moves only the synchronizer and
//! the prescaler; the frame is kept as integers.

pub mod bsp;
pub mod btl;
pub mod crc;
pub mod field;

use crate::engine::{ChannelInputs, ChannelOutputs, Probes};
use bsp::Bsp;
use btl::{Btl, BtlEvent};

/// One CAN channel: synchronizer, prescaler, bit timing logic, bit stream processor.
#[derive(Clone, Debug, Default)]
pub struct ChannelModel {
    btl: Btl,
    bsp: Bsp,
    /// `sample_point` register (one clock after a SAMPLE edge).
    sample_point: bool,
}

impl ChannelModel {
    /// A channel in its reset state.
    pub fn new() -> Self {
        ChannelModel {
            btl: Btl::new(),
            bsp: Bsp::new(),
            sample_point: false,
        }
    }

    /// Apply `inputs` for one clock period, make one rising edge, return the
    /// outputs right after it (contract §1).
    #[inline]
    pub fn step(&mut self, inputs: &ChannelInputs) -> ChannelOutputs {
        if inputs.rst {
            *self = ChannelModel::new();
            return self.outputs();
        }
        self.sample_point = false;
        self.bsp.clear_pulses();
        // tx_req is judged against tx_pending before the edge (contract §4.4).
        let request = inputs.tx_req && !self.bsp.tx_pending();
        let (rx_s, tick) = self.btl.clock(inputs.rx, inputs.timing.brp);
        if tick {
            let hard_sync_enable = self.bsp.hard_sync_enable();
            match self
                .btl
                .tick(rx_s, &inputs.timing, self.bsp.tx(), hard_sync_enable)
            {
                BtlEvent::None => {}
                BtlEvent::Sample(b) => {
                    self.sample_point = true;
                    self.bsp.sample(b);
                }
                BtlEvent::BitStart { hard } => self.bsp.bit_start(hard),
            }
        }
        if request {
            self.bsp.latch(&inputs.tx_frame);
        }
        self.outputs()
    }

    /// The output registers.
    #[inline]
    pub fn outputs(&self) -> ChannelOutputs {
        let (tx_done, arb_lost, rx_valid) = self.bsp.pulses();
        let counters = self.bsp.counters();
        ChannelOutputs {
            tx: self.bsp.tx(),
            tx_pending: self.bsp.tx_pending(),
            tx_done,
            arb_lost,
            rx_valid,
            rx_frame: *self.bsp.rx_frame(),
            probes: Probes {
                sample_point: self.sample_point,
                sampled_bit: self.btl.last_sample(),
                field: self.bsp.field(),
                tec: counters.tec(),
                rec: counters.rec(),
                err_state: counters.state(),
            },
        }
    }
}
