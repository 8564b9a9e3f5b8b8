//! TX message buffer (DRCC contract §6): one synchronous RAM of 16 frames x 99
//! bits (id, ide, rtr, dlc, data: the channel's `tx_*` ports), two circular
//! queues of `Q` (queue A = entries 0..Q-1, queue B = 8..8+Q-1, the queue bit is
//! the address MSB), and the normal-mode request logic. Generation parameter `Q`
//! (2, 4 or 8, default 8; `crate::config`): the 3-bit pointers wrap through
//! `qmask = Q - 1` (constant-zero upper bits for a smaller queue, removed by
//! synthesis); the register block refuses a push when the count is `Q`. A pushed frame is stored
//! normalized (`super::tx_normalize`: as a receiver delivers it), so the read
//! data compares with a received frame (the echo of contract §4.4).
//!
//! The RAM read data register is loaded at every edge from
//! `redundancy ? {0, head_a} : {rd_sel, head[rd_sel]}`; `rd_sel` toggles at every
//! edge in normal mode, so a normal-mode request `req_c` is raised only at an edge
//! where the read data being loaded is queue c's head. In redundancy mode queue A
//! is the one logical queue and the main FSM pops it (`pop_red`).
//!
//! Host abort (contract §11.5): normal mode, queue c keeps only the frame
//! channel c holds (`busy_c` and not ending at this edge) and that channel gets
//! `tx_abort` one clock later; redundancy mode, queue A keeps only its head
//! (the redundancy manager's message). No request is raised at an abort edge.
//! Frame layout (the TX_ID register bits in [98:68]): [98] rtr, [97] ide,
//! [96:68] id, [67:64] dlc, [63:0] data (byte 0 in [63:56], as the channel ports).
//!
//! Block RAM without read-before-write emulation (`super::bram`): the read meets
//! the write only when a push goes to the empty queue being read (`head +
//! count == head` with `count < 8`). The read data loaded there is never used:
//! a channel takes `tx_*` only at an edge where its `tx_req` is high, and the
//! request of the next edge needs the queue non-empty before this one (normal
//! mode: `count_c != 0`; redundancy mode: the main FSM requests only in `wait1`
//! / `wait3`, which hold the frame being sent in queue A until its pop; DMR
//! mode: a line requests only while its offset is below `count`, so its entry
//! is never the one a push writes).
//!
//! DMR mode (dmr_contract.md §5): queue A is the one logical queue, read at
//! `head_a + off[rd_sel]` for the line the read port serves (`rd_sel` toggles
//! as in normal mode); the line logic lives in the DMR control
//! (`crate::dmr`), which pops the entries both lines have sent (`dmr_pop`,
//! any number at one edge).

use super::bram::Bram;
use super::tx_normalize::FrameNormalizer;
use crate::channel::sized::Param;
use rust_hdl::prelude::*;

/// TX buffer: RAM, two queues, normal-mode requests.
#[derive(LogicBlock)]
pub struct TxBuffer {
    // clock and clear (rst or reset mode: both queues emptied)
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst` or reset mode: both queues are emptied.
    pub clear: Signal<In, Bit>,
    /// Redundancy mode: queue A is the one logical queue, popped by the main FSM; no requests here.
    pub redundancy: Signal<In, Bit>,
    // DMR mode: the lines' read offsets and the entries they left behind
    /// `CTRL.dmr`: queue A is read at `head_a + off[rd_sel]`, popped by `dmr_pop`.
    pub dmr: Signal<In, Bit>,
    /// DMR: the DCL's offset `off[0]` mod 8 (a register of the DMR control).
    pub off_dcl: Signal<In, Bits<3>>,
    /// DMR: the RCL's offset `off[1]` mod 8.
    pub off_rcl: Signal<In, Bits<3>>,
    /// DMR: entries of queue A both lines have sent, popped at this edge.
    pub dmr_pop: Signal<In, Bits<4>>,
    // push (already accepted by the register block) and the staged frame
    /// Push the staged frame at this edge (the register block checked the queue is not full).
    pub push: Signal<In, Bit>,
    /// The queue a push goes to: 0 = A, 1 = B.
    pub push_q: Signal<In, Bit>,
    /// The staged frame (layout above); the RAM stores it normalized (§6).
    pub push_frame: Signal<In, Bits<99>>,
    // redundancy mode: the main FSM's finish
    /// The main FSM's finish (its `pop`): queue A's head leaves (redundancy mode).
    pub pop_red: Signal<In, Bit>,
    // host abort (contract §11.5, already accepted by the register block)
    /// `TX_CMD.abort_a`: queue A keeps only the frame a channel holds.
    pub abort_a: Signal<In, Bit>,
    /// `TX_CMD.abort_b` (normal mode).
    pub abort_b: Signal<In, Bit>,
    /// Normal mode: channel A's `tx_abort`, one clock after an abort that kept
    /// the frame channel A holds.
    pub chan_abort_a: Signal<Out, Bit>,
    /// Normal mode: channel B's `tx_abort`.
    pub chan_abort_b: Signal<Out, Bit>,
    // channel events
    /// Channel A's `tx_done` pulse: in normal mode queue A's head leaves.
    pub done_a: Signal<In, Bit>,
    /// Channel A's `tx_failed` pulse: in normal mode queue A's head is dropped.
    pub failed_a: Signal<In, Bit>,
    /// Channel B's `tx_done` pulse: in normal mode queue B's head leaves.
    pub done_b: Signal<In, Bit>,
    /// Channel B's `tx_failed` pulse: in normal mode queue B's head is dropped.
    pub failed_b: Signal<In, Bit>,
    // outputs
    /// Frames in queue A (`STATUS.txq_a_count`).
    pub count_a: Signal<Out, Bits<4>>,
    /// Frames in queue B (`STATUS.txq_b_count`).
    pub count_b: Signal<Out, Bits<4>>,
    /// RAM read data: the head (DMR: a line's entry) the read port served at the last edge; layout
    /// above.
    pub rd_frame: Signal<Out, Bits<99>>,
    /// The line (queue in normal mode) the read port serves before this edge.
    pub rd_sel_o: Signal<Out, Bit>,
    /// Normal mode: channel A's `tx_req`, a one-clock pulse while `rd_frame` is queue A's head.
    pub req_a: Signal<Out, Bit>,
    /// Normal mode: channel B's `tx_req`, a one-clock pulse while `rd_frame` is queue B's head.
    pub req_b: Signal<Out, Bit>,
    /// Normal mode: a channel sent its frame at this edge (`INT_STATUS.tx_done`).
    pub done_evt: Signal<Out, Bit>,
    /// Normal mode: a channel dropped its frame at this edge (`INT_STATUS.tx_failure`).
    pub failed_evt: Signal<Out, Bit>,
    // storage and queue state
    ram: Bram<Bits<99>, 4>,
    norm: FrameNormalizer,
    /// `Q - 1`: the pointer wrap (generation parameter).
    qmask: Param<3, 7>,
    head_a: DFF<Bits<3>>,
    head_b: DFF<Bits<3>>,
    cnt_a: DFF<Bits<4>>,
    cnt_b: DFF<Bits<4>>,
    rd_sel: DFF<Bit>,
    req_a_q: DFF<Bit>,
    req_b_q: DFF<Bit>,
    busy_a: DFF<Bit>,
    busy_b: DFF<Bit>,
    chan_abort_a_q: DFF<Bit>,
    chan_abort_b_q: DFF<Bit>,
    /// Normal mode: channel c holds the head and keeps it past this edge.
    holds_a: Signal<Local, Bit>,
    holds_b: Signal<Local, Bit>,
    pop_a: Signal<Local, Bit>,
    pop_n: Signal<Local, Bits<4>>,
    dmr_slot: Signal<Local, Bits<3>>,
    pop_b: Signal<Local, Bit>,
    push_a: Signal<Local, Bit>,
    push_b: Signal<Local, Bit>,
    wr_slot: Signal<Local, Bits<3>>,
    rd_slot: Signal<Local, Bits<3>>,
    one3: Constant<Bits<3>>,
    one4: Constant<Bits<4>>,
    zero3: Constant<Bits<3>>,
    zero4: Constant<Bits<4>>,
}

impl Default for TxBuffer {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            clear: Default::default(),
            redundancy: Default::default(),
            dmr: Default::default(),
            off_dcl: Default::default(),
            off_rcl: Default::default(),
            dmr_pop: Default::default(),
            push: Default::default(),
            push_q: Default::default(),
            push_frame: Default::default(),
            pop_red: Default::default(),
            abort_a: Default::default(),
            abort_b: Default::default(),
            chan_abort_a: Default::default(),
            chan_abort_b: Default::default(),
            chan_abort_a_q: Default::default(),
            chan_abort_b_q: Default::default(),
            holds_a: Default::default(),
            holds_b: Default::default(),
            done_a: Default::default(),
            failed_a: Default::default(),
            done_b: Default::default(),
            failed_b: Default::default(),
            count_a: Default::default(),
            count_b: Default::default(),
            rd_frame: Default::default(),
            rd_sel_o: Default::default(),
            req_a: Default::default(),
            req_b: Default::default(),
            done_evt: Default::default(),
            failed_evt: Default::default(),
            ram: Default::default(),
            norm: Default::default(),
            qmask: Default::default(),
            head_a: Default::default(),
            head_b: Default::default(),
            cnt_a: Default::default(),
            cnt_b: Default::default(),
            rd_sel: Default::default(),
            req_a_q: Default::default(),
            req_b_q: Default::default(),
            busy_a: Default::default(),
            busy_b: Default::default(),
            pop_a: Default::default(),
            pop_n: Default::default(),
            dmr_slot: Default::default(),
            pop_b: Default::default(),
            push_a: Default::default(),
            push_b: Default::default(),
            wr_slot: Default::default(),
            rd_slot: Default::default(),
            one3: Constant::new(1.into()),
            one4: Constant::new(1.into()),
            zero3: Constant::new(0.into()),
            zero4: Constant::new(0.into()),
        }
    }
}

impl TxBuffer {
    /// A TX buffer with two queues of `depth` entries (2, 4 or 8).
    pub fn new(depth: usize) -> Self {
        assert!(depth.is_power_of_two() && (2..=8).contains(&depth));
        Self {
            qmask: Param::new(depth as u64 - 1),
            ..Default::default()
        }
    }
}

impl Logic for TxBuffer {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            head_a,
            head_b,
            cnt_a,
            cnt_b,
            rd_sel,
            req_a_q,
            req_b_q,
            busy_a,
            busy_b,
            chan_abort_a_q,
            chan_abort_b_q
        );
        self.ram.clk.next = self.clk.val();
        self.ram.read_enable.next = true;

        // pops: redundancy mode by the main FSM, normal mode at each channel
        // tx_done / tx_failed
        // (never below empty)
        if self.dmr.val() {
            // the DMR control pops what both lines sent (`pop_n` below)
            self.pop_a.next = false;
            self.pop_b.next = false;
        } else if self.redundancy.val() {
            self.pop_a.next = self.pop_red.val() & (self.cnt_a.q.val() != self.zero4.val());
            self.pop_b.next = false;
        } else {
            self.pop_a.next = (self.done_a.val() | self.failed_a.val())
                & (self.cnt_a.q.val() != self.zero4.val());
            self.pop_b.next = (self.done_b.val() | self.failed_b.val())
                & (self.cnt_b.q.val() != self.zero4.val());
        }
        // entries queue A frees at this edge (never below empty)
        if self.dmr.val() {
            if self.dmr_pop.val() > self.cnt_a.q.val() {
                self.pop_n.next = self.cnt_a.q.val();
            } else {
                self.pop_n.next = self.dmr_pop.val();
            }
        } else {
            self.pop_n.next = bit_cast::<4, 1>(self.pop_a.val().into());
        }
        self.push_a.next = self.push.val() & !self.push_q.val();
        self.push_b.next = self.push.val() & self.push_q.val();

        // write port: the staged frame, normalized, goes to {q, head + count}
        if self.push_q.val() {
            self.wr_slot.next =
                (self.head_b.q.val() + self.cnt_b.q.val().get_bits::<3>(0)) & self.qmask.val();
        } else {
            self.wr_slot.next =
                (self.head_a.q.val() + self.cnt_a.q.val().get_bits::<3>(0)) & self.qmask.val();
        }
        self.ram.write_enable.next = self.push.val();
        self.ram.write_address.next = (bit_cast::<4, 1>(self.push_q.val().into()) << 3)
            | bit_cast::<4, 3>(self.wr_slot.val());
        self.norm.frame.next = self.push_frame.val();
        self.ram.write_data.next = self.norm.normalized.val();

        // read port: {0, head_a} in redundancy mode, else {rd_sel, head[rd_sel]}
        if self.rd_sel.q.val() {
            self.rd_slot.next = self.head_b.q.val();
        } else {
            self.rd_slot.next = self.head_a.q.val();
        }
        // DMR: the entry `head_a + off[rd_sel]` mod Q, summed in a 3-bit signal of
        // its own (inside a wider expression Verilog would keep the carry)
        if self.rd_sel.q.val() {
            self.dmr_slot.next = (self.head_a.q.val() + self.off_rcl.val()) & self.qmask.val();
        } else {
            self.dmr_slot.next = (self.head_a.q.val() + self.off_dcl.val()) & self.qmask.val();
        }
        if self.dmr.val() {
            self.ram.read_address.next = bit_cast::<4, 3>(self.dmr_slot.val());
        } else if self.redundancy.val() {
            self.ram.read_address.next = bit_cast::<4, 3>(self.head_a.q.val());
        } else {
            self.ram.read_address.next = (bit_cast::<4, 1>(self.rd_sel.q.val().into()) << 3)
                | bit_cast::<4, 3>(self.rd_slot.val());
        }
        self.rd_frame.next = self.ram.read_data.val();

        // queue pointers
        self.head_a.d.next = self.head_a.q.val();
        self.head_b.d.next = self.head_b.q.val();
        self.head_a.d.next =
            (self.head_a.q.val() + self.pop_n.val().get_bits::<3>(0)) & self.qmask.val();
        if self.pop_b.val() {
            self.head_b.d.next = (self.head_b.q.val() + self.one3.val()) & self.qmask.val();
        }
        self.cnt_a.d.next = self.cnt_a.q.val() - self.pop_n.val();
        if self.push_a.val() {
            self.cnt_a.d.next = self.cnt_a.q.val() - self.pop_n.val() + self.one4.val();
        }
        self.cnt_b.d.next = self.cnt_b.q.val();
        if self.push_b.val() & !self.pop_b.val() {
            self.cnt_b.d.next = self.cnt_b.q.val() + self.one4.val();
        } else if !self.push_b.val() & self.pop_b.val() {
            self.cnt_b.d.next = self.cnt_b.q.val() - self.one4.val();
        }

        // §11.5, host abort: normal mode keeps the frame channel c holds (and
        // aborts it in the channel one clock later), redundancy mode the head
        self.holds_a.next = self.busy_a.q.val()
            & !self.done_a.val()
            & !self.failed_a.val()
            & !self.redundancy.val();
        self.holds_b.next = self.busy_b.q.val()
            & !self.done_b.val()
            & !self.failed_b.val()
            & !self.redundancy.val();
        if self.abort_a.val() {
            self.cnt_a.d.next = self.zero4.val();
            if self.redundancy.val() & (self.cnt_a.q.val() != self.zero4.val()) & !self.pop_a.val()
            {
                self.cnt_a.d.next = self.one4.val();
            }
            if self.holds_a.val() {
                self.cnt_a.d.next = self.one4.val();
            }
        }
        if self.abort_b.val() {
            self.cnt_b.d.next = self.zero4.val();
            if self.holds_b.val() {
                self.cnt_b.d.next = self.one4.val();
            }
        }
        self.chan_abort_a_q.d.next = self.abort_a.val() & self.holds_a.val() & !self.dmr.val();
        self.chan_abort_b_q.d.next = self.abort_b.val() & self.holds_b.val() & !self.dmr.val();

        // normal mode: req_c <= (rd_sel == c) && count_c > 0 && !busy_c && !req_c
        // (none for queue c at its abort edge, §11.5)
        // the read port alternates between the queues (normal mode) or the
        // lines (DMR mode, whose requests are the DMR control's)
        self.rd_sel.d.next = !self.rd_sel.q.val() & !self.redundancy.val();
        self.req_a_q.d.next = !self.redundancy.val()
            & !self.dmr.val()
            & !self.rd_sel.q.val()
            & (self.cnt_a.q.val() != self.zero4.val())
            & !self.busy_a.q.val()
            & !self.req_a_q.q.val()
            & !self.abort_a.val();
        self.req_b_q.d.next = !self.redundancy.val()
            & !self.dmr.val()
            & self.rd_sel.q.val()
            & (self.cnt_b.q.val() != self.zero4.val())
            & !self.busy_b.q.val()
            & !self.req_b_q.q.val()
            & !self.abort_b.val();
        self.busy_a.d.next = self.busy_a.q.val() | self.req_a_q.d.val();
        self.busy_b.d.next = self.busy_b.q.val() | self.req_b_q.d.val();
        if self.dmr.val() | (!self.redundancy.val() & (self.done_a.val() | self.failed_a.val())) {
            self.busy_a.d.next = false;
        }
        if self.dmr.val() | (!self.redundancy.val() & (self.done_b.val() | self.failed_b.val())) {
            self.busy_b.d.next = false;
        }
        self.done_evt.next =
            !self.redundancy.val() & !self.dmr.val() & (self.done_a.val() | self.done_b.val());
        self.failed_evt.next =
            !self.redundancy.val() & !self.dmr.val() & (self.failed_a.val() | self.failed_b.val());

        if self.clear.val() {
            self.head_a.d.next = self.zero3.val();
            self.head_b.d.next = self.zero3.val();
            self.cnt_a.d.next = self.zero4.val();
            self.cnt_b.d.next = self.zero4.val();
            self.rd_sel.d.next = false;
            self.req_a_q.d.next = false;
            self.req_b_q.d.next = false;
            self.busy_a.d.next = false;
            self.busy_b.d.next = false;
            self.chan_abort_a_q.d.next = false;
            self.chan_abort_b_q.d.next = false;
            self.done_evt.next = false;
            self.failed_evt.next = false;
        }
        self.count_a.next = self.cnt_a.q.val();
        self.count_b.next = self.cnt_b.q.val();
        self.req_a.next = self.req_a_q.q.val();
        self.req_b.next = self.req_b_q.q.val();
        self.chan_abort_a.next = self.chan_abort_a_q.q.val();
        self.chan_abort_b.next = self.chan_abort_b_q.q.val();
        self.rd_sel_o.next = self.rd_sel.q.val();
    }
}
