//! Driver features of contract §11: the acceptance filters at the RX FIFO's write
//! port (§11.1), the per-channel transmit events (§11.3) and the clearing of the
//! statistics (§11.4). The RX timestamps (§11.2) live in the RX FIFO
//! ([`super::rx_path`]).

use super::regs::{filt, frame_id, int};
use super::DrccModel;
use crate::engine::ChannelOutputs;
use crate::frame::Frame;

/// The two identifier / mask pairs (`FILT_ID0`, `FILT_MASK0`, `FILT_ID1`,
/// `FILT_MASK1`): cfg registers, cleared by `rst` only.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Filters {
    /// `FILT_IDk` ([30:0]).
    pub id: [u32; 2],
    /// `FILT_MASKk` ([30:0] mask, [31] enable).
    pub mask: [u32; 2],
    /// A host view's acceptance filter (PeliCAN P-CORE-4); `None` natively.
    pub gate: Option<crate::model::pelican::acf::Acf>,
}

impl Filters {
    /// The frame word `{rtr, ide, id}` in the `RX_ID` layout (§11.1).
    pub fn word(f: &Frame) -> u32 {
        (f.id & frame_id::ID_MASK)
            | if f.ide { frame_id::IDE } else { 0 }
            | if f.rtr { frame_id::RTR } else { 0 }
    }

    /// Filter `k` matches: `((word ^ id) & mask) == 0` on bits [30:0].
    fn matches(&self, k: usize, word: u32) -> bool {
        (word ^ self.id[k]) & self.mask[k] & filt::WORD == 0
    }

    /// Accepted: no filter is enabled, or an enabled filter matches.
    pub fn accepts(&self, f: &Frame) -> bool {
        let word = Self::word(f);
        if self.gate.is_some_and(|g| !g.accepts(f)) {
            return false;
        }
        let enabled = [0, 1].map(|k| self.mask[k] & filt::ENABLE != 0);
        !enabled.contains(&true) || (0..2).any(|k| enabled[k] && self.matches(k, word))
    }
}

/// The `INT_STATUS` bits of §11.3 at an edge: each channel's `tx_done` /
/// `tx_failed` pulse (registered channel outputs), in every mode.
pub(super) fn tx_channel_events(a: &ChannelOutputs, b: &ChannelOutputs) -> u32 {
    [
        (a.tx_done, int::TX_DONE_A),
        (b.tx_done, int::TX_DONE_B),
        (a.tx_failed, int::TX_FAILURE_A),
        (b.tx_failed, int::TX_FAILURE_B),
    ]
    .into_iter()
    .filter(|&(pulse, _)| pulse)
    .fold(0, |m, (_, bit)| m | bit)
}

impl DrccModel {
    /// `STATS_CLR.clear` (§11.4), applied after every block's edge so that the
    /// clear wins over an event at the same edge: `STATS0`, `STATS1`,
    /// `OMISSIONS`, `DMR_RX_STATS`, the `failures` / `recoveries` counts of
    /// `AUX_A` / `AUX_B` and `ECSS_STATUS.ctoggle` (§12.1). Kept: the failed
    /// attempts, `TIMES`, `DMR_CS_COUNT`, the DMR state counts and every state.
    pub(super) fn clear_statistics(&mut self) {
        let rx = &mut self.rx;
        rx.duplicates = 0;
        rx.overruns = 0;
        rx.omissions = [0; 2];
        rx.pcl_frames = 0;
        rx.released = 0;
        rx.expired = 0;
        self.fsm.switches = 0;
        self.r.recoveries = 0;
        for a in &mut self.aux {
            a.failures = 0;
            a.recoveries = 0;
        }
        // §12.1: the ECSS toggle count.
        self.r.ecss.sel.ctoggle = 0;
    }
}
