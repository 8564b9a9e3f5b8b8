//! Single shot and `tx_abort` (timing contract §8).

use super::*;

/// Single shot, lost arbitration: `arb_lost` and `tx_failed` at the same edge,
/// `tx_pending` clears, no retry (the loser then only sends the winner's ACK).
/// Without single shot the loser retries and succeeds.
#[test]
fn single_shot_drops_frame_on_lost_arbitration() {
    for shot in [true, false] {
        let mut bus = Bus::new(2, timing(0));
        bus.configs[0] = ControllerConfig {
            single_shot: shot,
            ..ControllerConfig::default()
        };
        bus.reset();
        bus.integrate();
        // 0x200 = 010 0000 0000 loses to 0x100 = 001 0000 0000 at base-ID bit 1.
        let (a, b) = (frame(0x200, &[0xA0]), frame(0x100, &[0xB0]));
        bus.step(&[Some(a), Some(b)]);
        let mut lost_at = None;
        let (mut failed, mut done, mut falls) = (0, 0, 0);
        let mut rx1 = Vec::new();
        let mut prev_tx = true;
        for _ in 0..400 * 8 {
            let o = bus.step(&[]);
            if o[0].arb_lost {
                assert!(lost_at.is_none(), "one arbitration loss");
                lost_at = Some(bus.clock);
                assert_eq!(o[0].diag.alc, 1);
                assert_eq!(o[0].tx_failed, shot);
                assert_eq!(o[0].tx_pending, !shot);
            }
            failed += o[0].tx_failed as usize;
            done += o[0].tx_done as usize;
            if lost_at.is_some() && prev_tx && !o[0].tx {
                falls += 1;
            }
            prev_tx = o[0].tx;
            if o[1].rx_valid {
                rx1.push(o[1].rx_frame);
            }
            assert!(!o[0].diag.err_valid && !o[1].diag.err_valid);
        }
        assert!(lost_at.is_some());
        if shot {
            assert_eq!(
                (failed, done, falls),
                (1, 0, 1),
                "only the ACK after the loss"
            );
            assert!(rx1.is_empty());
        } else {
            assert_eq!((failed, done), (0, 1));
            assert_eq!(rx1, vec![a.normalized()]);
        }
    }
}

/// Single shot, ACK error of a lone transmitter: `tx_failed` at the ACK error's
/// SAMPLE edge, TEC + 8 once, no retransmission (after its error flag the node
/// stays recessive).
#[test]
fn single_shot_drops_frame_on_ack_error() {
    let t = timing(0);
    let mut bus = Bus::new(1, t);
    bus.configs[0] = single_shot();
    bus.reset();
    bus.integrate();
    bus.step(&[Some(frame(0x155, &[0x3C]))]);
    let mut fail_at = None;
    let mut last_dominant = 0;
    for _ in 0..600 * 8 {
        let o = bus.step(&[])[0];
        if o.tx_failed {
            assert!(fail_at.is_none());
            fail_at = Some(bus.clock);
            assert!(o.diag.err_valid && o.diag.err_kind == KIND_ACK && o.diag.err_tx);
            assert!(!o.tx_pending);
            assert_eq!(o.probes.tec, 8);
        }
        if !o.tx {
            last_dominant = bus.clock;
        }
        assert!(!o.tx_done);
    }
    let fail_at = fail_at.expect("tx_failed");
    // The active error flag: 6 dominant bits from the next bit_start (<= 1 bit + 6).
    assert!(last_dominant > fail_at && last_dominant <= fail_at + 7 * 8);
    let o = bus.step(&[])[0];
    assert_eq!((o.probes.tec, o.diag.cnt_ack), (8, 1));
}

/// `tx_abort` before the SOF: for every abort time after a request in IDLE, either
/// the node has not put its SOF on `tx` yet (`tx` register recessive before the
/// edge): the frame is dropped at that edge and never sent, also when that edge is
/// the bit_start that would have started the SOF; or the SOF is on `tx`: the
/// attempt runs on and succeeds (`tx_done`, no `tx_failed`).
#[test]
fn tx_abort_before_start() {
    let f = frame(0x0AA, &[0x01]);
    let (mut dropped, mut ran_on) = (0, 0);
    for d in 1..=12u32 {
        let mut bus = Bus::new(2, timing(0));
        bus.reset();
        bus.integrate();
        // An abort with nothing pending does nothing.
        bus.abort[0] = true;
        let o = bus.step(&[])[0];
        assert!(!o.tx_failed);
        let mut prev = bus.step(&[Some(f)])[0];
        assert!(prev.tx_pending);
        for _ in 1..d {
            prev = bus.step(&[])[0];
        }
        bus.abort[0] = true;
        let o = bus.step(&[])[0];
        let mut outs = Vec::new();
        for _ in 0..200 * 8 {
            outs.push(bus.step(&[]));
        }
        let done = outs.iter().filter(|o| o[0].tx_done).count();
        let failed = outs.iter().filter(|o| o[0].tx_failed).count();
        let rx1 = outs.iter().filter(|o| o[1].rx_valid).count();
        if prev.tx {
            dropped += 1;
            assert!(
                o.tx_failed && !o.tx_pending,
                "d {d}: dropped at the abort edge"
            );
            assert!(o.tx, "d {d}: no SOF started at the abort edge");
            assert!(outs.iter().all(|o| o[0].tx), "d {d}: never sent");
            assert_eq!((done, failed, rx1), (0, 0, 0));
        } else {
            ran_on += 1;
            assert!(!o.tx_failed && o.tx_pending, "d {d}: attempt runs on");
            assert_eq!((done, failed, rx1), (1, 0, 1), "d {d}");
        }
    }
    assert!(dropped > 0 && ran_on > 0, "both cases covered");
}

/// `tx_abort` and `tx_req` at the same edge with nothing pending: the abort does
/// nothing, the frame is latched and sent.
#[test]
fn tx_abort_with_request_at_same_edge_does_nothing() {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    bus.abort[0] = true;
    let o = bus.step(&[Some(frame(0x10, &[1]))])[0];
    assert!(o.tx_pending && !o.tx_failed);
    let outs = record(&mut bus, 200 * 8, 0);
    assert_eq!(outs.iter().filter(|o| o.tx_done).count(), 1);
    assert!(outs.iter().all(|o| !o.tx_failed));
}

/// `tx_abort` while the frame waits behind another node's frame (receiver, `tx`
/// recessive): dropped at once; the node then only sends its ACK.
#[test]
fn tx_abort_while_waiting_for_the_bus() {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[None, Some(frame(0x100, &[0xFF; 8]))]);
    // Wait until node 1 is in its data field, then request on node 0.
    while bus.step(&[])[1].probes.field != code::DATA {}
    let o = bus.step(&[Some(frame(0x001, &[0x22])), None])[0];
    assert!(o.tx_pending);
    for _ in 0..20 {
        bus.step(&[]);
    }
    bus.abort[0] = true;
    let o = bus.step(&[])[0];
    assert!(o.tx_failed && !o.tx_pending);
    let outs = record(&mut bus, 300 * 8, 0);
    assert!(outs
        .iter()
        .all(|o| !o.tx_done && !o.tx_failed && !o.tx_pending));
    let dominant = outs.iter().filter(|o| !o.tx).count();
    assert_eq!(dominant, 8, "only the one-bit ACK");
}

/// `tx_abort` during an attempt that succeeds: remembered, then forgotten at
/// `tx_done`; nothing is dropped.
#[test]
fn tx_abort_during_successful_attempt() {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    let f = frame(0x2F0, &[0x12, 0x34, 0x56]);
    bus.step(&[Some(f), None]);
    while bus.step(&[])[0].probes.field != code::DATA {}
    bus.abort[0] = true;
    let o = bus.step(&[])[0];
    assert!(o.tx_pending && !o.tx_failed, "transmitting: remembered");
    let outs = record(&mut bus, 300 * 8, 0);
    assert_eq!(outs.iter().filter(|o| o.tx_done).count(), 1);
    assert!(outs.iter().all(|o| !o.tx_failed && !o.diag.err_valid));
    // Forgotten: a new frame is sent normally.
    bus.step(&[Some(f), None]);
    let outs = record(&mut bus, 300 * 8, 0);
    assert_eq!(outs.iter().filter(|o| o.tx_done).count(), 1);
    assert!(outs.iter().all(|o| !o.tx_failed));
}

/// `tx_abort` during an attempt that fails (ACK error of a lone transmitter,
/// automatic retransmission on): dropped at the failing edge, no retry.
#[test]
fn tx_abort_during_failing_attempt() {
    let mut bus = Bus::new(1, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(frame(0x2F0, &[0x12]))]);
    while bus.step(&[])[0].probes.field != code::DLC {}
    bus.abort[0] = true;
    let o = bus.step(&[])[0];
    assert!(o.tx_pending && !o.tx_failed);
    let outs = record(&mut bus, 400 * 8, 0);
    let fail: Vec<usize> = (0..outs.len()).filter(|&k| outs[k].tx_failed).collect();
    assert_eq!(fail.len(), 1);
    let o = outs[fail[0]];
    assert!(o.diag.err_valid && o.diag.err_kind == KIND_ACK && !o.tx_pending);
    assert_eq!(o.probes.tec, 8, "one attempt");
    // Error flag, then silence.
    assert!(outs[fail[0] + 7 * 8..].iter().all(|o| o.tx));
}

/// `tx_abort` during arbitration, then arbitration is lost: `arb_lost` and
/// `tx_failed` at the same edge.
#[test]
fn tx_abort_during_arbitration_then_lost() {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    // 0x7F0 loses to 0x7E0 at base-ID bit 6.
    bus.step(&[Some(frame(0x7F0, &[])), Some(frame(0x7E0, &[]))]);
    while bus.step(&[])[0].probes.field != code::ID_A {}
    bus.abort[0] = true;
    let o = bus.step(&[])[0];
    assert!(o.tx_pending && !o.tx_failed);
    let outs = record(&mut bus, 200 * 8, 0);
    let k = outs
        .iter()
        .position(|o| o.arb_lost)
        .expect("arbitration lost");
    assert!(outs[k].tx_failed && !outs[k].tx_pending);
    assert_eq!(outs[k].diag.alc, 6);
    assert_eq!(outs.iter().filter(|o| o.tx_failed).count(), 1);
    assert!(outs.iter().all(|o| !o.tx_done));
}

/// A remembered abort while no attempt is on the bus (the node lost arbitration and
/// is sending its ACK, `tx` dominant) is carried out at the first edge where the
/// node is not transmitter and its `tx` register is recessive (contract §8).
#[test]
fn tx_abort_during_own_ack_waits_for_recessive_tx() {
    let mut bus = Bus::new(2, timing(0));
    bus.reset();
    bus.integrate();
    bus.step(&[Some(frame(0x400, &[1])), Some(frame(0x001, &[2]))]);
    let mut lost = false;
    loop {
        let o = bus.step(&[])[0];
        lost |= o.arb_lost;
        if lost && !o.tx {
            break; // node 0's ACK is on tx
        }
    }
    assert!(bus.step(&[])[0].tx_pending);
    bus.abort[0] = true;
    let o = bus.step(&[])[0];
    assert!(
        !o.tx && o.tx_pending && !o.tx_failed,
        "remembered while ACK is sent"
    );
    let outs = record(&mut bus, 300 * 8, 0);
    let first_recessive = outs.iter().position(|o| o.tx).unwrap();
    let fail = outs.iter().position(|o| o.tx_failed).expect("carried out");
    assert_eq!(fail, first_recessive + 1);
    assert!(!outs[fail].tx_pending);
    assert!(outs[first_recessive..].iter().all(|o| o.tx && !o.tx_done));
    assert_eq!(outs.iter().filter(|o| o.tx_failed).count(), 1);
}

/// LISTEN_ONLY follows an overload flag without checking it: a lower tester
/// sends a frame and one dominant intermission bit 1, then only recessive bits. A
/// normal node would read its own dominant overload flag; the listen-only node
/// sends recessive, reads recessive, and still raises no error.
#[test]
fn listen_only_follows_overload_flag_unchecked() {
    let f = frame(0x2C4, &[0x81]);
    let mut bits: Vec<bool> = model_support::frame_bits(&f, false, None)
        .iter()
        .map(|b| b.value)
        .collect();
    bits.push(false); // intermission bit 1: overload condition
    let mut t = Tester::with_config(timing(0), cfg(Mode::ListenOnly));
    t.idle(20);
    t.record = true;
    t.drive_all(bits);
    t.idle(30);
    let fields: Vec<u8> = t.samples.iter().map(|o| o.probes.field).collect();
    let first_ovl = fields
        .iter()
        .position(|&x| x == code::OVERLOAD_FLAG)
        .unwrap();
    let first_delim = fields
        .iter()
        .position(|&x| x == code::OVERLOAD_DELIM)
        .unwrap();
    assert_eq!(first_delim - first_ovl, 6, "6 flag bits followed");
    assert!(fields[first_delim..].contains(&code::IDLE));
    assert!(t.trace.iter().all(|o| o.tx && !o.diag.err_valid));
    assert_eq!(t.received, vec![f.normalized()]);
}

/// Single shot drops only a frame whose attempt fails: a frame latched during
/// the intermission after a successful one (the node is still transmitter there,
/// §4.5 roles) survives an error detected before its own SOF (a form error in an
/// overload delimiter, captured with `err_tx`), and is sent afterwards.
#[test]
fn single_shot_keeps_frame_not_yet_attempted() {
    let t = timing(0);
    let bpc = t.clocks_per_bit();
    let mut bus = Bus::new(2, t);
    bus.configs[0] = single_shot();
    bus.reset();
    bus.integrate();
    let (f1, f2) = (frame(0x111, &[1]), frame(0x222, &[2]));
    bus.step(&[Some(f1), None]);
    while !bus.step(&[])[0].tx_done {}
    let o = bus.step(&[Some(f2), None])[0];
    assert!(o.tx_pending);
    // Dominant intermission bit 2: overload frame.
    let mut outs = Vec::new();
    let force_next_but_one = |bus: &mut Bus, outs: &mut Vec<Vec<ChannelOutputs>>| {
        for _ in 0..bpc {
            outs.push(bus.step(&[]));
        }
        bus.force_dominant = true;
        for _ in 0..bpc {
            outs.push(bus.step(&[]));
        }
        bus.force_dominant = false;
    };
    force_next_but_one(&mut bus, &mut outs);
    // End of the 6-bit overload flag, then dominant delimiter bit 2: form error.
    loop {
        let o = bus.step(&[]);
        outs.push(o.clone());
        if o[0].probes.sample_point && o[0].probes.field == code::OVERLOAD_DELIM {
            break;
        }
    }
    force_next_but_one(&mut bus, &mut outs);
    for _ in 0..300 * bpc {
        outs.push(bus.step(&[]));
    }
    let errs: Vec<_> = outs.iter().filter(|o| o[0].diag.err_valid).collect();
    assert!(!errs.is_empty());
    assert_eq!(errs[0][0].diag.err_kind, KIND_FORM);
    assert!(
        errs[0][0].diag.err_tx,
        "still transmitter (role) after its frame"
    );
    assert!(outs.iter().all(|o| !o[0].tx_failed));
    assert_eq!(outs.iter().filter(|o| o[0].tx_done).count(), 1);
    let rx: Vec<Frame> = outs
        .iter()
        .filter(|o| o[1].rx_valid)
        .map(|o| o[1].rx_frame)
        .collect();
    assert_eq!(rx, vec![f2.normalized()]);
}
