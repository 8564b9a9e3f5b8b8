//! §11 acceptance filter and overrun, §10 captures, §13 window commits.

use crate::harness::*;
use drcc_cosim::model::drcc::DrccParams;
use drcc_cosim::model::pelican::acf::Acf;
use drcc_cosim::model::pelican::PelicanParams;
use drcc_cosim::Frame;

fn acf(acr: [u8; 4], amr: [u8; 4], single: bool) -> Acf {
    Acf { acr, amr, single }
}

/// P-ACF-1 single filter, standard: id, rtr, data 1, data 2, with nb0/nb1.
#[test]
fn p_acf_1_single_standard() {
    // id 0x2A5 = 0101_0100_101: ACR0 = 0x54, ACR1[7:4] = {101, rtr 0} = 0xA0.
    let a = acf([0x54, 0xA0, 0x11, 0x22], [0, 0x0F, 0, 0], true);
    assert!(a.accepts(&Frame::base(0x2A5, &[0x11, 0x22])));
    assert!(!a.accepts(&Frame::base(0x2A4, &[0x11, 0x22])), "id bit 0");
    assert!(!a.accepts(&Frame::base(0x2A5, &[0x11, 0x23])), "data 2");
    assert!(
        a.accepts(&Frame::base(0x2A5, &[0x11])),
        "nb1: dlc 1 has no data 2"
    );
    assert!(a.accepts(&Frame::base(0x2A5, &[])), "nb0: dlc 0");
    assert!(
        !a.accepts(&Frame::base(0x2A5, &[0x12])),
        "data 1 exists at dlc 1"
    );
    let rtr = Frame {
        rtr: true,
        dlc: 2,
        ..Frame::base(0x2A5, &[])
    };
    assert!(!a.accepts(&rtr), "the rtr bit is compared");
    let a = acf([0x54, 0xB0, 0, 0], [0, 0x0F, 0, 0], true);
    assert!(a.accepts(&rtr), "an RTR frame has no data bytes (nb0, nb1)");
    // AMR bit 1 = don't care.
    let a = acf([0x00, 0x00, 0, 0], [0xFF, 0xFF, 0xFF, 0xFF], true);
    assert!(a.accepts(&Frame::base(0x7FF, &[1, 2])));
}

/// P-ACF-1 single filter, extended.
#[test]
fn p_acf_1_single_extended() {
    let id = 0x1234_5678 & 0x1FFF_FFFF;
    let f = ext(id, &[1]);
    let acr = [
        (id >> 21) as u8,
        (id >> 13) as u8,
        (id >> 5) as u8,
        ((id << 3) as u8),
    ];
    assert!(acf(acr, [0, 0, 0, 0x03], true).accepts(&f));
    assert!(!acf(acr, [0, 0, 0, 0x03], true).accepts(&ext(id ^ 1, &[1])));
    assert!(!acf(acr, [0, 0, 0, 0x03], true).accepts(&Frame { rtr: true, ..f }));
}

/// P-ACF-1 dual filter: standard filter 1 with data 1 split over ACR1/ACR3
/// low nibbles, filter 2 on ACR2/ACR3; extended on id[28:13].
#[test]
fn p_acf_1_dual() {
    // filter 1: id 0x2A5, data1 = 0x3C -> ACR1[3:0] = 3, ACR3[3:0] = C.
    // filter 2: id 0x111 = 0010_0010_001 -> ACR2 = 0x22, ACR3[7:4] = 0x2.
    let a = acf([0x54, 0xA3, 0x22, 0x2C], [0, 0, 0, 0], false);
    assert!(a.accepts(&Frame::base(0x2A5, &[0x3C])));
    assert!(!a.accepts(&Frame::base(0x2A5, &[0x3D])));
    assert!(a.accepts(&Frame::base(0x2A5, &[])), "nb0");
    assert!(
        a.accepts(&Frame::base(0x111, &[0x99, 1])),
        "filter 2 ignores data"
    );
    assert!(!a.accepts(&Frame::base(0x112, &[])));
    let id = 0x00AB_CDEF;
    let a = acf(
        [0, 0, (id >> 21) as u8, (id >> 13) as u8],
        [0, 0, 0, 0],
        false,
    );
    assert!(a.accepts(&ext(id, &[])), "extended filter 2");
    assert!(a.accepts(&ext(id ^ 0x1FFF, &[])), "id[12:0] not compared");
    assert!(!a.accepts(&ext(id ^ 0x2000, &[])));
}

/// P-RX-5 / P-ACF-2 end to end: a rejected frame is not stored; P-RX-6
/// overrun: DOS, DOI once; P-CMR-5: CDO clears DOS.
#[test]
fn p_rx_5_6_filter_and_overrun() {
    let mut n = Net::new(PelicanParams {
        core: DrccParams::SMALL,
        ..single_a(4, true)
    });
    n.w(0, 0x09);
    n.w(16, 0x20);
    n.w(20, 0x00);
    n.w(21, 0xFF);
    n.w(22, 0xFF);
    n.w(23, 0xFF);
    n.w(4, 0x08);
    n.w(0, 0x08);
    n.idle(20 * BIT);
    // id[10:3] must be 0x20: 0x100..0x107.
    n.peer_req[0] = Some(Frame::base(0x200, &[1]));
    n.idle(200 * BIT);
    assert_eq!(n.r(29), 0, "P-RX-5: rejected, not stored");
    for k in 0..9u32 {
        n.peer_req[0] = Some(Frame::base(0x100 + (k & 7), &[k as u8]));
        n.until(300 * BIT, |n| {
            n.peer_req[0].is_none() && !n.peer_out[0].tx_pending
        });
    }
    n.idle(20 * BIT);
    assert_eq!(n.r(29), 8, "RMC = F");
    assert_eq!(n.r(2) & 0x02, 0x02, "P-RX-6: DOS");
    assert_eq!(n.r(3) & 0x08, 0x08, "P-RX-6: DOI");
    assert_eq!(n.r(3) & 0x08, 0, "DOI cleared by the read");
    n.w(1, 0x08);
    assert_eq!(n.r(2) & 0x02, 0, "P-CMR-5: CDO");
}

/// P-CAP-2: ECC of an ACK error as transmitter (ERRC 11, DIR 0, SEG 0x19),
/// held until read, re-armed by the read; P-IR-4 BEI.
#[test]
fn p_cap_2_ecc_capture_rearm() {
    let mut n = Net::new(single_a(4, true));
    n.peer_on = [false, false];
    n.linux_start(0x80, 0x00);
    n.load_tx(&Frame::base(0x123, &[1]));
    n.w(1, 0x01);
    n.until(200 * BIT, |n| n.dut.read(15) >= 16);
    assert_eq!(n.r(12), 0xD9, "P-CAP-2: ACK error code");
    assert_eq!(n.r(3) & 0x80, 0x80, "BEI");
    n.w(0, 0x01);
    assert_eq!(n.r(12), 0xD9, "P-CAP-3: reset mode keeps ECC");
}

/// P-CAP-1: ALC of a lost arbitration at base id bit 10 (position 10? no:
/// the first differing bit), held until read.
#[test]
fn p_cap_1_alc_capture() {
    let mut n = Net::new(single_a(4, true));
    n.linux_start(0x40, 0x00);
    // DUT 0x7F0 loses to 0x7E0 at base-ID bit 6 (bit position 6, first = 0).
    n.load_tx(&Frame::base(0x7F0, &[]));
    n.peer_req[0] = Some(Frame::base(0x7E0, &[]));
    n.w(1, 0x01);
    n.until(400 * BIT, |n| n.dut.read(2) & 0x04 != 0);
    assert_eq!(n.r(11), 6, "P-CAP-1: ALC = 6");
    assert_eq!(n.r(3) & 0x40, 0x40, "P-IR-4: ALI");
}

/// P-X-4: a window commit is accepted in host reset mode for a listed index
/// and refused in operating mode or for another index (XIR.win).
#[test]
fn p_x_4_window_commit() {
    let mut n = Net::new(single_a(4, true));
    n.w(122, 3);
    n.w(123, 1);
    assert_eq!(n.r(123), 0, "accepted in reset mode");
    assert_eq!(n.r(120) & 0x40, 0);
    n.w(122, 1);
    n.w(123, 1);
    assert_eq!(n.r(123), 1, "CTRL is not committable");
    assert_eq!(n.r(120) & 0x40, 0x40, "XIR.win");
    n.w(0, 0);
    n.w(122, 3);
    n.w(123, 1);
    assert_eq!(n.r(123), 1, "refused in operating mode");
}

/// P-CAP-1 re-arm: a capture disarms; a second lost arbitration before the
/// read leaves ALC; after a read the next one is captured (loss at bit 0).
fn alc_twice(read_between: bool) -> u8 {
    let mut n = Net::new(single_a(4, true));
    n.linux_start(0x00, 0x00);
    n.load_tx(&Frame::base(0x7F0, &[]));
    n.peer_req[0] = Some(Frame::base(0x7E0, &[]));
    n.w(1, 0x01);
    n.until(400 * BIT, |n| n.dut.core().core_view().chan[0].arb_lost);
    n.idle(2);
    assert_eq!(n.dut.read(11), 6);
    if read_between {
        assert_eq!(n.r(11), 6);
    }
    n.until(800 * BIT, |n| n.dut.read(2) & 0x04 != 0);
    n.idle(20 * BIT);
    // A second race on an idle bus, lost at the first identifier bit.
    n.peer_req[0] = Some(Frame::base(0x000, &[]));
    n.w(1, 0x01);
    n.until(800 * BIT, |n| n.dut.read(2) & 0x04 != 0);
    n.r(11)
}

#[test]
fn p_cap_1_alc_rearm_on_read() {
    assert_eq!(alc_twice(false), 6, "P-CAP-1: disarmed until read");
    assert_eq!(alc_twice(true), 0, "P-CAP-1: re-armed by the read");
}

/// P-X-2: an XIR event at the edge of an XIR read wins (the read returns the
/// value before, the bit stays set).
#[test]
fn p_x_2_xir_event_wins_over_read() {
    let mut n = Net::new(single_a(4, true));
    n.linux_start(0x00, 0x00);
    n.load_tx(&Frame::base(0x555, &[0xFF]));
    n.cut[0] = true;
    n.w(1, 0x01);
    assert_eq!(n.r(120), 0);
    // Find the edge of the next err_state event (active -> passive).
    let mut k = 0;
    loop {
        let mut t = n.clone();
        t.idle(1);
        if t.dut.read(120) & 0x10 != 0 {
            break;
        }
        n.idle(1);
        k += 1;
        assert!(k < 3000 * BIT, "no err_state event");
    }
    let o = n.clk(drcc_cosim::model::pelican::PelicanInputs {
        cyc: true,
        stb: true,
        adr: 120,
        sel: 1,
        ..Default::default()
    });
    assert!(o.ack);
    assert_eq!(
        o.dat & 0x10,
        0,
        "the read returns the value before the edge"
    );
    assert_eq!(n.dut.read(120) & 0x10, 0x10, "P-X-2: the event wins");
}
