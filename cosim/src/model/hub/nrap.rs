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

mod phases;
use phases::SampleEdge;

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
        let before = self.phase;
        let acting = matches!(before, phase::SRP_EXCHANGE | phase::NRP | phase::DDSP_SEND);

        self.transmitter_sample(i);

        // Recogniser.
        let id_frame = self.r_own || self.r_twin;
        let (own_frame, twin_frame) = self.recognise(i, acting);

        // Blocked-network count, in every phase (only RUN acts on it).
        if i.ack_delim {
            self.unacked = if i.b { 0 } else { (self.unacked + 1).min(31) };
        }

        let mut e = SampleEdge {
            id_frame,
            own_frame,
            twin_frame,
            nt: self.nt.saturating_add(1),
            ncnt: self.ncnt,
            sub_enabled: i.enabled & !((1u16 << n) - 1),
            fx: SampleEffects::default(),
        };
        let left = match before {
            phase::RUN => self.run(i, &mut e, cfg),
            phase::SRP_FORCE if e.nt >= cfg.force_bits => self.end_srp_force(&mut e, ports, n),
            phase::SRP_EXCHANGE => self.srp_exchange(i, &mut e, ports, n, cfg),
            phase::NRP => self.nrp(i, &mut e, ports, n, cfg),
            phase::DDSP_FORCE if e.nt >= cfg.force_bits => self.end_ddsp_force(&mut e, ports, n),
            phase::DDSP_SEND => self.ddsp_send(i, &mut e, ports, n, cfg),
            _ => false,
        };
        // A phase left restarts its timer and counter (`goto`).
        if !left {
            self.nt = e.nt;
            self.ncnt = e.ncnt;
        }
        e.fx
    }

    /// The transmitter's side of the sampled bit (§9.3): the run of recessive
    /// samples it waits for before it sends, and its withdrawal when arbitration
    /// is lost or a bit error ends the attempt.
    fn transmitter_sample(&mut self, i: &SampleInputs) {
        self.quiet = if i.b { (self.quiet + 1).min(15) } else { 0 };
        // Transmitter: arbitration lost or a bit error ends the attempt.
        if self.tx_on && i.b != self.tx_q {
            coverage::hit("hub nrap: transmitter withdraws (arbitration or bit error)");
            self.tx_on = false;
            self.tx_q = true;
        }
    }

    /// The recogniser of identification frames (§9.3): matches the frame on the
    /// bus against both ROMs, asks for the acknowledgement of the twin's frame
    /// (`acting`: in a phase that acknowledges) and returns, at the ACK slot,
    /// whether the frame was the own or the twin's.
    fn recognise(&mut self, i: &SampleInputs, acting: bool) -> (bool, bool) {
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

        (own_frame, twin_frame)
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
