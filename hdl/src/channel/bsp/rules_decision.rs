//! The fault-confinement rules (ISO 11898-1:2015, 12.1.4.2) decided one clock
//! ahead, for Fmax on the iCE40UP5K: `fault_confinement_rules` runs every clock
//! for a dominant and for a recessive sample, each fed with the error detection
//! of that level (`ErrorDecision`), and is registered (`sample_lookahead`), so
//! the counter events and the error state after them are one LUT after `sample`
//! and `sampled`. The counter thresholds are compared combinationally here: the
//! registered decision then sees the counters of the clock before the sample
//! point, exactly what the rules' former registered threshold pre-decodes held
//! at the sample point. Same value at every output in every clock.

use super::fault_confinement_rules::FaultConfinementRules;
use super::field::Field;
use super::sample_lookahead::SampleLookahead;
use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The counting rules and the error state after them, one clock ahead.
#[derive(LogicBlock, Default)]
pub struct RulesDecision {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// The sample point of the current bit (one clock).
    pub sample: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    // state of the protocol controller (stable before a sample point)
    /// The sampled bit is a stuff bit (no rule looks at it).
    pub at_stuff_bit: Signal<In, Bit>,
    /// The field of the sampled bit.
    pub field: Signal<In, Field>,
    /// The node is transmitter of the frame.
    pub is_tx: Signal<In, Bit>,
    /// The bit the node drives on the bus now.
    pub tx_bit: Signal<In, Bit>,
    /// The node sends a passive error flag.
    pub flag_passive: Signal<In, Bit>,
    /// The field is an error or overload delimiter.
    pub in_delim: Signal<In, Bit>,
    /// The delimiter follows an error flag (not an overload flag).
    pub after_error_flag: Signal<In, Bit>,
    /// The bit counter is 0: in a delimiter, still waiting for recessive.
    pub bc0: Signal<In, Bit>,
    /// The first bit after a flag is next (rule b).
    pub delim_first: Signal<In, Bit>,
    /// Seven dominant bits after a flag were counted (rule f).
    pub dom7: Signal<In, Bit>,
    /// Rule c exception 1 is pending (a passive ACK error).
    pub ack_pending: Signal<In, Bit>,
    /// Listen-only (contract §7): the counters never change.
    pub listen_only: Signal<In, Bit>,
    /// At a sample point: the frame is valid for its transmitter (10.7).
    pub tx_valid: Signal<In, Bit>,
    // error detection for either level (`ErrorDecision`, unregistered)
    /// Error detection, dominant sample: a frame error.
    pub dom_error: Signal<In, Bit>,
    /// Error detection, dominant sample: a bit error in its own flag.
    pub dom_flag_error: Signal<In, Bit>,
    /// Error detection, dominant sample: an ACK error.
    pub dom_ack_err: Signal<In, Bit>,
    /// Error detection, dominant sample: rule c exception 2.
    pub dom_tec_exempt: Signal<In, Bit>,
    /// Error detection, dominant sample: its own SOF read back recessive.
    pub dom_sof_error: Signal<In, Bit>,
    /// Error detection, recessive sample: a frame error.
    pub rec_error: Signal<In, Bit>,
    /// Error detection, recessive sample: a bit error in its own flag.
    pub rec_flag_error: Signal<In, Bit>,
    /// Error detection, recessive sample: an ACK error.
    pub rec_ack_err: Signal<In, Bit>,
    /// Error detection, recessive sample: rule c exception 2.
    pub rec_tec_exempt: Signal<In, Bit>,
    /// Error detection, recessive sample: its own SOF read back recessive.
    pub rec_sof_error: Signal<In, Bit>,
    // from the counters
    /// Transmit error counter.
    pub tec: Signal<In, Bits<9>>,
    /// Receive error counter.
    pub rec: Signal<In, Bits<8>>,
    /// The node is error passive.
    pub error_passive: Signal<In, Bit>,
    /// The node is bus-off.
    pub bus_off: Signal<In, Bit>,
    // events to the counters (listen-only already applied)
    /// TEC + 8 (rules c, d, e, f for a transmitter).
    pub tec_add8: Signal<Out, Bit>,
    /// REC + 1 (rule a).
    pub rec_add1: Signal<Out, Bit>,
    /// REC + 8 (rules b, d, e, f for a receiver).
    pub rec_add8: Signal<Out, Bit>,
    /// REC - 1, or back to 127 from above (rule h).
    pub rx_success: Signal<Out, Bit>,
    /// TEC - 1 (rule g).
    pub tx_success: Signal<Out, Bit>,
    // the error state after this sample's events (rules i/j, 12.1.4.4)
    /// Error passive after the events (the type of the error flag they start).
    pub passive_after: Signal<Out, Bit>,
    /// TEC > 255 after the events: bus-off at once.
    pub bus_off_after: Signal<Out, Bit>,
    // rule c exception 1, for the protocol controller's pending flag
    /// Defer this ACK error of a passive transmitter to its passive flag.
    pub ack_defer: Signal<Out, Bit>,
    /// The deferred ACK error is counted now (a dominant bit in the flag).
    pub ack_counted: Signal<Out, Bit>,
    // the rules for either level, and the registered decisions
    if_dominant: FaultConfinementRules,
    if_recessive: FaultConfinementRules,
    la_tec_add8: SampleLookahead,
    la_rec_add1: SampleLookahead,
    la_rec_add8: SampleLookahead,
    la_rx_success: SampleLookahead,
    la_passive_after: SampleLookahead,
    la_bus_off_after: SampleLookahead,
    la_ack_defer: SampleLookahead,
    la_ack_counted: SampleLookahead,
    tec_ge120: Signal<Local, Bit>,
    tec_ge248: Signal<Local, Bit>,
    rec_ge127: Signal<Local, Bit>,
    rec_ge120: Signal<Local, Bit>,
    n9_120: Const<9, 120>,
    n9_248: Const<9, 248>,
    n8_120: Const<8, 120>,
    n8_127: Const<8, 127>,
}

impl Logic for RulesDecision {
    #[hdl_gen]
    fn update(&mut self) {
        // Threshold compares of the counters as they are now: registered with
        // the rules below, they are what the sample point's counters give.
        self.tec_ge120.next = self.tec.val() >= self.n9_120.val();
        self.tec_ge248.next = self.tec.val() >= self.n9_248.val();
        self.rec_ge127.next = self.rec.val() >= self.n8_127.val();
        self.rec_ge120.next = self.rec.val() >= self.n8_120.val();
        // The rules as if this clock were a sample point reading dominant or
        // recessive, each with the error detection of that level.
        self.if_dominant.sample.next = true;
        self.if_dominant.sampled.next = false;
        self.if_dominant.at_stuff_bit.next = self.at_stuff_bit.val();
        self.if_dominant.field.next = self.field.val();
        self.if_dominant.is_tx.next = self.is_tx.val();
        self.if_dominant.tx_bit.next = self.tx_bit.val();
        self.if_dominant.flag_passive.next = self.flag_passive.val();
        self.if_dominant.in_delim.next = self.in_delim.val();
        self.if_dominant.after_error_flag.next = self.after_error_flag.val();
        self.if_dominant.bc0.next = self.bc0.val();
        self.if_dominant.delim_first.next = self.delim_first.val();
        self.if_dominant.dom7.next = self.dom7.val();
        self.if_dominant.ack_pending.next = self.ack_pending.val();
        self.if_dominant.listen_only.next = self.listen_only.val();
        self.if_dominant.error.next = self.dom_error.val();
        self.if_dominant.flag_error.next = self.dom_flag_error.val();
        self.if_dominant.ack_err.next = self.dom_ack_err.val();
        self.if_dominant.tec_exempt.next = self.dom_tec_exempt.val();
        self.if_dominant.as_tx.next = self.is_tx.val() || self.dom_sof_error.val();
        self.if_dominant.passive_now.next = self.error_passive.val();
        self.if_dominant.bus_off_now.next = self.bus_off.val();
        self.if_dominant.tec_ge120.next = self.tec_ge120.val();
        self.if_dominant.tec_ge248.next = self.tec_ge248.val();
        self.if_dominant.rec_ge127.next = self.rec_ge127.val();
        self.if_dominant.rec_ge120.next = self.rec_ge120.val();
        self.if_recessive.sample.next = true;
        self.if_recessive.sampled.next = true;
        self.if_recessive.at_stuff_bit.next = self.at_stuff_bit.val();
        self.if_recessive.field.next = self.field.val();
        self.if_recessive.is_tx.next = self.is_tx.val();
        self.if_recessive.tx_bit.next = self.tx_bit.val();
        self.if_recessive.flag_passive.next = self.flag_passive.val();
        self.if_recessive.in_delim.next = self.in_delim.val();
        self.if_recessive.after_error_flag.next = self.after_error_flag.val();
        self.if_recessive.bc0.next = self.bc0.val();
        self.if_recessive.delim_first.next = self.delim_first.val();
        self.if_recessive.dom7.next = self.dom7.val();
        self.if_recessive.ack_pending.next = self.ack_pending.val();
        self.if_recessive.listen_only.next = self.listen_only.val();
        self.if_recessive.error.next = self.rec_error.val();
        self.if_recessive.flag_error.next = self.rec_flag_error.val();
        self.if_recessive.ack_err.next = self.rec_ack_err.val();
        self.if_recessive.tec_exempt.next = self.rec_tec_exempt.val();
        self.if_recessive.as_tx.next = self.is_tx.val() || self.rec_sof_error.val();
        self.if_recessive.passive_now.next = self.error_passive.val();
        self.if_recessive.bus_off_now.next = self.bus_off.val();
        self.if_recessive.tec_ge120.next = self.tec_ge120.val();
        self.if_recessive.tec_ge248.next = self.tec_ge248.val();
        self.if_recessive.rec_ge127.next = self.rec_ge127.val();
        self.if_recessive.rec_ge120.next = self.rec_ge120.val();
        // The sample point picks the registered decision for the level it reads.
        self.la_tec_add8.clk.next = self.clk.val();
        self.la_tec_add8.sample.next = self.sample.val();
        self.la_tec_add8.sampled.next = self.sampled.val();
        self.la_tec_add8.if_dominant.next = self.if_dominant.tec_add8.val();
        self.la_tec_add8.if_recessive.next = self.if_recessive.tec_add8.val();
        self.tec_add8.next = self.la_tec_add8.decision.val();
        self.la_rec_add1.clk.next = self.clk.val();
        self.la_rec_add1.sample.next = self.sample.val();
        self.la_rec_add1.sampled.next = self.sampled.val();
        self.la_rec_add1.if_dominant.next = self.if_dominant.rec_add1.val();
        self.la_rec_add1.if_recessive.next = self.if_recessive.rec_add1.val();
        self.rec_add1.next = self.la_rec_add1.decision.val();
        self.la_rec_add8.clk.next = self.clk.val();
        self.la_rec_add8.sample.next = self.sample.val();
        self.la_rec_add8.sampled.next = self.sampled.val();
        self.la_rec_add8.if_dominant.next = self.if_dominant.rec_add8.val();
        self.la_rec_add8.if_recessive.next = self.if_recessive.rec_add8.val();
        self.rec_add8.next = self.la_rec_add8.decision.val();
        self.la_rx_success.clk.next = self.clk.val();
        self.la_rx_success.sample.next = self.sample.val();
        self.la_rx_success.sampled.next = self.sampled.val();
        self.la_rx_success.if_dominant.next = self.if_dominant.rx_success.val();
        self.la_rx_success.if_recessive.next = self.if_recessive.rx_success.val();
        self.rx_success.next = self.la_rx_success.decision.val();
        self.la_passive_after.clk.next = self.clk.val();
        self.la_passive_after.sample.next = self.sample.val();
        self.la_passive_after.sampled.next = self.sampled.val();
        self.la_passive_after.if_dominant.next = self.if_dominant.passive_after.val();
        self.la_passive_after.if_recessive.next = self.if_recessive.passive_after.val();
        self.passive_after.next = self.la_passive_after.decision.val();
        self.la_bus_off_after.clk.next = self.clk.val();
        self.la_bus_off_after.sample.next = self.sample.val();
        self.la_bus_off_after.sampled.next = self.sampled.val();
        self.la_bus_off_after.if_dominant.next = self.if_dominant.bus_off_after.val();
        self.la_bus_off_after.if_recessive.next = self.if_recessive.bus_off_after.val();
        self.bus_off_after.next = self.la_bus_off_after.decision.val();
        self.la_ack_defer.clk.next = self.clk.val();
        self.la_ack_defer.sample.next = self.sample.val();
        self.la_ack_defer.sampled.next = self.sampled.val();
        self.la_ack_defer.if_dominant.next = self.if_dominant.ack_defer.val();
        self.la_ack_defer.if_recessive.next = self.if_recessive.ack_defer.val();
        self.ack_defer.next = self.la_ack_defer.decision.val();
        self.la_ack_counted.clk.next = self.clk.val();
        self.la_ack_counted.sample.next = self.sample.val();
        self.la_ack_counted.sampled.next = self.sampled.val();
        self.la_ack_counted.if_dominant.next = self.if_dominant.ack_counted.val();
        self.la_ack_counted.if_recessive.next = self.if_recessive.ack_counted.val();
        self.ack_counted.next = self.la_ack_counted.decision.val();
        // Rule g: the frame was valid for its transmitter (the protocol
        // controller's own strobe, not looked ahead).
        self.tx_success.next = self.tx_valid.val() && !self.listen_only.val();
    }
}
