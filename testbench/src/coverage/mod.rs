//! Functional coverage over the test suite's workloads
//! (`drcc coverage`): the reference model's cover points
//! ([`drcc_cosim::model::coverage`]) counted while the workloads the tests run
//! execute on the model: every conformance item, random traffic, random error
//! stress, the dual-bus and star fault tables, the DMR plan, a hub's random
//! register and link stimulus, and small fault campaigns on both topologies.
//!
//! The bins come from the standard, the papers and the contracts
//! (`coverage::bins`), not from what a run hits; the report lists every bin with
//! its count, the bins never hit, the combinations that cannot occur (with the
//! reason) and any name counted that is not a bin (an illegal transition, or a
//! cover point without a definition).

pub mod races;

use std::collections::BTreeMap;
use std::time::{Duration, Instant};

use drcc_cosim::engine::hub::{HubEngine, HubOutputs};
use drcc_cosim::engine::hub_model::HubModelEngine;
use drcc_cosim::model::coverage::{self, Bin, Unreachable};

use crate::campaign::{self, Campaign, Topology};
use crate::conformance;
use crate::dmr::PlanConfig;
use crate::engines::EngineKind;
use crate::fault_gen::{plan, FaultEvent, FaultParams};
use crate::hub_stim::HubStim;
use crate::random::Traffic;
use crate::scenario::Expectations;

/// One workload: its name and the run.
pub struct Workload {
    pub name: &'static str,
    pub run: fn() -> Result<(), String>,
}

/// The workloads, in run order.
pub fn workloads() -> Vec<Workload> {
    vec![
        Workload {
            name: "conformance suite (every ISO 16845-1 item, model)",
            run: conformance_items,
        },
        Workload {
            name: "random traffic (3 seeds, 1 Mbit/s and 125 kbit/s)",
            run: random_traffic,
        },
        Workload {
            name: "random error stress (4 episodes)",
            run: error_stress,
        },
        Workload {
            name: "dual-bus fault table and the paper's experiment",
            run: dual_table,
        },
        Workload {
            name: "star fault table",
            run: star_table,
        },
        Workload {
            name: "DMR plan (Tables 2 and 3; deviation limit 3)",
            run: dmr_plan,
        },
        Workload {
            name: "DMR plan (Tables 2 and 3; deviation limit 100)",
            run: dmr_plan_timeouts,
        },
        Workload {
            name: "DRCC register port: byte-lane writes (bus contract §1)",
            run: drcc_byte_lanes,
        },
        Workload {
            name: "hub random register and link stimulus (200,000 clocks)",
            run: hub_stimulus,
        },
        Workload {
            name: "two hubs through NRAP with a node that errs in node restoration",
            run: nrap_erring_node,
        },
        Workload {
            name: "a hub with NRAP off whose sublink is stuck dominant decouples",
            run: hub_decouples_without_nrap,
        },
        Workload {
            name: "a star node whose transceiver dies in the ACK slot of its second attempt",
            run: star_echo_in_wait2,
        },
        Workload {
            name: "fault campaign, dual bus (150 single faults, first half)",
            run: || campaign_part(Topology::Dual, 150, (1, 2)),
        },
        Workload {
            name: "fault campaign, dual bus (150 single faults, second half)",
            run: || campaign_part(Topology::Dual, 150, (2, 2)),
        },
        Workload {
            name: "fault campaign, star (40 single faults)",
            run: || campaign_part(Topology::Star, 40, (1, 1)),
        },
        Workload {
            name: "random search for the main FSM's races (runs 0..500 of 1,500)",
            run: || main_fsm_races(0..500),
        },
        Workload {
            name: "random search for the main FSM's races (runs 500..1,000 of 1,500)",
            run: || main_fsm_races(500..1_000),
        },
        Workload {
            name: "random search for the main FSM's races (runs 1,000..1,500 of 1,500)",
            run: || main_fsm_races(1_000..races::RUNS),
        },
    ]
}

fn conformance_items() -> Result<(), String> {
    for (_, item) in conformance::items::ITEMS {
        item(&conformance::model_iut);
    }
    Ok(())
}

fn random_traffic() -> Result<(), String> {
    for (seed, hz, bitrate) in [
        (1, 8_000_000, 1_000_000),
        (2, 8_000_000, 1_000_000),
        (3, 24_000_000, 125_000),
    ] {
        let sc = Traffic::new(seed, 80, hz, bitrate).scenario()?;
        crate::run::run(&sc, EngineKind::Model)?;
    }
    Ok(())
}

fn error_stress() -> Result<(), String> {
    for seed in 1..=4u64 {
        let mut t = Traffic::new(seed, 200, 8_000_000, 1_000_000);
        t.nodes = 3 + (seed as usize % 3);
        t.max_gap_bits = 600;
        let mut sc = t.scenario()?;
        let cpb = sc.clocks_per_bit();
        sc.expect = Expectations::Explicit(Vec::new());
        let mut params = FaultParams::new(seed, 25 * cpb, 5_000 * cpb);
        params.forced = vec![(0.3, FaultEvent::LongDominant), (0.6, FaultEvent::BusOff)];
        let fp = plan(&sc, &params)?;
        sc.faults = fp.faults.clone();
        sc.max_cycles = sc.max_cycles.max(fp.end + 20_000 * cpb);
        crate::run::run(&sc, EngineKind::Model)?;
    }
    Ok(())
}

fn dual_table() -> Result<(), String> {
    crate::dual::fault_table(EngineKind::Model, None)?;
    crate::paper::switchover_table(EngineKind::Model)?;
    // The warning-limit policy (DRCC contract §5, policy 3) on a line stuck
    // dominant: the counters pass `ewl` before error passive.
    let mut s = crate::dual::DualScenario::standard(crate::dual::DualFault::AStuckDominant);
    s.policy = drcc_cosim::host::Policy::Warning;
    crate::dual::run_dual(&s, EngineKind::Model, None)?;
    Ok(())
}

fn star_table() -> Result<(), String> {
    crate::star::star_table(EngineKind::Model, None).map(|_| ())
}

fn dmr_plan() -> Result<(), String> {
    crate::dmr::report::dmr_table(&PlanConfig::standard(), EngineKind::Model, None, |_| {})
        .map(|_| ())
}

/// With a deviation limit the skew of a fault never reaches, the mailboxes
/// judge by their timeout (CiA 701 Tables 2 and 3: "timeout").
fn dmr_plan_timeouts() -> Result<(), String> {
    let timeouts = PlanConfig {
        limit: 100,
        ..PlanConfig::standard()
    };
    crate::dmr::report::dmr_table(&timeouts, EngineKind::Model, None, |_| {}).map(|_| ())
}

/// Writes with partial byte lanes on the DRCC model's register port: each kind of
/// word (bus contract §1) must answer as the contract says, ACK for a staged TX
/// word, ERR for a whole word.
fn drcc_byte_lanes() -> Result<(), String> {
    use drcc_cosim::engine::drcc::{DrccEngine, DrccInputs};
    use drcc_cosim::engine::drcc_model::DrccModelEngine;
    use drcc_cosim::model::drcc::regs::idx;
    let mut e = DrccModelEngine::new();
    e.step(&DrccInputs {
        rst: true,
        ..Default::default()
    });
    for (adr, sel, err) in [
        (idx::TX_DATA0, 0b0100, false),
        (idx::TX_ID, 0b0011, false),
        (idx::BTR, 0b0001, true),
    ] {
        let o = e.step(&DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: true,
            wb_adr: adr,
            wb_dat_w: 0x5A5A_5A5A,
            wb_sel: sel,
            ..Default::default()
        });
        if o.wb_err != err || o.wb_ack == err {
            return Err(format!(
                "word {adr} with lanes {sel:#06b}: ack {} err {} (bus contract §1 says err {err})",
                o.wb_ack, o.wb_err
            ));
        }
        e.step(&DrccInputs::default());
    }
    Ok(())
}

fn hub_stimulus() -> Result<(), String> {
    for (seed, n, m) in [(1, 4, 2), (2, 3, 1)] {
        let mut hub = HubModelEngine::new(n, m)?;
        let mut stim = HubStim::new(seed, n, m);
        let mut prev = HubOutputs::default();
        for _ in 0..100_000 {
            let i = stim.next(&prev);
            prev = hub.step(&i);
        }
    }
    Ok(())
}

/// Two hub models wired back to back (N = 2, M = 1, the star scenarios' bit
/// timing), NRAP on: hub B's incoming sublink is held dominant for 40 bit times, so
/// both hubs run NRAP; during node restoration hub A's node port 0 drives 20
/// dominant bits inside the identification frames (hub contract §9.2: the port
/// is disabled at once).
fn nrap_erring_node() -> Result<(), String> {
    use drcc_cosim::engine::hub::HubInputs;
    use drcc_cosim::star::hub_host::HubHost;
    let cpb = crate::star::CLOCKS_PER_BIT;
    let cfg = crate::star::StarScenario::standard(crate::star::StarFault::None).hub;
    let mut hubs = [
        HubModelEngine::new_hub(0, 2, 1)?,
        HubModelEngine::new_hub(1, 2, 1)?,
    ];
    let mut hosts = [HubHost::new(cfg), HubHost::new(cfg)];
    let mut out = [HubOutputs::default(); 2];
    let (mut nrp_seen, mut node_dominant, mut in_frame) = (None, 0u64, 0u64);
    for c in 0..12_000 * cpb {
        let bit = c / cpb;
        let stuck = (100..140).contains(&bit);
        if nrp_seen.is_none() && out[0].probes.nrap_phase == 3 {
            nrp_seen = Some(c);
        }
        // Clocks since hub A's tracker entered a frame (state FRAME = 1).
        in_frame = if out[0].probes.trk_state == 1 {
            in_frame + 1
        } else {
            0
        };
        // Bits 20..25 of the first identification frame in node restoration: past
        // the arbitration field, where only the hub drives the bus.
        let erring = nrp_seen.is_some()
            && node_dominant < 5 * cpb
            && (20 * cpb..25 * cpb).contains(&in_frame);
        node_dominant += erring as u64;
        let prev = out;
        for h in 0..2 {
            let mut i = HubInputs {
                rst: c < 2,
                uplink: if h == 0 && erring { 0b10 } else { 0b11 },
                sublink_in: if h == 1 && stuck {
                    0
                } else {
                    prev[1 - h].sublink_out & 1
                },
                ..HubInputs::default()
            };
            hosts[h].drive(c, &prev[h], c < 2, &mut i);
            out[h] = hubs[h].step(&i);
        }
    }
    if nrp_seen.is_none() || node_dominant == 0 {
        return Err("the two hubs never reached node restoration".to_string());
    }
    Ok(())
}

/// One hub model (N = 2, M = 1, the star scenarios' configuration) with NRAP off
/// (`CTRL.nrap_on` = 0): its incoming sublink stuck dominant from bit 100 on is
/// isolated and, showing a symptom at every bit, never restored, so after
/// `decouple_bits` without a sublink the hub decouples on its own (hub contract
/// §7). The star table's NRAP-off row no longer gets there: with the star node's
/// soft restart (DRCC contract §5) its hubs restore their silent sublinks first.
fn hub_decouples_without_nrap() -> Result<(), String> {
    use drcc_cosim::engine::hub::HubInputs;
    use drcc_cosim::star::hub_host::HubHost;
    let cpb = crate::star::CLOCKS_PER_BIT;
    let mut cfg = crate::star::StarScenario::standard(crate::star::StarFault::None).hub;
    cfg.nrap_on = false;
    let mut hub = HubModelEngine::new_hub(0, 2, 1)?;
    let mut host = HubHost::new(cfg);
    let mut out = HubOutputs::default();
    let bits = 100 + cfg.decouple_bits as u64 + 400;
    for c in 0..bits * cpb {
        let mut i = HubInputs {
            rst: c < 2,
            uplink: 0b11,
            sublink_in: if c / cpb >= 100 { 0 } else { 1 },
            ..HubInputs::default()
        };
        let prev = out;
        host.drive(c, &prev, c < 2, &mut i);
        out = hub.step(&i);
    }
    if !out.probes.decoupled {
        return Err("the hub with NRAP off did not decouple".to_string());
    }
    Ok(())
}

/// Star, no fault but on node 0's links to hub 1: one bit of node 0's first frame
/// is inverted on its uplink (a bit error: channel A's first failed attempt), then
/// its transceiver on hub 1 dies (uplink and downlink recessive) in the ACK slot of
/// the retransmission. Channel A sees an ACK error nobody else sees: its second
/// failure fails it (k = 2), the main FSM aborts A and waits in wait2, and channel
/// B's reception of the frame the others took completes the message there (DRCC
/// contract §4.4, the echo ahead of a failure). The star table's NRAP rows reached
/// this by chance before the soft restart; here the two instants are found by
/// running the same deterministic system up to each of them.
fn star_echo_in_wait2() -> Result<(), String> {
    use crate::star::{build_star, StarFault, StarScenario, CLOCKS_PER_BIT};
    use drcc_cosim::star::{Link, LinkFault, LinkFaultKind};
    const CH1: u8 = 2;
    const WAIT2: u8 = 4;
    const DATA: u8 = 10;
    const ACK_SLOT: u8 = 13;
    let mut s = StarScenario::standard(StarFault::None);
    s.frames_per_node = 2;
    let flip = |at: u64| LinkFault {
        link: Link::Uplink { hub: 0, node: 0 },
        kind: LinkFaultKind::BitFlip {
            period: u64::MAX / 2,
            width: CLOCKS_PER_BIT,
        },
        start: at,
        cycles: CLOCKS_PER_BIT,
    };
    let limit = 3_000 * CLOCKS_PER_BIT;
    // 1. The first data bit of node 0's first attempt on A.
    let mut sys = build_star(&s, EngineKind::Model)?;
    let mut data_at = None;
    while sys.cycle() < limit && data_at.is_none() {
        sys.step();
        let p = sys.node(0).outputs.probes;
        if p.state == CH1 && p.chan_a_field == DATA {
            data_at = Some(sys.cycle());
        }
    }
    let data_at = data_at.ok_or("node 0 never sent a data field on A")? + CLOCKS_PER_BIT;
    // 2. With that bit inverted: the ACK slot of the retransmission.
    let mut sys = build_star(&s, EngineKind::Model)?;
    sys.add_fault(flip(data_at))?;
    let mut ack_at = None;
    while sys.cycle() < limit && ack_at.is_none() {
        sys.step();
        let p = sys.node(0).outputs.probes;
        if sys.cycle() > data_at + 20 * CLOCKS_PER_BIT
            && p.state == CH1
            && p.chan_a_field == ACK_SLOT
        {
            ack_at = Some(sys.cycle());
        }
    }
    let ack_at = ack_at.ok_or("node 0 never retransmitted on A")?;
    // 3. Both, and the transceiver dead from that ACK slot on.
    let mut sys = build_star(&s, EngineKind::Model)?;
    sys.add_fault(flip(data_at))?;
    for link in [
        Link::Uplink { hub: 0, node: 0 },
        Link::Downlink { hub: 0, node: 0 },
    ] {
        sys.add_fault(LinkFault {
            link,
            kind: LinkFaultKind::StuckRecessive,
            start: ack_at,
            cycles: u64::MAX / 2,
        })?;
    }
    let mut before = sys.node(0).outputs.probes.state;
    while sys.cycle() < limit {
        sys.step();
        let p = sys.node(0).outputs.probes;
        if before == WAIT2 && p.transmission_ack {
            return Ok(());
        }
        before = p.state;
    }
    Err("node 0's message was not completed in wait2".to_string())
}

/// One shard of a campaign: the workloads are split so that the threads share
/// the long ones.
fn campaign_part(topology: Topology, count: u64, shard: (u64, u64)) -> Result<(), String> {
    let c = Campaign {
        topology,
        faults: 1,
        count,
        seed: 2026,
        shard,
        engine: EngineKind::Model,
    };
    campaign::run(
        &c,
        1,
        &mut std::io::sink(),
        |_, _| Ok(()),
        |_| {},
        Duration::from_secs(3600),
    )
    .map(|_| ())
}

fn main_fsm_races(runs: std::ops::Range<u64>) -> Result<(), String> {
    runs.into_iter().try_for_each(races::run)
}

/// What a collection found.
#[derive(Clone, Debug)]
pub struct Report {
    pub counts: BTreeMap<String, u64>,
    pub bins: Vec<Bin>,
    pub unreachable: Vec<Unreachable>,
    /// Wall time per workload.
    pub times: Vec<(&'static str, Duration)>,
}

impl Report {
    /// Bins never hit.
    pub fn missed(&self) -> Vec<&Bin> {
        self.bins
            .iter()
            .filter(|b| self.count(&b.name) == 0)
            .collect()
    }

    /// Names counted that are not bins.
    pub fn unlisted(&self) -> Vec<(String, u64)> {
        coverage::unlisted(&self.counts)
    }

    pub fn count(&self, name: &str) -> u64 {
        self.counts.get(name).copied().unwrap_or(0)
    }

    /// The report as Markdown: every bin with its count by group, then the bins
    /// never hit, the unlisted names and the unreachable combinations.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let hit = self.bins.len() - self.missed().len();
        s.push_str(&format!(
            "{hit} of {} bins hit ({} unlisted names counted)\n\n",
            self.bins.len(),
            self.unlisted().len()
        ));
        s.push_str("| group | bin | hits | source |\n|---|---|---:|---|\n");
        for b in &self.bins {
            s.push_str(&format!(
                "| {} | {} | {} | {} |\n",
                b.group,
                b.name,
                self.count(&b.name),
                b.source
            ));
        }
        let missed = self.missed();
        if !missed.is_empty() {
            s.push_str("\nNever hit:\n");
            for b in missed {
                s.push_str(&format!("- {}\n", b.name));
            }
        }
        let unlisted = self.unlisted();
        if !unlisted.is_empty() {
            s.push_str(
                "\nCounted but not a bin (illegal, or a cover point without a definition):\n",
            );
            for (n, c) in unlisted {
                s.push_str(&format!("- {n}: {c}\n"));
            }
        }
        s.push_str("\nUnreachable (cannot occur):\n\n| group | what | why |\n|---|---|---|\n");
        for u in &self.unreachable {
            s.push_str(&format!("| {} | {} | {} |\n", u.group, u.what, u.reason));
        }
        s
    }
}

/// Runs every workload on the model with coverage on, on every core (rayon; the
/// counts are summed over threads); `progress` sees each workload's name before
/// it runs. One collection at a time per process (the counters are global). The
/// first failing workload's error, in run order, is returned.
pub fn collect(progress: impl Fn(&str) + Sync) -> Result<Report, String> {
    use rayon::prelude::*;
    let list = workloads();
    coverage::start();
    let done: Vec<Result<Duration, String>> = list
        .par_iter()
        .with_max_len(1)
        .map(|w| {
            progress(w.name);
            let t = Instant::now();
            (w.run)()
                .map(|()| t.elapsed())
                .map_err(|e| format!("{}: {e}", w.name))
        })
        .collect();
    let counts = coverage::stop();
    let mut times = Vec::new();
    for (w, r) in list.iter().zip(done) {
        times.push((w.name, r?));
    }
    Ok(Report {
        counts,
        bins: coverage::bins(),
        unreachable: coverage::unreachable(),
        times,
    })
}
