//! Replicated-star fault scenarios (issue "ReCANcentrate hub"): 4 DRCC nodes, channel
//! A on hub 1 and channel B on hub 2, two hubs coupled by two interlinks, one fault on
//! one link for 4000 bit times (`testbench::star`). The reference models (DRCC and
//! hub) run the system and the Verilated `drcc.v` / `hub.v` run it in lock step: any
//! difference at any clock fails. On top of that agreement, each scenario must show
//! what the hub contract (`cosim/src/model/hub_contract.md`) and the paper promise:
//!
//! - every single fault: no frame lost or duplicated at the application level;
//! - the faulty input isolated by its own hub with the fault kind of §6, within the
//!   bound the contract's thresholds give (stuck-dominant: the 14th / 16th dominant
//!   sample), no other port isolated, and the port restored after the fault ends
//!   (no earlier than `restore_bits` when the symptom lasts to the end of the fault);
//! - one interlink lost: the coupling holds (no decoupling, no omission anywhere);
//! - every interlink lost, for a while or for good, and the paper's malicious hubs:
//!   NRAP (§9) brings both hubs to one decision within its bounds, every node's
//!   `STAR_STATUS` follows it, and nothing is lost or duplicated.

use drcc_cosim::engine::hub_verilator::HubVerilatorEngine;
use drcc_cosim::star::hub_host::HubConfig;
use drcc_testbench::engines::lockstep_engine;
use drcc_testbench::star::{run_star, StarFault, StarReport, StarScenario, CLOCKS_PER_BIT, HUB_N};
use drcc_testbench::EngineKind;

fn cosim_engine() -> Option<EngineKind> {
    lockstep_engine("hub", || HubVerilatorEngine::new().map(|_| ()))
}

fn run(fault: StarFault) -> (StarScenario, StarReport) {
    let s = StarScenario::standard(fault);
    let r = run_star(&s, EngineKind::Model, cosim_engine()).unwrap_or_else(|e| panic!("{e}"));
    (s, r)
}

/// PORT_p: [0] enabled, [3:1] kind, [23:16] isolations, [31:24] restorations.
fn port_kind(port: u32) -> u32 {
    port >> 1 & 7
}
fn port_isolations(port: u32) -> u32 {
    port >> 16 & 0xFF
}

fn bits_after(from: u64, at: u64) -> u64 {
    (at - from) / CLOCKS_PER_BIT
}

fn assert_lossless(s: &StarScenario, r: &StarReport) {
    assert!(
        r.exactly_once(),
        "{}: missing {:?}, duplicates {:?}, foreign {}",
        s.fault.name(),
        r.missing,
        r.duplicates,
        r.foreign
    );
    assert_eq!(r.delivered, s.nodes * (s.nodes - 1) * s.frames_per_node);
    // Star nodes (DRCC contract §4.4): the echo of a node's own frame on its other
    // channel is the notice of its transmission, never delivered to its host.
    assert!(
        r.own.iter().all(|&n| n == 0),
        "{}: own frames delivered back per node: {:?}",
        s.fault.name(),
        r.own
    );
}

/// Each target port isolated during the fault with the expected kind, nothing else
/// isolated, each target restored after the fault ended. Returns the isolation
/// delays in bit times.
fn assert_isolated_and_restored(s: &StarScenario, r: &StarReport) -> Vec<u64> {
    let name = s.fault.name();
    let targets = s.fault.target_ports();
    assert!(
        r.false_isolations(&targets).is_empty(),
        "{name}: ports isolated that are not faulty: {:?}",
        r.false_isolations(&targets)
    );
    let mut delays = Vec::new();
    for &(h, p) in &targets {
        let at = r
            .isolated_at(h, p, r.fault_start)
            .unwrap_or_else(|| panic!("{name}: hub {} port {p} never isolated", h + 1));
        assert!(
            at < r.fault_end,
            "{name}: isolated only after the fault ended"
        );
        delays.push(bits_after(r.fault_start, at));
        let reg = r.hub_ports[h][p];
        assert_eq!(
            Some(port_kind(reg)),
            s.fault.expected_kind(),
            "{name}: hub {} PORT_{p} = {reg:#010x}",
            h + 1
        );
        assert!(
            port_isolations(reg) >= 1,
            "{name}: PORT_{p} counts no isolation"
        );
        let back = r
            .restored_at(h, p, r.fault_end)
            .unwrap_or_else(|| panic!("{name}: hub {} port {p} never restored", h + 1));
        assert_eq!(reg & 1, 1, "{name}: PORT_{p} not enabled at the end");
        if matches!(
            s.fault,
            StarFault::UplinkStuckDominant | StarFault::SublinkStuckDominant
        ) {
            // A stuck-dominant link shows its symptom until the fault ends, so the
            // restoration counter (§6) starts at the end at the earliest.
            assert!(
                bits_after(r.fault_end, back) >= s.hub.restore_bits as u64,
                "{name}: restored {} bit times after the fault, before restore_bits",
                bits_after(r.fault_end, back)
            );
        }
    }
    delays
}

#[test]
fn no_fault_isolates_nothing_and_delivers_everything_once() {
    let (s, r) = run(StarFault::None);
    assert_lossless(&s, &r);
    assert!(
        r.events.is_empty(),
        "isolations without a fault: {:?}",
        r.events
    );
    assert_eq!(r.decoupled_at, [None, None]);
    // Coupled hubs bring every frame to both channels of every node: the DRCC
    // removes one copy of each, and no node sees an omission.
    for i in 0..s.nodes {
        assert_eq!(r.omissions(i), 0, "node {i}");
    }
    // Both hubs tracked every frame to its ACK slot (STATS[15:0]).
    let frames = s.nodes * s.frames_per_node;
    for h in 0..2 {
        assert_eq!(
            r.hub_stats[h] & 0xFFFF,
            frames as u32,
            "hub {} STATS",
            h + 1
        );
    }
}

#[test]
fn uplink_stuck_dominant_is_isolated_at_the_14th_dominant_bit() {
    let (s, r) = run(StarFault::UplinkStuckDominant);
    assert_lossless(&s, &r);
    let d = assert_isolated_and_restored(&s, &r);
    // §6 rule SD: the SAMPLE edge where dom_run reaches sd_run_up (14); the first
    // dominant sample comes within one bit time of the onset.
    let limit = HubConfig::default().sd_run_up as u64;
    assert!(
        (limit - 1..=limit).contains(&d[0]),
        "isolated after {} bit times",
        d[0]
    );
}

#[test]
fn uplink_bit_flipping_is_isolated_and_loses_nothing() {
    let (s, r) = run(StarFault::UplinkBitFlipping);
    assert_lossless(&s, &r);
    let d = assert_isolated_and_restored(&s, &r);
    // BF: +8 per blamed frame, isolation at pec >= bf_up (32): at least four frames
    // with a flipped bit, i.e. more than one frame length after the onset.
    assert!(d[0] >= 44, "isolated after {} bit times", d[0]);
}

#[test]
fn uplink_stuck_recessive_is_isolated_as_silent() {
    let (s, r) = run(StarFault::UplinkStuckRecessive);
    assert_lossless(&s, &r);
    let d = assert_isolated_and_restored(&s, &r);
    // SR: sr_frames (8) whole frames through their ACK slot, each at least 44 bits.
    let frames = HubConfig::default().sr_frames as u64;
    assert!(d[0] >= frames * 44, "isolated after {} bit times", d[0]);
}

#[test]
fn cut_downlink_loses_nothing_and_the_deaf_node_is_contained() {
    let (s, r) = run(StarFault::DownlinkCut);
    assert_lossless(&s, &r);
    assert_isolated_and_restored(&s, &r);
    // Node 3 hears hub 1 no more: every frame reaches it through hub 2 only.
    assert!(r.omissions(3) > 0, "node 3 saw no omission");
}

#[test]
fn incoming_sublink_stuck_dominant_is_isolated_at_the_16th_dominant_bit() {
    let (s, r) = run(StarFault::SublinkStuckDominant);
    assert_lossless(&s, &r);
    let d = assert_isolated_and_restored(&s, &r);
    let limit = HubConfig::default().sd_run_sub as u64;
    assert!(
        (limit - 1..=limit).contains(&d[0]),
        "isolated after {} bit times",
        d[0]
    );
    assert_eq!(r.decoupled_at, [None, None]);
}

#[test]
fn one_interlink_lost_keeps_the_hubs_coupled() {
    let (s, r) = run(StarFault::InterlinkLost);
    assert_lossless(&s, &r);
    assert_isolated_and_restored(&s, &r);
    assert_eq!(
        r.decoupled_at,
        [None, None],
        "the other interlink carries the coupling"
    );
    for i in 0..s.nodes {
        assert_eq!(
            r.omissions(i),
            0,
            "node {i}: the coupling held, both hubs deliver"
        );
    }
}

/// NRAP phases (hub contract §9.2).
const RUN: u8 = 0;
const SPLIT: u8 = 6;

/// §9.5 worst cases from a hub's trigger with the default registers (64, 1024,
/// 1024, 64, 1024): recoupling, and definitive decoupling.
const RECOUPLE_BOUND: u64 = 64 + 1024 + 1024;
const SPLIT_BOUND: u64 = 64 + 1024 + 1024 + 64 + 1024;

/// Each hub ran NRAP once after the onset and ended in `end`, within `bound` bit
/// times of its own start (the hub counts its own bit times, which resynchronisation
/// stretches a little: allow 1/64); returns the end clocks.
fn assert_nrap_ended(s: &StarScenario, r: &StarReport, end: u8, bound: u64) -> [u64; 2] {
    let name = s.fault.name();
    let mut ends = [0u64; 2];
    for (h, end_clock) in ends.iter_mut().enumerate() {
        let first = r
            .nrap_events
            .iter()
            .find(|e| e.hub == h && e.cycle >= r.fault_start)
            .unwrap_or_else(|| panic!("{name}: hub {} never ran NRAP", h + 1));
        let (finish, phase) = r
            .nrap_events
            .iter()
            .find(|e| e.hub == h && e.cycle > first.cycle && (e.phase == RUN || e.phase == SPLIT))
            .map(|e| (e.cycle, e.phase))
            .unwrap_or_else(|| panic!("{name}: hub {} NRAP never ended", h + 1));
        assert_eq!(phase, end, "{name}: hub {} ended in phase {phase}", h + 1);
        let took = bits_after(first.cycle, finish);
        assert!(
            took <= bound + bound / 64,
            "{name}: hub {} took {took} bit times (bound {bound})",
            h + 1
        );
        assert_eq!(r.final_phase(h), end, "{name}: hub {} NRAP_STATUS", h + 1);
        assert_eq!(
            r.hub_nrap[h] >> 3 & 1,
            (end == RUN) as u32,
            "{name}: hub {} outcome",
            h + 1
        );
        *end_clock = finish;
    }
    ends
}

/// Every node's `STAR_STATUS.split` (DRCC contract §4.5) shows `split`.
fn assert_nodes_follow(s: &StarScenario, r: &StarReport, split: bool) {
    assert_eq!(
        r.node_split(),
        vec![split; s.nodes],
        "{}: the nodes' domain (STAR_STATUS {:x?})",
        s.fault.name(),
        r.star_status
    );
    // The identification frames are the hubs' traffic: no host got one.
    assert!(r.hub_frames.iter().all(|&n| n == 0), "{:?}", r.hub_frames);
}

#[test]
fn all_interlinks_lost_ends_in_an_agreed_definitive_decoupling_and_loses_nothing() {
    // Before NRAP the hubs decoupled on their own at different times and 2
    // frames were lost. Now both run NRAP (paper section 5), each ends in SPLIT
    // within the §9.5 bound, every node's register says so, and nothing is lost.
    let (s, r) = run(StarFault::AllInterlinksLost);
    assert_lossless(&s, &r);
    assert_nrap_ended(&s, &r, SPLIT, SPLIT_BOUND);
    assert_nodes_follow(&s, &r, true);
    let targets = s.fault.target_ports();
    assert!(r.false_isolations(&targets).iter().all(|e| e.port < HUB_N));
    // ACK interdependence: a frame that started after the onset completes nowhere
    // until the first hub decides on its own star (DDSP_FORCE sets `decoupled`).
    assert_eq!(receptions_while_blocked(&r), 0);
    let first = r.decoupled_at.iter().flatten().min().copied().unwrap();
    let after = r
        .received_at
        .iter()
        .flatten()
        .filter(|&&c| c >= first && c < r.fault_end)
        .count();
    assert!(after > 0, "no star carried traffic after the decision");
}

#[test]
fn a_transient_loss_of_every_interlink_recouples_through_nrap() {
    // Both interlinks cut for 1500 bit times: one hub triggers while they are down;
    // once they are back its identification frames reach the other hub, which joins
    // (§9.2), and both recouple at the ACK slot of the same frame.
    let (s, r) = run(StarFault::TransientDecoupling);
    assert_lossless(&s, &r);
    let ends = assert_nrap_ended(&s, &r, RUN, RECOUPLE_BOUND);
    assert!(
        ends[0].abs_diff(ends[1]) < CLOCKS_PER_BIT,
        "the hubs recoupled at bit times {} and {}",
        ends[0] / CLOCKS_PER_BIT,
        ends[1] / CLOCKS_PER_BIT
    );
    assert_eq!(r.decoupled_at, [None, None], "neither hub decoupled");
    assert_nodes_follow(&s, &r, false);
    // The restored nodes resume together: nobody received anything between the
    // onset's blocking and the recoupling.
    let blocked_from = r.fault_start + 130 * CLOCKS_PER_BIT;
    let early = r
        .received_at
        .iter()
        .flatten()
        .filter(|&&c| (blocked_from..ends[0]).contains(&c))
        .count();
    assert_eq!(early, 0, "frames completed before the hubs recoupled");
}

#[test]
fn a_permanent_loss_splits_the_network_into_two_working_stars() {
    let (s, r) = run(StarFault::PermanentDecoupling);
    assert_lossless(&s, &r);
    let ends = assert_nrap_ended(&s, &r, SPLIT, SPLIT_BOUND);
    assert_nodes_follow(&s, &r, true);
    // After both decided, both stars carry traffic: each node delivers frames from
    // both channels (the copy through the other star is dropped as a duplicate).
    let split = ends[0].max(ends[1]);
    let after: usize = r
        .received_at
        .iter()
        .map(|v| v.iter().filter(|&&c| c > split).count())
        .sum();
    assert!(after > 0, "nothing delivered after the split");
    assert!(
        r.dups_dropped.iter().all(|&d| d > 0),
        "every node removed copies that came through the other star: {:?}",
        r.dups_dropped
    );
}

#[test]
fn a_hub_that_does_not_couple_its_twin_is_settled_by_nrap() {
    // Paper section 3's malicious hub (CTRL.fi_no_twin on hub 2): its sublinks stay
    // enabled and nothing is isolated, but no frame is acknowledged through the
    // coupling any more; the blocked-network trigger starts NRAP and both hubs end
    // in the same decision, which every node follows.
    let (s, r) = run(StarFault::HubIgnoresTwin);
    assert_lossless(&s, &r);
    assert_nrap_ended(&s, &r, SPLIT, SPLIT_BOUND);
    assert_nodes_follow(&s, &r, true);
}

#[test]
fn a_hub_that_passes_its_own_ack_is_held_by_its_ack_unit() {
    let (s, r) = run(StarFault::HubLeaksAck);
    assert_lossless(&s, &r);
    assert!(
        r.hub_ack_unit[0] & 0xFFFF > 0,
        "ACK_UNIT = {:#x}",
        r.hub_ack_unit[0]
    );
    assert_eq!(r.hub_ack_unit[1] & 0xFFFF, 0);
    assert!(r.nrap_events.is_empty(), "a guarded leak needs no NRAP");
}

/// Receptions at any host between the moment ACK interdependence must have blocked
/// every star (130 bit times after the onset: one frame may be under way) and the
/// first decoupling.
fn receptions_while_blocked(r: &StarReport) -> usize {
    let blocked_from = r.fault_start + 130 * CLOCKS_PER_BIT;
    let first = r
        .decoupled_at
        .iter()
        .flatten()
        .min()
        .copied()
        .unwrap_or(r.cycles);
    r.received_at
        .iter()
        .flatten()
        .filter(|&&c| (blocked_from..first).contains(&c))
        .count()
}

#[test]
fn the_ack_units_hold_two_hubs_that_leak_their_own_ack() {
    // Paper section 4: ACK interdependence assumes no hub passes its own nodes'
    // ACK; the ACK unit (hub contract §4.1) enforces it. Both hubs are made to leak
    // (`CTRL.fi_ack_leak`) and every interlink is lost.
    let honest = StarScenario::standard(StarFault::AllInterlinksLost);
    let mut leaky = honest;
    leaky.hub.fi_ack_leak = true;

    // Without the units (the model only: the RTL always has them), each star
    // acknowledges its own frames and carries traffic while the hubs are still
    // coupled: the two domains the mechanism exists to prevent.
    let mut unguarded = leaky;
    unguarded.ack_units = false;
    let r = run_star(&unguarded, EngineKind::Model, None).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        receptions_while_blocked(&r) > 0,
        "a leaking hub without its ACK unit should let its star carry traffic"
    );

    // With them, the leaking hubs behave exactly as honest ones, clock by clock on
    // the model and the Verilated RTL, and each unit counts its interventions.
    let (_, base) = run(StarFault::AllInterlinksLost);
    let r = run_star(&leaky, EngineKind::Model, cosim_engine()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(receptions_while_blocked(&r), 0);
    assert_eq!(
        r.received_at, base.received_at,
        "the same deliveries at the same clocks"
    );
    assert_eq!(r.decoupled_at, base.decoupled_at);
    assert_eq!(
        r.events, base.events,
        "the same isolations and restorations"
    );
    for h in 0..2 {
        assert_eq!(
            base.hub_ack_unit[h] & 0xFFFF,
            0,
            "honest hub {}: no intervention",
            h + 1
        );
        assert!(
            r.hub_ack_unit[h] & 0xFFFF > 0,
            "leaking hub {}: ACK_UNIT = {:#x}",
            h + 1,
            r.hub_ack_unit[h]
        );
    }
}

/// Runs `rows` with rust-hdl's hubs in lock step with the hub models, one thread
/// per row.
fn rust_hdl_rows(rows: &[StarFault]) {
    std::thread::scope(|scope| {
        for &f in rows {
            scope.spawn(move || {
                let s = StarScenario::standard(f);
                let r = run_star(&s, EngineKind::Model, Some(EngineKind::RustHdl))
                    .unwrap_or_else(|e| panic!("{e}"));
                assert!(r.exactly_once(), "{}", f.name());
            });
        }
    });
}

/// The third engine: rust-hdl's simulation of the hub blocks (hub A and hub B, with
/// model nodes) in lock step with the hub models, clock by clock, every hub output
/// and probe, on the NRAP row where one hub triggers, the other joins and both
/// recouple (§9.2) (the Verilated RTL runs every row above). A row in lock step
/// with rust-hdl takes about ten times as long as with the Verilated RTL (130 s
/// against 15 s on a 2-core machine), so the other NRAP rows run on it in the
/// soak below.
#[test]
fn the_rust_hdl_hubs_agree_with_the_models_through_an_nrap_recoupling() {
    rust_hdl_rows(&[StarFault::TransientDecoupling]);
}

/// The soak (scripts/soak.sh): the other NRAP rows on rust-hdl's hubs.
#[test]
#[ignore = "soak: scripts/soak.sh runs it"]
fn soak_the_rust_hdl_hubs_agree_with_the_models_on_every_nrap_row() {
    rust_hdl_rows(&[
        StarFault::AllInterlinksLost,
        StarFault::PermanentDecoupling,
        StarFault::HubIgnoresTwin,
        StarFault::HubLeaksAck,
    ]);
}
