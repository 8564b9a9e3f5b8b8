//! Reference model, error handling and fault confinement (ISO 11898-1 clause 12,
//! error counting rules a to l). Expected values come from the standard's rules.

mod model_support;

use drcc_cosim::Frame;
use model_support::{
    bus_off_node_0, code, frame_bits, samples_to_recovery, timing, Bus, Tester, RECOVERY_SAMPLES,
};

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

/// A lone transmitter (nobody ACKs): every attempt ends in an ACK error. TEC goes
/// +8 per attempt (rule c) up to 128, where the node turns error passive at the
/// same clock edge (rule i); from then on rule c exception 1 keeps TEC at 128.
/// The error flag is active (6 dominant bits) while error active and passive
/// afterwards, and a passive transmitter suspends transmission for 8 bits: the
/// next SOF is the 18th bit after the ACK slot when active (6 flag + 8 delimiter +
/// 3 intermission) and the 26th when passive (+ 8 suspend).
#[test]
fn ack_errors_raise_tec_to_128_then_exception_1_holds_it() {
    for brp in [0u16, 1] {
        let t = timing(brp);
        let mut bus = Bus::new(1, t);
        bus.integrate();
        let mut req = vec![Some(frame(0x2A5, &[0xC3]))];
        let mut tec = 0u16;
        let mut passive_seen_at = None;
        let mut samples = Vec::new();
        let mut prev_field = code::IDLE;
        let mut ack_slots = Vec::new();
        let mut sofs = Vec::new();
        for clock in 0..(40 * 100 * t.clocks_per_bit()) {
            let o = bus.step(&req)[0];
            req = vec![None];
            let p = o.probes;
            if p.tec != tec {
                assert_eq!(p.tec, tec + 8, "TEC moves by +8 only");
                tec = p.tec;
            }
            assert!(tec <= 128, "exception 1: no increment while error passive");
            assert_eq!(p.err_state, (tec >= 128) as u8, "state follows TEC at once");
            if p.err_state == 1 && passive_seen_at.is_none() {
                passive_seen_at = Some(clock);
            }
            assert!(o.tx_pending && !o.tx_done);
            if p.sample_point {
                if prev_field == code::ACK_SLOT {
                    ack_slots.push((samples.len(), p.tec));
                }
                if p.field == code::ID_A
                    && matches!(prev_field, code::IDLE | code::SUSPEND | code::INTERMISSION)
                {
                    sofs.push(samples.len());
                }
                prev_field = p.field;
                samples.push(o);
            }
        }
        assert_eq!(tec, 128);
        assert!(passive_seen_at.is_some());
        assert!(ack_slots.len() > 20, "many attempts");
        for (n, &(k, tec_after)) in ack_slots.iter().enumerate() {
            let expected = ((n as u16 + 1) * 8).min(128);
            assert_eq!(tec_after, expected, "attempt {n}");
            let active_flag = tec_after < 128;
            for j in 1..=6 {
                assert_eq!(samples[k + j].tx, !active_flag, "attempt {n} flag bit {j}");
            }
            let next_sof = sofs.iter().find(|&&s| s > k);
            if let Some(&s) = next_sof {
                let gap = if active_flag { 18 } else { 26 };
                assert_eq!(s - k, gap, "attempt {n}: bits from ACK slot to next SOF");
            }
        }
    }
}

/// Receiver: CRC error. No ACK, the active error flag starts at the bit after the
/// ACK delimiter, REC + 1 (rule a); a following valid frame brings REC back to 0
/// (rule h).
#[test]
fn crc_error_flag_after_ack_delimiter() {
    let f = frame(0x3C5, &[0x11, 0x22, 0x33]);
    let mut t = Tester::new(timing(0));
    t.idle(15);
    let bits = frame_bits(&f, true, Some(4));
    let mark = t.samples.len();
    // Drive up to the ACK delimiter, then recessive: only the node's flag is dominant.
    let until = bits
        .iter()
        .position(|b| b.field == code::ACK_DELIM)
        .unwrap();
    t.drive_all(bits[..=until].iter().map(|b| b.value));
    t.idle(6 + 8 + 3 + 4);
    let s = &t.samples[mark..];
    let sof = s.iter().position(|s| !s.probes.sampled_bit).unwrap();
    let ack = sof + until - 1;
    let delim = sof + until;
    assert!(s[ack].tx, "no ACK for a bad CRC");
    assert_eq!(s[ack].probes.rec, 0);
    assert_eq!(s[delim].probes.rec, 1, "REC + 1 at the ACK delimiter");
    assert_eq!(s[delim].probes.field, code::ERROR_FLAG);
    for j in 1..=6 {
        assert!(!s[delim + j].tx, "active flag bit {j}");
    }
    assert_eq!(s[delim + 6].probes.field, code::ERROR_DELIM);
    assert!(s[delim + 7..delim + 7 + 11].iter().all(|s| s.tx));
    assert_eq!(s[delim + 14].probes.field, code::INTERMISSION);
    assert_eq!(s[delim + 17].probes.field, code::IDLE);
    assert!(t.received.is_empty());
    // A valid frame: REC - 1.
    t.drive_all(frame_bits(&f, true, None).iter().map(|b| b.value));
    t.idle(5);
    assert_eq!(t.received, vec![f]);
    assert_eq!(t.last().probes.rec, 0);
}

/// Drives SOF and identifier bits 0 up to the first stuff bit (SOF and 4
/// identifier bits make 5 equal bits), which is sent dominant: a stuff error at
/// the 6th dominant bit.
fn stuff_error(t: &mut Tester) {
    t.drive_all([false; 6]);
}

/// Receiver: stuff error (rule a, +1), dominant first bit after its active flag
/// (rule b, +8), up to 7 dominant bits tolerated after the flag, the 8th (the 14th
/// counted from the flag's start) +8 and every further 8 dominant bits +8 (rule f).
#[test]
fn stuff_error_rule_b_and_rule_f() {
    let mut t = Tester::new(timing(0));
    t.idle(15);
    stuff_error(&mut t);
    let p = t.last().probes;
    assert_eq!((p.rec, p.field), (1, code::ERROR_FLAG));
    t.idle(6); // the node's own 6 flag bits make the bus dominant
    assert_eq!(t.samples.iter().rev().take(6).filter(|s| !s.tx).count(), 6);
    assert_eq!(t.last().probes.field, code::ERROR_DELIM);
    t.drive(false);
    assert_eq!(t.last().probes.rec, 9, "rule b");
    t.drive_all([false; 6]);
    assert_eq!(
        t.last().probes.rec,
        9,
        "7 dominant bits tolerated (13-bit flag)"
    );
    t.drive(false);
    assert_eq!(t.last().probes.rec, 17, "14th dominant bit");
    t.drive_all([false; 7]);
    assert_eq!(t.last().probes.rec, 17);
    t.drive(false);
    assert_eq!(t.last().probes.rec, 25, "each further 8 dominant bits");
    t.idle(7);
    assert_eq!(t.last().probes.field, code::ERROR_DELIM);
    t.idle(1);
    assert_eq!(t.last().probes.field, code::INTERMISSION);
    t.idle(3);
    assert_eq!(t.last().probes.field, code::IDLE);
    assert_eq!(t.last().probes.rec, 25);

    // Exactly 7 dominant bits after the flag and then a clean delimiter: only the
    // rule a and rule b increments.
    let mut t = Tester::new(timing(0));
    t.idle(15);
    stuff_error(&mut t);
    t.idle(6);
    t.drive_all([false; 7]);
    t.idle(8 + 3);
    let p = t.last().probes;
    assert_eq!((p.rec, p.field), (9, code::IDLE));
}

/// Form error in the error delimiter (a dominant bit among delimiter bits 2..7):
/// REC + 1 and a new error flag; a dominant 8th delimiter bit starts an overload
/// frame without counter change.
#[test]
fn delimiter_form_error_and_overload_at_8th_bit() {
    let mut t = Tester::new(timing(0));
    t.idle(15);
    stuff_error(&mut t);
    t.idle(6 + 3);
    t.drive(false); // 4th delimiter bit
    let p = t.last().probes;
    assert_eq!((p.rec, p.field), (2, code::ERROR_FLAG));
    t.idle(6 + 7);
    t.drive(false); // 8th delimiter bit
    let p = t.last().probes;
    assert_eq!((p.rec, p.field), (2, code::OVERLOAD_FLAG));
    t.idle(6);
    assert!(
        t.samples.iter().rev().take(6).all(|s| !s.tx),
        "overload flag"
    );
    // A dominant bit right after the overload flag: no rule b for overload flags.
    t.drive(false);
    t.idle(8 + 3);
    let p = t.last().probes;
    assert_eq!((p.rec, p.field), (2, code::IDLE));
}

/// Receiver overload frames: dominant EOF bit 7 (the frame is already valid), and
/// dominant intermission bit 1; counters do not change.
#[test]
fn overload_frames_after_valid_frame() {
    let f = frame(0x0F0, &[0xAB]);
    let mut t = Tester::new(timing(0));
    t.idle(15);
    let mut bits: Vec<bool> = frame_bits(&f, true, None).iter().map(|b| b.value).collect();
    *bits.last_mut().unwrap() = false; // EOF bit 7 dominant
    t.drive_all(bits);
    assert_eq!(t.received, vec![f], "valid at EOF bit 6");
    assert_eq!(t.last().probes.field, code::OVERLOAD_FLAG);
    t.idle(6 + 8);
    assert_eq!(t.last().probes.field, code::INTERMISSION);
    t.drive(false); // intermission bit 1
    assert_eq!(t.last().probes.field, code::OVERLOAD_FLAG);
    t.idle(6 + 8 + 3);
    let p = t.last().probes;
    assert_eq!((p.rec, p.tec, p.field), (0, 0, code::IDLE));
}

/// REC above 127 makes the receiver error passive (rule i): its error flag is
/// passive (recessive). A valid frame then sets REC to a value in 119..=127 and the
/// node is error active again (rules h, k).
#[test]
fn rec_above_127_passive_flag_then_valid_frame() {
    let mut t = Tester::new(timing(0));
    t.idle(15);
    stuff_error(&mut t);
    t.idle(6);
    // 1 (rule a) + 8 (rule b) + 16 x 8 (rule f) = 137.
    t.drive_all(std::iter::repeat_n(false, 129));
    let p = t.last().probes;
    assert_eq!((p.rec, p.err_state), (137, 1));
    let first_passive = t
        .samples
        .iter()
        .position(|s| s.probes.err_state == 1)
        .unwrap();
    assert_eq!(t.samples[first_passive].probes.rec, 129);
    t.idle(8 + 3 + 2);
    // A stuff error while error passive: the flag is recessive.
    stuff_error(&mut t);
    assert_eq!(t.last().probes.rec, 138);
    t.idle(6 + 8 + 3 + 2);
    assert!(
        t.samples.iter().rev().take(19).all(|s| s.tx),
        "passive flag"
    );
    assert_eq!(t.last().probes.field, code::IDLE);
    let f = frame(0x555, &[0x01]);
    t.drive_all(frame_bits(&f, true, None).iter().map(|b| b.value));
    t.idle(4);
    assert_eq!(t.received, vec![f]);
    let p = t.last().probes;
    assert!(
        (119..=127).contains(&p.rec),
        "REC {} after a valid frame",
        p.rec
    );
    assert_eq!(p.err_state, 0);
}

/// Transmitter: an ACK error (+8), then a successful retransmission once a
/// receiver is connected (rule g, -1).
#[test]
fn tec_decrements_after_successful_transmission() {
    let t = timing(0);
    let mut bus = Bus::new(2, t);
    bus.connected[1] = false;
    bus.integrate();
    let f = frame(0x321, &[9, 8, 7]);
    let mut req = vec![Some(f), None];
    let mut done = 0;
    let mut received = Vec::new();
    for _ in 0..300 * t.clocks_per_bit() {
        let o = bus.step(&req);
        req = vec![None, None];
        if o[0].probes.tec == 8 {
            bus.connected[1] = true;
        }
        if o[0].tx_done {
            done += 1;
            assert_eq!(o[0].probes.tec, 7);
        }
        if o[1].rx_valid && bus.connected[1] {
            received.push(o[1].rx_frame);
        }
    }
    assert_eq!(done, 1);
    assert_eq!(received, vec![f]);
}

/// Transmitter bit error in the data field: TEC + 8 (rule c); the receiver counts
/// +1 (rule a) and both recover with the successful retransmission (rules g, h).
#[test]
fn transmitter_bit_error_then_retransmission() {
    let t = timing(0);
    let mut bus = Bus::new(2, t);
    bus.integrate();
    let f = frame(0x0C4, &[0xFF, 0x0F]);
    let mut req = vec![Some(f), None];
    let mut a_prev = bus.nodes[0].outputs();
    let mut max_rec = 0;
    let mut received = Vec::new();
    let mut injected = false;
    for _ in 0..300 * t.clocks_per_bit() {
        bus.force_dominant = !injected && a_prev.probes.field == code::DATA && a_prev.tx;
        let o = bus.step(&req);
        req = vec![None, None];
        if o[0].probes.tec == 8 {
            injected = true;
        }
        max_rec = max_rec.max(o[1].probes.rec);
        if o[1].rx_valid {
            received.push(o[1].rx_frame);
        }
        a_prev = o[0];
    }
    assert!(injected);
    assert_eq!(a_prev.probes.tec, 7);
    assert_eq!(max_rec, 1);
    assert_eq!(bus.nodes[1].outputs().probes.rec, 0);
    assert_eq!(received, vec![f]);
}

/// Repeated transmitter bit errors drive TEC past 255: bus-off (rule j), `tx`
/// recessive, frame still pending. Recovery after 128 occurrences of 11
/// consecutive recessive bits (rule l): TEC = REC = 0, error active, then the
/// pending frame is sent.
#[test]
fn bus_off_and_recovery() {
    let t = timing(0);
    let mut bus = Bus::new(2, t);
    bus.integrate();
    let f = frame(0x0C4, &[0xFF]);
    let mut req = vec![Some(f), None];
    let mut a_prev = bus.nodes[0].outputs();
    let mut tec = 0;
    let mut bus_off = false;
    let mut recessive_run = 0;
    let mut recovered_after = None;
    let mut done = 0;
    for _ in 0..4000 * t.clocks_per_bit() {
        bus.force_dominant = !bus_off && a_prev.probes.field == code::DATA && a_prev.tx;
        let o = bus.step(&req);
        req = vec![None, None];
        let a = o[0];
        let p = a.probes;
        if !bus_off {
            if p.tec != tec {
                assert_eq!(p.tec, tec + 8);
                tec = p.tec;
            }
            assert_eq!(p.err_state, if tec > 255 { 2 } else { (tec >= 128) as u8 });
            if p.err_state == 2 {
                bus_off = true;
                assert_eq!(p.tec, 256);
                assert_eq!(p.field, code::BUS_OFF);
            }
        } else if recovered_after.is_none() {
            if p.err_state == 2 {
                assert_eq!(p.field, code::BUS_OFF);
                assert!(a.tx_pending);
                if p.sample_point {
                    recessive_run = if p.sampled_bit { recessive_run + 1 } else { 0 };
                }
            } else {
                assert!(p.sample_point);
                recovered_after = Some(recessive_run + 1);
                assert_eq!((p.tec, p.rec, p.err_state, p.field), (0, 0, 0, code::IDLE));
            }
        }
        if bus_off && a.probes.err_state == 2 {
            assert!(a.tx, "a bus-off node stays recessive");
        }
        if a.tx_done {
            done += 1;
        }
        a_prev = a;
    }
    assert!(bus_off);
    assert_eq!(recovered_after, Some(128 * 11));
    assert_eq!(done, 1);
    assert_eq!(a_prev.probes.tec, 0);
}

/// Timing contract §4.5, `boff_hold`: while it is 1 a bus-off node does not count
/// its recovery, however long the bus stays recessive (here 5 x 128 x 11 bit
/// times): it stays bus-off, `tx` recessive, TEC 256, the frame pending. From the
/// first edge with `boff_hold` 0 it needs the whole 128 x 11 recessive bits (the
/// counts were 0 at bus-off entry and stood still), then sends the pending frame,
/// which node 1 (back on the bus) receives and acknowledges.
#[test]
fn boff_hold_keeps_a_bus_off_node_from_recovering() {
    let (mut bus, f) = bus_off_node_0(true);
    let cpb = bus.timing.clocks_per_bit() as u64;
    let mut samples = 0;
    for _ in 0..5 * RECOVERY_SAMPLES as u64 * cpb {
        let a = bus.step(&[])[0];
        let p = a.probes;
        samples += p.sample_point as u32;
        assert_eq!(
            (p.err_state, p.field, p.tec),
            (2, code::BUS_OFF, 256),
            "held after {samples} recessive samples"
        );
        assert!(a.tx && a.tx_pending);
    }
    assert!(samples >= 5 * RECOVERY_SAMPLES - 1);
    // Node 1 has been idle for thousands of bits: back on the bus to acknowledge.
    bus.connected[1] = true;
    bus.boff_hold[0] = false;
    assert_eq!(
        samples_to_recovery(&mut bus, RECOVERY_SAMPLES),
        RECOVERY_SAMPLES
    );
    let mut received = Vec::new();
    let mut done = 0;
    for _ in 0..200 * cpb {
        let o = bus.step(&[]);
        done += o[0].tx_done as u32;
        if o[1].rx_valid {
            received.push(o[1].rx_frame);
        }
    }
    assert_eq!(done, 1, "the pending frame is sent after the recovery");
    assert_eq!(received, vec![f]);
}

/// Timing contract §4.5: the hold freezes both counts where they are, the
/// recessive samples of the current run and the completed runs, and a dominant
/// sample while held does not restart the run. Node 0 counts 5 runs and 7
/// recessive bits of a sixth (62 samples), is held for 300 bit times in which the
/// bus is dominant for 20 single bits and recessive otherwise, and is released:
/// it recovers after exactly 128 x 11 - 62 more recessive samples.
#[test]
fn boff_hold_freezes_the_recovery_counts_where_they_are() {
    let (mut bus, _) = bus_off_node_0(false);
    let cpb = bus.timing.clocks_per_bit() as u64;
    let before = 5 * 11 + 7;
    let mut samples = 0;
    while samples < before {
        let p = bus.step(&[])[0].probes;
        assert_eq!(p.err_state, 2);
        if p.sample_point {
            assert!(p.sampled_bit);
            samples += 1;
        }
    }
    bus.boff_hold[0] = true;
    let mut dominant = 0;
    for bit in 0..300 {
        // Every 15th bit time dominant (bits 0, 15, ..., 285: 20 of them).
        bus.force_dominant = bit % 15 == 0;
        for _ in 0..cpb {
            let p = bus.step(&[])[0].probes;
            assert_eq!((p.err_state, p.field), (2, code::BUS_OFF), "held");
            dominant += (p.sample_point && !p.sampled_bit) as u32;
        }
    }
    assert_eq!(dominant, 20, "the node sampled every dominant bit");
    bus.force_dominant = false;
    bus.boff_hold[0] = false;
    assert_eq!(
        samples_to_recovery(&mut bus, RECOVERY_SAMPLES),
        RECOVERY_SAMPLES - before
    );
}
