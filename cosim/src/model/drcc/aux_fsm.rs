//! Auxiliary FSM of one channel ("channel validity", contract §5): the failure
//! policies (error-passive, bus-off, k failed attempts, stall), the restart of a
//! failed channel and its probation before it is trusted again.

use super::regs::aux::*;
use super::regs::ctrl::{POLICY_KFAIL, POLICY_NONE, POLICY_PASSIVE, POLICY_WARNING};
use crate::model::coverage;

/// What one aux FSM samples at an edge (pre-edge values).
#[derive(Clone, Copy, Debug, Default)]
pub struct AuxInputs {
    /// Redundancy mode and not reset mode.
    pub running: bool,
    pub policy: u32,
    /// `k`, 1..15.
    pub k: u8,
    pub stall_limit: u16,
    pub recovery_bits: u16,
    pub tick: bool,
    /// The main FSM is in one of this channel's states.
    pub in_use: bool,
    /// A restart cannot cost a frame: the channel is at bus idle, and for channel
    /// B, A is valid (contract §5).
    pub restart_ok: bool,
    // The channel's registered outputs.
    pub tx_pending: bool,
    pub tx_done: bool,
    /// A frame received without error (clears the stall count: the line works).
    pub rx_valid: bool,
    pub err_valid: bool,
    pub err_tx: bool,
    pub err_state: u8,
    /// The channel's TEC or REC is at or above `ewl`.
    pub err_warning: bool,
    pub sample_point: bool,
}

/// What the aux FSM did at an edge.
#[derive(Clone, Copy, Debug, Default)]
pub struct AuxEvents {
    /// INT_STATUS.aux (valid -> failed, probation -> valid).
    pub int: bool,
    /// probation -> valid (STATS1 recoveries).
    pub recovered: bool,
}

/// One auxiliary FSM.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AuxFsm {
    pub state: u8,
    /// Failed attempts since the last success, saturating at 15.
    pub fail_cnt: u8,
    pub stall_cnt: u16,
    pub probe_cnt: u16,
    /// Latched causes (CAUSE_* bits).
    pub causes: u8,
    // Cleared only by `rst`.
    pub failures: u8,
    pub recoveries: u8,
}

impl AuxFsm {
    /// Channel `rst` contribution: the channel restarts while in `restart`.
    pub fn restarting(&self) -> bool {
        self.state == RESTART
    }

    /// AUX_x register value.
    pub fn reg(&self) -> u32 {
        self.state as u32
            | (self.causes as u32) << 2
            | (self.fail_cnt as u32) << 8
            | (self.failures as u32) << 16
            | (self.recoveries as u32) << 24
    }

    /// One rising edge.
    pub fn edge(&mut self, i: &AuxInputs) -> AuxEvents {
        let mut ev = AuxEvents::default();
        if !i.running {
            self.state = VALID;
            self.fail_cnt = 0;
            self.stall_cnt = 0;
            self.probe_cnt = 0;
            self.causes = 0;
            return ev;
        }
        let c = *self;
        let mut n = c;
        n.fail_cnt = if i.tx_done {
            0
        } else if i.err_valid && i.err_tx {
            (c.fail_cnt + 1).min(15)
        } else {
            c.fail_cnt
        };
        n.stall_cnt = if !i.tx_pending || i.rx_valid {
            0
        } else if i.tick {
            c.stall_cnt.saturating_add(1)
        } else {
            c.stall_cnt
        };
        match c.state {
            VALID => {
                let mut causes = 0;
                if i.policy == POLICY_PASSIVE && i.err_state != 0 {
                    causes |= CAUSE_PASSIVE;
                }
                if i.policy != POLICY_NONE && i.err_state == 2 {
                    causes |= CAUSE_BUSOFF;
                }
                if i.policy == POLICY_KFAIL && c.fail_cnt >= i.k {
                    causes |= CAUSE_KFAIL;
                }
                if i.policy != POLICY_NONE && i.stall_limit != 0 && c.stall_cnt >= i.stall_limit {
                    causes |= CAUSE_STALL;
                }
                if i.policy == POLICY_WARNING && i.err_warning {
                    causes |= CAUSE_WARNING;
                }
                if causes != 0 {
                    for (bit, name) in [
                        (CAUSE_PASSIVE, "aux: valid -> failed (error passive)"),
                        (CAUSE_BUSOFF, "aux: valid -> failed (bus-off)"),
                        (CAUSE_KFAIL, "aux: valid -> failed (k failed)"),
                        (CAUSE_STALL, "aux: valid -> failed (stall)"),
                        (CAUSE_WARNING, "aux: valid -> failed (warning limit)"),
                    ] {
                        if causes & bit != 0 {
                            coverage::hit(name);
                        }
                    }
                    n.state = FAILED;
                    n.causes |= causes;
                    n.failures = c.failures.saturating_add(1);
                    ev.int = true;
                }
            }
            FAILED => {
                if !i.tx_pending && i.err_state != 2 && !i.in_use && i.restart_ok {
                    coverage::hit("aux: failed -> restart");
                    n.state = RESTART;
                    n.fail_cnt = 0;
                }
            }
            RESTART => {
                coverage::hit("aux: restart -> probation");
                n.state = PROBATION;
                n.probe_cnt = 0;
            }
            _ => {
                if c.probe_cnt >= i.recovery_bits.max(1) {
                    coverage::hit("aux: probation -> valid");
                    n.state = VALID;
                    n.recoveries = c.recoveries.saturating_add(1);
                    ev.recovered = true;
                    ev.int = true;
                }
                n.probe_cnt = if i.err_valid {
                    if c.probe_cnt > 0 && n.state == PROBATION {
                        coverage::hit("aux: probation count restarted by an error");
                    }
                    0
                } else if i.sample_point {
                    c.probe_cnt.saturating_add(1)
                } else {
                    c.probe_cnt
                };
            }
        }
        *self = n;
        ev
    }
}
