//! The DMR mailboxes' state (DMR contract §4.1, §4.2, `MB_STATE` of §2.1): the
//! `counter` (8-bit two's complement) and `timer` (16 bits) of each of the `M`
//! mailboxes (generation parameter, 1..16),
//! in registers, read by the host window live, and a copy in block RAM, read by
//! the engine. The engine writes one mailbox per clock (`sel`).
//!
//! One register per mailbox, written by its own enable (a one-hot decode of
//! `sel`) with the shared value: on the iCE40 each bit is a flip-flop with clock
//! enable and synchronous reset and no LUT (a packed register written as
//! `q & !slot | value & slot` costs one LUT per bit, 384 for 16). `clear` zeroes
//! every mailbox at once (reset mode, another DRCC mode, a recovery: §2.1, §7)
//! and wins over a write.
//!
//! The engine's copy: a block RAM with a registered read (the engine gives the
//! address one edge ahead, `rd_addr`) saves the engine a 24-bit 16-way
//! multiplexer (about 250 LUT4) for two `SB_RAM40_4K`. A block RAM cannot clear
//! at once, so a `valid` bit per mailbox clears with `clear`, sets with a write,
//! and the read data of a mailbox whose bit is 0 reads 0. Collisions (the read
//! and write addresses meet at an edge, the RAM's read data is undefined there,
//! `crate::memory::bram`): the engine writes only in `UPDATE` and `EVAL`; in
//! `EVAL` it writes `e_i` while it loads `e_i + 1`, and the data loaded at the
//! last `EVAL` edge and at the `UPDATE` edge belongs to the `IDLE` clock after
//! them, which does not read it.
//!
//! The §4.2 debt bits (`owed`): set by a timeout verdict, which keeps the
//! counter; dropped when the counter returns to 0 or by a deviation; cleared
//! with everything by `clear`.
//!
//! The register outputs are the registers themselves: the readers (the engine's
//! mailbox, the host window) slice them in the parent, so no combinational path
//! runs from this block's inputs to its outputs (one `always` block per module:
//! a read here would close a false loop through the engine's write data).

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
    // ---- the state ----
    /// Every counter (two's complement): mailbox i in `[8i+7:8i]` (0 beyond `M`).
    pub counters: Signal<Out, Bits<128>>,
    /// Every timer (DMR ticks left, 0 = stopped): mailbox i in `[16i+15:16i]`.
    pub timers: Signal<Out, Bits<256>>,
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
    // ---- registers: mailbox i = {timer [23:8], counter [7:0]} ----
    mb: [DFF<Bits<24>>; M],
    copy: Bram<Bits<24>, 4>,
    valid: DFF<Bits<16>>,
    settle: DFF<Bits<16>>,
    owed: DFF<Bits<16>>,
    rd_q: DFF<Bits<4>>,
    // ---- internals ----
    rd_word: Signal<Local, Bits<24>>,
    slot: Signal<Local, Bits<16>>,
    word: Signal<Local, Bits<24>>,
    mb_counter: Signal<Local, Bits<8>>,
    mb_timer: Signal<Local, Bits<16>>,
    one16: Const<16, 1>,
    zero24: Const<24, 0>,
    zero16: Const<16, 0>,
    ones16: Const<16, 0xFFFF>,
    zero128: Const<128, 0>,
    zero256: Const<256, 0>,
    at_c: [Constant<Bits<8>>; M],
    at_t: [Constant<Bits<9>>; M],
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
            counters: Default::default(),
            timers: Default::default(),
            settle_all: Default::default(),
            settle_none: Default::default(),
            settle_drop: Default::default(),
            settles: Default::default(),
            owe_set: Default::default(),
            owe_drop: Default::default(),
            oweds: Default::default(),
            mb: std::array::from_fn(|_| Default::default()),
            copy: Default::default(),
            valid: Default::default(),
            settle: Default::default(),
            owed: Default::default(),
            rd_q: Default::default(),
            rd_word: Default::default(),
            slot: Default::default(),
            word: Default::default(),
            mb_counter: Default::default(),
            mb_timer: Default::default(),
            one16: Default::default(),
            zero24: Default::default(),
            zero16: Default::default(),
            ones16: Default::default(),
            zero128: Default::default(),
            zero256: Default::default(),
            at_c: std::array::from_fn(|i| Constant::new(((8 * i) as u64).into())),
            at_t: std::array::from_fn(|i| Constant::new(((16 * i) as u64).into())),
        }
    }
}

impl<const M: usize> Logic for MailboxState<M> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, valid, settle, owed, rd_q);
        // the write: one enable per mailbox, the same word to all
        self.slot.next = self.one16.val() << self.sel.val();
        self.word.next =
            bit_cast::<24, 8>(self.counter_d.val()) | (bit_cast::<24, 16>(self.timer_d.val()) << 8);
        // the engine's copy: written with the registers, read one edge ahead
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
        // the registers, and the packed outputs (wiring)
        self.counters.next = self.zero128.val();
        self.timers.next = self.zero256.val();
        for i in 0..M {
            self.mb[i].clock.next = self.clk.val();
            self.mb[i].d.next = self.mb[i].q.val();
            if self.we.val() & self.slot.val().get_bit(i) {
                self.mb[i].d.next = self.word.val();
            }
            if self.clear.val() {
                self.mb[i].d.next = self.zero24.val();
            }
            self.mb_counter.next = self.mb[i].q.val().get_bits::<8>(0);
            self.mb_timer.next = self.mb[i].q.val().get_bits::<16>(8);
            self.counters.next = self.counters.val()
                | (bit_cast::<128, 8>(self.mb_counter.val()) << self.at_c[i].val());
            self.timers.next = self.timers.val()
                | (bit_cast::<256, 16>(self.mb_timer.val()) << self.at_t[i].val());
        }
    }
}
