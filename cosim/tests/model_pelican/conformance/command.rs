//! CMR (DS 6.4.4; §6, P-CMR-1..3, P-TX-2..7): reads 0, TR / AT / SRR ignored
//! in reset mode, TR starts a transmission and locks the buffer, AT aborts
//! (single modes) or is ignored with XIR.ign (redundancy), TR + AT one-shot
//! (single modes) or retried with XIR.ign (redundancy), SRR self-reception at
//! the successful end (differs). RRB and CDO are in `buffers`.

use super::*;
use drcc_cosim::Frame;

/// DS 6.4.4 / P-MAP-1: CMR reads 0x00 in both modes, also after a write.
#[test]
fn cmr_reads_zero() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::CMR, 0xFF);
    assert_eq!(n.r(reg::CMR), 0, "DS 6.4.4: CMR reads 0 (rm)");
    n.w(reg::MOD, 0x00);
    n.idle(12 * BIT);
    n.load_tx(&Frame::base(0x100, &[]));
    n.w(reg::CMR, cmd::TR);
    assert_eq!(n.r(reg::CMR), 0, "DS 6.4.4: CMR reads 0 (op)");
}

/// DS 6.4.4 / §6: in reset mode TR, AT and SRR are ignored: TBS stays 1 and
/// nothing is sent after reset mode ends.
#[test]
fn cmr_tr_at_srr_ignored_in_reset_mode() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::TXB, 0x01);
    n.w(reg::TXB + 1, 0x24);
    for c in [cmd::TR, cmd::SRR, cmd::TR | cmd::AT, cmd::AT] {
        n.w(reg::CMR, c);
        assert_eq!(n.r(reg::SR), 0x3C, "§6: CMR {c:#x} ignored in reset mode");
    }
    n.w(reg::MOD, 0x00);
    n.idle(100 * BIT);
    assert_eq!(n.r(reg::SR) & sr::TBS, sr::TBS, "no message pending");
    assert!(n.received.is_empty(), "§6: nothing sent");
}

/// DS 6.4.4 CMR.0, 6.4.5 SR.2 / SR.3 (P-CMR-1, P-TX-2, P-TX-7): TR starts the
/// transmission, TBS and TCS fall at once and rise at the successful end with
/// TI; the other node receives the frame.
#[test]
fn cmr_tr_transmits_tbs_tcs_and_ti() {
    let mut n = op_single(ir::TI, 0x00);
    let f = Frame::base(0x4B1, &[1, 2, 3]);
    n.load_tx(&f);
    assert_eq!(n.r(reg::SR) & (sr::TBS | sr::TCS), sr::TBS | sr::TCS);
    n.w(reg::CMR, cmd::TR);
    let s = n.r(reg::SR);
    assert_eq!(s & (sr::TBS | sr::TCS), 0, "DS 6.4.5: TBS, TCS 0 after TR");
    assert_eq!(n.r(reg::IR) & ir::TI, 0, "no TI before the end");
    wait_tbs(&mut n, 200);
    assert_eq!(n.r(reg::SR) & sr::TCS, sr::TCS, "DS 6.4.5: TCS at success");
    assert_eq!(n.r(reg::IR), ir::TI, "DS 6.4.6: TI");
    assert_eq!(n.received, vec![(0, f)], "the frame was sent");
}

/// DS 6.4.4 / 6.4.13, P-CMR-1, P-TX-1: while TBS = 0 a second TR is ignored
/// and the TX buffer is locked (a write is lost); one frame is sent, as
/// written before the first TR.
#[test]
fn cmr_tr_ignored_and_buffer_locked_while_tbs_zero() {
    let mut n = op_single(0x00, 0x00);
    let f = Frame::base(0x0A5, &[0x5A]);
    n.load_tx(&f);
    n.w(reg::CMR, cmd::TR);
    n.w(reg::WIN + 3, 0xEE);
    n.w(reg::CMR, cmd::TR);
    assert_eq!(n.r(reg::TXB + 3), 0x5A, "DS 6.4.13: buffer locked");
    wait_tbs(&mut n, 200);
    n.idle(100 * BIT);
    assert_eq!(n.received, vec![(0, f)], "P-CMR-1: one frame, as written");
}

/// Differs (CMR.AT, single modes: same as DS 6.4.4): P-TX-3. AT alone while a
/// message is pending ends it: TBS = 1, TCS = 0, TI, and no further attempt.
#[test]
fn cmr_at_aborts_pending_message_in_single_mode() {
    let mut n = op_single(ir::TI, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x0C3, &[]));
    n.w(reg::CMR, cmd::TR);
    n.until(400 * BIT, |n| n.dut.read(reg::TXERR) >= 16);
    n.w(reg::CMR, cmd::AT);
    wait_tbs(&mut n, 100);
    assert_eq!(n.r(reg::SR) & sr::TCS, 0, "P-TX-7: TCS 0 after an abort");
    assert_eq!(n.r(reg::IR), ir::TI, "P-TX-7: TI");
    let tec = n.r(reg::TXERR);
    n.idle(100 * BIT);
    assert_eq!(n.r(reg::TXERR), tec, "P-TX-3: no attempt after the abort");
}

/// Differs (CMR.AT, redundancy): P-TX-3. AT is ignored with XIR.ign; the
/// message completes successfully.
#[test]
fn cmr_at_ignored_in_redundancy_with_xir_ign() {
    let mut n = op_with(PelicanParams::default(), 0x00, 0x00);
    n.load_tx(&Frame::base(0x155, &[1]));
    n.w(reg::CMR, cmd::TR);
    n.w(reg::CMR, cmd::AT);
    assert_eq!(n.r(reg::XIR), xir::IGN, "P-TX-3: XIR.ign");
    wait_tbs(&mut n, 400);
    assert_eq!(n.r(reg::SR) & sr::TCS, sr::TCS, "P-TX-3: not aborted");
}

/// Differs (CMR.TR + AT single shot, single modes: same as DS 6.4.4):
/// P-CMR-2, P-TX-4. Without ACK the message is tried once: TBS = 1, TCS = 0,
/// TXERR = 8 and stays 8.
#[test]
fn cmr_tr_at_single_shot_in_single_mode() {
    let mut n = op_single(ir::TI, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x123, &[1]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    assert_eq!(n.r(reg::SR) & sr::TCS, 0, "P-TX-7: TCS 0");
    assert_eq!(n.r(reg::IR), ir::TI, "P-TX-7: TI");
    assert_eq!(n.r(reg::TXERR), 8, "one ACK error");
    assert_eq!(n.r(reg::XIR), 0, "P-TX-4: no XIR.ign in single mode");
    n.idle(100 * BIT);
    assert_eq!(n.r(reg::TXERR), 8, "P-TX-4: no retransmission");
}

/// Differs (CMR.TR + AT, redundancy): P-TX-4. The one-shot is ignored with
/// XIR.ign: the message is retried (TBS stays 0) until reset mode ends it.
#[test]
fn cmr_tr_at_retried_in_redundancy_with_xir_ign() {
    let mut n = op_with(PelicanParams::default(), 0x00, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x321, &[]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    assert_eq!(n.r(reg::XIR), xir::IGN, "P-TX-4: XIR.ign at the TR edge");
    n.idle(200 * BIT);
    assert_eq!(n.r(reg::SR) & sr::TBS, 0, "P-TX-7: still pending");
    assert!(n.r(reg::TXERR) >= 16, "P-TX-4: retried");
    n.w(reg::MOD, md::RM);
    assert_eq!(n.r(reg::SR) & (sr::TBS | sr::TCS), sr::TBS, "P-MOD-5");
}

/// Differs (CMR.SRR: own frame stored when the transmission succeeds, not at
/// EOF bit 6): P-TX-5. The frame is sent, and enters the RX FIFO with RI in
/// the clock of TI or later; TR alone stores nothing (P-CMR-2).
#[test]
fn cmr_srr_self_reception_when_the_transmission_succeeds() {
    let mut n = op_single(ir::RI | ir::TI, 0x00);
    let f = ext(0x00AB_CDEF, &[9, 8]);
    n.load_tx(&f);
    n.w(reg::CMR, cmd::SRR);
    let (mut ti_at, mut ri_at) = (None, None);
    n.until(400 * BIT, |n| {
        let i = n.dut.read(reg::IR);
        if i & ir::TI != 0 && ti_at.is_none() {
            ti_at = Some(n.clock);
        }
        if i & ir::RI != 0 && ri_at.is_none() {
            ri_at = Some(n.clock);
        }
        ti_at.is_some() && ri_at.is_some()
    });
    assert!(ri_at >= ti_at, "P-TX-5: RI with TI or later");
    assert_eq!(n.received, vec![(0, f)], "P-TX-5: the frame was sent");
    assert_eq!(n.r(reg::SR) & sr::TCS, sr::TCS);
    assert_eq!(n.r(reg::RMC), 1, "P-TX-5: own frame stored");
    assert_eq!(n.read_rx(), f, "P-TX-5: as transmitted");
    n.w(reg::CMR, cmd::RRB);
    n.w(reg::CMR, cmd::TR);
    wait_tbs(&mut n, 400);
    n.idle(4);
    assert_eq!(n.r(reg::RMC), 0, "P-CMR-2: TR alone is not self-received");
}
