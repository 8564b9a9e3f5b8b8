//! Error detection (ISO 11898-1:2015, 12.1.3) at the sample point: bit, stuff,
//! CRC, form and ACK errors, errors in the node's own error or overload flag,
//! and lost arbitration (12.1.2), which is not an error.
//!
//! Purely combinational: every input is a register of the protocol controller
//! or of the stuffing counter (or a registered pre-decode of them), so the
//! decision adds no register stage and no path back into this block.

use super::field::Field;
use rust_hdl::prelude::*;

/// The error checks of one sample point.
#[derive(LogicBlock, Default)]
pub struct ErrorDetection {
    /// The sample point of the current bit (one clock).
    pub sample: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    // state of the protocol controller
    /// The field the sampled bit belongs to.
    pub field: Signal<In, Field>,
    /// The node is transmitter of the frame.
    pub is_tx: Signal<In, Bit>,
    /// The bit the node drives on the bus now.
    pub tx_bit: Signal<In, Bit>,
    /// The field is between SOF and EOF (bit monitoring applies).
    pub in_frame: Signal<In, Bit>,
    /// The field is part of the arbitration field (10.4.2.2).
    pub in_arbitration: Signal<In, Bit>,
    /// The field is the ACK slot.
    pub ack_slot: Signal<In, Bit>,
    /// The field is an error or overload delimiter.
    pub in_delim: Signal<In, Bit>,
    /// The bit counter is 0 (registered pre-decode).
    pub bc0: Signal<In, Bit>,
    /// The bit counter is 6: the last EOF bit (registered pre-decode).
    pub bc6: Signal<In, Bit>,
    /// The bit counter is 7: the last delimiter bit (registered pre-decode).
    pub bc7: Signal<In, Bit>,
    /// The node sends a passive error flag.
    pub flag_passive: Signal<In, Bit>,
    /// The received CRC sequence matched.
    pub crc_ok: Signal<In, Bit>,
    /// The last non-stuff bit was in the arbitration field.
    pub last_bit_arb: Signal<In, Bit>,
    // from the stuffing counter
    /// The sampled bit is a stuff bit.
    pub at_stuff_bit: Signal<In, Bit>,
    /// The last bit counted for stuffing.
    pub stuff_last: Signal<In, Bit>,
    // operating mode (contract §7)
    /// Listen-only: no own flags are checked.
    pub listen_only: Signal<In, Bit>,
    /// Self-test or loop-back: no ACK check.
    pub ack_check_off: Signal<In, Bit>,
    // results (valid in the clock of `sample`)
    /// Any error of the frame (bit, stuff, CRC, form or ACK).
    pub error: Signal<Out, Bit>,
    /// A bit error in the node's own error or overload flag (rules d/e).
    pub flag_error: Signal<Out, Bit>,
    /// The error counts as a bit error (contract §9): monitoring, a stuff bit
    /// of its own read back wrong, or an error in its own flag.
    pub bit_err: Signal<Out, Bit>,
    /// Stuff error.
    pub stuff_err: Signal<Out, Bit>,
    /// Form error.
    pub form_err: Signal<Out, Bit>,
    /// CRC error.
    pub crc_err: Signal<Out, Bit>,
    /// ACK error.
    pub ack_err: Signal<Out, Bit>,
    /// The node's own SOF read back recessive (a bit error as transmitter).
    pub sof_error: Signal<Out, Bit>,
    /// Arbitration lost: recessive sent, dominant read in arbitration.
    pub lost: Signal<Out, Bit>,
    /// 12.1.4.2 rule c exception 2: the stuff error needs no TEC increment.
    pub tec_exempt: Signal<Out, Bit>,
    monitor: Signal<Local, Bit>,
    bit_mon: Signal<Local, Bit>,
    stuff_as_bit: Signal<Local, Bit>,
}

impl Logic for ErrorDetection {
    // rust-hdl's hdl_gen has no match guards; each check stays next to its
    // clause as written in the standard.
    #[allow(clippy::collapsible_match, clippy::nonminimal_bool)]
    #[hdl_gen]
    fn update(&mut self) {
        self.stuff_err.next = false;
        self.stuff_as_bit.next = false;
        self.tec_exempt.next = false;
        self.bit_mon.next = false;
        self.form_err.next = false;
        self.crc_err.next = false;
        self.ack_err.next = false;
        self.flag_error.next = false;
        self.sof_error.next = false;
        self.lost.next = false;
        // 10.5: a stuff bit must be the complement of the five before it.
        if self.sample.val()
            && self.at_stuff_bit.val()
            && (self.sampled.val() == self.stuff_last.val())
        {
            self.stuff_err.next = true;
            // A transmitter reads back its own stuff bit: a bit error, except the
            // recessive stuff bit in arbitration (12.1.4.2 rule c exception 2).
            if self.is_tx.val() && !(self.last_bit_arb.val() && self.tx_bit.val()) {
                self.stuff_as_bit.next = true;
            }
            if self.is_tx.val() && self.last_bit_arb.val() && self.tx_bit.val() {
                self.tec_exempt.next = true;
            }
        }
        self.monitor.next = self.sample.val() && !self.at_stuff_bit.val();
        if self.monitor.val() {
            // 12.1.3.1 bit monitoring by the transmitter, with 12.1.2 arbitration.
            if self.is_tx.val() && self.in_frame.val() && (self.sampled.val() != self.tx_bit.val())
            {
                if self.in_arbitration.val() && self.tx_bit.val() {
                    self.lost.next = true;
                } else if self.ack_slot.val() && self.tx_bit.val() {
                    // Dominant ACK slot: acknowledged.
                } else {
                    self.bit_mon.next = true;
                }
            }
            // 12.1.3.1: a receiver's own dominant ACK read back recessive.
            if !self.is_tx.val() && self.ack_slot.val() && !self.tx_bit.val() && self.sampled.val()
            {
                self.bit_mon.next = true;
            }
            match self.field.val() {
                Field::Idle => {
                    // 12.1.3.1: its own SOF read back recessive.
                    if self.sampled.val() && !self.tx_bit.val() {
                        self.sof_error.next = true;
                        self.bit_mon.next = true;
                    }
                }
                Field::CrcDelim => {
                    // 12.1.3.4: a fixed-form bit read dominant.
                    self.form_err.next = !self.sampled.val();
                }
                Field::AckSlot => {
                    // 12.1.3.5 ACK error (not checked in self-test and loop-back).
                    self.ack_err.next =
                        self.is_tx.val() && self.sampled.val() && !self.ack_check_off.val();
                }
                Field::AckDelim => {
                    if !self.sampled.val() {
                        self.form_err.next = true; // 12.1.3.4
                    } else if !self.crc_ok.val() && !self.is_tx.val() {
                        // 12.1.3.3: the CRC error flag starts after the ACK delimiter.
                        self.crc_err.next = true;
                    }
                }
                Field::Eof => {
                    // 12.1.3.4, except a receiver's dominant last EOF bit, which is
                    // an overload condition (10.4.4).
                    if !self.sampled.val() && !(self.bc6.val() && !self.is_tx.val()) {
                        self.form_err.next = true;
                    }
                }
                Field::ErrorFlag => {
                    // Rules d/e: a bit error in its own active error flag.
                    self.flag_error.next = !self.flag_passive.val() && self.sampled.val();
                }
                Field::OverloadFlag => {
                    // Rules d/e: a bit error in its own overload flag.
                    self.flag_error.next = self.sampled.val() && !self.listen_only.val();
                }
                _ => {}
            }
            // 12.1.3.4 in a delimiter: a dominant bit after the first recessive
            // one, except the eighth (an overload flag follows, 10.4.4).
            if self.in_delim.val() && !self.bc0.val() && !self.sampled.val() && !self.bc7.val() {
                self.form_err.next = true;
            }
        }
        self.error.next = self.stuff_err.val()
            || self.bit_mon.val()
            || self.form_err.val()
            || self.crc_err.val()
            || self.ack_err.val();
        self.bit_err.next = self.stuff_as_bit.val() || self.bit_mon.val() || self.flag_error.val();
    }
}
