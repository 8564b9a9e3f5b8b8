//! Input synchronizers and the two-stage AND coupling (hub contract §2 and §3), with
//! the ACK interdependence mask on the downlinks (§4, paper sections 2 and 4).
//!
//! Ports are packed into one integer: bit p is port p, node ports (uplinks) are bits
//! `0..N`, incoming sublinks bits `N..N+M`; 1 = recessive. Every value here is a
//! register (reset 1) computed at an edge from the values before it:
//!
//! ```text
//! s1 <= pin ; in_s <= s1 ; port_q <= in_s
//! own  = AND over node ports    of (in_s | !enabled) & tx_q & !forcing   (§9.4)
//! twin = AND over sublink ports of (in_s | !enabled) | fi_no_twin     (empty AND = 1)
//! view = decoupled ? own : own & twin
//! coupled_q <= view ; sublink_out <= quiet_twin ? 1 : own               (§9.4)
//! dl_next    = (ack_window & ack_interdep & !decoupled & !fi_ack_leak) ? twin : view
//! ```
//!
//! `dl_next` goes to the ACK unit (§4.1), which owns the downlink register.

/// What the coupling takes at an edge (values before it).
#[derive(Clone, Copy, Debug)]
pub struct CouplingInputs {
    /// The port inputs (bit p = port p).
    pub pins: u16,
    /// The enabled mask.
    pub enabled: u16,
    /// `tx_q & !forcing` (§9.4).
    pub own_gate: bool,
    /// The hub says nothing to its twin (§9.4).
    pub quiet_twin: bool,
    /// `CTRL.fi_no_twin` (§9.6).
    pub no_twin: bool,
    pub decoupled: bool,
    /// `ack_window & ack_interdep & !decoupled & !fi_ack_leak`.
    pub mask_ack: bool,
}

/// Synchronizer stages, the guards' port register and the coupling outputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Coupling {
    /// First synchronizer stage, one bit per port.
    pub s1: u16,
    /// Second synchronizer stage (`in_s`), what the coupling ANDs.
    pub in_s: u16,
    /// `port_q`: `in_s` one edge later, what the guards judge (same age as
    /// `coupled_q`).
    pub port_q: u16,
    /// `coupled_q`: the bus as this hub sees it (tracked by the BTL).
    pub coupled_q: bool,
    /// The value on every outgoing sublink (this hub's own contribution).
    pub sublink_out: bool,
}

impl Default for Coupling {
    fn default() -> Self {
        Self::new()
    }
}

impl Coupling {
    /// Reset state: everything recessive.
    pub fn new() -> Self {
        Coupling {
            s1: u16::MAX,
            in_s: u16::MAX,
            port_q: u16::MAX,
            coupled_q: true,
            sublink_out: true,
        }
    }

    /// One edge on `i` (registers before the edge); `node_mask` / `sub_mask`
    /// select the node and sublink ports. Returns `dl_next`.
    #[inline]
    pub fn edge(&mut self, i: &CouplingInputs, node_mask: u16, sub_mask: u16) -> bool {
        let CouplingInputs {
            pins,
            enabled,
            own_gate,
            quiet_twin,
            no_twin,
            decoupled,
            mask_ack,
        } = *i;
        let contrib = self.in_s | !enabled;
        let own = contrib & node_mask == node_mask && own_gate;
        let twin = contrib & sub_mask == sub_mask || no_twin;
        let view = if decoupled { own } else { own & twin };
        self.coupled_q = view;
        self.sublink_out = own || quiet_twin;
        self.port_q = self.in_s;
        self.in_s = self.s1;
        self.s1 = pins;
        if mask_ack {
            twin
        } else {
            view
        }
    }
}
