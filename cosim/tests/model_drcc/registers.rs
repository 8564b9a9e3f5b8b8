//! DRCC registers: reset values and ID (contract §3), illegal writes and their
//! documented effect (§9), configuration taken when leaving reset mode.

use super::*;

/// Every register at its reset value (contract §3), also after `rst`.
#[test]
fn reset_values_and_id() {
    let expected: [(u8, u32); 25] = [
        (ID, 0x4452_4343),
        // reset_mode 1, redundancy 0, policy 1, dual_tx 0, k 1, modes 0, single shot 0.
        (CTRL, 1 | 1 << 2 | 1 << 8),
        // brp 0, tseg1 4, tseg2 1, sjw 0, triple 0, ewl 96.
        (BTR, 4 << 6 | 1 << 10 | 96 << 16),
        (RMB_CFG, 1024),
        (DEDUP_CFG, 1024),
        // state idle1, aux valid, error active, reset_mode 1, queues empty.
        (STATUS, 1 << 13),
        (INT_STATUS, 0),
        (INT_ENABLE, 0),
        (CHAN_A_ERR, 0),
        (CHAN_B_ERR, 0),
        (AUX_A, 0),
        (AUX_B, 0),
        (TX_ID, 0),
        (TX_CTRL, 0),
        (TX_DATA0, 0),
        (TX_DATA1, 0),
        (TX_CMD, 0),
        (RX_ID, 0),
        (RX_CTRL, 0),
        (RX_DATA0, 0),
        (RX_DATA1, 0),
        (RX_CMD, 0),
        (STATS0, 0),
        (STATS1, 0),
        (TIMES, 0),
    ];
    let mut sys = Sys::new(1);
    for &(adr, v) in &expected {
        assert_eq!(sys.read(0, adr), v, "register {adr} at power-up");
    }
    // Words 25..35 are the DMR registers (dmr_contract.md §2.1, tests/model_dmr);
    // 36 STAR_STATUS and 37 OMISSIONS read 0 after reset, 38 VERSION and 39 SIZES
    // are constants (§10.1, driver_features.rs), 40 CAP_A and 41 CAP_B read 0
    // after reset (§10.2); 42..45 the filters and 46 RX_TIME read 0 after reset,
    // 47 STATS_CLR reads 0 (§11); 48..51 are the ECSS registers (§12.1,
    // ecss.rs); 52..63 are unmapped.
    for adr in (36..64).filter(|a| !matches!(*a, VERSION | SIZES | 48..=51)) {
        assert_eq!(sys.read(0, adr), 0, "word {adr} reads 0 after reset");
    }
    // Change some registers, then `rst` brings every one back.
    sys.write(0, INT_ENABLE, 0xFF);
    sys.write(0, BTR, 0x0012_3456);
    sys.write(0, TX_DATA0, 0xDEAD_BEEF);
    sys.write(0, CTRL, REDUNDANCY | policy(2) | k(3));
    sys.run(50);
    assert_ne!(sys.read(0, STATUS) & 1 << 13, 1 << 13, "left reset mode");
    sys.nodes[0].wb.rst = true;
    sys.step();
    sys.nodes[0].wb.rst = false;
    assert!(!sys.nodes[0].out.wb_ack && !sys.nodes[0].out.irq);
    for &(adr, v) in &expected {
        assert_eq!(sys.read(0, adr), v, "register {adr} after rst");
    }
    // The paper probes after rst.
    let p = sys.nodes[0].out.probes;
    assert_eq!(p.state, IDLE1);
    assert!(!p.tx_channel && !p.tx_going_on && !p.transmission_ack && !p.tx_success);
    assert_eq!((p.tx_ok_channel, p.tx_failure_channel), (0, 0));
    assert!(sys.nodes[0].out.chan_a_tx && sys.nodes[0].out.chan_b_tx);
}

// ---------------------------------------------------------------------------
// (b) illegal writes (§9)
// ---------------------------------------------------------------------------

/// Reads INT_STATUS.illegal and clears it (W1C).
fn take_illegal(sys: &mut Sys) -> bool {
    let s = sys.read(0, INT_STATUS) & I_ILLEGAL != 0;
    sys.write(0, INT_STATUS, I_ILLEGAL);
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0, "W1C clears");
    s
}

#[test]
fn illegal_writes_set_illegal_with_the_documented_effect() {
    let mut sys = Sys::new(1);
    let ctrl0 = sys.read(0, CTRL);

    // CTRL with policy 3 (warning limit, §5) in reset mode: legal, stored.
    sys.write(0, CTRL, RESET_MODE | REDUNDANCY | policy(3) | k(5));
    assert!(!take_illegal(&mut sys));
    assert_eq!(
        sys.read(0, CTRL),
        RESET_MODE | REDUNDANCY | policy(3) | k(5)
    );
    sys.write(0, CTRL, ctrl0);
    assert_eq!(sys.read(0, CTRL), ctrl0);

    // k = 0 is clamped to 1, not illegal.
    sys.write(0, CTRL, RESET_MODE | policy(2) | k(0));
    assert!(!take_illegal(&mut sys));
    assert_eq!(sys.read(0, CTRL), RESET_MODE | policy(2) | k(1));
    // Reserved bits are not stored.
    // (Bit 5 is `star`, DRCC contract §4.4; bit 17 is `dmr`, dmr_contract.md §2;
    // bit 18 is `busoff_manual`, §11.6; bit 19 is `first_copy`, dmr_contract.md
    // §8.1.)
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1) | 0xC0 | 0xFFF0_0000);
    assert!(!take_illegal(&mut sys));
    assert_eq!(sys.read(0, CTRL), RESET_MODE | policy(1) | k(1));

    // recovery_bits = 0 is stored as written.
    sys.write(0, RMB_CFG, 0x0005_0000);
    assert!(!take_illegal(&mut sys));
    assert_eq!(sys.read(0, RMB_CFG), 0x0005_0000);
    sys.write(0, RMB_CFG, 1024);
    // DEDUP_CFG window is 15 bits.
    sys.write(0, DEDUP_CFG, 0xFFFF_FFFF);
    assert_eq!(sys.read(0, DEDUP_CFG), 0x7FFF);
    sys.write(0, DEDUP_CFG, 1024);

    // Push in reset mode: refused.
    sys.push(0, &frame(0x10, false, false, 1, &[1]), 0);
    assert!(take_illegal(&mut sys));
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0);

    // Pop on an empty RX FIFO: refused.
    sys.write(0, RX_CMD, 1);
    assert!(take_illegal(&mut sys));
    // A command write without the command bit does nothing.
    sys.write(0, RX_CMD, 0);
    sys.write(0, TX_CMD, 0);
    assert!(!take_illegal(&mut sys));

    // Read-only and unmapped words: refused.
    for adr in [
        ID, STATUS, CHAN_A_ERR, CHAN_B_ERR, AUX_A, AUX_B, RX_ID, RX_CTRL, RX_DATA0, RX_DATA1,
        STATS0, STATS1, TIMES, 36, 40, 63,
    ] {
        let before = sys.read(0, adr);
        sys.write(0, adr, 0x1234_5678);
        assert!(take_illegal(&mut sys), "write to word {adr}");
        assert_eq!(sys.read(0, adr), before, "word {adr} unchanged");
    }

    // Leave reset mode (normal mode). CTRL cfg changes outside reset mode: only
    // reset_mode is taken, illegal set.
    sys.start(0, policy(1) | k(1));
    assert!(!take_illegal(&mut sys));
    sys.write(0, CTRL, policy(2) | k(4) | REDUNDANCY);
    assert!(take_illegal(&mut sys));
    assert_eq!(sys.read(0, CTRL), policy(1) | k(1));
    // Same cfg, k = 0 (clamps to the current 1): legal.
    sys.write(0, CTRL, policy(1) | k(0));
    assert!(!take_illegal(&mut sys));
    // BTR, RMB_CFG, DEDUP_CFG outside reset mode: refused.
    for (adr, v) in [(BTR, 0x0060_0501), (RMB_CFG, 7), (DEDUP_CFG, 9)] {
        let before = sys.read(0, adr);
        sys.write(0, adr, v);
        assert!(
            take_illegal(&mut sys),
            "write to word {adr} outside reset mode"
        );
        assert_eq!(sys.read(0, adr), before);
    }

    // Push to a full queue: 8 fit (nobody acknowledges, nothing leaves), the 9th is
    // refused.
    let f = frame(0x55, false, false, 2, &[0xA, 0xB]);
    for i in 0..8 {
        sys.push(0, &f, 0);
        assert!(!take_illegal(&mut sys), "push {i}");
    }
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 8);
    sys.push(0, &f, 0);
    assert!(take_illegal(&mut sys));
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 8);
    // Queue B is independent.
    sys.push(0, &f, 1);
    assert!(!take_illegal(&mut sys));
    assert_eq!(status_txq(sys.read(0, STATUS), 1), 1);

    // irq = |(INT_STATUS & INT_ENABLE), one clock after.
    sys.write(0, INT_ENABLE, I_ILLEGAL);
    assert!(!sys.nodes[0].out.irq);
    sys.write(0, ID, 0);
    assert!(sys.nodes[0].out.irq);
    sys.write(0, INT_STATUS, I_ILLEGAL);
    assert!(
        !sys.nodes[0].out.irq,
        "irq follows the clear one clock later"
    );

    // Entering reset mode empties both TX queues; statistics stay.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
    assert!(!take_illegal(&mut sys));
    let s = sys.read(0, STATUS);
    assert_eq!((status_txq(s, 0), status_txq(s, 1)), (0, 0));
    assert_eq!(s >> 13 & 1, 1);
}

/// Contract §9: redundancy mode needs both channels able to transmit; a CTRL write
/// asking for redundancy with a LISTEN_ONLY channel (§C.7 mode 1) is refused.
#[test]
fn redundancy_with_a_listen_only_channel_is_refused() {
    let mut sys = Sys::new(1);
    let ctrl0 = sys.read(0, CTRL);
    for mode in [1u32 << 12, 1u32 << 14] {
        sys.write(0, CTRL, RESET_MODE | REDUNDANCY | policy(1) | k(1) | mode);
        assert!(take_illegal(&mut sys), "mode bits {mode:#x}");
        assert_eq!(sys.read(0, CTRL), ctrl0, "the whole write is refused");
    }
    // The same channel modes are fine in normal mode.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1) | 1 << 12);
    assert!(!take_illegal(&mut sys));
}

/// Contract §6: the write that clears reset mode may also carry the configuration;
/// the channels stay in reset one more clock and take it. Here channel A becomes
/// SELF_TEST (§C.7: no ACK needed) in that very write: alone on its line, it then
/// sends a frame successfully instead of collecting ACK errors.
#[test]
fn configuration_in_the_write_that_leaves_reset_mode_is_taken() {
    let mut sys = Sys::new(1);
    sys.write(0, CTRL, policy(1) | k(1) | 2 << 12); // reset_mode 0, mode_a SELF_TEST
    sys.run(20 * CPB);
    let f = frame(0x321, false, false, 1, &[0x5A]);
    sys.push(0, &f, 0);
    sys.run(200 * CPB);
    assert_eq!(
        sys.read(0, INT_STATUS) & (I_TX_DONE | I_TX_FAILURE),
        I_TX_DONE,
        "self-test frame sent without acknowledgement"
    );
    assert_eq!(sys.read(0, CHAN_A_ERR) & 0x1FF, 0, "no ACK error counted");
}

/// Byte lanes and the error response (bus_contract.md §1): the staged frame's
/// words take the selected bytes and keep the others; a partial write to any
/// other word is refused with ERR and `INT_STATUS.illegal` and changes nothing;
/// reads ignore the select; a refused whole-word write (§9) ends with ERR too.
#[test]
fn byte_lanes_and_error_responses() {
    let mut sys = Sys::new(1);
    sys.write(0, TX_DATA0, 0x1122_3344);
    // one byte, then a halfword, as a byte-wise memcpy would store them
    assert!(!sys.access_lanes(0, TX_DATA0, true, 0xAAAA_AAAA, 0b0100).1);
    assert_eq!(sys.read(0, TX_DATA0), 0x11AA_3344);
    assert!(!sys.access_lanes(0, TX_DATA0, true, 0xBBBB_CCDD, 0b0011).1);
    assert_eq!(sys.read(0, TX_DATA0), 0x11AA_CCDD);
    // TX_ID, TX_CTRL and TX_DATA1 honour lanes too; no lane writes nothing
    assert!(!sys.access_lanes(0, TX_ID, true, 0x0000_0123, 0b0001).1);
    assert_eq!(sys.read(0, TX_ID), 0x23);
    assert!(!sys.access_lanes(0, TX_CTRL, true, 0x0000_0008, 0b0001).1);
    assert_eq!(sys.read(0, TX_CTRL) & 0xF, 8);
    assert!(!sys.access_lanes(0, TX_DATA1, true, 0xFFFF_FFFF, 0).1);
    assert_eq!(sys.read(0, TX_DATA1), 0);
    assert_eq!(
        sys.read(0, INT_STATUS) & I_ILLEGAL,
        0,
        "none of these is illegal"
    );
    // a partial write to a whole word: ERR, illegal, nothing written
    let btr = sys.read(0, BTR);
    assert!(sys.access_lanes(0, BTR, true, 0, 0b0001).1, "ERR");
    assert_eq!(sys.read(0, BTR), btr, "BTR unchanged");
    assert_ne!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
    sys.write(0, INT_STATUS, I_ILLEGAL);
    // the W1C word by bytes is refused too: the flag stays up
    assert!(sys.access_lanes(0, RX_CMD, true, 1, 0b0001).1);
    assert_ne!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
    assert!(sys.access_lanes(0, INT_STATUS, true, I_ILLEGAL, 0b0001).1);
    assert_ne!(
        sys.read(0, INT_STATUS) & I_ILLEGAL,
        0,
        "not cleared by a byte"
    );
    sys.write(0, INT_STATUS, I_ILLEGAL);
    // reads ignore the select
    assert_eq!(sys.access_lanes(0, ID, false, 0, 0).0, 0x4452_4343);
    // a whole-word write the register rules refuse (§9) also ends with ERR
    assert!(
        sys.access_lanes(0, ID, true, 0, 0xF).1,
        "write to a read-only word"
    );
    assert!(
        sys.access_lanes(0, RX_CMD, true, 1, 0xF).1,
        "pop of an empty FIFO"
    );
    assert!(!sys.access_lanes(0, INT_STATUS, true, I_ILLEGAL, 0xF).1);
}
