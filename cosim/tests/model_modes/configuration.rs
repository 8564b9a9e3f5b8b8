//! Configuration captured at reset only, and clamping of illegal bit timings
//! (timing contract §6).

use super::*;

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
