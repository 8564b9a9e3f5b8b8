//! Nominal bit tick and bit-time clock of the redundancy management (DRCC
//! contract §4.3, §7 `now`): `tick` pulses once every
//! `(brp+1) * (1 + (tseg1+1) + (tseg2+1))` clocks from the `BTR` fields as written
//! (not clamped). `tq_cnt` counts 0..brp, `bit_cnt` 0..tq_per_bit-1, both wrap at
//! `tick`; `tick` is combinational from them. `now` counts ticks (16 bits,
//! wrapping). Everything is 0 while `hold` (reset mode).

use crate::channel::BRP_BITS;
use rust_hdl::prelude::*;

/// Bit tick and `now`.
#[derive(LogicBlock)]
pub struct BitTick {
    // clock and hold (rst or reset mode)
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst` or reset mode: the counters and `now` are 0, no tick.
    pub hold: Signal<In, Bit>,
    // BTR fields (value - 1 encodings)
    /// `BTR.brp` as written: a time quantum lasts `brp + 1` clocks.
    pub brp: Signal<In, Bits<BRP_BITS>>,
    /// `BTR.tseg1` as written (minus one, not clamped).
    pub tseg1: Signal<In, Bits<4>>,
    /// `BTR.tseg2` as written (minus one, not clamped).
    pub tseg2: Signal<In, Bits<3>>,
    // outputs
    /// Nominal bit tick: one clock every `(brp+1) * (1 + (tseg1+1) + (tseg2+1))` clocks
    /// (combinational).
    pub tick: Signal<Out, Bit>,
    /// Bit-time clock: counts ticks, 16 bits, wrapping (the RX timestamps, contract §7, §11.2).
    pub now: Signal<Out, Bits<16>>,
    tq_cnt: DFF<Bits<BRP_BITS>>,
    bit_cnt: DFF<Bits<5>>,
    now_q: DFF<Bits<16>>,
    tq_last: Signal<Local, Bits<5>>,
    tick_l: Signal<Local, Bit>,
    one5: Constant<Bits<5>>,
    two5: Constant<Bits<5>>,
    one_brp: Constant<Bits<BRP_BITS>>,
    one16: Constant<Bits<16>>,
    zero5: Constant<Bits<5>>,
    zero_brp: Constant<Bits<BRP_BITS>>,
    zero16: Constant<Bits<16>>,
}

impl Default for BitTick {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            hold: Default::default(),
            brp: Default::default(),
            tseg1: Default::default(),
            tseg2: Default::default(),
            tick: Default::default(),
            now: Default::default(),
            tq_cnt: Default::default(),
            bit_cnt: Default::default(),
            now_q: Default::default(),
            tq_last: Default::default(),
            tick_l: Default::default(),
            one5: Constant::new(1.into()),
            two5: Constant::new(2.into()),
            one_brp: Constant::new(1.into()),
            one16: Constant::new(1.into()),
            zero5: Constant::new(0.into()),
            zero_brp: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
        }
    }
}

impl Logic for BitTick {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, tq_cnt, bit_cnt, now_q);
        // last quantum index of a bit: 1 + (tseg1+1) + (tseg2+1) - 1
        self.tq_last.next = bit_cast::<5, 4>(self.tseg1.val())
            + bit_cast::<5, 3>(self.tseg2.val())
            + self.two5.val();
        self.tick_l.next =
            (self.tq_cnt.q.val() == self.brp.val()) & (self.bit_cnt.q.val() == self.tq_last.val());
        self.tq_cnt.d.next = self.tq_cnt.q.val() + self.one_brp.val();
        self.bit_cnt.d.next = self.bit_cnt.q.val();
        self.now_q.d.next = self.now_q.q.val();
        if self.tq_cnt.q.val() == self.brp.val() {
            self.tq_cnt.d.next = self.zero_brp.val();
            if self.bit_cnt.q.val() == self.tq_last.val() {
                self.bit_cnt.d.next = self.zero5.val();
            } else {
                self.bit_cnt.d.next = self.bit_cnt.q.val() + self.one5.val();
            }
        }
        if self.tick_l.val() {
            self.now_q.d.next = self.now_q.q.val() + self.one16.val();
        }
        if self.hold.val() {
            self.tq_cnt.d.next = self.zero_brp.val();
            self.bit_cnt.d.next = self.zero5.val();
            self.now_q.d.next = self.zero16.val();
            self.tick_l.next = false;
        }
        self.tick.next = self.tick_l.val();
        self.now.next = self.now_q.q.val();
    }
}
