//! The scenario and the fault plan of one episode.

use super::*;

/// Largest gap between bursts of frames, in bit times (about 140 bit times per
/// frame on average: a busy bus with room to recover).
pub(super) const MAX_GAP_BITS: u64 = 600;

/// The traffic of one episode, its fault plan, and the scenario holding both.
pub(super) fn build(spec: &Stress, seed: u64) -> (Scenario, FaultPlan) {
    // Plenty of traffic (about 140 bit times per frame); cut after planning.
    let mut t = Traffic::new(
        seed,
        (spec.fault_bits / 25) as usize,
        spec.clock_hz,
        spec.bitrate,
    );
    t.nodes = spec.nodes;
    t.max_gap_bits = MAX_GAP_BITS;
    let mut sc = t.scenario().unwrap();
    let cpb = sc.clocks_per_bit();
    sc.name = format!("error-stress-{}-{seed:#x}", spec.name);
    if let Some((brp, tseg1, tseg2, sjw)) = spec.timing {
        sc.timing.brp = brp.into();
        sc.timing.tseg1 = tseg1;
        sc.timing.tseg2 = tseg2;
        sc.timing.sjw = sjw;
        assert_eq!(sc.timing.clocks_per_bit() as u64, cpb, "{}", spec.name);
    }
    sc.timing.triple_sampling = spec.triple_sampling;
    sc.timing.validate().unwrap();
    // Faults make the default expectation (every frame to every other node)
    // meaningless; the checks are this file's.
    sc.expect = Expectations::Explicit(Vec::new());
    // Every episode: a long stuck-dominant window (error passive) and a
    // stuck-dominant line held in a frame until a node is bus-off, besides the
    // random events.
    let mut params = FaultParams::new(seed, 25 * cpb, spec.fault_bits * cpb);
    params.forced = vec![(0.3, FaultEvent::LongDominant), (0.6, FaultEvent::BusOff)];
    let fp = plan(&sc, &params).unwrap();
    // The traffic goes on for a quarter of the fault window after the faults
    // (and at least to where the planner ran, so the replay is the planner's).
    let cut = (fp.end + spec.fault_bits / 4 * cpb)
        .max(fp.planned_until)
        .max(spec.fault_bits / 4 * 5 * cpb);
    let last_due = sc.frames.iter().map(|f| f.at_cycle).max().unwrap();
    assert!(
        cut <= last_due,
        "{}: the traffic (until cycle {last_due}) is too short for the faults (until cycle {})",
        sc.name,
        fp.end
    );
    sc.frames.retain(|f| f.at_cycle <= cut);
    let last_due = sc.frames.iter().map(|f| f.at_cycle).max().unwrap();
    sc.faults = fp.faults.clone();
    sc.description = format!(
        "error stress {}: {} random frames on {} nodes (traffic and fault seed {seed:#x}), \
         {} faults until cycle {} (bit {})",
        spec.name,
        sc.frames.len(),
        spec.nodes,
        fp.faults.len(),
        fp.end,
        fp.end / cpb
    );
    // A generous cycle limit: a node that locks up shows as frames never sent.
    let bits = last_due / cpb + (sc.frames.len() as u64 + 128) * MAX_FRAME_BITS + 2000;
    sc.max_cycles = bits * cpb;
    (sc, fp)
}
