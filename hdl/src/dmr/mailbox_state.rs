//! The DMR mailboxes' state (DMR contract §4.1, §4.2, `MB_STATE` of §2.1): the
//! `counter` (8-bit two's complement) and `timer` (16 bits) of every mailbox,
//! in registers, read by the host window live, and a copy in block RAM, read by
//! the engine. The engine writes one mailbox per clock (`sel`).
//!
//! One register per mailbox, written by its own enable (a one-hot decode of
//! `sel`) with the shared value: on the iCE40 each bit is a flip-flop with clock
//! enable and synchronous reset and no LUT (a packed register written as
//! `q & !slot | value & slot` costs one LUT per bit, 384 here). `clear` zeroes
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
//! The register outputs are the registers themselves: the readers (the engine's
//! mailbox, the host window) slice them in the parent, so no combinational path
//! runs from this block's inputs to its outputs (one `always` block per module:
//! a read here would close a false loop through the engine's write data).

use crate::channel::sized::Const;
use crate::memory::bram::Bram;
use rust_hdl::prelude::*;

/// Counter and timer of 16 mailboxes.
#[derive(LogicBlock, Default)]
pub struct MailboxState {
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
    /// Every counter (two's complement): mailbox i in `[8i+7:8i]`.
    pub counters: Signal<Out, Bits<128>>,
    /// Every timer (DMR ticks left, 0 = stopped): mailbox i in `[16i+15:16i]`.
    pub timers: Signal<Out, Bits<256>>,
    // ---- registers: mailbox i = {timer [23:8], counter [7:0]} ----
    mb0: DFF<Bits<24>>,
    mb1: DFF<Bits<24>>,
    mb2: DFF<Bits<24>>,
    mb3: DFF<Bits<24>>,
    mb4: DFF<Bits<24>>,
    mb5: DFF<Bits<24>>,
    mb6: DFF<Bits<24>>,
    mb7: DFF<Bits<24>>,
    mb8: DFF<Bits<24>>,
    mb9: DFF<Bits<24>>,
    mb10: DFF<Bits<24>>,
    mb11: DFF<Bits<24>>,
    mb12: DFF<Bits<24>>,
    mb13: DFF<Bits<24>>,
    mb14: DFF<Bits<24>>,
    mb15: DFF<Bits<24>>,
    copy: Bram<Bits<24>, 4>,
    valid: DFF<Bits<16>>,
    rd_q: DFF<Bits<4>>,
    // ---- internals ----
    rd_word: Signal<Local, Bits<24>>,
    slot: Signal<Local, Bits<16>>,
    word: Signal<Local, Bits<24>>,
    one16: Const<16, 1>,
    zero24: Const<24, 0>,
    zero16: Const<16, 0>,
}

impl Logic for MailboxState {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, valid, rd_q, mb0, mb1, mb2, mb3, mb4, mb5, mb6, mb7, mb8, mb9, mb10, mb11,
            mb12, mb13, mb14, mb15
        );
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
        if self.we.val() & self.slot.val().get_bit(0) {
            self.mb0.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(1) {
            self.mb1.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(2) {
            self.mb2.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(3) {
            self.mb3.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(4) {
            self.mb4.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(5) {
            self.mb5.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(6) {
            self.mb6.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(7) {
            self.mb7.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(8) {
            self.mb8.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(9) {
            self.mb9.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(10) {
            self.mb10.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(11) {
            self.mb11.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(12) {
            self.mb12.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(13) {
            self.mb13.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(14) {
            self.mb14.d.next = self.word.val();
        }
        if self.we.val() & self.slot.val().get_bit(15) {
            self.mb15.d.next = self.word.val();
        }
        if self.clear.val() {
            self.valid.d.next = self.zero16.val();
            self.mb0.d.next = self.zero24.val();
            self.mb1.d.next = self.zero24.val();
            self.mb2.d.next = self.zero24.val();
            self.mb3.d.next = self.zero24.val();
            self.mb4.d.next = self.zero24.val();
            self.mb5.d.next = self.zero24.val();
            self.mb6.d.next = self.zero24.val();
            self.mb7.d.next = self.zero24.val();
            self.mb8.d.next = self.zero24.val();
            self.mb9.d.next = self.zero24.val();
            self.mb10.d.next = self.zero24.val();
            self.mb11.d.next = self.zero24.val();
            self.mb12.d.next = self.zero24.val();
            self.mb13.d.next = self.zero24.val();
            self.mb14.d.next = self.zero24.val();
            self.mb15.d.next = self.zero24.val();
        }
        // the packed outputs (wiring)
        self.counters.next = (bit_cast::<128, 8>(self.mb0.q.val().get_bits::<8>(0)) << 0)
            | (bit_cast::<128, 8>(self.mb1.q.val().get_bits::<8>(0)) << 8)
            | (bit_cast::<128, 8>(self.mb2.q.val().get_bits::<8>(0)) << 16)
            | (bit_cast::<128, 8>(self.mb3.q.val().get_bits::<8>(0)) << 24)
            | (bit_cast::<128, 8>(self.mb4.q.val().get_bits::<8>(0)) << 32)
            | (bit_cast::<128, 8>(self.mb5.q.val().get_bits::<8>(0)) << 40)
            | (bit_cast::<128, 8>(self.mb6.q.val().get_bits::<8>(0)) << 48)
            | (bit_cast::<128, 8>(self.mb7.q.val().get_bits::<8>(0)) << 56)
            | (bit_cast::<128, 8>(self.mb8.q.val().get_bits::<8>(0)) << 64)
            | (bit_cast::<128, 8>(self.mb9.q.val().get_bits::<8>(0)) << 72)
            | (bit_cast::<128, 8>(self.mb10.q.val().get_bits::<8>(0)) << 80)
            | (bit_cast::<128, 8>(self.mb11.q.val().get_bits::<8>(0)) << 88)
            | (bit_cast::<128, 8>(self.mb12.q.val().get_bits::<8>(0)) << 96)
            | (bit_cast::<128, 8>(self.mb13.q.val().get_bits::<8>(0)) << 104)
            | (bit_cast::<128, 8>(self.mb14.q.val().get_bits::<8>(0)) << 112)
            | (bit_cast::<128, 8>(self.mb15.q.val().get_bits::<8>(0)) << 120);
        self.timers.next = (bit_cast::<256, 16>(self.mb0.q.val().get_bits::<16>(8)) << 0)
            | (bit_cast::<256, 16>(self.mb1.q.val().get_bits::<16>(8)) << 16)
            | (bit_cast::<256, 16>(self.mb2.q.val().get_bits::<16>(8)) << 32)
            | (bit_cast::<256, 16>(self.mb3.q.val().get_bits::<16>(8)) << 48)
            | (bit_cast::<256, 16>(self.mb4.q.val().get_bits::<16>(8)) << 64)
            | (bit_cast::<256, 16>(self.mb5.q.val().get_bits::<16>(8)) << 80)
            | (bit_cast::<256, 16>(self.mb6.q.val().get_bits::<16>(8)) << 96)
            | (bit_cast::<256, 16>(self.mb7.q.val().get_bits::<16>(8)) << 112)
            | (bit_cast::<256, 16>(self.mb8.q.val().get_bits::<16>(8)) << 128)
            | (bit_cast::<256, 16>(self.mb9.q.val().get_bits::<16>(8)) << 144)
            | (bit_cast::<256, 16>(self.mb10.q.val().get_bits::<16>(8)) << 160)
            | (bit_cast::<256, 16>(self.mb11.q.val().get_bits::<16>(8)) << 176)
            | (bit_cast::<256, 16>(self.mb12.q.val().get_bits::<16>(8)) << 192)
            | (bit_cast::<256, 16>(self.mb13.q.val().get_bits::<16>(8)) << 208)
            | (bit_cast::<256, 16>(self.mb14.q.val().get_bits::<16>(8)) << 224)
            | (bit_cast::<256, 16>(self.mb15.q.val().get_bits::<16>(8)) << 240);
    }
}

#[test]
fn mailbox_state_synthesizes() {
    let mut uut = MailboxState::default();
    uut.connect_all();
    yosys_validate("mailbox_state", &generate_verilog(&uut)).unwrap();
}
