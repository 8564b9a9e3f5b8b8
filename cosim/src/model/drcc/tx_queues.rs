//! TX buffer RAM and its two queues (contract §6): 16 x 99-bit synchronous RAM,
//! queue A = entries 0..Q-1, queue B = 8..8+Q-1 (`Q` the queue depth, §1.1); the registered read port feeding both
//! channels; the normal-mode request / busy logic of each channel. In DMR mode
//! (dmr_contract.md §5) queue A is the one logical queue, read at `head + off[L]`
//! for the line the read port serves; the DMR block pops what both lines sent.
//! The host's abort (§11.5) drops a queue's frames behind the one in the channel
//! (normal mode) or behind the head (redundancy mode).
//!
//! Abort readings: "DMR mode" is `CTRL.dmr` as written, so an abort is refused
//! while `CTRL.dmr` is set even in reset mode; an abort of a queue that is
//! neither held nor counted (count 0) is legal and does nothing; `abort_b` in
//! redundancy mode is not refused.

use crate::frame::Frame;

/// What the TX queues sample at an edge (pre-edge values and this edge's requests).
#[derive(Clone, Copy, Debug, Default)]
pub struct TxqInputs {
    pub reset_mode: bool,
    pub redundancy: bool,
    /// A `TX_CMD.push` write at this edge, with its target queue.
    pub push: Option<(usize, Frame)>,
    /// A `TX_CMD` write with `abort_a` / `abort_b` at this edge, already judged
    /// legal (no `push`, not DMR mode, §11.5).
    pub abort: [bool; 2],
    /// Redundancy mode: the main FSM's "finish" pops queue A.
    pub fsm_pop: bool,
    /// DMR mode: the read offset `off[rd_sel]` and the entries to pop (§5).
    pub dmr: Option<(u8, u8)>,
    /// Channel `tx_done` / `tx_failed` pulses (registered channel outputs).
    pub done: [bool; 2],
    pub failed: [bool; 2],
}

/// What the TX queues did at an edge.
#[derive(Clone, Copy, Debug, Default)]
pub struct TxqEvents {
    /// The push was refused (reset mode or queue full): INT_STATUS.illegal.
    pub push_refused: bool,
    /// Normal mode: INT_STATUS.tx_done / tx_failure.
    pub tx_done: bool,
    pub tx_failure: bool,
}

/// The TX RAM, the queue pointers and the normal-mode request logic.
#[derive(Clone, Debug)]
pub struct TxQueues {
    ram: [Frame; 16],
    pub head: [u8; 2],
    pub count: [u8; 2],
    /// RAM read data register: the channels' `tx_*` inputs.
    pub rd: Frame,
    /// Normal mode: which queue the read port serves (toggles every edge).
    pub rd_sel: u8,
    /// Normal mode: channel `tx_req` pulses.
    pub req: [bool; 2],
    pub busy: [bool; 2],
    /// Normal mode: the channels' `tx_abort` pulse registers (§11.5), set at the
    /// edge of a host abort that keeps the frame the channel holds.
    pub abort: [bool; 2],
    /// Entries per queue `Q` (generation parameter, not reset).
    pub depth: u8,
}

impl Default for TxQueues {
    /// The default configuration's queues (8 entries each).
    fn default() -> Self {
        TxQueues {
            ram: [Frame::default(); 16],
            head: [0; 2],
            count: [0; 2],
            rd: Frame::default(),
            rd_sel: 0,
            req: [false; 2],
            busy: [false; 2],
            abort: [false; 2],
            depth: 8,
        }
    }
}

impl TxQueues {
    /// A `rst` edge: the read port loads as at every edge (RAM contents are not
    /// reset), every register clears.
    pub fn reset(&mut self, redundancy: bool, dmr_off: Option<u8>) {
        let rd = self.read_port(redundancy, dmr_off);
        *self = TxQueues {
            ram: self.ram,
            depth: self.depth,
            rd,
            ..TxQueues::default()
        };
    }

    /// A queue pair of `depth` entries each (2, 4 or 8).
    pub fn new(depth: u8) -> Self {
        TxQueues {
            depth,
            ..TxQueues::default()
        }
    }

    /// `Q`: entries per queue.
    fn q(&self) -> u8 {
        self.depth
    }

    /// The entry the read port addresses (pre-edge registers).
    fn read_port(&self, redundancy: bool, dmr_off: Option<u8>) -> Frame {
        if let Some(off) = dmr_off {
            return self.ram[((self.head[0] + off) & (self.q() - 1)) as usize];
        }
        let q = if redundancy { 0 } else { self.rd_sel as usize };
        self.ram[q * 8 + self.head[q] as usize]
    }

    /// One rising edge.
    pub fn edge(&mut self, i: &TxqInputs) -> TxqEvents {
        let mut ev = TxqEvents::default();
        // Registered read port, from the pre-edge address and RAM (read-first).
        self.rd = self.read_port(i.redundancy, i.dmr.map(|d| d.0));
        if i.reset_mode {
            ev.push_refused = i.push.is_some();
            self.head = [0; 2];
            self.count = [0; 2];
            self.rd_sel = 0;
            self.req = [false; 2];
            self.busy = [false; 2];
            self.abort = [false; 2];
            return ev;
        }
        let (head, count) = (self.head, self.count);
        let mut pop = [false; 2];
        let mut dmr_pop = 0;
        // §11.5: what an abort leaves in each queue (None: no abort of that queue).
        let mut kept: [Option<u8>; 2] = [None; 2];
        self.abort = [false; 2];
        if let Some((_, p)) = i.dmr {
            // DMR: the lines' own request logic lives in the DMR block (§5).
            dmr_pop = p.min(count[0]);
            self.req = [false; 2];
            self.busy = [false; 2];
            self.rd_sel ^= 1;
        } else if i.redundancy {
            pop[0] = i.fsm_pop;
            // The head stays unless the main FSM pops it at this edge.
            if i.abort[0] {
                kept[0] = Some((count[0] != 0 && !i.fsm_pop) as u8);
            }
            self.req = [false; 2];
            self.busy = [false; 2];
            self.rd_sel = 0;
        } else {
            let (req, busy) = (self.req, self.busy);
            for c in 0..2 {
                self.req[c] =
                    self.rd_sel as usize == c && count[c] > 0 && !busy[c] && !req[c] && !i.abort[c];
                if i.abort[c] {
                    // Only the frame channel c holds stays, and the channel is
                    // told to drop it at the next edge.
                    let held = busy[c] && !i.done[c] && !i.failed[c];
                    kept[c] = Some(held as u8);
                    self.abort[c] = held;
                }
                if i.done[c] || i.failed[c] {
                    pop[c] = true;
                    self.busy[c] = false;
                    ev.tx_done |= i.done[c];
                    ev.tx_failure |= i.failed[c];
                } else if self.req[c] {
                    self.busy[c] = true;
                }
            }
            self.rd_sel ^= 1;
        }
        let mut push_q = None;
        if let Some((q, frame)) = i.push {
            if count[q] >= self.q() {
                ev.push_refused = true;
            } else {
                self.ram[q * 8 + ((head[q] + count[q]) & (self.q() - 1)) as usize] = frame;
                push_q = Some(q);
            }
        }
        for c in 0..2 {
            let popped = if c == 0 && dmr_pop > 0 {
                dmr_pop
            } else {
                (pop[c] && count[c] > 0) as u8
            };
            self.head[c] = (head[c] + popped) & (self.q() - 1);
            self.count[c] = match kept[c] {
                Some(k) => k,
                None => count[c] + (push_q == Some(c)) as u8 - popped,
            };
        }
        ev
    }
}
