//! The DMR state machine's shared registers (DMR contract §6, seed Figure 6): the
//! active line `acl` and its switch, `dmr_state` from the lines' flags, the
//! `cause` / `cause_line` / `cause_mb` of the last fault, the `state_changes` and
//! `acl_switches` statistics, and the `DMR_STATUS` word (§2.1).

use super::sat_count::SatCount8;
use rust_hdl::prelude::*;

/// `acl`, `dmr_state`, the fault cause and the state statistics.
#[derive(LogicBlock)]
pub struct DmrStatus {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// The DRCC `rst`: everything, the statistics too.
    pub rst: Signal<In, Bit>,
    /// Held (reset mode or not DMR mode): the state clears, the statistics stay,
    /// and the return to the reset values is no change (no event, no count).
    pub hold: Signal<In, Bit>,
    // ---- flags before the edge ----
    /// `tx_fault[DCL]`.
    pub tx_fault_dcl: Signal<In, Bit>,
    /// `rx_fault[DCL]`.
    pub rx_fault_dcl: Signal<In, Bit>,
    /// `tx_fault[RCL]`.
    pub tx_fault_rcl: Signal<In, Bit>,
    /// `rx_fault[RCL]`.
    pub rx_fault_rcl: Signal<In, Bit>,
    // ---- faults of this edge ----
    /// A fault counted against the DCL.
    pub against_dcl: Signal<In, Bit>,
    /// A fault counted against the RCL.
    pub against_rcl: Signal<In, Bit>,
    /// The DCL's live CS attempt timed out.
    pub cs_fail_dcl: Signal<In, Bit>,
    /// The RCL's live CS attempt timed out.
    pub cs_fail_rcl: Signal<In, Bit>,
    /// The DCL's channel entered bus-off.
    pub busoff_dcl: Signal<In, Bit>,
    /// The RCL's channel entered bus-off.
    pub busoff_rcl: Signal<In, Bit>,
    /// An evaluation fault (§4.2).
    pub eval_fault: Signal<In, Bit>,
    /// Its line (0 DCL, 1 RCL).
    pub eval_line: Signal<In, Bit>,
    /// Its kind: deviation (1) or timeout (0).
    pub eval_deviation: Signal<In, Bit>,
    /// Its mailbox.
    pub eval_mb: Signal<In, Bits<4>>,
    // ---- outputs ----
    /// `acl` (0 DCL, 1 RCL).
    pub acl: Signal<Out, Bit>,
    /// `dmr_state`.
    pub dmr_state: Signal<Out, Bits<2>>,
    /// The ACL switches at this edge (combinational).
    pub acl_switch: Signal<Out, Bit>,
    /// `dmr_state` or `acl` changes at this edge: `INT_STATUS.dmr` (combinational).
    pub int_evt: Signal<Out, Bit>,
    /// `DMR_STATUS` (§2.1).
    pub status_word: Signal<Out, Bits<32>>,
    // ---- registers ----
    /// `acl`.
    pub acl_q: DFF<Bit>,
    /// `dmr_state`.
    pub state_q: DFF<Bits<2>>,
    /// `cause`.
    pub cause_q: DFF<Bits<2>>,
    /// `cause_line`.
    pub cause_line_q: DFF<Bit>,
    /// `cause_mb`.
    pub cause_mb_q: DFF<Bits<4>>,
    /// `state_changes`.
    pub state_changes: SatCount8,
    /// `acl_switches`.
    pub acl_switches: SatCount8,
    // ---- internals ----
    switch: Signal<Local, Bit>,
    state_next: Signal<Local, Bits<2>>,
    changed: Signal<Local, Bit>,
    c_timeout: Constant<Bits<2>>,
    c_deviation: Constant<Bits<2>>,
    c_busoff: Constant<Bits<2>>,
    c_cs_failed: Constant<Bits<2>>,
    s_active: Constant<Bits<2>>,
    s_passive: Constant<Bits<2>>,
    s_disabled: Constant<Bits<2>>,
    s_disconnected: Constant<Bits<2>>,
    zero4: Constant<Bits<4>>,
}

impl Default for DmrStatus {
    fn default() -> Self {
        let c = |v: u64| Constant::new(v.into());
        Self {
            clk: Default::default(),
            rst: Default::default(),
            hold: Default::default(),
            tx_fault_dcl: Default::default(),
            rx_fault_dcl: Default::default(),
            tx_fault_rcl: Default::default(),
            rx_fault_rcl: Default::default(),
            against_dcl: Default::default(),
            against_rcl: Default::default(),
            cs_fail_dcl: Default::default(),
            cs_fail_rcl: Default::default(),
            busoff_dcl: Default::default(),
            busoff_rcl: Default::default(),
            eval_fault: Default::default(),
            eval_line: Default::default(),
            eval_deviation: Default::default(),
            eval_mb: Default::default(),
            acl: Default::default(),
            dmr_state: Default::default(),
            acl_switch: Default::default(),
            int_evt: Default::default(),
            status_word: Default::default(),
            acl_q: Default::default(),
            state_q: Default::default(),
            cause_q: Default::default(),
            cause_line_q: Default::default(),
            cause_mb_q: Default::default(),
            state_changes: Default::default(),
            acl_switches: Default::default(),
            switch: Default::default(),
            state_next: Default::default(),
            changed: Default::default(),
            // §2.1 DMR_STATUS.cause and dmr_state codes
            c_timeout: c(0),
            c_deviation: c(1),
            c_busoff: c(2),
            c_cs_failed: c(3),
            s_active: c(0),
            s_passive: c(1),
            s_disabled: c(2),
            s_disconnected: c(3),
            zero4: Constant::new(0.into()),
        }
    }
}

impl Logic for DmrStatus {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, acl_q, state_q, cause_q, cause_line_q, cause_mb_q);
        self.state_changes.clk.next = self.clk.val();
        self.acl_switches.clk.next = self.clk.val();
        // §6 cause of the last fault set: written in the order CS failed, bus-off,
        // evaluation (the last written stays); cause_mb only by an evaluation.
        if self.cs_fail_dcl.val() {
            self.cause_q.d.next = self.c_cs_failed.val();
            self.cause_line_q.d.next = false;
        }
        if self.cs_fail_rcl.val() {
            self.cause_q.d.next = self.c_cs_failed.val();
            self.cause_line_q.d.next = true;
        }
        if self.busoff_dcl.val() {
            self.cause_q.d.next = self.c_busoff.val();
            self.cause_line_q.d.next = false;
        }
        if self.busoff_rcl.val() {
            self.cause_q.d.next = self.c_busoff.val();
            self.cause_line_q.d.next = true;
        }
        if self.eval_fault.val() {
            if self.eval_deviation.val() {
                self.cause_q.d.next = self.c_deviation.val();
            } else {
                self.cause_q.d.next = self.c_timeout.val();
            }
            self.cause_line_q.d.next = self.eval_line.val();
            self.cause_mb_q.d.next = self.eval_mb.val();
        }
        // §6 ACL switch: a fault against the ACL while the other line is sound.
        if self.acl_q.q.val() {
            self.switch.next = self.against_rcl.val()
                & !self.tx_fault_dcl.val()
                & !self.rx_fault_dcl.val()
                & !self.against_dcl.val();
        } else {
            self.switch.next = self.against_dcl.val()
                & !self.tx_fault_rcl.val()
                & !self.rx_fault_rcl.val()
                & !self.against_rcl.val();
        }
        if self.switch.val() {
            self.acl_q.d.next = !self.acl_q.q.val();
        }
        // §6 dmr_state from the flags before the edge (seed Figure 6).
        if self.tx_fault_dcl.val() & self.tx_fault_rcl.val() {
            self.state_next.next = self.s_disconnected.val();
        } else if self.tx_fault_dcl.val() | self.tx_fault_rcl.val() {
            self.state_next.next = self.s_disabled.val();
        } else if self.rx_fault_dcl.val() | self.rx_fault_rcl.val() {
            self.state_next.next = self.s_passive.val();
        } else {
            self.state_next.next = self.s_active.val();
        }
        self.state_q.d.next = self.state_next.val();
        self.changed.next = self.state_next.val() != self.state_q.q.val();
        self.state_changes.rst.next = self.rst.val();
        self.acl_switches.rst.next = self.rst.val();
        self.state_changes.inc.next = self.changed.val() & !self.hold.val();
        self.acl_switches.inc.next = self.switch.val() & !self.hold.val();
        self.acl_switch.next = self.switch.val() & !self.hold.val() & !self.rst.val();
        self.int_evt.next =
            (self.changed.val() | self.switch.val()) & !self.hold.val() & !self.rst.val();
        if self.hold.val() | self.rst.val() {
            self.acl_q.d.next = false;
            self.state_q.d.next = self.s_active.val();
            self.cause_q.d.next = self.c_timeout.val();
            self.cause_line_q.d.next = false;
            self.cause_mb_q.d.next = self.zero4.val();
        }
        self.acl.next = self.acl_q.q.val();
        self.dmr_state.next = self.state_q.q.val();
        self.status_word.next = bit_cast::<32, 2>(self.state_q.q.val())
            | (bit_cast::<32, 1>(self.acl_q.q.val().into()) << 2)
            | (bit_cast::<32, 1>(self.tx_fault_dcl.val().into()) << 3)
            | (bit_cast::<32, 1>(self.rx_fault_dcl.val().into()) << 4)
            | (bit_cast::<32, 1>(self.tx_fault_rcl.val().into()) << 5)
            | (bit_cast::<32, 1>(self.rx_fault_rcl.val().into()) << 6)
            | (bit_cast::<32, 2>(self.cause_q.q.val()) << 8)
            | (bit_cast::<32, 1>(self.cause_line_q.q.val().into()) << 10)
            | (bit_cast::<32, 4>(self.cause_mb_q.q.val()) << 12)
            | (bit_cast::<32, 8>(self.state_changes.count.val()) << 16)
            | (bit_cast::<32, 8>(self.acl_switches.count.val()) << 24);
    }
}
