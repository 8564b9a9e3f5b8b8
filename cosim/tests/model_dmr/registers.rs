//! §2: `CTRL.dmr`, the DMR registers' reset values, the mailbox window, and every
//! illegal configuration of §2.2 refused with `INT_STATUS.illegal`.

use super::*;

#[test]
fn dmr_registers_reset_values() {
    let mut sys = Sys::new(1);
    // §2: CTRL[17] dmr resets to 0 (reset mode, policy 1, k 1 as before).
    assert_eq!(sys.read(0, CTRL) & DMR, 0);
    // §2.1 table, reset values in brackets.
    assert_eq!(sys.read(0, DMR_CFG), 100, "timeout 100, cs_period 0");
    assert_eq!(sys.read(0, DMR_TIME), 125 | 2000 << 16);
    assert_eq!(sys.read(0, DMR_CS), 0x7EA | 0x7EB << 16);
    assert_eq!(sys.read(0, DMR_STATUS), 0, "active, ACL = DCL, no flag");
    assert_eq!(sys.read(0, DMR_CS_COUNT), 0);
    assert_eq!(sys.read(0, DMR_RX_STATS), 0);
    assert_eq!(sys.read(0, MB_SEL), 0);
    assert_eq!(sys.read(0, MB_ID), 0, "memory: 0 after configuration");
    assert_eq!(sys.read(0, MB_MASK), 0);
    assert_eq!(sys.read(0, MB_CFG), 3, "limit 3, disabled");
    assert_eq!(sys.read(0, MB_STATE), 0);
    // INT_ENABLE[8] dmr is a real bit (and [9] domain, DRCC contract §4.5, and
    // [12:10] err_warning, arb_lost, bus_error, §10.2, and [16:13] the
    // per-channel transmit events, §11.3, and [17] bus_toggle, §12): 18 bits.
    sys.write(0, INT_ENABLE, 0xFFFF_FFFF);
    assert_eq!(sys.read(0, INT_ENABLE), 0x3_FFFF);
    // Probes: all 0 outside DMR mode (§9).
    let p = sys.probes(0);
    assert_eq!(
        (
            p.dmr_state,
            p.acl,
            p.dcl_tx_fault,
            p.rcl_rx_fault,
            p.dmr_tick
        ),
        (0, false, false, false, false)
    );
}

#[test]
fn mailbox_window_and_memory() {
    let mut sys = Sys::new(1);
    sys.write(0, MB_SEL, 5);
    sys.write(0, MB_ID, 0x1234_5678 | MB_IDE | MB_TX);
    sys.write(0, MB_MASK, 0xFFFF_FFFF);
    sys.write(0, MB_CFG, 0x7F | MB_ENABLE);
    assert_eq!(sys.read(0, MB_ID), 0x1234_5678 | MB_IDE | MB_TX);
    assert_eq!(sys.read(0, MB_MASK), 0x1FFF_FFFF, "[28:0] mask");
    assert_eq!(sys.read(0, MB_CFG), 0x7F | MB_ENABLE);
    sys.write(0, MB_SEL, 4);
    assert_eq!(sys.read(0, MB_CFG), 3, "mailbox 4 untouched");
    assert_eq!(sys.read(0, MB_ID), 0);
    // §2.1: the window reads 0 outside reset mode (the engine owns the memory),
    // MB_STATE reads live.
    sys.write(0, MB_SEL, 5);
    sys.start(0);
    assert_eq!(sys.read(0, MB_ID), 0);
    assert_eq!(sys.read(0, MB_MASK), 0);
    assert_eq!(sys.read(0, MB_CFG), 0);
    assert_eq!(sys.read(0, MB_STATE), 0);
    // §2.1: `rst` clears limit and enable, not the identifier memory.
    sys.nodes[0].wb = DrccInputs {
        rst: true,
        ..Default::default()
    };
    sys.step();
    sys.nodes[0].wb = DrccInputs::default();
    sys.step();
    sys.write(0, MB_SEL, 5);
    assert_eq!(sys.read(0, MB_ID), 0x1234_5678 | MB_IDE | MB_TX);
    assert_eq!(sys.read(0, MB_MASK), 0x1FFF_FFFF);
    assert_eq!(sys.read(0, MB_CFG), 3);
}

#[test]
fn illegal_configurations_are_refused() {
    let mut sys = Sys::with_mailboxes(1, 4);
    // §2.2: zero times.
    assert!(sys.refused(0, DMR_CFG, 7 << 16), "timeout 0");
    assert_eq!(sys.read(0, DMR_CFG), 100, "nothing stored");
    assert!(sys.refused(0, DMR_TIME, 2000 << 16), "tick_bits 0");
    assert!(sys.refused(0, DMR_TIME, 125), "recovery_delay 0");
    assert_eq!(sys.read(0, DMR_TIME), 125 | 2000 << 16);
    assert!(!sys.refused(0, DMR_CFG, 50), "cs_period 0 is legal");
    assert_eq!(sys.read(0, DMR_CFG), 50);
    // §2.2: equal CS identifiers.
    assert!(sys.refused(0, DMR_CS, 0x123 | 0x123 << 16));
    assert_eq!(sys.read(0, DMR_CS), 0x7EA | 0x7EB << 16);
    // §2.2: enable with limit 0.
    sys.write(0, MB_SEL, 1);
    assert!(sys.refused(0, MB_CFG, MB_ENABLE));
    assert_eq!(sys.read(0, MB_CFG), 3);
    assert!(
        !sys.refused(0, MB_CFG, 0),
        "limit 0 while disabled is legal"
    );
    // §2.2: a mailbox identifier equal to a CS identifier.
    sys.write(0, MB_ID, 0x7EB);
    assert!(
        sys.refused(0, MB_CFG, 2 | MB_ENABLE),
        "stored id is cs_id_rcl"
    );
    assert_eq!(sys.read(0, MB_CFG), 0);
    sys.write(0, MB_ID, 0x7EB | MB_IDE);
    assert!(
        !sys.refused(0, MB_CFG, 2 | MB_ENABLE),
        "an extended identifier is not a CS identifier"
    );
    assert!(
        sys.refused(0, MB_ID, 0x7EA),
        "enabled mailbox takes cs_id_dcl"
    );
    assert_eq!(sys.read(0, MB_ID), 0x7EB | MB_IDE);
    assert!(!sys.refused(0, MB_ID, 0x7EC), "another base id is fine");
    // §2.2: DMR_CS while a mailbox is enabled.
    assert!(sys.refused(0, DMR_CS, 0x100 | 0x101 << 16));
    sys.write(0, MB_CFG, 2);
    assert!(!sys.refused(0, DMR_CS, 0x100 | 0x101 << 16));
    assert_eq!(sys.read(0, DMR_CS), 0x100 | 0x101 << 16);
    // §2.2: MB_SEL >= M (M = 4 here).
    assert!(sys.refused(0, MB_SEL, 4));
    assert_eq!(sys.read(0, MB_SEL), 1);
    assert!(!sys.refused(0, MB_SEL, 3));
    // §2: CTRL with redundancy and dmr, or dmr with a listen-only channel.
    assert!(sys.refused(0, CTRL, RESET_MODE | REDUNDANCY | DMR));
    assert!(sys.refused(0, CTRL, RESET_MODE | DMR | mode_a(LISTEN_ONLY)));
    assert!(sys.refused(0, CTRL, RESET_MODE | DMR | mode_b(LISTEN_ONLY)));
    assert_eq!(sys.read(0, CTRL) & (DMR | REDUNDANCY), 0, "nothing stored");
    // Outside reset mode: every cfg register is refused, the mode never changes.
    sys.start(0);
    assert_eq!(sys.read(0, CTRL) & (DMR | RESET_MODE), DMR);
    for (adr, v) in [
        (DMR_CFG, 10),
        (DMR_TIME, 10 | 10 << 16),
        (DMR_CS, 0x200 | 0x201 << 16),
        (MB_ID, 0x55),
        (MB_MASK, 0x55),
        (MB_CFG, 1),
    ] {
        assert!(
            sys.refused(0, adr, v),
            "cfg register {adr} outside reset mode"
        );
    }
    assert!(sys.refused(0, CTRL, REDUNDANCY), "the mode never changes");
    assert_eq!(sys.read(0, CTRL) & (DMR | REDUNDANCY), DMR);
    assert!(!sys.refused(0, MB_SEL, 2), "MB_SEL is not cfg");
    for adr in [DMR_STATUS, DMR_CS_COUNT, DMR_RX_STATS, MB_STATE] {
        assert!(sys.refused(0, adr, 0xFFFF_FFFF), "read-only {adr}");
    }
    sys.write(0, CTRL, RESET_MODE | DMR);
    sys.write(0, MB_SEL, 3);
    assert_eq!(sys.read(0, MB_ID), 0, "refused writes stored nothing");
    assert_eq!(sys.read(0, DMR_CFG), 50);
}
