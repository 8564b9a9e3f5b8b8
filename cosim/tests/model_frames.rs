//! Reference model, error-free traffic: the transmitted bit stream checked bit by
//! bit against an independent encoder, reception, ACK, arbitration and retry.

mod model_support;

use drcc_cosim::model::crc::crc15_bytes;
use drcc_cosim::{BitTiming, ChannelOutputs, Frame};
use model_support::{code, field_after, frame_bits, timing, Bus, Tester};

fn data_frame(id: u32, ide: bool, data: &[u8]) -> Frame {
    let mut d = [0u8; 8];
    d[..data.len()].copy_from_slice(data);
    Frame {
        id,
        ide,
        rtr: false,
        dlc: data.len() as u8,
        data: d,
    }
}

fn sample_frames() -> Vec<Frame> {
    let mut frames = vec![
        data_frame(0x123, false, &[0x12, 0x34]),
        // Long runs everywhere: stuff bits in identifier, control and data fields.
        data_frame(0x000, false, &[0x00; 8]),
        data_frame(0x7FF, false, &[0xFF; 8]),
        data_frame(
            0x1FFF_FFFF,
            true,
            &[0xFF, 0x00, 0xFF, 0x00, 0x0F, 0xF0, 0x55, 0xAA],
        ),
        data_frame(0x0000_0000, true, &[]),
        data_frame(0x1234_5678, true, &[0xDE, 0xAD, 0xBE, 0xEF]),
        data_frame(0x3E0, false, &[0x83]),
    ];
    // Remote frames: base and extended, DLC as requested, no data field.
    frames.push(Frame {
        id: 0x7F0,
        ide: false,
        rtr: true,
        dlc: 4,
        data: [0; 8],
    });
    frames.push(Frame {
        id: 0x0ABC_DEF0,
        ide: true,
        rtr: true,
        dlc: 15,
        data: [0; 8],
    });
    // DLC 9..15 carry 8 bytes.
    frames.push(Frame {
        id: 0x555,
        ide: false,
        rtr: false,
        dlc: 13,
        data: [1, 2, 3, 4, 5, 6, 7, 8],
    });
    // A frame whose CRC ends in five equal bits: a stuff bit follows the last CRC
    // bit (found with the independent encoder).
    let with_stuff_after_crc = (0u32..0x800)
        .map(|id| data_frame(id, false, &[0x5A]))
        .find(|f| {
            let bits = frame_bits(f, false, None);
            let delim = bits
                .iter()
                .position(|b| b.field == code::CRC_DELIM && !b.stuff);
            bits[delim.unwrap() - 1].stuff
        })
        .expect("some identifier gives a stuff bit after the CRC");
    frames.push(with_stuff_after_crc);
    frames
}

#[test]
fn crc15_check_value() {
    assert_eq!(crc15_bytes(b"123456789"), 0x059E);
    // The test's own long-division CRC agrees with the catalogue value too.
    let bits: Vec<bool> = b"123456789"
        .iter()
        .flat_map(|&b| (0..8).rev().map(move |i| (b >> i) & 1 == 1))
        .collect();
    assert_eq!(model_support::crc15_division(&bits), 0x059E);
}

/// Node 0 sends `frame` alone on a bus with one receiver (node 1) that ACKs.
/// Checks node 0's `tx` and `field` at every one of its sample points against the
/// independent encoder, the ACK on the bus, `tx_done` at EOF bit 7, `rx_valid` and
/// `rx_frame` at node 1.
fn lone_transmission(frame: Frame, t: BitTiming) {
    let mut bus = Bus::new(2, t);
    bus.integrate();
    // The transmitter sends a recessive ACK slot; the bus carries the receiver's ACK.
    let expected = frame_bits(&frame, true, None);
    let mut req = vec![Some(frame), None];
    let mut tx_samples: Vec<ChannelOutputs> = Vec::new();
    let mut started = false;
    let mut tx_done_at = None;
    let mut rx_valid_at = None;
    let mut received = None;
    for _ in 0..(expected.len() as u32 + 40) * t.clocks_per_bit() {
        let outs = bus.step(&req);
        req = vec![None, None];
        let (a, b) = (outs[0], outs[1]);
        if a.probes.sample_point && (started || !a.probes.sampled_bit) {
            started = true;
            tx_samples.push(a);
        }
        if a.tx_done {
            assert!(tx_done_at.is_none(), "tx_done pulses once");
            assert!(a.probes.sample_point, "tx_done comes from a SAMPLE edge");
            tx_done_at = Some(tx_samples.len() - 1);
        }
        if b.rx_valid {
            assert!(rx_valid_at.is_none(), "rx_valid pulses once");
            assert!(b.probes.sample_point, "rx_valid comes from a SAMPLE edge");
            // At EOF bit 6: the next bit is still EOF (bit 7).
            assert_eq!(b.probes.field, code::EOF, "rx_valid at EOF bit 6");
            rx_valid_at = Some(bus.clock);
            received = Some(b.rx_frame);
        }
        assert!(
            !a.rx_valid,
            "the transmitter does not receive its own frame"
        );
        assert!(!a.arb_lost && !b.arb_lost);
    }
    assert!(
        tx_samples.len() >= expected.len(),
        "{frame}: frame incomplete"
    );
    for (k, bit) in expected.iter().enumerate() {
        let s = tx_samples[k];
        assert_eq!(s.tx, bit.value, "{frame} {t:?}: tx of bit {k} ({bit:?})");
        let bus_value = if bit.field == code::ACK_SLOT {
            false // the receiver's ACK
        } else {
            bit.value
        };
        assert_eq!(s.probes.sampled_bit, bus_value, "{frame}: bus at bit {k}");
        assert_eq!(
            s.probes.field,
            field_after(&expected, k),
            "{frame}: field probe after bit {k} ({bit:?})"
        );
    }
    assert_eq!(tx_done_at, Some(expected.len() - 1), "tx_done at EOF bit 7");
    assert!(rx_valid_at.is_some(), "{frame}: receiver got nothing");
    assert_eq!(received, Some(frame.normalized()));
    let last = tx_samples.last().unwrap();
    assert!(!last.tx_pending);
    assert_eq!((last.probes.tec, last.probes.err_state), (0, 0));
    // The three intermission bits, then idle: the transmitter stays recessive.
    for s in &tx_samples[expected.len()..] {
        assert!(s.tx);
    }
    assert_eq!(tx_samples[expected.len() + 2].probes.field, code::IDLE);
}

#[test]
fn lone_transmission_bit_exact_brp0() {
    for f in sample_frames() {
        lone_transmission(f, timing(0));
    }
}

#[test]
fn lone_transmission_bit_exact_brp1_and_brp3() {
    for f in sample_frames() {
        lone_transmission(f, timing(1));
        lone_transmission(f, timing(3));
    }
}

#[test]
fn lone_transmission_other_timings() {
    let long = BitTiming {
        brp: 0,
        tseg1: 13,
        tseg2: 2,
        sjw: 2,
        triple_sampling: false,
    };
    // Triple sampling needs the ACK to arrive 2 tq before the sample point: brp 1.
    let triple = BitTiming {
        brp: 1,
        tseg1: 5,
        tseg2: 2,
        sjw: 1,
        triple_sampling: true,
    };
    let wide = BitTiming {
        brp: 2,
        tseg1: 16,
        tseg2: 8,
        sjw: 4,
        triple_sampling: false,
    };
    for f in sample_frames() {
        lone_transmission(f, long);
        lone_transmission(f, triple);
        lone_transmission(f, wide);
    }
}

#[test]
fn receiver_acks_and_takes_frame_from_lower_tester() {
    for f in sample_frames() {
        let mut t = Tester::new(timing(0));
        t.idle(15);
        let bits = frame_bits(&f, true, None);
        let mark = t.samples.len();
        t.drive_all(bits.iter().map(|b| b.value));
        t.idle(5);
        let sof = mark
            + t.samples[mark..]
                .iter()
                .position(|s| !s.probes.sampled_bit)
                .unwrap();
        for (k, bit) in bits.iter().enumerate() {
            let s = t.samples[sof + k];
            let ack = bit.field == code::ACK_SLOT;
            assert_eq!(s.tx, !ack, "{f}: receiver tx at bit {k}");
            assert_eq!(
                s.probes.field,
                field_after(&bits, k),
                "{f}: field after bit {k}"
            );
        }
        assert_eq!(t.received, vec![f.normalized()]);
        assert_eq!(t.last().probes.rec, 0);
    }
}

/// Runs a bus until `clocks` have passed, collecting per node the frames received
/// and the number of tx_done / arb_lost pulses.
struct Traffic {
    received: Vec<Vec<Frame>>,
    done: Vec<u32>,
    lost: Vec<u32>,
    lost_field: Vec<u8>,
    order: Vec<usize>,
}

fn run(bus: &mut Bus, mut req: Vec<Option<Frame>>, clocks: u32) -> Traffic {
    let n = bus.nodes.len();
    let mut tr = Traffic {
        received: vec![Vec::new(); n],
        done: vec![0; n],
        lost: vec![0; n],
        lost_field: Vec::new(),
        order: Vec::new(),
    };
    for _ in 0..clocks {
        let outs = bus.step(&req);
        req = vec![None; n];
        for (i, o) in outs.iter().enumerate() {
            if o.rx_valid {
                tr.received[i].push(o.rx_frame);
            }
            if o.tx_done {
                tr.done[i] += 1;
                tr.order.push(i);
            }
            if o.arb_lost {
                tr.lost[i] += 1;
                tr.lost_field.push(o.probes.field);
            }
            assert_eq!(o.probes.tec, 0, "node {i}: no errors expected");
            assert_eq!(o.probes.rec, 0, "node {i}: no errors expected");
        }
    }
    tr
}

#[test]
fn three_nodes_lower_id_wins_loser_retries() {
    for brp in [0, 1] {
        let t = timing(brp);
        let a = data_frame(0x65B, false, &[0xA0, 0xA1]);
        let b = data_frame(0x65A, false, &[0xB0]);
        let mut bus = Bus::new(3, t);
        bus.integrate();
        let tr = run(
            &mut bus,
            vec![Some(a), Some(b), None],
            300 * t.clocks_per_bit(),
        );
        assert_eq!(tr.order, vec![1, 0], "B (lower id) first, then A's retry");
        assert_eq!(tr.done, vec![1, 1, 0]);
        assert_eq!(tr.lost, vec![1, 0, 0]);
        // The identifiers differ in their last bit: the next field is SRR_RTR.
        assert_eq!(tr.lost_field, vec![code::SRR_RTR]);
        assert_eq!(tr.received[0], vec![b]);
        assert_eq!(tr.received[1], vec![a]);
        assert_eq!(tr.received[2], vec![b, a]);
    }
}

#[test]
fn arbitration_base_beats_extended_and_data_beats_remote() {
    let t = timing(0);
    // Same base identifier: the base data frame wins at SRR (dominant RTR).
    let base = data_frame(0x123, false, &[1]);
    let ext = data_frame(0x123 << 18 | 0x5, true, &[2]);
    let mut bus = Bus::new(3, t);
    bus.integrate();
    let tr = run(
        &mut bus,
        vec![Some(ext), Some(base), None],
        400 * t.clocks_per_bit(),
    );
    assert_eq!(tr.order, vec![1, 0]);
    assert_eq!(
        tr.lost_field,
        vec![code::IDE],
        "lost at SRR, next field IDE"
    );
    assert_eq!(tr.received[2], vec![base, ext]);

    // Base remote frame against extended frame with the same base id: RTR and SRR
    // are both recessive, the extended frame loses at IDE.
    let remote = Frame {
        id: 0x123,
        ide: false,
        rtr: true,
        dlc: 2,
        data: [0; 8],
    };
    let mut bus = Bus::new(3, t);
    bus.integrate();
    let tr = run(
        &mut bus,
        vec![Some(ext), Some(remote), None],
        400 * t.clocks_per_bit(),
    );
    assert_eq!(tr.order, vec![1, 0]);
    assert_eq!(
        tr.lost_field,
        vec![code::R0],
        "lost at IDE (bus: base frame), next R0"
    );
    assert_eq!(tr.received[2], vec![remote, ext]);

    // Extended frames differing in the last extension bit, and a data frame against
    // a remote frame with the same extended identifier.
    let e1 = data_frame(0x0ABC_DEF0, true, &[3]);
    let e2 = data_frame(0x0ABC_DEF1, true, &[4]);
    let mut bus = Bus::new(3, t);
    bus.integrate();
    let tr = run(
        &mut bus,
        vec![Some(e2), Some(e1), None],
        400 * t.clocks_per_bit(),
    );
    assert_eq!(tr.order, vec![1, 0]);
    assert_eq!(tr.lost_field, vec![code::RTR_EXT]);
    let r1 = Frame {
        rtr: true,
        dlc: 1,
        data: [0; 8],
        ..e1
    };
    let mut bus = Bus::new(3, t);
    bus.integrate();
    let tr = run(
        &mut bus,
        vec![Some(r1), Some(e1), None],
        400 * t.clocks_per_bit(),
    );
    assert_eq!(tr.order, vec![1, 0]);
    assert_eq!(tr.lost_field, vec![code::R1]);
    assert_eq!(tr.received[2], vec![e1, r1]);
}

#[test]
fn back_to_back_frames_without_bus_idle() {
    // Node 0 queues a second frame as soon as the first is done: with another
    // node's frame pending too, frames follow each other without bus idle.
    let t = timing(0);
    let f = [
        data_frame(0x100, false, &[1]),
        data_frame(0x200, false, &[2]),
        data_frame(0x101, false, &[3]),
    ];
    let mut bus = Bus::new(3, t);
    bus.integrate();
    let mut req = vec![Some(f[0]), Some(f[1]), None];
    let mut got = Vec::new();
    let mut queued = false;
    for _ in 0..600 * t.clocks_per_bit() {
        let outs = bus.step(&req);
        req = vec![None; 3];
        if outs[0].tx_done && !queued {
            req[0] = Some(f[2]);
            queued = true;
        }
        if outs[2].rx_valid {
            got.push(outs[2].rx_frame);
        }
    }
    assert_eq!(got, vec![f[0], f[2], f[1]]);
}

/// ISO 16845-1 7.3.2 / 7.1.9: a SOF at intermission bit 3 is accepted, so two
/// frames follow each other with only two intermission bits between them.
#[test]
fn receiver_accepts_sof_at_intermission_bit_3() {
    let f1 = data_frame(0x101, false, &[0x10]);
    let f2 = data_frame(0x0ABCDE, true, &[0x20, 0x21]);
    let mut t = Tester::new(timing(0));
    t.idle(15);
    t.drive_all(frame_bits(&f1, true, None).iter().map(|b| b.value));
    t.idle(2);
    t.drive_all(frame_bits(&f2, true, None).iter().map(|b| b.value));
    t.idle(4);
    assert_eq!(t.received, vec![f1, f2]);
    assert_eq!(t.last().probes.rec, 0);
}

/// ISO 16845-1 8.1.8 / 8.4.3: a node with a pending frame that sees a dominant
/// intermission bit 3 takes it as SOF and sends its identifier from the next bit.
#[test]
fn pending_frame_starts_on_sof_at_intermission_bit_3() {
    let f1 = data_frame(0x101, false, &[0x10]);
    let g = data_frame(0x2F3, false, &[0x77]);
    let mut t = Tester::new(timing(0));
    t.idle(15);
    let bits = frame_bits(&f1, true, None);
    t.drive_all(bits[..10].iter().map(|b| b.value));
    t.request = Some(g); // latched while receiving f1
    t.drive_all(bits[10..].iter().map(|b| b.value));
    t.idle(2);
    let mark = t.samples.len();
    t.drive(false); // intermission bit 3: another node's SOF
    t.idle(30);
    assert_eq!(t.received, vec![f1]);
    let expected = frame_bits(&g, true, None);
    let s = &t.samples[mark..];
    assert!(!s[0].probes.sampled_bit);
    // ISO 11898-1 10.4.6: a node joining at intermission bit 3 sends no SOF bit.
    assert!(
        s[0].tx,
        "no SOF bit of its own when joining at intermission bit 3"
    );
    assert_eq!(s[0].probes.field, code::ID_A);
    // From the first identifier bit on, the node drives g (the tester is recessive).
    for k in 1..25 {
        assert_eq!(s[k].tx, expected[k].value, "bit {k}");
    }
}
