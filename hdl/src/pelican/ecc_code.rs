//! The SJA1000 error code of a channel's captured error (pelican_contract.md
//! P-CAP-2, SJA1000 data sheet 6.4.9, "error code capture"): `ECC =
//! {ERRC[1:0], DIR, SEG[4:0]}` from the channel's error capture (timing
//! contract §9: `err_kind`, `err_field`, `err_tx`).
//!
//! `ERRC`: bit error 00, form error 01, stuff error 10, other 11. An ACK error
//! reads as "other" in the ACK slot and a CRC error as a form error at the ACK
//! delimiter, which is how the SJA1000 itself reports them. `DIR` = 1 for an
//! error while receiving. `SEG` is the data sheet's segment code of the field
//! the error was found in. The channel reports the field, not the bit in it,
//! so the identifier's segments read as their field's first code (P-CAP-2's
//! decision). Combinational: the capture register (`super::captures`) takes it
//! with `err_valid`.

use crate::channel::bsp::field::Field;
use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// Channel error capture -> SJA1000 `ECC` byte.
#[derive(LogicBlock, Default)]
pub struct EccCode {
    // ---- the channel's error capture (timing contract §9) ----
    /// Kind: 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK.
    pub err_kind: Signal<In, Bits<3>>,
    /// The field of the bit in error.
    pub err_field: Signal<In, Field>,
    /// The channel was transmitter.
    pub err_tx: Signal<In, Bit>,
    /// The channel is error passive (its error flag is a passive one).
    pub passive: Signal<In, Bit>,
    // ---- the code ----
    /// `ECC`: [7:6] `ERRC`, [5] `DIR`, [4:0] `SEG`.
    pub ecc: Signal<Out, Bits<8>>,
    /// `SEG` of the field.
    seg: Signal<Local, Bits<5>>,
    /// `ERRC`.
    errc: Signal<Local, Bits<2>>,
    /// `DIR` (1 = receiving).
    dir: Signal<Local, Bit>,
    /// `SEG` 0x03: start of frame.
    seg_sof: Const<5, 0x03>,
    /// `SEG` 0x02: ID.28 to ID.21.
    seg_id_28_21: Const<5, 0x02>,
    /// `SEG` 0x04: SRTR bit.
    seg_srtr: Const<5, 0x04>,
    /// `SEG` 0x05: IDE bit.
    seg_ide: Const<5, 0x05>,
    /// `SEG` 0x07: ID.17 to ID.13.
    seg_id_17_13: Const<5, 0x07>,
    /// `SEG` 0x0c: RTR bit.
    seg_rtr: Const<5, 0x0C>,
    /// `SEG` 0x0d: reserved bit 1.
    seg_r1: Const<5, 0x0D>,
    /// `SEG` 0x09: reserved bit 0.
    seg_r0: Const<5, 0x09>,
    /// `SEG` 0x0b: data length code.
    seg_dlc: Const<5, 0x0B>,
    /// `SEG` 0x0a: data field.
    seg_data: Const<5, 0x0A>,
    /// `SEG` 0x08: CRC sequence.
    seg_crc: Const<5, 0x08>,
    /// `SEG` 0x18: CRC delimiter.
    seg_crc_delim: Const<5, 0x18>,
    /// `SEG` 0x19: acknowledge slot.
    seg_ack_slot: Const<5, 0x19>,
    /// `SEG` 0x1b: acknowledge delimiter.
    seg_ack_delim: Const<5, 0x1B>,
    /// `SEG` 0x1a: end of frame.
    seg_eof: Const<5, 0x1A>,
    /// `SEG` 0x12: intermission.
    seg_intermission: Const<5, 0x12>,
    /// `SEG` 0x11: active error flag.
    seg_active_flag: Const<5, 0x11>,
    /// `SEG` 0x16: passive error flag.
    seg_passive_flag: Const<5, 0x16>,
    /// `SEG` 0x17: error delimiter.
    seg_err_delim: Const<5, 0x17>,
    /// `SEG` 0x1c: overload flag.
    seg_overload_flag: Const<5, 0x1C>,
    /// `SEG` 0x00: no segment code.
    seg_none: Const<5, 0x00>,
    /// `ERRC` codes: bit 00, form 01, stuff 10, other 11.
    errc_bit: Const<2, 0>,
    errc_form: Const<2, 1>,
    errc_stuff: Const<2, 2>,
    errc_other: Const<2, 3>,
    /// The channel's `err_kind` codes (timing contract §9).
    kind_stuff: Const<3, 2>,
    kind_crc: Const<3, 3>,
    kind_form: Const<3, 4>,
    kind_ack: Const<3, 5>,
}

impl Logic for EccCode {
    #[hdl_gen]
    fn update(&mut self) {
        // Segment codes of the data sheet (table "bit interpretation of the
        // error code capture register", SEG4..SEG0).
        self.seg.next = self.seg_none.val();
        match self.err_field.val() {
            Field::Idle => self.seg.next = self.seg_sof.val(),
            Field::IdA => self.seg.next = self.seg_id_28_21.val(),
            Field::SrrRtr => self.seg.next = self.seg_srtr.val(),
            Field::Ide => self.seg.next = self.seg_ide.val(),
            Field::IdB => self.seg.next = self.seg_id_17_13.val(),
            Field::RtrExt => self.seg.next = self.seg_rtr.val(),
            Field::R1 => self.seg.next = self.seg_r1.val(),
            Field::R0 => self.seg.next = self.seg_r0.val(),
            Field::Dlc => self.seg.next = self.seg_dlc.val(),
            Field::Data => self.seg.next = self.seg_data.val(),
            Field::Crc => self.seg.next = self.seg_crc.val(),
            Field::CrcDelim => self.seg.next = self.seg_crc_delim.val(),
            Field::AckSlot => self.seg.next = self.seg_ack_slot.val(),
            Field::AckDelim => self.seg.next = self.seg_ack_delim.val(),
            Field::Eof => self.seg.next = self.seg_eof.val(),
            Field::Intermission => self.seg.next = self.seg_intermission.val(),
            Field::Suspend => self.seg.next = self.seg_intermission.val(),
            Field::ErrorFlag => {
                if self.passive.val() {
                    self.seg.next = self.seg_passive_flag.val();
                } else {
                    self.seg.next = self.seg_active_flag.val();
                }
            }
            Field::ErrorDelim => self.seg.next = self.seg_err_delim.val(),
            Field::OverloadDelim => self.seg.next = self.seg_err_delim.val(),
            Field::OverloadFlag => self.seg.next = self.seg_overload_flag.val(),
            _ => {}
        }
        // ERRC from the kind (1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK).
        self.errc.next = self.errc_bit.val();
        if self.err_kind.val() == self.kind_stuff.val() {
            self.errc.next = self.errc_stuff.val();
        }
        if self.err_kind.val() == self.kind_form.val() {
            self.errc.next = self.errc_form.val();
        }
        // The SJA1000's own patterns: an ACK error is "other" in the ACK slot,
        // a CRC error a form error at the ACK delimiter.
        if self.err_kind.val() == self.kind_ack.val() {
            self.errc.next = self.errc_other.val();
            self.seg.next = self.seg_ack_slot.val();
        }
        if self.err_kind.val() == self.kind_crc.val() {
            self.errc.next = self.errc_form.val();
            self.seg.next = self.seg_ack_delim.val();
        }
        self.dir.next = !self.err_tx.val();
        self.ecc.next = (bit_cast::<8, 2>(self.errc.val()) << 6)
            | (bit_cast::<8, 1>(self.dir.val().into()) << 5)
            | bit_cast::<8, 5>(self.seg.val());
    }
}
