//! Operating modes (timing contract §7): listen-only, self test, loop-back.

use super::*;

/// LISTEN_ONLY: across frames, arbitration, a bit error with error frames and an
/// overload frame, the node never drives dominant, TEC and REC stay 0, it receives
/// every frame that was sent successfully, refuses `tx_req` with `tx_failed`, and
/// still detects and captures (stuff/CRC/form) errors.
#[test]
fn listen_only_is_completely_passive() {
    let t = timing(0);
    let bpc = t.clocks_per_bit();
    let mut bus = Bus::new(3, t);
    bus.configs[0] = cfg(Mode::ListenOnly);
    bus.reset();
    bus.integrate();
    let frames1 = [
        frame(0x123, &[0x11, 0x22]),
        frame(0x0F0, &[0x0F, 0xF0, 0x00]),
        frame(0x555, &[0xFF; 8]),
        frame(0x001, &[]),
    ];
    let frame2 = frame(0x0F1, &[0xAB]);
    let mut sent = Vec::new();
    let mut rx0 = Vec::new();
    let mut errors0 = Vec::new();
    let mut refused = 0;
    let mut checks = |o: &[ChannelOutputs], sent: &mut Vec<Frame>, pending: &[Frame; 3]| {
        assert!(o[0].tx, "listen-only node drives dominant");
        assert_eq!((o[0].probes.tec, o[0].probes.rec), (0, 0));
        assert!(!o[0].tx_pending && !o[0].tx_done && !o[0].arb_lost);
        if o[0].rx_valid {
            rx0.push(o[0].rx_frame);
        }
        if o[0].diag.err_valid {
            errors0.push(o[0].diag);
        }
        for i in 1..3 {
            if o[i].tx_done {
                sent.push(pending[i].normalized());
            }
        }
    };
    let mut pending = [Frame::default(); 3];
    // Phase 1: plain frames; phase 2: node 1 and 2 arbitrate; node 0 asks too.
    for (n, &f) in frames1.iter().enumerate() {
        let mut req = vec![Some(frame(0x7FF, &[1])), Some(f), None];
        pending[1] = f;
        if n == 1 {
            req[2] = Some(frame2);
            pending[2] = frame2;
        }
        let o = bus.step(&req);
        assert!(o[0].tx_failed && !o[0].tx_pending, "tx_req refused");
        refused += 1;
        checks(&o, &mut sent, &pending);
        for _ in 0..300 * bpc {
            let o = bus.step(&[]);
            checks(&o, &mut sent, &pending);
            assert!(!o[0].tx_failed);
        }
    }
    // Phase 3: a bit error of node 1 in its data field (forced dominant bit).
    let f = frame(0x321, &[0x0F, 0x0F]);
    pending[1] = f;
    bus.step(&[None, Some(f)]);
    let mut forced = false;
    let mut prev_tx = true;
    for _ in 0..400 * bpc {
        let o = bus.step(&[]);
        checks(&o, &mut sent, &pending);
        // The bit_start of a recessive data bit after a dominant one.
        let rising = !prev_tx && o[1].tx;
        prev_tx = o[1].tx;
        if !forced && rising && o[1].probes.field == code::DATA {
            forced = true;
            bus.force_dominant = true;
            for _ in 0..bpc {
                let o = bus.step(&[]);
                checks(&o, &mut sent, &pending);
            }
            bus.force_dominant = false;
        }
    }
    assert!(forced);
    // Phase 4: overload frame (dominant intermission bit 1 after a frame).
    let f = frame(0x3C3, &[0x99]);
    pending[1] = f;
    bus.step(&[None, Some(f)]);
    let mut forced = false;
    let mut overload_seen = false;
    for _ in 0..300 * bpc {
        let o = bus.step(&[]);
        checks(&o, &mut sent, &pending);
        overload_seen |= o[0].probes.field == code::OVERLOAD_FLAG;
        if !forced && o[0].probes.sample_point && o[0].probes.field == code::INTERMISSION {
            forced = true;
            // Node 0 has just sampled EOF bit 7; force the next bit.
            for _ in 0..bpc {
                let o = bus.step(&[]);
                checks(&o, &mut sent, &pending);
            }
            bus.force_dominant = true;
            for _ in 0..bpc {
                let o = bus.step(&[]);
                checks(&o, &mut sent, &pending);
            }
            bus.force_dominant = false;
        }
    }
    assert!(forced && overload_seen, "overload frame followed");
    assert_eq!(refused, frames1.len());
    assert_eq!(sent.len(), frames1.len() + 3, "every frame sent once");
    assert_eq!(rx0, sent, "listen-only node receives every frame");
    assert!(!errors0.is_empty(), "errors still detected");
    for d in &errors0 {
        assert!(
            matches!(d.err_kind, KIND_STUFF | KIND_CRC | KIND_FORM),
            "listen-only has no bit or ACK errors: {d:?}"
        );
        assert!(!d.err_tx);
    }
    let last = bus.step(&[])[0].diag;
    assert_eq!((last.cnt_bit, last.cnt_ack), (0, 0));
    assert_eq!(
        (last.cnt_stuff + last.cnt_crc + last.cnt_form) as usize,
        errors0.len()
    );
}

/// LISTEN_ONLY as the only other node: a transmitter gets no ACK; the listen-only
/// node follows the error frame with a passive flag and never counts.
#[test]
fn listen_only_never_acks() {
    let mut bus = Bus::new(2, timing(0));
    bus.configs[1] = cfg(Mode::ListenOnly);
    bus.reset();
    bus.integrate();
    bus.step(&[Some(frame(0x100, &[0x42])), None]);
    let mut ack_errors = 0;
    let mut passive_rx = 0;
    for _ in 0..2000 * 8 {
        let o = bus.step(&[]);
        assert!(o[1].tx);
        assert_eq!((o[1].probes.tec, o[1].probes.rec), (0, 0));
        if o[0].probes.err_state == 0 {
            // An error-active transmitter's flag destroys the frame at the ACK
            // delimiter; an error-passive one's passive flag does not.
            assert!(
                !o[1].rx_valid,
                "ACK error: frame destroyed at the ACK delimiter"
            );
        } else {
            passive_rx += o[1].rx_valid as usize;
        }
        if o[0].diag.err_valid {
            assert_eq!(o[0].diag.err_kind, KIND_ACK);
            ack_errors += 1;
        }
    }
    assert!(ack_errors > 16, "into error passive");
    assert!(passive_rx > 0);
}

/// SELF_TEST: a lone transmitter accepts its recessive ACK slot: `tx_done`, TEC
/// stays 0, no error; a listen-only node on the same bus receives the frame.
#[test]
fn self_test_lone_transmitter_succeeds() {
    for brp in [0u16, 2] {
        let t = timing(brp);
        let mut bus = Bus::new(2, t);
        bus.configs[0] = cfg(Mode::SelfTest);
        bus.configs[1] = cfg(Mode::ListenOnly);
        bus.reset();
        bus.integrate();
        let frames = [frame(0x6E1, &[1, 2, 3, 4, 5]), frame(0x012, &[])];
        let mut done = 0;
        let mut rx = Vec::new();
        let mut ack_slot_bus = Vec::new();
        let mut prev_field = code::IDLE;
        for f in frames {
            bus.step(&[Some(f), None]);
            for _ in 0..200 * t.clocks_per_bit() {
                let o = bus.step(&[]);
                assert_eq!((o[0].probes.tec, o[0].probes.rec), (0, 0));
                assert!(!o[0].diag.err_valid && !o[1].diag.err_valid);
                assert!(!o[0].tx_failed && !o[0].arb_lost);
                if o[0].probes.sample_point {
                    if prev_field == code::ACK_SLOT {
                        ack_slot_bus.push(o[0].probes.sampled_bit);
                    }
                    prev_field = o[0].probes.field;
                }
                done += o[0].tx_done as usize;
                assert!(!o[0].rx_valid, "SELF_TEST does not deliver own frames");
                if o[1].rx_valid {
                    rx.push(o[1].rx_frame);
                }
            }
            assert!(!bus.step(&[])[0].tx_pending);
        }
        assert_eq!(done, 2);
        assert_eq!(ack_slot_bus, vec![true, true], "nobody acknowledged");
        assert_eq!(rx, frames.map(|f| f.normalized()).to_vec());
    }
}

/// LOOPBACK: the `tx` pin stays recessive, the node hears only itself, receives
/// its own frame (`rx_valid` at EOF bit 6, `tx_done` one bit later at EOF bit 7);
/// a normal node on the bus sees nothing and its traffic does not reach the
/// loop-back node.
#[test]
fn loopback_receives_own_frame_with_pin_recessive() {
    for brp in [0u16, 1] {
        let t = timing(brp);
        let bpc = t.clocks_per_bit() as u64;
        let mut bus = Bus::new(2, t);
        bus.configs[0] = cfg(Mode::Loopback);
        bus.reset();
        bus.integrate();
        let frames = [frame(0x5A5, &[0xDE, 0xAD]), frame(0x7FF, &[0; 8])];
        let mut rx = Vec::new();
        let mut done = Vec::new();
        // Node 1 transmits too: it gets no ACK (ACK errors), node 0 ignores it.
        bus.step(&[None, Some(frame(0x001, &[0x11]))]);
        for f in frames {
            bus.step(&[Some(f), None]);
            for _ in 0..200 * bpc {
                let o = bus.step(&[]);
                assert!(o[0].tx, "loop-back pin stays recessive");
                assert_eq!((o[0].probes.tec, o[0].probes.rec), (0, 0));
                assert!(!o[0].diag.err_valid && !o[0].arb_lost && !o[0].tx_failed);
                assert!(!o[1].rx_valid, "nothing reaches the bus");
                if o[0].rx_valid {
                    rx.push((bus.clock, o[0].rx_frame));
                }
                if o[0].tx_done {
                    done.push(bus.clock);
                }
            }
        }
        assert_eq!(rx.len(), 2);
        assert_eq!(done.len(), 2);
        for k in 0..2 {
            assert_eq!(rx[k].1, frames[k].normalized());
            assert_eq!(done[k] - rx[k].0, bpc, "tx_done one bit after rx_valid");
        }
    }
}
