//! Transmit request (timing contract §7, §8): the host's frame from `tx_req`
//! until it is sent or dropped, and the decision whether a SOF starts it.
//!
//! A one-clock `tx_req` latches the frame while nothing is pending (listen-only
//! refuses it). The frame stays pending through lost arbitration and errors and
//! is sent again (automatic retransmission) until it is valid for the
//! transmitter (10.7). An attempt runs from its SOF to `tx_done`, lost
//! arbitration or the first error it detects as transmitter; with single shot,
//! per configuration or per request (`tx_single`), or an abort due, a failed
//! attempt drops the frame. An abort is carried out at
//! the first clock the frame is not on the bus, else remembered until then.
//! The protocol control tells this block what happened by one-clock strobes at
//! the sample point; it answers with `starts` / `joins` for the next SOF.

use rust_hdl::prelude::*;

/// The host's transmit request and the attempts to send it.
#[derive(LogicBlock, Default)]
pub struct TxRequest {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: nothing pending.
    pub rst: Signal<In, Bit>,
    // configuration (held)
    /// Listen-only mode (contract §7): requests are refused, nothing starts.
    pub listen_only: Signal<In, Bit>,
    /// Single shot: a failed attempt drops the frame (contract §8).
    pub single_shot: Signal<In, Bit>,
    // host transmit control
    /// One clock: a frame to send (latched while nothing is pending).
    pub tx_req: Signal<In, Bit>,
    /// Latched with `tx_req`: this frame is single shot (contract §8).
    pub tx_single: Signal<In, Bit>,
    /// Abort the pending frame at the first bit it is not on the bus.
    pub tx_abort: Signal<In, Bit>,
    /// A frame is pending.
    pub tx_pending: Signal<Out, Bit>,
    /// One clock: the pending frame was dropped (abort, single shot, refused).
    pub tx_failed: Signal<Out, Bit>,
    /// One clock: the frame was sent (10.7).
    pub tx_done: Signal<Out, Bit>,
    /// One clock: arbitration was lost (the frame stays pending).
    pub arb_lost: Signal<Out, Bit>,
    /// Latch the host's frame into the transmit frame.
    pub tx_load: Signal<Out, Bit>,
    // node state (protocol control and counters)
    /// Counters: the node is bus-off (12.1.4.4): nothing starts.
    pub bus_off: Signal<In, Bit>,
    /// Protocol control: an error-passive transmitter suspends after this
    /// frame (10.4.5), so it joins no SOF at intermission bit 3.
    pub suspend_due: Signal<In, Bit>,
    /// Protocol control: the node is transmitter of the frame.
    pub is_tx: Signal<In, Bit>,
    /// Protocol control: the bit on the `tx` pin now (false: its own SOF is
    /// already on the bus).
    pub tx_pin: Signal<In, Bit>,
    // events of the frame on the bus, at the sample point
    /// The sample point of the current bit (one clock).
    pub sample: Signal<In, Bit>,
    /// Protocol control: a SOF at this sample point.
    pub sof: Signal<In, Bit>,
    /// Protocol control: the node is transmitter of the frame this SOF starts.
    pub sof_as_tx: Signal<In, Bit>,
    /// Protocol control: the frame is valid for its transmitter (10.7).
    pub sent: Signal<In, Bit>,
    /// Error detection: arbitration lost (12.1.2), only at a sample point.
    pub lost: Signal<In, Bit>,
    /// Error detection: a frame error at this sample point.
    pub error: Signal<In, Bit>,
    /// Error detection: a bit error in the node's own flag.
    pub flag_error: Signal<In, Bit>,
    /// Error detection: its own SOF read back recessive (a failed attempt).
    pub sof_error: Signal<In, Bit>,
    /// Rules: bus-off after this sample's counter events (the attempt ends).
    pub bus_off_after: Signal<In, Bit>,
    // to protocol control
    /// A SOF from idle is this node's frame (pending and allowed to start, or
    /// its own SOF already on `tx`).
    pub starts: Signal<Out, Bit>,
    /// A SOF at intermission bit 3 is this node's frame (10.4.5).
    pub joins: Signal<Out, Bit>,
    pending: DFF<Bit>,
    /// The pending frame was requested single shot (`tx_single`).
    single_q: DFF<Bit>,
    /// An abort waits for the frame to leave the bus.
    abort_pending: DFF<Bit>,
    /// An attempt to send the pending frame is on the bus.
    attempt: DFF<Bit>,
    tx_failed_q: DFF<Bit>,
    tx_done_q: DFF<Bit>,
    arb_lost_q: DFF<Bit>,
    start_ok: Signal<Local, Bit>,
    join_ok: Signal<Local, Bit>,
}

impl Logic for TxRequest {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            pending,
            single_q,
            abort_pending,
            attempt,
            tx_failed_q,
            tx_done_q,
            arb_lost_q
        );
        // Contract §8: nothing starts in listen-only mode or while an abort is due.
        self.start_ok.next = self.pending.q.val()
            && !self.bus_off.val()
            && !self.listen_only.val()
            && !self.tx_abort.val()
            && !self.abort_pending.q.val();
        self.tx_failed_q.d.next = false;
        if !self.pending.q.val() {
            self.abort_pending.d.next = false;
        }
        // Transmit abort (contract §8), new or remembered: carried out at the first
        // edge where the frame is not on the bus.
        if (self.tx_abort.val() || self.abort_pending.q.val()) && self.pending.q.val() {
            if !self.is_tx.val() && self.tx_pin.val() {
                self.pending.d.next = false;
                self.tx_failed_q.d.next = true;
                self.abort_pending.d.next = false;
            } else {
                self.abort_pending.d.next = true;
            }
        }
        // 10.4.5: an error-passive transmitter suspends after its frame and does
        // not join a SOF at intermission bit 3.
        self.join_ok.next = self.start_ok.val() && !self.suspend_due.val();
        // A node whose own SOF is already on `tx` keeps its attempt (contract §8).
        self.starts.next = (!self.tx_pin.val() && self.pending.q.val()) || self.start_ok.val();
        self.joins.next = (!self.tx_pin.val() && self.pending.q.val()) || self.join_ok.val();

        // ---- events of the frame on the bus
        self.tx_done_q.d.next = false;
        self.arb_lost_q.d.next = false;
        if self.lost.val() {
            self.arb_lost_q.d.next = true;
        }
        // 10.7: the frame was sent; it and any abort are done.
        if self.sent.val() {
            self.tx_done_q.d.next = true;
            self.pending.d.next = false;
            self.attempt.d.next = false;
            self.abort_pending.d.next = false;
        }
        if self.sample.val() {
            if self.sof.val() {
                self.attempt.d.next = self.sof_as_tx.val();
            }
            // Single shot or a due abort: a failed attempt drops the frame (§8).
            // An attempt runs from its SOF to tx_done, lost arbitration or the
            // first error it detects as transmitter (contract §8).
            if (self.attempt.q.val()
                && self.is_tx.val()
                && (self.lost.val() || self.error.val() || self.flag_error.val()))
                || self.sof_error.val()
            {
                self.attempt.d.next = false;
                if self.single_shot.val() || self.single_q.q.val() || self.abort_pending.q.val() {
                    self.pending.d.next = false;
                    self.tx_failed_q.d.next = true;
                    self.abort_pending.d.next = false;
                }
            }
            // 12.1.4.4: bus-off ends the attempt.
            if self.bus_off_after.val() {
                self.attempt.d.next = false;
            }
        }

        // ---- host transmit request: latched while nothing is pending
        self.tx_load.next = false;
        if self.tx_req.val() && !self.pending.q.val() && self.listen_only.val() {
            // Contract §7: listen-only refuses transmit requests.
            self.tx_failed_q.d.next = true;
        } else if self.tx_req.val() && !self.pending.q.val() {
            self.pending.d.next = true;
            self.single_q.d.next = self.tx_single.val();
            self.tx_load.next = true;
        }

        self.tx_pending.next = self.pending.q.val();
        self.tx_done.next = self.tx_done_q.q.val();
        self.arb_lost.next = self.arb_lost_q.q.val();
        self.tx_failed.next = self.tx_failed_q.q.val();

        // ---- synchronous reset
        if self.rst.val() {
            self.pending.d.next = false;
            self.single_q.d.next = false;
            self.abort_pending.d.next = false;
            self.attempt.d.next = false;
            self.tx_failed_q.d.next = false;
            self.tx_done_q.d.next = false;
            self.arb_lost_q.d.next = false;
        }
    }
}
