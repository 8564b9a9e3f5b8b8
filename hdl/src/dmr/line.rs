//! One CAN line of the DMR function (DMR contract §5, §6, §7), instantiated for the
//! DCL and the RCL: the host-copy and CS requests (`req`, `busy`, `cs_req`,
//! `cs_busy`, `cs_live`, `cs_due`), the completion of an attempt, the line's fault
//! flags and their sources (CS timeout, bus-off, an evaluation against the line),
//! the deletion abort, the recovery delay and the restart pulse.
//!
//! One 16-bit `timer` serves both the CS timeout and the recovery delay: it is the
//! CS timer while an attempt is live (`cs_busy && cs_live`) and the recovery timer
//! otherwise. They never run together: a live attempt starts from `cs_due`, which
//! only a finished recovery delay, the period (a line without a flag) or reset
//! mode sets, and every fault that reloads the delay cancels the attempt.

use rust_hdl::prelude::*;

/// Requests, flags, CS attempt and recovery of one line.
#[derive(LogicBlock)]
pub struct DmrLine {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// The DRCC `rst`: every register to its reset value.
    pub rst: Signal<In, Bit>,
    /// Held (reset mode or not DMR mode): the reset-mode state, `cs_due = 1`,
    /// `busoff_q` follows the channel.
    pub hold: Signal<In, Bit>,
    // ---- configuration ----
    /// `DMR_CFG.timeout`: the CS timeout, DMR ticks.
    pub timeout: Signal<In, Bits<16>>,
    /// `DMR_TIME.recovery_delay`: DMR ticks.
    pub recovery_delay: Signal<In, Bits<16>>,
    // ---- time base ----
    /// `dmr_tick` (§3).
    pub dmr_tick: Signal<In, Bit>,
    /// A periodic CS is due at this edge (§7).
    pub period_due: Signal<In, Bit>,
    // ---- TX queue A ----
    /// The RAM read port serves this line at this edge (`rd_sel == L`).
    pub mine: Signal<In, Bit>,
    /// The line has a message left to send (`off[L] < count`).
    pub more: Signal<In, Bit>,
    /// Key `{ide, id}` of the RAM read data register.
    pub rd_key: Signal<In, Bits<30>>,
    // ---- the line's channel ----
    /// `reset_mode_q`, part of the channel's `rst`.
    pub reset_mode_q: Signal<In, Bit>,
    /// The channel's `tx_done`.
    pub done: Signal<In, Bit>,
    /// The channel's `tx_failed` (an aborted attempt).
    pub failed: Signal<In, Bit>,
    /// The channel's fault-confinement state (2 = bus-off).
    pub err_state: Signal<In, Bits<2>>,
    /// The channel's `tx_req` (`req | cs_req`, a register pulse).
    pub tx_req: Signal<Out, Bit>,
    /// The channel sends the CS frame of this line (a register pulse).
    pub cs_req: Signal<Out, Bit>,
    /// The channel's `tx_abort` (a register pulse).
    pub abort: Signal<Out, Bit>,
    /// The channel's restart (`rst` in the next clock; a register pulse).
    pub restart: Signal<Out, Bit>,
    // ---- the other line and the evaluation ----
    /// The other line sends (`!tx_fault[O]`, before the edge).
    pub other_sends: Signal<In, Bit>,
    /// An evaluation fault against this line at this edge (§4.2).
    pub eval_here: Signal<In, Bit>,
    /// That evaluation judged a transmit mailbox (`tx_fault`, else `rx_fault`).
    pub eval_tx: Signal<In, Bit>,
    // ---- events of this edge (combinational) ----
    /// `REQ(L)`: a host copy is requested (the `req` register).
    pub raise_req: Signal<Out, Bit>,
    /// `TX(L)`: a host copy completed while both lines send.
    pub raise_tx: Signal<Out, Bit>,
    /// The key of `TX(L)`: latched at the line's last host request.
    pub key_tx: Signal<Out, Bits<30>>,
    /// A host copy completed on a sending line (its offset steps).
    pub complete: Signal<Out, Bit>,
    /// The live CS attempt timed out (fault, cause CS failed).
    pub cs_fail: Signal<Out, Bit>,
    /// The channel entered bus-off (fault, cause bus-off).
    pub busoff: Signal<Out, Bit>,
    /// A fault counted against the line (reloads the delay, may switch the ACL).
    pub against: Signal<Out, Bit>,
    /// The line sends after this edge (`!tx_fault'`).
    pub sends_next: Signal<Out, Bit>,
    /// A CS attempt of a flagged line succeeded: a recovery (§7).
    pub recovered: Signal<Out, Bit>,
    // ---- flags (registers) ----
    /// `tx_fault`: the line cannot transmit.
    pub tx_fault: Signal<Out, Bit>,
    /// `rx_fault`: a reception fault was found on the line.
    pub rx_fault: Signal<Out, Bit>,
    // ---- registers ----
    /// `req`.
    pub req_q: DFF<Bit>,
    /// `busy`.
    pub busy_q: DFF<Bit>,
    /// `cs_req`.
    pub cs_req_q: DFF<Bit>,
    /// `cs_busy`.
    pub cs_busy_q: DFF<Bit>,
    /// `cs_live`.
    pub cs_live_q: DFF<Bit>,
    /// `cs_due`.
    pub cs_due_q: DFF<Bit>,
    /// `cs_timer` while `cs_busy && cs_live`, else `rec_timer`.
    pub timer_q: DFF<Bits<16>>,
    /// `abort`.
    pub abort_q: DFF<Bit>,
    /// `key_sent`.
    pub key_sent_q: DFF<Bits<30>>,
    /// `tx_fault`.
    pub tx_fault_q: DFF<Bit>,
    /// `rx_fault`.
    pub rx_fault_q: DFF<Bit>,
    /// `rec_pending`.
    pub rec_pending_q: DFF<Bit>,
    /// `restart`.
    pub restart_q: DFF<Bit>,
    /// `busoff_q`: bus-off at the previous edge.
    pub busoff_q: DFF<Bit>,
    // ---- internals ----
    free: Signal<Local, Bit>,
    cs_mode: Signal<Local, Bit>,
    take_cs: Signal<Local, Bit>,
    take_req: Signal<Local, Bit>,
    is_busoff: Signal<Local, Bit>,
    timer_dec: Signal<Local, Bits<16>>,
    timer_one: Signal<Local, Bit>,
    success: Signal<Local, Bit>,
    tx_set: Signal<Local, Bit>,
    rx_set: Signal<Local, Bit>,
    against_l: Signal<Local, Bit>,
    busoff2: Constant<Bits<2>>,
    one16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    zero30: Constant<Bits<30>>,
}

impl Default for DmrLine {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            hold: Default::default(),
            timeout: Default::default(),
            recovery_delay: Default::default(),
            dmr_tick: Default::default(),
            period_due: Default::default(),
            mine: Default::default(),
            more: Default::default(),
            rd_key: Default::default(),
            reset_mode_q: Default::default(),
            done: Default::default(),
            failed: Default::default(),
            err_state: Default::default(),
            tx_req: Default::default(),
            cs_req: Default::default(),
            abort: Default::default(),
            restart: Default::default(),
            other_sends: Default::default(),
            eval_here: Default::default(),
            eval_tx: Default::default(),
            raise_req: Default::default(),
            raise_tx: Default::default(),
            key_tx: Default::default(),
            complete: Default::default(),
            cs_fail: Default::default(),
            busoff: Default::default(),
            against: Default::default(),
            sends_next: Default::default(),
            recovered: Default::default(),
            tx_fault: Default::default(),
            rx_fault: Default::default(),
            req_q: Default::default(),
            busy_q: Default::default(),
            cs_req_q: Default::default(),
            cs_busy_q: Default::default(),
            cs_live_q: Default::default(),
            cs_due_q: Default::default(),
            timer_q: Default::default(),
            abort_q: Default::default(),
            key_sent_q: Default::default(),
            tx_fault_q: Default::default(),
            rx_fault_q: Default::default(),
            rec_pending_q: Default::default(),
            restart_q: Default::default(),
            busoff_q: Default::default(),
            free: Default::default(),
            cs_mode: Default::default(),
            take_cs: Default::default(),
            take_req: Default::default(),
            is_busoff: Default::default(),
            timer_dec: Default::default(),
            timer_one: Default::default(),
            success: Default::default(),
            tx_set: Default::default(),
            rx_set: Default::default(),
            against_l: Default::default(),
            busoff2: Constant::new(2.into()),
            one16: Constant::new(1.into()),
            zero16: Constant::new(0.into()),
            zero30: Constant::new(0.into()),
        }
    }
}

impl Logic for DmrLine {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            req_q,
            busy_q,
            cs_req_q,
            cs_busy_q,
            cs_live_q,
            cs_due_q,
            timer_q,
            abort_q,
            key_sent_q,
            tx_fault_q,
            rx_fault_q,
            rec_pending_q,
            restart_q,
            busoff_q
        );
        // §5 free[L]: nothing under way, the channel not in reset, no restart pending.
        self.free.next = !self.busy_q.q.val()
            & !self.req_q.q.val()
            & !self.cs_busy_q.q.val()
            & !self.cs_req_q.q.val()
            & !self.reset_mode_q.val()
            & !self.restart_q.q.val()
            & !self.rec_pending_q.q.val();
        self.cs_mode.next = self.cs_busy_q.q.val() & self.cs_live_q.q.val();
        self.take_cs.next = self.mine.val() & self.cs_due_q.q.val() & self.free.val();
        self.take_req.next = self.mine.val()
            & !self.tx_fault_q.q.val()
            & self.more.val()
            & !self.cs_due_q.q.val()
            & self.free.val();
        self.timer_one.next = self.timer_q.q.val() == self.one16.val();
        self.timer_dec.next = self.timer_q.q.val() - self.one16.val();
        self.is_busoff.next = self.err_state.val() == self.busoff2.val();
        // §5 requests: a CS frame when due, else the next host copy.
        self.cs_req_q.d.next = self.take_cs.val();
        self.req_q.d.next = self.take_req.val();
        self.abort_q.d.next = false;
        self.restart_q.d.next = false;
        if self.take_cs.val() {
            self.cs_busy_q.d.next = true;
            self.cs_due_q.d.next = false;
            self.cs_live_q.d.next = true;
            self.timer_q.d.next = self.timeout.val();
        }
        if self.take_req.val() {
            self.busy_q.d.next = true;
        }
        // REQ(L) carries the read data of the request's edge; TX(L) will too.
        if self.req_q.q.val() {
            self.key_sent_q.d.next = self.rd_key.val();
        }
        // §5 completion: the CS attempt or the host copy ends.
        self.complete.next = self.done.val()
            & !self.cs_busy_q.q.val()
            & self.busy_q.q.val()
            & !self.tx_fault_q.q.val();
        if self.done.val() {
            if self.cs_busy_q.q.val() {
                self.cs_busy_q.d.next = false;
            } else if self.busy_q.q.val() {
                self.busy_q.d.next = false;
            }
        } else if self.failed.val() {
            if self.cs_busy_q.q.val() {
                self.cs_busy_q.d.next = false;
            } else {
                self.busy_q.d.next = false;
            }
        }
        // §7 CS timeout: a live attempt counts DMR ticks, fails at 1 -> 0.
        self.cs_fail.next = self.cs_mode.val() & self.dmr_tick.val() & self.timer_one.val();
        if self.cs_mode.val() & self.dmr_tick.val() & (self.timer_q.q.val() != self.zero16.val()) {
            self.timer_q.d.next = self.timer_dec.val();
        }
        // §7 success: "Upon successful transmission of the DMR Connection Service
        // the DMR state is updated"; the attempt's end leaves rec_timer = 0.
        self.success.next = self.done.val() & self.cs_mode.val();
        self.recovered.next =
            self.success.val() & (self.tx_fault_q.q.val() | self.rx_fault_q.q.val());
        if self.success.val() {
            self.tx_fault_q.d.next = false;
            self.rx_fault_q.d.next = false;
        }
        if (self.done.val() | self.failed.val()) & self.cs_mode.val() {
            self.timer_q.d.next = self.zero16.val();
        }
        // §6 bus-off: the channel enters it at this edge.
        self.busoff.next = self.is_busoff.val() & !self.busoff_q.q.val();
        self.busoff_q.d.next = self.is_busoff.val();
        // §7 recovery (Figure 8): a flagged line's delay runs out -> restart, CS.
        if !self.cs_mode.val()
            & (self.tx_fault_q.q.val() | self.rx_fault_q.q.val())
            & self.dmr_tick.val()
            & (self.timer_q.q.val() != self.zero16.val())
        {
            self.timer_q.d.next = self.timer_dec.val();
            if self.timer_one.val() {
                self.rec_pending_q.d.next = true;
                self.cs_due_q.d.next = true;
            }
        }
        // The restart waits for a quiet line; a bus-off channel recovers by itself
        // (ISO 11898-1 12.1.4.2), never cut short.
        if self.rec_pending_q.q.val()
            & !self.busy_q.q.val()
            & !self.cs_busy_q.q.val()
            & !self.is_busoff.val()
        {
            self.rec_pending_q.d.next = false;
            self.restart_q.d.next = true;
        }
        // §7 periodic CS for a line without a flag and no CS due or busy.
        if self.period_due.val()
            & !self.tx_fault_q.q.val()
            & !self.rx_fault_q.q.val()
            & !self.cs_due_q.q.val()
            & !self.cs_busy_q.q.val()
        {
            self.cs_due_q.d.next = true;
        }
        // §6 faults set against the line (they win over a CS success).
        self.tx_set.next =
            self.cs_fail.val() | self.busoff.val() | (self.eval_here.val() & self.eval_tx.val());
        self.rx_set.next = self.eval_here.val() & !self.eval_tx.val();
        // A receive fault on a line already unable to transmit only records itself.
        self.against_l.next = self.tx_set.val() | (self.rx_set.val() & !self.tx_fault_q.q.val());
        if self.rx_set.val() {
            self.rx_fault_q.d.next = true;
        }
        if self.tx_set.val() {
            self.tx_fault_q.d.next = true;
            // §5 deletion: the attempt on the bus runs on, it is aborted.
            if self.busy_q.q.val() {
                self.abort_q.d.next = true;
            }
        }
        if self.against_l.val() {
            // The recovery delay restarts; the line's connection service is cancelled.
            self.timer_q.d.next = self.recovery_delay.val();
            self.cs_due_q.d.next = false;
            self.cs_live_q.d.next = false;
            self.rec_pending_q.d.next = false;
            if self.cs_busy_q.q.val() {
                self.abort_q.d.next = true;
            }
        }
        self.sends_next.next =
            !(self.tx_set.val() | (self.tx_fault_q.q.val() & !self.success.val()));
        // Held: the reset-mode state (cs_due = 1: the CS leaves with the channel).
        if self.hold.val() | self.rst.val() {
            self.req_q.d.next = false;
            self.busy_q.d.next = false;
            self.cs_req_q.d.next = false;
            self.cs_busy_q.d.next = false;
            self.cs_live_q.d.next = false;
            self.cs_due_q.d.next = true;
            self.timer_q.d.next = self.zero16.val();
            self.abort_q.d.next = false;
            self.key_sent_q.d.next = self.zero30.val();
            self.tx_fault_q.d.next = false;
            self.rx_fault_q.d.next = false;
            self.rec_pending_q.d.next = false;
            self.restart_q.d.next = false;
        }
        if self.rst.val() {
            self.busoff_q.d.next = false;
        }
        self.tx_req.next = self.req_q.q.val() | self.cs_req_q.q.val();
        self.cs_req.next = self.cs_req_q.q.val();
        self.abort.next = self.abort_q.q.val();
        self.restart.next = self.restart_q.q.val();
        self.raise_req.next = self.req_q.q.val();
        self.raise_tx.next = self.complete.val() & self.other_sends.val();
        self.key_tx.next = self.key_sent_q.q.val();
        self.against.next = self.against_l.val();
        self.tx_fault.next = self.tx_fault_q.q.val();
        self.rx_fault.next = self.rx_fault_q.q.val();
    }
}
