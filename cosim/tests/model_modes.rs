//! Reference model: configuration captured in reset mode and clamping (timing
//! contract §6), operating modes (§7), single-shot and `tx_abort` (§8).
//! Expected values come from the contract's text and ISO 11898-1, computed by hand
//! (bit lengths, synchronisation arithmetic of §3) or by the independent helpers.

mod model_support;

use drcc_cosim::{BitTiming, ChannelOutputs, ControllerConfig, Frame, Mode};
use model_support::{code, timing, Bus, Tester};

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

fn cfg(mode: Mode) -> ControllerConfig {
    ControllerConfig {
        mode,
        ..ControllerConfig::default()
    }
}

fn single_shot() -> ControllerConfig {
    ControllerConfig {
        single_shot: true,
        ..ControllerConfig::default()
    }
}

/// Lengths of the runs of equal values strictly between the first and the last
/// transition of `tx` (the SOF, lengthened by the hard synchronisation, and the
/// recessive tail are left out).
fn inner_runs(tx: &[bool]) -> Vec<usize> {
    let edges: Vec<usize> = (1..tx.len()).filter(|&i| tx[i] != tx[i - 1]).collect();
    edges.windows(2).map(|w| w[1] - w[0]).collect()
}

/// Records every output of node `n` while stepping the bus `clocks` times.
fn record(bus: &mut Bus, clocks: u32, n: usize) -> Vec<ChannelOutputs> {
    (0..clocks).map(|_| bus.step(&[])[n]).collect()
}

/// Node `n`'s `tx` from its first dominant bit (SOF) up to its `tx_done`.
fn frame_tx(outs: &[ChannelOutputs]) -> Vec<bool> {
    let start = outs.iter().position(|o| !o.tx).expect("no SOF");
    let end = outs.iter().position(|o| o.tx_done).expect("no tx_done");
    outs[start..end].iter().map(|o| o.tx).collect()
}

/// The bit length seen on a transmitter's `tx` pin: with data 0x55 there are
/// one-bit runs, and without resynchronisation (a lone transmitter sends every
/// dominant edge itself) every run is a whole number of bits.
fn assert_bit_length(tx: &[bool], clocks: usize, what: &str) {
    let runs = inner_runs(tx);
    assert!(runs.len() > 10, "{what}: too few transitions");
    assert_eq!(*runs.iter().min().unwrap(), clocks, "{what}: bit length");
    for r in &runs {
        assert_eq!(r % clocks, 0, "{what}: run of {r} clocks");
    }
}

fn with_brp(t: BitTiming, brp: u8) -> BitTiming {
    BitTiming { brp, ..t }
}

// ---------------------------------------------------------------- §6

/// Bit timing, mode, EWL and single-shot are captured at reset edges only:
/// changed while running they have no effect; after a reset they do.
#[test]
fn configuration_changes_take_effect_only_at_reset() {
    let f = frame(0x4A5, &[0x55, 0x55, 0x55]);
    let mut bus = Bus::new(3, timing(0));
    bus.reset();
    bus.integrate();
    // Change everything while running: 16 clocks per bit, node 0 listen-only with
    // EWL 0 and single shot.
    bus.timing = with_brp(timing(0), 1);
    bus.configs[0] = ControllerConfig {
        mode: Mode::ListenOnly,
        ewl: 0,
        single_shot: true,
    };
    let o = bus.step(&[Some(f)])[0];
    assert!(
        o.tx_pending && !o.tx_failed,
        "request accepted: still NORMAL"
    );
    assert!(!o.diag.err_warning, "EWL still 96");
    let outs = record(&mut bus, 200 * 8, 0);
    assert_bit_length(&frame_tx(&outs), 8, "old timing");
    assert!(outs.iter().all(|o| !o.diag.err_warning && !o.tx_failed));
    assert_eq!(outs.iter().filter(|o| o.tx_done).count(), 1);

    // Reset: now captured.
    bus.reset();
    let o = bus.step(&[])[0];
    assert!(o.diag.err_warning, "TEC 0 >= EWL 0");
    bus.integrate();
    let o = bus.step(&[Some(f), Some(f)]);
    assert!(
        o[0].tx_failed && !o[0].tx_pending,
        "listen-only refuses tx_req"
    );
    assert!(o[1].tx_pending && !o[1].tx_failed);
    let mut outs0 = Vec::new();
    let mut outs1 = Vec::new();
    let mut rx0 = Vec::new();
    for _ in 0..200 * 16 {
        let o = bus.step(&[]);
        outs0.push(o[0]);
        outs1.push(o[1]);
        if o[0].rx_valid {
            rx0.push(o[0].rx_frame);
        }
    }
    assert!(outs0.iter().all(|o| o.tx && o.diag.err_warning));
    assert_bit_length(&frame_tx(&outs1), 16, "new timing");
    assert_eq!(rx0, vec![f.normalized()]);
}

/// §6 clamping, measured on a lone transmitter's `tx` pin:
/// `T1' = max(T1, 7 - T2, M)`, M = 3 / 2 / 1 for BRP 0 / 1 / >= 2. The
/// transmitter runs in SELF_TEST (with a sample point 3 clocks after SYNC_SEG a
/// receiver's ACK, 2 + 1 clocks late through its synchronizer and back through
/// the transmitter's, would be too late), a LISTEN_ONLY node receives.
#[test]
fn illegal_bit_timing_is_clamped() {
    let cases = [
        // (brp, tseg1, tseg2, sjw, clocks per bit)
        (0, 1, 1, 1, 8),    // T1' = 6: 8 tq
        (1, 1, 1, 1, 16),   // T1' = 6: 8 tq of 2 clocks
        (3, 1, 1, 1, 32),   // T1' = 6: 8 tq of 4 clocks
        (0, 1, 8, 1, 12),   // T1' = M = 3: 12 tq
        (1, 1, 8, 1, 22),   // T1' = M = 2: 11 tq of 2 clocks
        (2, 1, 8, 1, 30),   // T1' = 1: 10 tq of 3 clocks
        (0, 2, 3, 4, 8),    // T1' = 4, SJW' = 3: 8 tq
        (0, 3, 2, 2, 8),    // T1' = 5: 8 tq
        (0, 5, 2, 4, 8),    // legal lengths, SJW' = 2
        (4, 16, 8, 4, 125), // legal, 25 tq of 5 clocks
    ];
    let f = frame(0x2B3, &[0x55, 0xAA, 0x55]);
    for (brp, tseg1, tseg2, sjw, clocks) in cases {
        let t = BitTiming {
            brp,
            tseg1,
            tseg2,
            sjw,
            triple_sampling: false,
        };
        let mut bus = Bus::new(2, t);
        bus.configs = vec![cfg(Mode::SelfTest), cfg(Mode::ListenOnly)];
        bus.reset();
        // Bus integration: 11 recessive bits (BitTiming::clocks_per_bit does not
        // know the clamping).
        for _ in 0..20 * clocks {
            bus.step(&[]);
        }
        bus.step(&[Some(f)]);
        let mut outs = Vec::new();
        let mut rx = Vec::new();
        for _ in 0..150 * clocks {
            let o = bus.step(&[]);
            outs.push(o[0]);
            if o[1].rx_valid {
                rx.push(o[1].rx_frame);
            }
            assert!(o[0].diag.err_kind == 0 && o[1].diag.err_kind == 0, "{t:?}");
        }
        assert_bit_length(&frame_tx(&outs), clocks as usize, &format!("{t:?}"));
        assert_eq!(rx, vec![f.normalized()], "{t:?}");
    }
}

/// SJW > TSEG2 is clamped to `SJW' = TSEG2`. A receiver (brp 0, TSEG1 5, TSEG2 2,
/// 8 clocks per bit) gets SOF, a recessive ID bit whose end comes `e` clocks late,
/// then dominant bits: the 6th equal bit is a stuff error and its error flag goes
/// on `tx` at the bit_start after that sample point.
///
/// §3 arithmetic: SOF presented at clock s0 is seen at s0+2 (hard sync, SYNC tq);
/// bit k's SYNC tq is then at s0+2+8k. The late edge L = s0+16+e is seen at
/// s0+18+e, in TSEG1 with phase error e: TSEG1 grows by j = min(e, SJW'), so bit
/// 3's SYNC is at s0+26+j, bit 7 (the stuff error) is sampled at s0+63+j and the
/// flag starts at s0+65+j: flag - L = 49 + j - e.
#[test]
fn sjw_larger_than_tseg2_is_clamped() {
    let flag_after_late_edge = |t: BitTiming, e: usize| -> usize {
        let mut tester = Tester::new(t);
        tester.node.step(&drcc_cosim::ChannelInputs {
            rst: true,
            rx: true,
            timing: t,
            ..Default::default()
        });
        tester.idle(20);
        let mut levels = vec![false; 8]; // SOF
        levels.extend(vec![true; 8 + e]); // ID bit 10, late end
        levels.extend(vec![false; 80]); // ID bits 9.., stuff error
        levels.extend(vec![true; 200]);
        let late_edge = 16 + e;
        let mut flag = None;
        for (k, &v) in levels.iter().enumerate() {
            let o = tester.node.step(&drcc_cosim::ChannelInputs {
                rst: false,
                rx: v && tester.tx,
                timing: t,
                ..Default::default()
            });
            tester.tx = o.tx;
            if !o.tx && flag.is_none() {
                flag = Some(k);
                assert_eq!(o.probes.field, code::ERROR_FLAG);
            }
        }
        flag.expect("no error flag") - late_edge
    };
    let t = |sjw| BitTiming {
        brp: 0,
        tseg1: 5,
        tseg2: 2,
        sjw,
        triple_sampling: false,
    };
    for e in 1..=5 {
        let expected = 49 + e.min(2) - e;
        assert_eq!(
            flag_after_late_edge(t(4), e),
            expected,
            "sjw 4 (clamped to 2), e {e}"
        );
        assert_eq!(
            flag_after_late_edge(t(3), e),
            expected,
            "sjw 3 (clamped to 2), e {e}"
        );
        assert_eq!(flag_after_late_edge(t(2), e), expected, "sjw 2, e {e}");
        assert_eq!(
            flag_after_late_edge(t(1), e),
            49 + e.min(1) - e,
            "sjw 1, e {e}"
        );
    }
}

// ---------------------------------------------------------------- §7

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
    for brp in [0u8, 2] {
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
    for brp in [0u8, 1] {
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

// ---------------------------------------------------------------- §8

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
