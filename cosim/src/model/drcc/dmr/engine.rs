//! The sequential DMR engine (dmr_contract.md §4.3, the seed's "DMR process
//! action"): seven event flags with their latched keys, served one job at a time;
//! an event job scans the mailboxes one per clock for the lowest match and updates
//! it (`M + 2` clocks), an evaluation visits every mailbox once (`M + 1` clocks).

use super::mailboxes::{Key, Mailboxes, Verdict, RECEIVE, TRANSMIT};

/// Engine states (§4.3).
pub const E_IDLE: u8 = 0;
pub const E_SCAN: u8 = 1;
pub const E_UPDATE: u8 = 2;
pub const E_EVAL: u8 = 3;

/// Event kinds of a job.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Kind {
    /// A transfer of a host message on a line (`TX(L)`).
    #[default]
    Tx,
    /// A received frame on a line (`RX(L)`).
    Rx,
    /// A transmission request on a line (`REQ(L)`).
    Req,
}

/// The events raised at an edge (flag set with its key).
#[derive(Clone, Copy, Debug, Default)]
pub struct Raised {
    pub tx: [Option<Key>; 2],
    pub rx: [Option<Key>; 2],
    pub req: [Option<Key>; 2],
    pub eval: bool,
}

/// Event registers and engine registers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Engine {
    pub pend_tx: [bool; 2],
    pub pend_rx: [bool; 2],
    pub pend_req: [bool; 2],
    pub pend_eval: bool,
    pub key_tx: [Key; 2],
    pub key_rx: [Key; 2],
    pub key_req: [Key; 2],
    pub e_state: u8,
    pub e_i: u8,
    pub e_kind: Kind,
    pub e_line: u8,
    pub e_key: Key,
    pub e_found: bool,
    pub e_hit: u8,
}

/// A fault found by an evaluation, with its mailbox.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EvalFault {
    pub verdict: Verdict,
    pub mb: u8,
}

impl Engine {
    /// One edge in DMR mode outside reset mode. `mbx` is updated in place: at most
    /// one mailbox changes per edge, judged on its values before the edge.
    pub fn edge(&mut self, r: &Raised, mbx: &mut Mailboxes, timeout: u16) -> Option<EvalFault> {
        let m = mbx.m();
        if m == 0 {
            // No mailboxes: no events, no evaluation (§2).
            *self = Engine::default();
            return None;
        }
        let c = *self;
        let last = (m - 1) as u8;
        let mut fault = None;
        // Sources set their flags (the newer key wins).
        for l in 0..2 {
            if let Some(k) = r.tx[l] {
                self.pend_tx[l] = true;
                self.key_tx[l] = k;
            }
            if let Some(k) = r.rx[l] {
                self.pend_rx[l] = true;
                self.key_rx[l] = k;
            }
            if let Some(k) = r.req[l] {
                self.pend_req[l] = true;
                self.key_req[l] = k;
            }
        }
        self.pend_eval |= r.eval;
        match c.e_state {
            E_IDLE => {
                // Fixed priority: tx DCL, tx RCL, rx DCL, rx RCL, req DCL, req RCL, eval.
                let mut job = None;
                for (kind, pend, keys, raised) in [
                    (Kind::Tx, c.pend_tx, c.key_tx, r.tx),
                    (Kind::Rx, c.pend_rx, c.key_rx, r.rx),
                    (Kind::Req, c.pend_req, c.key_req, r.req),
                ] {
                    if job.is_some() {
                        break;
                    }
                    for l in 0..2 {
                        if pend[l] {
                            job = Some((kind, l, keys[l], raised[l].is_some()));
                            break;
                        }
                    }
                }
                if let Some((kind, l, key, again)) = job {
                    // Taken: the flag clears unless its source sets it at this edge.
                    let flag = match kind {
                        Kind::Tx => &mut self.pend_tx[l],
                        Kind::Rx => &mut self.pend_rx[l],
                        Kind::Req => &mut self.pend_req[l],
                    };
                    *flag = again;
                    self.e_kind = kind;
                    self.e_line = l as u8;
                    self.e_key = key;
                    self.e_found = false;
                    self.e_i = 0;
                    self.e_state = E_SCAN;
                } else if c.pend_eval {
                    self.pend_eval = r.eval;
                    self.e_i = 0;
                    self.e_state = E_EVAL;
                }
            }
            E_SCAN => {
                let dir = if c.e_kind == Kind::Rx {
                    RECEIVE
                } else {
                    TRANSMIT
                };
                if !c.e_found && mbx.mb[c.e_i as usize].matches(&c.e_key, dir) {
                    self.e_found = true;
                    self.e_hit = c.e_i;
                }
                if c.e_i >= last {
                    self.e_state = E_UPDATE;
                } else {
                    self.e_i = c.e_i + 1;
                }
            }
            E_UPDATE => {
                if c.e_found {
                    let b = &mut mbx.mb[c.e_hit as usize];
                    match c.e_kind {
                        Kind::Req => b.request(timeout),
                        _ => b.step(c.e_line as usize, timeout),
                    }
                }
                self.e_state = E_IDLE;
            }
            _ => {
                let b = &mut mbx.mb[c.e_i as usize];
                if b.enable {
                    if let Some(verdict) = b.evaluate() {
                        fault = Some(EvalFault { verdict, mb: c.e_i });
                    }
                }
                if c.e_i >= last {
                    self.e_state = E_IDLE;
                } else {
                    self.e_i = c.e_i + 1;
                }
            }
        }
        fault
    }
}
