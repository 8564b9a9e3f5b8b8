//! The frame's CRC register (ISO 11898-1:2015, 10.4.2.6): computed over the
//! destuffed bits from SOF to the end of the data field, sent by a transmitter
//! and checked bit by bit by a receiver during the CRC field.
//!
//! A transmitter sends the register itself in the CRC field (the CRC bits are
//! not shifted in), so one register serves sending and checking.

use super::crc::Crc15Step;
use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The CRC-15 register and the CRC check.
#[derive(LogicBlock, Default)]
pub struct FrameCrc {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset.
    pub rst: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    /// At a sample point: SOF, start a new CRC.
    pub start: Signal<In, Bit>,
    /// At a sample point: a bit covered by the CRC (SOF to the data field).
    pub step: Signal<In, Bit>,
    /// At a sample point: a bit of the received CRC sequence, check it.
    pub check: Signal<In, Bit>,
    /// The next bit belongs to the CRC field (for the registered pre-decode).
    pub in_crc_field: Signal<In, Bit>,
    /// Position of the next bit in the CRC field.
    pub bit_cnt: Signal<In, Bits<4>>,
    /// The CRC register (the sequence a transmitter sends).
    pub crc: Signal<Out, Bits<15>>,
    /// Every received CRC bit so far matched.
    pub crc_ok: Signal<Out, Bit>,
    crc_q: DFF<Bits<15>>,
    crc_ok_q: DFF<Bit>,
    /// CRC bit 14 - n, registered before the sample point of CRC bit n.
    p_crc_bit: DFF<Bit>,
    crc_rx_idx: Signal<Local, Bits<4>>,
    crc_step: Crc15Step,
    n4_14: Const<4, 14>,
    zero15: Const<15, 0>,
}

impl Logic for FrameCrc {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, crc_q, crc_ok_q, p_crc_bit);
        self.crc_step.crc.next = self.crc_q.q.val();
        self.crc_step.data_bit.next = self.sampled.val();
        self.crc_rx_idx.next = self.n4_14.val() - self.bit_cnt.val();
        // (indexed only in the CRC field, where the index is in range)
        self.p_crc_bit.d.next = false;
        if self.in_crc_field.val() {
            self.p_crc_bit.d.next = self.crc_q.q.val().get_bit(self.crc_rx_idx.val().index());
        }
        if self.step.val() {
            self.crc_q.d.next = self.crc_step.crc_next.val();
        }
        if self.check.val() && (self.sampled.val() != self.p_crc_bit.q.val()) {
            self.crc_ok_q.d.next = false;
        }
        if self.start.val() {
            self.crc_q.d.next = self.zero15.val();
            self.crc_ok_q.d.next = true;
        }
        if self.rst.val() {
            self.crc_q.d.next = self.zero15.val();
            self.crc_ok_q.d.next = true;
        }
        self.crc.next = self.crc_q.q.val();
        self.crc_ok.next = self.crc_ok_q.q.val();
    }
}
