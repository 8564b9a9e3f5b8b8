//! Reference model of the ReCANcentrate hub top (two-stage AND star hub), written
//! from its clock-level contract (`hub_contract.md`, included below), the channel
//! contract (`timing_contract.md` §C.3 bit timing, §C.6 configuration capture and
//! clamps) and the DRCC contract's Wishbone conventions (§D.1, §D.2). It is the
//! oracle the RTL is compared with, so it never looks at the RTL.
//!
//! Parts: input synchronizers and coupling ([`coupling`], §2-§4), the frame tracker
//! ([`tracker`], §5) run at the sample points of the channel's own bit timing logic
//! ([`crate::model::btl`]) on `coupled_q`, the per-port guards ([`guard`], §6),
//! decoupling ([`decouple`], §7), the register file ([`regs`], §8) and the
//! Network Reconfiguration Agreement Protocol ([`nrap`], §9).
//!
//! Step order (a registered design): at every edge every next value is computed
//! from the values before it: Wishbone access, coupling, bit timing and (at a
//! SAMPLE edge) tracker, guards and decoupling, then the reset-mode hold, then the
//! commands (a command wins over a guard event of the same edge), then
//! `INT_STATUS` and `irq`.
//!
//! Guard stage (§6.1): `ports` are the guards as §6 decides them, edge by edge;
//! the RTL's guard registers, which everything else reads (the coupling, the ACK
//! unit, NRAP's decisions, §7, `STATUS`, `PORT_p`, `port_enabled`) and whose
//! events set `INT_STATUS`, are that state one clock late: `late`, `enabled` and
//! `late_ints`. `late` takes the value `ports` had before an edge at the end of
//! that edge, copied only after an edge that could change `ports`.
//!
//! Speed: a clock without a sample point and without a Wishbone access moves only
//! the synchronizers, the coupling registers and the prescaler (the accesses and
//! the commands are out of line); nothing allocates.
//!
//! ## Ambiguities (the reading taken where the contract leaves a choice)
//!
//! 1. `ack_window` is the combinational decode of the `trk` register (not a
//!    register of its own): the `ack_window` probe, `STATUS[2]` and the downlink
//!    mask all use `trk` as it is before the edge at which they are used.
//! 2. The BTL's `rx_s` is `coupled_q` itself (it is already a registered,
//!    synchronized signal): no further synchronizer stages. The prescaler, the
//!    segments and the sample point are the channel's (§C.3) with `tx = 1`,
//!    `triple = 0`, `hard_sync_enable = (trk == IDLE_WAIT)` before the edge.
//! 3. The BTL configuration is captured from `BTR` (value before the edge, clamped
//!    as §C.6) at every edge where the BTL is held in reset (`reset_mode |
//!    reset_mode_q` before the edge; at a `rst` edge the reset `BTR`).
//! 4. At a stuff error with `b == 1`, "every port with `cand`" uses `cand` after
//!    the arbitration update of that same bit (the rules of `FRAME_PORTS` apply in
//!    the order written).
//! 5. A disabled port only tracks its per-frame flags (`cand`, `lost`, `active`;
//!    `blamed` is cleared by `SOF_PORTS`); its `pec` and `silent` do not change
//!    until it is restored (restoration clears them).
//! 6. A `CTRL` write with both command bits set is refused whole (and sets
//!    `illegal`) whatever the reset mode, as the contract states it without a
//!    condition.
//! 7. `force_decouple` sets `INT_STATUS.decoupled` every time it acts, also when the
//!    hub is already decoupled.
//! 8. A command and a guard event of the same edge: the command's field writes win
//!    (`recouple` re-enables a sublink isolated at that edge, `decoupled = 0` beats
//!    a decoupling at that edge), but the guard event's `INT_STATUS` bit and its
//!    `kind` / `isolations` updates stay (the command keeps "kind and the counts").
//!    `recouple` is not a restoration (no count, no `INT_STATUS.restoration`).
//! 9. `no_twin` keeps counting while decoupled (it is not a sublink guard field);
//!    it is only observable through the next decoupling, after `recouple` cleared it.
//! 10. The reset-mode hold (every guard field, `enabled`, tracker, `no_twin`,
//!     `decoupled`, `STATS`) is a synchronous clear at every edge where
//!     `reset_mode` before the edge is 1; the coupling at that edge still uses the
//!     registers before it.
//! 11. Bits of `downlink`, `sublink_out` and `port_enabled` above N, M and N + M are
//!     0 (the ports are zero-extended into the engine's integers).
//! 12. Rule RID is judged, as written, at data bit `pos == 10`, before IDE is
//!     known: an extended frame whose 11-bit base part is 0x000 or 0x001 (ID[28:19]
//!     all dominant) isolates its node port too. The contract writes no exemption,
//!     and such identifiers outrank every other frame but the hubs' own.
#![doc = include_str!("../hub_contract.md")]

pub mod ack_unit;
pub mod coupling;
pub mod decouple;
pub mod guard;
mod host;
pub mod nrap;
pub mod regs;
pub mod tracker;

use crate::engine::hub::{HubInputs, HubOutputs, HubProbes, MAX_INTERLINKS, MAX_NODE_PORTS};
use crate::engine::BitTiming;
use crate::model::btl::{Btl, BtlEvent, Timing};
use ack_unit::{AckUnit, AckUnitInputs};
use coupling::{Coupling, CouplingInputs};
use decouple::Decoupler;
use guard::{Limits, PortGuard};
use nrap::{Nrap, SampleInputs};
use regs::{btr, int, Regs, WriteEffects};
use tracker::{Tracker, IDLE_WAIT};

/// Most ports a hub has (N + M).
pub const MAX_PORTS: usize = MAX_NODE_PORTS + MAX_INTERLINKS;

/// The bit timing a `BTR` value configures (value - 1 encodings), clamped as a
/// channel clamps its configuration (§C.6).
pub fn timing_of(btr_value: u32) -> Timing {
    Timing::capture(&BitTiming {
        brp: ((btr_value & btr::BRP_MASK) | ((btr_value >> btr::BRP_EXT_SHIFT) & 0xF) << 6) as u16,
        tseg1: ((btr_value >> btr::TSEG1_SHIFT) & 0xF) as u8 + 1,
        tseg2: ((btr_value >> btr::TSEG2_SHIFT) & 0x7) as u8 + 1,
        sjw: ((btr_value >> btr::SJW_SHIFT) & 0x3) as u8 + 1,
        triple_sampling: false,
    })
}

/// The hub top, simulated clock by clock.
#[derive(Clone, Debug)]
pub struct HubModel {
    /// `HUB_ID`: 0 = hub A (`hub.v`), 1 = hub B (`hub_b.v`).
    hub_id: u8,
    n: usize,
    m: usize,
    /// Bits `0..N`.
    node_mask: u16,
    /// Bits `N..N+M`.
    sub_mask: u16,
    regs: Regs,
    cpl: Coupling,
    btl: Btl,
    /// Bit timing captured while the BTL is held in reset.
    timing: Timing,
    /// `sample_point` probe register.
    sample_point: bool,
    trk: Tracker,
    /// The guards as §6 decides them (§6.1: the decision state).
    ports: [PortGuard; MAX_PORTS],
    /// The guard registers (§6.1): `ports` one clock late.
    late: [PortGuard; MAX_PORTS],
    /// Bit p = `late[p].enabled`: the enabled mask everything else reads.
    enabled: u16,
    /// `INT_STATUS` events of the guards decided at the last edge (set at this one).
    late_ints: u32,
    /// `ports` may have changed at the last edge (`late` must follow).
    moved: bool,
    dec: Decoupler,
    /// NRAP (§9): phases, transmitter, recogniser.
    nrap: Nrap,
    /// The ACK unit (§4.1); owns the downlink register.
    ack: AckUnit,
    /// The unit is fitted (always, in the RTL); a model without it shows what the
    /// unit prevents.
    ack_unit_fitted: bool,
}

impl HubModel {
    /// Hub A (`HUB_ID` 0) with `n` node ports and `m` interlinks in its reset
    /// state. Shapes outside N 2..=8, M 1..=4 are refused.
    pub fn new(n: usize, m: usize) -> Result<Self, String> {
        Self::new_hub(0, n, m)
    }

    /// Hub `hub_id` (0 = A, 1 = B: which identification frame it sends, §9.1).
    pub fn new_hub(hub_id: u8, n: usize, m: usize) -> Result<Self, String> {
        if !(2..=MAX_NODE_PORTS).contains(&n) || !(1..=MAX_INTERLINKS).contains(&m) {
            return Err(format!(
                "hub shape N = {n}, M = {m} is not supported: the hub has 2..={MAX_NODE_PORTS} \
                 node ports (N) and 1..={MAX_INTERLINKS} interlinks (M)"
            ));
        }
        let node_mask = (1u16 << n) - 1;
        let sub_mask = ((1u16 << m) - 1) << n;
        let mut hub = HubModel {
            hub_id: hub_id & 1,
            n,
            m,
            node_mask,
            sub_mask,
            regs: Regs::reset(),
            cpl: Coupling::new(),
            btl: Btl::new(),
            timing: timing_of(btr::RESET),
            sample_point: false,
            trk: Tracker::new(),
            ports: [PortGuard::new(); MAX_PORTS],
            late: [PortGuard::new(); MAX_PORTS],
            enabled: 0,
            late_ints: 0,
            moved: false,
            dec: Decoupler::default(),
            nrap: Nrap::new(hub_id & 1),
            ack: AckUnit::new(),
            ack_unit_fitted: true,
        };
        // A power-up also clears what reset mode keeps.
        hub.nrap = Nrap::new(hub_id & 1);
        hub.reset();
        Ok(hub)
    }

    /// The same hub without its ACK unit: the downlinks carry the coupler's value
    /// as it is. Not a configuration of the RTL (the unit is always fitted); tests
    /// use it to show what a faulty hub does when nothing guards it.
    pub fn without_ack_unit(mut self) -> Self {
        self.ack_unit_fitted = false;
        self
    }

    /// `HUB_ID` (0 = A, 1 = B).
    pub fn hub_id(&self) -> u8 {
        self.hub_id
    }

    /// Node ports N and interlinks M.
    pub fn shape(&self) -> (usize, usize) {
        (self.n, self.m)
    }

    /// Every register at its `rst` value.
    fn reset(&mut self) {
        self.regs = Regs::reset();
        self.cpl = Coupling::new();
        self.ack = AckUnit::new();
        self.nrap = Nrap::new(self.hub_id);
        self.btl = Btl::new();
        self.timing = timing_of(btr::RESET);
        self.sample_point = false;
        self.hold_reset_mode();
        // `rst` resets the guard registers at its own edge (§6.1)
        self.late = self.ports;
        self.enabled = self.node_mask | self.sub_mask;
        self.late_ints = 0;
        self.moved = false;
    }

    /// The fields reset mode holds at their reset values (§8 "Reset mode").
    fn hold_reset_mode(&mut self) {
        self.trk = Tracker::new();
        self.ports = [PortGuard::new(); MAX_PORTS];
        self.moved = true;
        self.dec = Decoupler::default();
        self.nrap.hold_reset_mode();
    }

    /// §6.1: the guard registers take the decision state `before` (the value
    /// `ports` had before this edge).
    fn follow(&mut self, before: &[PortGuard; MAX_PORTS]) {
        self.late = *before;
        self.late_mask();
    }

    /// `enabled` from the guard registers.
    fn late_mask(&mut self) {
        let mut e = 0u16;
        for (p, g) in self.late[..self.n + self.m].iter().enumerate() {
            e |= (g.enabled as u16) << p;
        }
        self.enabled = e;
    }

    /// Apply `inputs` for one clock period, make one rising edge, return the outputs
    /// right after it.
    #[inline]
    pub fn step(&mut self, i: &HubInputs) -> HubOutputs {
        if i.rst {
            self.reset();
        } else {
            self.edge(i);
        }
        self.outputs()
    }

    /// One edge out of `rst`.
    #[inline]
    fn edge(&mut self, i: &HubInputs) {
        // §6.1: the decision state before this edge, for the guard registers at
        // its end (only when it may have moved at the last edge).
        let before = if self.moved { Some(self.ports) } else { None };
        self.moved = false;
        let late_ints = std::mem::take(&mut self.late_ints);
        // The registers this edge needs as they are before it.
        let reset_mode = self.regs.reset_mode;
        let btl_reset = reset_mode || self.regs.reset_mode_q;
        let ack_interdep = self.regs.ack_interdep;
        let fi_ack_leak = self.regs.fi_ack_leak;
        let fi_no_twin = self.regs.fi_no_twin;
        let btr_before = self.regs.btr;
        let int_before = self.regs.int_status;
        let irq = int_before & self.regs.int_enable != 0;

        // Wishbone (§D.2): a transaction is taken when the ack register is low.
        let take = i.wb_cyc && i.wb_stb && !(self.regs.wb_ack || self.regs.wb_err);
        let mut fx = WriteEffects::default();
        if take {
            fx = self.wishbone(i);
        } else {
            self.regs.wb_ack = false;
            self.regs.wb_err = false;
            self.regs.wb_dat = 0;
        }
        let mut ints = if fx.illegal { int::ILLEGAL } else { 0 };

        // Synchronizers and coupling (§2-§4), on the registers before the edge.
        let b = self.cpl.coupled_q;
        let pq = self.cpl.port_q;
        let decoupled = self.dec.decoupled;
        let tx_q = self.nrap.tx_q;
        let tx_idle = !self.nrap.active() || self.nrap.forcing();
        let mask_ack = self.trk.ack_window() && ack_interdep && !decoupled && !fi_ack_leak;
        let pins = (i.uplink & self.node_mask) | ((i.sublink_in as u16) << self.n);
        let enabled = self.enabled;
        let dl_next = self.cpl.edge(
            &CouplingInputs {
                pins,
                enabled,
                own_gate: tx_q && !self.nrap.forcing(),
                quiet_twin: self.nrap.quiet_twin(),
                no_twin: fi_no_twin,
                decoupled,
                mask_ack,
            },
            self.node_mask,
            self.sub_mask,
        );

        // The ACK unit (§4.1), on the hub registers before the edge.
        if self.ack_unit_fitted {
            let first = self.ack.edge(
                &AckUnitInputs {
                    pins,
                    enabled,
                    decoupled,
                    own_gate: tx_q && !self.nrap.forcing(),
                    ack_interdep,
                    dl_next,
                    reset_mode,
                    btl_reset,
                },
                &self.timing,
                self.node_mask,
                self.sub_mask,
            );
            if first {
                ints |= int::ACK_UNIT;
            }
        } else {
            self.ack.downlink = dl_next;
        }

        // Bit timing (§5), held in reset by reset_mode | reset_mode_q.
        self.sample_point = false;
        if btl_reset {
            self.btl = Btl::new();
            self.timing = timing_of(btr_before);
        } else {
            let (_, tick) = self.btl.clock(b, self.timing.brp);
            if tick {
                let hard_sync_enable = self.trk.state == IDLE_WAIT;
                match self.btl.tick(b, &self.timing, tx_q, hard_sync_enable) {
                    BtlEvent::Sample(sampled) => {
                        self.sample_point = true;
                        // The guard configuration cannot change at a SAMPLE edge
                        // (it is written only in reset mode), so `self.regs` holds
                        // the values before the edge.
                        let (now, guards) = self.sample(sampled, pq);
                        ints |= now;
                        self.late_ints = guards;
                    }
                    BtlEvent::BitStart { hard } => {
                        let sub_any = self.enabled & self.sub_mask != 0;
                        self.nrap.bit_start(hard, sub_any);
                    }
                    BtlEvent::None => {}
                }
            }
        }

        // §9.3: the transmitter is quiet at every edge where NRAP was not active (or
        // was forcing) before it.
        if tx_idle {
            self.nrap.quiet_transmitter();
        }

        // Reset mode: a transparent star (§8).
        if reset_mode {
            self.hold_reset_mode();
        }

        // Commands (§8; they act only outside reset mode): the command wins.
        if fx.force_decouple | fx.recouple {
            ints |= self.command(&fx);
        }

        // §6.1: the guard registers, one clock behind the decisions
        if let Some(before) = before {
            self.follow(&before);
        }
        if fx.recouple {
            // §6.1: the command's enable shows at its own edge (its other writes
            // one clock later, with the rest of the guard state)
            for g in self.late[self.n..self.n + self.m].iter_mut() {
                g.enabled = true;
            }
            self.late_mask();
        }
        ints |= late_ints;

        self.regs.reset_mode_q = reset_mode;
        self.regs.int_status = (int_before & !fx.w1c) | ints;
        self.regs.irq = irq;
    }

    /// A SAMPLE edge: tracker, guards, decoupling. `b` = the sampled bus value,
    /// `pq` = `port_q` before the edge. Returns the `INT_STATUS` events of this
    /// edge and those of the guards (set one clock later, §6.1).
    fn sample(&mut self, b: bool, pq: u16) -> (u32, u32) {
        let r = &self.regs;
        let decouple_bits = r.decouple_bits();
        let ack_slot = self.trk.state == tracker::ACK_SLOT;
        let ack_delim = self.trk.state == tracker::ACK_DELIM;
        let ev = self.trk.sample(b);
        let enabled = self.enabled;
        let any_sub_enabled = enabled & self.sub_mask != 0;
        let decoupled = self.dec.decoupled;
        let nrap_active = self.nrap.active();
        let node = Limits {
            sd: r.sd_run_up(),
            bf: r.bf_up(),
            sr_frames: r.sr_frames(),
            restore_bits: r.restore_bits(),
            node: true,
        };
        let sub = Limits {
            sd: r.sd_run_sub(),
            bf: r.bf_sub(),
            node: false,
            ..node
        };
        let mut ints = 0;
        let mut guard_ints = 0;
        self.moved = true;
        // While NRAP is active no guard rule runs; while decoupled the sublink
        // guards are frozen.
        let ports = if nrap_active {
            0
        } else if decoupled {
            self.n
        } else {
            self.n + self.m
        };
        for (p, g) in self.ports[..ports].iter_mut().enumerate() {
            let lim = if p < self.n { &node } else { &sub };
            let e = g.sample((pq >> p) & 1 != 0, b, ev, lim);
            if e.isolated {
                guard_ints |= int::ISOLATION;
            }
            if e.restored {
                guard_ints |= int::RESTORATION;
            }
        }
        // NRAP (§9), on the values before the edge.
        let nrap_on = r.nrap_on;
        let cfg = r.nrap();
        let fx = self.nrap.sample(
            &SampleInputs {
                b,
                pq,
                ev,
                ack_slot,
                ack_delim,
                enabled,
                nrap_on,
                decoupled,
            },
            &mut self.ports[..self.n + self.m],
            self.n,
            &cfg,
        );
        if fx.phase_changed {
            ints |= int::NRAP;
        }
        if fx.decouple {
            self.dec.decoupled = true;
            ints |= int::DECOUPLED;
        }
        // §7 decouples only without NRAP.
        if !nrap_on && self.dec.sample(any_sub_enabled, decouple_bits) {
            ints |= int::DECOUPLED;
        }
        (ints, guard_ints)
    }

    /// The outputs after the last edge.
    #[inline]
    pub fn outputs(&self) -> HubOutputs {
        HubOutputs {
            wb_ack: self.regs.wb_ack,
            wb_err: self.regs.wb_err,
            wb_dat_r: self.regs.wb_dat,
            irq: self.regs.irq,
            downlink: if self.ack.downlink { self.node_mask } else { 0 },
            sublink_out: if self.cpl.sublink_out {
                (self.sub_mask >> self.n) as u8
            } else {
                0
            },
            probes: HubProbes {
                coupled: self.cpl.coupled_q,
                sample_point: self.sample_point,
                trk_state: self.trk.state,
                ack_window: self.trk.ack_window(),
                decoupled: self.dec.decoupled,
                port_enabled: self.enabled,
                nrap_phase: self.nrap.phase,
                hub_tx: self.nrap.tx_q,
            },
        }
    }

    /// The guard registers of port `p` (node ports `0..N`, sublinks `N..N+M`), as
    /// `PORT_p` shows them (one clock behind the decisions, §6.1).
    pub fn port(&self, p: usize) -> &PortGuard {
        &self.late[p]
    }

    /// The tracker (state and `STATS` counters).
    pub fn tracker(&self) -> &Tracker {
        &self.trk
    }

    /// `no_twin` and `decoupled`.
    pub fn decoupler(&self) -> &Decoupler {
        &self.dec
    }

    /// NRAP state (§9).
    pub fn nrap(&self) -> &Nrap {
        &self.nrap
    }
}
