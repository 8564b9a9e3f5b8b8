//! The DMR mailboxes' state (DMR contract §4.1, §4.2, `MB_STATE` of §2.1): the
//! `counter` (8-bit two's complement) and `timer` (16 bits) of each of the `M`
//! mailboxes (generation parameter, 1..16), in two block RAM copies written
//! together, one mailbox per clock (`sel`): one read by the engine, one by the
//! host window. No mailbox state lives in flip-flops (16 x 24 of them and the
//! window's 24-bit 16-way multiplexer were about 630 iCE40 logic cells).
//!
//! Both copies have a registered read: the reader names the mailbox one edge
//! ahead (`rd_addr`, `win_addr`). A block RAM cannot clear at once, so a `valid`
//! bit per mailbox clears with `clear` (reset mode, another DRCC mode, a
//! recovery: §2.1, §7; it wins over a write), sets with a write, and a mailbox
//! whose bit is 0 reads 0.
//!
//! Collisions (the read and write addresses meet at an edge; the RAM's read data
//! is undefined there, `crate::memory::bram`):
//! - the engine's copy: the engine writes only in `UPDATE` and `EVAL`; in
//!   `EVAL` it writes `e_i` while it loads `e_i + 1`, and the data loaded at the
//!   last `EVAL` edge and at the `UPDATE` edge belongs to the `IDLE` clock after
//!   them, which does not read it.
//! - the window: a write at an edge to the mailbox the window loads there is
//!   kept in a bypass register (`win_hit`, `win_word`), which the window shows
//!   instead of the RAM's read data. So after every edge the window shows the
//!   state after that edge of the mailbox `win_addr` named at it, as the
//!   registers did. `win_addr` is `MB_SEL`, a register: after a write of
//!   `MB_SEL` the window follows one clock later, and no bus access can be taken
//!   in that clock (the write's acknowledge is up, bus contract §1).
//!
//! The §4.2 debt bits (`owed`): set by a timeout verdict, which keeps the
//! counter; dropped when the counter returns to 0 or by a deviation; cleared
//! with everything by `clear`.
//!
//! The outputs are registers or RAM outputs, selected by registers: no
//! combinational path runs from this block's inputs to its outputs (one `always`
//! block per module: a read here would close a false loop through the engine's
//! write data).

use crate::channel::sized::Const;
use crate::memory::bram::Bram;
use rust_hdl::prelude::*;

/// Counter and timer of `M` mailboxes (1..16).
#[derive(LogicBlock)]
pub struct MailboxState<const M: usize> {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Every counter and timer becomes 0 at this edge (over a write).
    pub clear: Signal<In, Bit>,
    // ---- the write port ----
    /// The mailbox written.
    pub sel: Signal<In, Bits<4>>,
    /// Write `counter_d` and `timer_d` to mailbox `sel` at this edge.
    pub we: Signal<In, Bit>,
    /// The new counter of mailbox `sel`.
    pub counter_d: Signal<In, Bits<8>>,
    /// The new timer of mailbox `sel`.
    pub timer_d: Signal<In, Bits<16>>,
    // ---- the engine's read port (block RAM copy) ----
    /// The mailbox whose state `rd_counter` / `rd_timer` show after this edge.
    pub rd_addr: Signal<In, Bits<4>>,
    /// `counter` of the mailbox `rd_addr` named at the previous edge.
    pub rd_counter: Signal<Out, Bits<8>>,
    /// `timer` of the mailbox `rd_addr` named at the previous edge.
    pub rd_timer: Signal<Out, Bits<16>>,
    // ---- the host window's read port (block RAM copy and bypass) ----
    /// The mailbox whose state `win_counter` / `win_timer` show after this edge
    /// (`MB_SEL`).
    pub win_addr: Signal<In, Bits<4>>,
    /// `counter` after the previous edge of the mailbox `win_addr` named there.
    pub win_counter: Signal<Out, Bits<8>>,
    /// `timer` after the previous edge of the mailbox `win_addr` named there.
    pub win_timer: Signal<Out, Bits<16>>,
    // ---- §4.2 settling ----
    /// A recovery: every mailbox settles at this edge (over `settle_drop`).
    pub settle_all: Signal<In, Bit>,
    /// No mailbox settles after this edge (reset mode; over `settle_all`).
    pub settle_none: Signal<In, Bit>,
    /// Mailbox `sel` was judged at this edge: it no longer settles.
    pub settle_drop: Signal<In, Bit>,
    /// The settling bits, bit i = mailbox i.
    pub settles: Signal<Out, Bits<16>>,
    // ---- §4.2 debt: a timeout keeps the counter as the judged line's debt ----
    /// Mailbox `sel` was judged by a timeout at this edge: it owes (over `owe_drop`).
    pub owe_set: Signal<In, Bit>,
    /// Mailbox `sel`'s counter is back at 0, or it was judged by a deviation.
    pub owe_drop: Signal<In, Bit>,
    /// The debt bits, bit i = mailbox i (0 after `clear`).
    pub oweds: Signal<Out, Bits<16>>,
    // ---- storage: mailbox i = {timer [23:8], counter [7:0]} ----
    copy: Bram<Bits<24>, 4>,
    win: Bram<Bits<24>, 4>,
    valid: DFF<Bits<16>>,
    settle: DFF<Bits<16>>,
    owed: DFF<Bits<16>>,
    rd_q: DFF<Bits<4>>,
    win_q: DFF<Bits<4>>,
    win_hit: DFF<Bit>,
    win_word: DFF<Bits<24>>,
    // ---- internals ----
    rd_word: Signal<Local, Bits<24>>,
    win_data: Signal<Local, Bits<24>>,
    slot: Signal<Local, Bits<16>>,
    word: Signal<Local, Bits<24>>,
    one16: Const<16, 1>,
    zero24: Const<24, 0>,
    zero16: Const<16, 0>,
    ones16: Const<16, 0xFFFF>,
}

impl<const M: usize> Default for MailboxState<M> {
    fn default() -> Self {
        assert!((1..=16).contains(&M), "mailbox state: M is 1..16");
        Self {
            clk: Default::default(),
            clear: Default::default(),
            sel: Default::default(),
            we: Default::default(),
            counter_d: Default::default(),
            timer_d: Default::default(),
            rd_addr: Default::default(),
            rd_counter: Default::default(),
            rd_timer: Default::default(),
            win_addr: Default::default(),
            win_counter: Default::default(),
            win_timer: Default::default(),
            settle_all: Default::default(),
            settle_none: Default::default(),
            settle_drop: Default::default(),
            settles: Default::default(),
            owe_set: Default::default(),
            owe_drop: Default::default(),
            oweds: Default::default(),
            copy: Default::default(),
            win: Default::default(),
            valid: Default::default(),
            settle: Default::default(),
            owed: Default::default(),
            rd_q: Default::default(),
            win_q: Default::default(),
            win_hit: Default::default(),
            win_word: Default::default(),
            rd_word: Default::default(),
            win_data: Default::default(),
            slot: Default::default(),
            word: Default::default(),
            one16: Default::default(),
            zero24: Default::default(),
            zero16: Default::default(),
            ones16: Default::default(),
        }
    }
}

impl<const M: usize> Logic for MailboxState<M> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, valid, settle, owed, rd_q, win_q, win_hit, win_word);
        // the write: one mailbox, the same word to both copies
        self.slot.next = self.one16.val() << self.sel.val();
        self.word.next =
            bit_cast::<24, 8>(self.counter_d.val()) | (bit_cast::<24, 16>(self.timer_d.val()) << 8);
        // the engine's copy, read one edge ahead
        self.copy.clk.next = self.clk.val();
        self.copy.write_address.next = self.sel.val();
        self.copy.write_data.next = self.word.val();
        self.copy.write_enable.next = self.we.val();
        self.copy.read_address.next = self.rd_addr.val();
        self.copy.read_enable.next = true;
        self.rd_q.d.next = self.rd_addr.val();
        if self.valid.q.val().get_bit(self.rd_q.q.val().index()) {
            self.rd_word.next = self.copy.read_data.val();
        } else {
            self.rd_word.next = self.zero24.val();
        }
        self.rd_counter.next = self.rd_word.val().get_bits::<8>(0);
        self.rd_timer.next = self.rd_word.val().get_bits::<16>(8);
        // the window's copy, read one edge ahead; a write to the mailbox it
        // loads at the same edge is taken from the bypass (the collision)
        self.win.clk.next = self.clk.val();
        self.win.write_address.next = self.sel.val();
        self.win.write_data.next = self.word.val();
        self.win.write_enable.next = self.we.val();
        self.win.read_address.next = self.win_addr.val();
        self.win.read_enable.next = true;
        self.win_q.d.next = self.win_addr.val();
        self.win_hit.d.next =
            self.we.val() & (self.sel.val() == self.win_addr.val()) & !self.clear.val();
        self.win_word.d.next = self.word.val();
        if self.win_hit.q.val() {
            self.win_data.next = self.win_word.q.val();
        } else if self.valid.q.val().get_bit(self.win_q.q.val().index()) {
            self.win_data.next = self.win.read_data.val();
        } else {
            self.win_data.next = self.zero24.val();
        }
        self.win_counter.next = self.win_data.val().get_bits::<8>(0);
        self.win_timer.next = self.win_data.val().get_bits::<16>(8);
        if self.we.val() {
            self.valid.d.next = self.valid.q.val() | self.slot.val();
        }
        if self.clear.val() {
            self.valid.d.next = self.zero16.val();
        }
        if self.settle_drop.val() {
            self.settle.d.next = self.settle.q.val() & !self.slot.val();
        }
        if self.settle_all.val() {
            self.settle.d.next = self.ones16.val();
        }
        if self.settle_none.val() {
            self.settle.d.next = self.zero16.val();
        }
        self.settles.next = self.settle.q.val();
        if self.owe_drop.val() {
            self.owed.d.next = self.owed.q.val() & !self.slot.val();
        }
        if self.owe_set.val() {
            self.owed.d.next = self.owed.q.val() | self.slot.val();
        }
        if self.clear.val() {
            self.owed.d.next = self.zero16.val();
        }
        self.oweds.next = self.owed.q.val();
    }
}
