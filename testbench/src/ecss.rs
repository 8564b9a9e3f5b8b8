//! ECSS bus-selection scenarios (DRCC contract §12; ECSS-E-ST-50-15C's
//! redundancy management): a redundancy master and three nodes that follow its
//! heartbeat, on lines A and B, every host submitting frames, one fault.
//!
//! - Node 0 is the master: redundancy mode with the product's k-failed policy
//!   and stall limit (`DualScenario::standard`), so its own failover decides
//!   the bus; its host sends the heartbeat (CANopen: 0x701, one byte, the NMT
//!   state) every `hb_bits` bit times through its TX queue, as firmware would.
//! - Nodes 1..3 run the ECSS policy with `Ttoggle`, `Ntoggle`, `Bdefault` = A
//!   and the consumer time `consumer_bits` (the master's period plus a margin).
//!
//! The faults: line A stuck dominant or stuck recessive for a window (the
//! master fails over, the nodes follow, and all come back after the window),
//! and a master whose software stops (no heartbeat, no frame) for good, with
//! `Ntoggle` 3 and 0.

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::dual::lockstep::compare;
use drcc_cosim::dual::{DualBusSystem, Line};
use drcc_cosim::host::ecss_config::EcssConfig;
use drcc_cosim::host::{reg, HostConfig, Policy};
use drcc_cosim::Frame;
use drcc_hdl::host::registers::MAP;

use crate::delivery::Deliveries;
use crate::dual::{DualFault, DualScenario, CLOCKS_PER_BIT};
use crate::engines::EngineKind;

/// The master's heartbeat identifier (CANopen: 0x700 + node-ID 1).
pub const HB_ID: u16 = 0x701;

/// The fault of an ECSS scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EcssFault {
    None,
    AStuckDominant,
    AStuckRecessive,
    /// The master's software stops: no heartbeat and no frame from then on.
    MasterSilent,
}

impl EcssFault {
    pub fn name(self) -> &'static str {
        match self {
            EcssFault::None => "no_fault",
            EcssFault::AStuckDominant => "a_stuck_dominant",
            EcssFault::AStuckRecessive => "a_stuck_recessive",
            EcssFault::MasterSilent => "master_silent",
        }
    }
}

/// An ECSS scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EcssScenario {
    pub fault: EcssFault,
    pub nodes: usize,
    /// Data frames each host submits, one per `period_bits`.
    pub frames_per_node: usize,
    pub period_bits: u64,
    /// The master's heartbeat period and the nodes' consumer time (bit times).
    pub hb_bits: u64,
    pub consumer_bits: u32,
    pub ttoggle: u8,
    pub ntoggle: u8,
    /// Fault window in bit times (`MasterSilent`: from the start, for good).
    pub fault_start_bits: u64,
    pub fault_bits: u64,
}

impl EcssScenario {
    /// The rows of `drcc redundancy ecss`: 1 Mbit/s, a heartbeat every 1,000
    /// bit times (1 ms), a consumer time of 1,200, `Ttoggle` 3, `Ntoggle` 3.
    pub fn standard(fault: EcssFault) -> Self {
        EcssScenario {
            fault,
            nodes: 4,
            frames_per_node: 24,
            period_bits: 700,
            hb_bits: 1_000,
            consumer_bits: 1_200,
            ttoggle: 3,
            ntoggle: 3,
            fault_start_bits: 3_000,
            fault_bits: 6_000,
        }
    }

    /// The rows, in report order: one per fault, and the silent master with
    /// toggling off (`Ntoggle` 0).
    pub fn rows() -> Vec<EcssScenario> {
        let mut rows: Vec<_> = [
            EcssFault::None,
            EcssFault::AStuckDominant,
            EcssFault::AStuckRecessive,
            EcssFault::MasterSilent,
        ]
        .map(Self::standard)
        .to_vec();
        rows.push(EcssScenario {
            ntoggle: 0,
            ..Self::standard(EcssFault::MasterSilent)
        });
        rows
    }

    /// `name` as the report spells it (with `Ntoggle` where it is not 3).
    pub fn label(&self) -> String {
        if self.ntoggle == 3 {
            self.fault.name().to_string()
        } else {
            format!("{} (Ntoggle {})", self.fault.name(), self.ntoggle)
        }
    }

    /// The master's configuration: the product's (`DualScenario::standard`),
    /// one copy per message (the heartbeat marks one bus).
    pub fn master_config(&self) -> HostConfig {
        HostConfig {
            dual_tx: false,
            ..DualScenario::standard(DualFault::None).host_config()
        }
    }

    /// A node's: the master's with the ECSS policy on and no channel policy.
    pub fn node_config(&self) -> HostConfig {
        HostConfig {
            ecss: Some(EcssConfig {
                ttoggle: self.ttoggle,
                ntoggle: self.ntoggle,
                bdefault_b: false,
                hb_id: HB_ID,
                period_bits: self.consumer_bits,
            }),
            // no channel judgement: the selection alone decides, and a restart
            // (a controller reset) would cost a frame on a bus that carries
            // one copy (docs/drcc.md "ECSS bus selection")
            policy: Policy::None,
            stall_limit: 0,
            ..self.master_config()
        }
    }

    /// When the master's software stops (`MasterSilent`), in bit times.
    fn master_stops(&self) -> Option<u64> {
        (self.fault == EcssFault::MasterSilent).then_some(self.fault_start_bits)
    }

    /// Whether host `n` submits its `k`-th frame (due at `due` bit times).
    fn submits(&self, n: usize, due: u64) -> bool {
        n != 0 || self.master_stops().is_none_or(|stop| due < stop)
    }

    fn due(&self, n: usize, k: usize) -> u64 {
        100 + k as u64 * self.period_bits + n as u64 * 37
    }

    /// The longest time a node may take to follow: `Ttoggle` consumer times.
    pub fn toggle_bound_bits(&self) -> u64 {
        self.ttoggle as u64 * self.consumer_bits as u64
    }

    /// Run length in bit times: the traffic, and after the fault the master's
    /// return (recovery) and the nodes' following it, or the silent master's
    /// `Ntoggle` toggles and the one search more that gives up.
    pub fn run_bits(&self) -> u64 {
        let traffic = self.period_bits * self.frames_per_node as u64 + 1_000;
        let follow = (self.ntoggle as u64 + 2) * self.toggle_bound_bits();
        let after = match self.fault {
            EcssFault::None => 0,
            EcssFault::MasterSilent => self.fault_start_bits + follow,
            _ => self.fault_start_bits + self.fault_bits + 2_500 + 2 * self.toggle_bound_bits(),
        };
        traffic.max(after)
    }

    /// The master's `seq`-th heartbeat.
    pub fn heartbeat(seq: u64) -> Frame {
        let mut data = [0u8; 8];
        // CANopen heartbeat: the NMT state (operational); byte 1 only tells the
        // frames apart in a trace
        data[0] = 0x05;
        data[1] = seq as u8;
        Frame {
            id: HB_ID as u32,
            ide: false,
            rtr: false,
            dlc: 1,
            data,
        }
    }

    fn build(&self, kind: EngineKind) -> Result<DualBusSystem, String> {
        let build = crate::drcc_build::DrccBuild::Default;
        let engines = (0..self.nodes)
            .map(|_| build.engine(kind))
            .collect::<Result<Vec<_>, _>>()?;
        let mut configs = vec![self.node_config(); self.nodes];
        configs[0] = self.master_config();
        let mut sys = DualBusSystem::new(engines, configs)?;
        let start = self.fault_start_bits * CLOCKS_PER_BIT;
        let cycles = self.fault_bits * CLOCKS_PER_BIT;
        let bus = |kind| Fault {
            target: FaultTarget::Bus,
            kind,
            start,
            cycles,
        };
        match self.fault {
            EcssFault::AStuckDominant => sys.add_fault(Line::A, bus(FaultKind::StuckDominant))?,
            EcssFault::AStuckRecessive => sys.add_fault(Line::A, bus(FaultKind::StuckRecessive))?,
            EcssFault::None | EcssFault::MasterSilent => {}
        }
        for n in 0..self.nodes {
            for k in 0..self.frames_per_node {
                let due = self.due(n, k);
                if self.submits(n, due) {
                    let f = DualScenario::frame(n, k);
                    sys.node_mut(n).host.submit(due * CLOCKS_PER_BIT, f, 0);
                }
            }
        }
        let end = self.run_bits();
        let mut seq = 0;
        while 50 + seq * self.hb_bits < self.master_stops().unwrap_or(end).min(end) {
            let due = (50 + seq * self.hb_bits) * CLOCKS_PER_BIT;
            sys.node_mut(0).host.submit(due, Self::heartbeat(seq), 0);
            seq += 1;
        }
        Ok(sys)
    }
}

/// What one run showed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EcssReport {
    /// Data frames expected at some host, delivered, lost, duplicated.
    pub expected: usize,
    pub delivered: usize,
    pub missing: Vec<(usize, usize, usize)>,
    pub duplicates: Vec<(usize, usize, usize)>,
    /// Heartbeats the nodes received (all nodes together).
    pub heartbeats: usize,
    /// Per node: the clocks at which its main FSM changed channel
    /// (`tx_channel`), and `ECSS_STATUS` at the end.
    pub moves: Vec<Vec<u64>>,
    pub ecss_status: Vec<u32>,
    /// The clocks of the master's heartbeat deliveries (its `tx_success`
    /// pulses, matched in order with the frames its host pushed).
    pub hb_sent: Vec<u64>,
    pub fault_start: u64,
}

impl EcssReport {
    pub fn exactly_once(&self) -> bool {
        self.missing.is_empty() && self.duplicates.is_empty()
    }

    /// The clock of the master's last heartbeat delivered before the fault.
    pub fn last_hb_sent_before_fault(&self) -> Option<u64> {
        self.hb_sent
            .iter()
            .copied()
            .rfind(|&c| c < self.fault_start)
    }

    /// Bit times from the master's last heartbeat before the fault to node
    /// `n`'s first move to the other bus (its main FSM's `tx_channel`).
    pub fn follow_bits(&self, n: usize) -> Option<u64> {
        let hb = self.last_hb_sent_before_fault()?;
        let m = *self.moves[n].first()?;
        Some(m.saturating_sub(hb) / CLOCKS_PER_BIT)
    }

    /// `ECSS_STATUS.field` of node `n` at the end.
    pub fn status(&self, n: usize, field: &str) -> u32 {
        MAP.field("ECSS_STATUS", field).get(self.ecss_status[n])
    }
}

/// Runs `s` on `kind`, or on two engines in lock step (the first divergence is
/// an error).
pub fn run_ecss(
    s: &EcssScenario,
    kind: EngineKind,
    cosim: Option<EngineKind>,
) -> Result<EcssReport, String> {
    let mut main = s.build(kind)?;
    let mut other = cosim.map(|k| s.build(k)).transpose()?;
    let total = s.run_bits() * CLOCKS_PER_BIT;
    let fault_start = s.fault_start_bits * CLOCKS_PER_BIT;
    let mut r = EcssReport {
        moves: vec![vec![]; s.nodes],
        fault_start,
        ..EcssReport::default()
    };
    let mut channel = vec![false; s.nodes];
    let mut successes = 0;
    let mut cycle = 0;
    while cycle < total || main.nodes().iter().any(|n| n.host.reads.is_empty()) {
        if cycle == total {
            for sys in std::iter::once(&mut main).chain(other.as_mut()) {
                for n in 0..s.nodes {
                    sys.node_mut(n).host.read(reg::ECSS_STATUS);
                }
            }
        }
        main.step();
        if let Some(o) = other.as_mut() {
            o.step();
            if let Some(d) = compare(&main, o) {
                return Err(format!(
                    "ECSS scenario {}: {d} (bit time {})",
                    s.label(),
                    d.cycle / CLOCKS_PER_BIT
                ));
            }
        }
        let master = main.node(0);
        if master.outputs.probes.tx_success {
            // one success per message, in queue order (redundancy mode, one copy)
            if master.host.sent.get(successes).map(|t| t.frame.id) == Some(HB_ID as u32) {
                r.hb_sent.push(cycle);
            }
            successes += 1;
        }
        for (i, n) in main.nodes().iter().enumerate() {
            if n.outputs.probes.tx_channel != channel[i] {
                channel[i] = n.outputs.probes.tx_channel;
                r.moves[i].push(cycle);
            }
        }
        cycle += 1;
        if cycle > total + 100_000 {
            return Err(format!("{}: the hosts did not read ECSS_STATUS", s.label()));
        }
    }
    tally(s, &main, &mut r);
    Ok(r)
}

fn tally(s: &EcssScenario, sys: &DualBusSystem, r: &mut EcssReport) {
    for (rx, n) in sys.nodes().iter().enumerate() {
        let received = n.host.received.iter().map(|got| got.frame);
        let d = Deliveries::count(
            received,
            s.nodes,
            s.frames_per_node,
            |f| f.id == HB_ID as u32,
            DualScenario::frame,
        );
        r.heartbeats += d.skipped;
        r.delivered += d.total();
        let sent = |sender: usize, k: usize| s.submits(sender, s.due(sender, k));
        r.expected += d.judge(rx, sent, &mut r.missing, &mut r.duplicates);
        r.ecss_status
            .push(n.host.reads.first().map_or(0, |x| x.value));
    }
}

/// `drcc redundancy ecss`: the rows as a Markdown table.
pub fn ecss_table(kind: EngineKind, cosim: Option<EngineKind>) -> Result<String, String> {
    let mut t = String::from(
        "| fault | deliveries (exactly once) | lost | duplicated | heartbeats heard | master's last heartbeat -> node on B, bit times (Ttoggle x consumer time) | moves per node | Ctoggle per node | no_master |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for s in EcssScenario::rows() {
        let r = run_ecss(&s, kind, cosim)?;
        let nodes = 1..s.nodes;
        let follow: Vec<String> = nodes
            .clone()
            .map(|n| match r.follow_bits(n) {
                Some(b) if s.fault != EcssFault::None => b.to_string(),
                _ => "-".into(),
            })
            .collect();
        let per = |f: &dyn Fn(usize) -> String| -> String {
            nodes.clone().map(f).collect::<Vec<_>>().join(" / ")
        };
        t.push_str(&format!(
            "| {} | {}/{} {} | {} | {} | {} | {} ({}) | {} | {} | {} |\n",
            s.label(),
            r.delivered,
            r.expected,
            if r.exactly_once() { "yes" } else { "NO" },
            r.missing.len(),
            r.duplicates.len(),
            r.heartbeats,
            follow.join(" / "),
            s.toggle_bound_bits(),
            per(&|n| r.moves[n].len().to_string()),
            per(&|n| r.status(n, "ctoggle").to_string()),
            per(&|n| r.status(n, "no_master").to_string()),
        ));
    }
    Ok(t)
}
