//! The Network Reconfiguration Agreement Protocol (hub contract §9, ReCANcentrate
//! paper section 5): the identification frames ([`IdRom`], §9.1), the phase
//! machine (§9.2), the hub's transmitter and the recogniser of identification
//! frames (§9.3). The coupling gate it adds to §3 (`own & tx_q & !forcing`, §9.4)
//! and the freezing of the guards are applied by the hub (`super::HubModel`).
//!
//! Every rule is evaluated at an edge on the values before it; [`Nrap::bit_start`]
//! is a bit-start edge of the hub's bit timing logic, [`Nrap::sample`] a SAMPLE
//! edge.

use super::guard::PortGuard;
use super::tracker::TrkEvent;
use crate::model::coverage;
use crate::model::crc::crc15;

/// `nrap` phase encodings (§9.2).
pub mod phase {
    pub const RUN: u8 = 0;
    pub const SRP_FORCE: u8 = 1;
    pub const SRP_EXCHANGE: u8 = 2;
    pub const NRP: u8 = 3;
    pub const DDSP_FORCE: u8 = 4;
    pub const DDSP_SEND: u8 = 5;
    pub const SPLIT: u8 = 6;
}

/// Recessive samples after which a disabled sublink counts as silent (§9.2).
const SILENT_SUBLINK: u8 = 11;

/// One hub's identification frame as it appears on the bus (§9.1): the base data
/// frame with identifier `hub_id` and DLC 0, from SOF to the CRC delimiter, stuff
/// bits and CRC included. Bit `i` of `bits` is bus bit `i` (1 = recessive).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IdRom {
    pub bits: u64,
    pub len: u8,
}

impl IdRom {
    /// The identification frame of hub `hub_id` (0 = A, identifier 0x000; 1 = B,
    /// 0x001), built from ISO 11898-1 clause 10: SOF, identifier, RTR, IDE, r0,
    /// DLC, CRC-15 over those, stuffing after five equal bits up to the end of the
    /// CRC, then the recessive CRC delimiter.
    pub fn of(hub_id: u8) -> Self {
        let ident = hub_id as u16 & 1;
        let mut field: Vec<bool> = vec![false]; // SOF
        field.extend((0..11).rev().map(|i| (ident >> i) & 1 == 1));
        field.extend([false, false, false]); // RTR (data frame), IDE (base), r0
        field.extend([false; 4]); // DLC 0
        let crc = crc15(field.iter().copied());
        field.extend((0..15).rev().map(|i| (crc >> i) & 1 == 1));
        let mut bus = Vec::new();
        let (mut last, mut run) = (true, 0);
        for b in field {
            bus.push(b);
            run = if b == last { run + 1 } else { 1 };
            last = b;
            if run == 5 {
                bus.push(!b);
                last = !b;
                run = 1;
            }
        }
        bus.push(true); // CRC delimiter
        let bits = bus
            .iter()
            .enumerate()
            .fold(0u64, |acc, (i, &b)| acc | (b as u64) << i);
        IdRom {
            bits,
            len: bus.len() as u8,
        }
    }

    /// Bus bit `i` (1 = recessive); bits past the end read recessive.
    #[inline]
    pub fn bit(&self, i: u8) -> bool {
        i >= self.len || (self.bits >> i) & 1 == 1
    }
}

/// The NRAP registers of `NRAP_CFG`, `NRAP_TIME`, `NRAP_DDSP` (stored, clamped).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NrapCfg {
    pub force_bits: u16,
    pub srp_pairs: u8,
    pub nrp_pairs: u8,
    pub ddsp_frames: u8,
    pub srp_bits: u16,
    pub nrp_bits: u16,
    pub ddsp_bits: u16,
    /// Frames in a row ending in an ACK-delimiter error flag that start NRAP (0 =
    /// off).
    pub block_frames: u8,
}

/// What the hub needs to know at a SAMPLE edge (values before the edge).
#[derive(Clone, Copy, Debug)]
pub struct SampleInputs {
    /// Sampled bus value (`coupled_q`).
    pub b: bool,
    /// `port_q` (bit p = port p).
    pub pq: u16,
    /// The tracker's action for this bit.
    pub ev: TrkEvent,
    /// `trk == ACK_SLOT` before the edge.
    pub ack_slot: bool,
    /// `trk == ACK_DELIM` before the edge.
    pub ack_delim: bool,
    /// Enabled mask before the edge, as the guards show it (one clock late,
    /// §6.1): NRAP's own decisions use it; its writes to a port judge that
    /// guard's own `enabled`.
    pub enabled: u16,
    pub nrap_on: bool,
    pub decoupled: bool,
}

/// What a SAMPLE edge did that the hub applies elsewhere.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SampleEffects {
    /// The phase changed (`INT_STATUS.nrap`).
    pub phase_changed: bool,
    /// `DDSP_FORCE` was entered: `decoupled = 1` (`INT_STATUS.decoupled`).
    pub decouple: bool,
}

/// NRAP state (reset values in the comments).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Nrap {
    /// [RUN] `nrap`.
    pub phase: u8,
    /// [0] SAMPLE edges in this phase (saturating).
    pub nt: u16,
    /// [0] identification frames counted in this phase (0..15).
    pub ncnt: u8,
    /// [0] whose frame reached its ACK slot last: 0 none, 1 own, 2 twin.
    pub last: u8,
    /// [0] hub A's identification frame was acknowledged; hub B's next makes a
    /// pair.
    pub half: bool,
    /// [0] frames in a row with an error flag at the ACK delimiter (0..31).
    pub unacked: u8,
    /// [0] NRAP runs started (0..15; cleared by `rst` only).
    pub runs: u8,
    /// [0] the last run ended in `RUN` (cleared by `rst` only).
    pub outcome: bool,
    /// [1] the transmitter's bit.
    pub tx_q: bool,
    tx_on: bool,
    tx_idx: u8,
    ack_due: bool,
    acking: bool,
    /// Recessive samples in a row (0..15).
    quiet: u8,
    r_idx: u8,
    r_own: bool,
    r_twin: bool,
    /// Per port: consecutive recessive samples of a disabled sublink (0..15).
    rrun: [u8; 16],
    own: IdRom,
    twin: IdRom,
    /// `HUB_ID`.
    hub_id: u8,
}

impl Nrap {
    /// Reset state of hub `hub_id`.
    pub fn new(hub_id: u8) -> Self {
        Nrap {
            phase: phase::RUN,
            nt: 0,
            ncnt: 0,
            last: 0,
            half: false,
            unacked: 0,
            runs: 0,
            outcome: false,
            tx_q: true,
            tx_on: false,
            tx_idx: 0,
            ack_due: false,
            acking: false,
            quiet: 0,
            r_idx: 0,
            r_own: false,
            r_twin: false,
            rrun: [0; 16],
            own: IdRom::of(hub_id),
            twin: IdRom::of(hub_id ^ 1),
            hub_id,
        }
    }

    /// Reset mode: everything but `runs` and `outcome` at its reset value.
    pub fn hold_reset_mode(&mut self) {
        *self = Nrap {
            runs: self.runs,
            outcome: self.outcome,
            ..Nrap::new(self.hub_id)
        };
    }

    /// Phases 1..=5.
    #[inline]
    pub fn active(&self) -> bool {
        (phase::SRP_FORCE..=phase::DDSP_SEND).contains(&self.phase)
    }

    /// The own contribution is held dominant.
    #[inline]
    pub fn forcing(&self) -> bool {
        self.phase == phase::SRP_FORCE || self.phase == phase::DDSP_FORCE
    }

    /// The hub says nothing to its twin any more (§9.4).
    #[inline]
    pub fn quiet_twin(&self) -> bool {
        self.phase == phase::DDSP_SEND || self.phase == phase::SPLIT
    }

    /// `NRAP_STATUS`.
    pub fn status(&self) -> u32 {
        self.phase as u32
            | (self.outcome as u32) << 3
            | (self.runs as u32) << 4
            | (self.ncnt as u32) << 8
            | (self.last as u32) << 12
            | (self.half as u32) << 14
            | (self.nt as u32) << 16
    }

    fn send(&self, sub_any: bool) -> bool {
        ((self.phase == phase::SRP_EXCHANGE && sub_any || self.phase == phase::NRP)
            && self.last != 1)
            || self.phase == phase::DDSP_SEND
    }

    /// A bit-start edge of the hub's BTL (§9.3). `hard`: a hard synchronization
    /// started the bit; `sub_any`: a sublink port is enabled.
    pub fn bit_start(&mut self, hard: bool, sub_any: bool) {
        if !self.active() || self.forcing() {
            self.tx_q = true;
            self.tx_on = false;
            self.ack_due = false;
            self.acking = false;
        } else if self.tx_on && hard {
            // A hard synchronization restarts the SOF bit.
        } else if self.tx_on && self.tx_idx < self.own.len {
            self.tx_q = self.own.bit(self.tx_idx);
            self.tx_idx += 1;
        } else if self.tx_on {
            self.tx_q = true;
            self.tx_on = false;
        } else if self.ack_due {
            coverage::hit("hub nrap: acknowledges the twin's identification frame");
            self.tx_q = false;
            self.ack_due = false;
            self.acking = true;
        } else if self.acking {
            self.tx_q = true;
            self.acking = false;
        } else if self.send(sub_any) && self.quiet >= 11 {
            self.tx_q = false;
            self.tx_on = true;
            self.tx_idx = 1;
        }
    }

    /// `tx_on`, `ack_due`, `acking` cleared and `tx_q = 1`: at every edge where NRAP
    /// was not active, or was forcing, before it (§9.3).
    pub fn quiet_transmitter(&mut self) {
        self.tx_q = true;
        self.tx_on = false;
        self.ack_due = false;
        self.acking = false;
    }

    /// Phase change: the timer and the counter start again.
    fn goto(&mut self, p: u8, fx: &mut SampleEffects) {
        self.phase = p;
        self.nt = 0;
        self.ncnt = 0;
        self.half = false;
        fx.phase_changed = true;
    }

    /// `DDSP_FORCE` entry: decoupled, every sublink disabled.
    fn enter_ddsp(&mut self, ports: &mut [PortGuard], n: usize, fx: &mut SampleEffects) {
        coverage::hit("hub nrap: definitive decoupling");
        self.goto(phase::DDSP_FORCE, fx);
        fx.decouple = true;
        for g in ports[n..].iter_mut() {
            g.enabled = false;
        }
    }

    /// Every node port is restored with clean counters (NRP and DDSP_SEND entry).
    fn restore_nodes(&self, ports: &mut [PortGuard], n: usize) {
        for g in ports[..n].iter_mut() {
            g.enabled = true;
            g.pec = 0;
            g.silent = 0;
            g.restore_cnt = 0;
        }
    }

    /// A node port that drives a dominant bit after the arbitration field of an
    /// identification frame, before its ACK slot, while enabled is disabled at
    /// once (NRP, DDSP_SEND): only the transmitter (a hub) drives those bits.
    /// `id_frame`: the frame matched a ROM up to the bit before this one.
    fn drop_erring(&self, ports: &mut [PortGuard], n: usize, i: &SampleInputs, id_frame: bool) {
        if !id_frame || !matches!(i.ev, TrkEvent::Frame { in_arb: false, .. }) {
            return;
        }
        for (p, g) in ports[..n].iter_mut().enumerate() {
            // the guard's own `enabled` (§6.1: the guard judges its own state)
            if g.enabled && (i.pq >> p) & 1 == 0 {
                coverage::hit("hub nrap: a node port errs and is disabled");
                g.enabled = false;
            }
        }
    }

    /// The ACK slot of an identification frame in SRP_EXCHANGE or NRP: `last`,
    /// `half`; returns whether a pair (A's frame acknowledged, then B's) is
    /// complete.
    fn pairs(&mut self, own_frame: bool, twin_frame: bool, b: bool) -> bool {
        if !(own_frame || twin_frame) {
            return false;
        }
        if b {
            // Nobody acknowledged: an own frame is sent again at the next chance.
            self.half = false;
            if twin_frame {
                self.last = 2;
            }
            return false;
        }
        self.last = if own_frame { 1 } else { 2 };
        // Hub A is HUB_ID 0: its frame is the one with identifier 0x000.
        let from_a = if self.hub_id == 0 {
            own_frame
        } else {
            twin_frame
        };
        if from_a {
            self.half = true;
            false
        } else if self.half {
            self.half = false;
            coverage::hit("hub nrap: a pair of identification frames");
            true
        } else {
            false
        }
    }

    /// A SAMPLE edge (§9.2, §9.3). `ports[..n]` are the node ports, `ports[n..]`
    /// the incoming sublinks.
    pub fn sample(
        &mut self,
        i: &SampleInputs,
        ports: &mut [PortGuard],
        n: usize,
        cfg: &NrapCfg,
    ) -> SampleEffects {
        let mut fx = SampleEffects::default();
        let before = self.phase;
        let acting = matches!(before, phase::SRP_EXCHANGE | phase::NRP | phase::DDSP_SEND);

        self.quiet = if i.b { (self.quiet + 1).min(15) } else { 0 };
        // Transmitter: arbitration lost or a bit error ends the attempt.
        if self.tx_on && i.b != self.tx_q {
            coverage::hit("hub nrap: transmitter withdraws (arbitration or bit error)");
            self.tx_on = false;
            self.tx_q = true;
        }

        // Recogniser.
        let id_frame = self.r_own || self.r_twin;
        let (mut own_frame, mut twin_frame) = (false, false);
        match i.ev {
            TrkEvent::Sof => {
                self.r_idx = 1;
                self.r_own = true;
                self.r_twin = true;
            }
            TrkEvent::Frame { .. } => {
                let k = self.r_idx;
                self.r_own &= k < self.own.len && i.b == self.own.bit(k);
                self.r_twin &= k < self.twin.len && i.b == self.twin.bit(k);
                self.r_idx = (k + 1).min(63);
                if acting && self.r_twin && self.r_idx == self.twin.len {
                    self.ack_due = true;
                }
            }
            TrkEvent::Ack => {
                own_frame = self.r_own && self.r_idx == self.own.len;
                twin_frame = self.r_twin && self.r_idx == self.twin.len;
            }
            TrkEvent::None => {}
        }

        // Blocked-network count, in every phase (only RUN acts on it).
        if i.ack_delim {
            self.unacked = if i.b { 0 } else { (self.unacked + 1).min(31) };
        }

        let nt = self.nt.saturating_add(1);
        let mut ncnt = self.ncnt;
        let sub_enabled = i.enabled & !((1u16 << n) - 1);
        match before {
            phase::RUN => {
                let blocked = cfg.block_frames != 0 && self.unacked >= cfg.block_frames;
                if i.nrap_on && !i.decoupled && blocked {
                    coverage::hit("hub nrap: triggered (network blocked)");
                }
                if i.nrap_on && !i.decoupled && (sub_enabled == 0 || blocked) {
                    coverage::hit("hub nrap: triggered (no sublink left)");
                    self.goto(phase::SRP_FORCE, &mut fx);
                    self.last = 0;
                    self.runs = (self.runs + 1).min(15);
                    return fx;
                }
                if i.nrap_on && !i.decoupled && twin_frame {
                    coverage::hit("hub nrap: joins the twin's exchange");
                    self.goto(phase::SRP_EXCHANGE, &mut fx);
                    self.runs = (self.runs + 1).min(15);
                    self.rrun = [0; 16];
                    // The joining frame counts for the pairs as in SRP_EXCHANGE.
                    self.pairs(false, true, i.b);
                    return fx;
                }
            }
            phase::SRP_FORCE if nt >= cfg.force_bits => {
                self.goto(phase::SRP_EXCHANGE, &mut fx);
                for g in ports[n..].iter_mut() {
                    g.enabled = false;
                }
                self.rrun = [0; 16];
                return fx;
            }
            phase::SRP_EXCHANGE => {
                for (p, g) in ports.iter_mut().enumerate().skip(n) {
                    // the guard's own `enabled` (§6.1), not the late copy
                    if !g.enabled {
                        let r = if (i.pq >> p) & 1 == 1 {
                            (self.rrun[p] + 1).min(15)
                        } else {
                            0
                        };
                        self.rrun[p] = r;
                        if r >= SILENT_SUBLINK {
                            coverage::hit("hub nrap: silent sublink restored");
                            g.enabled = true;
                            g.pec = 0;
                            g.silent = 0;
                            g.restore_cnt = 0;
                        }
                    }
                }
                // The ACK of the own frame must come through an interlink: the
                // AND of the enabled sublinks (1 when none is enabled).
                let twin_b = i.pq | !sub_enabled | ((1u16 << n) - 1) == u16::MAX;
                let acked = if own_frame { twin_b } else { i.b };
                if self.pairs(own_frame, twin_frame, acked) {
                    ncnt = (ncnt + 1).min(15);
                }
                if ncnt >= cfg.srp_pairs {
                    coverage::hit("hub nrap: sublinks agreed (to node restoration)");
                    self.goto(phase::NRP, &mut fx);
                    self.restore_nodes(ports, n);
                    return fx;
                }
                if nt >= cfg.srp_bits {
                    self.enter_ddsp(ports, n, &mut fx);
                    return fx;
                }
            }
            phase::NRP => {
                self.drop_erring(ports, n, i, id_frame);
                if self.pairs(own_frame, twin_frame, i.b) {
                    ncnt = (ncnt + 1).min(15);
                }
                if ncnt >= cfg.nrp_pairs {
                    coverage::hit("hub nrap: recoupled");
                    self.goto(phase::RUN, &mut fx);
                    self.outcome = true;
                    return fx;
                }
                if nt >= cfg.nrp_bits {
                    self.enter_ddsp(ports, n, &mut fx);
                    return fx;
                }
            }
            phase::DDSP_FORCE if nt >= cfg.force_bits => {
                self.goto(phase::DDSP_SEND, &mut fx);
                self.restore_nodes(ports, n);
                return fx;
            }
            phase::DDSP_SEND => {
                self.drop_erring(ports, n, i, id_frame);
                if own_frame && !i.b {
                    ncnt = (ncnt + 1).min(15);
                }
                if ncnt >= cfg.ddsp_frames || nt >= cfg.ddsp_bits {
                    coverage::hit("hub nrap: split (each star on its own)");
                    self.goto(phase::SPLIT, &mut fx);
                    self.outcome = false;
                    return fx;
                }
            }
            _ => {}
        }
        self.nt = nt;
        self.ncnt = ncnt;
        fx
    }

    /// `CTRL.force_decouple` (NRAP on) or `CTRL.recouple`: the phase a command
    /// ends NRAP in. Returns whether the phase changed.
    pub fn command(&mut self, to: u8) -> bool {
        if self.phase == to {
            return false;
        }
        if self.active() {
            self.outcome = to == phase::RUN;
        }
        self.phase = to;
        self.nt = 0;
        self.ncnt = 0;
        self.half = false;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bus_string(r: &IdRom) -> String {
        (0..r.len)
            .map(|i| if r.bit(i) { '1' } else { '0' })
            .collect()
    }

    /// The frames written out from ISO 11898-1 clause 10: identifier 0x000, DLC 0
    /// has CRC 0 (an all-zero message leaves the divider at zero), so it is SOF and
    /// 33 zero bits with a stuff bit after every five, then the recessive
    /// delimiter; 0x001's CRC, 0x2213, was computed by a separate script.
    #[test]
    fn identification_frames_are_the_iso_bit_strings() {
        let a = IdRom::of(0);
        assert_eq!(a.len, 41);
        assert_eq!(bus_string(&a), "00000100000100000100000100000100000100001");
        let b = IdRom::of(1);
        assert_eq!(b.len, 38);
        assert_eq!(bus_string(&b), "00000100000101000001000100010000100111");
    }
}
