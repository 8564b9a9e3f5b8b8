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
        // Pulse registers.
        n.req_a = false;
        n.req_b = false;
        n.abort_a = false;
        n.abort_b = false;
        n.transmission_ack = false;
        n.tx_failure = false;
        n.tx_success = c.finish_q;
        if i.tick {
            n.tx_time = c.tx_time.saturating_add(1);
        }
        // "finish" with the given tx_ok_channel (§4.1).
        let finish = |n: &mut MainFsm, ev: &mut FsmEvents, ok: u8| {
            ev.pop = true;
            n.resend = false;
            n.copy = false;
            n.attempted = false;
            n.last_tx_time = c.tx_time;
            n.tx_ok_channel = ok;
        };
        // "A delivered" (§4.1).
        let a_delivered = |n: &mut MainFsm, ev: &mut FsmEvents| {
            n.transmission_ack = true;
            if i.dual_tx && i.vb {
                n.copy = true;
                n.state = IDLE2;
            } else {
                finish(n, ev, 0b01);
                n.state = IDLE1;
            }
        };
        // "B delivered" (§4.1); the caller sets the next state.
        let b_delivered = |n: &mut MainFsm, ev: &mut FsmEvents| {
            n.transmission_ack = true;
            finish(n, ev, if c.copy { 0b11 } else { 0b10 });
        };
        // Star node (§4.4): the other channel heard the attempted message, which was
        // therefore exchanged on the one domain; this row comes first in every state.
        let echo = i.echo_a || i.echo_b;
        match c.state {
            _ if echo => {
                coverage::hit_with(|| coverage::star_echo(c.state));
                n.transmission_ack = true;
                finish(&mut n, &mut ev, if i.echo_b { 0b01 } else { 0b10 });
                n.abort_a = matches!(c.state, CH1 | ABORT1 | WAIT2);
                n.abort_b = matches!(c.state, CH2 | ABORT2);
                n.state = match c.state {
                    IDLE2 | WAIT3 | CH2 | ABORT2 => IDLE2,
                    WAIT4 if !i.va => IDLE2,
                    _ => IDLE1,
                };
                if c.state == WAIT4 && n.state == IDLE1 {
                    n.failover = false;
                }
            }
            IDLE1 => {
                if !i.va && i.vb {
                    n.state = IDLE2;
                    n.failover = true;
                } else if i.q {
                    n.state = WAIT1;
                }
            }
            WAIT1 => {
                if !i.pending_a {
                    n.state = CH1;
                    n.req_a = true;
                    if !c.resend && !c.copy {
                        n.tx_time = 0;
                    }
                }
            }
            CH1 => {
                if i.done_a {
                    a_delivered(&mut n, &mut ev);
                } else if !i.va && i.vb {
                    n.state = ABORT1;
                }
            }
            ABORT1 => {
                if i.done_a {
                    a_delivered(&mut n, &mut ev);
                } else {
                    n.state = WAIT2;
                    n.abort_a = true;
                }
            }
            WAIT2 => {
                if i.done_a {
                    a_delivered(&mut n, &mut ev);
                } else if i.failed_a || (!i.pending_a && !c.abort_a) {
                    n.state = IDLE2;
                    n.tx_failure = true;
                    n.tx_failure_channel = 0b01;
                    n.resend = true;
                    n.failover = true;
                    n.switch_time = c.tx_time;
                }
            }
            IDLE2 => {
                if c.resend || c.copy {
                    n.state = WAIT3;
                } else if i.va {
                    n.state = WAIT4;
                } else if i.q {
                    n.state = WAIT3;
                }
            }
            WAIT3 => {
                if !i.pending_b {
                    n.state = CH2;
                    n.req_b = true;
                    if !c.resend && !c.copy {
                        n.tx_time = 0;
                    }
                }
            }
            CH2 => {
                if i.done_b {
                    b_delivered(&mut n, &mut ev);
                    n.state = IDLE2;
                } else if !i.vb && i.va {
                    n.state = ABORT2;
                }
            }
            ABORT2 => {
                if i.done_b {
                    b_delivered(&mut n, &mut ev);
                    n.state = IDLE2;
                } else {
                    n.state = WAIT4;
                    n.abort_b = true;
                }
            }
            WAIT4 => {
                if i.done_b {
                    b_delivered(&mut n, &mut ev);
                    n.state = if i.va { IDLE1 } else { IDLE2 };
                } else if i.failed_b || (!i.pending_b && !c.abort_b) {
                    n.state = if i.va { IDLE1 } else { IDLE2 };
                    if i.failed_b {
                        n.tx_failure = true;
                        n.tx_failure_channel = if i.va { 0b10 } else { 0b11 };
                    }
                    if c.copy {
                        finish(&mut n, &mut ev, 0b01);
                    }
                }
                if n.state == IDLE1 {
                    n.failover = false;
                }
            }
            // Unused encodings 10..15: back to idle1.
            _ => n.state = IDLE1,
        }
        if n.state != c.state {
            coverage::hit_with(|| coverage::main_transition(c.state, n.state));
        }
        if n.req_a || n.req_b {
            n.attempted = true;
        }
        n.finish_q = n.transmission_ack && ev.pop;
        if n.failover != c.failover {
            ev.switch = true;
            n.switches = c.switches.saturating_add(1);
        }
        ev.tx_success = n.tx_success;
        ev.tx_failure = n.tx_failure;
        *self = n;
        ev
    }
}
