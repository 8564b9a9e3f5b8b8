//! Reference model: the per-request single shot `tx_single` (timing contract
//! §4.4, §8), the transmitter role probe `is_tx` (§4.5 "Roles") and the bus-off
//! recovery probe `boff_runs` (§4.5 "Bus-off"). Expected values come from the
//! contract's text and ISO 11898-1 (arbitration 10.4.2.2, rule l of 12.1.4.2).

mod model_support;

use drcc_cosim::{ChannelInputs, ChannelOutputs, Frame};
use model_support::{bus_off_node_0, code, samples_to_recovery, timing, Bus, RECOVERY_SAMPLES};

/// Node 0's frame: base identifier 0x100 = 001_0000_0000.
fn loser() -> Frame {
    Frame::base(0x100, &[0x11])
}

/// Node 1's frame: base identifier 0x080 = 000_1000_0000. The identifiers first
/// differ at bit index 2 (MSB = 0), where node 1 sends dominant and wins.
fn winner() -> Frame {
    Frame::base(0x080, &[0x22])
}

/// Arbitration-lost position of node 0 against node 1 (§9: base-ID bit i is i).
const LOST_AT: u8 = 2;

/// What a node did during a run: the clocks of its pulses, what the other
/// node received, and the outputs clock by clock.
#[derive(Default)]
struct Run {
    arb_lost: Vec<usize>,
    tx_failed: Vec<usize>,
    tx_done: Vec<usize>,
    /// Frames received by node 1.
    received_1: Vec<Frame>,
    trace: Vec<[ChannelOutputs; 2]>,
}

/// Steps a two-node bus for `bits` bit times, applying `reqs[k]` at clock `k`.
fn run(bus: &mut Bus, reqs: &[[Option<Frame>; 2]], bits: u64) -> Run {
    let mut r = Run::default();
    for k in 0..(bits * bus.timing.clocks_per_bit() as u64) as usize {
        let req = reqs.get(k).copied().unwrap_or([None, None]);
        let o = bus.step(&req);
        let o = [o[0], o[1]];
        if o[0].arb_lost {
            r.arb_lost.push(k);
        }
        if o[0].tx_failed {
            r.tx_failed.push(k);
        }
        if o[0].tx_done {
            r.tx_done.push(k);
        }
        if o[1].rx_valid {
            r.received_1.push(o[1].rx_frame);
        }
        r.trace.push(o);
    }
    r
}

fn integrated_pair() -> Bus {
    let mut bus = Bus::new(2, timing(0));
    bus.integrate();
    bus
}

/// Timing contract §8 (`tx_single`): node 0 runs without `cfg_single_shot`, but
/// its request carries `tx_single = 1`; it loses arbitration to node 1, so at
/// that SAMPLE edge `tx_pending` clears and `tx_failed` pulses together with
/// `arb_lost` (alc = 2), and the frame is never sent. The next request without
/// `tx_single` loses the same way but is retried (automatic retransmission) and
/// sent after node 1's frame.
#[test]
fn tx_single_drops_a_frame_that_loses_arbitration_the_next_request_is_retried() {
    let mut bus = integrated_pair();
    bus.tx_single[0] = true;
    let r = run(&mut bus, &[[Some(loser()), Some(winner())]], 1);
    bus.tx_single[0] = false;
    let rest = run(&mut bus, &[], 200);
    let (lost, failed) = (
        [r.arb_lost.clone(), rest.arb_lost.clone()].concat(),
        [r.tx_failed.clone(), rest.tx_failed.clone()].concat(),
    );
    assert_eq!(lost.len(), 1, "one arbitration loss");
    assert_eq!(failed, lost, "tx_failed pulses with arb_lost");
    let k = rest.arb_lost[0];
    let at = rest.trace[k][0];
    assert!(!at.tx_pending, "the single-shot frame is dropped");
    assert_eq!(at.diag.alc, LOST_AT);
    assert!(rest.trace[k..].iter().all(|o| !o[0].tx_pending));
    assert!(rest.tx_done.is_empty(), "node 0 never sends it");
    assert_eq!(rest.received_1, Vec::<Frame>::new());

    // The same contest without tx_single: retried, then sent.
    let r = run(&mut bus, &[[Some(loser()), Some(winner())]], 200);
    assert_eq!(r.arb_lost.len(), 1);
    assert_eq!(
        r.tx_failed,
        Vec::<usize>::new(),
        "no drop without tx_single"
    );
    assert!(r.trace[r.arb_lost[0]][0].tx_pending, "still pending");
    assert_eq!(r.tx_done.len(), 1, "retransmitted");
    assert_eq!(r.received_1, vec![loser()]);
}

/// Timing contract §4.4 and §8: the `tx_single` latch is taken only by an
/// accepted `tx_req` (with `tx_pending = 0`). A second request one clock later,
/// while the first frame is pending, is ignored with its `tx_single`: a frame
/// latched with 0 stays retried although the ignored request said 1, and a frame
/// latched with 1 is dropped although the ignored request said 0.
#[test]
fn tx_single_of_an_ignored_request_changes_nothing() {
    for latched in [false, true] {
        let mut bus = integrated_pair();
        bus.tx_single[0] = latched;
        let o = bus.step(&[Some(loser()), None]);
        assert!(o[0].tx_pending, "the first request is accepted");
        // The second request (node 0, while pending) carries the other value.
        bus.tx_single[0] = !latched;
        let o = bus.step(&[Some(loser()), Some(winner())]);
        assert!(o[0].tx_pending);
        bus.tx_single[0] = false;
        let r = run(&mut bus, &[], 200);
        assert_eq!(r.arb_lost.len(), 1, "latched {latched}");
        if latched {
            assert_eq!(r.tx_failed, r.arb_lost, "dropped (latched 1)");
            assert!(r.tx_done.is_empty());
        } else {
            assert!(r.tx_failed.is_empty(), "kept (latched 0)");
            assert_eq!(r.tx_done.len(), 1);
            assert_eq!(r.received_1, vec![loser()]);
        }
    }
}

/// Index of the first clock at or after `from` where node `n` takes a SAMPLE
/// edge that moves its field from `before` to `after`.
fn field_edge(
    trace: &[[ChannelOutputs; 2]],
    n: usize,
    from: usize,
    before: u8,
    after: u8,
) -> usize {
    (from.max(1)..trace.len())
        .find(|&k| {
            trace[k][n].probes.sample_point
                && trace[k - 1][n].probes.field == before
                && trace[k][n].probes.field == after
        })
        .unwrap_or_else(|| panic!("no {before} -> {after} edge of node {n} after {from}"))
}

/// Timing contract §4.5 "Roles": `is_tx` is 0 while idle, rises at the SAMPLE
/// edge of the SOF the node starts (field IDLE -> ID_A), stays 1 through the
/// frame, EOF and intermission bits 1 and 2, and clears at the SAMPLE edge of the
/// 3rd recessive intermission bit (INTERMISSION -> IDLE). The receiver's `is_tx`
/// is 0 throughout; `boff_runs` is 0 for both (not bus-off).
#[test]
fn is_tx_spans_sof_to_the_third_intermission_bit() {
    let mut bus = integrated_pair();
    let r = run(&mut bus, &[[Some(loser()), None]], 150);
    assert_eq!(r.tx_done.len(), 1);
    let sof = field_edge(&r.trace, 0, 0, code::IDLE, code::ID_A);
    let end = field_edge(&r.trace, 0, sof, code::INTERMISSION, code::IDLE);
    for (k, o) in r.trace.iter().enumerate() {
        let expect = (sof..end).contains(&k);
        assert_eq!(
            o[0].probes.is_tx, expect,
            "node 0 clock {k} (SOF {sof}, end {end})"
        );
        assert!(!o[1].probes.is_tx, "the receiver is never transmitter");
        assert_eq!((o[0].probes.boff_runs, o[1].probes.boff_runs), (0, 0));
    }
    assert!(r.tx_done[0] > sof && r.tx_done[0] < end);
    assert_eq!(r.trace[end - 1][0].probes.field, code::INTERMISSION);
}

/// Timing contract §4.5 "Roles": both nodes start the SOF as transmitters; the
/// loser's `is_tx` clears at the edge of `arb_lost`, the winner's stays 1.
#[test]
fn is_tx_clears_at_arbitration_loss() {
    let mut bus = integrated_pair();
    let r = run(&mut bus, &[[Some(loser()), Some(winner())]], 60);
    let k = r.arb_lost[0];
    let sof = field_edge(&r.trace, 0, 0, code::IDLE, code::ID_A);
    assert!(
        r.trace[sof][1].probes.is_tx,
        "node 1 transmitter from the SOF"
    );
    assert!(
        (sof..k).all(|j| r.trace[j][0].probes.is_tx),
        "node 0 until the loss"
    );
    assert!(!r.trace[k][0].probes.is_tx, "cleared at the arb_lost edge");
    assert!(r.trace[k][1].probes.is_tx, "the winner stays transmitter");
    let done_1 = r
        .trace
        .iter()
        .position(|o| o[1].tx_done)
        .expect("node 1 done");
    assert!(
        r.trace[k..=done_1].iter().all(|o| !o[0].probes.is_tx),
        "a receiver"
    );
}

/// Timing contract §4.5 "Roles": error frames count for the transmitter, so
/// `is_tx` stays 1 through its own error flag and delimiter (a bit error forced
/// in its DATA field) and clears only at the 3rd intermission bit; it rises again
/// at the SOF of the retransmission.
#[test]
fn is_tx_stays_through_the_own_error_frame() {
    let mut bus = integrated_pair();
    let cpb = bus.timing.clocks_per_bit() as usize;
    let mut trace = Vec::new();
    let mut forced = false;
    let mut req = [Some(Frame::base(0x0C4, &[0xFF])), None];
    let mut prev = bus.nodes[0].outputs();
    for _ in 0..200 * cpb {
        bus.force_dominant = !forced && prev.probes.field == code::DATA && prev.tx;
        let o = bus.step(&req);
        req = [None, None];
        forced |= o[0].diag.err_valid;
        prev = o[0];
        trace.push([o[0], o[1]]);
    }
    let err = trace
        .iter()
        .position(|o| o[0].diag.err_valid)
        .expect("error");
    assert!(trace[err][0].diag.err_tx, "detected as transmitter");
    let sof = field_edge(&trace, 0, 0, code::IDLE, code::ID_A);
    let end = field_edge(&trace, 0, err, code::INTERMISSION, code::IDLE);
    let fields: Vec<u8> = trace[sof..end].iter().map(|o| o[0].probes.field).collect();
    assert!(fields.contains(&code::ERROR_FLAG) && fields.contains(&code::ERROR_DELIM));
    assert!(trace[sof..end].iter().all(|o| o[0].probes.is_tx));
    assert!(!trace[end][0].probes.is_tx);
    let again = field_edge(&trace, 0, end, code::IDLE, code::ID_A);
    assert!(trace[end..again].iter().all(|o| !o[0].probes.is_tx));
    assert!(
        trace[again][0].probes.is_tx,
        "transmitter again at the retransmission"
    );
    assert_eq!(trace.iter().filter(|o| o[0].tx_done).count(), 1);
}

/// Timing contract §4.5: a node stops being transmitter when it becomes
/// bus-off (the edge that captures its last error as transmitter, §9), stays 0
/// during the recovery, and is transmitter again from the SOF of its pending
/// frame after it. A reset edge clears `is_tx` (0 in reset).
#[test]
fn is_tx_clears_at_bus_off_and_in_reset() {
    let (mut bus, _) = bus_off_node_0(false);
    let at = bus.nodes[0].outputs();
    assert_eq!(at.probes.err_state, 2);
    assert!(
        at.diag.err_valid && at.diag.err_tx,
        "its last error as transmitter"
    );
    assert!(
        !at.probes.is_tx,
        "no longer transmitter at the bus-off edge"
    );
    bus.connected[1] = true;
    let mut rose = false;
    for _ in 0..(RECOVERY_SAMPLES as usize + 40) * bus.timing.clocks_per_bit() as usize {
        let o = bus.step(&[])[0];
        if o.probes.err_state == 2 {
            assert!(!o.probes.is_tx);
        }
        rose |= o.probes.is_tx;
        if rose {
            break;
        }
    }
    assert!(rose, "transmitter again after the recovery");
    let o = bus.nodes[0].step(&ChannelInputs {
        rst: true,
        rx: true,
        timing: bus.timing,
        ..Default::default()
    });
    assert!(!o.probes.is_tx, "0 in reset");
}

/// Timing contract §4.5 "Bus-off": `boff_runs` is 0 at bus-off entry, one more
/// at each SAMPLE edge that completes a run of 11 recessive samples (so after n
/// recessive samples it is n / 11, up to 127), and 0 at the edge of the 128th
/// run, which ends bus-off, and after it.
#[test]
fn boff_runs_counts_0_to_127_and_is_0_after_recovery() {
    let (mut bus, _) = bus_off_node_0(false);
    assert_eq!(bus.nodes[0].outputs().probes.boff_runs, 0, "0 at entry");
    let mut samples = 0u32;
    let mut max = 0;
    loop {
        let p = bus.step(&[])[0].probes;
        samples += p.sample_point as u32;
        if p.err_state != 2 {
            assert_eq!(samples, RECOVERY_SAMPLES);
            assert_eq!(p.boff_runs, 0, "0 at the recovering edge");
            break;
        }
        assert_eq!(p.boff_runs as u32, samples / 11, "after {samples} samples");
        max = max.max(p.boff_runs);
    }
    assert_eq!(max, 127);
    bus.connected[1] = true;
    for _ in 0..100 * bus.timing.clocks_per_bit() {
        assert_eq!(bus.step(&[])[0].probes.boff_runs, 0, "0 outside bus-off");
    }
}

/// Timing contract §4.5: `boff_hold` freezes the completed runs, so `boff_runs`
/// stands still however long the hold (also across dominant bits); released, the
/// run in progress completes after its missing recessive samples. A reset edge
/// while bus-off shows 0.
#[test]
fn boff_runs_is_frozen_under_boff_hold_and_0_in_reset() {
    let (mut bus, _) = bus_off_node_0(false);
    let cpb = bus.timing.clocks_per_bit() as u64;
    let mut samples = 0;
    while samples < 5 * 11 + 7 {
        samples += bus.step(&[])[0].probes.sample_point as u32;
    }
    assert_eq!(bus.nodes[0].outputs().probes.boff_runs, 5);
    bus.boff_hold[0] = true;
    for bit in 0..400 {
        bus.force_dominant = bit % 13 == 0;
        for _ in 0..cpb {
            assert_eq!(bus.step(&[])[0].probes.boff_runs, 5, "held");
        }
    }
    bus.force_dominant = false;
    bus.boff_hold[0] = false;
    // 4 more recessive samples complete the sixth run.
    let mut more = 0;
    loop {
        let p = bus.step(&[])[0].probes;
        more += p.sample_point as u32;
        if p.boff_runs == 6 {
            assert!(p.sample_point);
            break;
        }
        assert_eq!(p.boff_runs, 5);
    }
    assert_eq!(more, 4);
    assert_eq!(
        samples_to_recovery(&mut bus, RECOVERY_SAMPLES),
        RECOVERY_SAMPLES - 66
    );
    // Bus-off again, then a reset edge.
    let (mut bus, _) = bus_off_node_0(false);
    for _ in 0..30 * 11 * cpb {
        bus.step(&[]);
    }
    assert!(bus.nodes[0].outputs().probes.boff_runs >= 29);
    let o = bus.nodes[0].step(&ChannelInputs {
        rst: true,
        rx: true,
        timing: bus.timing,
        ..Default::default()
    });
    assert_eq!(
        (o.probes.boff_runs, o.probes.err_state),
        (0, 0),
        "0 in reset"
    );
}
