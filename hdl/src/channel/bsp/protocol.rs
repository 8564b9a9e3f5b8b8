//! Bit stream processor (ISO 11898-1:2015, clauses 10 and 12; timing contract
//! §4): the protocol units of one channel, wired together. Each unit does one
//! concern and is a sub-module of the emitted Verilog:
//! - `protocol_fsm`: frame fields, interframe, error and overload frames,
//!   arbitration and the transmitter role (with `field_decode`, its registered
//!   pre-decodes);
//! - `tx_request`: the host's transmit request, its attempts and abort
//!   (contract §8);
//! - `tx_pin`: the bit this node drives on the `tx` pin (contract §4.2);
//! - `bit_stuffing`: stuffing and destuffing (10.5);
//! - `frame_crc`: the CRC-15 register and check (10.4.2.6);
//! - `tx_frame` / `rx_frame`: the frame sent and the frame received (10.4.2);
//! - `error_detection`: bit, stuff, CRC, form and ACK errors (12.1.3), run by
//!   `error_decision` one clock ahead for either bus level;
//! - `fault_confinement_rules` and `fault_confinement`: the counting rules and
//!   the error counters (12.1.4); the rules are run one clock ahead the same
//!   way by `rules_decision`;
//! - `error_capture`: error code capture and counts (contract §9).
//!
//! All wiring here is combinational: a signal decided at a sample point reaches
//! the unit that uses it in the same clock, as it did in one block. For Fmax on
//! the iCE40UP5K the error checks and counting rules are registered the clock
//! before for a dominant and a recessive sample (`sample_lookahead`: their
//! inputs are stable then), so at the sample point they are one LUT after
//! `sample` and `sampled`; the values are the same in every clock. Decisions
//! where the standard leaves room are written in the timing contract:
//! - The type of error flag (active or passive) is the error state after the
//!   counters have been updated for the error that starts it (contract §4.5).
//! - The counting rules follow contract §4.5 rule by rule (rule letters of
//!   ISO 11898-1 12.1.4.2); REC is decremented at the ACK slot (rule h).
//! - A transmitter's frame is latched by a one-clock `tx_req` and stays pending
//!   through lost arbitration and errors until sent (automatic retransmission,
//!   `tx_request`).

use super::bit_stuffing::BitStuffing;
use super::error_capture::ErrorCapture;
use super::error_decision::ErrorDecision;
use super::fault_confinement::FaultConfinement;
use super::field::Field;
use super::frame_crc::FrameCrc;
use super::protocol_fsm::ProtocolFsm;
use super::rules_decision::RulesDecision;
use super::rx_frame::RxFrame;
use super::tx_frame::TxFrame;
use super::tx_pin::TxPin;
use super::tx_request::TxRequest;
use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The bit stream processor of one channel.
#[derive(LogicBlock, Default)]
pub struct ProtocolController<const RX_HOLD: u64 = 1> {
    // clock and reset
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset.
    pub rst: Signal<In, Bit>,
    // from the bit timing logic
    /// The sample point of the current bit (one clock).
    pub sample: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    /// The start of a bit: the `tx` pin may change.
    pub bit_start: Signal<In, Bit>,
    /// This bit start is a hard synchronisation.
    pub hard_sync: Signal<In, Bit>,
    // to the bit timing logic and the pin
    /// Hard synchronisation is allowed (between frames, 11.3.2.1).
    pub hard_sync_enable: Signal<Out, Bit>,
    /// The CAN tx pin (true: recessive).
    pub tx: Signal<Out, Bit>,
    // configuration (held, from the configuration registers)
    /// Operating mode: 0 normal, 1 listen-only, 2 self-test, 3 loop-back.
    pub mode: Signal<In, Bits<2>>,
    /// Error warning limit.
    pub ewl: Signal<In, Bits<8>>,
    /// No automatic retransmission.
    pub single_shot: Signal<In, Bit>,
    // host transmit interface
    /// One clock: send the frame on tx_id..tx_data (taken while nothing is pending).
    pub tx_req: Signal<In, Bit>,
    /// Identifier (base frame: ID[10:0]).
    pub tx_id: Signal<In, Bits<29>>,
    /// Extended frame.
    pub tx_ide: Signal<In, Bit>,
    /// Remote frame.
    pub tx_rtr: Signal<In, Bit>,
    /// Data length code.
    pub tx_dlc: Signal<In, Bits<4>>,
    /// Data, byte 0 in bits 63..56.
    pub tx_data: Signal<In, Bits<64>>,
    /// Latched with `tx_req`: this frame is single shot (contract §8).
    pub tx_single: Signal<In, Bit>,
    /// Abort the pending frame (contract §8).
    pub tx_abort: Signal<In, Bit>,
    /// Error counter reset (contract §4.5).
    pub err_reset: Signal<In, Bit>,
    /// Bus-off hold: the recovery is not counted (contract §4.5).
    pub boff_hold: Signal<In, Bit>,
    /// A frame is pending.
    pub tx_pending: Signal<Out, Bit>,
    /// One clock: the pending frame was dropped.
    pub tx_failed: Signal<Out, Bit>,
    /// One clock: the frame was sent.
    pub tx_done: Signal<Out, Bit>,
    /// One clock: arbitration was lost.
    pub arb_lost: Signal<Out, Bit>,
    // host receive interface
    /// One clock: a frame was received.
    pub rx_valid: Signal<Out, Bit>,
    /// Received identifier.
    pub rx_id: Signal<Out, Bits<29>>,
    /// Received IDE bit.
    pub rx_ide: Signal<Out, Bit>,
    /// Received RTR bit.
    pub rx_rtr: Signal<Out, Bit>,
    /// Received data length code.
    pub rx_dlc: Signal<Out, Bits<4>>,
    /// Received data, byte 0 in bits 63..56.
    pub rx_data: Signal<Out, Bits<64>>,
    // probes
    /// The field the next bit belongs to (timing contract §4.1).
    pub field: Signal<Out, Field>,
    /// Transmit error counter.
    pub tec: Signal<Out, Bits<9>>,
    /// Receive error counter.
    pub rec: Signal<Out, Bits<8>>,
    /// 0 error active, 1 error passive, 2 bus-off.
    pub err_state: Signal<Out, Bits<2>>,
    /// The node is transmitter (contract §4.5, "Roles").
    pub is_tx: Signal<Out, Bit>,
    /// Completed runs of the bus-off recovery (contract §4.5).
    pub boff_runs: Signal<Out, Bits<7>>,
    // diagnostics (contract §9)
    /// TEC or REC at or above the error warning limit.
    pub err_warning: Signal<Out, Bit>,
    /// One clock: an error was captured.
    pub err_valid: Signal<Out, Bit>,
    /// Kind of the last error: 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK.
    pub err_kind: Signal<Out, Bits<3>>,
    /// Field of the last error.
    pub err_field: Signal<Out, Field>,
    /// The node was transmitter at the last error.
    pub err_tx: Signal<Out, Bit>,
    /// Arbitration-lost position.
    pub alc: Signal<Out, Bits<5>>,
    /// Bit errors counted (saturating).
    pub cnt_bit: Signal<Out, Bits<8>>,
    /// Stuff errors counted (saturating).
    pub cnt_stuff: Signal<Out, Bits<8>>,
    /// CRC errors counted (saturating).
    pub cnt_crc: Signal<Out, Bits<8>>,
    /// Form errors counted (saturating).
    pub cnt_form: Signal<Out, Bits<8>>,
    /// ACK errors counted (saturating).
    pub cnt_ack: Signal<Out, Bits<8>>,
    // operating mode
    listen_only: Signal<Local, Bit>,
    ack_check_off: Signal<Local, Bit>,
    loopback: Signal<Local, Bit>,
    mode_listen_only: Const<2, 1>,
    mode_loopback: Const<2, 3>,
    // the units
    fsm: ProtocolFsm,
    tx_request: TxRequest,
    tx_pin: TxPin,
    stuffing: BitStuffing,
    frame_crc: FrameCrc,
    tx_frame: TxFrame,
    rx_frame: RxFrame<RX_HOLD>,
    detect: ErrorDecision,
    rules: RulesDecision,
    fc: FaultConfinement,
    err_capture: ErrorCapture,
}

impl<const RX_HOLD: u64> Logic for ProtocolController<RX_HOLD> {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- clocks and resets
        self.fsm.clk.next = self.clk.val();
        self.fsm.rst.next = self.rst.val();
        self.tx_request.clk.next = self.clk.val();
        self.tx_request.rst.next = self.rst.val();
        self.tx_pin.clk.next = self.clk.val();
        self.tx_pin.rst.next = self.rst.val();
        self.stuffing.clk.next = self.clk.val();
        self.stuffing.rst.next = self.rst.val();
        self.frame_crc.clk.next = self.clk.val();
        self.frame_crc.rst.next = self.rst.val();
        self.tx_frame.clk.next = self.clk.val();
        self.rx_frame.clk.next = self.clk.val();
        self.rx_frame.rst.next = self.rst.val();
        self.rules.clk.next = self.clk.val();
        self.fc.clk.next = self.clk.val();
        self.fc.rst.next = self.rst.val();
        self.err_capture.clk.next = self.clk.val();
        self.err_capture.rst.next = self.rst.val();

        // ---- operating mode (contract §7), decoded once for every unit
        self.listen_only.next = self.mode.val() == self.mode_listen_only.val();
        self.ack_check_off.next = self.mode.val().get_bit(1);
        self.loopback.next = self.mode.val() == self.mode_loopback.val();

        // ---- protocol control
        self.fsm.sample.next = self.sample.val();
        self.fsm.sampled.next = self.sampled.val();
        self.fsm.listen_only.next = self.listen_only.val();
        self.fsm.boff_hold.next = self.boff_hold.val();
        self.fsm.loopback.next = self.loopback.val();
        self.fsm.tx_starts.next = self.tx_request.starts.val();
        self.fsm.tx_joins.next = self.tx_request.joins.val();
        self.fsm.frame_ide.next = self.tx_frame.frame_ide.val();
        self.fsm.at_stuff_bit.next = self.stuffing.at_stuff_bit.val();
        self.fsm.stuff_last.next = self.stuffing.last.val();
        self.fsm.no_data.next = self.rx_frame.no_data.val();
        self.fsm.data_end.next = self.rx_frame.data_end.val();
        self.fsm.error.next = self.detect.error.val();
        self.fsm.flag_error.next = self.detect.flag_error.val();
        self.fsm.lost.next = self.detect.lost.val();
        self.fsm.sof_error.next = self.detect.sof_error.val();
        self.fsm.passive_after.next = self.rules.passive_after.val();
        self.fsm.bus_off_after.next = self.rules.bus_off_after.val();
        self.fsm.ack_defer.next = self.rules.ack_defer.val();
        self.fsm.ack_counted.next = self.rules.ack_counted.val();
        self.fsm.error_passive.next = self.fc.error_passive.val();

        // ---- transmit request (contract §8) and the tx pin (contract §4.2)
        self.tx_request.listen_only.next = self.listen_only.val();
        self.tx_request.single_shot.next = self.single_shot.val();
        self.tx_request.tx_req.next = self.tx_req.val();
        self.tx_request.tx_abort.next = self.tx_abort.val();
        self.tx_request.tx_single.next = self.tx_single.val();
        self.tx_request.bus_off.next = self.fc.bus_off.val();
        self.tx_request.suspend_due.next = self.fsm.suspend_due.val();
        self.tx_request.is_tx.next = self.fsm.is_tx.val();
        self.tx_request.tx_pin.next = self.tx_pin.tx.val();
        self.tx_request.sample.next = self.sample.val();
        self.tx_request.sof.next = self.fsm.sof.val();
        self.tx_request.sof_as_tx.next = self.fsm.sof_as_tx.val();
        self.tx_request.sent.next = self.fsm.tx_valid.val();
        self.tx_request.lost.next = self.detect.lost.val();
        self.tx_request.error.next = self.detect.error.val();
        self.tx_request.flag_error.next = self.detect.flag_error.val();
        self.tx_request.sof_error.next = self.detect.sof_error.val();
        self.tx_request.bus_off_after.next = self.rules.bus_off_after.val();
        self.tx_pin.bit_start.next = self.bit_start.val();
        self.tx_pin.hard_sync.next = self.hard_sync.val();
        self.tx_pin.listen_only.next = self.listen_only.val();
        self.tx_pin.field.next = self.fsm.field.val();
        self.tx_pin.is_tx.next = self.fsm.is_tx.val();
        self.tx_pin.flag_passive.next = self.fsm.flag_passive.val();
        self.tx_pin.tx_starts.next = self.tx_request.starts.val();
        self.tx_pin.frame_bit.next = self.tx_frame.frame_bit.val();
        self.tx_pin.stuff_insert.next = self.stuffing.insert.val();
        self.tx_pin.stuff_last.next = self.stuffing.last.val();
        self.tx_pin.crc_ok.next = self.frame_crc.crc_ok.val();

        // ---- stuffing, CRC and the frames
        self.stuffing.sample.next = self.sample.val();
        self.stuffing.sampled.next = self.sampled.val();
        self.stuffing.start.next = self.fsm.sof.val();
        self.stuffing.stop.next = self.fsm.stuff_stop.val();
        self.stuffing.resync.next = self.fsm.stuff_resync.val();
        self.frame_crc.sampled.next = self.sampled.val();
        self.frame_crc.start.next = self.fsm.sof.val();
        self.frame_crc.step.next = self.fsm.crc_step.val();
        self.frame_crc.check.next = self.fsm.crc_check.val();
        self.frame_crc.in_crc_field.next = self.fsm.in_crc_field.val();
        self.frame_crc.bit_cnt.next = self.fsm.bit_cnt.val().get_bits::<4>(0);
        self.tx_frame.load.next = self.tx_request.tx_load.val();
        self.tx_frame.id.next = self.tx_id.val();
        self.tx_frame.ide.next = self.tx_ide.val();
        self.tx_frame.rtr.next = self.tx_rtr.val();
        self.tx_frame.dlc.next = self.tx_dlc.val();
        self.tx_frame.data.next = self.tx_data.val();
        self.tx_frame.field.next = self.fsm.field.val();
        self.tx_frame.bit_cnt.next = self.fsm.bit_cnt.val();
        self.tx_frame.crc.next = self.frame_crc.crc.val();
        self.rx_frame.sampled.next = self.sampled.val();
        self.rx_frame.bit_cnt.next = self.fsm.bit_cnt.val();
        self.rx_frame.bit_cnt_inc.next = self.fsm.bit_cnt_inc.val();
        self.rx_frame.clear.next = self.fsm.sof.val();
        self.rx_frame.shift_id.next = self.fsm.rx_shift_id.val();
        self.rx_frame.take_srr_rtr.next = self.fsm.rx_take_srr_rtr.val();
        self.rx_frame.take_ide.next = self.fsm.rx_take_ide.val();
        self.rx_frame.take_rtr_ext.next = self.fsm.rx_take_rtr_ext.val();
        self.rx_frame.take_dlc.next = self.fsm.rx_take_dlc.val();
        self.rx_frame.take_data_len.next = self.fsm.rx_take_data_len.val();
        self.rx_frame.take_data.next = self.fsm.rx_take_data.val();
        self.rx_frame.publish.next = self.fsm.rx_publish.val();

        // ---- error detection
        self.detect.clk.next = self.clk.val();
        self.detect.sample.next = self.sample.val();
        self.detect.sampled.next = self.sampled.val();
        self.detect.field.next = self.fsm.field.val();
        self.detect.is_tx.next = self.fsm.is_tx.val();
        self.detect.tx_bit.next = self.tx_pin.tx.val();
        self.detect.in_frame.next = self.fsm.in_frame.val();
        self.detect.in_arbitration.next = self.fsm.in_arbitration.val();
        self.detect.ack_slot.next = self.fsm.ack_slot.val();
        self.detect.in_delim.next = self.fsm.in_delim.val();
        self.detect.bc0.next = self.fsm.bc0.val();
        self.detect.bc6.next = self.fsm.bc6.val();
        self.detect.bc7.next = self.fsm.bc7.val();
        self.detect.flag_passive.next = self.fsm.flag_passive.val();
        self.detect.crc_ok.next = self.frame_crc.crc_ok.val();
        self.detect.last_bit_arb.next = self.fsm.last_bit_arb.val();
        self.detect.at_stuff_bit.next = self.stuffing.at_stuff_bit.val();
        self.detect.stuff_last.next = self.stuffing.last.val();
        self.detect.listen_only.next = self.listen_only.val();
        self.detect.ack_check_off.next = self.ack_check_off.val();

        // ---- fault confinement
        self.rules.sample.next = self.sample.val();
        self.rules.sampled.next = self.sampled.val();
        self.rules.at_stuff_bit.next = self.stuffing.at_stuff_bit.val();
        self.rules.field.next = self.fsm.field.val();
        self.rules.is_tx.next = self.fsm.is_tx.val();
        self.rules.tx_bit.next = self.tx_pin.tx.val();
        self.rules.flag_passive.next = self.fsm.flag_passive.val();
        self.rules.in_delim.next = self.fsm.in_delim.val();
        self.rules.after_error_flag.next = self.fsm.after_error_flag.val();
        self.rules.bc0.next = self.fsm.bc0.val();
        self.rules.delim_first.next = self.fsm.delim_first.val();
        self.rules.dom7.next = self.fsm.dom7.val();
        self.rules.ack_pending.next = self.fsm.ack_pending.val();
        self.rules.tx_valid.next = self.fsm.tx_valid.val();
        self.rules.listen_only.next = self.listen_only.val();
        self.rules.dom_error.next = self.detect.dom_error.val();
        self.rules.dom_flag_error.next = self.detect.dom_flag_error.val();
        self.rules.dom_ack_err.next = self.detect.dom_ack_err.val();
        self.rules.dom_tec_exempt.next = self.detect.dom_tec_exempt.val();
        self.rules.dom_sof_error.next = self.detect.dom_sof_error.val();
        self.rules.rec_error.next = self.detect.rec_error.val();
        self.rules.rec_flag_error.next = self.detect.rec_flag_error.val();
        self.rules.rec_ack_err.next = self.detect.rec_ack_err.val();
        self.rules.rec_tec_exempt.next = self.detect.rec_tec_exempt.val();
        self.rules.rec_sof_error.next = self.detect.rec_sof_error.val();
        self.rules.tec.next = self.fc.tec.val();
        self.rules.rec.next = self.fc.rec.val();
        self.rules.error_passive.next = self.fc.error_passive.val();
        self.rules.bus_off.next = self.fc.bus_off.val();
        self.fc.tec_add8.next = self.rules.tec_add8.val();
        self.fc.rec_add1.next = self.rules.rec_add1.val();
        self.fc.rec_add8.next = self.rules.rec_add8.val();
        self.fc.tx_success.next = self.rules.tx_success.val();
        self.fc.rx_success.next = self.rules.rx_success.val();
        self.fc.recovered.next = self.fsm.recovered.val();
        self.fc.err_reset.next = self.err_reset.val();
        self.fc.ewl.next = self.ewl.val();

        // ---- diagnostics (contract §9)
        self.err_capture.capture.next = self.detect.error.val() || self.detect.flag_error.val();
        self.err_capture.kind_bit.next = self.detect.kind_bit.val();
        self.err_capture.kind_stuff.next = self.detect.kind_stuff.val();
        self.err_capture.kind_form.next = self.detect.kind_form.val();
        self.err_capture.kind_ack.next = self.detect.kind_ack.val();
        self.err_capture.kind_crc.next = self.detect.kind_crc.val();
        self.err_capture.as_tx.next = self.fsm.is_tx.val() || self.detect.sof_error.val();
        self.err_capture.arb_lost.next = self.detect.lost.val();
        self.err_capture.field.next = self.fsm.field.val();
        self.err_capture.bit_cnt.next = self.fsm.bit_cnt.val().get_bits::<5>(0);

        // ---- outputs
        self.hard_sync_enable.next = self.fsm.hard_sync_enable.val();
        self.tx.next = self.tx_pin.tx.val();
        self.tx_pending.next = self.tx_request.tx_pending.val();
        self.tx_failed.next = self.tx_request.tx_failed.val();
        self.tx_done.next = self.tx_request.tx_done.val();
        self.arb_lost.next = self.tx_request.arb_lost.val();
        self.rx_valid.next = self.rx_frame.rx_valid.val();
        self.rx_id.next = self.rx_frame.rx_id.val();
        self.rx_ide.next = self.rx_frame.rx_ide.val();
        self.rx_rtr.next = self.rx_frame.rx_rtr.val();
        self.rx_dlc.next = self.rx_frame.rx_dlc.val();
        self.rx_data.next = self.rx_frame.rx_data.val();
        self.field.next = self.fsm.field.val();
        self.tec.next = self.fc.tec.val();
        self.rec.next = self.fc.rec.val();
        self.err_state.next = self.fc.err_state.val();
        self.is_tx.next = self.fsm.is_tx.val();
        self.boff_runs.next = self.fsm.boff_runs.val();
        self.err_warning.next = self.fc.warning.val();
        self.err_valid.next = self.err_capture.err_valid.val();
        self.err_kind.next = self.err_capture.err_kind.val();
        self.err_field.next = self.err_capture.err_field.val();
        self.err_tx.next = self.err_capture.err_tx.val();
        self.alc.next = self.err_capture.alc.val();
        self.cnt_bit.next = self.err_capture.cnt_bit.val();
        self.cnt_stuff.next = self.err_capture.cnt_stuff.val();
        self.cnt_crc.next = self.err_capture.cnt_crc.val();
        self.cnt_form.next = self.err_capture.cnt_form.val();
        self.cnt_ack.next = self.err_capture.cnt_ack.val();
    }
}
