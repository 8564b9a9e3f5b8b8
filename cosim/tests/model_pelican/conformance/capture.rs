//! ALC and ECC capture and re-arm (DS 6.4.8, 6.4.9; P-CAP-1..3, P-IR-4 ALI,
//! BEI), the error counters RXERR / TXERR (DS 6.4.11, 6.4.12; P-ERR-1, P-ERR-2,
//! differs / refused rows), EWLR (DS 6.4.10), and bus-off (DS 6.4.3 MOD.0,
//! 6.4.5 SR.7; P-BO-1..7).

use super::*;
use drcc_cosim::model::pelican::PelicanParams;
use drcc_cosim::Frame;

/// One arbitration race on line A: the DUT one-shot (`TR | AT`, single mode)
/// with `dut` against the peer's `peer`; returns when both are done.
fn race(n: &mut Net, dut: Frame, peer: Frame) {
    n.load_tx(&dut);
    n.peer_req[0] = Some(peer);
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(n, 200);
    n.until(300 * BIT, |n| {
        n.peer_req[0].is_none() && !n.peer_out[0].tx_pending
    });
    n.idle(4);
    assert_eq!(n.r(reg::SR) & sr::TCS, 0, "the DUT lost the race");
}

/// DS 6.4.8 (same: "ALC capture, held until read"; P-CAP-1, P-CAP-3, P-IR-4):
/// the position of the first lost arbitration is captured and held until ALC
/// is read; ALI at every loss; reset mode keeps ALC, `rst` clears it.
#[test]
fn alc_capture_held_until_read_and_rearmed() {
    let mut n = op_single(ir::ALI, 0x00);
    // 0x7F0 against 0x7E0: lost at the 7th identifier bit (ID.22), code 6.
    race(&mut n, Frame::base(0x7F0, &[]), Frame::base(0x7E0, &[]));
    assert_eq!(n.r(reg::IR), ir::ALI, "DS 6.4.6: ALI");
    // A remote frame against a data frame: lost at the RTR bit, code 11.
    race(&mut n, base_rtr(0x123, 0), Frame::base(0x123, &[]));
    assert_eq!(n.r(reg::IR), ir::ALI, "P-IR-4: ALI at every loss");
    assert_eq!(n.r(reg::ALC), 6, "DS 6.4.8: the first loss held");
    // Extended against standard remote: SRR = RTR, lost at IDE, code 12.
    race(&mut n, ext(0x123 << 18, &[]), base_rtr(0x123, 0));
    assert_eq!(n.r(reg::ALC), 12, "DS 6.4.8: re-armed by the read");
    assert_eq!(n.r(reg::ALC), 12, "held until the next capture");
    n.w(reg::MOD, md::RM);
    assert_eq!(n.r(reg::ALC), 12, "P-CAP-3: reset mode keeps ALC");
    hardware_reset(&mut n);
    assert_eq!(n.r(reg::ALC), 0, "P-CAP-3: rst clears ALC");
}

/// DS 6.4.8 codes ID.17 = 13 and extended RTR = 31 (P-CAP-1); ALI is not set
/// while ALIE = 0 (DS 6.4.7).
#[test]
fn alc_codes_extended_id_and_rtr_ali_gated_by_alie() {
    let mut n = op_single(0x00, 0x00);
    let id = 0x123 << 18;
    race(&mut n, ext(id | (1 << 17), &[]), ext(id, &[]));
    assert_eq!(n.r(reg::ALC), 13, "DS 6.4.8: lost at ID.17");
    assert_eq!(n.r(reg::IR), 0, "DS 6.4.7: no ALI without ALIE");
    race(&mut n, ext_rtr(id | 0x5A5, 0), ext(id | 0x5A5, &[]));
    assert_eq!(n.r(reg::ALC), 31, "DS 6.4.8: lost at the RTR bit");
}

/// DS 6.4.9 (same; P-CAP-2, P-IR-4): an ACK error as transmitter reads
/// ERRC = 11 (other), DIR = 0 (TX), SEG = 11001 (ACK slot): 0xD9, with BEI.
/// The capture is held through reset mode and later (receive) errors until
/// ECC is read; the next error then is captured, DIR = 1 for a receive error.
#[test]
fn ecc_ack_error_code_held_until_read_then_rearmed() {
    let mut n = op_single(ir::BEI, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x123, &[1]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    assert_eq!(n.r(reg::IR), ir::BEI, "DS 6.4.6: BEI");
    // Reset mode (P-CAP-3 keeps ECC) to run at half the peer's bit rate: the
    // DUT receives the peer's frames with errors.
    n.w(reg::MOD, md::RM);
    n.w(reg::BTR0, 0x01);
    n.w(reg::MOD, 0x00);
    // Bus integration: 11 recessive bits of 32 clocks.
    n.idle(12 * 2 * BIT);
    n.peer_on = [true, true];
    n.peer_req[0] = Some(Frame::base(0x0F0, &[0x55, 0xAA, 0x0F]));
    n.until(400 * BIT, |n| n.dut.read(reg::RXERR) != 0);
    n.idle(2);
    assert_eq!(n.r(reg::IR), ir::BEI, "receive errors raise BEI");
    assert_eq!(n.r(reg::ECC), 0xD9, "DS 6.4.9: the first error held");
    n.until(400 * BIT, |n| n.dut.read(reg::ECC) != 0xD9);
    n.idle(2);
    let e = n.r(reg::ECC);
    assert_eq!(e & 0x20, 0x20, "DS 6.4.9: DIR = 1, error during reception");
    assert!(
        n.r(reg::RXERR) > 0,
        "DS 6.4.11: RXERR counts receive errors"
    );
    hardware_reset(&mut n);
    assert_eq!(n.r(reg::ECC), 0, "P-CAP-3: rst clears ECC");
}

/// The peer sends `f`; line A is cut at the DUT for the line-time window
/// `[16 from, 16 to)` after the frame's SOF edge (bit indices from SOF = 0,
/// no stuff bit before `to`), so the DUT samples bits `from..to` recessive.
/// Returns ECC once the DUT captured an error.
fn ecc_of_cut(f: Frame, from: u64, to: u64) -> u8 {
    let mut n = op_single(0x00, 0x00);
    n.peer_req[0] = Some(f);
    n.until(100 * BIT, |n| !n.peer_out[0].tx);
    // The DUT sees the SOF edge in the next clock: line time 0.
    n.idle(from * BIT);
    n.cut[0] = true;
    n.idle((to - from) * BIT);
    n.cut[0] = false;
    n.until(200 * BIT, |n| n.dut.read(reg::RXERR) != 0);
    n.idle(2);
    n.r(reg::ECC)
}

/// Differs (ECC segment code, per field): P-CAP-2. A stuff error as receiver
/// (ERRC 10, DIR 1) right after ID.20 reads SEG 0x02 (ID.28..18 all 0x02;
/// the SJA1000 reads 0x06 for ID.20..18), one after ID.12 reads 0x07
/// (ID.17..0 all 0x07; the SJA1000 reads 0x0F / 0x0E).
#[test]
fn ecc_segment_code_per_field_in_the_identifier() {
    // id 0x555: SOF 0, ID.28..25 = 1 0 1 0; from bit 5 (ID.24) recessive:
    // five recessive bits ID.24..20, the stuff bit after ID.20 fails.
    let e = ecc_of_cut(Frame::base(0x555, &[]), 5, 12);
    assert_eq!(
        e,
        0x80 | 0x20 | 0x02,
        "P-CAP-2: stuff, RX, ID.28..18 -> 0x02"
    );
    // Extended, base 0x555, ID.17..0 = 0: bits 11..13 (ID.18, SRR, IDE) = 1,
    // 14 (ID.17) = 0; from bit 15 recessive: the stuff bit after ID.12 fails.
    let e = ecc_of_cut(ext(0x555 << 18, &[]), 15, 22);
    assert_eq!(
        e,
        0x80 | 0x20 | 0x07,
        "P-CAP-2: stuff, RX, ID.17..0 -> 0x07"
    );
}

/// Same (ECC: "CRC error = form error at the ACK delimiter, as the chip"):
/// DS 6.4.9, P-CAP-2. One data bit received flipped: ECC = form (01), RX,
/// SEG 0x1B = 0x7B.
#[test]
fn ecc_crc_error_reads_form_error_at_ack_delimiter() {
    // id 0x555, DLC 8, data 0x55..: no stuff bit before the data (bit 19);
    // bit 21 (data 1 bit 5, dominant) between two recessive bits.
    let f = Frame::base(0x555, &[0x55; 8]);
    let e = ecc_of_cut(f, 21, 22);
    assert_eq!(e, 0x40 | 0x20 | 0x1B, "P-CAP-2: CRC error code");
}

/// A one-shot frame with no other node on line A: an ACK error as transmitter
/// (TXERR + 8). ECC (0xD9) and IR (BEI) are read while the DUT's active error
/// flag is on the line, which re-arms ECC; returns at the first clock after
/// the flag (the DUT's tx recessive again): the start of the error delimiter.
fn ack_error_to_the_delimiter(n: &mut Net) {
    let tec = n.dut.read(reg::TXERR);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x123, &[1]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    n.until(200 * BIT, |n| n.dut.read(reg::TXERR) == tec + 8);
    // Two clocks until a read sees the capture (§15).
    n.idle(2);
    assert_eq!(n.r(reg::ECC), 0xD9, "DS 6.4.9: the ACK error");
    assert_eq!(n.r(reg::IR), ir::BEI, "DS 6.4.6: BEI");
    n.until(8 * BIT, |n| !n.tx[0]);
    n.until(8 * BIT, |n| n.tx[0]);
}

/// Same (ECC segment code 10111, "error delimiter"): DS 6.4.9, P-CAP-2; ISO
/// 11898-1 (a dominant bit in the error delimiter is a form error). Another
/// node's dominant bit in the third bit of the DUT's error delimiter, after an
/// ACK error as transmitter: ERRC form (01), DIR TX (0), SEG 0x17 = 0x57, with
/// BEI and TXERR 8 + 8.
#[test]
fn ecc_form_error_in_the_error_delimiter_reads_0x17() {
    let mut n = op_single(ir::BEI, 0x00);
    ack_error_to_the_delimiter(&mut n);
    n.idle(2 * BIT);
    n.force_dom[0] = true;
    n.idle(BIT);
    n.force_dom[0] = false;
    n.until(20 * BIT, |n| n.dut.read(reg::TXERR) == 16);
    n.idle(2);
    assert_eq!(n.r(reg::IR), ir::BEI, "DS 6.4.6: BEI at the form error");
    assert_eq!(n.r(reg::ECC), 0x40 | 0x17, "DS 6.4.9: form, TX, delimiter");
}

/// Differs (ECC segment code 10011, "tolerate dominant bits"): P-CAP-2; ISO
/// 11898-1 12.1.4.2 f. After its active error flag a node tolerates 7 more
/// dominant bits: nothing is counted or captured. At the 14th dominant bit
/// from the flag's start a transmitter's TEC rises by 8, which the channel
/// counts without a bus-error event: no BEI and no ECC capture (the chip
/// captures SEG 0x13), ECC keeps the ACK error.
#[test]
fn dominant_bits_after_the_error_flag_tolerated_then_counted_without_capture() {
    let mut n = op_single(ir::BEI, 0x00);
    ack_error_to_the_delimiter(&mut n);
    n.force_dom[0] = true;
    n.idle(7 * BIT);
    n.force_dom[0] = false;
    n.idle(20 * BIT);
    assert_eq!(
        n.r(reg::TXERR),
        8,
        "ISO 12.1.4.2: 7 dominant bits tolerated"
    );
    assert_eq!(n.r(reg::IR), 0, "no bus error");
    assert_eq!(n.r(reg::ECC), 0xD9, "nothing captured after the re-arm");
    ack_error_to_the_delimiter(&mut n);
    n.force_dom[0] = true;
    n.idle(8 * BIT);
    n.force_dom[0] = false;
    n.idle(20 * BIT);
    assert_eq!(
        n.r(reg::TXERR),
        24,
        "ISO 12.1.4.2 f: ACK error + 8, 14th bit + 8"
    );
    assert_eq!(n.r(reg::IR), 0, "P-CAP-2: no BEI for rule f");
    assert_eq!(n.r(reg::ECC), 0xD9, "P-CAP-2: no capture for rule f");
}

/// Same (RXERR, TXERR read "of the channel in use"): DS 6.4.12, P-ERR-1,
/// P-LOG-1. In `single_b` TXERR is channel B's: one ACK error reads 8.
#[test]
fn txerr_reads_the_channel_in_use() {
    let p = PelicanParams {
        mode: 3,
        ..single_a(4, true)
    };
    let mut n = op_with(p, 0x00, 0x00);
    n.peer_on = [true, false];
    n.load_tx(&Frame::base(0x3F3, &[]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    assert_eq!(n.r(reg::TXERR), 8, "DS 6.4.12: channel B's TEC");
    assert_eq!(n.r(reg::RXERR), 0, "DS 6.4.11");
    assert!(n.received.is_empty(), "nothing sent on line A");
}

/// Differs (RXERR, TXERR write in reset mode: only 0 accepted; counters not
/// kept through a software reset): P-ERR-1, P-ERR-2, P-MAP-2. Reset mode
/// resets the counters (read 0); a write of 0 is accepted silently, another
/// value ignored with XIR.ign; operating-mode writes are ignored silently.
#[test]
fn rxerr_txerr_writes_and_software_reset() {
    let mut n = op_single(0x00, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x0E0, &[]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    assert_eq!(n.r(reg::TXERR), 8);
    n.w(reg::TXERR, 0x00);
    n.w(reg::RXERR, 0x20);
    assert_eq!(n.r(reg::TXERR), 8, "P-ERR-2: op write ignored");
    assert_eq!(n.r(reg::RXERR), 0);
    assert_eq!(n.r(reg::XIR), 0, "P-MAP-2: without a flag");
    n.w(reg::MOD, md::RM);
    assert_eq!(n.r(reg::TXERR), 0, "P-ERR-1: 0 in host reset mode");
    n.w(reg::TXERR, 0);
    n.w(reg::RXERR, 0);
    assert_eq!(n.r(reg::XIR), 0, "P-ERR-2: a write of 0 accepted");
    n.w(reg::TXERR, 5);
    assert_eq!(n.r(reg::XIR), xir::IGN, "P-ERR-2: TXERR 5 ignored, XIR.ign");
    n.w(reg::RXERR, 3);
    assert_eq!(n.r(reg::XIR), xir::IGN, "P-ERR-2: RXERR 3 ignored, XIR.ign");
    assert_eq!(n.r(reg::TXERR), 0);
    assert_eq!(n.r(reg::RXERR), 0);
    n.w(reg::MOD, 0x00);
    assert_eq!(n.r(reg::TXERR), 0, "P-ERR-1: the channel was reset");
}

/// Refused (TXERR write 255 forces bus-off): P-ERR-2. Ignored with XIR.ign;
/// no bus-off follows.
#[test]
fn txerr_write_255_does_not_force_bus_off() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::TXERR, 255);
    assert_eq!(n.r(reg::XIR), xir::IGN, "P-ERR-2: XIR.ign");
    n.w(reg::MOD, 0x00);
    n.idle(20 * BIT);
    assert_eq!(n.r(reg::SR) & sr::BS, 0, "no bus-off");
    assert_eq!(n.r(reg::MOD), 0x00, "RM stays 0");
    assert_eq!(n.r(reg::TXERR), 0);
}

/// Same (EWLR, default 96, reset mode only): DS 6.4.10, P-CFG-1.
#[test]
fn ewlr_default_96_writable_in_reset_mode_only() {
    let mut n = Net::keyed(single_a(4, true));
    assert_eq!(n.r(reg::EWLR), 96, "DS 6.4.10: 96 after reset");
    n.w(reg::EWLR, 200);
    assert_eq!(n.r(reg::EWLR), 200, "DS 6.4.10: written in reset mode");
    n.w(reg::MOD, 0x00);
    n.w(reg::EWLR, 10);
    assert_eq!(n.r(reg::EWLR), 200, "DS 6.4.10: read only in op");
}

/// Line A cut at the DUT: every dominant bit it sends is a bit error, up to
/// bus-off. A frame is in the RX FIFO before.
fn to_busoff(n: &mut Net) {
    peer_sends(n, 0, Frame::base(0x050, &[1]));
    assert_eq!(n.r(reg::RMC), 1);
    n.load_tx(&Frame::base(0x555, &[0xFF, 0x00]));
    n.cut[0] = true;
    n.w(reg::CMR, cmd::TR);
    n.until(3000 * BIT, |n| n.dut.read(reg::SR) & sr::BS != 0);
    n.idle(2);
}

/// Same (MOD.RM at bus-off; entering reset mode: TX aborted, FIFO cleared,
/// IR cleared but EI): DS 6.4.3 MOD.0, 6.4.5 SR.7, 6.4.12; P-BO-1, P-BO-2,
/// P-MOD-5, P-ERR-1. Then the recovery waits for RM = 0 (P-BO-3, P-BO-4), and
/// a TXERR write while held does not shorten it (refused, P-BO-5).
#[test]
fn busoff_sets_rm_and_recovery_starts_when_rm_cleared() {
    let mut n = op_single(0xFF, 0x00);
    to_busoff(&mut n);
    assert_eq!(n.r(reg::MOD), md::RM, "P-BO-1: RM set by the bus-off");
    let s = n.r(reg::SR);
    assert_eq!(
        s & !sr::ES,
        sr::BS | sr::TS | sr::RS | sr::TBS,
        "P-MOD-5: BS, message dropped (TBS, TCS 0), FIFO empty, DOS 0"
    );
    assert_eq!(n.r(reg::RMC), 0, "P-MOD-5: FIFO cleared");
    assert_eq!(n.r(reg::IR), ir::EI, "P-MOD-5 / P-BO-2: IR cleared but EI");
    assert_eq!(n.r(reg::TXERR), 127, "DS 6.4.12: 127 at bus-off");
    assert_eq!(n.r(reg::RXERR), 0, "DS 6.4.11: 0 at bus-off");
    // P-BO-3: held, the recovery does not run.
    n.cut[0] = false;
    n.idle(40 * BIT);
    assert_eq!(n.r(reg::TXERR), 127, "P-BO-3: no recovery while RM = 1");
    n.w(reg::TXERR, 0);
    assert_eq!(n.r(reg::XIR) & xir::IGN, xir::IGN, "P-BO-5: ignored");
    assert_eq!(n.r(reg::TXERR), 127, "P-BO-5: not shortened");
    // P-BO-4: RM = 0 starts the recovery, TXERR counts down (DS 6.4.12).
    n.w(reg::MOD, 0x00);
    assert_eq!(n.r(reg::MOD), 0x00);
    n.idle(15 * 11 * BIT);
    let t = n.r(reg::TXERR);
    assert!((100..=113).contains(&t), "DS 6.4.12: counts down, read {t}");
    assert_eq!(n.r(reg::SR) & sr::BS, sr::BS, "still bus-off");
}

/// Same (bus-off sets RM "only in bom mode"): P-BO-7. With
/// `pelican_busoff = "auto"` RM stays 0 while BS = 1, EI is raised.
#[test]
fn busoff_auto_mode_leaves_rm_clear() {
    let mut n = op_with(single_a(4, false), ir::EI, 0x00);
    to_busoff(&mut n);
    assert_eq!(n.r(reg::MOD), 0x00, "P-BO-7: RM not set");
    assert_eq!(n.r(reg::SR) & sr::BS, sr::BS, "SR.BS");
    assert_eq!(n.r(reg::IR) & ir::EI, ir::EI, "EI at the bus-off");
}
