//! Bit stuffing and destuffing (ISO 11898-1:2015, 10.5): the one counter of
//! equal consecutive bits that both directions share.
//!
//! A CAN transmitter reads back every bit it sends, so the bits it counts for
//! stuffing are the bits every receiver counts for destuffing: one counter, fed
//! with the sampled bit, serves both. After five equal bits the next bit is a
//! stuff bit: the transmitter sends the complement of the last bit (`insert`,
//! `last`), every node skips it (`at_stuff_bit`) and checks it (error detection).
//! The stuffed region runs from SOF to the end of the CRC sequence.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The stuff-bit counter.
#[derive(LogicBlock, Default)]
pub struct BitStuffing {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset.
    pub rst: Signal<In, Bit>,
    /// The sample point of the current bit (one clock).
    pub sample: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    /// At a sample point: a frame starts (SOF), the stuffed region begins.
    pub start: Signal<In, Bit>,
    /// At a sample point: the stuffed region ends (CRC delimiter or an error).
    pub stop: Signal<In, Bit>,
    /// At a sample point: restart the run of equal bits from this bit (a passive
    /// error flag looks for 6 equal bits with the same register, 10.4.3).
    pub resync: Signal<In, Bit>,
    /// The next bit is a stuff bit (from the counter, for the transmitter).
    pub insert: Signal<Out, Bit>,
    /// Registered copy of `insert`, valid at every sample point.
    pub at_stuff_bit: Signal<Out, Bit>,
    /// The last bit counted: a stuff bit must be its complement.
    pub last: Signal<Out, Bit>,
    /// Length of the current run of equal bits (1..=5).
    cnt: DFF<Bits<3>>,
    last_q: DFF<Bit>,
    en: DFF<Bit>,
    at_stuff_q: DFF<Bit>,
    one: Const<3, 1>,
    five: Const<3, 5>,
}

impl Logic for BitStuffing {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, cnt, last_q, en, at_stuff_q);
        // 10.5: after five equal bits the transmitter inserts the complement.
        self.insert.next = self.en.q.val() && (self.cnt.q.val() == self.five.val());
        self.at_stuff_q.d.next = self.insert.val();
        self.at_stuff_bit.next = self.at_stuff_q.q.val();
        self.last.next = self.last_q.q.val();
        if self.sample.val() {
            if self.at_stuff_q.q.val() {
                // A correct stuff bit starts a new run; a wrong one is a stuff error
                // (error detection) and the region ends.
                if self.sampled.val() != self.last_q.q.val() {
                    self.cnt.d.next = self.one.val();
                    self.last_q.d.next = self.sampled.val();
                }
            } else if self.en.q.val() {
                if self.sampled.val() == self.last_q.q.val() {
                    self.cnt.d.next = self.cnt.q.val() + self.one.val();
                } else {
                    self.cnt.d.next = self.one.val();
                    self.last_q.d.next = self.sampled.val();
                }
            }
        }
        if self.resync.val() {
            self.last_q.d.next = self.sampled.val();
        }
        // SOF is dominant: it is the first bit of the first run.
        if self.start.val() {
            self.en.d.next = true;
            self.cnt.d.next = self.one.val();
            self.last_q.d.next = false;
        }
        if self.stop.val() {
            self.en.d.next = false;
        }
        if self.rst.val() {
            self.cnt.d.next = self.one.val();
            self.last_q.d.next = false;
            self.en.d.next = false;
        }
    }
}
