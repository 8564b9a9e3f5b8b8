//! Main redundancy-management FSM (DRCC paper Table 1, contract §4): the state
//! register, `resend` / `copy` / `failover`, the channel request and abort pulses,
//! the paper's delivery probes, `tx_time` and the TIMES / switch statistics.

use super::regs::state::*;
use crate::model::coverage;

/// Everything the main FSM samples at one edge (pre-edge values).
#[derive(Clone, Copy, Debug, Default)]
pub struct FsmInputs {
    /// Redundancy mode and not reset mode.
    pub running: bool,
    /// `Q`: TX queue A not empty.
    pub q: bool,
    /// `VA` / `VB`: aux A / B in `valid`.
    pub va: bool,
    pub vb: bool,
    pub dual_tx: bool,
    /// Nominal bit tick (§4.3).
    pub tick: bool,
    pub pending_a: bool,
    pub done_a: bool,
    pub failed_a: bool,
    pub pending_b: bool,
    pub done_b: bool,
    pub failed_b: bool,
    /// Echo of the attempted head message on channel A / B (star node, §4.4):
    /// `star && attempted && rx_valid && rx frame == head`.
    pub echo_a: bool,
    pub echo_b: bool,
}

/// What the FSM did at an edge, for the rest of the top.
#[derive(Clone, Copy, Debug, Default)]
pub struct FsmEvents {
    /// "finish": pop TX queue A.
    pub pop: bool,
    /// `tx_success` was set at this edge (INT_STATUS.tx_done).
    pub tx_success: bool,
    /// `tx_failure` was set at this edge (INT_STATUS.tx_failure).
    pub tx_failure: bool,
    /// `failover` changed (INT_STATUS.switch).
    pub switch: bool,
}

/// The main FSM registers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MainFsm {
    pub state: u8,
    pub resend: bool,
    pub copy: bool,
    pub failover: bool,
    /// The head message was handed to a channel and is not finished (§4.4).
    pub attempted: bool,
    /// `chan_a_transmission_req` / `chan_b_transmission_req` (pulses).
    pub req_a: bool,
    pub req_b: bool,
    /// Channel `tx_abort` pulses.
    pub abort_a: bool,
    pub abort_b: bool,
    pub transmission_ack: bool,
    /// The message was popped at the edge that raised `transmission_ack`.
    pub finish_q: bool,
    pub tx_success: bool,
    pub tx_failure: bool,
    pub tx_ok_channel: u8,
    pub tx_failure_channel: u8,
    pub tx_time: u16,
    // Statistics, cleared only by `rst`.
    pub last_tx_time: u16,
    pub switch_time: u16,
    /// STATS1[15:0].
    pub switches: u16,
}

impl MainFsm {
    /// `tx_channel = (state >= idle2)`.
    pub fn tx_channel(&self) -> bool {
        self.state >= IDLE2
    }

    /// `tx_going_on = state not in {idle1, idle2}`.
    pub fn tx_going_on(&self) -> bool {
        self.state != IDLE1 && self.state != IDLE2
    }

    /// Channel A is in use: {wait1, ch1, abort1, wait2} (§5).
    pub fn uses_a(&self) -> bool {
        matches!(self.state, WAIT1 | CH1 | ABORT1 | WAIT2)
    }

    /// Channel B is in use: {wait3, ch2, abort2, wait4} (§5).
    pub fn uses_b(&self) -> bool {
        matches!(self.state, WAIT3 | CH2 | ABORT2 | WAIT4)
    }

    /// Held in idle1 with every register cleared (normal mode, reset mode); the
    /// statistics stay.
    fn hold(&mut self) {
        *self = MainFsm {
            last_tx_time: self.last_tx_time,
            switch_time: self.switch_time,
            switches: self.switches,
            ..MainFsm::default()
        };
    }

    /// One rising edge.
    pub fn edge(&mut self, i: &FsmInputs) -> FsmEvents {
        let mut ev = FsmEvents::default();
        if !i.running {
            self.hold();
            return ev;
        }
        let c = *self;
        let mut n = c;
        n.pulses_and_time(&c, i);
        // Star node (§4.4): the other channel heard the attempted message, which was
        // therefore exchanged on the one domain; this row comes first in every state.
        let echo = i.echo_a || i.echo_b;
        match c.state {
            _ if echo => n.star_echo(&c, i, &mut ev),
            IDLE1 | WAIT1 | CH1 | ABORT1 | WAIT2 => n.rows_a(&c, i, &mut ev),
            IDLE2 | WAIT3 | CH2 | ABORT2 | WAIT4 => n.rows_b(&c, i, &mut ev),
            // Unused encodings 10..15: back to idle1.
            _ => n.state = IDLE1,
        }
        n.edge_end(&c, &mut ev);
        *self = n;
        ev
    }

    /// The edge's start, on the registers after it (`self`, a copy of `c`): the
    /// pulse registers fall, `tx_success` follows `finish_q`, `tx_time` counts
    /// the tick.
    fn pulses_and_time(&mut self, c: &MainFsm, i: &FsmInputs) {
        // Pulse registers.
        self.req_a = false;
        self.req_b = false;
        self.abort_a = false;
        self.abort_b = false;
        self.transmission_ack = false;
        self.tx_failure = false;
        self.tx_success = c.finish_q;
        if i.tick {
            self.tx_time = c.tx_time.saturating_add(1);
        }
    }

    /// "finish" with the given tx_ok_channel (§4.1).
    fn finish(&mut self, c: &MainFsm, ev: &mut FsmEvents, ok: u8) {
        ev.pop = true;
        self.resend = false;
        self.copy = false;
        self.attempted = false;
        self.last_tx_time = c.tx_time;
        self.tx_ok_channel = ok;
    }

    /// "A delivered" (§4.1).
    fn a_delivered(&mut self, c: &MainFsm, i: &FsmInputs, ev: &mut FsmEvents) {
        self.transmission_ack = true;
        if i.dual_tx && i.vb {
            self.copy = true;
            self.state = IDLE2;
        } else {
            self.finish(c, ev, 0b01);
            self.state = IDLE1;
        }
    }

    /// "B delivered" (§4.1); the caller sets the next state.
    fn b_delivered(&mut self, c: &MainFsm, ev: &mut FsmEvents) {
        self.transmission_ack = true;
        self.finish(c, ev, if c.copy { 0b11 } else { 0b10 });
    }

    /// The star node's echo row (§4.4), in any state: the message is finished,
    /// the attempt in flight aborted.
    fn star_echo(&mut self, c: &MainFsm, i: &FsmInputs, ev: &mut FsmEvents) {
        coverage::hit_with(|| coverage::star_echo(c.state));
        self.transmission_ack = true;
        self.finish(c, ev, if i.echo_b { 0b01 } else { 0b10 });
        self.abort_a = matches!(c.state, CH1 | ABORT1 | WAIT2);
        self.abort_b = matches!(c.state, CH2 | ABORT2);
        self.state = match c.state {
            IDLE2 | WAIT3 | CH2 | ABORT2 => IDLE2,
            WAIT4 if !i.va => IDLE2,
            _ => IDLE1,
        };
        if c.state == WAIT4 && self.state == IDLE1 {
            self.failover = false;
        }
    }

    /// Table 1's rows of the states on channel A (idle1, wait1, ch1, abort1,
    /// wait2): start an attempt on A, judge it, abort it or fail over to B.
    fn rows_a(&mut self, c: &MainFsm, i: &FsmInputs, ev: &mut FsmEvents) {
        match c.state {
            IDLE1 => {
                if !i.va && i.vb {
                    self.state = IDLE2;
                    self.failover = true;
                } else if i.q {
                    self.state = WAIT1;
                }
            }
            WAIT1 => {
                if !i.pending_a {
                    self.state = CH1;
                    self.req_a = true;
                    if !c.resend && !c.copy {
                        self.tx_time = 0;
                    }
                }
            }
            CH1 => {
                if i.done_a {
                    self.a_delivered(c, i, ev);
                } else if !i.va && i.vb {
                    self.state = ABORT1;
                }
            }
            ABORT1 => {
                if i.done_a {
                    self.a_delivered(c, i, ev);
                } else {
                    self.state = WAIT2;
                    self.abort_a = true;
                }
            }
            WAIT2 => {
                if i.done_a {
                    self.a_delivered(c, i, ev);
                } else if i.failed_a || (!i.pending_a && !c.abort_a) {
                    self.state = IDLE2;
                    self.tx_failure = true;
                    self.tx_failure_channel = 0b01;
                    self.resend = true;
                    self.failover = true;
                    self.switch_time = c.tx_time;
                }
            }
            _ => unreachable!("not a state on channel A"),
        }
    }

    /// Table 1's rows of the states on channel B (idle2, wait3, ch2, abort2,
    /// wait4): start an attempt on B (a resend, a copy or a new message),
    /// judge it, abort it or go back to A.
    fn rows_b(&mut self, c: &MainFsm, i: &FsmInputs, ev: &mut FsmEvents) {
        match c.state {
            IDLE2 => {
                if c.resend || c.copy {
                    self.state = WAIT3;
                } else if i.va {
                    self.state = WAIT4;
                } else if i.q {
                    self.state = WAIT3;
                }
            }
            WAIT3 => {
                if !i.pending_b {
                    self.state = CH2;
                    self.req_b = true;
                    if !c.resend && !c.copy {
                        self.tx_time = 0;
                    }
                }
            }
            CH2 => {
                if i.done_b {
                    self.b_delivered(c, ev);
                    self.state = IDLE2;
                } else if !i.vb && i.va {
                    self.state = ABORT2;
                }
            }
            ABORT2 => {
                if i.done_b {
                    self.b_delivered(c, ev);
                    self.state = IDLE2;
                } else {
                    self.state = WAIT4;
                    self.abort_b = true;
                }
            }
            WAIT4 => {
                if i.done_b {
                    self.b_delivered(c, ev);
                    self.state = if i.va { IDLE1 } else { IDLE2 };
                } else if i.failed_b || (!i.pending_b && !c.abort_b) {
                    self.state = if i.va { IDLE1 } else { IDLE2 };
                    if i.failed_b {
                        self.tx_failure = true;
                        self.tx_failure_channel = if i.va { 0b10 } else { 0b11 };
                    }
                    if c.copy {
                        self.finish(c, ev, 0b01);
                    }
                }
                if self.state == IDLE1 {
                    self.failover = false;
                }
            }
            _ => unreachable!("not a state on channel B"),
        }
    }

    /// The edge's end: the transition's coverage, `attempted`, `finish_q`, the
    /// switch count and the events.
    fn edge_end(&mut self, c: &MainFsm, ev: &mut FsmEvents) {
        if self.state != c.state {
            coverage::hit_with(|| coverage::main_transition(c.state, self.state));
        }
        if self.req_a || self.req_b {
            self.attempted = true;
        }
        self.finish_q = self.transmission_ack && ev.pop;
        if self.failover != c.failover {
            ev.switch = true;
            self.switches = c.switches.saturating_add(1);
        }
        ev.tx_success = self.tx_success;
        ev.tx_failure = self.tx_failure;
    }
}
