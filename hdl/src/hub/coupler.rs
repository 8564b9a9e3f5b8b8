//! Coupler of the hub (ReCANcentrate paper section 2 "two-stage AND coupling",
//! section 4 "ACK interdependence"; hub contract §2, §3, §4): the two-flip-flop
//! synchronizer and the judged copy `port_q` of every port, stage 1 (the hub's own
//! contribution: AND of the enabled node ports and of the NRAP transmitter, §9.4:
//! `tx_q & !forcing`), stage 2 (AND with the twin hub's
//! contribution: the enabled incoming sublinks, unless decoupled), the registered
//! outputs `coupled_q` and `sublink_out`, and `dl_next`: the value the coupler
//! would put on the downlinks (the right-hand side of §3's `downlink <=`: only the
//! twin's contribution inside the ACK window under ACK interdependence). The
//! downlink register itself belongs to the ACK unit (§4.1, `super::ack_unit`),
//! which may only make that value recessive. Fault injection `CTRL.fi_ack_leak`
//! (§4.1): the coupler ignores ACK interdependence (`dl_next = view` inside the
//! window too); `CTRL.fi_no_twin` (§9.6): the twin's contribution is taken as
//! recessive (`twin = 1`). A hub that decided on definitive decoupling (NRAP
//! `DDSP_SEND` or `SPLIT`, `quiet_twin`, §9.4) keeps `sublink_out` recessive.
//! Every register resets to 1 (recessive); an empty AND is 1.

use crate::pins::RecessiveReg;
use rust_hdl::prelude::*;

/// Synchronizers and two-stage AND coupling for N node ports and M interlinks.
#[derive(LogicBlock)]
pub struct Coupler<const N: usize, const M: usize> {
    // clock and reset
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register to 1 (recessive).
    pub rst: Signal<In, Bit>,
    // pins (1 = recessive)
    /// Node transmit values, bit i = node port i (the hub's `uplink` pins).
    pub uplink: Signal<In, Bits<N>>,
    /// The twin hub's contribution, bit j = interlink j (the hub's `sublink_in` pins).
    pub sublink_in: Signal<In, Bits<M>>,
    /// This hub's own contribution (stage 1) to the twin, on every interlink; registered, recessive
    /// while `quiet_twin`.
    pub sublink_out: Signal<Out, Bits<M>>,
    // control (registered values of the guards and the register block)
    /// Enabled node ports, bit i = node port i: a disabled port counts as recessive.
    pub node_en: Signal<In, Bits<N>>,
    /// Enabled sublinks, bit j = interlink j: a disabled one counts as recessive.
    pub sub_en: Signal<In, Bits<M>>,
    /// The hub is decoupled (§7): stage 2 leaves out the twin's contribution.
    pub decoupled: Signal<In, Bit>,
    /// The hub's own transmitter in stage 1, `tx_q & !forcing` (§9.4; registers),
    /// 1 = recessive.
    pub tx_own: Signal<In, Bit>,
    /// `ack_window & ack_interdep & !decoupled` (§3).
    pub ack_mask: Signal<In, Bit>,
    /// `CTRL.fi_ack_leak` (§4.1 fault injection): ignore `ack_mask`.
    pub fi_ack_leak: Signal<In, Bit>,
    /// `CTRL.fi_no_twin` (§9.6 fault injection): `twin = 1`.
    pub fi_no_twin: Signal<In, Bit>,
    /// `quiet_twin` (§9.4): `sublink_out <= 1`.
    pub quiet_twin: Signal<In, Bit>,
    // to the ACK unit (§4.1): the next downlink value, combinational
    /// `(ack_mask & !fi_ack_leak) ? twin : view`, 1 = recessive.
    pub dl_next: Signal<Out, Bit>,
    // to the tracker and the guards
    /// `coupled_q`: the registered stage-2 AND, the bus value the hub judges, 1 = recessive.
    pub coupled: Signal<Out, Bit>,
    /// `port_q` of the node ports, bit i = node port i: each uplink after its synchronizer (§2).
    pub node_q: Signal<Out, Bits<N>>,
    /// `port_q` of the sublinks, bit j = interlink j.
    pub sub_q: Signal<Out, Bits<M>>,
    // synchronizers (§2)
    node_s1: DFF<Bits<N>>,
    node_s: DFF<Bits<N>>,
    node_pq: DFF<Bits<N>>,
    sub_s1: DFF<Bits<M>>,
    sub_s: DFF<Bits<M>>,
    sub_pq: DFF<Bits<M>>,
    // outputs (§3)
    coupled_q: DFF<Bit>,
    /// The sublinks' register: recessive from configuration on.
    sub_out_q: RecessiveReg<Bits<M>>,
    // stage 1 / stage 2
    own: Signal<Local, Bit>,
    twin: Signal<Local, Bit>,
    view: Signal<Local, Bit>,
    ones_n: Constant<Bits<N>>,
    ones_m: Constant<Bits<M>>,
    zero_m: Constant<Bits<M>>,
}

impl<const N: usize, const M: usize> Default for Coupler<N, M> {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            uplink: Default::default(),
            sublink_in: Default::default(),
            sublink_out: Default::default(),
            node_en: Default::default(),
            sub_en: Default::default(),
            decoupled: Default::default(),
            tx_own: Default::default(),
            ack_mask: Default::default(),
            fi_ack_leak: Default::default(),
            fi_no_twin: Default::default(),
            quiet_twin: Default::default(),
            dl_next: Default::default(),
            coupled: Default::default(),
            node_q: Default::default(),
            sub_q: Default::default(),
            node_s1: Default::default(),
            node_s: Default::default(),
            node_pq: Default::default(),
            sub_s1: Default::default(),
            sub_s: Default::default(),
            sub_pq: Default::default(),
            coupled_q: Default::default(),
            sub_out_q: Default::default(),
            own: Default::default(),
            twin: Default::default(),
            view: Default::default(),
            ones_n: Constant::new(Bits::<N>::mask()),
            ones_m: Constant::new(Bits::<M>::mask()),
            zero_m: Constant::new(0.into()),
        }
    }
}

impl<const N: usize, const M: usize> Logic for Coupler<N, M> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, node_s1, node_s, node_pq, sub_s1, sub_s, sub_pq, coupled_q, sub_out_q
        );
        // §2: s1 <= pin ; in_s <= s1 ; port_q <= in_s
        self.node_s1.d.next = self.uplink.val();
        self.node_s.d.next = self.node_s1.q.val();
        self.node_pq.d.next = self.node_s.q.val();
        self.sub_s1.d.next = self.sublink_in.val();
        self.sub_s.d.next = self.sub_s1.q.val();
        self.sub_pq.d.next = self.sub_s.q.val();
        // §3 stage 1 (own, with the NRAP transmitter, §9.4) and the twin's
        // contribution: isolated ports are recessive
        self.own.next = (self.node_s.q.val() | !self.node_en.val()).all() & self.tx_own.val();
        self.twin.next = (self.sub_s.q.val() | !self.sub_en.val()).all() | self.fi_no_twin.val();
        // §3 stage 2
        if self.decoupled.val() {
            self.view.next = self.own.val();
        } else {
            self.view.next = self.own.val() & self.twin.val();
        }
        self.coupled_q.d.next = self.view.val();
        if self.own.val() | self.quiet_twin.val() {
            self.sub_out_q.d.next = self.ones_m.val();
        } else {
            self.sub_out_q.d.next = self.zero_m.val();
        }
        // §4: inside the ACK window only the twin's contribution reaches the nodes;
        // §4.1 fault injection: fi_ack_leak passes the view there too
        if self.ack_mask.val() & !self.fi_ack_leak.val() {
            self.dl_next.next = self.twin.val();
        } else {
            self.dl_next.next = self.view.val();
        }
        if self.rst.val() {
            self.node_s1.d.next = self.ones_n.val();
            self.node_s.d.next = self.ones_n.val();
            self.node_pq.d.next = self.ones_n.val();
            self.sub_s1.d.next = self.ones_m.val();
            self.sub_s.d.next = self.ones_m.val();
            self.sub_pq.d.next = self.ones_m.val();
            self.coupled_q.d.next = true;
            self.sub_out_q.d.next = self.ones_m.val();
        }
        self.coupled.next = self.coupled_q.q.val();
        self.sublink_out.next = self.sub_out_q.q.val();
        self.node_q.next = self.node_pq.q.val();
        self.sub_q.next = self.sub_pq.q.val();
    }
}
