//! The logical controller (§5, P-LOG-1..4) where it differs from one SJA1000
//! by having two channels: the captures and counters come from the channel in
//! use, and bus-off (DS 6.4.3 MOD.0, 6.4.5 SR.7) is the logical controller's,
//! set only when no channel is left (P-LOG-3, P-BO-1).

use super::*;

/// Same (DS 6.4.8 ALC, 6.4.9 ECC, 6.4.6 ALI / BEI) with channel B in use
/// (`XMODE.mode = SINGLE_B`, P-LOG-1, P-LOG-4): a lost arbitration and an ACK
/// error on line B are captured and interrupt as on line A.
#[test]
fn ali_bei_alc_ecc_from_channel_b_in_use() {
    let p = PelicanParams {
        mode: 3,
        ..single_a(4, true)
    };
    let mut n = op_with(p, ir::ALI | ir::BEI, 0x00);
    // 0x7F0 against 0x7E0: lost at the 7th identifier bit, code 6 (DS 6.4.8).
    n.load_tx(&Frame::base(0x7F0, &[]));
    n.peer_req[1] = Some(Frame::base(0x7E0, &[]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    n.until(300 * BIT, |n| {
        n.peer_req[1].is_none() && !n.peer_out[1].tx_pending
    });
    n.idle(4);
    assert_eq!(n.r(reg::IR), ir::ALI, "DS 6.4.6: ALI from B");
    assert_eq!(n.r(reg::ALC), 6, "DS 6.4.8: B's loss at ID.22");
    // No peer acknowledges: an ACK error as transmitter, 0xD9 (P-CAP-2).
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x123, &[1]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    assert_eq!(n.r(reg::IR), ir::BEI, "DS 6.4.6: BEI from B");
    assert_eq!(n.r(reg::ECC), 0xD9, "DS 6.4.9: B's ACK error");
    assert_eq!(n.r(reg::TXERR), 8, "DS 6.4.12: B's TEC after one ACK error");
}

/// Differs (DS 6.4.3: a bus-off sets MOD.RM): with redundancy the logical
/// controller is bus-off only when no channel is left (P-LOG-3, P-BO-1). Line
/// A cut: the message goes out on B (`TCS`), `RM` and `BS` stay 0, and
/// `TXERR` is B's. Both lines cut: the channel in use goes bus-off with the
/// other not valid, and then `BS`, `RM` and `EI` are set as on the chip.
#[test]
fn busoff_in_redundancy_sets_rm_only_when_no_channel_is_left() {
    let mut n = op_with(PelicanParams::default(), ir::EI, 0x00);
    n.cut[0] = true;
    n.load_tx(&Frame::base(0x555, &[0xFF, 0x00]));
    n.w(reg::CMR, cmd::TR);
    wait_tbs(&mut n, 3000);
    assert_eq!(n.r(reg::SR) & sr::TCS, sr::TCS, "delivered on B");
    assert_eq!(n.r(reg::MOD) & md::RM, 0, "P-LOG-3: one line is no bus-off");
    assert_eq!(n.r(reg::SR) & sr::BS, 0, "P-LOG-4: BS = lbo = 0");
    assert_eq!(n.r(reg::XSTAT) & 1, 1, "§13: XSTAT.u = B");
    assert_eq!(n.r(reg::TXERR), 0, "P-LOG-4: TXERR is B's, error free");
    n.r(reg::IR);
    n.cut[1] = true;
    n.load_tx(&Frame::base(0x556, &[0x0F]));
    n.w(reg::CMR, cmd::TR);
    n.until(8000 * BIT, |n| n.dut.read(reg::SR) & sr::BS != 0);
    n.idle(2);
    assert_eq!(
        n.r(reg::MOD) & md::RM,
        md::RM,
        "P-BO-1: RM at the logical bus-off"
    );
    assert_eq!(n.r(reg::IR) & ir::EI, ir::EI, "DS 6.4.6: EI at the bus-off");
    assert_eq!(n.r(reg::XSTAT) & 1, 1, "P-LOG-1: u kept on B in the hold");
    assert_eq!(n.r(reg::TXERR), 127, "DS 6.4.12: 127 at bus-off");
    // P-BO-3: held; the main FSM idles on A meanwhile, BS and TXERR stay B's.
    n.idle(200 * BIT);
    assert_eq!(
        n.r(reg::SR) & sr::BS,
        sr::BS,
        "P-LOG-3: BS through the hold"
    );
    assert_eq!(n.r(reg::TXERR), 127, "P-LOG-4: TXERR of the held channel");
    // Line A repaired; the host restarts (Linux: MOD = 0): A is valid again,
    // so the logical bus-off ends at once with EI (P-LOG-3, P-IR-5).
    n.cut[0] = false;
    n.idle(1200 * BIT);
    n.r(reg::IR);
    n.w(reg::MOD, 0x00);
    n.idle(4);
    assert_eq!(
        n.r(reg::SR) & sr::BS,
        0,
        "P-LOG-3: A carries the controller"
    );
    assert_eq!(n.r(reg::IR) & ir::EI, ir::EI, "P-IR-5: EI at the BS fall");
}

/// Differs (IR.EPI, "raised when the channel in use changes to a passive
/// one"): P-IR-6, P-LOG-4, P-LOG-5, with either `pelican_report`. Redundancy
/// with the k-failed policy, k = 1 (§D5: an error-passive channel stays
/// valid). Line B is held dominant until its receive errors make it error
/// passive (REC >= 128, ISO 11898-1 12.1.4.2 b, f); then line A is cut under
/// a transmission: the first failed attempt fails A and the DRCC moves the
/// message to B. The logical controller goes from A (error active, below the
/// warning limit) to B (error passive, REC >= 96): `EPI` and `EI` (`ES`
/// rises) together, and the message is delivered on B.
#[test]
fn epi_when_the_channel_in_use_changes_to_a_passive_one() {
    for report_best in [false, true] {
        let p = PelicanParams {
            policy: 2,
            k: 1,
            report_best,
            ..PelicanParams::default()
        };
        let mut n = op_with(p, ir::EI | ir::EPI, 0x00);
        n.force_dom[1] = true;
        n.until(400 * BIT, |n| n.dut.read(reg::XERR) & 0x0C == 0x04);
        n.force_dom[1] = false;
        n.idle(30 * BIT);
        assert_eq!(n.r(reg::XERR) & 0x0C, 0x04, "§13: B error passive");
        assert_eq!(n.r(reg::XSTAT) & 0x31, 0x00, "§13: A in use, B's aux valid");
        assert_eq!(n.r(reg::IR), 0, "B's state is not the controller's");
        n.cut[0] = true;
        n.load_tx(&Frame::base(0x2A5, &[0x11]));
        n.w(reg::CMR, cmd::TR);
        n.until(100 * BIT, |n| n.dut.u() == 1);
        n.idle(3);
        assert_eq!(
            n.r(reg::IR),
            ir::EI | ir::EPI,
            "P-IR-6: EPI at the switch to a passive channel (rep {report_best})"
        );
        let s = n.r(reg::SR);
        assert_eq!(s & (sr::ES | sr::BS), sr::ES, "P-LOG-4: B's ES");
        wait_tbs(&mut n, 400);
        assert_eq!(n.r(reg::SR) & sr::TCS, sr::TCS, "sent on B");
    }
}
