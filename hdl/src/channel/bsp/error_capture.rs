//! Error code capture and error counts by kind (timing contract §9): what the
//! host can read about the last error and the last lost arbitration.
//!
//! One kind per error, by the precedence of contract §9 (bit, stuff, form, ACK,
//! CRC), which `error_decision` applies one clock ahead and hands over one-hot
//! (Fmax). The counts saturate at 255. Nothing here feeds back into the protocol.

use super::field::Field;
use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The error code capture, arbitration-lost capture and error counters.
#[derive(LogicBlock, Default)]
pub struct ErrorCapture {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset.
    pub rst: Signal<In, Bit>,
    // from error detection (at a sample point)
    /// An error starts an error flag: capture it.
    pub capture: Signal<In, Bit>,
    // its one kind (contract §9 precedence applied, one-hot, each implies
    // `capture`)
    /// The captured error is a bit error.
    pub kind_bit: Signal<In, Bit>,
    /// The captured error is a stuff error.
    pub kind_stuff: Signal<In, Bit>,
    /// The captured error is a form error.
    pub kind_form: Signal<In, Bit>,
    /// The captured error is an ACK error.
    pub kind_ack: Signal<In, Bit>,
    /// The captured error is a CRC error.
    pub kind_crc: Signal<In, Bit>,
    /// The node was transmitter when it detected the error.
    pub as_tx: Signal<In, Bit>,
    /// Arbitration was lost at this sample point.
    pub arb_lost: Signal<In, Bit>,
    // position in the frame
    /// The field of the sampled bit.
    pub field: Signal<In, Field>,
    /// Position of the sampled bit in its field.
    pub bit_cnt: Signal<In, Bits<5>>,
    // to the host
    /// One clock: an error was captured.
    pub err_valid: Signal<Out, Bit>,
    /// Kind of the last error: 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK.
    pub err_kind: Signal<Out, Bits<3>>,
    /// Field of the last error.
    pub err_field: Signal<Out, Field>,
    /// The node was transmitter at the last error.
    pub err_tx: Signal<Out, Bit>,
    /// Arbitration-lost position: ID_A bit n is n, SRR/RTR 11, IDE 12, ID_B bit
    /// n is 13 + n.
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
    err_valid_q: DFF<Bit>,
    err_kind_q: DFF<Bits<3>>,
    err_field_q: DFF<Field>,
    err_tx_q: DFF<Bit>,
    alc_q: DFF<Bits<5>>,
    cnt_bit_q: DFF<Bits<8>>,
    cnt_stuff_q: DFF<Bits<8>>,
    cnt_crc_q: DFF<Bits<8>>,
    cnt_form_q: DFF<Bits<8>>,
    cnt_ack_q: DFF<Bits<8>>,
    // registered pre-decodes (stable for clocks before the next sample point)
    p_alc: DFF<Bits<5>>,
    p_cnt_bit_max: DFF<Bit>,
    p_cnt_stuff_max: DFF<Bit>,
    p_cnt_crc_max: DFF<Bit>,
    p_cnt_form_max: DFF<Bit>,
    p_cnt_ack_max: DFF<Bit>,
    kind: Signal<Local, Bits<3>>,
    alc_n: Signal<Local, Bits<5>>,
    k_bit: Const<3, 1>,
    k_stuff: Const<3, 2>,
    k_crc: Const<3, 3>,
    k_form: Const<3, 4>,
    k_ack: Const<3, 5>,
    zero3: Const<3, 0>,
    n5_11: Const<5, 11>,
    n5_12: Const<5, 12>,
    n5_13: Const<5, 13>,
    n5_31: Const<5, 31>,
    zero5: Const<5, 0>,
    one8: Const<8, 1>,
    max8: Const<8, 255>,
    zero8: Const<8, 0>,
}

impl Logic for ErrorCapture {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            err_valid_q,
            err_kind_q,
            err_field_q,
            err_tx_q,
            alc_q,
            cnt_bit_q,
            cnt_stuff_q,
            cnt_crc_q,
            cnt_form_q,
            cnt_ack_q,
            p_alc,
            p_cnt_bit_max,
            p_cnt_stuff_max,
            p_cnt_crc_max,
            p_cnt_form_max,
            p_cnt_ack_max
        );
        // Arbitration-lost position (contract §9).
        match self.field.val() {
            Field::IdA => {
                self.alc_n.next = self.bit_cnt.val();
            }
            Field::SrrRtr => {
                self.alc_n.next = self.n5_11.val();
            }
            Field::Ide => {
                self.alc_n.next = self.n5_12.val();
            }
            Field::IdB => {
                self.alc_n.next = self.n5_13.val() + self.bit_cnt.val();
            }
            _ => {
                self.alc_n.next = self.n5_31.val();
            }
        }
        self.p_alc.d.next = self.alc_n.val();
        self.p_cnt_bit_max.d.next = self.cnt_bit_q.q.val() == self.max8.val();
        self.p_cnt_stuff_max.d.next = self.cnt_stuff_q.q.val() == self.max8.val();
        self.p_cnt_crc_max.d.next = self.cnt_crc_q.q.val() == self.max8.val();
        self.p_cnt_form_max.d.next = self.cnt_form_q.q.val() == self.max8.val();
        self.p_cnt_ack_max.d.next = self.cnt_ack_q.q.val() == self.max8.val();
        // The kind code of the one-hot kind (contract §9).
        self.kind.next = self.k_crc.val();
        if self.kind_bit.val() {
            self.kind.next = self.k_bit.val();
        } else if self.kind_stuff.val() {
            self.kind.next = self.k_stuff.val();
        } else if self.kind_form.val() {
            self.kind.next = self.k_form.val();
        } else if self.kind_ack.val() {
            self.kind.next = self.k_ack.val();
        }
        self.err_valid_q.d.next = false;
        if self.capture.val() {
            self.err_valid_q.d.next = true;
            self.err_kind_q.d.next = self.kind.val();
            self.err_field_q.d.next = self.field.val();
            self.err_tx_q.d.next = self.as_tx.val();
        }
        // Each count from its one-hot kind: no decoder after the sample point.
        if self.kind_bit.val() && !self.p_cnt_bit_max.q.val() {
            self.cnt_bit_q.d.next = self.cnt_bit_q.q.val() + self.one8.val();
        }
        if self.kind_stuff.val() && !self.p_cnt_stuff_max.q.val() {
            self.cnt_stuff_q.d.next = self.cnt_stuff_q.q.val() + self.one8.val();
        }
        if self.kind_crc.val() && !self.p_cnt_crc_max.q.val() {
            self.cnt_crc_q.d.next = self.cnt_crc_q.q.val() + self.one8.val();
        }
        if self.kind_form.val() && !self.p_cnt_form_max.q.val() {
            self.cnt_form_q.d.next = self.cnt_form_q.q.val() + self.one8.val();
        }
        if self.kind_ack.val() && !self.p_cnt_ack_max.q.val() {
            self.cnt_ack_q.d.next = self.cnt_ack_q.q.val() + self.one8.val();
        }
        if self.arb_lost.val() {
            self.alc_q.d.next = self.p_alc.q.val();
        }
        if self.rst.val() {
            self.err_valid_q.d.next = false;
            self.err_kind_q.d.next = self.zero3.val();
            self.err_field_q.d.next = Field::Integrating;
            self.err_tx_q.d.next = false;
            self.alc_q.d.next = self.zero5.val();
            self.cnt_bit_q.d.next = self.zero8.val();
            self.cnt_stuff_q.d.next = self.zero8.val();
            self.cnt_crc_q.d.next = self.zero8.val();
            self.cnt_form_q.d.next = self.zero8.val();
            self.cnt_ack_q.d.next = self.zero8.val();
        }
        self.err_valid.next = self.err_valid_q.q.val();
        self.err_kind.next = self.err_kind_q.q.val();
        self.err_field.next = self.err_field_q.q.val();
        self.err_tx.next = self.err_tx_q.q.val();
        self.alc.next = self.alc_q.q.val();
        self.cnt_bit.next = self.cnt_bit_q.q.val();
        self.cnt_stuff.next = self.cnt_stuff_q.q.val();
        self.cnt_crc.next = self.cnt_crc_q.q.val();
        self.cnt_form.next = self.cnt_form_q.q.val();
        self.cnt_ack.next = self.cnt_ack_q.q.val();
    }
}
