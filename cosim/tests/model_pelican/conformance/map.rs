//! The address map, address by address (DS 6.4.1 PeliCAN address allocation,
//! DS 6.4.2 reset values; P-MAP-1..3, §13, §16): the reset value of every
//! address 0..127 at both strides, read-back and the reset-mode / operating-mode
//! write rules of every address 1..114, read-only and reserved addresses, the
//! RX FIFO RAM window (refused), the TX buffer and free RAM, the extension at
//! 112..127 (differs), accesses of a wrong lane (differs). OCR, CDR and
//! BasicCAN are in `mode`.

use super::*;
use drcc_cosim::model::drcc::DrccParams;

/// The value every address has after `rst` (DS 6.4.2 where it defines one,
/// §16 for the rest), computed from the generation keys of `p` by the bit
/// layout of §13.
fn reset_value(r: u8, p: &PelicanParams) -> u8 {
    match r {
        // DS 6.4.2: MOD.RM = 1 (reset mode), P-MOD-1.
        0 => 0x01,
        // DS 6.4.2: SR = 0x3C (TBS, TCS, RS, TS), P-SR-1.
        2 => 0x3C,
        // P-CFG-1 (BTR1 chosen 0x14), DS 6.4.10 (EWLR 96).
        7 => 0x14,
        13 => 96,
        // P-ACF-1: AMR0..3 = 0xFF (accept all), ACR0..3 = 0; 24..28 read 0 in
        // reset mode (P-MAP-1).
        20..=23 => 0xFF,
        // §13: XID0, XID1 ("DR"), XVER 1.0.
        112 => 0x44,
        113 => 0x52,
        114 => 0x10,
        // §13 / P-X-1: XMODE and XK from the generation keys.
        115 => {
            p.mode
                | p.policy << 2
                | (p.dual_tx as u8) << 4
                | (p.star as u8) << 5
                | (p.bom as u8) << 6
                | (p.report_best as u8) << 7
        }
        116 => p.k.max(1),
        // §13 XSTAT[0] = u, P-LOG-1: B in SINGLE_B; the rest 0 (below).
        117 => (p.mode == 3) as u8,
        // Everything else 0: CMR, IR, IER, BTR0, OCR, ALC, ECC, RXERR, TXERR,
        // RMC, RBSA, CDR (§16), 5, 9, 10 (P-CFG-6), 32..95 (P-MAP-3), TXB
        // (power-up 0, P-TX-1), SCR0..2, the rest of XSTAT (aux FSMs valid = 0
        // §D5, no hold, no head), XERR (both error active), XFSM (main FSM
        // idle1 = 0 §D4, DMR state 0, ACL = A), XIR, XIER, XWIN_* (§16).
        _ => 0,
    }
}

fn every_address_reads_its_reset_value(p: PelicanParams) {
    let mut n = Net::keyed(p);
    for r in 0..128u8 {
        assert_eq!(
            n.r(r),
            reset_value(r, &p),
            "reset value of register {r} at stride {}",
            p.stride
        );
    }
}

/// DS 6.4.2 / §16: all 128 addresses after `rst`, stride 4, default keys.
#[test]
fn reset_values_every_address_stride4() {
    every_address_reads_its_reset_value(PelicanParams::default());
}

/// DS 6.4.2 / §16 at stride 1 (P-BUS-2), with other generation keys (P-GEN-1:
/// they set only XMODE / XK).
#[test]
fn reset_values_every_address_stride1() {
    every_address_reads_its_reset_value(PelicanParams {
        stride: 1,
        mode: 3,
        policy: 2,
        k: 3,
        dual_tx: true,
        star: false,
        bom: false,
        report_best: false,
        core: DrccParams::DEFAULT,
    });
}

/// The byte written at address `r` in reset mode by the sweep below.
fn v_rm(r: u8) -> u8 {
    r ^ 0x5A
}

/// The byte written at address `r` in operating mode by the sweep below.
fn v_op(r: u8) -> u8 {
    r ^ 0xC3
}

/// What a read of `r` returns after the reset-mode sweep (P-MAP-1).
fn after_rm_sweep(r: u8, rm: bool) -> Option<u8> {
    let v = v_rm(r);
    Some(match r {
        1 => 0,                   // P-MAP-1, DS 6.4.4: CMR reads 0
        2 if rm => 0x3C,          // P-SR-1: reset mode, nothing pending
        2 => return None,         // RS / TS: the slow bus is still integrating
        3 | 11 | 12 | 29 => 0,    // IR, ALC, ECC, RMC read only
        5 | 9 | 10 => 0,          // P-CFG-6
        4 | 6 | 7 | 8 | 13 => v,  // IER, BTR0, BTR1, OCR, EWLR
        14 | 15 => 0,             // P-ERR-2: only 0 accepted; P-ERR-1
        16..=23 if rm => v,       // P-ACF-1: ACR0..3, AMR0..3
        24..=28 if rm => 0,       // P-MAP-1: 0x00 in reset mode
        16..=28 => return None,   // the RX window of an empty FIFO
        30 => v & 0x3F,           // DS 6.4.17: RBSA.7..6 read 0
        31 => v & 0xEF,           // P-CFG-5: CDR bit 4 not defined
        32..=95 => 0,             // P-MAP-3
        96..=111 => v,            // P-TX-1, P-MAP-3 (SCR0..2)
        112..=114 => return None, // checked by the reset values
        _ => unreachable!(),
    })
}

fn sweep(stride: u8) {
    let mut n = Net::keyed(single_a(stride, true));
    n.peer_on = [false, false];
    // P-MAP-1, P-MAP-2: every address 1..114 written in reset mode.
    for r in 1..=114u8 {
        n.w(r, v_rm(r));
    }
    for r in 1..=114u8 {
        if let Some(e) = after_rm_sweep(r, true) {
            assert_eq!(n.r(r), e, "register {r} after a reset-mode write");
        }
    }
    // P-ERR-2 (TXERR / RXERR other than 0) and P-MAP-1 (32..95 in reset
    // mode) set XIR.ign.
    assert_eq!(n.r(reg::XIR) & xir::IGN, xir::IGN, "P-MAP-1: XIR.ign");
    // Operating mode: the same values read back (P-MOD-2, P-MAP-1).
    n.w(reg::MOD, 0x00);
    assert_eq!(n.r(reg::MOD), 0x00, "P-MOD-3: operating mode");
    for r in 1..=114u8 {
        if let Some(e) = after_rm_sweep(r, false) {
            assert_eq!(n.r(r), e, "register {r} read in operating mode");
        }
    }
    // Every address 2..114 written in operating mode (CMR is §6's).
    for r in 2..=114u8 {
        n.w(r, v_op(r));
    }
    for r in 2..=114u8 {
        let e = match r {
            // P-IER-1: IER in both modes; P-CFG-5: CDR.CD in both modes.
            4 => v_op(4),
            31 => (v_rm(31) & 0xE8) | (v_op(31) & 0x07),
            // P-TX-1: the window writes fill TXB[0..12], read at 96..108;
            // 96..108 themselves are reset mode only (P-MAP-2).
            96..=108 => v_op(r - 80),
            // P-CFG-1, P-RX-4, P-MAP-2: rm-only registers keep their value;
            // read-only ones ignore the write.
            _ => match after_rm_sweep(r, false) {
                Some(e) => e,
                None => continue,
            },
        };
        assert_eq!(n.r(r), e, "register {r} after an operating-mode write");
    }
    // P-MAP-2: wrong-mode writes are ignored without a flag; 32..95 flag only
    // in reset mode (P-MAP-1); TXERR / RXERR in operating mode (P-ERR-2).
    assert_eq!(n.r(reg::XIR), 0, "P-MAP-2: no XIR bit in operating mode");
    // Back in reset mode: ACR/AMR were not written through the window, and
    // P-MOD-5 keeps IER, BTR0/1, OCR, EWLR, RBSA, CDR, ACR/AMR.
    n.w(reg::MOD, md::RM);
    for r in 4..=31u8 {
        let e = match r {
            4 => v_op(4),
            31 => (v_rm(31) & 0xE8) | (v_op(31) & 0x07),
            _ => after_rm_sweep(r, true).unwrap(),
        };
        assert_eq!(n.r(r), e, "register {r} after re-entering reset mode");
    }
}

/// P-MAP-1 / P-MAP-2 / DS 6.4.1: every address read back after reset-mode and
/// operating-mode writes, stride 4.
#[test]
fn every_address_write_rules_reset_and_operating_mode_stride4() {
    sweep(4);
}

/// The same at stride 1 (P-BUS-2).
#[test]
fn every_address_write_rules_reset_and_operating_mode_stride1() {
    sweep(1);
}

/// DS 6.4.1 ("read only" in the address allocation), P-MAP-1, §13: SR, IR,
/// ALC, ECC, RMC, XID0, XID1, XVER, XSTAT, XERR, XFSM ignore writes in both
/// modes.
#[test]
fn read_only_registers_ignore_writes() {
    let mut n = Net::keyed(single_a(4, true));
    n.peer_on = [false, false];
    let ro = [2u8, 3, 11, 12, 29, 112, 113, 114, 117, 118, 119];
    for rm in [true, false] {
        let before: Vec<u8> = ro.iter().map(|&r| n.r(r)).collect();
        for &r in &ro {
            n.w(r, 0xFF);
            n.w(r, 0x00);
        }
        for (k, &r) in ro.iter().enumerate() {
            assert_eq!(n.r(r), before[k], "read-only {r} (rm {rm})");
        }
        if rm {
            n.w(reg::MOD, 0x00);
            n.idle(12 * BIT);
        }
    }
}

/// DS 6.4.1: 5 and 10 reserved, read 0 (same); P-CFG-6: the test register 9
/// reads 0, writes ignored (refused), in both modes.
#[test]
fn reserved_5_10_and_test_register_9_read_zero() {
    let mut n = Net::keyed(single_a(4, true));
    for rm in [true, false] {
        for r in [5u8, 9, 10] {
            n.w(r, 0xFF);
            assert_eq!(n.r(r), 0, "register {r} (rm {rm})");
        }
        n.w(reg::MOD, 0x00);
    }
}

/// P-MAP-3 (refused; DS: the RX FIFO RAM at 32..95): reads 0 in both modes,
/// writes ignored, XIR.ign only for a reset-mode write (P-MAP-1).
#[test]
fn rx_fifo_ram_32_to_95_reads_zero() {
    let mut n = Net::keyed(single_a(4, true));
    n.peer_on = [false, false];
    for r in 32..=95u8 {
        n.w(r, 0xA5);
    }
    assert_eq!(n.r(reg::XIR) & xir::IGN, xir::IGN, "P-MAP-1: XIR.ign in rm");
    for r in 32..=95u8 {
        assert_eq!(n.r(r), 0, "P-MAP-3: {r} reads 0 in reset mode");
    }
    n.w(reg::MOD, 0x00);
    n.w(40, 0x5A);
    n.w(95, 0x5A);
    assert_eq!(n.r(reg::XIR), 0, "P-MAP-1: no XIR.ign in operating mode");
    for r in [32u8, 40, 64, 95] {
        assert_eq!(n.r(r), 0, "P-MAP-3: {r} reads 0 in operating mode");
    }
}

/// P-TX-1, P-MAP-3 (same as DS 6.4.1: TX buffer RAM 96..108, free RAM
/// 109..111): written in reset mode, read in both modes, not written in
/// operating mode; TXB is not reset by `rst` (§16), SCR0..2 are (reset 0).
#[test]
fn tx_buffer_ram_96_108_and_free_ram_109_111() {
    let mut n = Net::keyed(single_a(4, true));
    for r in 96..=111u8 {
        n.w(r, r.wrapping_mul(7));
    }
    n.w(reg::MOD, 0x00);
    for r in 96..=111u8 {
        n.w(r, 0x00);
    }
    for r in 96..=111u8 {
        assert_eq!(n.r(r), r.wrapping_mul(7), "{r} read in operating mode");
    }
    hardware_reset(&mut n);
    for r in 96..=108u8 {
        assert_eq!(n.r(r), r.wrapping_mul(7), "§16: TXB {r} not reset");
    }
    for r in 109..=111u8 {
        assert_eq!(n.r(r), 0, "§16: SCR {r} reset to 0");
    }
}

/// Differs (DS: 112..127 read 0x00): §13 extension. Identification read
/// only; XMODE (all 8 bits) / XK reset mode only with XIR.ign (P-X-1); XIER both modes;
/// XIR clears on read (P-X-2); XWIN_IDX [5:0], XWIN_D read back; a commit of
/// an index outside P-X-4's list is refused (XWIN_CMD[0], XIR.win).
#[test]
fn extension_112_127_replaces_the_zero_reads() {
    let mut n = Net::keyed(single_a(4, true));
    n.peer_on = [false, false];
    // P-X-1: XMODE [6:0], XK [3:0] with 0 stored as 1.
    n.w(reg::XMODE, 0x80 | 0x46);
    assert_eq!(n.r(reg::XMODE), 0xC6, "§13: XMODE [7:0], rep in [7]");
    n.w(reg::XMODE, 0x44);
    n.w(reg::XK, 0xF7);
    assert_eq!(n.r(reg::XK), 0x07, "§13: XK [3:0]");
    n.w(reg::XK, 0x00);
    assert_eq!(n.r(reg::XK), 0x01, "§13: k = 0 stored as 1");
    assert_eq!(n.r(reg::XIR), 0, "accepted writes flag nothing");
    n.w(reg::XIER, 0x81);
    n.w(122, 0xFF);
    assert_eq!(n.r(122), 0x3F, "§13: XWIN_IDX [5:0]");
    for k in 0..4u8 {
        n.w(124 + k, 0x10 + k);
    }
    for k in 0..4u8 {
        assert_eq!(n.r(124 + k), 0x10 + k, "§13: XWIN_D{k} read back");
    }
    n.w(123, 0x01);
    assert_eq!(n.r(123), 0x01, "P-X-4: index 63 refused");
    assert_eq!(n.r(reg::XIR), xir::WIN, "P-X-4: XIR.win");
    assert_eq!(n.r(reg::XIR), 0, "P-X-2: XIR clears on read");
    // Operating mode.
    n.w(reg::MOD, 0x00);
    n.w(reg::XMODE, 0x45);
    n.w(reg::XK, 0x05);
    assert_eq!(n.r(reg::XMODE), 0x44, "P-X-1: XMODE write in op ignored");
    assert_eq!(n.r(reg::XK), 0x01, "P-X-1: XK write in op ignored");
    assert_eq!(n.r(reg::XIR), xir::IGN, "P-X-1: with XIR.ign");
    assert_eq!(n.r(reg::XIER), 0x81, "§13: XIER kept");
    n.w(reg::XIER, 0x7E);
    assert_eq!(n.r(reg::XIER), 0x7E, "§13: XIER written in op");
    n.w(reg::XIR, 0xFF);
    assert_eq!(n.r(reg::XIR), 0, "§13: XIR is not written");
    for (r, e) in [(112u8, 0x44u8), (113, 0x52), (114, 0x10)] {
        assert_eq!(n.r(r), e, "§13: identification {r}");
    }
}

/// P-X-1: XMODE `mode = DMR` or `star` on a top without them: ignored, XIR.ign.
#[test]
fn extension_xmode_refuses_dmr_and_star_without_them() {
    let mut n = Net::keyed(PelicanParams {
        core: DrccParams::SMALL,
        ..single_a(4, true)
    });
    n.w(reg::XMODE, 0xC2);
    assert_eq!(n.r(reg::XMODE), 0xC4, "P-X-1: DMR refused");
    assert_eq!(n.r(reg::XIR), xir::IGN);
    n.w(reg::XMODE, 0xE4);
    assert_eq!(n.r(reg::XMODE), 0xC4, "P-X-1: star refused");
    assert_eq!(n.r(reg::XIR), xir::IGN);
}

/// Differs (the SJA1000 has an 8-bit bus): P-BUS-1..3. A stride-4 write
/// without lane 0 and a stride-1 access of two lanes end with the bus error,
/// change nothing, have no read side effect and set XIR.bus; a stride-4 read
/// ignores `sel`.
#[test]
fn wrong_lane_access_ends_with_bus_error() {
    let mut n = Net::keyed(single_a(4, true));
    let (_, ack, err) = n.access(true, reg::MOD, 0x00, 0x2);
    assert!(!ack && err, "P-BUS-1: write without lane 0 refused");
    assert_eq!(
        n.r(reg::MOD),
        0x01,
        "P-BUS-3: the refused write changed nothing"
    );
    let (d, ack, err) = n.access(false, reg::EWLR, 0, 0x0);
    assert!(ack && !err && d == 96, "P-BUS-1: a read ignores sel");
    assert_eq!(n.r(reg::XIR), xir::BUS, "P-BUS-3: XIR.bus");

    let mut n = Net::keyed(single_a(1, true));
    n.w(reg::MOD, md::SM | md::RM);
    // XIR = 120 = word 30, lane 0; read with lanes 0 and 1.
    let (_, ack, err) = n.access(false, 30, 0, 0x3);
    assert!(!ack && err, "P-BUS-2: two lanes refused");
    assert_eq!(
        n.r(reg::XIR),
        xir::IGN | xir::BUS,
        "P-BUS-3: the refused XIR read cleared nothing (P-MOD-7: SM sets ign)"
    );
}
