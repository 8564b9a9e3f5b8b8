//! DMR state machine, connection service and fault recovery (dmr_contract.md §6
//! and §7, the seed's Figures 6, 7 and 8): the fault flags per line and their
//! sources (evaluation, bus-off, failed CS attempt), the ACL switch, `dmr_state`,
//! the CS timeout, the periodic CS, the recovery delay and the channel restart.

use super::super::regs::dmr::*;
use super::engine::EvalFault;
use super::{DmrBlock, DmrEvents, DmrInputs};
use crate::model::coverage;

/// A fault set against a line at this edge.
#[derive(Clone, Copy, Debug)]
struct Fault {
    line: usize,
    /// `tx_fault` (true) or `rx_fault`.
    tx: bool,
    cause: u8,
    mb: Option<u8>,
}

impl DmrBlock {
    /// Faults, CS outcome, recovery and the state machine at one edge, on pre-edge
    /// values `c`; `eval` is this edge's evaluation verdict (§4.2). Returns the lines
    /// whose `tx_fault` is set at this edge (the deletion of §5).
    pub(super) fn faults(
        &mut self,
        c: &DmrBlock,
        i: &DmrInputs,
        eval: Option<EvalFault>,
        ev: &mut DmrEvents,
    ) -> [bool; 2] {
        let mut faults: Vec<Fault> = Vec::new();
        let recovered = self.cs_attempts(c, i, &mut faults);
        self.busoff_faults(c, i, &mut faults);
        // §4.2: the evaluation's verdict against a line.
        if let Some(f) = eval {
            faults.push(Fault {
                line: f.verdict.line,
                tx: f.verdict.dir,
                cause: if f.verdict.deviation {
                    CAUSE_DEVIATION
                } else {
                    CAUSE_TIMEOUT
                },
                mb: Some(f.mb),
            });
        }
        self.recovery_timers(c, i);
        self.periodic_cs(c);
        let (against, tx_set) = self.set_faults(c, &faults);
        if recovered {
            self.mbx.clear_for_recovery();
        }
        self.acl_and_state(c, against, ev);
        tx_set
    }

    /// §7 the connection service attempts: the timeout of a live attempt (a
    /// failed CS is a fault) and its success, which clears the line's flags.
    /// Returns whether a line recovered (it had a flag).
    fn cs_attempts(&mut self, c: &DmrBlock, i: &DmrInputs, faults: &mut Vec<Fault>) -> bool {
        let dt = c.dmr_tick;
        let mut recovered = false;
        for l in 0..2 {
            // §7 CS attempt: its timeout counts DMR ticks while it is live.
            if c.cs_busy[l] && c.cs_live[l] && dt {
                self.cs_timer[l] = c.cs_timer[l].saturating_sub(1);
                if c.cs_timer[l] == 1 {
                    faults.push(Fault {
                        line: l,
                        tx: true,
                        cause: CAUSE_CS_FAILED,
                        mb: None,
                    });
                }
            }
            // §7 success: "Upon successful transmission of the DMR Connection
            // Service the DMR state is updated".
            if i.done[l] && c.cs_busy[l] && c.cs_live[l] {
                self.tx_fault[l] = false;
                self.rx_fault[l] = false;
                self.rec_timer[l] = 0;
                // A recovery (the line had a flag): the counts of the fault period
                // are no evidence about the restored line; every mailbox restarts
                // balanced (§7).
                if c.tx_fault[l] || c.rx_fault[l] {
                    coverage::hit("dmr: recovery (connection service after a fault)");
                    recovered = true;
                }
            }
        }
        recovered
    }

    /// §6 bus-off: a channel entering bus-off at this edge is a fault.
    fn busoff_faults(&mut self, c: &DmrBlock, i: &DmrInputs, faults: &mut Vec<Fault>) {
        for l in 0..2 {
            // §6 bus-off: the channel enters bus-off at this edge.
            let busoff = i.err_state[l] == 2;
            self.busoff_q[l] = busoff;
            if busoff && !c.busoff_q[l] {
                faults.push(Fault {
                    line: l,
                    tx: true,
                    cause: CAUSE_BUSOFF,
                    mb: None,
                });
            }
        }
    }

    /// §7 recovery: the recovery delay of a flagged line and the channel
    /// restart it leads to.
    fn recovery_timers(&mut self, c: &DmrBlock, i: &DmrInputs) {
        let dt = c.dmr_tick;
        // §7 recovery: while L has a flag, `rec_timer` counts DMR ticks; at 1 -> 0
        // the line is due for a restart and a CS frame.
        for l in 0..2 {
            let flagged = c.tx_fault[l] || c.rx_fault[l];
            if flagged && dt && c.rec_timer[l] != 0 {
                self.rec_timer[l] = c.rec_timer[l] - 1;
                if c.rec_timer[l] == 1 {
                    self.rec_pending[l] = true;
                    self.cs_due[l] = true;
                }
            }
            // The restart pulse waits for the line to be quiet; a bus-off channel
            // recovers by itself (ISO 11898-1 12.1.4.2), never cut short.
            self.restart[l] = false;
            if c.rec_pending[l] && !c.busy[l] && !c.cs_busy[l] && i.err_state[l] != 2 {
                self.rec_pending[l] = false;
                self.restart[l] = true;
            }
        }
    }

    /// §7 periodic CS: every CS period, a CS is due on each sound line.
    fn periodic_cs(&mut self, c: &DmrBlock) {
        let dt = c.dmr_tick;
        // §7 periodic CS for each line without a flag and no CS due or busy.
        if dt && c.cs_period() != 0 {
            if c.period_cnt >= c.cs_period() - 1 {
                self.period_cnt = 0;
                for l in 0..2 {
                    if !c.tx_fault[l] && !c.rx_fault[l] && !c.cs_due[l] && !c.cs_busy[l] {
                        self.cs_due[l] = true;
                    }
                }
            } else {
                self.period_cnt = c.period_cnt + 1;
            }
        }
    }

    /// §6 the faults of this edge set their flags, cause and recovery delay and
    /// cancel the line's connection service. Returns the lines a fault counts
    /// against and those whose `tx_fault` is set.
    fn set_faults(&mut self, c: &DmrBlock, faults: &[Fault]) -> ([bool; 2], [bool; 2]) {
        // §6 set the faults (they win over a success at the same edge).
        let mut against = [false; 2];
        let mut tx_set = [false; 2];
        for f in faults {
            let l = f.line;
            coverage::hit_with(|| {
                let cause = match f.cause {
                    CAUSE_CS_FAILED => "connection service failed",
                    CAUSE_BUSOFF => "bus-off",
                    CAUSE_DEVIATION => "deviation",
                    _ => "timeout",
                };
                let dir = if f.tx { "tx" } else { "rx" };
                format!("dmr: {dir} fault ({cause})")
            });
            // §6: a receive fault against a line already unable to transmit only
            // records itself: the imbalance it saw is the deleted copies of that
            // known fault (its own and the other devices'); it neither reloads the
            // recovery delay nor cancels the line's CS, which alone decides.
            if !f.tx && c.tx_fault[l] {
                coverage::hit("dmr: rx fault on a line already unable to transmit");
                self.rx_fault[l] = true;
                self.cause = f.cause;
                self.cause_line = l as u8;
                if let Some(mb) = f.mb {
                    self.cause_mb = mb;
                }
                continue;
            }
            against[l] = true;
            if f.tx {
                self.tx_fault[l] = true;
                tx_set[l] = true;
                // Deletion (§5): the attempt on the bus runs on, further ones abort.
                if c.busy[l] {
                    self.abort[l] = true;
                }
            } else {
                self.rx_fault[l] = true;
            }
            self.cause = f.cause;
            self.cause_line = l as u8;
            if let Some(mb) = f.mb {
                self.cause_mb = mb;
            }
            self.rec_timer[l] = c.recovery_delay();
            // L's connection service is cancelled.
            self.cs_due[l] = false;
            self.cs_live[l] = false;
            self.rec_pending[l] = false;
            if c.cs_busy[l] {
                self.abort[l] = true;
            }
        }
        (against, tx_set)
    }

    /// §6 the ACL switch, `dmr_state` and their counts (`INT_STATUS.dmr`).
    fn acl_and_state(&mut self, c: &DmrBlock, against: [bool; 2], ev: &mut DmrEvents) {
        // ACL switch: a fault against the ACL while the other line is sound.
        let a = c.acl as usize;
        let o = 1 - a;
        if against[a] && !c.tx_fault[o] && !c.rx_fault[o] && !against[o] {
            self.acl = c.acl ^ 1;
            ev.acl_switch = true;
            coverage::hit("dmr: ACL switch");
        }
        // `dmr_state` from the flags before the edge (seed Figure 6).
        self.dmr_state = match (c.tx_fault[0] as u8 + c.tx_fault[1] as u8, c.rx_fault) {
            (2, _) => DISCONNECTED,
            (1, _) => DISABLED,
            (_, [false, false]) => ACTIVE,
            _ => PASSIVE,
        };
        if self.dmr_state != c.dmr_state {
            coverage::hit_with(|| {
                let s = |x| match x {
                    ACTIVE => "active",
                    PASSIVE => "passive",
                    DISABLED => "disabled",
                    _ => "disconnected",
                };
                format!("dmr: state {} -> {}", s(c.dmr_state), s(self.dmr_state))
            });
            self.state_changes = c.state_changes.saturating_add(1);
            ev.int = true;
        }
        if self.acl != c.acl {
            self.acl_switches = c.acl_switches.saturating_add(1);
            ev.int = true;
        }
    }
}
