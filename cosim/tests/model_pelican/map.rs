//! §16 reset values, §2 bus access and §12 address map on both strides.

use crate::harness::*;
use drcc_cosim::model::pelican::PelicanParams;

/// §16 / P-MOD-1 / P-SR-1 / P-CFG-1 / P-ACF-1 / §13: the values after `rst`.
fn reset_values(stride: u8) {
    let mut n = Net::new(PelicanParams {
        stride,
        ..PelicanParams::default()
    });
    let expect = [
        (0, 0x01),
        (2, 0x3C),
        (3, 0x00),
        (4, 0x00),
        (6, 0x00),
        (7, 0x14),
        (8, 0x00),
        (11, 0x00),
        (12, 0x00),
        (13, 0x60),
        (14, 0x00),
        (15, 0x00),
        (16, 0x00),
        (19, 0x00),
        (20, 0xFF),
        (23, 0xFF),
        (29, 0x00),
        (30, 0x00),
        (31, 0x00),
        (109, 0),
        (110, 0),
        (111, 0),
        (112, 0x44),
        (113, 0x52),
        (114, 0x10),
        // XMODE: redundancy (1), error-passive (1 << 2), bom (1 << 6),
        // report the best channel (1 << 7).
        (115, 0xC5),
        (2, 0x3C),
        (116, 0x01),
        (120, 0),
        (121, 0),
        (122, 0),
        (124, 0),
    ];
    for (r, v) in expect {
        assert_eq!(n.r(r), v, "register {r} after rst at stride {stride}");
    }
}

#[test]
fn p16_reset_values_stride4() {
    reset_values(4);
}

#[test]
fn p16_reset_values_stride1() {
    reset_values(1);
}

/// P-BUS-1: stride 4 ignores lanes 1..3, refuses a write without lane 0, reads
/// with any sel; the byte is in [7:0].
#[test]
fn p_bus_1_stride4_lanes() {
    let mut n = Net::new(single_a(4, true));
    // A 32-bit write: lane 0 carries the byte.
    let (_, ack, err) = n.access(true, 13, 0xAABB_CC40, 0xF);
    assert!(ack && !err);
    assert_eq!(n.r(13), 0x40);
    let (_, ack, err) = n.access(true, 13, 0x55, 0x2);
    assert!(!ack && err, "P-BUS-1: write without lane 0 is refused");
    assert_eq!(n.r(13), 0x40, "P-BUS-3: a refused write changes nothing");
    assert_eq!(n.r(120) & 0x20, 0x20, "P-BUS-3: XIR.bus");
    assert_eq!(n.r(120), 0, "P-X-2: XIR clears on read");
    let (d, ack, _) = n.access(false, 7, 0, 0x8);
    assert!(ack);
    assert_eq!(d, 0x14, "P-BUS-1: read ignores sel, [31:8] = 0");
}

/// P-BUS-2: stride 1 picks the register from {adr, lane}, replicates the read
/// byte, refuses other lane patterns.
#[test]
fn p_bus_2_stride1_lanes() {
    let mut n = Net::new(single_a(1, true));
    // EWLR = 13 = word 3, lane 1.
    let (_, ack, _) = n.access(true, 3, 0x0000_2100, 0x2);
    assert!(ack);
    let (d, ack, _) = n.access(false, 3, 0, 0x2);
    assert!(ack);
    assert_eq!(d, 0x2121_2121, "P-BUS-2: read byte replicated");
    let (d, _, _) = n.access(false, 1, 0, 0x8);
    assert_eq!(d, 0x1414_1414, "register 7 = word 1 lane 3 = BTR1");
    for sel in [0x0, 0x3, 0xF] {
        let (_, ack, err) = n.access(false, 3, 0, sel);
        assert!(!ack && err, "P-BUS-2: sel {sel:#x} refused on a read");
        let (_, ack, err) = n.access(true, 3, 0, sel);
        assert!(!ack && err, "P-BUS-2: sel {sel:#x} refused on a write");
    }
    assert_eq!(n.r(13), 0x21);
}

/// P-MAP-1..3, P-CFG-6: reserved and RAM addresses read 0; operating-mode
/// writes of rm-only registers are ignored without error; 32..95 in reset mode
/// set XIR.ign; TXB at 96 reads back.
#[test]
fn p_map_1_3_refusal_rules() {
    for stride in [4, 1] {
        let mut n = Net::new(single_a(stride, true));
        n.w(5, 0x77);
        n.w(9, 0x77);
        n.w(40, 0x77);
        assert_eq!(
            n.r(120) & 0x80,
            0x80,
            "P-MAP-1: 32..95 write in rm sets XIR.ign"
        );
        for r in [5, 9, 10, 40, 95] {
            assert_eq!(n.r(r), 0, "P-MAP-3/P-CFG-6: {r} reads 0");
        }
        n.w(96, 0x88);
        n.w(109, 0x5A);
        assert_eq!(n.r(96), 0x88, "P-TX-1: TXB in rm at 96");
        assert_eq!(n.r(109), 0x5A, "P-MAP-3: SCR0");
        n.w(0, 0x00);
        n.w(6, 0x3F);
        n.w(96, 0x11);
        n.w(115, 0x01);
        assert_eq!(n.r(6), 0x00, "P-CFG-1: BTR0 write in op ignored");
        assert_eq!(n.r(96), 0x88, "P-TX-1: 96.. not written in op");
        assert_eq!(n.r(115), 0xC4, "P-X-1: XMODE write in op ignored");
        assert_eq!(n.r(120) & 0x80, 0x80, "P-X-1: with XIR.ign");
        assert_eq!(n.r(1), 0, "P-MAP-1: CMR reads 0");
        n.w(0, 0x10);
        assert_eq!(n.r(0) & 0x10, 0, "P-MOD-7: SM never set");
    }
}
