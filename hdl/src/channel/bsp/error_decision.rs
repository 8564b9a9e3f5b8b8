//! Error detection (ISO 11898-1:2015, 12.1.3) decided one clock ahead, for Fmax
//! on the iCE40UP5K: the checks of `error_detection` run every clock for a
//! dominant and for a recessive sample, registered (`sample_lookahead`), so at
//! the sample point every error signal is one LUT after `sample` and `sampled`
//! instead of the whole check. Same value at every output in every clock as
//! `ErrorDetection` itself: its inputs are protocol state that is stable in the
//! clocks before a sample point (see `sample_lookahead`).

use super::error_detection::ErrorDetection;
use super::field::Field;
use super::sample_lookahead::SampleLookahead;
use rust_hdl::prelude::*;

/// The error checks of one sample point, registered one clock ahead.
#[derive(LogicBlock, Default)]
pub struct ErrorDecision {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
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
    /// The node's own SOF read back recessive (a bit error as transmitter).
    pub sof_error: Signal<Out, Bit>,
    /// Arbitration lost: recessive sent, dominant read in arbitration.
    pub lost: Signal<Out, Bit>,
    // the error code capture (contract §9): an error starts a flag and its one
    // kind, by the precedence bit, stuff, form, ACK, CRC
    /// An error is captured and it is a bit error (monitoring, its own stuff bit read back wrong, or its own flag).
    pub kind_bit: Signal<Out, Bit>,
    /// An error is captured and it is a stuff error.
    pub kind_stuff: Signal<Out, Bit>,
    /// An error is captured and it is a CRC error.
    pub kind_crc: Signal<Out, Bit>,
    /// An error is captured and it is a form error.
    pub kind_form: Signal<Out, Bit>,
    /// An error is captured and it is an ACK error.
    pub kind_ack: Signal<Out, Bit>,
    // the checks for either level, unregistered, for the rules' lookahead
    /// `error` if the next sample point reads dominant (before the register).
    pub dom_error: Signal<Out, Bit>,
    /// `flag_error` if the next sample point reads dominant (before the register).
    pub dom_flag_error: Signal<Out, Bit>,
    /// `ack_err` if the next sample point reads dominant (before the register).
    pub dom_ack_err: Signal<Out, Bit>,
    /// `tec_exempt` if the next sample point reads dominant (before the register).
    pub dom_tec_exempt: Signal<Out, Bit>,
    /// `sof_error` if the next sample point reads dominant (before the register).
    pub dom_sof_error: Signal<Out, Bit>,
    /// `error` if the next sample point reads recessive (before the register).
    pub rec_error: Signal<Out, Bit>,
    /// `flag_error` if the next sample point reads recessive (before the register).
    pub rec_flag_error: Signal<Out, Bit>,
    /// `ack_err` if the next sample point reads recessive (before the register).
    pub rec_ack_err: Signal<Out, Bit>,
    /// `tec_exempt` if the next sample point reads recessive (before the register).
    pub rec_tec_exempt: Signal<Out, Bit>,
    /// `sof_error` if the next sample point reads recessive (before the register).
    pub rec_sof_error: Signal<Out, Bit>,
    // the checks for either bus level, and the registered decisions
    if_dominant: ErrorDetection,
    if_recessive: ErrorDetection,
    la_error: SampleLookahead,
    la_flag_error: SampleLookahead,
    la_sof_error: SampleLookahead,
    la_lost: SampleLookahead,
    la_kind_bit: SampleLookahead,
    la_kind_stuff: SampleLookahead,
    la_kind_crc: SampleLookahead,
    la_kind_form: SampleLookahead,
    la_kind_ack: SampleLookahead,
    dom_kind_bit: Signal<Local, Bit>,
    dom_kind_stuff: Signal<Local, Bit>,
    dom_kind_crc: Signal<Local, Bit>,
    dom_kind_form: Signal<Local, Bit>,
    dom_kind_ack: Signal<Local, Bit>,
    rec_kind_bit: Signal<Local, Bit>,
    rec_kind_stuff: Signal<Local, Bit>,
    rec_kind_crc: Signal<Local, Bit>,
    rec_kind_form: Signal<Local, Bit>,
    rec_kind_ack: Signal<Local, Bit>,
    dom_capture: Signal<Local, Bit>,
    rec_capture: Signal<Local, Bit>,
}

impl Logic for ErrorDecision {
    #[hdl_gen]
    fn update(&mut self) {
        // The checks as if this clock were a sample point reading dominant or
        // recessive; state inputs are shared.
        self.if_dominant.sample.next = true;
        self.if_dominant.sampled.next = false;
        self.if_recessive.sample.next = true;
        self.if_recessive.sampled.next = true;
        self.if_dominant.field.next = self.field.val();
        self.if_recessive.field.next = self.field.val();
        self.if_dominant.is_tx.next = self.is_tx.val();
        self.if_recessive.is_tx.next = self.is_tx.val();
        self.if_dominant.tx_bit.next = self.tx_bit.val();
        self.if_recessive.tx_bit.next = self.tx_bit.val();
        self.if_dominant.in_frame.next = self.in_frame.val();
        self.if_recessive.in_frame.next = self.in_frame.val();
        self.if_dominant.in_arbitration.next = self.in_arbitration.val();
        self.if_recessive.in_arbitration.next = self.in_arbitration.val();
        self.if_dominant.ack_slot.next = self.ack_slot.val();
        self.if_recessive.ack_slot.next = self.ack_slot.val();
        self.if_dominant.in_delim.next = self.in_delim.val();
        self.if_recessive.in_delim.next = self.in_delim.val();
        self.if_dominant.bc0.next = self.bc0.val();
        self.if_recessive.bc0.next = self.bc0.val();
        self.if_dominant.bc6.next = self.bc6.val();
        self.if_recessive.bc6.next = self.bc6.val();
        self.if_dominant.bc7.next = self.bc7.val();
        self.if_recessive.bc7.next = self.bc7.val();
        self.if_dominant.flag_passive.next = self.flag_passive.val();
        self.if_recessive.flag_passive.next = self.flag_passive.val();
        self.if_dominant.crc_ok.next = self.crc_ok.val();
        self.if_recessive.crc_ok.next = self.crc_ok.val();
        self.if_dominant.last_bit_arb.next = self.last_bit_arb.val();
        self.if_recessive.last_bit_arb.next = self.last_bit_arb.val();
        self.if_dominant.at_stuff_bit.next = self.at_stuff_bit.val();
        self.if_recessive.at_stuff_bit.next = self.at_stuff_bit.val();
        self.if_dominant.stuff_last.next = self.stuff_last.val();
        self.if_recessive.stuff_last.next = self.stuff_last.val();
        self.if_dominant.listen_only.next = self.listen_only.val();
        self.if_recessive.listen_only.next = self.listen_only.val();
        self.if_dominant.ack_check_off.next = self.ack_check_off.val();
        self.if_recessive.ack_check_off.next = self.ack_check_off.val();
        // The unregistered checks for the rules evaluated one clock ahead.
        self.dom_error.next = self.if_dominant.error.val();
        self.dom_flag_error.next = self.if_dominant.flag_error.val();
        self.dom_ack_err.next = self.if_dominant.ack_err.val();
        self.dom_tec_exempt.next = self.if_dominant.tec_exempt.val();
        self.dom_sof_error.next = self.if_dominant.sof_error.val();
        self.rec_error.next = self.if_recessive.error.val();
        self.rec_flag_error.next = self.if_recessive.flag_error.val();
        self.rec_ack_err.next = self.if_recessive.ack_err.val();
        self.rec_tec_exempt.next = self.if_recessive.tec_exempt.val();
        self.rec_sof_error.next = self.if_recessive.sof_error.val();
        // The sample point picks the registered decision for the level it reads.
        self.la_error.clk.next = self.clk.val();
        self.la_error.sample.next = self.sample.val();
        self.la_error.sampled.next = self.sampled.val();
        self.la_error.if_dominant.next = self.if_dominant.error.val();
        self.la_error.if_recessive.next = self.if_recessive.error.val();
        self.error.next = self.la_error.decision.val();
        self.la_flag_error.clk.next = self.clk.val();
        self.la_flag_error.sample.next = self.sample.val();
        self.la_flag_error.sampled.next = self.sampled.val();
        self.la_flag_error.if_dominant.next = self.if_dominant.flag_error.val();
        self.la_flag_error.if_recessive.next = self.if_recessive.flag_error.val();
        self.flag_error.next = self.la_flag_error.decision.val();
        self.la_sof_error.clk.next = self.clk.val();
        self.la_sof_error.sample.next = self.sample.val();
        self.la_sof_error.sampled.next = self.sampled.val();
        self.la_sof_error.if_dominant.next = self.if_dominant.sof_error.val();
        self.la_sof_error.if_recessive.next = self.if_recessive.sof_error.val();
        self.sof_error.next = self.la_sof_error.decision.val();
        self.la_lost.clk.next = self.clk.val();
        self.la_lost.sample.next = self.sample.val();
        self.la_lost.sampled.next = self.sampled.val();
        self.la_lost.if_dominant.next = self.if_dominant.lost.val();
        self.la_lost.if_recessive.next = self.if_recessive.lost.val();
        self.lost.next = self.la_lost.decision.val();
        // The kind of a captured error for either level (contract §9), one-hot:
        // the error code capture then counts without a decoder.
        self.dom_capture.next = self.if_dominant.error.val() || self.if_dominant.flag_error.val();
        self.dom_kind_bit.next = self.dom_capture.val() && self.if_dominant.bit_err.val();
        self.dom_kind_stuff.next = self.dom_capture.val()
            && !self.if_dominant.bit_err.val()
            && self.if_dominant.stuff_err.val();
        self.dom_kind_form.next = self.dom_capture.val()
            && !self.if_dominant.bit_err.val()
            && !self.if_dominant.stuff_err.val()
            && self.if_dominant.form_err.val();
        self.dom_kind_ack.next = self.dom_capture.val()
            && !self.if_dominant.bit_err.val()
            && !self.if_dominant.stuff_err.val()
            && !self.if_dominant.form_err.val()
            && self.if_dominant.ack_err.val();
        // (a captured error with none of the four above is always a CRC error)
        self.dom_kind_crc.next = self.if_dominant.crc_err.val()
            && !self.if_dominant.bit_err.val()
            && !self.if_dominant.stuff_err.val()
            && !self.if_dominant.form_err.val()
            && !self.if_dominant.ack_err.val();
        self.rec_capture.next = self.if_recessive.error.val() || self.if_recessive.flag_error.val();
        self.rec_kind_bit.next = self.rec_capture.val() && self.if_recessive.bit_err.val();
        self.rec_kind_stuff.next = self.rec_capture.val()
            && !self.if_recessive.bit_err.val()
            && self.if_recessive.stuff_err.val();
        self.rec_kind_form.next = self.rec_capture.val()
            && !self.if_recessive.bit_err.val()
            && !self.if_recessive.stuff_err.val()
            && self.if_recessive.form_err.val();
        self.rec_kind_ack.next = self.rec_capture.val()
            && !self.if_recessive.bit_err.val()
            && !self.if_recessive.stuff_err.val()
            && !self.if_recessive.form_err.val()
            && self.if_recessive.ack_err.val();
        // (a captured error with none of the four above is always a CRC error)
        self.rec_kind_crc.next = self.if_recessive.crc_err.val()
            && !self.if_recessive.bit_err.val()
            && !self.if_recessive.stuff_err.val()
            && !self.if_recessive.form_err.val()
            && !self.if_recessive.ack_err.val();
        self.la_kind_bit.clk.next = self.clk.val();
        self.la_kind_bit.sample.next = self.sample.val();
        self.la_kind_bit.sampled.next = self.sampled.val();
        self.la_kind_bit.if_dominant.next = self.dom_kind_bit.val();
        self.la_kind_bit.if_recessive.next = self.rec_kind_bit.val();
        self.kind_bit.next = self.la_kind_bit.decision.val();
        self.la_kind_stuff.clk.next = self.clk.val();
        self.la_kind_stuff.sample.next = self.sample.val();
        self.la_kind_stuff.sampled.next = self.sampled.val();
        self.la_kind_stuff.if_dominant.next = self.dom_kind_stuff.val();
        self.la_kind_stuff.if_recessive.next = self.rec_kind_stuff.val();
        self.kind_stuff.next = self.la_kind_stuff.decision.val();
        self.la_kind_crc.clk.next = self.clk.val();
        self.la_kind_crc.sample.next = self.sample.val();
        self.la_kind_crc.sampled.next = self.sampled.val();
        self.la_kind_crc.if_dominant.next = self.dom_kind_crc.val();
        self.la_kind_crc.if_recessive.next = self.rec_kind_crc.val();
        self.kind_crc.next = self.la_kind_crc.decision.val();
        self.la_kind_form.clk.next = self.clk.val();
        self.la_kind_form.sample.next = self.sample.val();
        self.la_kind_form.sampled.next = self.sampled.val();
        self.la_kind_form.if_dominant.next = self.dom_kind_form.val();
        self.la_kind_form.if_recessive.next = self.rec_kind_form.val();
        self.kind_form.next = self.la_kind_form.decision.val();
        self.la_kind_ack.clk.next = self.clk.val();
        self.la_kind_ack.sample.next = self.sample.val();
        self.la_kind_ack.sampled.next = self.sampled.val();
        self.la_kind_ack.if_dominant.next = self.dom_kind_ack.val();
        self.la_kind_ack.if_recessive.next = self.rec_kind_ack.val();
        self.kind_ack.next = self.la_kind_ack.decision.val();
    }
}
