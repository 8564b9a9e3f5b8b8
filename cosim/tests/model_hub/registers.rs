//! Hub shape and registers (hub contract §8): refused shapes, ID, reset values,
//! the two-clock Wishbone access, clamping in reset mode, refused writes, IRQ.

use super::*;

#[test]
fn shapes_outside_the_contract_are_refused() {
    for (n, m) in [(1, 1), (9, 1), (2, 0), (2, 5), (0, 0)] {
        let e = HubModel::new(n, m).expect_err("shape must be refused");
        assert!(e.contains("2..=8") && e.contains("1..=4"), "{e}");
    }
    for (n, m) in [(2, 1), (4, 2), (8, 4)] {
        assert!(HubModel::new(n, m).is_ok());
    }
}

#[test]
fn id_register_names_the_shape() {
    for (n, m, id) in [
        (4, 2, 0x4855_0402),
        (2, 1, 0x4855_0201),
        (8, 4, 0x4855_0804),
    ] {
        let mut b = Bench::new(n, m);
        assert_eq!(b.read(ID), id, "N={n} M={m}");
    }
}

#[test]
fn registers_reset_to_the_contract_values() {
    let mut b = Bench::new(4, 2);
    // nrap_on [9] resets to 1 (§9).
    assert_eq!(b.read(CTRL), RESET_MODE | ACK_INTERDEP | 1 << 9);
    assert_eq!(b.read(BTR), (4 << 6) | (1 << 10));
    assert_eq!(b.read(GUARD_CFG), 14 | 28 << 8 | 8 << 16);
    assert_eq!(b.read(BF_CFG), 32 | 64 << 8);
    assert_eq!(b.read(RESTORE_CFG), 1408 | 4096 << 16);
    // STATUS: reset mode, not decoupled, no ACK window, IDLE_WAIT, 6 ports enabled.
    assert_eq!(b.read(STATUS), 1 | 0x3F << 16);
    assert_eq!(b.read(INT_STATUS), 0);
    assert_eq!(b.read(INT_ENABLE), 0);
    assert_eq!(b.read(STATS), 0);
    for p in 0..6 {
        assert_eq!(b.port_reg(p), 1, "PORT_{p}: enabled, nothing else");
    }
    // PORT_p beyond N + M and other unmapped words read 0.
    assert_eq!(b.read(PORT0 + 6), 0);
    assert_eq!(b.read(15), 0);
    assert_eq!(b.read(63), 0);
}

#[test]
fn wishbone_access_takes_two_clocks() {
    let mut b = Bench::new(2, 1);
    // A request held for 4 clocks is taken every other clock (§D.2).
    let req = HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_adr: ID,
        ..b.pin_inputs()
    };
    let acks: Vec<(bool, u32)> = (0..4)
        .map(|_| {
            let o = b.step_with(req);
            (o.wb_ack, o.wb_dat_r)
        })
        .collect();
    let id = 0x4855_0201;
    assert_eq!(acks, [(true, id), (false, 0), (true, id), (false, 0)]);
    // cyc without stb is no access.
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        ..b.pin_inputs()
    });
    assert!(!o.wb_ack);
}

#[test]
fn configuration_writes_are_clamped_in_reset_mode() {
    let mut b = Bench::new(4, 2);
    b.write(GUARD_CFG, 5 | 13 << 8 | 3 << 16);
    assert_eq!(b.read(GUARD_CFG), 14 | 14 << 8 | 3 << 16);
    b.write(GUARD_CFG, 40 | 63 << 8 | 15 << 16 | 0xFFF0_0000);
    assert_eq!(b.read(GUARD_CFG), 40 | 63 << 8 | 15 << 16);
    b.write(BF_CFG, 2 | 7 << 8);
    assert_eq!(b.read(BF_CFG), 8 | 8 << 8);
    b.write(BF_CFG, 200 | 9 << 8);
    assert_eq!(b.read(BF_CFG), 200 | 9 << 8);
    b.write(BTR, 0xFFFF_FFFF);
    assert_eq!(
        b.read(BTR),
        0x0F00_7FFF,
        "BTR [23:15] and [31:28] read 0, brp_ext [27:24] kept"
    );
    b.write(RESTORE_CFG, 0x1234_5678);
    assert_eq!(b.read(RESTORE_CFG), 0x1234_5678);
    b.write(INT_ENABLE, 0xFF);
    assert_eq!(b.read(INT_ENABLE), 0x3F, "INT_ENABLE [5:0]");
    assert_eq!(b.read(INT_STATUS), 0, "legal writes");
}

#[test]
fn refused_writes_set_illegal_and_change_nothing() {
    let mut b = Bench::running(4, 2, &[], true);
    let illegal_after = |b: &mut Bench, adr: u8, d: u32| {
        b.write(adr, d);
        let s = b.read(INT_STATUS);
        b.write(INT_STATUS, 0xF);
        s & INT_ILLEGAL != 0
    };
    // cfg registers outside reset mode.
    assert!(illegal_after(&mut b, BTR, 0));
    assert!(illegal_after(&mut b, GUARD_CFG, 20));
    assert!(illegal_after(&mut b, BF_CFG, 20));
    assert!(illegal_after(&mut b, RESTORE_CFG, 20));
    assert_eq!(b.read(BTR), (4 << 6) | (1 << 10));
    assert_eq!(b.read(GUARD_CFG), 14 | 28 << 8 | 8 << 16);
    assert_eq!(b.read(RESTORE_CFG), 1408 | 4096 << 16);
    // Read-only and unmapped words.
    for adr in [ID, STATUS, STATS, PORT0, PORT0 + 5, PORT0 + 6, 10, 15, 63] {
        assert!(illegal_after(&mut b, adr, 0), "write to word {adr}");
    }
    // Legal writes do not set it.
    assert!(!illegal_after(&mut b, INT_ENABLE, 0));
    assert!(!illegal_after(&mut b, CTRL, ACK_INTERDEP));
    // CTRL outside reset mode: a different ack_interdep is illegal, not taken, and
    // the rest of the write (reset_mode) is taken.
    assert!(illegal_after(&mut b, CTRL, 0));
    assert_eq!(b.read(CTRL), ACK_INTERDEP);
    // Both commands in one write: refused whole (reset_mode 1 is not taken).
    assert!(illegal_after(
        &mut b,
        CTRL,
        ACK_INTERDEP | FORCE_DECOUPLE | RECOUPLE | RESET_MODE
    ));
    assert_eq!(b.read(CTRL), ACK_INTERDEP);
    assert_eq!(b.read(STATUS) & 3, 0, "neither reset mode nor decoupled");
    // A changed ack_interdep outside reset mode with reset_mode 1: illegal, and
    // reset mode is entered; in reset mode ack_interdep is taken.
    assert!(illegal_after(&mut b, CTRL, RESET_MODE));
    assert_eq!(b.read(CTRL), RESET_MODE | ACK_INTERDEP);
    assert!(!illegal_after(&mut b, CTRL, RESET_MODE));
    assert_eq!(b.read(CTRL), RESET_MODE);
}

#[test]
fn irq_is_registered_one_clock_after_int_status() {
    let mut b = Bench::running(2, 1, &[(INT_ENABLE, INT_ILLEGAL)], true);
    // The illegal write's edge sets INT_STATUS.illegal; irq follows one edge later.
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: ID,
        ..b.pin_inputs()
    });
    // bus_contract.md §1: a refused write ends with ERR, not ACK.
    assert!(o.wb_err && !o.wb_ack && !o.irq);
    let s = b.step();
    assert!(b.log[s].irq);
    assert_eq!(b.read(INT_STATUS), INT_ILLEGAL);
    // W1C: cleared at the write edge, irq one edge later.
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: INT_STATUS,
        wb_dat_w: INT_ILLEGAL,
        ..b.pin_inputs()
    });
    assert!(o.irq, "irq still shows INT_STATUS before the write edge");
    let s = b.step();
    assert!(!b.log[s].irq);
    // A masked event raises no irq.
    b.write(INT_ENABLE, INT_ISOLATION);
    b.write(ID, 0);
    b.idle_bits(1);
    assert!(!b.log.last().unwrap().irq);
    assert_eq!(b.read(INT_STATUS), INT_ILLEGAL);
}
