//! Reference model: host-visible diagnostics (timing contract §9): `err_warning`
//! against EWL, the error code capture (`err_valid`, `err_kind`, `err_field`,
//! `err_tx`), the arbitration lost capture `alc` and the error counters by kind.
//! Expected values come from the contract's definitions and ISO 11898-1 (which
//! error a node detects where), with frames from the independent encoder.

mod model_support;

use drcc_cosim::{ChannelOutputs, ControllerConfig, Diagnostics, Frame, Mode};
use model_support::{code, frame_bits, timing, Bus, Tester};

const KIND_BIT: u8 = 1;
const KIND_STUFF: u8 = 2;
const KIND_CRC: u8 = 3;
const KIND_FORM: u8 = 4;
const KIND_ACK: u8 = 5;

fn frame(id: u32, data: &[u8]) -> Frame {
    let mut d = [0u8; 8];
    d[..data.len()].copy_from_slice(data);
    Frame {
        id,
        ide: false,
        rtr: false,
        dlc: data.len() as u8,
        data: d,
    }
}

fn ext(id: u32, rtr: bool) -> Frame {
    Frame {
        id,
        ide: true,
        rtr,
        dlc: 1,
        data: [0x5A, 0, 0, 0, 0, 0, 0, 0],
    }
}

fn ewl(ewl: u8) -> ControllerConfig {
    ControllerConfig {
        ewl,
        ..ControllerConfig::default()
    }
}

/// The capture of the first error (`err_valid` pulse) among `outs`, with the
/// `field` probe of the output before it (the field of the bit in error).
fn first_error(outs: &[ChannelOutputs]) -> (Diagnostics, u8) {
    let k = outs
        .iter()
        .position(|o| o.diag.err_valid)
        .expect("no err_valid");
    assert!(
        outs[k].probes.sample_point,
        "err_valid comes from a SAMPLE edge"
    );
    assert_eq!(outs[k].probes.field, code::ERROR_FLAG, "a flag follows");
    (outs[k].diag, outs[k - 1].probes.field)
}

/// Exactly one `err_valid` pulse in `outs`; returns its capture.
fn only_error(outs: &[ChannelOutputs]) -> (Diagnostics, u8) {
    assert_eq!(outs.iter().filter(|o| o.diag.err_valid).count(), 1);
    first_error(outs)
}

fn assert_counts(d: &Diagnostics, bit: u8, stuff: u8, crc: u8, form: u8, ack: u8) {
    assert_eq!(
        (d.cnt_bit, d.cnt_stuff, d.cnt_crc, d.cnt_form, d.cnt_ack),
        (bit, stuff, crc, form, ack)
    );
}

/// A receiver driven by the lower tester: idle, then `bits`, then idle.
fn receive(bits: &[bool]) -> Vec<ChannelOutputs> {
    let mut t = Tester::new(timing(0));
    t.idle(20);
    t.record = true;
    t.drive_all(bits.iter().copied());
    t.idle(40);
    t.trace
}

// ---------------------------------------------------------------- err_warning

/// A lone transmitter collects ACK errors (TEC + 8 each): `err_warning` is
/// `TEC >= EWL || REC >= EWL` at every clock, for a low EWL and the default 96.
#[test]
fn err_warning_at_ewl_from_tec() {
    for limit in [24u8, 96, 1] {
        let mut bus = Bus::new(1, timing(0));
        bus.configs[0] = ewl(limit);
        bus.reset();
        let o = bus.step(&[])[0];
        assert!(!o.diag.err_warning);
        bus.integrate();
        bus.step(&[Some(frame(0x0C3, &[0xF0]))]);
        let mut raised_at_tec = None;
        for _ in 0..3000 * 8 {
            let o = bus.step(&[])[0];
            let expected = o.probes.tec >= limit as u16 || o.probes.rec >= limit;
            assert_eq!(
                o.diag.err_warning, expected,
                "EWL {limit}, TEC {}",
                o.probes.tec
            );
            if expected && raised_at_tec.is_none() {
                raised_at_tec = Some(o.probes.tec);
            }
        }
        // TEC moves in steps of 8: the first value at or above EWL.
        let first = (limit as u16).div_ceil(8) * 8;
        assert_eq!(raised_at_tec, Some(first.max(8)), "EWL {limit}");
    }
}

/// REC against EWL: stuff errors seen by a receiver (REC + 1 each, rule a).
#[test]
fn err_warning_at_ewl_from_rec() {
    let mut t = Tester::with_config(timing(0), ewl(2));
    t.idle(20);
    let mut seen = Vec::new();
    for _ in 0..3 {
        // SOF and 4 dominant ID bits: the 6th equal bit is a stuff error.
        t.drive_all([false; 6]);
        t.idle(30);
        let o = t.last();
        seen.push((o.probes.rec, o.diag.err_warning));
    }
    assert_eq!(seen, vec![(1, false), (2, true), (3, true)]);
}

// ---------------------------------------------------------------- error capture

/// A receiver's stuff error: SOF and four dominant ID bits, then a sixth dominant
/// bit at the stuff position (the next non-stuff bit is still ID_A).
#[test]
fn capture_stuff_error_receiver() {
    let mut bits = vec![false; 6];
    bits.extend([true; 10]);
    let outs = receive(&bits);
    let (d, before) = only_error(&outs);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_STUFF, code::ID_A, false)
    );
    assert_eq!(before, code::ID_A);
    assert_counts(&outs.last().unwrap().diag, 0, 1, 0, 0, 0);
}

/// A transmitter's recessive stuff bit in arbitration read dominant: STUFF with
/// `err_tx` (rule c exception 2: TEC unchanged); the receiver sees six dominant
/// bits: STUFF, not transmitter.
#[test]
fn capture_stuff_error_in_arbitration_transmitter() {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    // 0x03F: SOF + ID bits 10..7 are five dominant bits, the stuff bit is the first
    // recessive bit the transmitter sends.
    bus.step(&[Some(frame(0x03F, &[1])), None]);
    let mut outs = Vec::new();
    let mut forced = false;
    let mut prev_tx = true;
    for _ in 0..100 * 8 {
        let o = bus.step(&[]);
        outs.push(o.clone());
        let rising = !prev_tx && o[0].tx;
        prev_tx = o[0].tx;
        if !forced && rising && o[0].probes.field == code::ID_A {
            forced = true;
            bus.force_dominant = true;
            for _ in 0..8 {
                outs.push(bus.step(&[]));
            }
            bus.force_dominant = false;
        }
    }
    let n0: Vec<ChannelOutputs> = outs.iter().map(|o| o[0]).collect();
    let n1: Vec<ChannelOutputs> = outs.iter().map(|o| o[1]).collect();
    let (d, _) = first_error(&n0);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_STUFF, code::ID_A, true)
    );
    let k = n0.iter().position(|o| o.diag.err_valid).unwrap();
    assert_eq!(n0[k].probes.tec, 0, "rule c exception 2");
    let (d, _) = first_error(&n1);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_STUFF, code::ID_A, false)
    );
}

/// A receiver's CRC error: signalled at the ACK delimiter (`err_field` ACK_DELIM),
/// the tester drives the ACK (the node does not ACK a wrong CRC).
#[test]
fn capture_crc_error() {
    for k in [0usize, 7, 14] {
        let f = frame(0x3A1, &[0xCA, 0xFE]);
        let bits: Vec<bool> = frame_bits(&f, false, Some(k))
            .iter()
            .map(|b| b.value)
            .collect();
        let outs = receive(&bits);
        let (d, before) = only_error(&outs);
        assert_eq!(
            (d.err_kind, d.err_field, d.err_tx),
            (KIND_CRC, code::ACK_DELIM, false)
        );
        assert_eq!(before, code::ACK_DELIM);
        let last = outs.last().unwrap();
        assert_counts(&last.diag, 0, 0, 1, 0, 0);
        assert!(outs.iter().all(|o| !o.rx_valid));
    }
}

/// A receiver's form errors: dominant CRC delimiter, ACK delimiter, EOF bit 3.
#[test]
fn capture_form_errors() {
    let f = frame(0x1B4, &[0x01, 0x80]);
    for (target, n) in [(code::CRC_DELIM, 0), (code::ACK_DELIM, 0), (code::EOF, 2)] {
        let mut bits = frame_bits(&f, false, None);
        let i = bits
            .iter()
            .enumerate()
            .filter(|(_, b)| b.field == target && !b.stuff)
            .nth(n)
            .unwrap()
            .0;
        bits[i].value = false;
        let values: Vec<bool> = bits.iter().map(|b| b.value).collect();
        let outs = receive(&values);
        let (d, before) = first_error(&outs);
        assert_eq!(
            (d.err_kind, d.err_field, d.err_tx),
            (KIND_FORM, target, false)
        );
        assert_eq!(before, target);
        assert_counts(&outs.last().unwrap().diag, 0, 0, 0, 1, 0);
    }
}

/// A lone transmitter's ACK error: ACK, field ACK_SLOT, transmitter.
#[test]
fn capture_ack_error() {
    let mut bus = Bus::new(1, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(frame(0x111, &[0x22]))]);
    let outs: Vec<ChannelOutputs> = (0..100 * 8).map(|_| bus.step(&[])[0]).collect();
    let (d, before) = first_error(&outs);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_ACK, code::ACK_SLOT, true)
    );
    assert_eq!(before, code::ACK_SLOT);
    let k = outs.iter().position(|o| o.diag.err_valid).unwrap();
    assert_eq!(outs[k].probes.tec, 8);
    assert_counts(&outs[k].diag, 0, 0, 0, 0, 1);
}

/// A transmitter's bit error: a recessive data bit forced dominant. The
/// transmitter captures BIT in DATA; the receiver, which has then seen five equal
/// dominant bits, meets the transmitter's error flag at the stuff position: STUFF.
#[test]
fn capture_bit_error_transmitter() {
    // 0x555, DLC 1, data 0x0F: the four dominant data bits 0..3 follow DLC bit 0
    // (recessive) without a stuff bit between; data bit 4 is the first recessive one.
    let f = frame(0x555, &[0x0F]);
    let bits = frame_bits(&f, false, None);
    let data: Vec<_> = bits.iter().filter(|b| b.field == code::DATA).collect();
    assert!(
        data[..5].iter().all(|b| !b.stuff),
        "no stuff bit in data bits 0..4"
    );
    let first_data = bits.iter().position(|b| b.field == code::DATA).unwrap();
    assert!(
        bits[first_data - 1].value,
        "recessive bit before the data field"
    );

    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(f), None]);
    let mut outs = Vec::new();
    let mut forced = false;
    let mut prev_tx = true;
    for _ in 0..100 * 8 {
        let o = bus.step(&[]);
        outs.push(o.clone());
        // The bit_start of the first recessive data bit (after dominant ones).
        let rising = !prev_tx && o[0].tx;
        prev_tx = o[0].tx;
        if !forced && rising && o[0].probes.field == code::DATA {
            forced = true;
            bus.force_dominant = true;
            for _ in 0..8 {
                outs.push(bus.step(&[]));
            }
            bus.force_dominant = false;
        }
    }
    let n0: Vec<ChannelOutputs> = outs.iter().map(|o| o[0]).collect();
    let n1: Vec<ChannelOutputs> = outs.iter().map(|o| o[1]).collect();
    let (d, before) = first_error(&n0);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_BIT, code::DATA, true)
    );
    assert_eq!(before, code::DATA);
    let (d, _) = first_error(&n1);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_STUFF, code::DATA, false)
    );
    let end = n0.last().unwrap().diag;
    assert_eq!(end.cnt_bit, 1);
}

/// A receiver's own ACK read back recessive is a BIT error in ACK_SLOT. The
/// lower tester cannot override a dominant bit, so the node's `rx` is driven
/// directly here (a bus fault that makes the ACK invisible).
#[test]
fn capture_bit_error_receiver_ack() {
    let f = frame(0x0A0, &[0x77]);
    let bits = frame_bits(&f, true, None);
    let mut t = Tester::new(timing(0));
    t.idle(20);
    let mut outs = Vec::new();
    for b in &bits {
        for _ in 0..8 {
            // rx ignores the node's tx: the bus shows exactly `bits`.
            let o = t.node.step(&drcc_cosim::ChannelInputs {
                rx: b.value,
                timing: timing(0),
                ..Default::default()
            });
            outs.push(o);
        }
    }
    let (d, before) = first_error(&outs);
    assert_eq!(
        (d.err_kind, d.err_field, d.err_tx),
        (KIND_BIT, code::ACK_SLOT, false)
    );
    assert_eq!(before, code::ACK_SLOT);
}

// ---------------------------------------------------------------- alc

/// Runs node 0 (`loser`) against node 1 (`winner`) and returns node 0's `alc` at
/// its `arb_lost` pulse; the winner's frame must then get through.
fn alc_of(loser: Frame, winner: Frame) -> u8 {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(loser), Some(winner)]);
    let mut alc = None;
    let mut winner_done = false;
    for _ in 0..200 * 8 {
        let o = bus.step(&[]);
        if o[0].arb_lost {
            assert!(alc.is_none());
            alc = Some(o[0].diag.alc);
            assert!(o[0].tx_pending, "retried later");
        }
        winner_done |= o[1].tx_done;
        assert!(!o[1].arb_lost);
    }
    assert!(winner_done);
    alc.expect("no arbitration loss")
}

#[test]
fn alc_base_identifier_bits() {
    for i in 0..11u32 {
        // Equal up to base-ID bit i (MSB = bit 0): the loser sends 1 there.
        let loser = 0x7FF;
        let winner = 0x7FF & !(1 << (10 - i));
        assert_eq!(
            alc_of(frame(loser, &[1]), frame(winner, &[2])),
            i as u8,
            "bit {i}"
        );
    }
}

#[test]
fn alc_srr_rtr_ide_and_extension() {
    let base_remote = |id| Frame {
        id,
        ide: false,
        rtr: true,
        dlc: 0,
        data: [0; 8],
    };
    // Base remote frame loses to the base data frame at RTR.
    assert_eq!(alc_of(base_remote(0x123), frame(0x123, &[1])), 11);
    // Extended frame (SRR = 1) loses to a base data frame (RTR = 0) at SRR.
    assert_eq!(alc_of(ext(0x123 << 18, false), frame(0x123, &[1])), 11);
    // Extended frame loses to a base remote frame (SRR = RTR = 1) at IDE.
    assert_eq!(alc_of(ext(0x123 << 18, false), base_remote(0x123)), 12);
    // Extension bits: same base ID, differing at extension bit j.
    for j in [0u32, 1, 9, 17] {
        let loser = (0x155 << 18) | 0x3FFFF;
        let winner = loser & !(1 << (17 - j));
        assert_eq!(
            alc_of(ext(loser, false), ext(winner, false)),
            13 + j as u8,
            "ext bit {j}"
        );
    }
    // Extended remote frame loses to the extended data frame at RTR.
    assert_eq!(alc_of(ext(0x1ABCDEF, true), ext(0x1ABCDEF, false)), 31);
}

// ---------------------------------------------------------------- counters

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
