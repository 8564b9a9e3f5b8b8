//! The DMR control (DMR contract §3, §5, §6, §7): everything of the DMR function
//! but the engine with its mailboxes (`DmrEngine`, which takes the events raised
//! here and returns the evaluation's verdict) and the register storage (`DmrRegs`,
//! whose configuration arrives on ports). It wires the time base
//! ([`super::time_base`]), the CS reception ([`super::cs_rx`]), the two lines
//! ([`super::line`]: requests, completion, flags, CS attempt, recovery), the queue
//! offsets ([`super::offsets`]) and the state machine ([`super::status`]).
//!
//! `hold` is the reset-mode state of the contract (`!(CTRL.dmr && !reset_mode)`):
//! everything clears but the statistics, `cs_due = 1`, and no event leaves.

use super::cs_rx::DmrCsRx;
use super::line::DmrLine;
use super::offsets::DmrOffsets;
use super::status::DmrStatus;
use super::time_base::DmrTimeBase;
use rust_hdl::prelude::*;

/// The DMR control block.
#[derive(LogicBlock, Default)]
pub struct DmrControl {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// The DRCC `rst`: every register, the statistics too.
    pub rst: Signal<In, Bit>,
    /// Not running (`!(CTRL.dmr && !reset_mode)`): the reset-mode state.
    pub hold: Signal<In, Bit>,
    // ---- configuration (DmrRegs) ----
    /// `DMR_CFG.timeout`: mailbox and CS timeout, DMR ticks.
    pub timeout: Signal<In, Bits<16>>,
    /// `DMR_CFG.cs_period`: DMR ticks between periodic CS frames, 0 = none.
    pub cs_period: Signal<In, Bits<16>>,
    /// `DMR_TIME.tick_bits`: nominal bit times per DMR tick.
    pub tick_bits: Signal<In, Bits<16>>,
    /// `DMR_TIME.recovery_delay`: DMR ticks.
    pub recovery_delay: Signal<In, Bits<16>>,
    /// `DMR_CS.cs_id_dcl`: CS identifier of the DCL.
    pub cs_id_dcl: Signal<In, Bits<11>>,
    /// `DMR_CS.cs_id_rcl`: CS identifier of the RCL.
    pub cs_id_rcl: Signal<In, Bits<11>>,
    // ---- DRCC timing ----
    /// The nominal bit tick.
    pub tick: Signal<In, Bit>,
    /// `reset_mode_q` (part of both channels' `rst`).
    pub reset_mode_q: Signal<In, Bit>,
    // ---- channel A (DCL): registered outputs ----
    /// `tx_done`.
    pub done_dcl: Signal<In, Bit>,
    /// `tx_failed`.
    pub failed_dcl: Signal<In, Bit>,
    /// `rx_valid`.
    pub rx_valid_dcl: Signal<In, Bit>,
    /// `rx_ide`.
    pub rx_ide_dcl: Signal<In, Bit>,
    /// `rx_rtr`.
    pub rx_rtr_dcl: Signal<In, Bit>,
    /// `rx_dlc`.
    pub rx_dlc_dcl: Signal<In, Bits<4>>,
    /// `rx_id`.
    pub rx_id_dcl: Signal<In, Bits<29>>,
    /// Fault-confinement state (2 = bus-off).
    pub err_state_dcl: Signal<In, Bits<2>>,
    // ---- channel B (RCL): registered outputs ----
    /// `tx_done`.
    pub done_rcl: Signal<In, Bit>,
    /// `tx_failed`.
    pub failed_rcl: Signal<In, Bit>,
    /// `rx_valid`.
    pub rx_valid_rcl: Signal<In, Bit>,
    /// `rx_ide`.
    pub rx_ide_rcl: Signal<In, Bit>,
    /// `rx_rtr`.
    pub rx_rtr_rcl: Signal<In, Bit>,
    /// `rx_dlc`.
    pub rx_dlc_rcl: Signal<In, Bits<4>>,
    /// `rx_id`.
    pub rx_id_rcl: Signal<In, Bits<29>>,
    /// Fault-confinement state (2 = bus-off).
    pub err_state_rcl: Signal<In, Bits<2>>,
    // ---- TX queue A ----
    /// `count`.
    pub q_count: Signal<In, Bits<4>>,
    /// `ide` of the RAM read data register.
    pub rd_ide: Signal<In, Bit>,
    /// `id` of the RAM read data register.
    pub rd_id: Signal<In, Bits<29>>,
    /// The read port's line select (toggles every edge).
    pub rd_sel: Signal<In, Bit>,
    // ---- the engine's verdict (combinational, at the edge of the fault) ----
    /// An evaluation found a fault.
    pub eval_fault: Signal<In, Bit>,
    /// Its line (0 DCL, 1 RCL).
    pub eval_line: Signal<In, Bit>,
    /// A transmit mailbox (`tx_fault`), else a receive one (`rx_fault`).
    pub eval_tx: Signal<In, Bit>,
    /// Deviation (1) or timeout (0).
    pub eval_deviation: Signal<In, Bit>,
    /// The mailbox.
    pub eval_mb: Signal<In, Bits<4>>,
    // ---- to the channels ----
    /// DCL `tx_req` (`req | cs_req`).
    pub tx_req_dcl: Signal<Out, Bit>,
    /// RCL `tx_req`.
    pub tx_req_rcl: Signal<Out, Bit>,
    /// The DCL channel sends its CS frame (mux it onto the frame inputs).
    pub cs_req_dcl: Signal<Out, Bit>,
    /// The RCL channel sends its CS frame.
    pub cs_req_rcl: Signal<Out, Bit>,
    /// DCL `tx_abort`.
    pub tx_abort_dcl: Signal<Out, Bit>,
    /// RCL `tx_abort`.
    pub tx_abort_rcl: Signal<Out, Bit>,
    /// DCL channel restart (its `rst` in the next clock).
    pub restart_dcl: Signal<Out, Bit>,
    /// RCL channel restart.
    pub restart_rcl: Signal<Out, Bit>,
    // ---- to TX queue A ----
    /// `off[DCL]`.
    pub off_dcl: Signal<Out, Bits<4>>,
    /// `off[RCL]`.
    pub off_rcl: Signal<Out, Bits<4>>,
    /// Entries the queue frees at this edge (combinational).
    pub pop: Signal<Out, Bits<4>>,
    // ---- to the engine (combinational, §4.1) ----
    /// `TX(DCL)`.
    pub raise_tx_dcl: Signal<Out, Bit>,
    /// `TX(RCL)`.
    pub raise_tx_rcl: Signal<Out, Bit>,
    /// `RX(DCL)`.
    pub raise_rx_dcl: Signal<Out, Bit>,
    /// `RX(RCL)`.
    pub raise_rx_rcl: Signal<Out, Bit>,
    /// `REQ(DCL)`.
    pub raise_req_dcl: Signal<Out, Bit>,
    /// `REQ(RCL)`.
    pub raise_req_rcl: Signal<Out, Bit>,
    /// Key of `TX(DCL)` (`{ide, id}`).
    pub key_tx_dcl: Signal<Out, Bits<30>>,
    /// Key of `TX(RCL)`.
    pub key_tx_rcl: Signal<Out, Bits<30>>,
    /// Key of `RX(DCL)`.
    pub key_rx_dcl: Signal<Out, Bits<30>>,
    /// Key of `RX(RCL)`.
    pub key_rx_rcl: Signal<Out, Bits<30>>,
    /// Key of `REQ(DCL)`.
    pub key_req_dcl: Signal<Out, Bits<30>>,
    /// Key of `REQ(RCL)`.
    pub key_req_rcl: Signal<Out, Bits<30>>,
    /// The evaluation event (the `dmr_tick` register).
    pub raise_eval: Signal<Out, Bit>,
    /// A recovery succeeded at this edge: every mailbox's counter and timer to 0.
    pub clear_mailboxes: Signal<Out, Bit>,
    // ---- to the RX path ----
    /// A DCL frame that is not a CS frame.
    pub rx_deliver_dcl: Signal<Out, Bit>,
    /// An RCL frame that is not a CS frame.
    pub rx_deliver_rcl: Signal<Out, Bit>,
    /// The ACL switches at this edge.
    pub acl_switch: Signal<Out, Bit>,
    // ---- to the register block (combinational) ----
    /// `INT_STATUS.tx_done`: the first copy of a message.
    pub tx_done_evt: Signal<Out, Bit>,
    /// `INT_STATUS.dmr`: `dmr_state` or `acl` changed.
    pub int_evt: Signal<Out, Bit>,
    // ---- status (registers) ----
    /// `dmr_state`.
    pub dmr_state: Signal<Out, Bits<2>>,
    /// `acl`.
    pub acl: Signal<Out, Bit>,
    /// `tx_fault[DCL]`.
    pub dcl_tx_fault: Signal<Out, Bit>,
    /// `rx_fault[DCL]`.
    pub dcl_rx_fault: Signal<Out, Bit>,
    /// `tx_fault[RCL]`.
    pub rcl_tx_fault: Signal<Out, Bit>,
    /// `rx_fault[RCL]`.
    pub rcl_rx_fault: Signal<Out, Bit>,
    /// `dmr_tick`.
    pub dmr_tick: Signal<Out, Bit>,
    /// `DMR_STATUS`.
    pub status_word: Signal<Out, Bits<32>>,
    /// `DMR_CS_COUNT`.
    pub cs_count_word: Signal<Out, Bits<32>>,
    // ---- blocks ----
    /// §3 time base and the CS period.
    pub time_base: DmrTimeBase,
    /// §7 CS reception and counts.
    pub cs_rx: DmrCsRx,
    /// The DCL.
    pub dcl: DmrLine,
    /// The RCL.
    pub rcl: DmrLine,
    /// §5 offsets and pop.
    pub offsets: DmrOffsets,
    /// §6 state machine.
    pub status: DmrStatus,
    // ---- internals ----
    clear: Signal<Local, Bit>,
    run: Signal<Local, Bit>,
    rd_key: Signal<Local, Bits<30>>,
}

impl Logic for DmrControl {
    #[hdl_gen]
    fn update(&mut self) {
        self.clear.next = self.rst.val() | self.hold.val();
        self.run.next = !self.clear.val();
        self.rd_key.next = bit_cast::<30, 29>(self.rd_id.val())
            | (bit_cast::<30, 1>(self.rd_ide.val().into()) << 29);
        // §3 time base.
        self.time_base.clk.next = self.clk.val();
        self.time_base.clear.next = self.clear.val();
        self.time_base.tick_bits.next = self.tick_bits.val();
        self.time_base.cs_period.next = self.cs_period.val();
        self.time_base.tick.next = self.tick.val();
        // §7 CS reception.
        self.cs_rx.clk.next = self.clk.val();
        self.cs_rx.rst.next = self.rst.val();
        self.cs_rx.run.next = self.run.val();
        self.cs_rx.cs_id_dcl.next = self.cs_id_dcl.val();
        self.cs_rx.cs_id_rcl.next = self.cs_id_rcl.val();
        self.cs_rx.rx_valid_dcl.next = self.rx_valid_dcl.val();
        self.cs_rx.rx_ide_dcl.next = self.rx_ide_dcl.val();
        self.cs_rx.rx_rtr_dcl.next = self.rx_rtr_dcl.val();
        self.cs_rx.rx_dlc_dcl.next = self.rx_dlc_dcl.val();
        self.cs_rx.rx_id_dcl.next = self.rx_id_dcl.val().get_bits::<11>(0);
        self.cs_rx.rx_valid_rcl.next = self.rx_valid_rcl.val();
        self.cs_rx.rx_ide_rcl.next = self.rx_ide_rcl.val();
        self.cs_rx.rx_rtr_rcl.next = self.rx_rtr_rcl.val();
        self.cs_rx.rx_dlc_rcl.next = self.rx_dlc_rcl.val();
        self.cs_rx.rx_id_rcl.next = self.rx_id_rcl.val().get_bits::<11>(0);
        // §5-§7 the DCL (channel A).
        self.dcl.clk.next = self.clk.val();
        self.dcl.rst.next = self.rst.val();
        self.dcl.hold.next = self.hold.val();
        self.dcl.timeout.next = self.timeout.val();
        self.dcl.recovery_delay.next = self.recovery_delay.val();
        self.dcl.dmr_tick.next = self.time_base.dmr_tick.val();
        self.dcl.period_due.next = self.time_base.period_due.val();
        self.dcl.mine.next = !self.rd_sel.val();
        self.dcl.more.next = self.offsets.more_dcl.val();
        self.dcl.rd_key.next = self.rd_key.val();
        self.dcl.reset_mode_q.next = self.reset_mode_q.val();
        self.dcl.done.next = self.done_dcl.val();
        self.dcl.failed.next = self.failed_dcl.val();
        self.dcl.err_state.next = self.err_state_dcl.val();
        self.dcl.other_sends.next = !self.rcl.tx_fault.val();
        self.dcl.eval_here.next = self.eval_fault.val() & !self.eval_line.val();
        self.dcl.eval_tx.next = self.eval_tx.val();
        // The RCL (channel B).
        self.rcl.clk.next = self.clk.val();
        self.rcl.rst.next = self.rst.val();
        self.rcl.hold.next = self.hold.val();
        self.rcl.timeout.next = self.timeout.val();
        self.rcl.recovery_delay.next = self.recovery_delay.val();
        self.rcl.dmr_tick.next = self.time_base.dmr_tick.val();
        self.rcl.period_due.next = self.time_base.period_due.val();
        self.rcl.mine.next = self.rd_sel.val();
        self.rcl.more.next = self.offsets.more_rcl.val();
        self.rcl.rd_key.next = self.rd_key.val();
        self.rcl.reset_mode_q.next = self.reset_mode_q.val();
        self.rcl.done.next = self.done_rcl.val();
        self.rcl.failed.next = self.failed_rcl.val();
        self.rcl.err_state.next = self.err_state_rcl.val();
        self.rcl.other_sends.next = !self.dcl.tx_fault.val();
        self.rcl.eval_here.next = self.eval_fault.val() & self.eval_line.val();
        self.rcl.eval_tx.next = self.eval_tx.val();
        // §5 offsets.
        self.offsets.clk.next = self.clk.val();
        self.offsets.clear.next = self.clear.val();
        self.offsets.q_count.next = self.q_count.val();
        self.offsets.tx_fault_dcl.next = self.dcl.tx_fault.val();
        self.offsets.tx_fault_rcl.next = self.rcl.tx_fault.val();
        self.offsets.sends_next_dcl.next = self.dcl.sends_next.val();
        self.offsets.sends_next_rcl.next = self.rcl.sends_next.val();
        self.offsets.complete_dcl.next = self.dcl.complete.val();
        self.offsets.complete_rcl.next = self.rcl.complete.val();
        // §6 state machine.
        self.status.clk.next = self.clk.val();
        self.status.rst.next = self.rst.val();
        self.status.hold.next = self.hold.val();
        self.status.tx_fault_dcl.next = self.dcl.tx_fault.val();
        self.status.rx_fault_dcl.next = self.dcl.rx_fault.val();
        self.status.tx_fault_rcl.next = self.rcl.tx_fault.val();
        self.status.rx_fault_rcl.next = self.rcl.rx_fault.val();
        self.status.against_dcl.next = self.dcl.against.val();
        self.status.against_rcl.next = self.rcl.against.val();
        self.status.cs_fail_dcl.next = self.dcl.cs_fail.val();
        self.status.cs_fail_rcl.next = self.rcl.cs_fail.val();
        self.status.busoff_dcl.next = self.dcl.busoff.val();
        self.status.busoff_rcl.next = self.rcl.busoff.val();
        self.status.eval_fault.next = self.eval_fault.val();
        self.status.eval_line.next = self.eval_line.val();
        self.status.eval_deviation.next = self.eval_deviation.val();
        self.status.eval_mb.next = self.eval_mb.val();
        // To the channels.
        self.tx_req_dcl.next = self.dcl.tx_req.val();
        self.tx_req_rcl.next = self.rcl.tx_req.val();
        self.cs_req_dcl.next = self.dcl.cs_req.val();
        self.cs_req_rcl.next = self.rcl.cs_req.val();
        self.tx_abort_dcl.next = self.dcl.abort.val();
        self.tx_abort_rcl.next = self.rcl.abort.val();
        self.restart_dcl.next = self.dcl.restart.val();
        self.restart_rcl.next = self.rcl.restart.val();
        // To the queue.
        self.off_dcl.next = self.offsets.off_dcl.val();
        self.off_rcl.next = self.offsets.off_rcl.val();
        self.pop.next = self.offsets.pop.val();
        // To the engine: events only while the function runs.
        self.raise_tx_dcl.next = self.run.val() & self.dcl.raise_tx.val();
        self.raise_tx_rcl.next = self.run.val() & self.rcl.raise_tx.val();
        self.raise_rx_dcl.next = self.run.val() & self.cs_rx.deliver_dcl.val();
        self.raise_rx_rcl.next = self.run.val() & self.cs_rx.deliver_rcl.val();
        self.raise_req_dcl.next = self.run.val() & self.dcl.raise_req.val();
        self.raise_req_rcl.next = self.run.val() & self.rcl.raise_req.val();
        self.key_tx_dcl.next = self.dcl.key_tx.val();
        self.key_tx_rcl.next = self.rcl.key_tx.val();
        self.key_rx_dcl.next = bit_cast::<30, 29>(self.rx_id_dcl.val())
            | (bit_cast::<30, 1>(self.rx_ide_dcl.val().into()) << 29);
        self.key_rx_rcl.next = bit_cast::<30, 29>(self.rx_id_rcl.val())
            | (bit_cast::<30, 1>(self.rx_ide_rcl.val().into()) << 29);
        self.key_req_dcl.next = self.rd_key.val();
        self.key_req_rcl.next = self.rd_key.val();
        self.raise_eval.next = self.time_base.dmr_tick.val();
        // from the ports, not `run`: Verilator would see a false loop through
        // this always block (UNOPTFLAT) via `time_base.clear`
        self.clear_mailboxes.next = !(self.rst.val() | self.hold.val())
            & (self.dcl.recovered.val() | self.rcl.recovered.val());
        // To the RX path and the register block.
        self.rx_deliver_dcl.next = self.run.val() & self.cs_rx.deliver_dcl.val();
        self.rx_deliver_rcl.next = self.run.val() & self.cs_rx.deliver_rcl.val();
        self.acl_switch.next = self.status.acl_switch.val();
        self.tx_done_evt.next = self.offsets.first.val();
        self.int_evt.next = self.status.int_evt.val();
        // Status.
        self.dmr_state.next = self.status.dmr_state.val();
        self.acl.next = self.status.acl.val();
        self.dcl_tx_fault.next = self.dcl.tx_fault.val();
        self.dcl_rx_fault.next = self.dcl.rx_fault.val();
        self.rcl_tx_fault.next = self.rcl.tx_fault.val();
        self.rcl_rx_fault.next = self.rcl.rx_fault.val();
        self.dmr_tick.next = self.time_base.dmr_tick.val();
        self.status_word.next = self.status.status_word.val();
        self.cs_count_word.next = self.cs_rx.cs_count_word.val();
    }
}
