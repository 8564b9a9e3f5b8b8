//! ACK unit of the hub (ReCANcentrate paper section 4: the bus guardian that keeps
//! a faulty hub from breaking ACK interdependence; hub contract §4.1). A block with
//! state of its own: its own two-flip-flop input synchronizers (`u_s1`, `u_in_s`),
//! its own copy of the coupled bus (`u_view_q`), a second instance of the channel's
//! bit timing logic and of the hub's frame tracker (state only: the tracker's guard
//! events and statistics stay unconnected), and the `downlink` output register.
//!
//! From the hub it reads only the configuration (the captured bit timing, the same
//! capture as the hub's BTL, and `ack_interdep`), the `enabled` mask, `decoupled`
//! and NRAP's `tx_q & !forcing` (registers, values before the edge) and `dl_next`,
//! the value the coupler would put on the downlinks (`super::coupler`). Rules
//! (§4.1, as of commit 753312e):
//!
//! ```text
//! u_s1 <= pins ; u_in_s <= u_s1                                  // reset 1
//! u_own  = AND over node ports    of (u_in_s | !enabled) & tx_q & !forcing  // §9.4
//! u_twin = AND over sublink ports of (u_in_s | !enabled)         // empty AND = 1
//! u_view_q <= decoupled ? u_own : u_own & u_twin                 // reset 1
//! u_window = (u_trk == ACK_SLOT) | (u_trk == ACK_DELIM)
//! guard    = u_window & ack_interdep & !decoupled
//! downlink <= guard ? (dl_next | u_twin) : dl_next               // reset 1
//! ```
//!
//! - *Interventions*: at an edge where `guard & !dl_next & u_twin & !u_blocked`:
//!   `blocks += 1` (saturating), `u_blocked <= 1` and the `INT_STATUS.ack_unit`
//!   event; `u_blocked <= 0` at every edge where `!u_window`.
//! - *Reset mode*: the tracker is held at edges where `reset_mode` is 1 and the BTL
//!   while `reset_mode | reset_mode_q`, exactly as the hub's (§5; the hub hands in
//!   `trk_rst` and `btl_rst`); `u_blocked` is held at 0 with the tracker; `blocks`
//!   keeps its value (it clears with `rst` only). The synchronizers, `u_view_q` and
//!   `downlink` run in reset mode too.
//!
//! NRAP (§4.1, §9.4): the hub's own transmitter is part of the hub's contribution,
//! so `u_own` takes `tx_q & !forcing` as the coupler does; the unit's view carries
//! the identification frames, its tracker follows them, and it guards during NRAP
//! too. (§9.2 still says the unit is transparent while NRAP is active, `guard`
//! with `& !active`; §4.1's rule, the later change, is the one built.)
//!
//! In a correct hub the unit changes nothing: `u_view_q` equals `coupled_q` at
//! every clock, so `u_window` equals `ack_window`, and inside it `dl_next` already
//! is `twin = u_twin`.

use super::tracker::{FrameTracker, ACK_DELIM, ACK_SLOT, IDLE_WAIT};
use crate::channel::btl::BitTimingLogic;
use crate::channel::BRP_BITS;
use crate::pins::RecessiveReg;
use rust_hdl::prelude::*;

/// The ACK unit of a hub with N node ports, M interlinks and P = N + M ports.
#[derive(LogicBlock)]
pub struct AckUnit<const N: usize, const M: usize, const P: usize> {
    // ---- clock and resets ----
    /// Clock.
    pub clk: Signal<In, Clock>,
    /// The hub's synchronous reset: synchronizers, `u_view_q` and `downlink` to 1
    /// (recessive), `blocks` and `u_blocked` to 0.
    pub rst: Signal<In, Bit>,
    /// `rst | reset_mode` (value before the edge): holds the tracker at
    /// `IDLE_WAIT` and `u_blocked` at 0 (§4.1 reset mode).
    pub trk_rst: Signal<In, Bit>,
    /// `rst | reset_mode | reset_mode_q`: holds the BTL in reset (§5).
    pub btl_rst: Signal<In, Bit>,
    // ---- pins (1 = recessive) ----
    /// Node transmit values, bit i = node port i (the hub's `uplink` pins).
    pub uplink: Signal<In, Bits<N>>,
    /// The twin hub's contribution, bit j = interlink j (the hub's `sublink_in`).
    pub sublink_in: Signal<In, Bits<M>>,
    /// The downlink output register (§4.1 `downlink`): every bit carries the same
    /// value.
    pub downlink: Signal<Out, Bits<N>>,
    // ---- from the hub: configuration (the hub's captured bit timing, §5) ----
    /// Captured BRP, as the hub's BTL gets it (`ChannelConfig::brp_next`).
    pub cfg_brp_next: Signal<In, Bits<BRP_BITS>>,
    /// Captured TSEG1' in time quanta.
    pub cfg_tseg1_len: Signal<In, Bits<5>>,
    /// Captured TSEG2 in time quanta.
    pub cfg_tseg2_len: Signal<In, Bits<4>>,
    /// Captured SJW' in time quanta.
    pub cfg_sjw_len: Signal<In, Bits<4>>,
    /// `CTRL.ack_interdep`.
    pub ack_interdep: Signal<In, Bit>,
    // ---- from the hub: state (registers, values before the edge) ----
    /// Enabled ports, bit p = port p (node ports 0..N, then the sublinks).
    pub enabled: Signal<In, Bits<P>>,
    /// The hub is decoupled (§7).
    pub decoupled: Signal<In, Bit>,
    /// NRAP's transmitter as part of the own contribution (§9.4): `tx_q &
    /// !forcing` (registers), 0 = dominant.
    pub own_gate: Signal<In, Bit>,
    /// The coupler's next downlink value (§3's right-hand side), combinational.
    pub dl_next: Signal<In, Bit>,
    // ---- to the register block (§8 `ACK_UNIT`, `INT_STATUS.ack_unit`) ----
    /// `ACK_UNIT.blocks`: ACK windows in which the unit intervened (saturating).
    pub blocks: Signal<Out, Bits<16>>,
    /// `ACK_UNIT.u_window`: the unit's tracker is in the ACK slot or delimiter.
    pub u_window: Signal<Out, Bit>,
    /// The unit intervenes for the first time in this window at this edge (the
    /// `INT_STATUS.ack_unit` event), combinational.
    pub ev_block: Signal<Out, Bit>,
    // ---- blocks: the unit's own bit timing and frame tracker ----
    u_btl: BitTimingLogic,
    u_trk: FrameTracker,
    // ---- registers ----
    u_s1: DFF<Bits<P>>,
    u_in_s: DFF<Bits<P>>,
    u_view_q: DFF<Bit>,
    /// The downlinks' register: recessive from configuration on.
    downlink_q: RecessiveReg<Bits<N>>,
    blocks_q: DFF<Bits<16>>,
    u_blocked: DFF<Bit>,
    // ---- combinational ----
    pins: Signal<Local, Bits<P>>,
    contrib: Signal<Local, Bits<P>>,
    u_own: Signal<Local, Bit>,
    u_twin: Signal<Local, Bit>,
    u_win: Signal<Local, Bit>,
    guard: Signal<Local, Bit>,
    intervene: Signal<Local, Bit>,
    // ---- constants ----
    node_mask: Constant<Bits<P>>,
    sub_mask: Constant<Bits<P>>,
    shift_n: Constant<Bits<4>>,
    ones_n: Constant<Bits<N>>,
    zero_n: Constant<Bits<N>>,
    ones_p: Constant<Bits<P>>,
    s_idle: Constant<Bits<2>>,
    s_ack: Constant<Bits<2>>,
    s_delim: Constant<Bits<2>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
}

impl<const N: usize, const M: usize, const P: usize> Default for AckUnit<N, M, P> {
    fn default() -> Self {
        assert_eq!(P, N + M, "ack unit: P must be N + M");
        let node_mask = (1u64 << N) - 1;
        let port_mask = (1u64 << P) - 1;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            trk_rst: Default::default(),
            btl_rst: Default::default(),
            uplink: Default::default(),
            sublink_in: Default::default(),
            downlink: Default::default(),
            cfg_brp_next: Default::default(),
            cfg_tseg1_len: Default::default(),
            cfg_tseg2_len: Default::default(),
            cfg_sjw_len: Default::default(),
            ack_interdep: Default::default(),
            enabled: Default::default(),
            decoupled: Default::default(),
            own_gate: Default::default(),
            dl_next: Default::default(),
            blocks: Default::default(),
            u_window: Default::default(),
            ev_block: Default::default(),
            u_btl: Default::default(),
            u_trk: Default::default(),
            u_s1: Default::default(),
            u_in_s: Default::default(),
            u_view_q: Default::default(),
            downlink_q: Default::default(),
            blocks_q: Default::default(),
            u_blocked: Default::default(),
            pins: Default::default(),
            contrib: Default::default(),
            u_own: Default::default(),
            u_twin: Default::default(),
            u_win: Default::default(),
            guard: Default::default(),
            intervene: Default::default(),
            node_mask: Constant::new(node_mask.into()),
            sub_mask: Constant::new((port_mask & !node_mask).into()),
            shift_n: Constant::new((N as u64).into()),
            ones_n: Constant::new(Bits::<N>::mask()),
            zero_n: Constant::new(0.into()),
            ones_p: Constant::new(Bits::<P>::mask()),
            s_idle: Constant::new(IDLE_WAIT.into()),
            s_ack: Constant::new(ACK_SLOT.into()),
            s_delim: Constant::new(ACK_DELIM.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            max16: Constant::new(0xFFFF.into()),
        }
    }
}

impl<const N: usize, const M: usize, const P: usize> Logic for AckUnit<N, M, P> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, u_s1, u_in_s, u_view_q, downlink_q, blocks_q, u_blocked);
        // §4.1 synchronizers: u_s1 <= pins ; u_in_s <= u_s1 (bit p = port p)
        self.pins.next = bit_cast::<P, N>(self.uplink.val())
            | (bit_cast::<P, M>(self.sublink_in.val()) << self.shift_n.val());
        self.u_s1.d.next = self.pins.val();
        self.u_in_s.d.next = self.u_s1.q.val();
        // §4.1 u_own / u_twin: isolated ports are recessive; the other group's
        // bits are forced to 1 so that `all` is the AND over one group
        self.contrib.next = self.u_in_s.q.val() | !self.enabled.val();
        self.u_own.next = (self.contrib.val() | self.sub_mask.val()).all() & self.own_gate.val();
        self.u_twin.next = (self.contrib.val() | self.node_mask.val()).all();
        // §4.1 u_view_q: the unit's own copy of the coupled bus
        if self.decoupled.val() {
            self.u_view_q.d.next = self.u_own.val();
        } else {
            self.u_view_q.d.next = self.u_own.val() & self.u_twin.val();
        }

        // §4.1 u_window and guard, from the unit's registered tracker state
        self.u_win.next = (self.u_trk.trk.val() == self.s_ack.val())
            | (self.u_trk.trk.val() == self.s_delim.val());
        self.guard.next = self.u_win.val() & self.ack_interdep.val() & !self.decoupled.val();
        // §4.1 downlink: inside the guard a dominant bit needs a dominant twin
        if self.dl_next.val() | (self.guard.val() & self.u_twin.val()) {
            self.downlink_q.d.next = self.ones_n.val();
        } else {
            self.downlink_q.d.next = self.zero_n.val();
        }

        // §4.1 interventions: counted once per ACK window
        self.intervene.next =
            self.guard.val() & !self.dl_next.val() & self.u_twin.val() & !self.u_blocked.q.val();
        if self.intervene.val() {
            if self.blocks_q.q.val() != self.max16.val() {
                self.blocks_q.d.next = self.blocks_q.q.val() + self.one16.val();
            }
            self.u_blocked.d.next = true;
        }
        if !self.u_win.val() {
            self.u_blocked.d.next = false;
        }
        // §4.1 reset mode: u_blocked is held at 0 with the tracker
        if self.trk_rst.val() {
            self.u_blocked.d.next = false;
        }

        // §4.1 / §5: the unit's own BTL on u_view_q, configured and held in reset
        // exactly as the hub's (tx = 1, triple = 0, hard sync in IDLE_WAIT)
        self.u_btl.clk.next = self.clk.val();
        self.u_btl.rst.next = self.btl_rst.val();
        self.u_btl.cfg_brp_next.next = self.cfg_brp_next.val();
        self.u_btl.cfg_tseg1_len.next = self.cfg_tseg1_len.val();
        self.u_btl.cfg_tseg2_len.next = self.cfg_tseg2_len.val();
        self.u_btl.cfg_sjw_len.next = self.cfg_sjw_len.val();
        self.u_btl.cfg_triple.next = false;
        self.u_btl.rx_s.next = self.u_view_q.q.val();
        self.u_btl.tx.next = true;
        self.u_btl.hard_sync_enable.next = self.u_trk.trk.val() == self.s_idle.val();
        // §4.1 / §5: the unit's own tracker at the SAMPLE edges of its BTL
        self.u_trk.clk.next = self.clk.val();
        self.u_trk.rst.next = self.trk_rst.val();
        self.u_trk.sample.next = self.u_btl.sample.val();
        self.u_trk.b.next = self.u_view_q.q.val();

        if self.rst.val() {
            self.u_s1.d.next = self.ones_p.val();
            self.u_in_s.d.next = self.ones_p.val();
            self.u_view_q.d.next = true;
            self.downlink_q.d.next = self.ones_n.val();
            self.blocks_q.d.next = self.zero16.val();
            self.u_blocked.d.next = false;
        }

        // ---- outputs ----
        self.downlink.next = self.downlink_q.q.val();
        self.blocks.next = self.blocks_q.q.val();
        self.u_window.next = self.u_win.val();
        self.ev_block.next = self.intervene.val();
    }
}
