//! Protocol control (ISO 11898-1:2015, clauses 10 and 12; timing contract §4):
//! the frame field and bit counter, the transmitter role, frame coding field by
//! field, error and overload frames (10.4.3, 10.4.4), intermission and suspend
//! transmission (10.4.5), bus integration and bus-off recovery (12.1.4.4).
//!
//! State changes only at the sample point (`sample`). The other units of the
//! bit stream processor do one concern each and are told by strobes from here
//! what the sampled bit is: stuffing, CRC, the receive and transmit frame, error
//! detection and the fault-confinement rules. Whether a SOF is this node's frame
//! comes from the transmit request (`tx_request`, contract §8), which is told in
//! turn when an attempt starts (`sof_as_tx`) and when the frame was sent
//! (`tx_valid`); the `tx` pin (`tx_pin`) sends the bit this state asks for.

use super::field::Field;
use super::field_decode::FieldDecode;
use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The protocol control state machine.
#[derive(LogicBlock, Default)]
pub struct ProtocolFsm {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset.
    pub rst: Signal<In, Bit>,
    // from the bit timing logic
    /// The sample point of the current bit (one clock).
    pub sample: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    // to the bit timing logic
    /// Hard synchronisation is allowed (between frames, 11.3.2.1).
    pub hard_sync_enable: Signal<Out, Bit>,
    // configuration (held)
    /// Listen-only mode (contract §7): no dominant bit, no transmission.
    pub listen_only: Signal<In, Bit>,
    /// Loop-back mode (contract §7): the transmitter receives its own frame.
    pub loopback: Signal<In, Bit>,
    /// Host: a bus-off node does not count its recovery while 1 (contract §4.5).
    pub boff_hold: Signal<In, Bit>,
    // from the transmit request
    /// A SOF from idle is this node's frame (or its SOF is already on `tx`).
    pub tx_starts: Signal<In, Bit>,
    /// A SOF at intermission bit 3 is this node's frame (10.4.5).
    pub tx_joins: Signal<In, Bit>,
    // from the other units
    /// Transmit frame: the latched frame is extended.
    pub frame_ide: Signal<In, Bit>,
    /// Stuffing: the sampled bit is a stuff bit (registered).
    pub at_stuff_bit: Signal<In, Bit>,
    /// Stuffing: the last bit counted.
    pub stuff_last: Signal<In, Bit>,
    /// Receive frame: the data field is empty.
    pub no_data: Signal<In, Bit>,
    /// Receive frame: the sampled bit is the last data bit (registered).
    pub data_end: Signal<In, Bit>,
    /// Error detection: a frame error at this sample point.
    pub error: Signal<In, Bit>,
    /// Error detection: a bit error in the node's own flag.
    pub flag_error: Signal<In, Bit>,
    /// Error detection: arbitration lost at this sample point.
    pub lost: Signal<In, Bit>,
    /// Error detection: its own SOF read back recessive.
    pub sof_error: Signal<In, Bit>,
    /// Rules: error passive after this sample's counter events.
    pub passive_after: Signal<In, Bit>,
    /// Rules: bus-off after this sample's counter events.
    pub bus_off_after: Signal<In, Bit>,
    /// Rules: defer this ACK error to the passive flag (rule c exception 1).
    pub ack_defer: Signal<In, Bit>,
    /// Rules: the deferred ACK error was counted.
    pub ack_counted: Signal<In, Bit>,
    /// Counters: the node is error passive.
    pub error_passive: Signal<In, Bit>,
    // state for the other units
    /// The field the next bit belongs to.
    pub field: Signal<Out, Field>,
    /// Position of the next bit in its field, low six bits (the field bit
    /// indexes: at most 64 data bits).
    pub bit_cnt: Signal<Out, Bits<6>>,
    /// `bit_cnt + 1`.
    pub bit_cnt_inc: Signal<Out, Bits<7>>,
    /// The node is transmitter of the frame.
    pub is_tx: Signal<Out, Bit>,
    /// The node sends a passive error flag.
    pub flag_passive: Signal<Out, Bit>,
    /// The last non-stuff bit was in the arbitration field.
    pub last_bit_arb: Signal<Out, Bit>,
    /// The first bit after a flag is next (rule b).
    pub delim_first: Signal<Out, Bit>,
    /// Seven dominant bits after a flag were counted (rule f).
    pub dom7: Signal<Out, Bit>,
    /// An ACK error is deferred to the passive flag (rule c exception 1).
    pub ack_pending: Signal<Out, Bit>,
    // registered pre-decodes of the field and the bit counter
    /// The field is part of the arbitration field (10.4.2.2).
    pub in_arbitration: Signal<Out, Bit>,
    /// The field is between SOF and EOF.
    pub in_frame: Signal<Out, Bit>,
    /// The field is the ACK slot.
    pub ack_slot: Signal<Out, Bit>,
    /// The field is an error or overload delimiter.
    pub in_delim: Signal<Out, Bit>,
    /// The delimiter follows an error flag.
    pub after_error_flag: Signal<Out, Bit>,
    /// The bit counter is 0.
    pub bc0: Signal<Out, Bit>,
    /// The bit counter is 6.
    pub bc6: Signal<Out, Bit>,
    /// The bit counter is 7.
    pub bc7: Signal<Out, Bit>,
    /// The next bit belongs to the CRC field.
    pub in_crc_field: Signal<Out, Bit>,
    // strobes at a sample point, for the other units
    /// SOF: a frame starts (stuffing, CRC, receive frame).
    pub sof: Signal<Out, Bit>,
    /// The node is transmitter of the frame this SOF starts.
    pub sof_as_tx: Signal<Out, Bit>,
    /// The stuffed region ends (CRC delimiter or an error).
    pub stuff_stop: Signal<Out, Bit>,
    /// A passive error flag restarts its run of equal bits.
    pub stuff_resync: Signal<Out, Bit>,
    /// The sampled bit is covered by the CRC.
    pub crc_step: Signal<Out, Bit>,
    /// The sampled bit is a received CRC bit.
    pub crc_check: Signal<Out, Bit>,
    /// Receive frame: an identifier bit.
    pub rx_shift_id: Signal<Out, Bit>,
    /// Receive frame: the SRR/RTR bit after ID_A.
    pub rx_take_srr_rtr: Signal<Out, Bit>,
    /// Receive frame: the IDE bit.
    pub rx_take_ide: Signal<Out, Bit>,
    /// Receive frame: the RTR bit of an extended frame.
    pub rx_take_rtr_ext: Signal<Out, Bit>,
    /// Receive frame: a DLC bit.
    pub rx_take_dlc: Signal<Out, Bit>,
    /// Receive frame: the last DLC bit.
    pub rx_take_data_len: Signal<Out, Bit>,
    /// Receive frame: a data bit.
    pub rx_take_data: Signal<Out, Bit>,
    /// Receive frame: valid for this receiver (10.7), publish it.
    pub rx_publish: Signal<Out, Bit>,
    /// The frame is valid for its transmitter (10.7, rule g).
    pub tx_valid: Signal<Out, Bit>,
    /// Bus-off recovery completed (12.1.4.4).
    pub recovered: Signal<Out, Bit>,
    /// Completed runs of 11 recessive bits in this bus-off, 0 outside it
    /// (contract §4.5 `boff_runs`).
    pub boff_runs: Signal<Out, Bits<7>>,
    /// An error-passive transmitter suspends after this frame (10.4.5).
    pub suspend_due: Signal<Out, Bit>,
    // protocol state
    field_q: DFF<Field>,
    bit_cnt_q: DFF<Bits<7>>,
    is_tx_q: DFF<Bit>,
    flag_passive_q: DFF<Bit>,
    recovery_cnt: DFF<Bits<7>>,
    last_bit_arb_q: DFF<Bit>,
    // flag and delimiter state for the fault-confinement rules
    ack_pending_q: DFF<Bit>,
    delim_first_q: DFF<Bit>,
    /// Consecutive dominant bits after a flag, modulo 8.
    dom_cnt: DFF<Bits<3>>,
    /// Hard synchronisation is not allowed (the field's, registered with it).
    hse_off: DFF<Bit>,
    // registered pre-decodes of the state the next SAMPLE edge sees
    decode: FieldDecode,
    // next-state values of the sample-point update
    field_n: Signal<Local, Field>,
    bit_cnt_n: Signal<Local, Bits<7>>,
    is_tx_n: Signal<Local, Bit>,
    flag_passive_n: Signal<Local, Bit>,
    monitor: Signal<Local, Bit>,
    hse_class: Signal<Local, Bit>,
    hse_stay: Signal<Local, Bit>,
    hse_n: Signal<Local, Bit>,
    n7_0: Const<7, 0>,
    n7_1: Const<7, 1>,
    zero3: Const<3, 0>,
    one3: Const<3, 1>,
}

impl Logic for ProtocolFsm {
    // rust-hdl's hdl_gen has no match guards: the bus-off hold stays inside
    // its field's arm.
    #[allow(clippy::collapsible_match)]
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            field_q,
            bit_cnt_q,
            is_tx_q,
            flag_passive_q,
            recovery_cnt,
            last_bit_arb_q,
            ack_pending_q,
            delim_first_q,
            dom_cnt,
            hse_off
        );
        self.decode.clk.next = self.clk.val();
        self.decode.field.next = self.field_q.q.val();
        self.decode.bit_cnt.next = self.bit_cnt_q.q.val();
        self.decode.recovery_cnt.next = self.recovery_cnt.q.val();
        self.decode.dom_cnt.next = self.dom_cnt.q.val();
        self.decode.is_tx.next = self.is_tx_q.q.val();
        self.decode.error_passive.next = self.error_passive.val();
        self.decode.frame_ide.next = self.frame_ide.val();

        // ---- defaults: nothing changes unless the sample point says so
        self.field_n.next = self.field_q.q.val();
        self.bit_cnt_n.next = self.bit_cnt_q.q.val();
        self.bit_cnt_inc.next = self.bit_cnt_q.q.val() + self.n7_1.val();
        self.is_tx_n.next = self.is_tx_q.q.val();
        self.flag_passive_n.next = self.flag_passive_q.q.val();
        self.sof.next = false;
        self.sof_as_tx.next = false;
        self.stuff_stop.next = false;
        self.stuff_resync.next = false;
        self.crc_step.next = false;
        self.crc_check.next = false;
        self.rx_shift_id.next = false;
        self.rx_take_srr_rtr.next = false;
        self.rx_take_ide.next = false;
        self.rx_take_rtr_ext.next = false;
        self.rx_take_dlc.next = false;
        self.rx_take_data_len.next = false;
        self.rx_take_data.next = false;
        self.rx_publish.next = false;
        self.tx_valid.next = false;
        self.recovered.next = false;

        // ---- the sample point of a bit that is not a stuff bit
        self.monitor.next = self.sample.val() && !self.at_stuff_bit.val();
        if self.monitor.val() {
            self.last_bit_arb_q.d.next = self.decode.in_arbitration.val();
            self.crc_step.next = self.decode.crc_covered.val();
            // 12.1.2: a transmitter that lost arbitration becomes receiver.
            if self.lost.val() {
                self.is_tx_n.next = false;
            }
            match self.field_q.q.val() {
                Field::Integrating => {
                    // 12.1.4.4: 11 consecutive recessive bits before taking part.
                    if self.sampled.val() {
                        if self.decode.bc10.val() {
                            self.field_n.next = Field::Idle;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    } else {
                        self.bit_cnt_n.next = self.n7_0.val();
                    }
                }
                Field::Idle => {
                    if !self.sampled.val() {
                        self.sof.next = true;
                        self.sof_as_tx.next = self.tx_starts.val();
                    } else if self.sof_error.val() {
                        // Having sent a frame bit, it is transmitter of what follows.
                        self.is_tx_n.next = true;
                    }
                }
                Field::Suspend => {
                    // 10.4.5: a passive transmitter waits 8 bits; it may receive meanwhile.
                    if !self.sampled.val() {
                        self.sof.next = true;
                    } else if self.decode.bc7.val() {
                        self.field_n.next = Field::Idle;
                        self.bit_cnt_n.next = self.n7_0.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::Intermission => {
                    if !self.sampled.val() {
                        if self.decode.bc2.val() {
                            // 10.4.5: dominant third intermission bit is a SOF.
                            self.sof.next = true;
                            self.sof_as_tx.next = self.tx_joins.val();
                        } else {
                            // 10.4.4: dominant intermission bit 1 or 2: overload.
                            self.field_n.next = Field::OverloadFlag;
                            self.bit_cnt_n.next = self.n7_0.val();
                        }
                    } else if self.decode.bc2.val() {
                        if self.decode.suspend_due.val() {
                            self.field_n.next = Field::Suspend;
                        } else {
                            self.field_n.next = Field::Idle;
                        }
                        // The transmitter role ends with the intermission.
                        self.is_tx_n.next = false;
                        self.bit_cnt_n.next = self.n7_0.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::IdA => {
                    self.rx_shift_id.next = true;
                    if self.decode.bc10.val() {
                        self.field_n.next = Field::SrrRtr;
                        self.bit_cnt_n.next = self.n7_0.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::SrrRtr => {
                    self.rx_take_srr_rtr.next = true;
                    self.field_n.next = Field::Ide;
                }
                Field::Ide => {
                    self.rx_take_ide.next = true;
                    if self.sampled.val() {
                        self.field_n.next = Field::IdB;
                    } else {
                        self.field_n.next = Field::R0;
                    }
                    self.bit_cnt_n.next = self.n7_0.val();
                }
                Field::IdB => {
                    self.rx_shift_id.next = true;
                    if self.decode.bc17.val() {
                        self.field_n.next = Field::RtrExt;
                        self.bit_cnt_n.next = self.n7_0.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::RtrExt => {
                    self.rx_take_rtr_ext.next = true;
                    self.field_n.next = Field::R1;
                }
                Field::R1 => {
                    self.field_n.next = Field::R0;
                }
                Field::R0 => {
                    self.field_n.next = Field::Dlc;
                    self.bit_cnt_n.next = self.n7_0.val();
                }
                Field::Dlc => {
                    self.rx_take_dlc.next = true;
                    if self.decode.bc3.val() {
                        self.rx_take_data_len.next = true;
                        if self.no_data.val() {
                            self.field_n.next = Field::Crc;
                        } else {
                            self.field_n.next = Field::Data;
                        }
                        self.bit_cnt_n.next = self.n7_0.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::Data => {
                    self.rx_take_data.next = true;
                    if self.data_end.val() {
                        self.field_n.next = Field::Crc;
                        self.bit_cnt_n.next = self.n7_0.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::Crc => {
                    self.crc_check.next = true;
                    if self.decode.bc14.val() {
                        self.field_n.next = Field::CrcDelim;
                        self.bit_cnt_n.next = self.n7_0.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::CrcDelim => {
                    // 10.5: the stuffed region ends with the CRC sequence.
                    self.stuff_stop.next = true;
                    self.field_n.next = Field::AckSlot;
                }
                Field::AckSlot => {
                    self.field_n.next = Field::AckDelim;
                }
                Field::AckDelim => {
                    self.field_n.next = Field::Eof;
                    self.bit_cnt_n.next = self.n7_0.val();
                }
                Field::Eof => {
                    if !self.sampled.val() {
                        if self.decode.bc6.val() && !self.is_tx_q.q.val() {
                            // 10.4.4: a receiver's dominant last EOF bit is an overload.
                            self.field_n.next = Field::OverloadFlag;
                            self.bit_cnt_n.next = self.n7_0.val();
                        }
                    } else {
                        if self.decode.bc5.val() && (!self.is_tx_q.q.val() || self.loopback.val()) {
                            // 10.7: valid for receivers at the last but one EOF bit.
                            self.rx_publish.next = true;
                        }
                        if self.decode.bc6.val() {
                            if self.is_tx_q.q.val() {
                                // 10.7: valid for the transmitter at the end of EOF.
                                self.tx_valid.next = true;
                            }
                            self.field_n.next = Field::Intermission;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                }
                Field::ErrorFlag => {
                    if self.flag_passive_q.q.val() {
                        // Rule c exception 1: counted once, by the rules.
                        if self.ack_counted.val() {
                            self.ack_pending_q.d.next = false;
                        }
                        // 10.4.3: a passive flag ends after 6 equal consecutive bits.
                        if self.decode.bc0.val() || (self.sampled.val() != self.stuff_last.val()) {
                            self.bit_cnt_n.next = self.n7_1.val();
                            self.stuff_resync.next = true;
                        } else if self.decode.bc5.val() {
                            self.field_n.next = Field::ErrorDelim;
                            self.bit_cnt_n.next = self.n7_0.val();
                            self.delim_first_q.d.next = true;
                            self.dom_cnt.d.next = self.zero3.val();
                            self.ack_pending_q.d.next = false;
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    } else if self.sampled.val() {
                        // A bit error in its own active flag (error detection).
                    } else if self.decode.bc5.val() {
                        self.field_n.next = Field::ErrorDelim;
                        self.bit_cnt_n.next = self.n7_0.val();
                        self.delim_first_q.d.next = true;
                        self.dom_cnt.d.next = self.zero3.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::OverloadFlag => {
                    if self.sampled.val() && !self.listen_only.val() {
                        // A bit error in its own overload flag (error detection).
                    } else if self.decode.bc5.val() {
                        self.field_n.next = Field::OverloadDelim;
                        self.bit_cnt_n.next = self.n7_0.val();
                        self.delim_first_q.d.next = true;
                        self.dom_cnt.d.next = self.zero3.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
                Field::BusOff => {
                    // 12.1.4.4: 128 occurrences of 11 consecutive recessive bits,
                    // counted only while the host does not hold them (contract §4.5).
                    if !self.boff_hold.val() {
                        if self.sampled.val() {
                            if self.decode.bc10.val() {
                                self.bit_cnt_n.next = self.n7_0.val();
                                if self.decode.recovery_end.val() {
                                    self.field_n.next = Field::Idle;
                                    self.recovered.next = true;
                                    self.recovery_cnt.d.next = self.n7_0.val();
                                } else {
                                    self.recovery_cnt.d.next =
                                        self.recovery_cnt.q.val() + self.n7_1.val();
                                }
                            } else {
                                self.bit_cnt_n.next = self.bit_cnt_inc.val();
                            }
                        } else {
                            self.bit_cnt_n.next = self.n7_0.val();
                        }
                    }
                }
                _ => {}
            }
            // Error and overload delimiters share one rule set (10.4.3/10.4.4):
            // wait for recessive, then 8 recessive bits in all.
            if self.decode.in_delim.val() {
                if self.decode.bc0.val() {
                    self.delim_first_q.d.next = false;
                    if self.sampled.val() {
                        self.bit_cnt_n.next = self.n7_1.val();
                    } else {
                        // Rules b/f count the dominant bits after a flag.
                        self.dom_cnt.d.next = self.dom_cnt.q.val() + self.one3.val();
                    }
                } else if !self.sampled.val() {
                    if self.decode.bc7.val() {
                        self.field_n.next = Field::OverloadFlag;
                        self.bit_cnt_n.next = self.n7_0.val();
                    }
                } else if self.decode.bc7.val() {
                    self.field_n.next = Field::Intermission;
                    self.bit_cnt_n.next = self.n7_0.val();
                } else {
                    self.bit_cnt_n.next = self.bit_cnt_inc.val();
                }
            }
        }

        if self.sample.val() {
            // Start of frame: a new frame begins, as transmitter if one is pending.
            if self.sof.val() {
                self.field_n.next = Field::IdA;
                self.bit_cnt_n.next = self.n7_0.val();
                self.is_tx_n.next = self.sof_as_tx.val();
            }
            // Any error: error flag from the next bit on (10.4.3).
            if self.error.val() || self.flag_error.val() {
                self.field_n.next = Field::ErrorFlag;
                self.bit_cnt_n.next = self.n7_0.val();
                self.stuff_stop.next = true;
                // The flag type follows the state after this error's increment.
                self.flag_passive_n.next = self.passive_after.val() || self.listen_only.val();
            }
            if self.ack_defer.val() {
                self.ack_pending_q.d.next = true;
            }
            // 12.1.4.4: TEC > 255 makes the node bus-off at once.
            if self.bus_off_after.val() {
                self.field_n.next = Field::BusOff;
                self.is_tx_n.next = false;
                self.bit_cnt_n.next = self.n7_0.val();
                self.recovery_cnt.d.next = self.n7_0.val();
            }
            self.field_q.d.next = self.field_n.val();
            self.bit_cnt_q.d.next = self.bit_cnt_n.val();
            self.is_tx_q.d.next = self.is_tx_n.val();
            self.flag_passive_q.d.next = self.flag_passive_n.val();
        }

        // ---- hard synchronisation is allowed between frames (11.3.2.1): in
        // INTEGRATING, IDLE, SUSPEND, BUS_OFF and the third intermission bit. It is
        // registered with the field (`hse_off`, inverted so the power-up value
        // matches INTEGRATING) because the bit timing logic's next state needs it
        // in every clock (Fmax). Intermission is entered with bit_cnt = 0 and counts
        // up only while bit_cnt != 2, so bit 1 alone means "third bit" and bit 0
        // "second bit".
        self.hse_class.next = (self.field_q.q.val() == Field::Integrating)
            || (self.field_q.q.val() == Field::Idle)
            || (self.field_q.q.val() == Field::Suspend)
            || (self.field_q.q.val() == Field::BusOff);
        if self.monitor.val() {
            // The match above: a recessive second or third intermission bit leads
            // to the third bit, IDLE or SUSPEND; a dominant one to SOF or overload.
            self.hse_stay.next = (self.field_q.q.val() == Field::Intermission)
                && self.sampled.val()
                && (self.decode.bc2.val() || self.bit_cnt_q.q.val().get_bit(0));
        } else {
            self.hse_stay.next =
                (self.field_q.q.val() == Field::Intermission) && self.bit_cnt_q.q.val().get_bit(1);
        }
        // The overrides of the sample point above: SOF and error flags disallow
        // it, bus-off allows it.
        self.hse_n.next = self.bus_off_after.val()
            || (!self.sof.val()
                && !self.error.val()
                && !self.flag_error.val()
                && (self.hse_class.val() || self.hse_stay.val()));
        if self.sample.val() {
            self.hse_off.d.next = !self.hse_n.val();
        }
        self.hard_sync_enable.next = !self.hse_off.q.val();

        // ---- outputs
        self.field.next = self.field_q.q.val();
        self.bit_cnt.next = self.bit_cnt_q.q.val().get_bits::<6>(0);
        self.is_tx.next = self.is_tx_q.q.val();
        self.boff_runs.next = self.recovery_cnt.q.val();
        self.flag_passive.next = self.flag_passive_q.q.val();
        self.last_bit_arb.next = self.last_bit_arb_q.q.val();
        self.in_arbitration.next = self.decode.in_arbitration.val();
        self.in_frame.next = self.decode.in_frame.val();
        self.ack_slot.next = self.decode.ack_slot.val();
        self.in_delim.next = self.decode.in_delim.val();
        self.after_error_flag.next = self.decode.after_error_flag.val();
        self.bc0.next = self.decode.bc0.val();
        self.bc6.next = self.decode.bc6.val();
        self.bc7.next = self.decode.bc7.val();
        self.dom7.next = self.decode.dom7.val();
        self.delim_first.next = self.delim_first_q.q.val();
        self.ack_pending.next = self.ack_pending_q.q.val();
        self.in_crc_field.next = self.field_q.q.val() == Field::Crc;
        self.suspend_due.next = self.decode.suspend_due.val();

        // ---- synchronous reset
        if self.rst.val() {
            self.field_q.d.next = Field::Integrating;
            self.bit_cnt_q.d.next = self.n7_0.val();
            self.is_tx_q.d.next = false;
            self.flag_passive_q.d.next = false;
            self.recovery_cnt.d.next = self.n7_0.val();
            self.last_bit_arb_q.d.next = false;
            self.ack_pending_q.d.next = false;
            self.delim_first_q.d.next = false;
            self.dom_cnt.d.next = self.zero3.val();
            self.hse_off.d.next = false;
        }
    }
}
