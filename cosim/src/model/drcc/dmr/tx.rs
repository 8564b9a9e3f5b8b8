//! DMR transmission (dmr_contract.md §5, the seed's "duplication of packets"): one
//! logical queue (TX queue A) read by both lines through their offsets; per line
//! the host-copy and CS request logic, the completion rule (the host's `tx_done` at
//! the first copy), the deletion of a faulty line's copies and its return.

use super::engine::Raised;
use super::mailboxes::Key;
use super::{DmrBlock, DmrEvents, DmrInputs};

impl DmrBlock {
    /// Requests and completions of both lines (§5), on pre-edge values `c`.
    /// Returns the offset increments of this edge.
    pub(super) fn tx_requests(
        &mut self,
        c: &DmrBlock,
        i: &DmrInputs,
        raised: &mut Raised,
        ev: &mut DmrEvents,
    ) -> [bool; 2] {
        let sends = [!c.tx_fault[0], !c.tx_fault[1]];
        let mut inc = [false; 2];
        self.abort = [false; 2];
        for l in 0..2 {
            let o = 1 - l;
            // The channel's `rst`: reset_mode_q or a restart pulse (reset mode
            // itself holds the block). Interpretation 3: a pending restart also
            // holds the line's requests back.
            let chan_rst = i.reset_mode_q || c.restart[l];
            let free = !c.busy[l]
                && !c.req[l]
                && !c.cs_busy[l]
                && !c.cs_req[l]
                && !chan_rst
                && !c.rec_pending[l];
            let mine = i.rd_sel as usize == l;
            self.cs_req[l] = mine && c.cs_due[l] && free;
            if self.cs_req[l] {
                self.cs_busy[l] = true;
                self.cs_due[l] = false;
                self.cs_timer[l] = c.timeout();
                // §7: the attempt is live until a fault cancels it.
                self.cs_live[l] = true;
            }
            self.req[l] = mine && sends[l] && c.off[l] < i.q_count && !c.cs_due[l] && free;
            if self.req[l] {
                self.busy[l] = true;
            }
            // `REQ(L)`: the key of the message the request carries.
            if c.req[l] {
                let k = Key::of(&i.rd);
                self.key_sent[l] = k;
                raised.req[l] = Some(k);
            }
            // Completion at L's `tx_done` / `tx_failed`.
            if i.done[l] {
                if c.cs_busy[l] {
                    self.cs_busy[l] = false;
                } else if c.busy[l] {
                    self.busy[l] = false;
                    if sends[l] {
                        // The host hears of a message once, at its first copy.
                        if !sends[o] || c.off[l] >= c.off[o] {
                            ev.tx_done = true;
                        }
                        inc[l] = true;
                        // §4.1: transmit transfers count only while both lines send.
                        if !c.tx_fault[0] && !c.tx_fault[1] {
                            raised.tx[l] = Some(c.key_sent[l]);
                        }
                    }
                }
            } else if i.failed[l] {
                if c.cs_busy[l] {
                    self.cs_busy[l] = false;
                } else {
                    self.busy[l] = false;
                }
            }
        }
        inc
    }

    /// Offsets after this edge (§5): increments, deletion of a line whose
    /// `tx_fault` is set at this edge (`tx_set`), return of a line whose `tx_fault`
    /// clears, and the entries both sending lines left behind. Returns that count.
    pub(super) fn tx_offsets(&mut self, c: &DmrBlock, inc: [bool; 2], tx_set: [bool; 2]) -> u8 {
        let sends_after = [!self.tx_fault[0], !self.tx_fault[1]];
        let mut off = [0u8; 2];
        for l in 0..2 {
            off[l] = if tx_set[l] || !sends_after[l] {
                // Deletion: "any pending messages to be transmitted on the faulty
                // line ... must be deleted".
                0
            } else {
                c.off[l] + inc[l] as u8
            };
        }
        for l in 0..2 {
            let o = 1 - l;
            if c.tx_fault[l] && sends_after[l] {
                // Return: L sends every message the other line has not sent yet.
                off[l] = if sends_after[o] && !c.tx_fault[o] {
                    c.off[o] + inc[o] as u8
                } else {
                    0
                };
            }
        }
        let p = (0..2)
            .filter(|&l| sends_after[l])
            .map(|l| off[l])
            .min()
            .unwrap_or(0);
        for l in 0..2 {
            self.off[l] = if sends_after[l] { off[l] - p } else { 0 };
        }
        p
    }
}
