//! Driver sequences: Linux `sja1000.c` (§3, §6, §7, §9, §11, §15), Zephyr
//! `can_sja1000.c` (self test, listen-only) and the redundancy view (§5).

use crate::harness::*;
use drcc_cosim::model::pelican::{PelicanInputs, PelicanParams};
use drcc_cosim::Frame;

/// Linux: start, transmit a standard and an extended frame with CMR = TR; the
/// other node receives each (P-MOD-3, P-CFG-2, P-TX-1, P-TX-2, P-TX-7, P-IR-4).
#[test]
fn linux_transmit_standard_and_extended() {
    for stride in [4, 1] {
        let mut n = Net::new(single_a(stride, true));
        n.linux_start(0xFF, 0x00);
        assert_eq!(n.r(0), 0x00, "P-MOD-3: operating mode");
        assert_eq!(n.r(2) & 0x0C, 0x0C, "P-SR-1: TBS, TCS");
        for f in [
            Frame::base(0x5A3, &[1, 2, 3]),
            ext(0x1234_5678 & 0x1FFF_FFFF, &[9, 8, 7, 6, 5, 4, 3, 2]),
        ] {
            n.load_tx(&f);
            n.received.clear();
            n.w(1, 0x01);
            assert_eq!(n.r(2) & 0x0C, 0, "P-TX-2: TBS and TCS fall at the TR edge");
            let fi = n.r(96);
            n.w(16, fi ^ 0x0F);
            assert_eq!(n.r(96), fi, "P-TX-1: TX buffer locked while TBS = 0");
            n.until(200 * BIT, |n| n.dut.core().core_view().chan[0].tx_done);
            n.idle(3);
            assert_eq!(n.r(2) & 0x0C, 0x0C, "P-TX-7: TBS, TCS after success");
            assert_eq!(n.r(3) & 0x02, 0x02, "P-IR-4: TI");
            assert_eq!(n.r(3) & 0x02, 0, "P-IR-3: TI cleared by the IR read");
            assert_eq!(
                n.received,
                vec![(0, f.normalized())],
                "the peer receives it"
            );
        }
    }
}

/// §15: TI is loaded at E0+1 after the tx_done pulse and irq one clock later.
#[test]
fn p15_ti_and_irq_clocks() {
    let mut n = Net::new(single_a(4, true));
    n.linux_start(0x02, 0x00);
    n.load_tx(&Frame::base(0x100, &[0xAA]));
    n.w(1, 0x01);
    n.until(200 * BIT, |n| n.dut.core().core_view().chan[0].tx_done);
    // The pulse is visible after edge E0; TI set at E0+1; irq at E0+2.
    assert!(!n.out.irq);
    n.idle(1);
    assert!(n.dut.read(3) & 0x02 != 0, "TI at E0+1");
    assert!(!n.out.irq, "irq not yet at E0+1");
    n.idle(1);
    assert!(n.out.irq, "P-IRQ-1: irq from E0+2");
}

/// Linux receive: RI is a level (P-IR-2), read the window (P-RX-2), RRB pops
/// (P-CMR-4), RBSA advances by the SJA1000 length (P-RX-4).
#[test]
fn linux_receive_window_rrb() {
    let mut n = Net::new(single_a(4, true));
    n.linux_start(0x01, 0x00);
    let f1 = ext(0x00AB_CDEF, &[1, 2, 3, 4, 5]);
    let f2 = Frame {
        rtr: true,
        dlc: 4,
        ..Frame::base(0x7FF, &[])
    };
    n.peer_req[0] = Some(f1);
    n.idle(300 * BIT);
    n.until(300 * BIT, |n| n.dut.read(29) == 1);
    n.peer_req[0] = Some(f2);
    n.until(300 * BIT, |n| n.dut.read(29) == 2);
    n.idle(2);
    assert!(n.out.irq, "P-IRQ-1: RI drives irq");
    assert_eq!(n.r(3) & 1, 1, "P-IR-2: RI");
    assert_eq!(
        n.r(3) & 1,
        1,
        "P-IR-2: RI is a level, a read does not clear it"
    );
    assert_eq!(n.r(2) & 1, 1, "P-SR-1: RBS");
    assert_eq!(n.read_rx(), f1);
    assert_eq!(n.r(16), 0x85, "P-RX-2: FI = ide, dlc");
    assert_eq!(
        n.r(20),
        ((0x00AB_CDEF & 0x1F) << 3) as u8,
        "P-RX-2: ext byte 20"
    );
    n.w(1, 0x04);
    n.idle(2);
    assert_eq!(n.r(30), 3 + 2 + 5, "P-RX-4: RBSA += 3 + 2 ide + dlc");
    assert_eq!(n.r(16), 0x44, "P-RX-2: FI of an RTR with dlc 4");
    assert_eq!(n.r(17), 0xFF);
    assert_eq!(n.r(18), 0xF0, "P-RX-2: {{id[2:0], rtr, 0000}}");
    assert_eq!(n.r(19), 0, "P-RX-2: a remote frame's data read 0");
    n.w(1, 0x04);
    n.idle(2);
    assert_eq!(n.r(30), 10 + 3, "P-RX-4: an RTR frame adds no data length");
    assert_eq!(n.r(2) & 1, 0, "RBS 0 on an empty FIFO");
    assert_eq!(n.r(3) & 1, 0, "RI falls with RBS");
    n.w(1, 0x04);
    assert_eq!(n.r(30), 13, "P-CMR-4: RRB on an empty FIFO does nothing");
}

/// One-shot (CMR = TR | AT) on a bus with no other node: the first error ends
/// the message, TBS = 1, TCS = 0, TI (P-CMR-2, P-TX-4, P-TX-7).
#[test]
fn linux_one_shot_fails_without_ack() {
    let mut n = Net::new(single_a(4, true));
    n.peer_on = [false, false];
    n.linux_start(0x02, 0x00);
    n.load_tx(&Frame::base(0x123, &[1]));
    n.w(1, 0x03);
    n.until(200 * BIT, |n| n.dut.read(2) & 0x04 != 0);
    assert_eq!(n.r(2) & 0x0C, 0x04, "P-TX-7: TBS = 1, TCS = 0");
    assert_eq!(n.r(3) & 0x02, 0x02, "TI");
    let tec = n.r(15);
    assert_eq!(tec, 8, "one error counted: the message was tried once");
    n.idle(200 * BIT);
    assert_eq!(n.r(15), 8, "P-TX-4: no retransmission");
}

/// Zephyr self test with self-reception request (STM, SRR): the frame is sent
/// without ACK and completes (P-CFG-3, P-CMR-2).
#[test]
fn zephyr_self_test_srr() {
    let mut n = Net::new(single_a(4, true));
    n.peer_on = [false, false];
    n.linux_start(0x03, 0x04);
    assert_eq!(
        n.r(0),
        0x04,
        "P-MOD-2: STM taken with the write that clears RM"
    );
    n.load_tx(&Frame::base(0x0F0, &[0x11, 0x22]));
    n.w(1, 0x10);
    n.until(200 * BIT, |n| n.dut.read(2) & 0x04 != 0);
    assert_eq!(n.r(2) & 0x08, 0x08, "self test: success without ACK");
    assert_eq!(n.r(15), 0, "no error counted");
    n.idle(4);
    assert_eq!(n.r(29), 1, "P-TX-5: the own frame enters the RX FIFO");
    assert_eq!(n.read_rx(), Frame::base(0x0F0, &[0x11, 0x22]), "P-TX-5");
    // P-ACF-2: a self-received frame passes the filter, TR alone is not
    // self-received.
    n.w(1, 0x04);
    n.load_tx(&Frame::base(0x0F1, &[0x33]));
    n.w(1, 0x01);
    n.until(200 * BIT, |n| n.dut.read(2) & 0x04 != 0);
    n.idle(10);
    assert_eq!(n.r(29), 0, "P-CMR-2: TR alone is not self-received");
}

/// Zephyr listen-only: a start completes at once without transmission
/// (P-TX-6); frames are received without ACK.
#[test]
fn zephyr_listen_only() {
    let mut n = Net::new(single_a(4, true));
    n.linux_start(0x03, 0x02);
    n.load_tx(&Frame::base(0x0F0, &[0x11]));
    n.clk(PelicanInputs {
        cyc: true,
        stb: true,
        we: true,
        adr: 1,
        dat: 1,
        sel: 1,
        ..Default::default()
    });
    assert_eq!(n.dut.read(2) & 0x0C, 0, "P-TX-6: TBS, TCS 0 at E");
    n.idle(1);
    assert_eq!(
        n.dut.read(2) & 0x0C,
        0x04,
        "P-TX-6: TBS at E+1, TCS stays 0"
    );
    assert_eq!(n.dut.read(3) & 0x02, 0x02, "P-TX-6: TI");
    n.idle(100 * BIT);
    assert!(n.received.is_empty(), "nothing transmitted");
}

/// Redundancy: line A cut; the driver sees one controller that keeps
/// transmitting on B; XIR.switch says why (P-LOG-1, P-LOG-4, P-X-2, P-BO-8).
#[test]
fn redundancy_line_a_cut() {
    let mut n = Net::new(PelicanParams::default());
    n.linux_start(0x07, 0x00);
    n.w(0, 0x01);
    n.w(121, 0x01);
    n.w(0, 0x00);
    n.idle(20 * BIT);
    n.cut[0] = true;
    for k in 0..3u32 {
        n.load_tx(&Frame::base(0x200 + k, &[k as u8]));
        n.received.clear();
        n.w(1, 0x01);
        n.until(20_000 * BIT, |n| n.dut.read(2) & 0x04 != 0);
        assert_eq!(n.r(2) & 0x08, 0x08, "P-TX-7: success on the other line");
        assert!(n.received.iter().any(|&(l, f)| l == 1 && f.id == 0x200 + k));
    }
    assert_eq!(n.r(117) & 1, 1, "XSTAT.u = B");
    assert_eq!(n.r(120) & 1, 1, "P-X-2: XIR.switch");
    assert_eq!(n.r(2) & 0x80, 0, "P-LOG-3: no logical bus-off");
}

/// P-IR-2: RI needs RIE; RBS shows the frame regardless.
#[test]
fn p_ir_2_ri_needs_rie() {
    let mut n = Net::new(single_a(4, true));
    n.linux_start(0x02, 0x00);
    n.peer_req[0] = Some(Frame::base(0x321, &[5]));
    n.until(600 * BIT, |n| n.dut.read(2) & 1 != 0);
    n.idle(3);
    assert_eq!(n.r(3) & 1, 0, "P-IR-2: no RI without RIE");
    assert!(!n.out.irq, "no irq");
    n.w(4, 0x01);
    assert_eq!(n.r(3) & 1, 1, "P-IR-2: RI as a level once RIE is set");
}
