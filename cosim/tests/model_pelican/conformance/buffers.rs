//! The TX buffer and the RX window (DS 6.4.13, 6.4.14; P-TX-1, P-RX-2): the
//! standard and extended layouts in both directions, RTR copy, DLC above 8,
//! bytes past the frame (differs); RMC, RBSA and RRB (DS 6.4.16, 6.4.17,
//! 6.4.4; P-RX-3, P-RX-4, P-CMR-4); the FIFO of F frames, data overrun, DOS /
//! DOI / CDO (differs in capacity; P-RX-1, P-RX-6, P-CMR-5); entering reset
//! mode (P-MOD-5).

use super::*;
use drcc_cosim::model::drcc::DrccParams;
use drcc_cosim::Frame;

/// Write `bytes` into the TX window from 16 (operating mode).
fn write_window(n: &mut Net, bytes: &[u8]) {
    for (k, &b) in bytes.iter().enumerate() {
        n.w(reg::WIN + k as u8, b);
    }
}

/// Read the RX window 16..28 as raw bytes.
fn read_window(n: &mut Net) -> Vec<u8> {
    (16..=28u8).map(|r| n.r(r)).collect()
}

/// DS 6.4.13 standard layout (same; P-TX-1): FI = {FF, RTR, -, -, DLC},
/// ID1 = ID.28..21, ID2[7:5] = ID.20..18, data from 19; the other bits of FI
/// and ID2 are ignored; a remote frame sends no data; TXB reads back at 96.
#[test]
fn tx_buffer_standard_layout_sent_as_written() {
    let mut n = op_single(0x00, 0x00);
    // FI bits 5:4 and ID2 bits 4:0 are not part of the frame.
    write_window(&mut n, &[0x33, 0xB4, 0xBF, 1, 2, 3]);
    assert_eq!(n.r(reg::TXB), 0x33, "P-TX-1: TXB[0] reads back at 96");
    assert_eq!(n.r(reg::TXB + 2), 0xBF, "P-TX-1: TXB[2] reads back at 98");
    n.w(reg::CMR, cmd::TR);
    wait_tbs(&mut n, 200);
    // FI = RTR, DLC 4: a remote frame, the data bytes not sent.
    write_window(&mut n, &[0x44, 0x78, 0x60, 9, 9, 9, 9]);
    n.w(reg::CMR, cmd::TR);
    wait_tbs(&mut n, 200);
    assert_eq!(
        n.received,
        vec![(0, Frame::base(0x5A5, &[1, 2, 3])), (0, base_rtr(0x3C3, 4))],
        "DS 6.4.13: standard frame layout"
    );
}

/// DS 6.4.13 extended layout (same; P-TX-1): ID1..ID4 = ID.28..0 (ID4[7:3]),
/// data from 21; DLC 12 is sent as written with 8 data bytes.
#[test]
fn tx_buffer_extended_layout_dlc_above_8_sends_8_bytes() {
    let mut n = op_single(0x00, 0x00);
    let id: u32 = 0x1A2B_3C4D & 0x1FFF_FFFF;
    write_window(
        &mut n,
        &[
            0x8C,
            (id >> 21) as u8,
            (id >> 13) as u8,
            (id >> 5) as u8,
            ((id << 3) as u8) | 0x07,
            1,
            2,
            3,
            4,
            5,
            6,
            7,
            8,
        ],
    );
    n.w(reg::CMR, cmd::TR);
    wait_tbs(&mut n, 300);
    let mut f = ext(id, &[1, 2, 3, 4, 5, 6, 7, 8]);
    f.dlc = 12;
    assert_eq!(n.received, vec![(0, f)], "DS 6.4.13: extended, DLC 12");
}

/// DS 6.4.14 standard layout with the RTR copy in ID2.4 (same; P-RX-2), and
/// the bytes past the frame (27, 28 of a standard frame, past DLC, all data
/// of a remote frame) read 0 (differs: the SJA1000 shows the next message's
/// bytes there).
#[test]
fn rx_window_standard_layout_rtr_copy_and_zero_past_the_frame() {
    let mut n = op_single(0x00, 0x00);
    peer_sends(&mut n, 0, Frame::base(0x5A5, &[1, 2, 3, 4, 5]));
    peer_sends(&mut n, 0, base_rtr(0x3C3, 6));
    let mut e = vec![0x05, 0xB4, 0xA0, 1, 2, 3, 4, 5];
    e.resize(13, 0);
    assert_eq!(read_window(&mut n), e, "DS 6.4.14: standard data frame");
    n.w(reg::CMR, cmd::RRB);
    let mut e = vec![0x46, 0x78, 0x70];
    e.resize(13, 0);
    assert_eq!(read_window(&mut n), e, "DS 6.4.14: RTR copy in ID2.4");
}

/// DS 6.4.14 extended layout with the RTR copy in ID4.2 (same; P-RX-2), DLC
/// as received (12, 8 bytes), bytes past the data read 0 (differs).
#[test]
fn rx_window_extended_layout_rtr_copy_and_zero_past_the_frame() {
    let mut n = op_single(0x00, 0x00);
    let id: u32 = 0x0765_4321;
    let idb = [
        (id >> 21) as u8,
        (id >> 13) as u8,
        (id >> 5) as u8,
        (id << 3) as u8,
    ];
    let mut f = ext(id, &[8, 7, 6, 5, 4, 3, 2, 1]);
    f.dlc = 12;
    peer_sends(&mut n, 0, f);
    peer_sends(&mut n, 0, ext(id, &[0xAB, 0xCD]));
    peer_sends(&mut n, 0, ext_rtr(id, 3));
    let mut e = vec![0x8C];
    e.extend(idb);
    e.extend([8, 7, 6, 5, 4, 3, 2, 1]);
    assert_eq!(read_window(&mut n), e, "DS 6.4.14: extended, DLC 12");
    n.w(reg::CMR, cmd::RRB);
    let mut e = vec![0x82];
    e.extend(idb);
    e.extend([0xAB, 0xCD, 0, 0, 0, 0, 0, 0]);
    assert_eq!(read_window(&mut n), e, "P-RX-2: past DLC read 0");
    n.w(reg::CMR, cmd::RRB);
    let mut e = vec![0xC3, idb[0], idb[1], idb[2], idb[3] | 0x04];
    e.resize(13, 0);
    assert_eq!(read_window(&mut n), e, "DS 6.4.14: RTR copy in ID4.2");
}

/// DS 6.4.16 RMC, 6.4.17 RBSA, 6.4.4 RRB (same; P-RX-3, P-RX-4, P-CMR-4):
/// RMC counts the messages; RRB releases the head, shows the next one and
/// advances RBSA by the message's SJA1000 length (3 + 2 x FF + data bytes,
/// mod 64); RRB on an empty FIFO does nothing; RBSA is written in reset mode
/// only, kept by reset mode, cleared by `rst`.
#[test]
fn rmc_rbsa_and_rrb() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::RBSA, 60);
    n.w(reg::MOD, 0x00);
    n.w(reg::RBSA, 5);
    assert_eq!(n.r(reg::RBSA), 60, "DS 6.4.17: read only in op");
    n.idle(12 * BIT);
    let f1 = ext(0x0001_2345, &[1, 2, 3, 4, 5]); // 3 + 2 + 5 = 10
    let f2 = base_rtr(0x222, 4); // 3
    let f3 = Frame::base(0x333, &[1, 2, 3, 4, 5, 6, 7, 8]); // 11
    for f in [f1, f2, f3] {
        peer_sends(&mut n, 0, f);
    }
    assert_eq!(n.r(reg::RMC), 3, "DS 6.4.16: three messages");
    n.w(reg::CMR, cmd::RRB);
    assert_eq!(n.r(reg::RMC), 2, "DS 6.4.16: RRB decrements");
    assert_eq!(n.r(reg::RBSA), 6, "P-RX-4: (60 + 10) mod 64");
    assert_eq!(n.read_rx(), f2, "DS 6.4.4: the next message in the window");
    n.w(reg::CMR, cmd::RRB);
    assert_eq!(n.r(reg::RBSA), 9, "P-RX-4: a remote frame adds 3");
    n.w(reg::CMR, cmd::RRB);
    assert_eq!(n.r(reg::RBSA), 20, "P-RX-4: + 11");
    assert_eq!(n.r(reg::RMC), 0);
    assert_eq!(n.r(reg::SR) & sr::RBS, 0);
    n.w(reg::CMR, cmd::RRB);
    assert_eq!(n.r(reg::RBSA), 20, "P-CMR-4: RRB on an empty FIFO: nothing");
    assert_eq!(n.r(reg::RMC), 0);
    n.w(reg::MOD, md::RM);
    assert_eq!(n.r(reg::RBSA), 20, "DS 6.4.17: kept by reset mode");
    hardware_reset(&mut n);
    assert_eq!(n.r(reg::RBSA), 0, "DS 6.4.17: 0 after hardware reset");
}

/// Differs (DS 6.4.16: RMC.7..5 reserved, read 0): P-RX-1, P-RX-3. At the
/// default F = 32 the count reaches 32, bit 5, which the SJA1000's 64-byte
/// FIFO never shows (21 frames at most); the next frame is an overrun.
#[test]
fn rmc_counts_to_f_32_with_bit_5() {
    let mut n = op_single(0x00, 0x00);
    for k in 0..32u32 {
        peer_sends(&mut n, 0, Frame::base(0x100 + k, &[]));
    }
    assert_eq!(n.r(reg::RMC), 32, "P-RX-3: F = 32, bit 5");
    assert_eq!(n.r(reg::SR) & sr::DOS, 0, "no overrun at F");
    peer_sends(&mut n, 0, Frame::base(0x200, &[]));
    assert_eq!(n.r(reg::SR) & sr::DOS, sr::DOS, "P-RX-6: the 33rd overruns");
    assert_eq!(n.r(reg::RMC), 32);
}

/// Differs (64-byte RX FIFO: F frames of any length here), same (data
/// overrun: frame lost, DOS, DOI; a frame rejected by the filter is no
/// overrun; CMR.CDO, also with RRB; DOI gated by DOIE): P-RX-1, P-RX-5,
/// P-RX-6, P-IR-2, P-IR-4, P-CMR-5; DS 6.4.5 SR.1, 6.4.6 IR.3, 6.4.4 CMR.3.
#[test]
fn rx_fifo_of_f_frames_overrun_dos_doi_cdo() {
    let mut n = Net::keyed(PelicanParams {
        core: DrccParams::SMALL,
        ..single_a(4, true)
    });
    // Single filter: accept the standard ids 0x100..0x107 only.
    n.w(reg::WIN, 0x20);
    for k in 0..4 {
        n.w(reg::WIN + 4 + k, if k == 0 { 0x00 } else { 0xFF });
    }
    n.w(reg::MOD, md::AFM);
    n.idle(12 * BIT);
    for k in 0..8u32 {
        peer_sends(&mut n, 0, Frame::base(0x100 + k, &[]));
    }
    assert_eq!(n.r(reg::RMC), 8, "P-RX-1: F = 8 frames, each of 3 bytes");
    assert_eq!(n.r(reg::SR) & sr::DOS, 0);
    peer_sends(&mut n, 0, Frame::base(0x200, &[]));
    assert_eq!(n.r(reg::SR) & sr::DOS, 0, "P-RX-5: rejected, no overrun");
    // DOIE = 0: the overrun sets DOS, not DOI.
    peer_sends(&mut n, 0, Frame::base(0x100, &[9]));
    assert_eq!(n.r(reg::SR) & sr::DOS, sr::DOS, "DS 6.4.5: DOS");
    assert_eq!(n.r(reg::RMC), 8, "P-RX-6: the frame is lost");
    n.w(reg::IER, ir::DOI);
    assert_eq!(n.r(reg::IR), 0, "P-IR-2: DOI gated by DOIE");
    n.w(reg::CMR, cmd::CDO);
    assert_eq!(n.r(reg::SR) & sr::DOS, 0, "DS 6.4.4: CDO clears DOS");
    peer_sends(&mut n, 0, Frame::base(0x101, &[9]));
    assert_eq!(n.r(reg::SR) & sr::DOS, sr::DOS, "DS 6.4.5: DOS again");
    assert_eq!(n.r(reg::IR), ir::DOI, "DS 6.4.6: DOI");
    peer_sends(&mut n, 0, Frame::base(0x102, &[9]));
    assert_eq!(n.r(reg::IR), 0, "DS 6.4.4: no further DOI while DOS is set");
    n.w(reg::CMR, cmd::CDO | cmd::RRB);
    assert_eq!(n.r(reg::SR) & sr::DOS, 0, "DS 6.4.4: CDO clears DOS");
    assert_eq!(n.r(reg::RMC), 7, "DS 6.4.4: CDO with RRB");
    for _ in 0..6 {
        n.w(reg::CMR, cmd::RRB);
    }
    assert_eq!(n.r(reg::RMC), 1);
    assert_eq!(
        n.read_rx(),
        Frame::base(0x107, &[]),
        "the last stored frame"
    );
}

/// Same (entering reset mode: TX aborted, FIFO cleared, IR cleared but EI):
/// DS 6.4.2 (setting MOD.0 by software), P-MOD-5. A pending message is
/// dropped (TBS = 1, TCS = 0, no TI) and not sent later; the FIFO empties;
/// BEI clears, EI stays.
#[test]
fn entering_reset_mode_aborts_tx_clears_fifo_and_ir_but_ei() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::EWLR, 8);
    n.linux_start(0xFF, 0x00);
    peer_sends(&mut n, 0, Frame::base(0x060, &[1]));
    assert_eq!(n.r(reg::RMC), 1);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x061, &[2]));
    n.w(reg::CMR, cmd::TR);
    n.until(200 * BIT, |n| n.dut.read(reg::TXERR) >= 8);
    n.idle(4);
    assert_eq!(n.dut.read(reg::IR) & (ir::EI | ir::BEI), ir::EI | ir::BEI);
    n.w(reg::MOD, md::RM);
    let s = n.r(reg::SR);
    assert_eq!(s & (sr::TBS | sr::TCS | sr::RBS), sr::TBS, "P-MOD-5");
    assert_eq!(n.r(reg::RMC), 0, "P-MOD-5: FIFO cleared");
    assert_eq!(n.r(reg::IR), ir::EI, "P-MOD-5: IR cleared but EI");
    n.peer_on = [true, true];
    n.received.clear();
    n.w(reg::MOD, 0x00);
    n.idle(100 * BIT);
    assert!(n.received.is_empty(), "P-MOD-5: the message was dropped");
}
