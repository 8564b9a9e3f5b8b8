//! Per-port guards (hub contract §6, paper section 2: per-port fault treatment and
//! restoration policy). One [`PortGuard`] per port (node ports and incoming
//! sublinks); [`PortGuard::sample`] is one SAMPLE edge of the hub's bit timing logic
//! for that port, given the tracker's action for the bit ([`TrkEvent`]):
//!
//! - enabled ports: stuck-at-dominant (SD), bit-flipping blame (BF, port error
//!   counter `pec`), reserved identifier (RID, node ports only), silence
//!   (stuck-at-recessive, SR); several isolations at one edge take the kind of the
//!   first of SD, RID, BF, SR;
//! - disabled ports: the restoration counter (`restore_cnt`) of symptom-free samples;
//! - every port: `dom_run` and the per-frame flags `cand`, `lost`, `active`.
//!
//! Reset mode, the decoupled freeze of the sublinks and the commands are applied by
//! the hub (`super::HubModel`).

use super::tracker::TrkEvent;
use crate::model::coverage;

/// `kind` codes (last fault of a port).
pub mod kind {
    pub const NONE: u8 = 0;
    pub const STUCK_DOMINANT: u8 = 1;
    pub const SILENT: u8 = 2;
    pub const BIT_FLIPPING: u8 = 3;
    pub const RESERVED_ID: u8 = 4;
}

/// The thresholds that apply to one port at a SAMPLE edge (registers before it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// `sd_limit(p)`: `sd_run_up` or `sd_run_sub`.
    pub sd: u8,
    /// `bf_limit(p)`: `bf_up` or `bf_sub`.
    pub bf: u8,
    pub sr_frames: u8,
    pub restore_bits: u16,
    /// Node port (rule RID applies), not an incoming sublink.
    pub node: bool,
}

/// What happened to a port at a SAMPLE edge (for `INT_STATUS`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GuardEvents {
    pub isolated: bool,
    pub restored: bool,
}

/// The guard registers of one port (reset values in the comments).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PortGuard {
    /// [1] the port takes part in the coupling.
    pub enabled: bool,
    /// [0] last fault (`kind` codes).
    pub kind: u8,
    /// [0] port error counter, 0..255.
    pub pec: u8,
    /// [0] consecutive dominant samples, 0..63.
    pub dom_run: u8,
    /// [0] consecutive silent frames, 0..15.
    pub silent: u8,
    /// [0] consecutive symptom-free samples while disabled.
    pub restore_cnt: u16,
    /// [0] isolations, saturating.
    pub isolations: u8,
    /// [0] restorations, saturating.
    pub restorations: u8,
    /// [0] the port may be the frame's transmitter.
    pub cand: bool,
    /// [0] the port lost arbitration in this frame.
    pub lost: bool,
    /// [0] the port has been blamed in this frame.
    pub blamed: bool,
    /// [0] the port drove a dominant bit in this frame.
    pub active: bool,
}

impl Default for PortGuard {
    fn default() -> Self {
        Self::new()
    }
}

impl PortGuard {
    /// Reset state.
    pub const fn new() -> Self {
        PortGuard {
            enabled: true,
            kind: kind::NONE,
            pec: 0,
            dom_run: 0,
            silent: 0,
            restore_cnt: 0,
            isolations: 0,
            restorations: 0,
            cand: false,
            lost: false,
            blamed: false,
            active: false,
        }
    }

    /// `PORT_p` register value.
    pub fn reg(&self) -> u32 {
        self.enabled as u32
            | (self.kind as u32 & 7) << 1
            | (self.pec as u32) << 8
            | (self.isolations as u32) << 16
            | (self.restorations as u32) << 24
    }

    /// `BLAME(p)`: returns whether it reaches the port error counter limit.
    fn blame(&mut self, bf_limit: u8) -> bool {
        if self.blamed {
            return false;
        }
        self.blamed = true;
        self.pec = self.pec.saturating_add(8);
        self.pec >= bf_limit
    }

    /// Flags tracked for every port: `SOF_PORTS`, and the `active`, `cand`, `lost`
    /// updates of `FRAME_PORTS` / `ACK_PORTS`.
    #[inline]
    fn track_flags(&mut self, pb: bool, b: bool, ev: TrkEvent) {
        match ev {
            TrkEvent::Sof => {
                self.cand = !pb;
                self.lost = false;
                self.blamed = false;
                self.active = !pb;
            }
            TrkEvent::Frame { in_arb, .. } => {
                self.active |= !pb;
                if in_arb {
                    if !pb && !self.lost {
                        self.cand = true;
                    }
                    if pb && !b {
                        self.cand = false;
                        self.lost = true;
                    }
                }
            }
            TrkEvent::Ack => self.active |= !pb,
            TrkEvent::None => {}
        }
    }

    /// One SAMPLE edge: `pb` = `port_q` before the edge, `b` = the sampled bus value
    /// (`coupled_q` before the edge), `ev` the tracker's action for this bit.
    pub fn sample(&mut self, pb: bool, b: bool, ev: TrkEvent, lim: &Limits) -> GuardEvents {
        let mut out = GuardEvents::default();
        self.dom_run = if pb { 0 } else { (self.dom_run + 1).min(63) };
        let stuck = self.dom_run >= lim.sd;
        if self.enabled {
            self.track_flags(pb, b, ev);
            let mut bit_flipping = false;
            let mut reserved_id = false;
            let mut silence = false;
            match ev {
                TrkEvent::Frame {
                    in_arb,
                    stuff_recessive,
                    reserved_id: rid,
                } => {
                    // Rule BF: a port that is not the transmitter drove a dominant
                    // bit before the ACK slot.
                    if !in_arb && !pb && !self.cand {
                        bit_flipping |= self.blame(lim.bf);
                    }
                    // Six recessive bits: the transmitter failed to stuff.
                    if stuff_recessive && self.cand {
                        bit_flipping |= self.blame(lim.bf);
                    }
                    // Rule RID: identifier 0x000 / 0x001 from a node port.
                    if rid && lim.node && self.cand {
                        reserved_id = true;
                    }
                }
                TrkEvent::Ack => {
                    if !self.blamed {
                        self.pec = self.pec.saturating_sub(1);
                    }
                    if !self.active {
                        self.silent = (self.silent + 1).min(15);
                        silence = lim.sr_frames != 0 && self.silent >= lim.sr_frames;
                    } else {
                        self.silent = 0;
                    }
                }
                TrkEvent::Sof | TrkEvent::None => {}
            }
            let k = if stuck {
                kind::STUCK_DOMINANT
            } else if reserved_id {
                kind::RESERVED_ID
            } else if bit_flipping {
                kind::BIT_FLIPPING
            } else if silence {
                kind::SILENT
            } else {
                kind::NONE
            };
            if k != kind::NONE {
                coverage::hit_with(|| {
                    let what = match k {
                        kind::STUCK_DOMINANT => "stuck dominant",
                        kind::RESERVED_ID => "reserved identifier",
                        kind::BIT_FLIPPING => "bit flipping",
                        _ => "silent",
                    };
                    let port = if lim.node { "node port" } else { "sublink" };
                    format!("hub: isolate {port} ({what})")
                });
                self.enabled = false;
                self.kind = k;
                self.isolations = self.isolations.saturating_add(1);
                self.restore_cnt = 0;
                self.silent = 0;
                out.isolated = true;
            }
        } else {
            // Restoration: the port keeps being monitored.
            // `trk == ACK_SLOT & !(active | !pb)`: silent through a frame.
            let silent_frame = ev == TrkEvent::Ack && !self.active && pb;
            let symptom = (!pb && b) || stuck || silent_frame;
            self.track_flags(pb, b, ev);
            self.restore_cnt = if symptom {
                0
            } else {
                self.restore_cnt.saturating_add(1)
            };
            if lim.restore_bits != 0 && self.restore_cnt >= lim.restore_bits {
                coverage::hit(if lim.node {
                    "hub: restore node port"
                } else {
                    "hub: restore sublink"
                });
                self.enabled = true;
                self.restorations = self.restorations.saturating_add(1);
                self.pec = 0;
                self.silent = 0;
                self.restore_cnt = 0;
                out.restored = true;
            }
        }
        out
    }
}
