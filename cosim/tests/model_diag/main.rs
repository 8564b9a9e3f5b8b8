//! Reference model: host-visible diagnostics (timing contract §9): `err_warning`
//! against EWL, the error code capture (`err_valid`, `err_kind`, `err_field`,
//! `err_tx`), the arbitration lost capture `alc` and the error counters by kind.
//! Expected values come from the contract's definitions and ISO 11898-1 (which
//! error a node detects where), with frames from the independent encoder.

#[path = "../model_support/mod.rs"]
mod model_support;

use drcc_cosim::{ChannelOutputs, ControllerConfig, Diagnostics, Frame, Mode};
use model_support::{code, frame_bits, timing, Bus, Tester};

mod capture;
mod counters;

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
