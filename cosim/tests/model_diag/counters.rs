//! Error counters: counting and saturation (also in listen-only), the stuff bit
//! after a base IDE outside arbitration, the error that causes bus-off.

use super::*;

/// Counters by kind: a lone transmitter makes one ACK error per attempt; `cnt_ack`
/// follows the `err_valid` pulses, saturates at 255, the other counters stay 0;
/// only a reset clears them.
#[test]
fn error_counters_count_and_saturate() {
    let mut bus = Bus::new(1, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(frame(0x001, &[]))]);
    let mut pulses = 0u32;
    let mut last = Diagnostics::default();
    while pulses < 270 {
        let o = bus.step(&[])[0];
        if o.diag.err_valid {
            pulses += 1;
            assert_eq!(o.diag.err_kind, KIND_ACK);
        }
        assert_counts(&o.diag, 0, 0, 0, 0, pulses.min(255) as u8);
        last = o.diag;
        assert!(bus.clock < 10_000_000, "too slow");
    }
    assert_eq!(last.cnt_ack, 255);
    bus.reset();
    let o = bus.step(&[])[0];
    assert_counts(&o.diag, 0, 0, 0, 0, 0);
    assert_eq!((o.diag.err_kind, o.diag.err_field, o.diag.alc), (0, 0, 0));
}

/// Counters count in LISTEN_ONLY too (TEC/REC do not); `err_valid` and the
/// capture work the same.
#[test]
fn error_counters_count_in_listen_only() {
    let lo = ControllerConfig {
        mode: Mode::ListenOnly,
        ..ControllerConfig::default()
    };
    let mut t = Tester::with_config(timing(0), lo);
    t.idle(20);
    for n in 1..=5u8 {
        t.drive_all([false; 6]);
        t.idle(30);
        let o = t.last();
        assert_counts(&o.diag, 0, n, 0, 0, 0);
        assert_eq!(
            (o.diag.err_kind, o.diag.err_field),
            (KIND_STUFF, code::ID_A)
        );
        assert_eq!((o.probes.tec, o.probes.rec), (0, 0));
    }
    let f = frame(0x3A1, &[0xCA]);
    let bits: Vec<bool> = frame_bits(&f, false, Some(3))
        .iter()
        .map(|b| b.value)
        .collect();
    t.drive_all(bits);
    t.idle(30);
    let o = t.last();
    assert_counts(&o.diag, 0, 5, 1, 0, 0);
    assert_eq!(
        (o.diag.err_kind, o.diag.err_field),
        (KIND_CRC, code::ACK_DELIM)
    );
    assert_eq!((o.probes.tec, o.probes.rec), (0, 0));
}

/// Forces the first recessive bit node 0 sends while its `field` probe is `at`
/// (the bit_start of a recessive bit after dominant ones) to dominant; returns
/// node 0's outputs.
fn force_first_recessive(f: Frame, at: u8) -> Vec<ChannelOutputs> {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(f), None]);
    let mut outs = Vec::new();
    let mut forced = false;
    let mut prev_tx = true;
    for _ in 0..100 * 8 {
        let o = bus.step(&[])[0];
        outs.push(o);
        let rising = !prev_tx && o.tx;
        prev_tx = o.tx;
        if !forced && rising && o.probes.field == at {
            forced = true;
            bus.force_dominant = true;
            for _ in 0..8 {
                outs.push(bus.step(&[])[0]);
            }
            bus.force_dominant = false;
        }
    }
    assert!(forced);
    outs
}

/// Rule c exception 2 covers stuff bits in arbitration only. Base frame 0x0B0:
/// ID bits 7..10 and RTR are five dominant bits, the recessive stuff bit after RTR
/// is in arbitration: STUFF, TEC unchanged. Base frame 0x0A8: ID bits 8..10, RTR
/// and IDE are five dominant bits; a base frame's IDE is control field (ISO
/// 11898-1 10.4.2.2), so the stuff bit after it is not in arbitration: a bit error
/// (BIT), TEC + 8.
#[test]
fn stuff_bit_after_base_ide_is_not_in_arbitration() {
    for (id, at, kind, tec) in [
        (0x0B0, code::IDE, KIND_STUFF, 0u16),
        (0x0A8, code::R0, KIND_BIT, 8),
    ] {
        let f = frame(id, &[0x33]);
        let bits = frame_bits(&f, false, None);
        let k = bits.iter().position(|b| b.stuff).unwrap();
        assert!(
            bits[k].value && bits[k].field == at,
            "{id:#x}: first stuff bit"
        );
        let outs = force_first_recessive(f, at);
        let (d, before) = first_error(&outs);
        assert_eq!(
            (d.err_kind, d.err_field, d.err_tx),
            (kind, at, true),
            "{id:#x}"
        );
        assert_eq!(before, at);
        let e = outs.iter().position(|o| o.diag.err_valid).unwrap();
        assert_eq!(outs[e].probes.tec, tec, "{id:#x}");
    }
}

/// The error that makes the node bus-off is captured too (contract §9): node 0's
/// first recessive data bit is forced dominant in every attempt, a bit error each
/// time (TEC + 8, rule c); at the 32nd, TEC exceeds 255 at that very SAMPLE edge
/// (rule j), no flag follows, and `err_valid` pulses with BIT in DATA.
#[test]
fn error_causing_bus_off_is_captured() {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(frame(0x555, &[0x0F])), None]);
    let mut prev_tx = true;
    let mut bit_errors = 0;
    let mut off = None;
    for _ in 0..200_000 {
        let o = bus.step(&[])[0];
        if o.diag.err_valid {
            bit_errors += (o.diag.err_kind == KIND_BIT) as u32;
        }
        if o.probes.err_state == 2 {
            off = Some(o);
            break;
        }
        let rising = !prev_tx && o.tx;
        prev_tx = o.tx;
        if rising && o.probes.field == code::DATA {
            bus.force_dominant = true;
            for _ in 0..8 {
                let o = bus.step(&[])[0];
                if o.diag.err_valid {
                    bit_errors += (o.diag.err_kind == KIND_BIT) as u32;
                }
                if o.probes.err_state == 2 {
                    off = Some(o);
                    break;
                }
            }
            bus.force_dominant = false;
            if off.is_some() {
                break;
            }
        }
    }
    let o = off.expect("bus-off reached");
    assert!(
        o.diag.err_valid,
        "the error that caused bus-off is captured"
    );
    assert_eq!(
        (o.diag.err_kind, o.diag.err_field, o.diag.err_tx),
        (KIND_BIT, code::DATA, true)
    );
    assert_eq!(o.probes.tec, 256);
    assert_eq!(o.probes.field, code::BUS_OFF);
    assert_eq!(bit_errors, 32);
    assert_eq!(o.diag.cnt_bit, 32);
}
