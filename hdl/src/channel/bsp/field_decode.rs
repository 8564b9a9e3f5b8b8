//! Registered pre-decodes of the protocol state (timing contract §4): the field
//! classes and bit-counter values the next sample point looks at.
//!
//! Everything here is a function of state that changes only at SAMPLE edges,
//! `bit_start` or reset, registered every clock. The next SAMPLE edge comes at
//! least 3 clocks after any of these (8 tq after a sample, TSEG1 >= 3 clocks
//! after a bit_start, 2 ticks after reset), so at a SAMPLE edge each equals its
//! combinational value and the sample-point logic starts from flip-flops
//! instead of decoders and comparators.

use super::field::Field;
use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The field classes and bit-counter compares, one clock behind the state.
#[derive(LogicBlock, Default)]
pub struct FieldDecode {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// The field the next bit belongs to.
    pub field: Signal<In, Field>,
    /// Position of the next bit in its field.
    pub bit_cnt: Signal<In, Bits<7>>,
    /// Bus-off recovery: sequences of 11 recessive bits seen.
    pub recovery_cnt: Signal<In, Bits<7>>,
    /// Dominant bits counted after a flag (rule f).
    pub dom_cnt: Signal<In, Bits<3>>,
    /// The node is transmitter of the frame.
    pub is_tx: Signal<In, Bit>,
    /// The node is error passive.
    pub error_passive: Signal<In, Bit>,
    /// The latched transmit frame is extended (its IDE is arbitration).
    pub frame_ide: Signal<In, Bit>,
    /// The field is part of the arbitration field (10.4.2.2).
    pub in_arbitration: Signal<Out, Bit>,
    /// The field is between SOF and EOF (bit monitoring applies).
    pub in_frame: Signal<Out, Bit>,
    /// The field is covered by the CRC (SOF to the end of the data field).
    pub crc_covered: Signal<Out, Bit>,
    /// The field is an error or overload delimiter.
    pub in_delim: Signal<Out, Bit>,
    /// The field is an error delimiter (rule b).
    pub after_error_flag: Signal<Out, Bit>,
    /// The field is the ACK slot.
    pub ack_slot: Signal<Out, Bit>,
    /// bit_cnt == 0.
    pub bc0: Signal<Out, Bit>,
    /// bit_cnt == 2.
    pub bc2: Signal<Out, Bit>,
    /// bit_cnt == 3.
    pub bc3: Signal<Out, Bit>,
    /// bit_cnt == 5.
    pub bc5: Signal<Out, Bit>,
    /// bit_cnt == 6.
    pub bc6: Signal<Out, Bit>,
    /// bit_cnt == 7.
    pub bc7: Signal<Out, Bit>,
    /// bit_cnt == 10.
    pub bc10: Signal<Out, Bit>,
    /// bit_cnt == 14.
    pub bc14: Signal<Out, Bit>,
    /// bit_cnt == 17.
    pub bc17: Signal<Out, Bit>,
    /// The 128th sequence of 11 recessive bits is running (12.1.4.4).
    pub recovery_end: Signal<Out, Bit>,
    /// An error-passive transmitter suspends after its frame (10.4.5).
    pub suspend_due: Signal<Out, Bit>,
    /// dom_cnt == 7: the next dominant bit is the 8th (rule f).
    pub dom7: Signal<Out, Bit>,
    p_in_arbitration: DFF<Bit>,
    p_ide: DFF<Bit>,
    p_in_frame: DFF<Bit>,
    p_crc_covered: DFF<Bit>,
    p_in_delim: DFF<Bit>,
    p_after_error_flag: DFF<Bit>,
    p_ack_slot: DFF<Bit>,
    p_bc0: DFF<Bit>,
    p_bc2: DFF<Bit>,
    p_bc3: DFF<Bit>,
    p_bc5: DFF<Bit>,
    p_bc6: DFF<Bit>,
    p_bc7: DFF<Bit>,
    p_bc10: DFF<Bit>,
    p_bc14: DFF<Bit>,
    p_bc17: DFF<Bit>,
    p_recovery_end: DFF<Bit>,
    p_suspend_due: DFF<Bit>,
    p_dom7: DFF<Bit>,
    n3_7: Const<3, 7>,
    n7_0: Const<7, 0>,
    n7_2: Const<7, 2>,
    n7_3: Const<7, 3>,
    n7_5: Const<7, 5>,
    n7_6: Const<7, 6>,
    n7_7: Const<7, 7>,
    n7_10: Const<7, 10>,
    n7_14: Const<7, 14>,
    n7_17: Const<7, 17>,
    n7_127: Const<7, 127>,
}

impl Logic for FieldDecode {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            p_in_arbitration,
            p_ide,
            p_in_frame,
            p_crc_covered,
            p_in_delim,
            p_after_error_flag,
            p_ack_slot,
            p_bc0,
            p_bc2,
            p_bc3,
            p_bc5,
            p_bc6,
            p_bc7,
            p_bc10,
            p_bc14,
            p_bc17,
            p_recovery_end,
            p_suspend_due,
            p_dom7
        );
        // Field classification (10.4.2: the arbitration field is ID and RTR, plus
        // SRR and IDE in extended frames).
        self.p_in_arbitration.d.next = false;
        self.p_ide.d.next = false;
        self.p_in_frame.d.next = false;
        self.p_crc_covered.d.next = false;
        self.p_in_delim.d.next = false;
        self.p_after_error_flag.d.next = false;
        match self.field.val() {
            Field::ErrorDelim => {
                self.p_in_delim.d.next = true;
                self.p_after_error_flag.d.next = true;
            }
            Field::OverloadDelim => {
                self.p_in_delim.d.next = true;
            }
            Field::IdA => {
                self.p_in_arbitration.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::SrrRtr => {
                self.p_in_arbitration.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::Ide => {
                // IDE belongs to the arbitration field of extended frames only
                // (10.4.2.2); a base frame's IDE is control field.
                self.p_ide.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::IdB => {
                self.p_in_arbitration.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::RtrExt => {
                self.p_in_arbitration.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::R1 => {
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::R0 => {
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::Dlc => {
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::Data => {
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::Crc => {
                self.p_in_frame.d.next = true;
            }
            Field::CrcDelim => {
                self.p_in_frame.d.next = true;
            }
            Field::AckSlot => {
                self.p_in_frame.d.next = true;
            }
            Field::AckDelim => {
                self.p_in_frame.d.next = true;
            }
            Field::Eof => {
                self.p_in_frame.d.next = true;
            }
            _ => {}
        }
        self.p_ack_slot.d.next = self.field.val() == Field::AckSlot;
        self.p_bc0.d.next = self.bit_cnt.val() == self.n7_0.val();
        self.p_bc2.d.next = self.bit_cnt.val() == self.n7_2.val();
        self.p_bc3.d.next = self.bit_cnt.val() == self.n7_3.val();
        self.p_bc5.d.next = self.bit_cnt.val() == self.n7_5.val();
        self.p_bc6.d.next = self.bit_cnt.val() == self.n7_6.val();
        self.p_bc7.d.next = self.bit_cnt.val() == self.n7_7.val();
        self.p_bc10.d.next = self.bit_cnt.val() == self.n7_10.val();
        self.p_bc14.d.next = self.bit_cnt.val() == self.n7_14.val();
        self.p_bc17.d.next = self.bit_cnt.val() == self.n7_17.val();
        self.p_recovery_end.d.next = self.recovery_cnt.val() == self.n7_127.val();
        self.p_suspend_due.d.next = self.is_tx.val() && self.error_passive.val();
        self.p_dom7.d.next = self.dom_cnt.val() == self.n3_7.val();

        self.in_arbitration.next =
            self.p_in_arbitration.q.val() || (self.p_ide.q.val() && self.frame_ide.val());
        self.in_frame.next = self.p_in_frame.q.val();
        self.crc_covered.next = self.p_crc_covered.q.val();
        self.in_delim.next = self.p_in_delim.q.val();
        self.after_error_flag.next = self.p_after_error_flag.q.val();
        self.ack_slot.next = self.p_ack_slot.q.val();
        self.bc0.next = self.p_bc0.q.val();
        self.bc2.next = self.p_bc2.q.val();
        self.bc3.next = self.p_bc3.q.val();
        self.bc5.next = self.p_bc5.q.val();
        self.bc6.next = self.p_bc6.q.val();
        self.bc7.next = self.p_bc7.q.val();
        self.bc10.next = self.p_bc10.q.val();
        self.bc14.next = self.p_bc14.q.val();
        self.bc17.next = self.p_bc17.q.val();
        self.recovery_end.next = self.p_recovery_end.q.val();
        self.suspend_due.next = self.p_suspend_due.q.val();
        self.dom7.next = self.p_dom7.q.val();
    }
}
