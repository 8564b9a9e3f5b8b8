//! Main FSM of the redundancy management block: DRCC paper Table 1, as fixed by
//! the DRCC contract §4 (rows in priority order, §4.1 deliveries, §4.3 timers and
//! switch events). State encodings (`state[3:0]`, paper Table 1):
//! idle1 0, wait1 1, ch1 2, abort1 3, wait2 4, idle2 5, wait3 6, ch2 7, abort2 8,
//! wait4 9. Runs in redundancy mode only; while `hold` (normal or reset mode) it
//! sits in idle1 with its registers cleared (TIMES registers clear with `rst`
//! only).
//!
//! Replicated star node (§4.4): `attempted` is set at every edge that raises a
//! transmission request and cleared at every finish (and while held); an echo
//! (`echo_a` / `echo_b`, from `super::echo`: the other channel received the
//! attempted head message) takes the first row in every state: the message is
//! delivered and finished, a channel still attempting it is aborted, and the FSM
//! goes to the idle state of its side.
//!
//! Combinational outputs for the rest of the top: `pop` (a "finish": the head of
//! TX queue A leaves at this edge), `fail_evt` (`tx_failure` is set at this edge),
//! `switch_evt` (`failover` changes at this edge), `in_use_a` / `in_use_b` (the
//! FSM is in {wait1, ch1, abort1, wait2} / {wait3, ch2, abort2, wait4}).

use crate::host::registers::MainState;
use rust_hdl::prelude::*;

/// A state code (paper Table 1, `STATUS.state`) as an RTL constant.
fn state(s: MainState) -> Constant<Bits<4>> {
    Constant::new((s.code() as u64).into())
}

/// Main FSM (paper Table 1).
#[derive(LogicBlock)]
pub struct MainFsm {
    // clock, reset, hold (normal or reset mode)
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: also clears the TIMES registers (`last_tx_time`, `switch_time`), which
    /// `hold` keeps.
    pub rst: Signal<In, Bit>,
    /// Normal or reset mode: the FSM sits in idle1 with its registers cleared (contract §4).
    pub hold: Signal<In, Bit>,
    // inputs
    /// `CTRL.dual_tx`: a message delivered on A is sent again on B (§4.1; a star node only after
    /// the hubs split, §4.4).
    pub dual_tx: Signal<In, Bit>,
    /// `Q`: TX queue A, the one logical queue of redundancy mode, is not empty.
    pub queued: Signal<In, Bit>,
    /// `VA`: channel A is valid (aux FSM A in valid, or under the ECSS policy the bus in use is A,
    /// §12.2).
    pub valid_a: Signal<In, Bit>,
    /// `VB`: channel B is valid.
    pub valid_b: Signal<In, Bit>,
    /// Channel A's `tx_pending`: it holds a frame not yet sent or dropped.
    pub pending_a: Signal<In, Bit>,
    /// Channel B's `tx_pending`.
    pub pending_b: Signal<In, Bit>,
    /// Channel A's `tx_done` pulse: it sent the frame it held.
    pub done_a: Signal<In, Bit>,
    /// Channel B's `tx_done` pulse.
    pub done_b: Signal<In, Bit>,
    /// Channel A's `tx_failed` pulse: it dropped the frame it held (abort carried out, single
    /// shot).
    pub failed_a: Signal<In, Bit>,
    /// Channel B's `tx_failed` pulse.
    pub failed_b: Signal<In, Bit>,
    /// Nominal bit tick (`super::bit_tick`): `tx_time` counts it (§4.3).
    pub tick: Signal<In, Bit>,
    // star node (§4.4)
    /// Channel A received the attempted head message (an echo, `super::echo`).
    pub echo_a: Signal<In, Bit>,
    /// Channel B received the attempted head message.
    pub echo_b: Signal<In, Bit>,
    /// `attempted`: the head message was handed to a channel and is not finished.
    pub attempted: Signal<Out, Bit>,
    // paper signals
    /// Main FSM state `state[3:0]`, paper Table 1 codes (idle1 0 .. wait4 9, module doc).
    pub state: Signal<Out, Bits<4>>,
    /// Channel the FSM transmits on: 0 = A, 1 = B (`state >= idle2`).
    pub tx_channel: Signal<Out, Bit>,
    /// `failover` (§D4): the main FSM works on channel B since its last switch.
    pub failover: Signal<Out, Bit>,
    /// A transmission is in progress: the state is neither idle1 nor idle2.
    pub tx_going_on: Signal<Out, Bit>,
    /// Channel A transmit request (its `tx_req`), a one-clock pulse on entering ch1.
    pub req_a: Signal<Out, Bit>,
    /// Channel B transmit request (its `tx_req`), a one-clock pulse on entering ch2.
    pub req_b: Signal<Out, Bit>,
    /// Channel A abort (its `tx_abort`), a one-clock pulse: from abort1, or at an echo while A
    /// attempts the message.
    pub abort_a: Signal<Out, Bit>,
    /// Channel B abort (its `tx_abort`), a one-clock pulse: from abort2, or at an echo while B
    /// attempts the message.
    pub abort_b: Signal<Out, Bit>,
    /// One-clock pulse: a channel delivered the message in flight (§4.1), or an echo showed it
    /// delivered (§4.4).
    pub transmission_ack: Signal<Out, Bit>,
    /// One-clock pulse, the clock after the `transmission_ack` of a finish (never for the first
    /// copy of a dual message).
    pub tx_success: Signal<Out, Bit>,
    /// Channel(s) that delivered the last message, latched: bit 0 = A, bit 1 = B (11: both,
    /// `dual_tx`).
    pub tx_ok_channel: Signal<Out, Bits<2>>,
    /// One-clock pulse: the FSM judged a channel failed for the message (the wait2 and wait4 rows).
    pub tx_failure: Signal<Out, Bit>,
    /// Latched failed channel(s): bit 0 = A, bit 1 = B (11: B failed while A is not valid either).
    pub tx_failure_channel: Signal<Out, Bits<2>>,
    // host-visible times
    /// `TIMES.last_tx_time`: bit times from the first request to the delivery of the last message
    /// (saturating).
    pub last_tx_time: Signal<Out, Bits<16>>,
    /// `TIMES.switch_time`: bit times from the first request to the failover of the last switch
    /// (saturating).
    pub switch_time: Signal<Out, Bits<16>>,
    // events and channel use for the rest of the top
    /// A finish: the head of TX queue A leaves at this edge (combinational).
    pub pop: Signal<Out, Bit>,
    /// `tx_success` rises at this edge (`INT_STATUS.tx_done`; combinational).
    pub success_evt: Signal<Out, Bit>,
    /// `tx_failure` is set at this edge (`INT_STATUS.tx_failure`; combinational).
    pub fail_evt: Signal<Out, Bit>,
    /// A switch event: `failover` changes at this edge while running (§4.3: `STATS1.switches`,
    /// `INT_STATUS.switch`).
    pub switch_evt: Signal<Out, Bit>,
    /// The FSM is in {wait1, ch1, abort1, wait2}: channel A is in use, so aux FSM A does not
    /// restart it.
    pub in_use_a: Signal<Out, Bit>,
    /// The FSM is in {wait3, ch2, abort2, wait4}: channel B is in use, so aux FSM B does not
    /// restart it.
    pub in_use_b: Signal<Out, Bit>,
    // registers
    st: DFF<Bits<4>>,
    req_a_q: DFF<Bit>,
    req_b_q: DFF<Bit>,
    abort_a_q: DFF<Bit>,
    abort_b_q: DFF<Bit>,
    ack_q: DFF<Bit>,
    fin_q: DFF<Bit>,
    success_q: DFF<Bit>,
    ok_ch_q: DFF<Bits<2>>,
    failure_q: DFF<Bit>,
    fail_ch_q: DFF<Bits<2>>,
    resend: DFF<Bit>,
    copy: DFF<Bit>,
    failover_q: DFF<Bit>,
    attempted_q: DFF<Bit>,
    tx_time: DFF<Bits<16>>,
    last_time_q: DFF<Bits<16>>,
    switch_time_q: DFF<Bits<16>>,
    // constants
    s_idle1: Constant<Bits<4>>,
    s_wait1: Constant<Bits<4>>,
    s_ch1: Constant<Bits<4>>,
    s_abort1: Constant<Bits<4>>,
    s_wait2: Constant<Bits<4>>,
    s_idle2: Constant<Bits<4>>,
    s_wait3: Constant<Bits<4>>,
    s_ch2: Constant<Bits<4>>,
    s_abort2: Constant<Bits<4>>,
    s_wait4: Constant<Bits<4>>,
    ch_none: Constant<Bits<2>>,
    ch_a: Constant<Bits<2>>,
    ch_b: Constant<Bits<2>>,
    ch_both: Constant<Bits<2>>,
    one16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
}

impl Default for MainFsm {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            hold: Default::default(),
            dual_tx: Default::default(),
            queued: Default::default(),
            valid_a: Default::default(),
            valid_b: Default::default(),
            pending_a: Default::default(),
            pending_b: Default::default(),
            done_a: Default::default(),
            done_b: Default::default(),
            failed_a: Default::default(),
            failed_b: Default::default(),
            tick: Default::default(),
            echo_a: Default::default(),
            echo_b: Default::default(),
            attempted: Default::default(),
            state: Default::default(),
            tx_channel: Default::default(),
            failover: Default::default(),
            tx_going_on: Default::default(),
            req_a: Default::default(),
            req_b: Default::default(),
            abort_a: Default::default(),
            abort_b: Default::default(),
            transmission_ack: Default::default(),
            tx_success: Default::default(),
            tx_ok_channel: Default::default(),
            tx_failure: Default::default(),
            tx_failure_channel: Default::default(),
            last_tx_time: Default::default(),
            switch_time: Default::default(),
            pop: Default::default(),
            success_evt: Default::default(),
            fail_evt: Default::default(),
            switch_evt: Default::default(),
            in_use_a: Default::default(),
            in_use_b: Default::default(),
            st: Default::default(),
            req_a_q: Default::default(),
            req_b_q: Default::default(),
            abort_a_q: Default::default(),
            abort_b_q: Default::default(),
            ack_q: Default::default(),
            fin_q: Default::default(),
            success_q: Default::default(),
            ok_ch_q: Default::default(),
            failure_q: Default::default(),
            fail_ch_q: Default::default(),
            resend: Default::default(),
            copy: Default::default(),
            failover_q: Default::default(),
            attempted_q: Default::default(),
            tx_time: Default::default(),
            last_time_q: Default::default(),
            switch_time_q: Default::default(),
            s_idle1: state(MainState::Idle1),
            s_wait1: state(MainState::Wait1),
            s_ch1: state(MainState::Ch1),
            s_abort1: state(MainState::Abort1),
            s_wait2: state(MainState::Wait2),
            s_idle2: state(MainState::Idle2),
            s_wait3: state(MainState::Wait3),
            s_ch2: state(MainState::Ch2),
            s_abort2: state(MainState::Abort2),
            s_wait4: state(MainState::Wait4),
            ch_none: Constant::new(0.into()),
            ch_a: Constant::new(1.into()),
            ch_b: Constant::new(2.into()),
            ch_both: Constant::new(3.into()),
            one16: Constant::new(1.into()),
            zero16: Constant::new(0.into()),
            max16: Constant::new(0xFFFF.into()),
        }
    }
}

impl Logic for MainFsm {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            st,
            req_a_q,
            req_b_q,
            abort_a_q,
            abort_b_q,
            ack_q,
            fin_q,
            success_q,
            ok_ch_q,
            failure_q,
            fail_ch_q,
            resend,
            copy,
            failover_q,
            attempted_q,
            tx_time,
            last_time_q,
            switch_time_q
        );
        // defaults: pulses low, everything else holds
        self.st.d.next = self.st.q.val();
        self.req_a_q.d.next = false;
        self.req_b_q.d.next = false;
        self.abort_a_q.d.next = false;
        self.abort_b_q.d.next = false;
        self.ack_q.d.next = false;
        self.fin_q.d.next = false;
        self.success_q.d.next = self.fin_q.q.val();
        self.failure_q.d.next = false;
        self.ok_ch_q.d.next = self.ok_ch_q.q.val();
        self.fail_ch_q.d.next = self.fail_ch_q.q.val();
        self.resend.d.next = self.resend.q.val();
        self.copy.d.next = self.copy.q.val();
        self.failover_q.d.next = self.failover_q.q.val();
        self.last_time_q.d.next = self.last_time_q.q.val();
        self.switch_time_q.d.next = self.switch_time_q.q.val();
        // §4.3: tx_time counts bit ticks, saturating
        self.tx_time.d.next = self.tx_time.q.val();
        if self.tick.val() & (self.tx_time.q.val() != self.max16.val()) {
            self.tx_time.d.next = self.tx_time.q.val() + self.one16.val();
        }
        self.pop.next = false;
        self.fail_evt.next = false;

        if self.echo_a.val() | self.echo_b.val() {
            // §4.4 echo, first in every state: delivered, "finish" with
            // tx_ok_channel <= echo_b ? 01 : 10 (the channel whose attempt the
            // other one heard); abort the channel still attempting it
            self.ack_q.d.next = true;
            self.pop.next = true;
            self.resend.d.next = false;
            self.copy.d.next = false;
            self.last_time_q.d.next = self.tx_time.q.val();
            self.fin_q.d.next = true;
            if self.echo_b.val() {
                self.ok_ch_q.d.next = self.ch_a.val();
            } else {
                self.ok_ch_q.d.next = self.ch_b.val();
            }
            self.abort_a_q.d.next = (self.st.q.val() == self.s_ch1.val())
                | (self.st.q.val() == self.s_abort1.val())
                | (self.st.q.val() == self.s_wait2.val());
            self.abort_b_q.d.next =
                (self.st.q.val() == self.s_ch2.val()) | (self.st.q.val() == self.s_abort2.val());
            // idle2 from idle2, wait3, ch2, abort2 and from wait4 without VA;
            // idle1 from the others (failover <= 0 from wait4)
            if ((self.st.q.val() >= self.s_idle2.val()) & (self.st.q.val() <= self.s_abort2.val()))
                | ((self.st.q.val() == self.s_wait4.val()) & !self.valid_a.val())
            {
                self.st.d.next = self.s_idle2.val();
            } else {
                self.st.d.next = self.s_idle1.val();
                if self.st.q.val() == self.s_wait4.val() {
                    self.failover_q.d.next = false;
                }
            }
        } else if self.st.q.val() == self.s_idle1.val() {
            // idle1: !VA && VB -> idle2 (failover); Q -> wait1
            if !self.valid_a.val() & self.valid_b.val() {
                self.st.d.next = self.s_idle2.val();
                self.failover_q.d.next = true;
            } else if self.queued.val() {
                self.st.d.next = self.s_wait1.val();
            }
        } else if self.st.q.val() == self.s_wait1.val() {
            // wait1: !pending_a -> ch1, request on channel A
            if !self.pending_a.val() {
                self.st.d.next = self.s_ch1.val();
                self.req_a_q.d.next = true;
                if !self.resend.q.val() & !self.copy.q.val() {
                    self.tx_time.d.next = self.zero16.val();
                }
            }
        } else if (self.st.q.val() == self.s_ch1.val())
            | (self.st.q.val() == self.s_abort1.val())
            | (self.st.q.val() == self.s_wait2.val())
        {
            if self.done_a.val() {
                // §4.1 "A delivered"
                self.ack_q.d.next = true;
                if self.dual_tx.val() & self.valid_b.val() {
                    self.copy.d.next = true;
                    self.st.d.next = self.s_idle2.val();
                } else {
                    // finish, tx_ok_channel <= 01
                    self.pop.next = true;
                    self.resend.d.next = false;
                    self.copy.d.next = false;
                    self.last_time_q.d.next = self.tx_time.q.val();
                    self.fin_q.d.next = true;
                    self.ok_ch_q.d.next = self.ch_a.val();
                    self.st.d.next = self.s_idle1.val();
                }
            } else if self.st.q.val() == self.s_ch1.val() {
                // ch1: !VA && VB -> abort1
                if !self.valid_a.val() & self.valid_b.val() {
                    self.st.d.next = self.s_abort1.val();
                }
            } else if self.st.q.val() == self.s_abort1.val() {
                // abort1: -> wait2, abort channel A
                self.st.d.next = self.s_wait2.val();
                self.abort_a_q.d.next = true;
            } else if self.failed_a.val() | (!self.pending_a.val() & !self.abort_a_q.q.val()) {
                // wait2: A failed or quiet -> idle2 (failover)
                self.st.d.next = self.s_idle2.val();
                self.failure_q.d.next = true;
                self.fail_evt.next = true;
                self.fail_ch_q.d.next = self.ch_a.val();
                self.resend.d.next = true;
                self.failover_q.d.next = true;
                self.switch_time_q.d.next = self.tx_time.q.val();
            }
        } else if self.st.q.val() == self.s_idle2.val() {
            // idle2: resend || copy -> wait3; VA -> wait4; Q -> wait3
            if self.resend.q.val() | self.copy.q.val() {
                self.st.d.next = self.s_wait3.val();
            } else if self.valid_a.val() {
                self.st.d.next = self.s_wait4.val();
            } else if self.queued.val() {
                self.st.d.next = self.s_wait3.val();
            }
        } else if self.st.q.val() == self.s_wait3.val() {
            // wait3: !pending_b -> ch2, request on channel B
            if !self.pending_b.val() {
                self.st.d.next = self.s_ch2.val();
                self.req_b_q.d.next = true;
                if !self.resend.q.val() & !self.copy.q.val() {
                    self.tx_time.d.next = self.zero16.val();
                }
            }
        } else if (self.st.q.val() == self.s_ch2.val())
            | (self.st.q.val() == self.s_abort2.val())
            | (self.st.q.val() == self.s_wait4.val())
        {
            if self.done_b.val() {
                // §4.1 "B delivered": finish, tx_ok_channel <= copy ? 11 : 10
                self.ack_q.d.next = true;
                self.pop.next = true;
                self.resend.d.next = false;
                self.copy.d.next = false;
                self.last_time_q.d.next = self.tx_time.q.val();
                self.fin_q.d.next = true;
                if self.copy.q.val() {
                    self.ok_ch_q.d.next = self.ch_both.val();
                } else {
                    self.ok_ch_q.d.next = self.ch_b.val();
                }
                self.st.d.next = self.s_idle2.val();
                if (self.st.q.val() == self.s_wait4.val()) & self.valid_a.val() {
                    self.st.d.next = self.s_idle1.val();
                    self.failover_q.d.next = false;
                }
            } else if self.st.q.val() == self.s_ch2.val() {
                // ch2: !VB && VA -> abort2
                if !self.valid_b.val() & self.valid_a.val() {
                    self.st.d.next = self.s_abort2.val();
                }
            } else if self.st.q.val() == self.s_abort2.val() {
                // abort2: -> wait4, abort channel B
                self.st.d.next = self.s_wait4.val();
                self.abort_b_q.d.next = true;
            } else if self.failed_b.val() | (!self.pending_b.val() & !self.abort_b_q.q.val()) {
                // wait4: B failed or quiet -> VA ? idle1 : idle2
                if self.valid_a.val() {
                    self.st.d.next = self.s_idle1.val();
                    self.failover_q.d.next = false;
                } else {
                    self.st.d.next = self.s_idle2.val();
                }
                if self.failed_b.val() {
                    self.failure_q.d.next = true;
                    self.fail_evt.next = true;
                    if self.valid_a.val() {
                        self.fail_ch_q.d.next = self.ch_b.val();
                    } else {
                        self.fail_ch_q.d.next = self.ch_both.val();
                    }
                }
                if self.copy.q.val() {
                    // the copy on B is given up: finish, tx_ok_channel <= 01; no
                    // transmission_ack at this edge, hence no tx_success (§4.1:
                    // finish_q is "popped at the ack edge")
                    self.pop.next = true;
                    self.resend.d.next = false;
                    self.copy.d.next = false;
                    self.last_time_q.d.next = self.tx_time.q.val();
                    self.ok_ch_q.d.next = self.ch_a.val();
                }
            }
        }

        // §4.4: attempted from the request to the finish
        self.attempted_q.d.next = self.attempted_q.q.val();
        if self.pop.val() {
            self.attempted_q.d.next = false;
        }
        if self.req_a_q.d.val() | self.req_b_q.d.val() {
            self.attempted_q.d.next = true;
        }

        if self.hold.val() {
            self.st.d.next = self.s_idle1.val();
            self.req_a_q.d.next = false;
            self.req_b_q.d.next = false;
            self.abort_a_q.d.next = false;
            self.abort_b_q.d.next = false;
            self.ack_q.d.next = false;
            self.fin_q.d.next = false;
            self.success_q.d.next = false;
            self.failure_q.d.next = false;
            self.ok_ch_q.d.next = self.ch_none.val();
            self.fail_ch_q.d.next = self.ch_none.val();
            self.resend.d.next = false;
            self.copy.d.next = false;
            self.failover_q.d.next = false;
            self.attempted_q.d.next = false;
            self.tx_time.d.next = self.zero16.val();
            self.pop.next = false;
            self.fail_evt.next = false;
        }
        if self.rst.val() {
            self.last_time_q.d.next = self.zero16.val();
            self.switch_time_q.d.next = self.zero16.val();
        }
        // a switch event is a change of failover while running (clearing it in
        // normal or reset mode is not a switch)
        self.switch_evt.next =
            (self.failover_q.d.val() != self.failover_q.q.val()) & !self.hold.val();
        self.success_evt.next = self.success_q.d.val();

        self.state.next = self.st.q.val();
        self.tx_channel.next = self.st.q.val() >= self.s_idle2.val();
        self.failover.next = self.failover_q.q.val();
        self.tx_going_on.next =
            (self.st.q.val() != self.s_idle1.val()) & (self.st.q.val() != self.s_idle2.val());
        self.in_use_a.next =
            (self.st.q.val() >= self.s_wait1.val()) & (self.st.q.val() <= self.s_wait2.val());
        self.in_use_b.next = self.st.q.val() >= self.s_wait3.val();
        self.req_a.next = self.req_a_q.q.val();
        self.req_b.next = self.req_b_q.q.val();
        self.abort_a.next = self.abort_a_q.q.val();
        self.abort_b.next = self.abort_b_q.q.val();
        self.attempted.next = self.attempted_q.q.val();
        self.transmission_ack.next = self.ack_q.q.val();
        self.tx_success.next = self.success_q.q.val();
        self.tx_ok_channel.next = self.ok_ch_q.q.val();
        self.tx_failure.next = self.failure_q.q.val();
        self.tx_failure_channel.next = self.fail_ch_q.q.val();
        self.last_tx_time.next = self.last_time_q.q.val();
        self.switch_time.next = self.switch_time_q.q.val();
    }
}
