//! What the lower tester records: one [`BitRecord`] per script bit (bus, IUT `tx`,
//! probes, host events), the IUT's sample events, one [`ClockRecord`] per clock,
//! and the [`Run`] of a played script.

use super::*;

/// What happened during one tester bit.
#[derive(Clone, Debug)]
pub struct BitRecord {
    /// Label from the script.
    pub label: String,
    /// The tester's drive.
    pub drive: Lt,
    /// Bus value the IUT sampled (the bus two clocks before its SAMPLE edge).
    pub bus: bool,
    /// The IUT's `tx` on the bus at that moment.
    pub tx: bool,
    /// Clock of the bus value the IUT sampled, counted from the bit's first clock
    /// (None: no sample point read this bit).
    pub sample_offset: Option<u32>,
    /// Probes right after the sample point (at the end of the bit if there was none).
    pub probes: Probes,
    /// `rx_valid` pulsed during the bit.
    pub rx_valid: bool,
    /// `rx_frame` at the `rx_valid` pulse.
    pub rx_frame: Option<Frame>,
    /// `tx_done` pulsed during the bit.
    pub tx_done: bool,
    /// `arb_lost` pulsed during the bit.
    pub arb_lost: bool,
    /// Clocks the tester waited for the IUT's SOF before this bit ([`SBit::await_sof`]).
    pub waited: Option<u32>,
    /// First clock of the bit (tester clock count).
    pub start: u64,
    /// First clock after the bit.
    pub end: u64,
}

/// A SAMPLE edge of the IUT (or a host pulse), attributed to the clock of the bus
/// value it read: the IUT's synchronizer makes that two clocks before the edge.
#[derive(Clone, Copy, Debug)]
pub struct SampleEvent {
    /// Tester clock of the bus value the IUT sampled (edge clock - 2).
    pub rx_clock: u64,
    /// A sample point (false: only host pulses at this edge).
    pub sample: bool,
    /// The bus value sampled.
    pub bus: bool,
    /// The IUT's `tx` on the bus at `rx_clock`.
    pub tx: bool,
    /// Probes after the edge.
    pub probes: Probes,
    /// `rx_valid` at this edge, with the frame.
    pub rx_frame: Option<Frame>,
    /// `tx_done` at this edge.
    pub tx_done: bool,
    /// `arb_lost` at this edge.
    pub arb_lost: bool,
}

/// One clock as seen by the tester (for the bit-timing items).
#[derive(Clone, Copy, Debug)]
pub struct ClockRecord {
    /// Tester clock count of this clock.
    pub clock: u64,
    /// Bus value (the IUT's `rx`) in this clock.
    pub bus: bool,
    /// The IUT's `tx` on the bus in this clock (returned by the previous step).
    pub tx: bool,
    /// The outputs after this clock's edge.
    pub out: ChannelOutputs,
}

/// The records of a played script.
#[derive(Clone, Debug)]
pub struct Run {
    /// One record per script bit.
    pub recs: Vec<BitRecord>,
}

impl Run {
    /// Index of the first record labelled `label`.
    pub fn find(&self, label: &str) -> usize {
        self.find_from(0, label)
    }

    /// Index of the first record labelled `label` at or after `from`.
    pub fn find_from(&self, from: usize, label: &str) -> usize {
        (from..self.recs.len())
            .find(|&i| self.recs[i].label == label)
            .unwrap_or_else(|| panic!("no bit labelled {label:?} after bit {from}"))
    }

    /// The record labelled `label`.
    pub fn at(&self, label: &str) -> &BitRecord {
        &self.recs[self.find(label)]
    }

    /// The last record.
    pub fn last(&self) -> &BitRecord {
        self.recs.last().expect("empty run")
    }

    /// Indices of the bits where `rx_valid` pulsed.
    pub fn rx_valid_bits(&self) -> Vec<usize> {
        (0..self.recs.len())
            .filter(|&i| self.recs[i].rx_valid)
            .collect()
    }

    /// Indices of the bits where `tx_done` pulsed.
    pub fn tx_done_bits(&self) -> Vec<usize> {
        (0..self.recs.len())
            .filter(|&i| self.recs[i].tx_done)
            .collect()
    }

    /// Indices of the bits where `arb_lost` pulsed.
    pub fn arb_lost_bits(&self) -> Vec<usize> {
        (0..self.recs.len())
            .filter(|&i| self.recs[i].arb_lost)
            .collect()
    }
}
