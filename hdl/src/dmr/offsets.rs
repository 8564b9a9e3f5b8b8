//! The offsets of the one logical queue (DMR contract §5): each line's `off[L]`
//! (0..8) into TX queue A, the host's `tx_done` at the first copy of a message,
//! the deletion of a faulty line's copies (its offset is 0 while it does not
//! send), the return of a line (it takes the other line's offset), and the entries
//! both sending lines have left behind, which the queue frees (`pop`).

use rust_hdl::prelude::*;

/// Line offsets, first-copy completion and the queue's pop count.
#[derive(LogicBlock)]
pub struct DmrOffsets {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst` or held: both offsets to 0.
    pub clear: Signal<In, Bit>,
    // ---- TX queue A ----
    /// `count`: messages in the queue.
    pub q_count: Signal<In, Bits<4>>,
    /// Entries the queue frees at this edge (combinational).
    pub pop: Signal<Out, Bits<4>>,
    /// `off[DCL]`.
    pub off_dcl: Signal<Out, Bits<4>>,
    /// `off[RCL]`.
    pub off_rcl: Signal<Out, Bits<4>>,
    /// The DCL has a message left to send (`off[DCL] < count`).
    pub more_dcl: Signal<Out, Bit>,
    /// The RCL has a message left to send.
    pub more_rcl: Signal<Out, Bit>,
    // ---- the lines ----
    /// `tx_fault[DCL]` before the edge.
    pub tx_fault_dcl: Signal<In, Bit>,
    /// `tx_fault[RCL]` before the edge.
    pub tx_fault_rcl: Signal<In, Bit>,
    /// The DCL sends after the edge.
    pub sends_next_dcl: Signal<In, Bit>,
    /// The RCL sends after the edge.
    pub sends_next_rcl: Signal<In, Bit>,
    /// A host copy completed on the (sending) DCL at this edge.
    pub complete_dcl: Signal<In, Bit>,
    /// A host copy completed on the (sending) RCL at this edge.
    pub complete_rcl: Signal<In, Bit>,
    /// The first copy of a message completed: `INT_STATUS.tx_done` (combinational).
    pub first: Signal<Out, Bit>,
    // ---- registers ----
    /// `off[DCL]`.
    pub off_dcl_q: DFF<Bits<4>>,
    /// `off[RCL]`.
    pub off_rcl_q: DFF<Bits<4>>,
    // ---- internals ----
    base_dcl: Signal<Local, Bits<4>>,
    base_rcl: Signal<Local, Bits<4>>,
    next_dcl: Signal<Local, Bits<4>>,
    next_rcl: Signal<Local, Bits<4>>,
    left: Signal<Local, Bits<4>>,
    zero4: Constant<Bits<4>>,
}

impl Default for DmrOffsets {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            clear: Default::default(),
            q_count: Default::default(),
            pop: Default::default(),
            off_dcl: Default::default(),
            off_rcl: Default::default(),
            more_dcl: Default::default(),
            more_rcl: Default::default(),
            tx_fault_dcl: Default::default(),
            tx_fault_rcl: Default::default(),
            sends_next_dcl: Default::default(),
            sends_next_rcl: Default::default(),
            complete_dcl: Default::default(),
            complete_rcl: Default::default(),
            first: Default::default(),
            off_dcl_q: Default::default(),
            off_rcl_q: Default::default(),
            base_dcl: Default::default(),
            base_rcl: Default::default(),
            next_dcl: Default::default(),
            next_rcl: Default::default(),
            left: Default::default(),
            zero4: Constant::new(0.into()),
        }
    }
}

impl Logic for DmrOffsets {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, off_dcl_q, off_rcl_q);
        self.more_dcl.next = self.off_dcl_q.q.val() < self.q_count.val();
        self.more_rcl.next = self.off_rcl_q.q.val() < self.q_count.val();
        // The host hears of a message once, at its first copy: the other line does
        // not send or has not sent it yet.
        self.first.next = (self.complete_dcl.val()
            & (self.tx_fault_rcl.val() | (self.off_dcl_q.q.val() >= self.off_rcl_q.q.val())))
            | (self.complete_rcl.val()
                & (self.tx_fault_dcl.val() | (self.off_rcl_q.q.val() >= self.off_dcl_q.q.val())));
        // A line that sent and still sends steps at its completion; any other is 0.
        self.base_dcl.next = self.zero4.val();
        if self.sends_next_dcl.val() & !self.tx_fault_dcl.val() {
            self.base_dcl.next =
                self.off_dcl_q.q.val() + bit_cast::<4, 1>(self.complete_dcl.val().into());
        }
        self.base_rcl.next = self.zero4.val();
        if self.sends_next_rcl.val() & !self.tx_fault_rcl.val() {
            self.base_rcl.next =
                self.off_rcl_q.q.val() + bit_cast::<4, 1>(self.complete_rcl.val().into());
        }
        // Return: a line whose tx_fault clears sends every message the other line
        // has not sent yet (deletion: a line that does not send stays at 0).
        self.next_dcl.next = self.base_dcl.val();
        if self.tx_fault_dcl.val() {
            self.next_dcl.next = self.zero4.val();
            if self.sends_next_dcl.val() {
                self.next_dcl.next = self.base_rcl.val();
            }
        }
        self.next_rcl.next = self.base_rcl.val();
        if self.tx_fault_rcl.val() {
            self.next_rcl.next = self.zero4.val();
            if self.sends_next_rcl.val() {
                self.next_rcl.next = self.base_dcl.val();
            }
        }
        // The queue leaves behind what every sending line has sent.
        self.left.next = self.next_rcl.val();
        if self.sends_next_dcl.val() {
            self.left.next = self.next_dcl.val();
            if self.sends_next_rcl.val() & (self.next_rcl.val() < self.next_dcl.val()) {
                self.left.next = self.next_rcl.val();
            }
        }
        self.off_dcl_q.d.next = self.zero4.val();
        if self.sends_next_dcl.val() {
            self.off_dcl_q.d.next = self.next_dcl.val() - self.left.val();
        }
        self.off_rcl_q.d.next = self.zero4.val();
        if self.sends_next_rcl.val() {
            self.off_rcl_q.d.next = self.next_rcl.val() - self.left.val();
        }
        self.pop.next = self.left.val();
        if self.clear.val() {
            self.off_dcl_q.d.next = self.zero4.val();
            self.off_rcl_q.d.next = self.zero4.val();
            self.pop.next = self.zero4.val();
            self.first.next = false;
        }
        self.off_dcl.next = self.off_dcl_q.q.val();
        self.off_rcl.next = self.off_rcl_q.q.val();
    }
}
