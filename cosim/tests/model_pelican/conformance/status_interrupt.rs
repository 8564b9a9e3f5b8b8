//! SR, IR, IER and `irq` (DS 6.4.5 .. 6.4.7; P-SR-1, P-IER-1, P-IR-1..6,
//! P-IRQ-1): RS / TS, RBS, TBS, ES (EWLR), the read-clear of IR except RI, RI
//! as a level, TI at a TBS rise only, EI on every ES change, EPI reached and
//! left (and the switchover difference), IER gating every source, `irq`
//! active high (differs). DOS / DOI are in `buffers`, ALI / BEI in `capture`,
//! BS in `capture` (bus-off).

use super::*;
use drcc_cosim::Frame;

/// DS 6.4.2, 6.4.5 (same; P-SR-1): SR = 0x3C in reset mode (RS = TS = 1),
/// 0x0C on an idle bus in operating mode.
#[test]
fn sr_reads_0x3c_in_reset_mode_0x0c_idle() {
    let mut n = op_single(0x00, 0x00);
    assert_eq!(n.r(reg::SR), 0x0C, "P-SR-1: TBS, TCS; bus idle");
    n.w(reg::MOD, md::RM);
    assert_eq!(n.r(reg::SR), 0x3C, "P-SR-1: RS = TS = 1 in reset mode");
}

/// DS 6.4.5, SR note 3 ("If both bits are set the controller is waiting to
/// become idle again. After a hardware reset 11 consecutive recessive bits
/// have to be detected until the idle status is reached"): after reset mode
/// ends, RS = TS = 1 until the bus integration is done, then 0.
#[test]
fn sr_rs_ts_set_while_waiting_for_bus_idle() {
    let mut n = Net::keyed(single_a(4, true));
    n.peer_on = [false, false];
    n.w(reg::MOD, 0x00);
    let s = n.r(reg::SR);
    assert_eq!(s & (sr::RS | sr::TS), sr::RS | sr::TS, "DS 6.4.5 note 3");
    n.idle(12 * BIT);
    assert_eq!(n.r(reg::SR) & (sr::RS | sr::TS), 0, "idle reached");
}

/// DS 6.4.5 SR.4 RS, SR.5 TS (same; P-SR-1): TS (not RS) while the DUT
/// transmits, RS (not TS) while it receives, both 0 after.
#[test]
fn sr_ts_while_transmitting_rs_while_receiving() {
    let mut n = op_single(0x00, 0x00);
    n.load_tx(&Frame::base(0x1F0, &[1, 2, 3, 4]));
    n.w(reg::CMR, cmd::TR);
    let mut s = 0;
    n.until(100 * BIT, |n| {
        s = n.r(reg::SR);
        s & sr::TS != 0
    });
    assert_eq!(s & sr::RS, 0, "P-SR-1: RS = 0 while transmitting");
    wait_tbs(&mut n, 200);
    n.idle(4 * BIT);
    assert_eq!(n.r(reg::SR) & (sr::RS | sr::TS), 0, "idle after the frame");
    n.peer_req[0] = Some(Frame::base(0x0F1, &[5, 6, 7, 8]));
    n.until(100 * BIT, |n| {
        s = n.r(reg::SR);
        s & sr::RS != 0
    });
    assert_eq!(s & sr::TS, 0, "P-SR-1: TS = 0 while receiving");
    n.until(200 * BIT, |n| {
        n.peer_req[0].is_none() && !n.peer_out[0].tx_pending
    });
    n.idle(4 * BIT);
    assert_eq!(n.r(reg::SR) & (sr::RS | sr::TS), 0, "idle after the frame");
}

/// DS 6.4.5 SR.0 RBS, 6.4.6 IR.0 RI (same; P-SR-1, P-IR-2): RBS while the
/// FIFO holds a message; RI = RIE && RBS, a level a read does not clear,
/// raised by a later RIE write too.
#[test]
fn sr_rbs_and_ir_ri_level_while_fifo_not_empty() {
    let mut n = op_single(0x00, 0x00);
    assert_eq!(n.r(reg::SR) & sr::RBS, 0);
    peer_sends(&mut n, 0, Frame::base(0x010, &[1]));
    peer_sends(&mut n, 0, Frame::base(0x020, &[2]));
    assert_eq!(n.r(reg::SR) & sr::RBS, sr::RBS, "DS 6.4.5: RBS");
    assert_eq!(n.r(reg::IR), 0, "P-IR-2: no RI without RIE");
    n.w(reg::IER, ir::RI);
    assert_eq!(n.r(reg::IR), ir::RI, "P-IR-2: RI = RIE && RBS");
    assert_eq!(n.r(reg::IR), ir::RI, "P-IR-3: a read does not clear RI");
    n.w(reg::CMR, cmd::RRB);
    assert_eq!(n.r(reg::SR) & sr::RBS, sr::RBS, "one message left");
    assert_eq!(n.r(reg::IR), ir::RI);
    n.w(reg::CMR, cmd::RRB);
    assert_eq!(n.r(reg::SR) & sr::RBS, 0, "DS 6.4.5: RBS 0, FIFO empty");
    assert_eq!(n.r(reg::IR), 0, "P-IR-2: RI falls with RBS");
}

/// DS 6.4.5 SR.6 ES, 6.4.10 EWLR, 6.4.6 IR.2 EI (same; P-ERR-3, P-IR-5):
/// ES when a counter reaches EWLR; EI when ES rises and when it falls.
#[test]
fn sr_es_at_ewlr_and_ei_on_every_change() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::EWLR, 8);
    n.linux_start(ir::EI, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x2E0, &[]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    assert_eq!(n.r(reg::TXERR), 8);
    assert_eq!(n.r(reg::SR) & sr::ES, sr::ES, "DS 6.4.5: TEC 8 >= EWLR 8");
    assert_eq!(n.r(reg::IR), ir::EI, "DS 6.4.6: EI at the ES rise");
    assert_eq!(n.r(reg::IR), 0, "P-IR-3: EI cleared by the read");
    n.peer_on = [true, true];
    n.w(reg::CMR, cmd::TR);
    wait_tbs(&mut n, 200);
    assert_eq!(n.r(reg::TXERR), 7, "a success counts down");
    assert_eq!(n.r(reg::SR) & sr::ES, 0, "DS 6.4.5: TEC 7 < EWLR 8");
    assert_eq!(n.r(reg::IR), ir::EI, "DS 6.4.6: EI at the ES fall");
}

/// DS 6.4.6 (same; P-IR-3): a read of IR clears TI, BEI (and every bit) but
/// RI.
#[test]
fn ir_read_clears_all_but_ri() {
    let mut n = op_single(ir::RI | ir::TI | ir::BEI, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x300, &[]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    wait_tbs(&mut n, 200);
    n.peer_on = [true, true];
    peer_sends(&mut n, 0, Frame::base(0x301, &[]));
    assert_eq!(n.r(reg::IR), ir::RI | ir::TI | ir::BEI, "DS 6.4.6");
    assert_eq!(n.r(reg::IR), ir::RI, "P-IR-3: all cleared but RI");
}

/// DS 6.4.7 IER (same: "IR bits set only while their IER bit is set";
/// P-IR-2, P-IRQ-1): with IER = 0 the events of a failed one-shot (TI, BEI,
/// EI) set nothing and `irq` stays 0; enabling afterwards raises no past
/// event; with RIE | EIE only, a success raises EI but not TI.
#[test]
fn ier_gates_every_source_and_a_late_enable_raises_nothing() {
    let mut n = Net::keyed(single_a(4, true));
    n.w(reg::EWLR, 8);
    n.linux_start(0x00, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x2E0, &[]));
    n.w(reg::CMR, cmd::TR | cmd::AT);
    let mut irq = false;
    n.until(200 * BIT, |n| {
        irq |= n.out.irq;
        n.dut.read(reg::SR) & sr::TBS != 0
    });
    n.idle(4);
    assert_eq!(n.r(reg::SR) & sr::ES, sr::ES, "the ES event happened");
    assert!(!irq && !n.out.irq, "P-IRQ-1: no irq");
    assert_eq!(n.r(reg::IR), 0, "P-IR-2: nothing set without IER");
    n.w(reg::IER, 0xFF);
    assert_eq!(n.r(reg::IR), 0, "P-IR-2: a later IER write raises nothing");
    n.w(reg::IER, ir::RI | ir::EI);
    n.peer_on = [true, true];
    n.w(reg::CMR, cmd::TR);
    wait_tbs(&mut n, 200);
    peer_sends(&mut n, 0, Frame::base(0x2E1, &[]));
    assert_eq!(n.r(reg::IR), ir::RI | ir::EI, "P-IR-2: TI gated by TIE");
}

/// DS 6.4.6 IR.1 TI (same; P-IR-4, P-MOD-5): TI at the TBS rise of a
/// completion, none at the TBS = 1 of entering reset mode.
#[test]
fn ir_ti_on_tbs_rise_not_on_reset_mode_entry() {
    let mut n = op_single(ir::TI, 0x00);
    n.peer_on = [false, false];
    n.load_tx(&Frame::base(0x3C0, &[]));
    n.w(reg::CMR, cmd::TR);
    n.idle(60 * BIT);
    assert_eq!(n.r(reg::SR) & sr::TBS, 0, "pending");
    n.w(reg::MOD, md::RM);
    assert_eq!(n.r(reg::SR) & sr::TBS, sr::TBS, "P-MOD-5: TBS = 1");
    assert_eq!(n.r(reg::IR), 0, "P-IR-4: no TI");
}

/// DS 6.4.6 IR.5 EPI, 6.4.7 EPIE (same in single mode; P-IR-2, P-IR-6):
/// with EPIE = 0 reaching error passive raises nothing, and a later EPIE
/// write raises no past event; EPI when the controller becomes error active
/// again. (EPI at passive is in the switchover test below.)
#[test]
fn ir_epi_error_passive_left_gated_by_epie() {
    let mut n = op_single(0x00, 0x00);
    n.load_tx(&Frame::base(0x555, &[]));
    n.cut[0] = true;
    n.w(reg::CMR, cmd::TR);
    n.until(3000 * BIT, |n| n.dut.read(reg::TXERR) >= 128);
    n.cut[0] = false;
    n.idle(4);
    assert_eq!(n.r(reg::IR), 0, "P-IR-2: no EPI without EPIE");
    n.w(reg::IER, ir::EPI);
    assert_eq!(n.r(reg::IR), 0, "P-IR-2: a later EPIE raises nothing");
    for _ in 0..40 {
        wait_tbs(&mut n, 400);
        if n.r(reg::TXERR) < 128 {
            break;
        }
        assert_eq!(n.r(reg::IR), 0, "no EPI while passive");
        n.w(reg::CMR, cmd::TR);
    }
    assert_eq!(n.r(reg::TXERR), 127);
    assert_eq!(n.r(reg::SR) & sr::ES, sr::ES, "ES stays (127 >= 96)");
    assert_eq!(n.r(reg::IR), ir::EPI, "DS 6.4.6: EPI at active again");
}

/// Differs (IR.EPI): P-IR-6. In redundancy with `pelican_report = "in_use"`
/// (P-LOG-5), line A cut: EPI when A becomes passive; at the switch to B (A
/// passive -> B active, ES falls in the same clock) EI alone, no EPI;
/// XIR.switch says why.
#[test]
fn ir_epi_not_raised_at_a_switchover_ei_alone() {
    let p = PelicanParams {
        report_best: false,
        ..PelicanParams::default()
    };
    let mut n = op_with(p, ir::EI | ir::EPI, 0x00);
    n.load_tx(&Frame::base(0x555, &[]));
    n.cut[0] = true;
    n.w(reg::CMR, cmd::TR);
    n.until(3000 * BIT, |n| n.dut.read(reg::IR) & ir::EPI != 0);
    assert_eq!(n.dut.u(), 0, "A in use when it became passive");
    assert_eq!(n.r(reg::IR) & ir::EPI, ir::EPI, "P-IR-6: EPI at passive");
    assert_eq!(n.dut.u(), 0, "the IR read was taken before the switch");
    n.until(3000 * BIT, |n| n.dut.u() == 1);
    n.idle(3);
    assert_eq!(n.r(reg::IR), ir::EI, "P-IR-6: EI alone at the switchover");
    let s = n.r(reg::SR);
    assert_eq!(s & (sr::ES | sr::BS), 0, "P-LOG-4: ES, BS of channel B");
    assert_eq!(
        n.r(reg::XIR) & xir::SWITCH,
        xir::SWITCH,
        "P-X-2: XIR.switch"
    );
    wait_tbs(&mut n, 400);
    assert_eq!(n.r(reg::SR) & sr::TCS, sr::TCS, "sent on B");
}

/// Differs (INT pin active low, open drain): P-IRQ-1. `irq` is an active-high
/// level: 1 one clock after an IR bit is set, 0 again after the read that
/// clears it.
#[test]
fn irq_is_an_active_high_level() {
    let mut n = op_single(ir::TI, 0x00);
    assert!(!n.out.irq, "P-IRQ-1: 0 with IR = 0");
    n.load_tx(&Frame::base(0x0AA, &[]));
    n.w(reg::CMR, cmd::TR);
    n.until(200 * BIT, |n| n.dut.read(reg::IR) & ir::TI != 0);
    assert!(!n.out.irq, "P-IRQ-1: one clock after the bit");
    n.idle(1);
    assert!(n.out.irq, "P-IRQ-1: irq = 1");
    n.idle(50);
    assert!(n.out.irq, "P-IRQ-1: a level");
    assert_eq!(n.r(reg::IR), ir::TI);
    n.idle(1);
    assert!(!n.out.irq, "P-IRQ-1: 0 after the clearing read");
}
