//! Guard stage of the hub (hub contract §6.1 "Guard stage", for Fmax on the
//! iCE40UP5K): one register for every input of the port guards, so that the guards
//! apply the rules of §6 (and the NRAP writes of §9.2, the `recouple` command and
//! the reset-mode hold) one clock after the edge the contract decides them at.
//! Without it the path from `coupled_q` through the bit timing's sample decision,
//! the tracker's events and the guard rules to the guard registers is one clock
//! (56 ns on the UP5K). With it the guards are exactly §6's guards run one clock
//! late: every guard register holds, after edge t + 1, the value §6 decides at
//! edge t, and the rest of the hub reads that one-clock-late copy.
//!
//! `rst` is not delayed: the guards reset at the `rst` edge itself, and `hold`
//! resets to 1, so at the next edge they hold again (reset mode follows `rst`).

use rust_hdl::prelude::*;

/// The registered guard inputs for N node ports and M incoming sublinks.
#[derive(LogicBlock)]
pub struct GuardStage<const N: usize, const M: usize> {
    // clock and reset
    /// Clock; every output is a register of it.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of the stage (to the reset-mode hold).
    pub rst: Signal<In, Bit>,
    // the inputs, at the edge §6 decides on
    /// `reset_mode` before the edge (the reset-mode hold of §6).
    pub reset_mode: Signal<In, Bit>,
    /// SAMPLE edge of the hub's bit timing.
    pub sample: Signal<In, Bit>,
    /// `port_q` of the node ports (1 = recessive).
    pub node_q: Signal<In, Bits<N>>,
    /// `port_q` of the incoming sublinks (1 = recessive).
    pub sub_q: Signal<In, Bits<M>>,
    /// `coupled_q`, the sampled bus value `b`.
    pub b: Signal<In, Bit>,
    /// Tracker event `SOF_PORTS` (§5).
    pub ev_sof: Signal<In, Bit>,
    /// Tracker event `FRAME_PORTS` (§5).
    pub ev_frame: Signal<In, Bit>,
    /// The bit is inside the arbitration field (§5).
    pub in_arb: Signal<In, Bit>,
    /// Stuff error on a recessive bit (§6, rule BF).
    pub ev_stuff_rec: Signal<In, Bit>,
    /// Data bit 10 of identifier 0x000/0x001 (§6, rule RID).
    pub ev_rid: Signal<In, Bit>,
    /// Tracker event `ACK_PORTS` (§5).
    pub ev_ack: Signal<In, Bit>,
    /// NRAP is active (§9.2: every guard frozen).
    pub nrap_active: Signal<In, Bit>,
    /// The hub is decoupled (§7: the sublink guards frozen).
    pub decoupled: Signal<In, Bit>,
    /// NRAP strobe `n_watch` for the node ports (§9.2).
    pub p_watch: Signal<In, Bit>,
    /// NRAP strobe `n_enable` for the node ports (§9.2).
    pub p_enable: Signal<In, Bit>,
    /// NRAP strobe `n_rrun` for the sublinks (§9.2).
    pub p_exchange: Signal<In, Bit>,
    /// NRAP strobe `n_off` for the sublinks (§9.2).
    pub p_off_sub: Signal<In, Bit>,
    /// NRAP strobe `n_clr` for the sublinks (§9.2).
    pub p_join: Signal<In, Bit>,
    /// Host command `CTRL.recouple` (§8).
    pub recouple: Signal<In, Bit>,
    // the same, one clock late
    /// `reset_mode` one clock late: with `rst`, the guards' hold.
    pub hold_d: Signal<Out, Bit>,
    /// `sample` one clock late.
    pub sample_d: Signal<Out, Bit>,
    /// `node_q` one clock late.
    pub node_q_d: Signal<Out, Bits<N>>,
    /// `sub_q` one clock late.
    pub sub_q_d: Signal<Out, Bits<M>>,
    /// `b` one clock late.
    pub b_d: Signal<Out, Bit>,
    /// `ev_sof` one clock late.
    pub ev_sof_d: Signal<Out, Bit>,
    /// `ev_frame` one clock late.
    pub ev_frame_d: Signal<Out, Bit>,
    /// `in_arb` one clock late.
    pub in_arb_d: Signal<Out, Bit>,
    /// `ev_stuff_rec` one clock late.
    pub ev_stuff_rec_d: Signal<Out, Bit>,
    /// `ev_rid` one clock late.
    pub ev_rid_d: Signal<Out, Bit>,
    /// `ev_ack` one clock late.
    pub ev_ack_d: Signal<Out, Bit>,
    /// Freeze of the node guards one clock late (`nrap_active`).
    pub node_freeze_d: Signal<Out, Bit>,
    /// Freeze of the sublink guards one clock late (`decoupled | nrap_active`).
    pub sub_freeze_d: Signal<Out, Bit>,
    /// `p_watch` one clock late.
    pub p_watch_d: Signal<Out, Bit>,
    /// `p_enable` one clock late.
    pub p_enable_d: Signal<Out, Bit>,
    /// `p_exchange` one clock late.
    pub p_exchange_d: Signal<Out, Bit>,
    /// `p_off_sub` one clock late.
    pub p_off_sub_d: Signal<Out, Bit>,
    /// `p_join` one clock late.
    pub p_join_d: Signal<Out, Bit>,
    /// `recouple` one clock late.
    pub recouple_d: Signal<Out, Bit>,
    // registers
    hold_q: DFF<Bit>,
    sample_q: DFF<Bit>,
    node_q_q: DFF<Bits<N>>,
    sub_q_q: DFF<Bits<M>>,
    b_q: DFF<Bit>,
    ev_sof_q: DFF<Bit>,
    ev_frame_q: DFF<Bit>,
    in_arb_q: DFF<Bit>,
    ev_stuff_rec_q: DFF<Bit>,
    ev_rid_q: DFF<Bit>,
    ev_ack_q: DFF<Bit>,
    node_freeze_q: DFF<Bit>,
    sub_freeze_q: DFF<Bit>,
    p_watch_q: DFF<Bit>,
    p_enable_q: DFF<Bit>,
    p_exchange_q: DFF<Bit>,
    p_off_sub_q: DFF<Bit>,
    p_join_q: DFF<Bit>,
    recouple_q: DFF<Bit>,
    ones_n: Constant<Bits<N>>,
    ones_m: Constant<Bits<M>>,
}

impl<const N: usize, const M: usize> Default for GuardStage<N, M> {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            reset_mode: Default::default(),
            sample: Default::default(),
            node_q: Default::default(),
            sub_q: Default::default(),
            b: Default::default(),
            ev_sof: Default::default(),
            ev_frame: Default::default(),
            in_arb: Default::default(),
            ev_stuff_rec: Default::default(),
            ev_rid: Default::default(),
            ev_ack: Default::default(),
            nrap_active: Default::default(),
            decoupled: Default::default(),
            p_watch: Default::default(),
            p_enable: Default::default(),
            p_exchange: Default::default(),
            p_off_sub: Default::default(),
            p_join: Default::default(),
            recouple: Default::default(),
            hold_d: Default::default(),
            sample_d: Default::default(),
            node_q_d: Default::default(),
            sub_q_d: Default::default(),
            b_d: Default::default(),
            ev_sof_d: Default::default(),
            ev_frame_d: Default::default(),
            in_arb_d: Default::default(),
            ev_stuff_rec_d: Default::default(),
            ev_rid_d: Default::default(),
            ev_ack_d: Default::default(),
            node_freeze_d: Default::default(),
            sub_freeze_d: Default::default(),
            p_watch_d: Default::default(),
            p_enable_d: Default::default(),
            p_exchange_d: Default::default(),
            p_off_sub_d: Default::default(),
            p_join_d: Default::default(),
            recouple_d: Default::default(),
            hold_q: Default::default(),
            sample_q: Default::default(),
            node_q_q: Default::default(),
            sub_q_q: Default::default(),
            b_q: Default::default(),
            ev_sof_q: Default::default(),
            ev_frame_q: Default::default(),
            in_arb_q: Default::default(),
            ev_stuff_rec_q: Default::default(),
            ev_rid_q: Default::default(),
            ev_ack_q: Default::default(),
            node_freeze_q: Default::default(),
            sub_freeze_q: Default::default(),
            p_watch_q: Default::default(),
            p_enable_q: Default::default(),
            p_exchange_q: Default::default(),
            p_off_sub_q: Default::default(),
            p_join_q: Default::default(),
            recouple_q: Default::default(),
            ones_n: Constant::new(Bits::<N>::mask()),
            ones_m: Constant::new(Bits::<M>::mask()),
        }
    }
}

impl<const N: usize, const M: usize> Logic for GuardStage<N, M> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            hold_q,
            sample_q,
            node_q_q,
            sub_q_q,
            b_q,
            ev_sof_q,
            ev_frame_q,
            in_arb_q,
            ev_stuff_rec_q,
            ev_rid_q,
            ev_ack_q,
            node_freeze_q,
            sub_freeze_q,
            p_watch_q,
            p_enable_q,
            p_exchange_q,
            p_off_sub_q,
            p_join_q,
            recouple_q
        );
        // §6.1: every guard input, one clock late
        self.hold_q.d.next = self.reset_mode.val();
        self.sample_q.d.next = self.sample.val();
        self.node_q_q.d.next = self.node_q.val();
        self.sub_q_q.d.next = self.sub_q.val();
        self.b_q.d.next = self.b.val();
        self.ev_sof_q.d.next = self.ev_sof.val();
        self.ev_frame_q.d.next = self.ev_frame.val();
        self.in_arb_q.d.next = self.in_arb.val();
        self.ev_stuff_rec_q.d.next = self.ev_stuff_rec.val();
        self.ev_rid_q.d.next = self.ev_rid.val();
        self.ev_ack_q.d.next = self.ev_ack.val();
        self.node_freeze_q.d.next = self.nrap_active.val();
        self.sub_freeze_q.d.next = self.decoupled.val() | self.nrap_active.val();
        self.p_watch_q.d.next = self.p_watch.val();
        self.p_enable_q.d.next = self.p_enable.val();
        self.p_exchange_q.d.next = self.p_exchange.val();
        self.p_off_sub_q.d.next = self.p_off_sub.val();
        self.p_join_q.d.next = self.p_join.val();
        self.recouple_q.d.next = self.recouple.val();
        if self.rst.val() {
            // the guards reset at the `rst` edge; at the next one they hold
            self.hold_q.d.next = true;
            self.sample_q.d.next = false;
            self.node_q_q.d.next = self.ones_n.val();
            self.sub_q_q.d.next = self.ones_m.val();
            self.b_q.d.next = true;
            self.ev_sof_q.d.next = false;
            self.ev_frame_q.d.next = false;
            self.in_arb_q.d.next = false;
            self.ev_stuff_rec_q.d.next = false;
            self.ev_rid_q.d.next = false;
            self.ev_ack_q.d.next = false;
            self.node_freeze_q.d.next = false;
            self.sub_freeze_q.d.next = false;
            self.p_watch_q.d.next = false;
            self.p_enable_q.d.next = false;
            self.p_exchange_q.d.next = false;
            self.p_off_sub_q.d.next = false;
            self.p_join_q.d.next = false;
            self.recouple_q.d.next = false;
        }
        self.hold_d.next = self.hold_q.q.val();
        self.sample_d.next = self.sample_q.q.val();
        self.node_q_d.next = self.node_q_q.q.val();
        self.sub_q_d.next = self.sub_q_q.q.val();
        self.b_d.next = self.b_q.q.val();
        self.ev_sof_d.next = self.ev_sof_q.q.val();
        self.ev_frame_d.next = self.ev_frame_q.q.val();
        self.in_arb_d.next = self.in_arb_q.q.val();
        self.ev_stuff_rec_d.next = self.ev_stuff_rec_q.q.val();
        self.ev_rid_d.next = self.ev_rid_q.q.val();
        self.ev_ack_d.next = self.ev_ack_q.q.val();
        self.node_freeze_d.next = self.node_freeze_q.q.val();
        self.sub_freeze_d.next = self.sub_freeze_q.q.val();
        self.p_watch_d.next = self.p_watch_q.q.val();
        self.p_enable_d.next = self.p_enable_q.q.val();
        self.p_exchange_d.next = self.p_exchange_q.q.val();
        self.p_off_sub_d.next = self.p_off_sub_q.q.val();
        self.p_join_d.next = self.p_join_q.q.val();
        self.recouple_d.next = self.recouple_q.q.val();
    }
}
