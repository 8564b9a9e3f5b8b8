//! Network Reconfiguration Agreement Protocol, the phase machine (ReCANcentrate
//! paper section 5; hub contract §9.2, the `NRAP_STATUS` word of §9.5).
//!
//! State: the phase `nrap` (`RUN`, `SRP_FORCE`, `SRP_EXCHANGE`, `NRP`,
//! `DDSP_FORCE`, `DDSP_SEND`, `SPLIT`), the phase timer `nt` (SAMPLE edges,
//! 16 bits, saturating, in every phase), the counter `ncnt` (4 bits, saturating:
//! pairs in `SRP_EXCHANGE` and `NRP`, own frames in `DDSP_SEND`), `half` (hub A's
//! frame of a pair was acknowledged), `last` (whose identification frame was
//! exchanged last), `unacked` (frames in a row with an error flag at their ACK
//! delimiter, 5 bits, saturating, counted in every phase; only `RUN` acts on it),
//! `runs` and `outcome`. At a SAMPLE edge the
//! rules of the current phase run on the values before the edge ("new" `nt` /
//! `ncnt` / `unacked` are this edge's counts); a phase change clears `nt`, `ncnt`
//! and `half` and raises `ev_phase` (`INT_STATUS.nrap`).
//!
//! - `RUN` (with `nrap_on & !decoupled`), in this order: no sublink enabled
//!   (Trigger) or the new `unacked` >= `block_frames != 0` (Blocked network) →
//!   `SRP_FORCE`, `last = 0`; the ACK slot of the twin's identification frame
//!   (Joining) → `SRP_EXCHANGE`; the ports stay as they are, and that ACK slot
//!   counts for the pairs as in `SRP_EXCHANGE`: `last = 2`, and `half = 1` if the
//!   twin is hub A (`H` = 1) and the bus is dominant there (`b = 0`); it cannot
//!   complete a pair (`half` is 0 in `RUN`).
//! - Pairs (`SRP_EXCHANGE`, `NRP`): at the ACK slot of an identification frame,
//!   `last = 2` for the twin's; if it is acknowledged (the bus dominant there,
//!   `b = 0`; for the own frame in `SRP_EXCHANGE` the ACK must come through an
//!   interlink, `twin_b = 0`), `last = 1` for the own, hub A's frame sets `half`,
//!   hub B's frame with `half` completes a pair (`ncnt += 1`, `half = 0`); if not,
//!   `half` clears. Which of own / twin is hub A's is fixed by `H` (the const
//!   generic `HUB_ID`).
//! - `DDSP_SEND`: the own frame's ACK slot with the bus dominant counts.
//!
//! Structural, for Fmax: the increments of `nt`, `ncnt`, `unacked` and their
//! comparisons with the limits come registered from `super::nrap_ahead`, computed
//! in the clock before the SAMPLE edge (the counters cannot change in between).
//! The rules are computed every clock from the tracker's state (`at_ack`,
//! `at_delim`), not from its SAMPLE-edge events, and `sample` gates only the
//! register writes: the bit timing's sample decision, which comes late in the
//! clock, then meets the rules at their last gate instead of their first.
//!
//! The per-port NRAP field (`rrun`) and the writes to the ports' `enabled`, `pec`,
//! `silent` and `restore_cnt` live in the port guards (`super::port_guard`); this
//! block hands them one strobe per action, valid in the clock of the edge (the top
//! wires each to the node ports or the sublinks, as §9.2 says):
//!
//! | strobe | when | ports |
//! |---|---|---|
//! | `p_exchange` | every SAMPLE edge of `SRP_EXCHANGE` | sublinks: `rrun` rule |
//! | `p_watch` | every SAMPLE edge of `NRP` and `DDSP_SEND` inside an identification frame (`in_id`) | node ports: an erring port is disabled |
//! | `p_off_sub` | `SRP_FORCE` → `SRP_EXCHANGE`, entry to `DDSP_FORCE` | sublinks disabled |
//! | `p_join` | Joining (`RUN` → `SRP_EXCHANGE`) | sublinks: `rrun = 0` |
//! | `p_enable` | `SRP_EXCHANGE` → `NRP`, `DDSP_FORCE` → `DDSP_SEND` | node ports enabled |
//!
//! Entry to `DDSP_FORCE` also sets `decoupled` (`set_decoupled`, taken by the
//! register block with `INT_STATUS.decoupled`).
//!
//! `p_join` is a reading: §9.2 gives `rrun` as recessive samples in a row while a
//! sublink is disabled in `SRP_EXCHANGE` and zeroes it at the other entry
//! (`SRP_FORCE` → `SRP_EXCHANGE`); a sublink disabled by §6 in `RUN` may still
//! hold a count from an earlier NRAP run, so the joining entry starts it at 0 too
//! (the count is not visible in any register).
//!
//! Commands (§8, §9.2): `cmd_run` (`CTRL.recouple` taken) makes the new phase
//! `RUN`, `cmd_split` (`CTRL.force_decouple` taken) makes it `SPLIT` when
//! `nrap_on`; the command decides the phase of its edge, the rest of the rules of
//! that edge still happens (the register block and the guards let the command
//! win where it writes the same field). `runs` counts the edges where the phase
//! goes from `RUN` to an active phase; `outcome` is written where it goes from an
//! active phase to `RUN` (1) or `SPLIT` (0), by a rule or by a command; a command
//! given in `RUN` or `SPLIT` leaves it. `unacked` is not touched by a phase
//! change.
//!
//! `hold` (`rst | reset_mode`, the value before the edge) holds `nrap = RUN`,
//! `nt`, `ncnt`, `half`, `last` and `unacked` at 0 and suppresses every event and
//! strobe; `runs` and `outcome` clear with `rst` only.

use super::nrap_ahead::NrapAhead;
use crate::host::hub_registers::{NrapPhase, MAP};
use crate::host::map::lsb;
use rust_hdl::prelude::*;

fn phase(p: NrapPhase) -> Constant<Bits<3>> {
    Constant::new((p.code() as u64).into())
}

/// The NRAP phase machine of hub `H` (0 = A, 1 = B).
#[derive(LogicBlock)]
pub struct Nrap<const H: usize> {
    // ---- clock and resets ----
    /// Clock.
    pub clk: Signal<In, Clock>,
    /// The hub's `rst`: clears `runs` and `outcome` too.
    pub rst: Signal<In, Bit>,
    /// `rst | reset_mode` (value before the edge): holds the phase at `RUN` and
    /// `nt`, `ncnt`, `last` at 0.
    pub hold: Signal<In, Bit>,
    // ---- configuration (§8, §9.5) ----
    /// `CTRL.nrap_on`.
    pub nrap_on: Signal<In, Bit>,
    /// `NRAP_CFG.force_bits`.
    pub force_bits: Signal<In, Bits<10>>,
    /// `NRAP_CFG.srp_pairs`.
    pub srp_pairs: Signal<In, Bits<4>>,
    /// `NRAP_CFG.nrp_pairs`.
    pub nrp_pairs: Signal<In, Bits<4>>,
    /// `NRAP_CFG.ddsp_frames`.
    pub ddsp_frames: Signal<In, Bits<4>>,
    /// `NRAP_TIME.srp_bits`.
    pub srp_bits: Signal<In, Bits<16>>,
    /// `NRAP_TIME.nrp_bits`.
    pub nrp_bits: Signal<In, Bits<16>>,
    /// `NRAP_DDSP.ddsp_bits`.
    pub ddsp_bits: Signal<In, Bits<16>>,
    /// `NRAP_DDSP.block_frames` (0: the blocked-network trigger is off).
    pub block_frames: Signal<In, Bits<5>>,
    // ---- hub state (values before the edge) ----
    /// The hub is decoupled (register).
    pub decoupled: Signal<In, Bit>,
    /// Some sublink port is enabled (`sub_any`).
    pub any_sub_en: Signal<In, Bit>,
    /// `twin_b`: AND over the enabled sublink ports of `port_q` (1 when none).
    pub twin_b: Signal<In, Bit>,
    // ---- bit timing, tracker, recogniser ----
    /// SAMPLE edge of the hub's BTL.
    pub sample: Signal<In, Bit>,
    /// `coupled_q`: the bus value sampled at a SAMPLE edge.
    pub b: Signal<In, Bit>,
    /// The tracker is in the ACK slot (`trk == ACK_SLOT`): at a SAMPLE edge this
    /// is `ACK_PORTS`.
    pub at_ack: Signal<In, Bit>,
    /// The tracker is at the ACK delimiter (`trk == ACK_DELIM`).
    pub at_delim: Signal<In, Bit>,
    /// The frame in its ACK slot is the own identification frame.
    pub own_frame: Signal<In, Bit>,
    /// The frame in its ACK slot is the twin's identification frame.
    pub twin_frame: Signal<In, Bit>,
    /// `r_own | r_twin` (registers): the frame so far is an identification frame.
    pub in_id: Signal<In, Bit>,
    // ---- host commands (taken at this edge) ----
    /// `CTRL.recouple` acts: the phase becomes `RUN`.
    pub cmd_run: Signal<In, Bit>,
    /// `CTRL.force_decouple` acts: the phase becomes `SPLIT` if `nrap_on`.
    pub cmd_split: Signal<In, Bit>,
    // ---- state out (registers) ----
    /// `nrap`, the phase.
    pub phase: Signal<Out, Bits<3>>,
    /// `active`: phase 1..=5.
    pub active: Signal<Out, Bit>,
    /// `forcing`: `SRP_FORCE` or `DDSP_FORCE` (the own contribution is dominant).
    pub forcing: Signal<Out, Bit>,
    /// `send` of §9.3 (from registers, with `sub_any`).
    pub send: Signal<Out, Bit>,
    /// The phase acknowledges the twin's frame (`SRP_EXCHANGE`, `NRP`, `DDSP_SEND`).
    pub ack_en: Signal<Out, Bit>,
    /// `!active | forcing`: the transmitter is held silent.
    pub hush: Signal<Out, Bit>,
    /// `quiet_twin` (§9.4): `DDSP_SEND` or `SPLIT`, the sublinks are held recessive.
    pub quiet_twin: Signal<Out, Bit>,
    /// The `NRAP_STATUS` word.
    pub status: Signal<Out, Bits<32>>,
    // ---- events and strobes at this edge (combinational) ----
    /// The phase changes at this edge (`INT_STATUS.nrap`).
    pub ev_phase: Signal<Out, Bit>,
    /// Entry to `DDSP_FORCE`: `decoupled = 1` and `INT_STATUS.decoupled`.
    pub set_decoupled: Signal<Out, Bit>,
    /// Every SAMPLE edge of `SRP_EXCHANGE`.
    pub p_exchange: Signal<Out, Bit>,
    /// Every SAMPLE edge of `NRP` and `DDSP_SEND` inside an identification frame.
    pub p_watch: Signal<Out, Bit>,
    /// `SRP_FORCE` → `SRP_EXCHANGE`, entry to `DDSP_FORCE`: every sublink disabled.
    pub p_off_sub: Signal<Out, Bit>,
    /// Joining (`RUN` → `SRP_EXCHANGE`): every sublink's `rrun` starts at 0.
    pub p_join: Signal<Out, Bit>,
    /// `SRP_EXCHANGE` → `NRP`, `DDSP_FORCE` → `DDSP_SEND`: every node port enabled.
    pub p_enable: Signal<Out, Bit>,
    // ---- registers ----
    /// The counters' increments and comparisons, one clock ahead (structural).
    ahead: NrapAhead,
    nrap_q: DFF<Bits<3>>,
    nt: DFF<Bits<16>>,
    ncnt: DFF<Bits<4>>,
    half: DFF<Bit>,
    last: DFF<Bits<2>>,
    unacked: DFF<Bits<5>>,
    runs: DFF<Bits<4>>,
    outcome: DFF<Bit>,
    // ---- combinational ----
    st_run: Signal<Local, Bit>,
    st_srp_force: Signal<Local, Bit>,
    st_exchange: Signal<Local, Bit>,
    st_nrp: Signal<Local, Bit>,
    st_ddsp_force: Signal<Local, Bit>,
    st_send: Signal<Local, Bit>,
    is_active: Signal<Local, Bit>,
    nt_new: Signal<Local, Bits<16>>,
    ack_own: Signal<Local, Bit>,
    ack_twin: Signal<Local, Bit>,
    ack_a: Signal<Local, Bit>,
    ack_b: Signal<Local, Bit>,
    pairs: Signal<Local, Bit>,
    ackd: Signal<Local, Bit>,
    inc: Signal<Local, Bit>,
    half_new: Signal<Local, Bit>,
    ncnt_new: Signal<Local, Bits<4>>,
    unacked_new: Signal<Local, Bits<5>>,
    go: Signal<Local, Bit>,
    next: Signal<Local, Bits<3>>,
    next_active: Signal<Local, Bit>,
    last_new: Signal<Local, Bits<2>>,
    half_join: Signal<Local, Bit>,
    blocked: Signal<Local, Bit>,
    chg: Signal<Local, Bit>,
    // ---- constants ----
    ph_run: Constant<Bits<3>>,
    ph_srp_force: Constant<Bits<3>>,
    ph_exchange: Constant<Bits<3>>,
    ph_nrp: Constant<Bits<3>>,
    ph_ddsp_force: Constant<Bits<3>>,
    ph_send: Constant<Bits<3>>,
    ph_split: Constant<Bits<3>>,
    is_b: Constant<Bit>,
    last_none: Constant<Bits<2>>,
    last_own: Constant<Bits<2>>,
    last_twin: Constant<Bits<2>>,
    s_nrap: Constant<Bits<5>>,
    s_outcome: Constant<Bits<5>>,
    s_runs: Constant<Bits<5>>,
    s_ncnt: Constant<Bits<5>>,
    s_last: Constant<Bits<5>>,
    s_half: Constant<Bits<5>>,
    s_nt: Constant<Bits<5>>,
    zero5: Constant<Bits<5>>,
    one5: Constant<Bits<5>>,
    max5: Constant<Bits<5>>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    max4: Constant<Bits<4>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
}

impl<const H: usize> Default for Nrap<H> {
    fn default() -> Self {
        assert!(H <= 1, "hub: HUB_ID is 0 (hub A) or 1 (hub B)");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            hold: Default::default(),
            nrap_on: Default::default(),
            force_bits: Default::default(),
            srp_pairs: Default::default(),
            nrp_pairs: Default::default(),
            ddsp_frames: Default::default(),
            srp_bits: Default::default(),
            nrp_bits: Default::default(),
            ddsp_bits: Default::default(),
            block_frames: Default::default(),
            decoupled: Default::default(),
            any_sub_en: Default::default(),
            twin_b: Default::default(),
            sample: Default::default(),
            b: Default::default(),
            at_ack: Default::default(),
            at_delim: Default::default(),
            own_frame: Default::default(),
            twin_frame: Default::default(),
            in_id: Default::default(),
            cmd_run: Default::default(),
            cmd_split: Default::default(),
            phase: Default::default(),
            active: Default::default(),
            forcing: Default::default(),
            send: Default::default(),
            ack_en: Default::default(),
            hush: Default::default(),
            quiet_twin: Default::default(),
            status: Default::default(),
            ev_phase: Default::default(),
            set_decoupled: Default::default(),
            p_exchange: Default::default(),
            p_watch: Default::default(),
            p_off_sub: Default::default(),
            p_join: Default::default(),
            p_enable: Default::default(),
            ahead: Default::default(),
            nrap_q: Default::default(),
            nt: Default::default(),
            ncnt: Default::default(),
            half: Default::default(),
            last: Default::default(),
            unacked: Default::default(),
            runs: Default::default(),
            outcome: Default::default(),
            st_run: Default::default(),
            st_srp_force: Default::default(),
            st_exchange: Default::default(),
            st_nrp: Default::default(),
            st_ddsp_force: Default::default(),
            st_send: Default::default(),
            is_active: Default::default(),
            nt_new: Default::default(),
            ack_own: Default::default(),
            ack_twin: Default::default(),
            ack_a: Default::default(),
            ack_b: Default::default(),
            pairs: Default::default(),
            ackd: Default::default(),
            inc: Default::default(),
            half_new: Default::default(),
            ncnt_new: Default::default(),
            unacked_new: Default::default(),
            go: Default::default(),
            next: Default::default(),
            next_active: Default::default(),
            last_new: Default::default(),
            half_join: Default::default(),
            blocked: Default::default(),
            chg: Default::default(),
            ph_run: phase(NrapPhase::Run),
            ph_srp_force: phase(NrapPhase::SrpForce),
            ph_exchange: phase(NrapPhase::SrpExchange),
            ph_nrp: phase(NrapPhase::Nrp),
            ph_ddsp_force: phase(NrapPhase::DdspForce),
            ph_send: phase(NrapPhase::DdspSend),
            ph_split: phase(NrapPhase::Split),
            is_b: Constant::new(H == 1),
            last_none: Constant::new(0.into()),
            last_own: Constant::new(1.into()),
            last_twin: Constant::new(2.into()),
            s_nrap: lsb(&MAP, "NRAP_STATUS", "nrap", 3),
            s_outcome: lsb(&MAP, "NRAP_STATUS", "outcome", 1),
            s_runs: lsb(&MAP, "NRAP_STATUS", "runs", 4),
            s_ncnt: lsb(&MAP, "NRAP_STATUS", "ncnt", 4),
            s_last: lsb(&MAP, "NRAP_STATUS", "last", 2),
            s_half: lsb(&MAP, "NRAP_STATUS", "half", 1),
            s_nt: lsb(&MAP, "NRAP_STATUS", "nt", 16),
            zero5: Constant::new(0.into()),
            one5: Constant::new(1.into()),
            max5: Constant::new(31.into()),
            zero4: Constant::new(0.into()),
            one4: Constant::new(1.into()),
            max4: Constant::new(15.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            max16: Constant::new(0xFFFF.into()),
        }
    }
}

#[path = "nrap_update.rs"]
mod update;
