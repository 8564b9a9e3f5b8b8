//! The DMR mailboxes' state (DMR contract §4.1, §4.2, `MB_STATE` of §2.1): the
//! `counter` (8-bit two's complement) and `timer` (16 bits) of every mailbox,
//! packed in two registers. The engine reads and writes one mailbox per clock
//! (its `sel`); the host window reads another (`win_sel`), live.
//!
//! A write is a per-slot enable and the value repeated in every slot, not a wide
//! variable shift (a barrel shifter on the FPGA); reads are a slice at a variable
//! offset (a 16-way multiplexer). `clear` zeroes every slot at once (reset mode,
//! another DRCC mode, a recovery: §2.1, §7) and wins over a write.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// Counter and timer of 16 mailboxes.
#[derive(LogicBlock, Default)]
pub struct MailboxState {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Every counter and timer becomes 0 at this edge (over a write).
    pub clear: Signal<In, Bit>,
    // ---- the engine's port: one mailbox, read live, written at the edge ----
    /// The engine's mailbox.
    pub sel: Signal<In, Bits<4>>,
    /// `counter` of mailbox `sel` (two's complement).
    pub counter: Signal<Out, Bits<8>>,
    /// `timer` of mailbox `sel` (DMR ticks left, 0 = stopped).
    pub timer: Signal<Out, Bits<16>>,
    /// Write `counter_d` and `timer_d` to mailbox `sel` at this edge.
    pub we: Signal<In, Bit>,
    /// The new counter of mailbox `sel`.
    pub counter_d: Signal<In, Bits<8>>,
    /// The new timer of mailbox `sel`.
    pub timer_d: Signal<In, Bits<16>>,
    // ---- the host window ----
    /// `MB_SEL`: the mailbox of the window.
    pub win_sel: Signal<In, Bits<4>>,
    /// `MB_STATE` of mailbox `win_sel`: [7:0] counter, [31:16] timer.
    pub win_word: Signal<Out, Bits<32>>,
    // ---- registers: mailbox i in counters [8i+7:8i], timers [16i+15:16i] ----
    counters: DFF<Bits<128>>,
    timers: DFF<Bits<256>>,
    // ---- internals ----
    sel_c: Signal<Local, Bits<7>>,
    sel_t: Signal<Local, Bits<8>>,
    win_c: Signal<Local, Bits<7>>,
    win_t: Signal<Local, Bits<8>>,
    slot_c: Signal<Local, Bits<128>>,
    slot_t: Signal<Local, Bits<256>>,
    c128: Signal<Local, Bits<128>>,
    t256: Signal<Local, Bits<256>>,
    rep_c: Signal<Local, Bits<128>>,
    rep_t: Signal<Local, Bits<256>>,
    slot_mask_c: Const<128, 0xFF>,
    slot_mask_t: Const<256, 0xFFFF>,
    zero128: Const<128, 0>,
    zero256: Const<256, 0>,
}

impl Logic for MailboxState {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, counters, timers);
        // slot offsets of the engine's mailbox and of the window's
        self.sel_c.next = bit_cast::<7, 4>(self.sel.val()) << 3;
        self.sel_t.next = bit_cast::<8, 4>(self.sel.val()) << 4;
        self.win_c.next = bit_cast::<7, 4>(self.win_sel.val()) << 3;
        self.win_t.next = bit_cast::<8, 4>(self.win_sel.val()) << 4;
        // reads
        self.counter.next = self
            .counters
            .q
            .val()
            .get_bits::<8>(self.sel_c.val().index());
        self.timer.next = self.timers.q.val().get_bits::<16>(self.sel_t.val().index());
        self.win_word.next = bit_cast::<32, 8>(
            self.counters
                .q
                .val()
                .get_bits::<8>(self.win_c.val().index()),
        ) | (bit_cast::<32, 16>(
            self.timers.q.val().get_bits::<16>(self.win_t.val().index()),
        ) << 16);
        // the write: a slot enable (a constant shifted: a decoder) and the value
        // in every slot (wiring)
        self.slot_c.next = self.slot_mask_c.val() << self.sel_c.val();
        self.slot_t.next = self.slot_mask_t.val() << self.sel_t.val();
        self.c128.next = bit_cast::<128, 8>(self.counter_d.val());
        self.t256.next = bit_cast::<256, 16>(self.timer_d.val());
        self.rep_c.next = self.c128.val()
            | (self.c128.val() << 8)
            | (self.c128.val() << 16)
            | (self.c128.val() << 24)
            | (self.c128.val() << 32)
            | (self.c128.val() << 40)
            | (self.c128.val() << 48)
            | (self.c128.val() << 56)
            | (self.c128.val() << 64)
            | (self.c128.val() << 72)
            | (self.c128.val() << 80)
            | (self.c128.val() << 88)
            | (self.c128.val() << 96)
            | (self.c128.val() << 104)
            | (self.c128.val() << 112)
            | (self.c128.val() << 120);
        self.rep_t.next = self.t256.val()
            | (self.t256.val() << 16)
            | (self.t256.val() << 32)
            | (self.t256.val() << 48)
            | (self.t256.val() << 64)
            | (self.t256.val() << 80)
            | (self.t256.val() << 96)
            | (self.t256.val() << 112)
            | (self.t256.val() << 128)
            | (self.t256.val() << 144)
            | (self.t256.val() << 160)
            | (self.t256.val() << 176)
            | (self.t256.val() << 192)
            | (self.t256.val() << 208)
            | (self.t256.val() << 224)
            | (self.t256.val() << 240);
        if self.we.val() {
            self.counters.d.next = (self.counters.q.val() & !self.slot_c.val())
                | (self.rep_c.val() & self.slot_c.val());
            self.timers.d.next =
                (self.timers.q.val() & !self.slot_t.val()) | (self.rep_t.val() & self.slot_t.val());
        }
        if self.clear.val() {
            self.counters.d.next = self.zero128.val();
            self.timers.d.next = self.zero256.val();
        }
    }
}

#[test]
fn mailbox_state_synthesizes() {
    let mut uut = MailboxState::default();
    uut.connect_all();
    yosys_validate("mailbox_state", &generate_verilog(&uut)).unwrap();
}
