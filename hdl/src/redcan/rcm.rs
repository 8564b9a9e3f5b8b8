//! The REDCAN relay module (RCM), ring contract §2: the host's two control bits
//! (connect left, connect right), the refusal of the illegal combination `00`, and
//! the decode of the mode in force to the relay, transceiver and termination
//! drivers. Transparent (relay closed, no termination) after reset: the paper's
//! default mode (Fig. 5) and a relay's rest position.

use rust_hdl::prelude::*;

/// The relay module.
#[derive(LogicBlock)]
pub struct Rcm {
    // ---- clock ----
    /// The clock of the module.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset, active high: transparent, `illegal` and `changes` cleared.
    pub rst: Signal<In, Bit>,
    // ---- host ----
    /// One-clock write strobe for `ctl`.
    pub ctl_we: Signal<In, Bit>,
    /// Requested mode: bit 0 connect left, bit 1 connect right; `11` transparent,
    /// `00` illegal (refused: the mode holds and `illegal` rises).
    pub ctl: Signal<In, Bits<2>>,
    // ---- relay and termination drivers ----
    /// 1 = relay closed: the left and right sections are joined.
    pub relay: Signal<Out, Bit>,
    /// 1 = the node's transceiver is on the left section.
    pub node_left: Signal<Out, Bit>,
    /// 1 = the node's transceiver is on the right section.
    pub node_right: Signal<Out, Bit>,
    /// 1 = a termination on the left section's end (whenever the relay is open).
    pub term_left: Signal<Out, Bit>,
    /// 1 = a termination on the right section's end (whenever the relay is open).
    pub term_right: Signal<Out, Bit>,
    // ---- status ----
    /// The mode in force: 3 transparent, 1 connect left, 2 connect right.
    pub mode: Signal<Out, Bits<2>>,
    /// The last write asked for `00` and was refused.
    pub illegal: Signal<Out, Bit>,
    /// Mode changes since reset, wrapping at 256.
    pub changes: Signal<Out, Bits<8>>,
    mode_q: DFF<Bits<2>>,
    illegal_q: DFF<Bit>,
    changes_q: DFF<Bits<8>>,
    transparent: Constant<Bits<2>>,
    none: Constant<Bits<2>>,
    one8: Constant<Bits<8>>,
    zero8: Constant<Bits<8>>,
}

impl Default for Rcm {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            ctl_we: Default::default(),
            ctl: Default::default(),
            relay: Default::default(),
            node_left: Default::default(),
            node_right: Default::default(),
            term_left: Default::default(),
            term_right: Default::default(),
            mode: Default::default(),
            illegal: Default::default(),
            changes: Default::default(),
            mode_q: Default::default(),
            illegal_q: Default::default(),
            changes_q: Default::default(),
            transparent: Constant::new(3.into()),
            none: Constant::new(0.into()),
            one8: Constant::new(1.into()),
            zero8: Constant::new(0.into()),
        }
    }
}

impl Logic for Rcm {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, mode_q, illegal_q, changes_q);
        if self.rst.val() {
            self.mode_q.d.next = self.transparent.val();
            self.illegal_q.d.next = false;
            self.changes_q.d.next = self.zero8.val();
        } else if self.ctl_we.val() {
            if self.ctl.val() == self.none.val() {
                // 00 would take the node off both sections: refused (§2)
                self.illegal_q.d.next = true;
            } else {
                if self.ctl.val() != self.mode_q.q.val() {
                    self.changes_q.d.next = self.changes_q.q.val() + self.one8.val();
                }
                self.mode_q.d.next = self.ctl.val();
                self.illegal_q.d.next = false;
            }
        }
        // Decode of the mode in force: an open relay terminates both section ends.
        self.relay.next = self.mode_q.q.val() == self.transparent.val();
        self.node_left.next = self.mode_q.q.val().get_bit(0);
        self.node_right.next = self.mode_q.q.val().get_bit(1);
        self.term_left.next = self.mode_q.q.val() != self.transparent.val();
        self.term_right.next = self.mode_q.q.val() != self.transparent.val();
        self.mode.next = self.mode_q.q.val();
        self.illegal.next = self.illegal_q.q.val();
        self.changes.next = self.changes_q.q.val();
    }
}
