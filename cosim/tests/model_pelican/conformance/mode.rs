//! MOD (DS 6.4.3; P-MOD-1..7, P-CFG-3, P-TX-6): RM at hardware reset and by
//! the host, LOM / STM / AFM writable in reset mode only, listen-only (single
//! and redundancy), self test, sleep mode refused; and the common registers
//! of DS 6.5: the bit timing of BTR0 / BTR1 (P-CFG-2, differs below 8 tq),
//! OCR and CDR (refused: stored, no effect; P-CFG-4, P-CFG-5), BasicCAN
//! (refused).

use super::*;
use drcc_cosim::{Frame, Mode};

/// DS 6.4.2 / 6.4.3, P-MOD-1, §16: `rst` sets RM and clears LOM, STM, AFM
/// and the registers with a reset value, also in the middle of operation.
#[test]
fn mod_rm_set_at_hardware_reset() {
    let mut n = Net::keyed(single_a(4, true));
    assert_eq!(n.r(reg::MOD), md::RM, "DS 6.4.2: MOD = 0x01 after reset");
    n.w(reg::MOD, md::RM | md::LOM | md::STM | md::AFM);
    n.w(reg::BTR0, 0x01);
    n.w(reg::MOD, md::LOM | md::STM | md::AFM);
    n.w(reg::IER, 0xFF);
    assert_eq!(n.r(reg::MOD), 0x0E);
    hardware_reset(&mut n);
    assert_eq!(n.r(reg::MOD), md::RM, "DS 6.4.2: RM set, LOM/STM/AFM 0");
    assert_eq!(n.r(reg::IER), 0, "§16: IER 0");
    assert_eq!(n.r(reg::BTR0), 0, "§16: BTR0 0");
    assert_eq!(n.r(reg::SR), 0x3C, "DS 6.4.2: SR 0x3C");
}

/// DS 6.4.3 MOD.0, P-MOD-2 / P-MOD-3: a MOD write with RM = 0 leaves reset
/// mode, with RM = 1 enters it, in both directions on the next access.
#[test]
fn mod_rm_host_write_enters_and_leaves_reset_mode() {
    let mut n = Net::keyed(single_a(4, true));
    n.peer_on = [false, false];
    n.w(reg::MOD, 0x00);
    assert_eq!(n.r(reg::MOD), 0x00, "P-MOD-3: RM cleared");
    n.idle(12 * BIT);
    assert_eq!(
        n.r(reg::SR) & (sr::RS | sr::TS),
        0,
        "P-SR-1: RS = TS = 0 idle"
    );
    n.w(reg::MOD, md::RM);
    assert_eq!(n.r(reg::MOD), md::RM, "P-MOD-2: RM set in operating mode");
    assert_eq!(n.r(reg::SR), 0x3C, "P-SR-1: RS = TS = 1 in reset mode");
    n.w(reg::MOD, md::RM);
    assert_eq!(n.r(reg::MOD), md::RM, "RM = 1 in reset mode stays");
}

/// DS 6.4.3 ("writable in reset mode only"), P-MOD-2: LOM, STM, AFM are taken
/// by a write while RM = 1 (also the one that clears RM), never by an
/// operating-mode write, which takes RM only.
#[test]
fn mod_lom_stm_afm_writable_in_reset_mode_only() {
    let mut n = Net::keyed(single_a(4, true));
    n.peer_on = [false, false];
    n.w(reg::MOD, 0x0F);
    assert_eq!(n.r(reg::MOD), 0x0F, "P-MOD-2: taken in reset mode");
    n.w(reg::MOD, 0x0A);
    assert_eq!(
        n.r(reg::MOD),
        0x0A,
        "P-MOD-2: taken by the write clearing RM"
    );
    n.w(reg::MOD, 0x04);
    assert_eq!(n.r(reg::MOD), 0x0A, "P-MOD-2: op write takes RM only");
    n.w(reg::MOD, 0x05);
    assert_eq!(n.r(reg::MOD), 0x0B, "P-MOD-2: RM set, bits kept");
    n.w(reg::MOD, 0x01);
    assert_eq!(n.r(reg::MOD), 0x01, "P-MOD-2: cleared in reset mode");
}

/// Refused: P-MOD-7 (DS 6.4.3 MOD.4 SM, 6.4.6 IR.4 WUI). SM is never set
/// (reads 0), a write with SM = 1 sets XIR.ign in both modes, and WUI is never
/// set, even with WUIE and bus activity.
#[test]
fn mod_sm_refused_reads_zero_wui_never_set() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::MOD, md::SM | md::RM);
    assert_eq!(n.r(reg::MOD), md::RM, "P-MOD-7: SM reads 0 (rm)");
    assert_eq!(n.r(reg::XIR), xir::IGN, "P-MOD-7: XIR.ign (rm)");
    n.w(reg::IER, 0xFF);
    n.w(reg::MOD, 0x00);
    n.idle(12 * BIT);
    n.w(reg::MOD, md::SM);
    assert_eq!(n.r(reg::MOD), 0x00, "P-MOD-7: SM reads 0 (op)");
    assert_eq!(n.r(reg::XIR), xir::IGN, "P-MOD-7: XIR.ign (op)");
    peer_sends(&mut n, 0, Frame::base(0x111, &[1]));
    let ir_ = n.r(reg::IR);
    assert_eq!(ir_ & ir::RI, ir::RI, "the frame arrived");
    assert_eq!(ir_ & ir::WUI, 0, "P-MOD-7: WUI never set");
}

/// Tracks the DUT's TX pins for `clocks`; returns whether either went dominant.
fn sent_dominant(n: &mut Net, clocks: u64) -> bool {
    let mut any = false;
    for _ in 0..clocks {
        n.idle(1);
        any |= !n.out.chan_a_tx || !n.out.chan_b_tx;
    }
    any
}

/// DS 6.4.3 MOD.1 LOM (same), P-CFG-3: frames are received, no ACK, no error
/// flag (the TX pin never goes dominant) and the counters are frozen.
#[test]
fn mod_lom_listen_only_no_ack_no_flags_counters_frozen() {
    let mut n = op_single(ir::RI, md::LOM);
    // A node in self test needs no ACK: its frame completes, the DUT stores it.
    n.reset_peers(Mode::SelfTest);
    n.idle(12 * BIT);
    n.peer_req[0] = Some(Frame::base(0x3A5, &[1, 2]));
    assert!(!sent_dominant(&mut n, 120 * BIT), "LOM: no ACK");
    assert_eq!(n.r(reg::RMC), 1, "LOM: the frame is received");
    assert_eq!(n.read_rx(), Frame::base(0x3A5, &[1, 2]));
    // A normal node gets no ACK: it detects an ACK error and flags it; the
    // DUT sees the error (form error at the ACK delimiter) and neither flags
    // it nor counts it.
    n.reset_peers(Mode::Normal);
    n.idle(12 * BIT);
    n.peer_req[0] = Some(Frame::base(0x3A6, &[3]));
    assert!(
        !sent_dominant(&mut n, 200 * BIT),
        "LOM: no ACK, no error flag"
    );
    assert!(n.peer_out[0].probes.tec > 0, "the peer saw ACK errors");
    assert_eq!(n.r(reg::RXERR), 0, "DS 6.4.3: counters frozen");
    assert_eq!(n.r(reg::TXERR), 0);
}

/// P-TX-6 (LOM row: "a TR completes at once with TCS = 0 and TI"): nothing is
/// sent.
#[test]
fn mod_lom_tr_completes_at_once_tcs_zero_with_ti() {
    let mut n = op_single(ir::TI, md::LOM);
    n.load_tx(&Frame::base(0x0F0, &[0x11]));
    n.w(reg::CMR, cmd::TR);
    let s = n.r(reg::SR);
    assert_eq!(s & (sr::TBS | sr::TCS), sr::TBS, "P-TX-6: TBS 1, TCS 0");
    assert_eq!(n.r(reg::IR), ir::TI, "P-TX-6: TI");
    assert!(!sent_dominant(&mut n, 80 * BIT), "P-TX-6: nothing sent");
    assert!(n.received.is_empty());
}

/// P-CFG-3 (LOM row, redundancy: "both channels listen"): both channels
/// receive, neither sends.
#[test]
fn mod_lom_in_redundancy_both_channels_listen() {
    let mut n = op_with(PelicanParams::default(), 0x00, md::LOM);
    n.reset_peers(Mode::SelfTest);
    n.idle(12 * BIT);
    n.peer_req = [
        Some(Frame::base(0x101, &[0xA])),
        Some(Frame::base(0x202, &[0xB])),
    ];
    assert!(
        !sent_dominant(&mut n, 120 * BIT),
        "P-CFG-3: no ACK on A or B"
    );
    assert_eq!(n.r(reg::RMC), 2, "P-CFG-3: both channels receive");
}

/// DS 6.4.3 MOD.2 STM (same), P-CFG-3: a transmission succeeds without ACK.
#[test]
fn mod_stm_self_test_needs_no_ack() {
    let mut n = Net::keyed(single_a(4, true));
    n.peer_on = [false, false];
    n.linux_start(0x00, md::STM);
    assert_eq!(n.r(reg::MOD), md::STM);
    n.load_tx(&Frame::base(0x246, &[7]));
    n.w(reg::CMR, cmd::TR);
    let mut sent = false;
    n.until(200 * BIT, |n| {
        sent |= !n.out.chan_a_tx;
        n.dut.read(reg::SR) & sr::TBS != 0
    });
    n.idle(2);
    assert!(sent, "the frame went on the bus");
    assert_eq!(n.r(reg::SR) & sr::TCS, sr::TCS, "STM: success without ACK");
    assert_eq!(n.r(reg::TXERR), 0, "STM: no ACK error counted");
}

/// Clocks of the recessive run that follows SOF of a frame with id 0x7FF
/// (ID.10..ID.6, five bits, before the first stuff bit), after leaving reset
/// mode with `btr0`, `btr1`.
fn five_bits(btr0: u8, btr1: u8) -> u64 {
    let mut n = Net::keyed(single_a(4, true));
    n.peer_on = [false, false];
    n.w(reg::BTR0, btr0);
    n.w(reg::BTR1, btr1);
    n.w(reg::MOD, 0x00);
    n.load_tx(&Frame::base(0x7FF, &[]));
    n.w(reg::CMR, cmd::TR);
    n.until(2000 * BIT, |n| !n.out.chan_a_tx);
    n.until(200 * BIT, |n| n.out.chan_a_tx);
    n.until(200 * BIT, |n| !n.out.chan_a_tx)
}

/// Same (DS 6.5.1 BTR0, 6.5.2 BTR1; P-CFG-2): tq = 2 x (BRP + 1) clocks, a
/// bit = tq x (1 + (TSEG1 + 1) + (TSEG2 + 1)).
#[test]
fn btr0_btr1_set_time_quantum_and_segments() {
    for (btr0, btr1) in [(0x00u8, 0x14u8), (0x01, 0x14), (0x00, 0x2F), (0xC2, 0x23)] {
        let tq = 2 * ((btr0 & 0x3F) as u64 + 1);
        let bit = tq * (3 + (btr1 & 0x0F) as u64 + ((btr1 >> 4) & 7) as u64);
        assert_eq!(
            five_bits(btr0, btr1),
            5 * bit,
            "DS 6.5: five bits with BTR0 {btr0:#04x}, BTR1 {btr1:#04x}"
        );
    }
}

/// Differs (bit timing with fewer than 8 tq): P-CFG-2 / timing contract §6.
/// BTR1 = 0x00 (3 tq on the SJA1000) is lengthened to 8 tq.
#[test]
fn btr_below_8_tq_lengthened_to_8_tq() {
    assert_eq!(five_bits(0x00, 0x00), 5 * 16, "8 tq of 2 clocks");
    assert_eq!(five_bits(0x01, 0x11), 5 * 32, "6 tq lengthened, 4 clocks");
}

/// Refused (DS 6.5: OCR output modes): P-CFG-4. OCR is stored and read back,
/// written in reset mode only, and has no effect: the TX pin idles recessive
/// (1) and a frame is sent at logic level whatever OCR holds.
#[test]
fn ocr_stored_read_back_no_effect() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::OCR, 0xFF);
    assert_eq!(n.r(reg::OCR), 0xFF, "P-CFG-4: stored");
    n.w(reg::MOD, 0x00);
    n.w(reg::OCR, 0x02);
    assert_eq!(n.r(reg::OCR), 0xFF, "P-CFG-1: OCR reset mode only");
    n.idle(20 * BIT);
    assert!(n.out.chan_a_tx, "P-CFG-4: TXD idles recessive (1)");
    let f = Frame::base(0x2C3, &[0x5A]);
    n.load_tx(&f);
    n.w(reg::CMR, cmd::TR);
    wait_tbs(&mut n, 200);
    assert_eq!(n.received, vec![(0, f)], "P-CFG-4: sent at logic level");
}

/// P-CFG-5 (DS 6.5 CDR): CD [2:0] writable in both modes, the other bits in
/// reset mode only, all stored and read back (CDR.7 reads back: Linux tests
/// it); bit 4 is not defined and reads 0.
#[test]
fn cdr_bits_stored_cd_writable_in_both_modes() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::CDR, 0xFF);
    assert_eq!(n.r(reg::CDR), 0xEF, "P-CFG-5: all defined bits stored");
    n.w(reg::CDR, 0x80);
    assert_eq!(n.r(reg::CDR), 0x80, "P-CFG-5: CDR.7 reads back");
    n.w(reg::MOD, 0x00);
    n.w(reg::CDR, 0x6D);
    assert_eq!(n.r(reg::CDR), 0x85, "P-CFG-5: only CD taken in op");
}

/// Refused (DS 6.3: BasicCAN): P-CFG-5. With CDR.7 = 0 the layout stays
/// PeliCAN: MOD, IER at 4, EWLR at 13, ACR/AMR at 16..23, RMC, TXB at 96.
#[test]
fn basiccan_refused_layout_stays_pelican() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::CDR, 0x00);
    assert_eq!(n.r(reg::CDR), 0x00);
    n.w(reg::IER, 0x55);
    n.w(reg::WIN, 0x12);
    n.w(reg::WIN + 4, 0x34);
    n.w(reg::TXB, 0x56);
    n.w(reg::MOD, md::RM | md::AFM);
    assert_eq!(n.r(reg::MOD), 0x09, "PeliCAN MOD at 0");
    assert_eq!(n.r(reg::IER), 0x55, "PeliCAN IER at 4");
    assert_eq!(n.r(reg::EWLR), 96, "PeliCAN EWLR at 13");
    assert_eq!(n.r(reg::WIN), 0x12, "ACR0 at 16");
    assert_eq!(n.r(reg::WIN + 4), 0x34, "AMR0 at 20");
    assert_eq!(n.r(reg::TXB), 0x56, "TXB at 96");
    assert_eq!(n.r(112), 0x44, "XID0");
}
