//! ISO 16845-1 8.2: error detection by the transmitter (bit errors in every
//! field, stuff errors, form errors, ACK errors).

use super::*;

/// Positions of one bit the IUT drives in every field of `fb`, both polarities
/// where the field has both, outside arbitration losses and the ACK slot.
fn one_bit_per_field(fb: &FrameBits) -> Vec<usize> {
    let mut v = Vec::new();
    for (i, b) in fb.bits.iter().enumerate() {
        let skip = b.stuff
            || matches!(b.field, Field::Sof | Field::AckSlot)
            || (b.value && b.field.is_arbitration());
        if skip {
            continue;
        }
        if !v
            .iter()
            .any(|&j: &usize| fb.bits[j].field == b.field && fb.bits[j].value == b.value)
        {
            v.push(i);
        }
    }
    v
}

/// Inverts one bit of each value in every field `frame` drives (see
/// [`one_bit_per_field`]) on a fresh IUT each; `want` are fields that must be
/// among them. Each: flag from the next bit, TEC + 8 at the bit, a successful
/// retransmission.
fn bit_error_each_field(iut: &Iut, frame: &Frame, want: &[Field]) {
    let fb = FrameBits::new(frame);
    let pos = one_bit_per_field(&fb);
    for w in want {
        assert!(
            pos.iter().any(|&p| fb.bits[p].field == *w),
            "{frame}: no bit of {w:?}"
        );
    }
    corrupt_each(iut, frame, &pos);
}

/// 8.2.1 (and 8.6.6): a bit error in every field the IUT drives in a base frame
/// (dominant identifier bits forced recessive, RTR, IDE, r0, DLC, data and CRC
/// bits of both values, CRC delimiter, ACK delimiter, EOF), data and remote
/// frames: error flag from the next bit, TEC + 8 at the bit, then a successful
/// retransmission.
pub fn iso_8_2_1_bit_error_base(iut: &Iut) {
    let common = [
        Field::IdA,
        Field::SrrRtr,
        Field::Ide,
        Field::R0,
        Field::Dlc,
        Field::Crc,
        Field::CrcDelim,
        Field::AckDelim,
        Field::Eof,
    ];
    let mut with_data = common.to_vec();
    with_data.push(Field::Data);
    bit_error_each_field(iut, &base(0x2B5, &[0x0F, 0xF0]), &with_data);
    // A remote frame's RTR is a recessive arbitration bit (lost arbitration).
    let remote_fields: Vec<Field> = common.into_iter().filter(|&f| f != Field::SrrRtr).collect();
    bit_error_each_field(iut, &remote(0x1C3, false, 3), &remote_fields);
}

/// 8.2.2: the same in an extended frame: dominant base and extended identifier
/// bits forced recessive, r1 (the FDF position) and r0, and every other field it
/// drives (IDE and SRR are recessive arbitration bits: read dominant they are
/// lost arbitration, 8.1.4).
pub fn iso_8_2_2_bit_error_extended(iut: &Iut) {
    let want = [
        Field::IdA,
        Field::IdB,
        Field::RtrExt,
        Field::R1,
        Field::R0,
        Field::Dlc,
        Field::Data,
        Field::Crc,
        Field::CrcDelim,
        Field::AckDelim,
        Field::Eof,
    ];
    bit_error_each_field(iut, &ext(0x0AB5_3C21, &[0x5A]), &want);
}

/// The recessive stuff bit after the IDE bit of a base frame: ISO 11898-1 puts
/// it in the control field (rule c exception 2 does not apply: TEC + 8), and so
/// does the contract (§4.4, §4.5).
pub(super) fn base_ide_stuff_bit(fb: &FrameBits, p: usize) -> bool {
    let b = fb.bits[p];
    b.stuff && b.value && b.field == Field::Ide && !fb.frame.ide
}

fn stuff_bits_tx(iut: &Iut, frames: &[Frame]) {
    for f in frames {
        let fb = FrameBits::new(f);
        corrupt_each(iut, f, &fb.stuff_positions());
    }
}

/// 8.2.3 (and 8.6.19): every stuff bit of base frames covering every field
/// inverted: error flag from the next bit; TEC + 8, except a recessive stuff bit
/// of the arbitration field read dominant (rule c exception 2: unchanged). A
/// base frame's IDE is control field (ISO 11898-1:2015 10.4.2.3), so a stuff bit
/// after it is not arbitration: TEC + 8.
pub fn iso_8_2_3_stuff_bit_errors_base(iut: &Iut) {
    stuff_bits_tx(iut, &stuffing_frames(false));
}

/// 8.2.4: as 8.2.3 on extended frames.
pub fn iso_8_2_4_stuff_bit_errors_extended(iut: &Iut) {
    stuff_bits_tx(iut, &stuffing_frames(true));
}

/// 8.2.8 (classical adaptation; ISO 16845-1 runs it on a 64-byte FD frame): as
/// 8.2.3 on base frames ID 555h, DLC 8, with the ISO data patterns.
pub fn iso_8_2_8_stuff_bit_errors_data_patterns(iut: &Iut) {
    stuff_bits_tx(iut, &data_pattern_frames());
}

/// 8.2.5 (and 8.6.7): a dominant CRC delimiter, ACK delimiter and EOF bits 1..=7
/// are errors for the transmitter: flag from the next bit, TEC + 8.
pub fn iso_8_2_5_form_errors_tx(iut: &Iut) {
    let f = base(0x5A5, &[0xA5, 0x5A]);
    let fb = FrameBits::new(&f);
    let mut pos = vec![fb.crc_delim(), fb.pos(Field::AckDelim, 0)];
    pos.extend((1..=7).map(|n| fb.eof(n)));
    corrupt_each(iut, &f, &pos);
}

/// 8.2.6 (and 8.6.8): ACK error: recessive ACK slot, error flag from the ACK
/// delimiter, TEC + 8 at the ACK slot while error active.
pub fn iso_8_2_6_ack_error(iut: &Iut) {
    iso_8_6_8_ack_error_active(iut);
}
