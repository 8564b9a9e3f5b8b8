//! Tests of `drcc_hdl::pelican::ecc_code` against the SJA1000 data sheet's
//! error code capture (6.4.9: `ERRC` bit 00, form 01, stuff 10, other 11;
//! `DIR` 1 = RX; the `SEG` table) and pelican_contract.md P-CAP-2 (the field
//! -> segment choices, the ACK and CRC patterns).

use drcc_hdl::channel::bsp::field::Field;
use drcc_hdl::pelican::ecc_code::EccCode;
use rust_hdl::prelude::*;

const BIT: u64 = 1;
const STUFF: u64 = 2;
const CRC: u64 = 3;
const FORM: u64 = 4;
const ACK: u64 = 5;

fn ecc(kind: u64, field: Field, tx: bool, passive: bool) -> u8 {
    let mut uut = EccCode::default();
    uut.connect_all();
    uut.err_kind.next = kind.into();
    uut.err_field.next = field;
    uut.err_tx.next = tx;
    uut.passive.next = passive;
    assert!(simulate(&mut uut, 100));
    uut.ecc.val().to_u64() as u8
}

/// The data sheet's segment code of each field (P-CAP-2's list).
#[test]
fn seg_is_the_data_sheet_code_of_the_field() {
    let table = [
        (Field::Idle, 0x03),
        (Field::IdA, 0x02),
        (Field::SrrRtr, 0x04),
        (Field::Ide, 0x05),
        (Field::IdB, 0x07),
        (Field::RtrExt, 0x0C),
        (Field::R1, 0x0D),
        (Field::R0, 0x09),
        (Field::Dlc, 0x0B),
        (Field::Data, 0x0A),
        (Field::Crc, 0x08),
        (Field::CrcDelim, 0x18),
        (Field::AckSlot, 0x19),
        (Field::AckDelim, 0x1B),
        (Field::Eof, 0x1A),
        (Field::Intermission, 0x12),
        (Field::Suspend, 0x12),
        (Field::ErrorFlag, 0x11),
        (Field::ErrorDelim, 0x17),
        (Field::OverloadFlag, 0x1C),
        (Field::OverloadDelim, 0x17),
        (Field::Integrating, 0x00),
        (Field::BusOff, 0x00),
    ];
    for (field, seg) in table {
        // a bit error while transmitting: ERRC 00, DIR 0
        assert_eq!(ecc(BIT, field, true, false), seg, "{field:?}");
    }
    // a passive error flag has its own code
    assert_eq!(ecc(BIT, Field::ErrorFlag, true, true), 0x16);
    assert_eq!(
        ecc(BIT, Field::Data, true, true),
        0x0A,
        "passive only flags"
    );
}

/// `ERRC` [7:6] from the kind and `DIR` [5] = 1 while receiving.
#[test]
fn errc_and_dir() {
    assert_eq!(ecc(BIT, Field::Data, true, false), 0x0A);
    assert_eq!(ecc(STUFF, Field::Data, false, false), 0x80 | 0x20 | 0x0A);
    assert_eq!(ecc(FORM, Field::Eof, false, false), 0x40 | 0x20 | 0x1A);
    assert_eq!(ecc(STUFF, Field::IdA, true, false), 0x80 | 0x02);
    assert_eq!(ecc(FORM, Field::ErrorDelim, true, false), 0x40 | 0x17);
}

/// P-CAP-2: an ACK error reads as the SJA1000 reports it, "other" in the ACK
/// slot (0xD9 for a transmitter), and a CRC error as a form error at the ACK
/// delimiter (0x7B for a receiver), whatever field the channel captured.
#[test]
fn ack_and_crc_errors_read_as_the_sja1000_reports_them() {
    assert_eq!(ecc(ACK, Field::AckSlot, true, false), 0xD9);
    assert_eq!(ecc(ACK, Field::AckDelim, true, true), 0xD9);
    assert_eq!(ecc(CRC, Field::AckDelim, false, false), 0x7B);
    assert_eq!(ecc(CRC, Field::CrcDelim, false, false), 0x7B);
}

#[test]
fn ecc_code_synthesizes() {
    let mut uut = EccCode::default();
    uut.connect_all();
    crate::synth_check::yosys_check("ecc_code", &generate_verilog(&uut));
}
