//! Fault-confinement rules (ISO 11898-1:2015, 12.1.4.2): which error counter
//! changes at a sample point, by the rule letters of the standard, and the
//! error state that follows (timing contract §4.5). The counters themselves are
//! in `fault_confinement`.
//!
//! Purely combinational: the counters come in as threshold compares, which
//! `rules_decision` evaluates one clock ahead together with these rules, so the
//! state "after this sample's events" needs no combinational path back from the
//! counters. The state the rules keep between bits
//! (the delimiter's dominant-bit count, the deferred ACK error) is protocol
//! state and lives in the protocol controller.

use super::field::Field;
use rust_hdl::prelude::*;

/// The counting rules and the error state after them.
#[derive(LogicBlock, Default)]
pub struct FaultConfinementRules {
    /// The sample point of the current bit (one clock).
    pub sample: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    /// The sampled bit is a stuff bit (no rule looks at it).
    pub at_stuff_bit: Signal<In, Bit>,
    // state of the protocol controller
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
    /// Seven dominant bits after a flag were counted: the next is the 8th
    /// (rule f).
    pub dom7: Signal<In, Bit>,
    /// Rule c exception 1 is pending: a passive ACK error, counted only if a
    /// dominant bit comes during its passive flag.
    pub ack_pending: Signal<In, Bit>,
    /// Listen-only (contract §7): the counters never change, flags are passive.
    pub listen_only: Signal<In, Bit>,
    // from error detection (at a sample point)
    /// A frame error (bit, stuff, CRC, form or ACK).
    pub error: Signal<In, Bit>,
    /// A bit error in the node's own error or overload flag.
    pub flag_error: Signal<In, Bit>,
    /// The error is an ACK error.
    pub ack_err: Signal<In, Bit>,
    /// Rule c exception 2 applies (recessive stuff bit in arbitration).
    pub tec_exempt: Signal<In, Bit>,
    /// The node is transmitter for this error (includes its own SOF read back).
    pub as_tx: Signal<In, Bit>,
    // from the counters: threshold compares of TEC/REC (the lookahead in
    // `rules_decision` gives them for the clock of the sample point)
    /// The node is error passive.
    pub passive_now: Signal<In, Bit>,
    /// The node is bus-off.
    pub bus_off_now: Signal<In, Bit>,
    /// TEC >= 120: TEC + 8 makes the node error passive.
    pub tec_ge120: Signal<In, Bit>,
    /// TEC >= 248: TEC + 8 makes the node bus-off.
    pub tec_ge248: Signal<In, Bit>,
    /// REC >= 127: REC + 1 makes the node error passive.
    pub rec_ge127: Signal<In, Bit>,
    /// REC >= 120: REC + 8 makes the node error passive.
    pub rec_ge120: Signal<In, Bit>,
    // events to the counters (listen-only already applied)
    /// TEC + 8 (rules c, d, e, f for a transmitter).
    pub tec_add8: Signal<Out, Bit>,
    /// REC + 1 (rule a).
    pub rec_add1: Signal<Out, Bit>,
    /// REC + 8 (rules b, d, e, f for a receiver).
    pub rec_add8: Signal<Out, Bit>,
    /// REC - 1 (rule h).
    pub rx_success: Signal<Out, Bit>,
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
    monitor: Signal<Local, Bit>,
    ev_tec_add8: Signal<Local, Bit>,
    ev_rec_add1: Signal<Local, Bit>,
    ev_rec_add8: Signal<Local, Bit>,
    ev_rx_success: Signal<Local, Bit>,
}

impl Logic for FaultConfinementRules {
    #[hdl_gen]
    fn update(&mut self) {
        self.ev_tec_add8.next = false;
        self.ev_rec_add1.next = false;
        self.ev_rec_add8.next = false;
        self.ev_rx_success.next = false;
        self.ack_defer.next = false;
        self.ack_counted.next = false;
        self.monitor.next = self.sample.val() && !self.at_stuff_bit.val();
        if self.monitor.val() {
            // Rule h: received up to the ACK slot and acknowledged it.
            if (self.field.val() == Field::AckSlot)
                && !self.is_tx.val()
                && !self.tx_bit.val()
                && !self.sampled.val()
            {
                self.ev_rx_success.next = true;
            }
            if (self.field.val() == Field::ErrorFlag) && self.flag_passive.val() {
                // Rule c exception 1: a dominant bit during the passive flag that
                // follows a passive ACK error costs TEC + 8 once.
                if self.ack_pending.val() && !self.sampled.val() {
                    self.ev_tec_add8.next = true;
                    self.ack_counted.next = true;
                }
            }
            if self.in_delim.val() && self.bc0.val() && !self.sampled.val() {
                // Rule b: a receiver's dominant first bit after its error flag.
                if self.delim_first.val() && self.after_error_flag.val() && !self.is_tx.val() {
                    self.ev_rec_add8.next = true;
                }
                // Rule f: every 8th consecutive dominant bit after a flag.
                if self.dom7.val() {
                    if self.is_tx.val() {
                        self.ev_tec_add8.next = true;
                    } else {
                        self.ev_rec_add8.next = true;
                    }
                }
            }
        }
        if self.error.val() {
            if self.as_tx.val() {
                if self.ack_err.val() && self.passive_now.val() {
                    // Rule c exception 1: decided during the passive flag.
                    self.ack_defer.next = true;
                } else if !self.tec_exempt.val() {
                    self.ev_tec_add8.next = true; // rule c
                }
            } else {
                self.ev_rec_add1.next = true; // rule a
            }
        }
        if self.flag_error.val() {
            if self.is_tx.val() {
                self.ev_tec_add8.next = true; // rule d
            } else {
                self.ev_rec_add8.next = true; // rule e
            }
        }
        // Rules i/j: the error state after this sample's events.
        self.passive_after.next = self.passive_now.val()
            || (self.ev_tec_add8.val() && self.tec_ge120.val())
            || (self.ev_rec_add1.val() && self.rec_ge127.val())
            || (self.ev_rec_add8.val() && self.rec_ge120.val());
        // 12.1.4.4: TEC > 255 makes the node bus-off at once.
        self.bus_off_after.next = !self.listen_only.val()
            && self.ev_tec_add8.val()
            && self.tec_ge248.val()
            && !self.bus_off_now.val();
        // Contract §7: a listen-only node never changes its counters.
        self.tec_add8.next = self.ev_tec_add8.val() && !self.listen_only.val();
        self.rec_add1.next = self.ev_rec_add1.val() && !self.listen_only.val();
        self.rec_add8.next = self.ev_rec_add8.val() && !self.listen_only.val();
        // Rule g (TEC - 1) is the protocol controller's own strobe: `rules_decision`.
        self.rx_success.next = self.ev_rx_success.val() && !self.listen_only.val();
    }
}
