//! The `tx` pin (timing contract §4.2): the bit this node drives on the bus,
//! loaded only at the start of a bit.
//!
//! The bit is prepared from the state the last sample point left: the state
//! changes only at sample points and no `bit_start` falls on one, so it is the
//! bit of that state, and the sample decision stays off this path. (The latched
//! frame can change only while nothing is pending, and then the node sends no
//! frame bit.) Listen-only never drives a dominant bit (contract §7).

use super::field::Field;
use crate::pins::RecessiveReg;
use rust_hdl::prelude::*;

/// The register behind the CAN `tx` pin and the bit it sends next.
#[derive(LogicBlock, Default)]
pub struct TxPin {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: recessive.
    pub rst: Signal<In, Bit>,
    // from the bit timing logic
    /// The start of a bit: the pin may change.
    pub bit_start: Signal<In, Bit>,
    /// This bit start is a hard synchronisation.
    pub hard_sync: Signal<In, Bit>,
    // configuration (held)
    /// Listen-only mode (contract §7): recessive always.
    pub listen_only: Signal<In, Bit>,
    // from protocol control (registered state)
    /// The field the next bit belongs to.
    pub field: Signal<In, Field>,
    /// The node is transmitter of the frame.
    pub is_tx: Signal<In, Bit>,
    /// The node sends a passive error flag.
    pub flag_passive: Signal<In, Bit>,
    // from the other units
    /// Transmit request: a SOF from idle is this node's frame.
    pub tx_starts: Signal<In, Bit>,
    /// Transmit frame: the frame's bit at the current field position.
    pub frame_bit: Signal<In, Bit>,
    /// Stuffing: the next bit is a stuff bit.
    pub stuff_insert: Signal<In, Bit>,
    /// Stuffing: the last bit counted.
    pub stuff_last: Signal<In, Bit>,
    /// CRC: every received CRC bit matched.
    pub crc_ok: Signal<In, Bit>,
    /// The bit this node drives on the bus (true: recessive).
    pub tx: Signal<Out, Bit>,
    /// The pin's register: recessive from configuration on (`RecessiveReg`).
    tx_q: RecessiveReg<Bit>,
    tx_bit_n: Signal<Local, Bit>,
    tx_bit: Signal<Local, Bit>,
}

impl Logic for TxPin {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, tx_q);
        // ---- the bit this node sends next
        self.tx_bit_n.next = true;
        match self.field.val() {
            Field::ErrorFlag => {
                self.tx_bit_n.next = self.flag_passive.val();
            }
            Field::OverloadFlag => {
                self.tx_bit_n.next = false;
            }
            Field::AckSlot => {
                // 10.4.2.7: receivers that found the CRC correct send ACK.
                self.tx_bit_n.next = self.is_tx.val() || !self.crc_ok.val();
            }
            _ => {
                if self.is_tx.val() {
                    if self.stuff_insert.val() {
                        // 10.5: the stuff bit is the complement of the last five.
                        self.tx_bit_n.next = !self.stuff_last.val();
                    } else {
                        self.tx_bit_n.next = self.frame_bit.val();
                    }
                }
            }
        }
        // Listen-only: the node never drives a dominant bit (contract §7).
        self.tx_bit.next = self.tx_bit_n.val() || self.listen_only.val();

        // ---- the pin changes only at the start of a bit
        if self.bit_start.val() {
            if self.hard_sync.val() && (self.field.val() == Field::Idle) {
                self.tx_q.d.next = !self.tx_starts.val();
            } else if self.hard_sync.val() && (self.field.val() == Field::Intermission) {
                // 10.4.6: a node joining at intermission bit 3 sends no SOF bit;
                // its first identifier bit follows.
                self.tx_q.d.next = true;
            } else if self.hard_sync.val() && (self.field.val() == Field::Suspend) {
                self.tx_q.d.next = true;
            } else if self.field.val() == Field::Idle {
                self.tx_q.d.next = !self.tx_starts.val();
            } else {
                self.tx_q.d.next = self.tx_bit.val();
            }
        }
        self.tx.next = self.tx_q.q.val();
        if self.rst.val() {
            self.tx_q.d.next = true;
        }
    }
}
