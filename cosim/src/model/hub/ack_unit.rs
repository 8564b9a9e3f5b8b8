//! The ACK unit (hub contract §4.1, paper section 4): a bus guardian beside the
//! hub that keeps it from passing its own nodes' ACK while coupled.
//!
//! Its state is its own: input synchronizers, a copy of the coupled bus, a bit
//! timing logic and a frame tracker (the §5 tracker, state only), and the downlink
//! output register. From the hub it takes the configuration, the `enabled` mask,
//! `decoupled` and the coupler's next downlink value `dl_next`:
//!
//! ```text
//! u_s1 <= pins ; u_in_s <= u_s1
//! u_own  = AND over node ports    of (u_in_s | !enabled) & tx_q & !forcing
//! u_twin = AND over sublink ports of (u_in_s | !enabled)
//! u_view_q <= decoupled ? u_own : u_own & u_twin
//! guard    = u_window & ack_interdep & !decoupled
//! downlink <= guard ? (dl_next | u_twin) : dl_next
//! ```

use super::tracker::{Tracker, IDLE_WAIT};
use crate::model::btl::{Btl, BtlEvent, Timing};

/// The hub registers the unit reads at an edge (values before it).
#[derive(Clone, Copy, Debug)]
pub struct AckUnitInputs {
    /// The port pins (bit p = port p, 1 = recessive).
    pub pins: u16,
    pub enabled: u16,
    pub decoupled: bool,
    /// The hub's NRAP transmitter is part of its contribution (§9.4): `tx_q &
    /// !forcing`.
    pub own_gate: bool,
    pub ack_interdep: bool,
    /// The coupler's next downlink value (§3).
    pub dl_next: bool,
    /// `reset_mode` (the tracker is held) and `reset_mode | reset_mode_q` (the BTL
    /// is held).
    pub reset_mode: bool,
    pub btl_reset: bool,
}

/// The unit's registers.
#[derive(Clone, Debug)]
pub struct AckUnit {
    s1: u16,
    in_s: u16,
    view_q: bool,
    btl: Btl,
    trk: Tracker,
    /// The downlink output register.
    pub downlink: bool,
    /// `ACK_UNIT[15:0]`: ACK windows in which the unit intervened (saturating).
    pub blocks: u16,
    /// The unit already intervened in this window.
    blocked: bool,
}

impl Default for AckUnit {
    fn default() -> Self {
        Self::new()
    }
}

impl AckUnit {
    /// `rst` state: everything recessive, counters 0.
    pub fn new() -> Self {
        AckUnit {
            s1: u16::MAX,
            in_s: u16::MAX,
            view_q: true,
            btl: Btl::new(),
            trk: Tracker::new(),
            downlink: true,
            blocks: 0,
            blocked: false,
        }
    }

    /// `u_window`: the unit's own tracker is in the ACK slot or delimiter.
    pub fn window(&self) -> bool {
        self.trk.ack_window()
    }

    /// One edge; `timing` is the hub's captured bit timing. Returns whether the
    /// unit intervened for the first time in this window (`INT_STATUS.ack_unit`).
    pub fn edge(
        &mut self,
        i: &AckUnitInputs,
        timing: &Timing,
        node_mask: u16,
        sub_mask: u16,
    ) -> bool {
        // Combinational values from the registers before the edge.
        let contrib = self.in_s | !i.enabled;
        let own = contrib & node_mask == node_mask && i.own_gate;
        let twin = contrib & sub_mask == sub_mask;
        let window = self.trk.ack_window();
        let guard = window && i.ack_interdep && !i.decoupled;
        let b = self.view_q;

        // Interventions: a dominant bit turned recessive, counted once per window.
        let mut first = false;
        if guard && !i.dl_next && twin && !self.blocked {
            self.blocks = self.blocks.saturating_add(1);
            self.blocked = true;
            first = true;
        }
        if !window {
            self.blocked = false;
        }

        self.downlink = if guard { i.dl_next | twin } else { i.dl_next };
        self.view_q = if i.decoupled { own } else { own & twin };
        self.in_s = self.s1;
        self.s1 = i.pins;

        // The unit's own bit timing and tracker, held in reset as the hub's (§5).
        if i.btl_reset {
            self.btl = Btl::new();
        } else {
            let (_, tick) = self.btl.clock(b, timing.brp);
            if tick {
                let hard_sync_enable = self.trk.state == IDLE_WAIT;
                if let BtlEvent::Sample(sampled) = self.btl.tick(b, timing, true, hard_sync_enable)
                {
                    self.trk.sample(sampled);
                }
            }
        }
        if i.reset_mode {
            self.trk = Tracker::new();
            self.blocked = false;
        }
        first
    }
}
