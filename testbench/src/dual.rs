//! Dual-bus fault scenarios of DRCC nodes (issue "The DRCC itself"): N >= 4 DRCC
//! nodes in redundancy mode on lines A and B, every host submitting frames, one
//! fault on line A for a while. A run reports, from the hosts' point of view,
//! whether every frame submitted by every host reached every other host exactly
//! once, what the registers said during the fault, and whether channel A was used
//! again after the fault (the main FSM's `wait4 -> idle1` path).
//!
//! The faults and how they are injected (contract of `drcc_cosim::bus`):
//! - `cut_a`: line A broken between two halves of the nodes ([`LineCut`]); each half
//!   still acknowledges its own frames, so only `dual_tx` keeps the halves informed;
//! - `a_stuck_dominant` / `a_stuck_recessive`: the whole line A;
//! - `dead_transceiver`: node 0's channel A transmitter and receiver stuck recessive
//!   (it neither drives nor hears line A);
//! - `a_bus_off`: node 0's channel A transmitter stuck dominant (a babbling
//!   transceiver) until fault confinement takes node 0's channel A to bus-off.

mod watch;
use watch::{tally, ChannelAWatch};

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::dual::lockstep::{compare, DrccDivergence};
use drcc_cosim::dual::vcd::DrccVcdWriter;
use drcc_cosim::dual::{DualBusSystem, Line, LineCut};
use drcc_cosim::engine::drcc::DrccEngine;
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::engine::drcc_verilator::DrccVerilatorEngine;
use drcc_cosim::host::{btr, reg, HostConfig, Policy};
use drcc_cosim::Frame;

use crate::delivery::Deliveries;
use crate::drcc_build::DrccBuild;
use crate::engines::{EngineKind, VERILATOR_HINT};

/// `field` probe code of the data field (timing contract §4.1).
const FIELD_DATA: u8 = 10;

/// Clocks per bit of the scenarios: 8 MHz, 1 Mbit/s, 8 tq of one clock.
pub const CLOCKS_PER_BIT: u64 = 8;

/// The clock of the scenarios in Hz (time = cycle / clock).
pub const CLOCK_HZ: u64 = 8_000_000;

/// Called with the main system after every clock (traffic taps); an error stops
/// the run.
pub type DualObserver<'a> = &'a mut dyn FnMut(&DualBusSystem) -> Result<(), String>;

/// The fault of a dual-bus scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DualFault {
    None,
    CutA,
    AStuckDominant,
    AStuckRecessive,
    DeadTransceiver,
    ABusOff,
}

impl DualFault {
    /// Every fault, in report order.
    pub const ALL: [DualFault; 6] = [
        DualFault::None,
        DualFault::CutA,
        DualFault::AStuckDominant,
        DualFault::AStuckRecessive,
        DualFault::DeadTransceiver,
        DualFault::ABusOff,
    ];

    /// Name as reports and the CLI spell it.
    pub fn name(self) -> &'static str {
        match self {
            DualFault::None => "no_fault",
            DualFault::CutA => "cut_a",
            DualFault::AStuckDominant => "a_stuck_dominant",
            DualFault::AStuckRecessive => "a_stuck_recessive",
            DualFault::DeadTransceiver => "dead_transceiver",
            DualFault::ABusOff => "a_bus_off",
        }
    }
}

/// A dual-bus scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DualScenario {
    pub fault: DualFault,
    pub nodes: usize,
    /// Frames each host submits.
    pub frames_per_node: usize,
    /// Bit times between two submissions of one host.
    pub period_bits: u64,
    /// Fault window, in bit times from the start.
    pub fault_start_bits: u64,
    pub fault_bits: u64,
    /// Redundancy configuration of every node.
    pub policy: Policy,
    pub dual_tx: bool,
    pub recovery_bits: u16,
    /// "No bus activity" judgement: a frame pending this many bit times (0 = off).
    pub stall_bits: u16,
    /// The generated DRCC every node is (contract §1.1).
    pub build: DrccBuild,
    /// Manual bus-off recovery (DRCC contract §11.6): every node runs with
    /// `CTRL.busoff_manual`, and node 0's host writes `TX_CMD.recover_a` this
    /// many bit times after the fault ended. `None`: automatic recovery.
    pub manual_recovery_bits: Option<u64>,
}

impl DualScenario {
    /// The product's recommended configuration against `fault`: redundancy mode,
    /// switch after 2 failed attempts, every message on both lines.
    pub fn standard(fault: DualFault) -> Self {
        DualScenario {
            fault,
            nodes: 4,
            frames_per_node: 24,
            period_bits: 700,
            fault_start_bits: 3_000,
            fault_bits: if fault == DualFault::ABusOff {
                400
            } else {
                6_000
            },
            policy: Policy::KFailed(2),
            dual_tx: true,
            recovery_bits: 1_000,
            // A stuck-dominant line never lets a waiting frame start: no attempt
            // fails, so only the stall judgement sees it. 500 bit times is about 8
            // frames of waiting for arbitration.
            stall_bits: 500,
            build: DrccBuild::Default,
            manual_recovery_bits: None,
        }
    }

    /// The hosts' configuration: the product's recommended redundancy settings
    /// (also every campaign scenario's, `crate::campaign::dual`).
    pub(crate) fn host_config(&self) -> HostConfig {
        HostConfig {
            btr: btr(0, 5, 2, 1, false, 96),
            redundancy: true,
            policy: self.policy,
            dual_tx: self.dual_tx,
            recovery_bits: self.recovery_bits,
            stall_limit: self.stall_bits,
            dedup_window: 2_000,
            tx_queue_depth: self.build.params().tx_queue_depth as u32,
            busoff_manual: self.manual_recovery_bits.is_some(),
            ..HostConfig::default()
        }
    }

    /// The frame host `node` submits as its `k`-th: a unique base identifier (lower
    /// identifiers for lower nodes) and data naming node and sequence number.
    pub fn frame(node: usize, k: usize) -> Frame {
        let mut data = [0u8; 8];
        data[0] = node as u8;
        data[1] = k as u8;
        data[2] = 0xA5;
        Frame {
            id: 0x100 + (node as u32) * 0x40 + (k as u32 % 0x40),
            ide: false,
            rtr: false,
            dlc: 3,
            data,
        }
    }

    /// Total run length in bit times (traffic, fault, recovery, and a tail).
    pub fn run_bits(&self) -> u64 {
        let traffic = self.period_bits * self.frames_per_node as u64;
        let fault_end = self.fault_start_bits + self.fault_bits;
        // Bus-off recovery (128 x 11 bits) + the aux probation before channel A is
        // used again, then a few frames on A.
        let held = self.manual_recovery_bits.unwrap_or(0);
        traffic.max(fault_end + held + 1_408 + self.recovery_bits as u64 + 6 * self.period_bits)
    }

    fn faults(&self, sys: &mut DualBusSystem, start: u64) -> Result<(), String> {
        let cycles = self.fault_bits * CLOCKS_PER_BIT;
        let f = |target, kind| Fault {
            target,
            kind,
            start,
            cycles,
        };
        match self.fault {
            DualFault::None => {}
            DualFault::CutA => sys.add_cut(
                Line::A,
                LineCut {
                    at: self.nodes / 2,
                    start,
                    cycles,
                },
            )?,
            DualFault::AStuckDominant => {
                sys.add_fault(Line::A, f(FaultTarget::Bus, FaultKind::StuckDominant))?
            }
            DualFault::AStuckRecessive => {
                sys.add_fault(Line::A, f(FaultTarget::Bus, FaultKind::StuckRecessive))?
            }
            DualFault::DeadTransceiver => {
                sys.add_fault(Line::A, f(FaultTarget::Tx(0), FaultKind::StuckRecessive))?;
                sys.add_fault(Line::A, f(FaultTarget::Rx(0), FaultKind::StuckRecessive))?;
            }
            DualFault::ABusOff => {
                sys.add_fault(Line::A, f(FaultTarget::Tx(0), FaultKind::StuckDominant))?
            }
        }
        Ok(())
    }
}

/// A DRCC engine by kind; Verilator missing is an error that says how to install it.
pub fn drcc_engine(kind: EngineKind) -> Result<Box<dyn DrccEngine>, String> {
    match kind {
        EngineKind::Model => Ok(Box::new(DrccModelEngine::new())),
        EngineKind::Verilator => DrccVerilatorEngine::new()
            .map(|e| Box::new(e) as Box<dyn DrccEngine>)
            .map_err(|e| format!("{e}; {VERILATOR_HINT}")),
        EngineKind::RustHdl => Err(
            "the DRCC top runs on the model and verilator engines (rust-hdl's simulator is \
             too slow for multi-node DRCC runs): use --engine model or --engine verilator"
                .to_string(),
        ),
    }
}

/// What one run showed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DualReport {
    pub scenario: String,
    pub cycles: u64,
    /// (receiver, sender, k) of frames a host never got.
    pub missing: Vec<(usize, usize, usize)>,
    /// (receiver, sender, k) of frames a host got more than once.
    pub duplicates: Vec<(usize, usize, usize)>,
    /// Frames a host got that nobody sent (corruption).
    pub foreign: usize,
    /// Frames delivered in total, and frames submitted.
    pub delivered: usize,
    pub submitted: usize,
    /// Per node: `AUX_A` and `STATUS` read by the host at the end of the fault window.
    pub aux_a_during: Vec<u32>,
    pub status_during: Vec<u32>,
    /// Per node: `STATUS`, `AUX_A` and `STATS0` at the end.
    pub status_end: Vec<u32>,
    pub aux_a_end: Vec<u32>,
    pub stats0_end: Vec<u32>,
    /// Per node: the clock at which the main FSM went wait4 -> idle1 after aux A
    /// had judged channel A failed and then reported it valid again (the return
    /// to channel A), if that happened (cleared again by a later failure).
    pub back_on_a: Vec<Option<u64>>,
    /// Per node: whether aux A ever left `valid`.
    pub a_failed: Vec<bool>,
    /// Per node: frames it sent as transmitter on line A after its return to A and
    /// after the fault ended (it drove a dominant bit in a data field).
    pub a_frames_after: Vec<u64>,
    /// First clock at which some node's aux A left `valid`, if any.
    pub first_aux_failure: Option<u64>,
    /// Clocks at which the fault started and ended.
    pub fault_start: u64,
    pub fault_end: u64,
    /// Frames the hosts pushed into their DRCC.
    pub pushed: usize,
    /// Clock at which node 0's host wrote `TX_CMD.recover_a` (manual recovery),
    /// and the first clock after the fault at which node 0's channel A was no
    /// longer bus-off.
    pub recover_written: Option<u64>,
    pub a_bus_off_end: Option<u64>,
}

impl DualReport {
    /// Every frame reached every other host exactly once.
    pub fn exactly_once(&self) -> bool {
        self.missing.is_empty() && self.duplicates.is_empty() && self.foreign == 0
    }
}

/// Runs `s` on one engine kind, or on two in lock step (`cosim = Some(other)`):
/// then the first divergence is an error.
pub fn run_dual(
    s: &DualScenario,
    kind: EngineKind,
    cosim: Option<EngineKind>,
) -> Result<DualReport, String> {
    run_dual_traced(s, kind, cosim, None)
}

/// [`run_dual`], also writing the VCD of the main engine's system (the paper's
/// signal names of every node, `dual::vcd`) into `vcd`.
pub fn run_dual_traced(
    s: &DualScenario,
    kind: EngineKind,
    cosim: Option<EngineKind>,
    vcd: Option<&mut Vec<u8>>,
) -> Result<DualReport, String> {
    run_dual_observed(s, kind, cosim, vcd, &mut |_| Ok(()))
}

/// The dual bus of `s` on engines of `kind`, its faults from `fault_start` (none
/// without), and every host's frames submitted, staggered so that they contend.
fn build_dual(
    s: &DualScenario,
    kind: EngineKind,
    fault_start: Option<u64>,
) -> Result<DualBusSystem, String> {
    let engines = (0..s.nodes)
        .map(|_| s.build.engine(kind))
        .collect::<Result<Vec<_>, _>>()?;
    let mut sys = DualBusSystem::new(engines, vec![s.host_config(); s.nodes])?;
    if let Some(start) = fault_start {
        s.faults(&mut sys, start)?;
    }
    for n in 0..s.nodes {
        for k in 0..s.frames_per_node {
            // Stagger the hosts so that frames also contend for the bus.
            let due = (100 + k as u64 * s.period_bits + n as u64 * 37) * CLOCKS_PER_BIT;
            sys.node_mut(n)
                .host
                .submit(due, DualScenario::frame(n, k), 0);
        }
    }
    Ok(sys)
}

/// The clock the fault starts at: `fault_start_bits`, except for `a_bus_off`.
fn fault_start(s: &DualScenario) -> Result<u64, String> {
    // The babbling transmitter must hit node 0 while it transmits (else another
    // node's frame takes the hit; in arbitration it would only make node 0 lose):
    // the fault starts in the data field of node 0's first frame on A at or after
    // `fault_start_bits`, found by running the fault-free prefix (the run is
    // deterministic up to the fault).
    let mut start = s.fault_start_bits * CLOCKS_PER_BIT;
    if s.fault == DualFault::ABusOff {
        let mut probe = build_dual(s, EngineKind::Model, None)?;
        loop {
            probe.step();
            let n0 = probe.node(0).outputs;
            // Node 0 drives a dominant bit in a data field: it is the transmitter
            // (receivers stay recessive there), past arbitration.
            if probe.cycle() > start && n0.probes.chan_a_field == FIELD_DATA && !n0.chan_a_tx {
                start = probe.cycle();
                break;
            }
            if probe.cycle() > start + 100_000 {
                return Err("a_bus_off: node 0 never transmitted on line A".into());
            }
        }
    }
    Ok(start)
}

/// [`run_dual_traced`], also calling `observe` with the main system after every
/// clock.
pub fn run_dual_observed(
    s: &DualScenario,
    kind: EngineKind,
    cosim: Option<EngineKind>,
    vcd: Option<&mut Vec<u8>>,
    observe: DualObserver,
) -> Result<DualReport, String> {
    let start = fault_start(s)?;
    let mut main = build_dual(s, kind, Some(start))?;
    let mut other = match cosim {
        Some(k) => Some(build_dual(s, k, Some(start))?),
        None => None,
    };
    let mut writer = match vcd {
        Some(buf) => Some(
            DrccVcdWriter::new(
                buf,
                CLOCK_HZ,
                s.nodes,
                &format!("DRCC dual-bus fault scenario {}", s.fault.name()),
            )
            .map_err(|e| e.to_string())?,
        ),
        None => None,
    };
    let total = s.run_bits() * CLOCKS_PER_BIT;
    let fault_end = start + s.fault_bits * CLOCKS_PER_BIT;
    // With manual recovery the reads "during" come just before the host's
    // recover: the channel must still be bus-off there.
    let recover_at = s
        .manual_recovery_bits
        .map(|d| fault_end + d * CLOCKS_PER_BIT);
    let read_during = recover_at
        .unwrap_or(fault_end)
        .saturating_sub(50 * CLOCKS_PER_BIT);
    let mut report = DualReport {
        scenario: s.fault.name().to_string(),
        back_on_a: vec![None; s.nodes],
        a_failed: vec![false; s.nodes],
        a_frames_after: vec![0; s.nodes],
        ..DualReport::default()
    };
    let mut watch = ChannelAWatch::new(s.nodes);
    let mut cycle = 0;
    let read_regs = |sys: &mut DualBusSystem, regs: &[u8]| {
        for n in 0..sys.len() {
            for &r in regs {
                sys.node_mut(n).host.read(r);
            }
        }
    };
    while cycle < total || main.nodes().iter().any(|n| n.host.reads.len() < 5) {
        if cycle == read_during {
            read_regs(&mut main, &[reg::AUX_A, reg::STATUS]);
            if let Some(o) = other.as_mut() {
                read_regs(o, &[reg::AUX_A, reg::STATUS]);
            }
        }
        if cycle == total {
            read_regs(&mut main, &[reg::STATUS, reg::AUX_A, reg::STATS0]);
            if let Some(o) = other.as_mut() {
                read_regs(o, &[reg::STATUS, reg::AUX_A, reg::STATS0]);
            }
        }
        if Some(cycle) == recover_at {
            let recover = drcc_hdl::host::registers::MAP
                .field("TX_CMD", "recover_a")
                .put(1);
            main.node_mut(0).host.write(reg::TX_CMD, recover);
            if let Some(o) = other.as_mut() {
                o.node_mut(0).host.write(reg::TX_CMD, recover);
            }
            report.recover_written = Some(cycle);
        }
        main.step();
        if cycle > fault_end
            && report.a_bus_off_end.is_none()
            && main.node(0).outputs.probes.chan_a_err_state != 2
        {
            report.a_bus_off_end = Some(cycle);
        }
        if let Some(w) = writer.as_mut() {
            w.write_cycle(&main).map_err(|e| e.to_string())?;
        }
        observe(&main)?;
        if let Some(o) = other.as_mut() {
            o.step();
            if let Some(d) = compare(&main, o) {
                return Err(divergence_message(s, &d));
            }
        }
        watch.sample(&main, cycle, fault_end, &mut report);
        cycle += 1;
        if cycle > total + 100_000 {
            return Err(format!(
                "{}: the hosts did not finish their register reads",
                s.fault.name()
            ));
        }
    }
    if let Some(w) = writer.as_mut() {
        w.finish(main.cycle()).map_err(|e| e.to_string())?;
    }
    report.cycles = cycle;
    report.fault_start = start;
    report.fault_end = fault_end;
    report.pushed = main.nodes().iter().map(|n| n.host.sent.len()).sum();
    tally(s, &main, &mut report);
    Ok(report)
}

fn divergence_message(s: &DualScenario, d: &DrccDivergence) -> String {
    format!(
        "scenario {}: {d} (bit time {})",
        s.fault.name(),
        d.cycle / CLOCKS_PER_BIT
    )
}

/// The fault scenarios as a Markdown table (`drcc redundancy table`): per fault,
/// deliveries, bit times from fault onset to the first node judging channel A
/// failed, and from the end of the fault to the last node back on channel A.
pub fn fault_table(kind: EngineKind, cosim: Option<EngineKind>) -> Result<String, String> {
    let mut t = String::from(
        "| fault (line A) | deliveries (exactly once) | lost | duplicated | duplicates dropped per node | onset -> channel A judged failed | fault end -> last node back on A (wait4 -> idle1) |\n\
         |---|---:|---:|---:|---:|---:|---:|\n",
    );
    for f in DualFault::ALL {
        let s = DualScenario::standard(f);
        let r = run_dual(&s, kind, cosim)?;
        let expected = s.nodes * (s.nodes - 1) * s.frames_per_node;
        let to_fail = match r.first_aux_failure {
            Some(c) if f != DualFault::None => {
                format!(
                    "{} bit times",
                    c.saturating_sub(r.fault_start) / CLOCKS_PER_BIT
                )
            }
            _ => "-".to_string(),
        };
        let back = if f == DualFault::None {
            "-".to_string()
        } else {
            let returns: Vec<u64> = (0..s.nodes)
                .filter(|&n| r.a_failed[n])
                .filter_map(|n| r.back_on_a[n])
                .collect();
            let failed = r.a_failed.iter().filter(|&&x| x).count();
            if failed == 0 {
                "no node left A".to_string()
            } else if returns.len() < failed {
                format!(
                    "{} of {failed} nodes did not return",
                    failed - returns.len()
                )
            } else {
                let last = returns.iter().max().copied().unwrap_or(r.fault_end);
                if last >= r.fault_end {
                    format!(
                        "{} bit times ({failed} nodes)",
                        (last - r.fault_end) / CLOCKS_PER_BIT
                    )
                } else {
                    // A receiver cannot tell a dead transceiver from a quiet bus:
                    // the aux probation ended while the fault was still there.
                    format!(
                        "{} bit times before the fault ended ({failed} nodes)",
                        (r.fault_end - last) / CLOCKS_PER_BIT
                    )
                }
            }
        };
        let dups: Vec<String> = r
            .stats0_end
            .iter()
            .map(|v| (v & 0xFFFF).to_string())
            .collect();
        t.push_str(&format!(
            "| {} | {}/{} {} | {} | {} | {} | {} | {} |\n",
            f.name(),
            r.delivered,
            expected,
            if r.exactly_once() { "yes" } else { "NO" },
            r.missing.len(),
            r.duplicates.len(),
            dups.join(" / "),
            to_fail,
            back
        ));
    }
    Ok(t)
}
