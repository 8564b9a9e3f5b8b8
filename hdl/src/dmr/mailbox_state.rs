//! The DMR mailboxes' state (DMR contract §4.1, §4.2, `MB_STATE` of §2.1): the
//! `counter` (8-bit two's complement) and `timer` (16 bits) of every mailbox,
//! packed in two registers. The engine writes one mailbox per clock (`sel`).
//!
//! A write is a per-slot enable and the value repeated in every slot, not a wide
//! variable shift (a barrel shifter on the FPGA). `clear` zeroes every slot at
//! once (reset mode, another DRCC mode, a recovery: §2.1, §7) and wins over a
//! write. The outputs are the registers themselves: the readers (the engine's
//! mailbox, the host window) slice them in the parent, so no combinational path
//! runs from this block's inputs to its outputs (one `always` block per module:
//! a read here would close a false loop through the engine's write data).

use crate::channel::sized::Const;
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
    // ---- the state ----
    /// Every counter (two's complement): mailbox i in `[8i+7:8i]`.
    pub counters: Signal<Out, Bits<128>>,
    /// Every timer (DMR ticks left, 0 = stopped): mailbox i in `[16i+15:16i]`.
    pub timers: Signal<Out, Bits<256>>,
    // ---- registers ----
    cnt_q: DFF<Bits<128>>,
    tmr_q: DFF<Bits<256>>,
    // ---- internals ----
    sel_c: Signal<Local, Bits<7>>,
    sel_t: Signal<Local, Bits<8>>,
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
        dff_setup!(self, clk, cnt_q, tmr_q);
        self.counters.next = self.cnt_q.q.val();
        self.timers.next = self.tmr_q.q.val();
        // slot offsets of the written mailbox
        self.sel_c.next = bit_cast::<7, 4>(self.sel.val()) << 3;
        self.sel_t.next = bit_cast::<8, 4>(self.sel.val()) << 4;
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
            self.cnt_q.d.next =
                (self.cnt_q.q.val() & !self.slot_c.val()) | (self.rep_c.val() & self.slot_c.val());
            self.tmr_q.d.next =
                (self.tmr_q.q.val() & !self.slot_t.val()) | (self.rep_t.val() & self.slot_t.val());
        }
        if self.clear.val() {
            self.cnt_q.d.next = self.zero128.val();
            self.tmr_q.d.next = self.zero256.val();
        }
    }
}

#[test]
fn mailbox_state_synthesizes() {
    let mut uut = MailboxState::default();
    uut.connect_all();
    yosys_validate("mailbox_state", &generate_verilog(&uut)).unwrap();
}
