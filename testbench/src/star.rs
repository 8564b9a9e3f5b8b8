//! Replicated-star fault scenarios (issue "ReCANcentrate hub"): 4 DRCC nodes in
//! redundancy mode, channel A on hub 1, channel B on hub 2, two hubs coupled by two
//! interlinks; every host submits frames; one fault on one link for a while. A run
//! reports, per scenario:
//!
//! - bit times from the fault's onset to the isolation of the faulty port (by the
//!   hub that owns it), read from the hubs' `port_enabled` probes;
//! - frames lost at the application level: every frame submitted by a host must
//!   reach every other host exactly once (the DRCC's duplicate removal drops the
//!   second copy; the one-copy frames are the *omissions* the node detects);
//! - bit times from the end of the fault to the restoration of the port;
//! - every isolation that happened (a port isolated that is not the faulty one is a
//!   false isolation and shows up in the report).
//!
//! The nodes transmit through one hub (dual_tx off: the coupled hubs bring every frame
//! to both controllers of every node, paper section 2.1) and switch hubs after two
//! failed attempts (k-failed policy).

use drcc_cosim::dual::host::{btr, reg, HostConfig, Policy};
use drcc_cosim::engine::drcc::DrccEngine;
use drcc_cosim::engine::hub::HubEngine;
use drcc_cosim::star::hub_host::{hub_reg, HubConfig};
use drcc_cosim::star::lockstep::compare;
use drcc_cosim::star::{Link, LinkFault, LinkFaultKind, StarSystem};
use drcc_cosim::Frame;

use crate::dual::drcc_engine;
use crate::engines::{EngineKind, VERILATOR_HINT};

/// Bit timing of the star scenarios: a time quantum of 2 clocks, TSEG1 13 tq, TSEG2
/// 4 tq, SJW 2: 36 clocks per bit, sample point at 28 clocks (78 %). The long
/// propagation segment covers the loop node → hub → twin hub → node → and back
/// (6 + 2 + 1 clocks each way through the hubs, the nodes' synchronizers and
/// output registers; `docs/hub.md` computes it).
pub const STAR_BRP: u8 = 1;
pub const STAR_TSEG1: u8 = 13;
pub const STAR_TSEG2: u8 = 4;
pub const STAR_SJW: u8 = 2;
/// Clocks per bit of the star scenarios.
pub const CLOCKS_PER_BIT: u64 = 36;

/// Node ports and interlinks of the scenarios' hubs (the emitted `hub.v`).
pub const HUB_N: usize = 4;
pub const HUB_M: usize = 2;

/// The fault of a star scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StarFault {
    None,
    UplinkStuckDominant,
    UplinkBitFlipping,
    UplinkStuckRecessive,
    DownlinkCut,
    SublinkStuckDominant,
    InterlinkLost,
    AllInterlinksLost,
}

impl StarFault {
    /// Every fault, in report order.
    pub const ALL: [StarFault; 8] = [
        StarFault::None,
        StarFault::UplinkStuckDominant,
        StarFault::UplinkBitFlipping,
        StarFault::UplinkStuckRecessive,
        StarFault::DownlinkCut,
        StarFault::SublinkStuckDominant,
        StarFault::InterlinkLost,
        StarFault::AllInterlinksLost,
    ];

    /// Name as reports and the CLI spell it.
    pub fn name(self) -> &'static str {
        match self {
            StarFault::None => "no_fault",
            StarFault::UplinkStuckDominant => "uplink_stuck_dominant",
            StarFault::UplinkBitFlipping => "uplink_bit_flipping",
            StarFault::UplinkStuckRecessive => "uplink_stuck_recessive",
            StarFault::DownlinkCut => "downlink_cut",
            StarFault::SublinkStuckDominant => "sublink_stuck_dominant",
            StarFault::InterlinkLost => "interlink_lost",
            StarFault::AllInterlinksLost => "all_interlinks_lost",
        }
    }

    /// Looks a fault up by name.
    pub fn from_name(s: &str) -> Option<StarFault> {
        StarFault::ALL.into_iter().find(|f| f.name() == s)
    }

    /// One fault (one link, or one interlink as a unit): the product promises no
    /// frame lost at the application level. Losing every interlink is a multiple
    /// fault; it promises that no frame completes while the hubs are blocked.
    pub fn is_single(self) -> bool {
        self != StarFault::AllInterlinksLost
    }

    /// What is faulty, in words.
    pub fn describe(self) -> &'static str {
        match self {
            StarFault::None => "nothing",
            StarFault::UplinkStuckDominant => "node 0 -> hub 1 uplink stuck dominant",
            StarFault::UplinkBitFlipping => {
                "node 1 -> hub 1 uplink inverted for 1 bit time in every 23"
            }
            StarFault::UplinkStuckRecessive => "node 2 -> hub 1 uplink stuck recessive",
            StarFault::DownlinkCut => "hub 1 -> node 3 downlink cut (reads recessive)",
            StarFault::SublinkStuckDominant => {
                "hub 2 -> hub 1 sublink of interlink 0 stuck dominant"
            }
            StarFault::InterlinkLost => "interlink 0 cut (both sublinks)",
            StarFault::AllInterlinksLost => "both interlinks cut (all four sublinks)",
        }
    }

    /// The links the fault acts on, with the kind.
    fn links(self) -> Vec<(Link, LinkFaultKind)> {
        use LinkFaultKind::*;
        let sub = |from, interlink| Link::Sublink { from, interlink };
        match self {
            StarFault::None => vec![],
            StarFault::UplinkStuckDominant => {
                vec![(Link::Uplink { hub: 0, node: 0 }, StuckDominant)]
            }
            StarFault::UplinkBitFlipping => vec![(
                Link::Uplink { hub: 0, node: 1 },
                BitFlip {
                    period: 23 * CLOCKS_PER_BIT,
                    width: CLOCKS_PER_BIT,
                },
            )],
            StarFault::UplinkStuckRecessive => {
                vec![(Link::Uplink { hub: 0, node: 2 }, StuckRecessive)]
            }
            StarFault::DownlinkCut => vec![(Link::Downlink { hub: 0, node: 3 }, StuckRecessive)],
            StarFault::SublinkStuckDominant => vec![(sub(1, 0), StuckDominant)],
            StarFault::InterlinkLost => {
                vec![(sub(0, 0), StuckRecessive), (sub(1, 0), StuckRecessive)]
            }
            StarFault::AllInterlinksLost => (0..HUB_M)
                .flat_map(|j| [(sub(0, j), StuckRecessive), (sub(1, j), StuckRecessive)])
                .collect(),
        }
    }

    /// The hub ports (hub, port) the fault should get isolated: the guarded input
    /// the faulty link feeds. A cut downlink feeds no guarded input, but it makes the
    /// node's uplink on that hub faulty: the node's controller never hears its own
    /// bits, so each dominant bit it sends is a bit error and its active error flags
    /// restart back to back (ISO 11898-1 10.11.2) until it is error passive, a
    /// dominant run the hub isolates as stuck-at-dominant (contract §6 rule SD).
    pub fn target_ports(self) -> Vec<(usize, usize)> {
        self.links()
            .into_iter()
            .map(|(l, _)| match l {
                Link::Uplink { hub, node } | Link::Downlink { hub, node } => (hub, node),
                Link::Sublink { from, interlink } => (1 - from, HUB_N + interlink),
            })
            .collect()
    }

    /// The fault kind (`PORT_p[3:1]`, contract §6) the target ports should show:
    /// 1 stuck-dominant, 2 silent, 3 bit-flipping.
    pub fn expected_kind(self) -> Option<u32> {
        match self {
            StarFault::None => None,
            StarFault::UplinkStuckDominant
            | StarFault::DownlinkCut
            | StarFault::SublinkStuckDominant => Some(1),
            StarFault::UplinkStuckRecessive
            | StarFault::InterlinkLost
            | StarFault::AllInterlinksLost => Some(2),
            StarFault::UplinkBitFlipping => Some(3),
        }
    }
}

/// A star scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StarScenario {
    pub fault: StarFault,
    pub nodes: usize,
    pub frames_per_node: usize,
    /// Bit times between two submissions of one host.
    pub period_bits: u64,
    /// Fault window in bit times.
    pub fault_start_bits: u64,
    pub fault_bits: u64,
    pub hub: HubConfig,
}

impl StarScenario {
    /// 4 nodes, 24 frames each, one every 500 bit times, the fault from bit 3000 for
    /// 4000 bit times, the hubs with the contract's default thresholds.
    pub fn standard(fault: StarFault) -> Self {
        StarScenario {
            fault,
            nodes: 4,
            frames_per_node: 24,
            period_bits: 500,
            fault_start_bits: 3_000,
            // Losing every interlink blocks all traffic (ACK interdependence) until the
            // hubs decouple, `decouple_bits` after the sublinks were judged silent; the
            // fault outlasts that so that both stars are seen carrying on alone.
            fault_bits: if fault == StarFault::AllInterlinksLost {
                9_000
            } else {
                4_000
            },
            hub: HubConfig {
                btr: btr(STAR_BRP, STAR_TSEG1, STAR_TSEG2, STAR_SJW, false, 0),
                ..HubConfig::default()
            },
        }
    }

    fn host_config(&self) -> HostConfig {
        HostConfig {
            btr: btr(STAR_BRP, STAR_TSEG1, STAR_TSEG2, STAR_SJW, false, 96),
            redundancy: true,
            policy: Policy::KFailed(2),
            dual_tx: false,
            // Longer than the hubs' restoration time (1408), so that a node whose
            // probation began after the fault ended returns only once the hub has
            // re-coupled its port; returning earlier is a dominant bit on an isolated
            // port, which restarts the restoration (docs/hub.md, "Restoration").
            recovery_bits: 2_000,
            stall_limit: 500,
            dedup_window: 2_000,
            ..HostConfig::default()
        }
    }

    /// The frame host `node` submits as its `k`-th (unique identifier and data).
    pub fn frame(node: usize, k: usize) -> Frame {
        let mut data = [0u8; 8];
        data[0] = node as u8;
        data[1] = k as u8;
        data[2] = 0x5A;
        Frame {
            id: 0x100 + (node as u32) * 0x40 + (k as u32 % 0x40),
            ide: false,
            rtr: false,
            dlc: 3,
            data,
        }
    }

    /// Total run length in bit times: traffic, the fault, the hubs' restoration time
    /// and the DRCC's recovery after it, and a tail.
    pub fn run_bits(&self) -> u64 {
        let traffic = self.period_bits * self.frames_per_node as u64 + 2_000;
        let fault_end = self.fault_start_bits + self.fault_bits;
        traffic.max(fault_end + self.hub.restore_bits as u64 + 1_408 + 2_000)
    }
}

/// Bit times after the end of `all_interlinks_lost` at which the hubs' hosts
/// re-couple them.
pub const RECOUPLE_AFTER_BITS: u64 = 200;

/// A hub engine by kind.
pub fn hub_engine(kind: EngineKind, n: usize, m: usize) -> Result<Box<dyn HubEngine>, String> {
    match kind {
        EngineKind::Model => drcc_cosim::engine::hub_model::HubModelEngine::new(n, m)
            .map(|e| Box::new(e) as Box<dyn HubEngine>),
        EngineKind::Verilator => {
            if (n, m) != (HUB_N, HUB_M) {
                return Err(format!(
                    "the Verilator hub is the emitted hub.v with {HUB_N} node ports and \
                     {HUB_M} interlinks (asked for {n} and {m}): use --engine model or rust-hdl"
                ));
            }
            drcc_cosim::engine::hub_verilator::HubVerilatorEngine::new()
                .map(|e| Box::new(e) as Box<dyn HubEngine>)
                .map_err(|e| format!("{e}; {VERILATOR_HINT}"))
        }
        EngineKind::RustHdl => drcc_cosim::engine::hub_rusthdl::HubRustHdlEngine::new(n, m)
            .map(|e| Box::new(e) as Box<dyn HubEngine>),
    }
}

/// One isolation or restoration seen on a hub's `port_enabled` probe.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PortEvent {
    pub cycle: u64,
    /// 0 = hub 1.
    pub hub: usize,
    pub port: usize,
    /// true = restored, false = isolated.
    pub enabled: bool,
}

/// What one run showed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StarReport {
    pub scenario: String,
    pub cycles: u64,
    pub fault_start: u64,
    pub fault_end: u64,
    /// (receiver, sender, k) of frames a host never got / got twice.
    pub missing: Vec<(usize, usize, usize)>,
    pub duplicates: Vec<(usize, usize, usize)>,
    pub foreign: usize,
    pub delivered: usize,
    pub submitted: usize,
    /// Per node: frames from others delivered, and second copies the DRCC dropped;
    /// their difference is the omissions the node saw (a frame that came through one
    /// hub only).
    pub from_others: Vec<usize>,
    pub dups_dropped: Vec<u32>,
    /// Per node: the clocks at which its host took each frame from its RX FIFO.
    pub received_at: Vec<Vec<u64>>,
    /// Every change of a hub's `port_enabled`.
    pub events: Vec<PortEvent>,
    /// Clocks at which each hub became decoupled.
    pub decoupled_at: [Option<u64>; 2],
    /// Per hub: `STATS` and every `PORT_p` register at the end.
    pub hub_stats: [u32; 2],
    pub hub_ports: [Vec<u32>; 2],
}

impl StarReport {
    /// Every frame reached every other host exactly once.
    pub fn exactly_once(&self) -> bool {
        self.missing.is_empty() && self.duplicates.is_empty() && self.foreign == 0
    }

    /// Omissions detected by node `i` (frames that came through one hub only).
    pub fn omissions(&self, i: usize) -> usize {
        self.from_others[i].saturating_sub(self.dups_dropped[i] as usize)
    }

    /// First isolation of (hub, port) at or after `from`.
    pub fn isolated_at(&self, hub: usize, port: usize, from: u64) -> Option<u64> {
        self.events
            .iter()
            .find(|e| e.hub == hub && e.port == port && !e.enabled && e.cycle >= from)
            .map(|e| e.cycle)
    }

    /// Last restoration of (hub, port) at or after `from`.
    pub fn restored_at(&self, hub: usize, port: usize, from: u64) -> Option<u64> {
        self.events
            .iter()
            .rev()
            .find(|e| e.hub == hub && e.port == port && e.enabled && e.cycle >= from)
            .map(|e| e.cycle)
    }

    /// Isolations of ports other than `targets`.
    pub fn false_isolations(&self, targets: &[(usize, usize)]) -> Vec<PortEvent> {
        self.events
            .iter()
            .filter(|e| !e.enabled && !targets.contains(&(e.hub, e.port)))
            .copied()
            .collect()
    }
}

/// Builds the system of `s` on engine `kind` (nodes and hubs).
pub fn build_star(s: &StarScenario, kind: EngineKind) -> Result<StarSystem, String> {
    let node_kind = match kind {
        // The DRCC has no rust-hdl engine (too slow): rust-hdl hubs run with model nodes.
        EngineKind::RustHdl => EngineKind::Model,
        k => k,
    };
    let engines = (0..s.nodes)
        .map(|_| drcc_engine(node_kind))
        .collect::<Result<Vec<Box<dyn DrccEngine>>, _>>()?;
    let hubs = [
        hub_engine(kind, HUB_N, HUB_M)?,
        hub_engine(kind, HUB_N, HUB_M)?,
    ];
    let mut sys = StarSystem::new(engines, vec![s.host_config(); s.nodes], hubs, [s.hub; 2])?;
    let start = s.fault_start_bits * CLOCKS_PER_BIT;
    for (link, kind) in s.fault.links() {
        sys.add_fault(LinkFault {
            link,
            kind,
            start,
            cycles: s.fault_bits * CLOCKS_PER_BIT,
        })?;
    }
    for n in 0..s.nodes {
        for k in 0..s.frames_per_node {
            let due = (100 + k as u64 * s.period_bits + n as u64 * 37) * CLOCKS_PER_BIT;
            sys.node_mut(n)
                .host
                .submit(due, StarScenario::frame(n, k), 0);
        }
    }
    Ok(sys)
}

/// Runs `s` on `kind`, or on two engines in lock step (`cosim`): then the first
/// divergence is an error.
pub fn run_star(
    s: &StarScenario,
    kind: EngineKind,
    cosim: Option<EngineKind>,
) -> Result<StarReport, String> {
    let mut main = build_star(s, kind)?;
    let mut other = match cosim {
        Some(k) => Some(build_star(s, k)?),
        None => None,
    };
    let total = s.run_bits() * CLOCKS_PER_BIT;
    let mut report = StarReport {
        scenario: s.fault.name().to_string(),
        fault_start: s.fault_start_bits * CLOCKS_PER_BIT,
        fault_end: (s.fault_start_bits + s.fault_bits) * CLOCKS_PER_BIT,
        ..StarReport::default()
    };
    let ask = |sys: &mut StarSystem| {
        for n in 0..sys.len() {
            sys.node_mut(n).host.read(reg::STATS0);
        }
        for h in 0..2 {
            let hub = sys.hub_mut(h);
            hub.host.read(hub_reg::STATS);
            for p in 0..HUB_N + HUB_M {
                hub.host.read(hub_reg::PORT0 + p as u8);
            }
        }
    };
    // After definitive decoupling only the hubs' host can re-couple them (the paper's
    // section 5 protocol is not built): both supervisors write `CTRL.recouple` once
    // the interlinks are back.
    let recouple_at = (s.fault == StarFault::AllInterlinksLost)
        .then_some(report.fault_end + RECOUPLE_AFTER_BITS * CLOCKS_PER_BIT);
    let recouple = |sys: &mut StarSystem| {
        for h in 0..2 {
            sys.hub_mut(h).host.write(
                hub_reg::CTRL,
                hub_reg::CTRL_ACK_INTERDEP | hub_reg::CTRL_RECOUPLE,
            );
        }
    };
    let mut prev_enabled = [0u16; 2];
    let mut prev_decoupled = [false; 2];
    let mut cycle = 0u64;
    loop {
        if Some(cycle) == recouple_at {
            recouple(&mut main);
            if let Some(o) = other.as_mut() {
                recouple(o);
            }
        }
        if cycle == total {
            ask(&mut main);
            if let Some(o) = other.as_mut() {
                ask(o);
            }
        }
        main.step();
        if let Some(o) = other.as_mut() {
            o.step();
            if let Some(d) = compare(&main, o) {
                return Err(format!(
                    "scenario {}: {d} (bit time {})",
                    s.fault.name(),
                    d.cycle / CLOCKS_PER_BIT
                ));
            }
        }
        for h in 0..2 {
            let p = main.hub(h).outputs.probes;
            let mask = ((1u32 << (HUB_N + HUB_M)) - 1) as u16;
            let en = p.port_enabled & mask;
            if main.hub(h).host.configured() && cycle > 0 {
                let changed = en ^ prev_enabled[h];
                for port in 0..HUB_N + HUB_M {
                    if changed >> port & 1 != 0 {
                        report.events.push(PortEvent {
                            cycle,
                            hub: h,
                            port,
                            enabled: en >> port & 1 != 0,
                        });
                    }
                }
                if p.decoupled && !prev_decoupled[h] && report.decoupled_at[h].is_none() {
                    report.decoupled_at[h] = Some(cycle);
                }
            }
            prev_enabled[h] = en;
            prev_decoupled[h] = p.decoupled;
        }
        cycle += 1;
        let done = cycle > total
            && main.nodes().iter().all(|n| !n.host.reads.is_empty())
            && (0..2).all(|h| main.hub(h).host.reads.len() > HUB_N + HUB_M);
        if done {
            break;
        }
        if cycle > total + 100_000 {
            return Err(format!(
                "{}: the hosts did not finish their register reads",
                s.fault.name()
            ));
        }
    }
    report.cycles = cycle;
    tally(s, &main, &mut report);
    Ok(report)
}

fn tally(s: &StarScenario, sys: &StarSystem, r: &mut StarReport) {
    r.submitted = s.nodes * s.frames_per_node;
    for (rx_node, n) in sys.nodes().iter().enumerate() {
        let mut seen = vec![vec![0usize; s.frames_per_node]; s.nodes];
        let mut from_others = 0;
        for got in &n.host.received {
            let f = got.frame;
            let (sender, k) = (f.data[0] as usize, f.data[1] as usize);
            if sender < s.nodes && k < s.frames_per_node && f == StarScenario::frame(sender, k) {
                seen[sender][k] += 1;
                if sender != rx_node {
                    from_others += 1;
                }
            } else {
                r.foreign += 1;
            }
        }
        r.delivered += from_others;
        r.received_at
            .push(n.host.received.iter().map(|got| got.cycle).collect());
        r.from_others.push(from_others);
        for (sender, counts) in seen.iter().enumerate() {
            if sender == rx_node {
                continue;
            }
            for (k, &c) in counts.iter().enumerate() {
                if c == 0 {
                    r.missing.push((rx_node, sender, k));
                } else if c > 1 {
                    r.duplicates.push((rx_node, sender, k));
                }
            }
        }
        r.dups_dropped
            .push(n.host.reads.first().map(|x| x.value & 0xFFFF).unwrap_or(0));
    }
    for h in 0..2 {
        let reads = &sys.hub(h).host.reads;
        r.hub_stats[h] = reads.first().map(|x| x.value).unwrap_or(0);
        r.hub_ports[h] = reads.iter().skip(1).map(|x| x.value).collect();
    }
}

/// Bit times between two clocks, or "-".
fn bits(from: u64, to: Option<u64>) -> String {
    match to {
        Some(c) if c >= from => format!("{}", (c - from) / CLOCKS_PER_BIT),
        Some(c) => format!("-{}", (from - c) / CLOCKS_PER_BIT),
        None => "never".to_string(),
    }
}

/// The star fault scenarios as a Markdown table (`drcc star table`).
pub fn star_table(kind: EngineKind, cosim: Option<EngineKind>) -> Result<String, String> {
    let mut t = String::from(
        "| fault | onset -> isolation (bit times) | frames lost (of 288) | duplicated | omissions seen per node | fault end -> restoration (bit times) | other isolations |\n\
         |---|---|---:|---:|---|---|---|\n",
    );
    for f in StarFault::ALL {
        let s = StarScenario::standard(f);
        let r = run_star(&s, kind, cosim)?;
        t.push_str(&table_row(&s, &r));
    }
    Ok(t)
}

/// One row of [`star_table`].
pub fn table_row(s: &StarScenario, r: &StarReport) -> String {
    let targets = s.fault.target_ports();
    let port_name = |hub: usize, port: usize| {
        if port < HUB_N {
            format!("hub {} port {port}", hub + 1)
        } else {
            format!("hub {} sublink {}", hub + 1, port - HUB_N)
        }
    };
    let iso: Vec<String> = targets
        .iter()
        .map(|&(h, p)| {
            format!(
                "{}: {}",
                port_name(h, p),
                bits(r.fault_start, r.isolated_at(h, p, r.fault_start))
            )
        })
        .collect();
    let mut iso = if iso.is_empty() {
        "-".to_string()
    } else {
        iso.join("; ")
    };
    for (h, at) in r.decoupled_at.iter().enumerate() {
        if let Some(c) = at {
            iso.push_str(&format!(
                "; hub {} decoupled: {}",
                h + 1,
                bits(r.fault_start, Some(*c))
            ));
        }
    }
    let restore: Vec<String> = targets
        .iter()
        .filter(|&&(h, p)| r.isolated_at(h, p, r.fault_start).is_some())
        .map(|&(h, p)| {
            let back = r.restored_at(h, p, r.fault_end);
            format!("{}: {}", port_name(h, p), bits(r.fault_end, back))
        })
        .collect();
    let others: Vec<String> = r
        .false_isolations(&targets)
        .iter()
        .map(|e| {
            format!(
                "{} at {}",
                port_name(e.hub, e.port),
                bits(r.fault_start, Some(e.cycle))
            )
        })
        .collect();
    let omissions: Vec<String> = (0..s.nodes).map(|i| r.omissions(i).to_string()).collect();
    format!(
        "| {} ({}) | {} | {} | {} | {} | {} | {} |\n",
        s.fault.name(),
        s.fault.describe(),
        iso,
        r.missing.len(),
        r.duplicates.len(),
        omissions.join(" / "),
        if restore.is_empty() {
            "-".to_string()
        } else {
            restore.join("; ")
        },
        if others.is_empty() {
            "none".to_string()
        } else {
            others.join("; ")
        }
    )
}
