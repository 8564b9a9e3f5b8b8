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
//! The nodes are replicated star nodes (DRCC contract §4.4): they transmit through
//! one hub (the coupled hubs bring every frame to both controllers of every node,
//! paper section 2.1, and the other channel's echo completes the message), switch
//! hubs after two failed attempts (k-failed policy), and send the copy on the other
//! star only when no echo came, i.e. once the hubs are decoupled (`dual_tx`).
//! The hubs run NRAP (hub contract §9); the report gives each hub's phases.

use drcc_cosim::engine::drcc::DrccEngine;
use drcc_cosim::engine::hub::HubEngine;
use drcc_cosim::host::{btr, reg, HostConfig, Policy};
use drcc_cosim::star::hub_host::{hub_reg, HubConfig};
use drcc_cosim::star::lockstep::compare;
use drcc_cosim::star::{Link, LinkFault, LinkFaultKind, StarSystem};
use drcc_cosim::Frame;

use crate::dual::drcc_engine;
use crate::engines::{EngineKind, VERILATOR_HINT};

mod fault;
mod report;
mod run;
pub use fault::*;
pub use report::*;
pub use run::*;

/// Bit timing of the star scenarios: a time quantum of 2 clocks, TSEG1 13 tq, TSEG2
/// 4 tq, SJW 2: 36 clocks per bit, sample point at 28 clocks (78 %). The long
/// propagation segment covers the loop node → hub → twin hub → node → and back
/// (6 + 2 + 1 clocks each way through the hubs, the nodes' synchronizers and
/// output registers; `docs/hub.md` computes it).
pub const STAR_BRP: u16 = 1;
pub const STAR_TSEG1: u8 = 13;
pub const STAR_TSEG2: u8 = 4;
pub const STAR_SJW: u8 = 2;
/// Clocks per bit of the star scenarios.
pub const CLOCKS_PER_BIT: u64 = 36;

/// The clock of the star scenarios in Hz: 36 MHz, so that a bit lasts 1 µs
/// (1 Mbit/s, as on the dual bus); time = cycle / clock.
pub const CLOCK_HZ: u64 = CLOCKS_PER_BIT * 1_000_000;

/// Node ports and interlinks of the scenarios' hubs (the emitted `hub.v`).
pub const HUB_N: usize = 4;
pub const HUB_M: usize = 2;

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
    /// The hubs have their ACK units (hub contract §4.1). Always, in the RTL; a
    /// model-only run without them shows what the units prevent.
    pub ack_units: bool,
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
            // Losing every interlink blocks all traffic (ACK interdependence) until
            // NRAP decides (hub contract §9): 9000 bit times outlast a definitive
            // decoupling, 1500 end during the sublink restoration phase (the hubs
            // recouple), and a permanent cut outlasts the run.
            fault_bits: match fault {
                StarFault::AllInterlinksLost => 9_000,
                StarFault::TransientDecoupling => 1_500,
                StarFault::PermanentDecoupling => PERMANENT_BITS,
                _ => 4_000,
            },
            hub: HubConfig {
                btr: btr(STAR_BRP, STAR_TSEG1, STAR_TSEG2, STAR_SJW, false, 0),
                ..HubConfig::default()
            },
            ack_units: true,
        }
    }

    /// [`StarScenario::standard`] with NRAP off (`CTRL.nrap_on = 0`): the hubs
    /// decouple on their own (hub contract §7) and their hosts recouple them.
    pub fn without_nrap(fault: StarFault) -> Self {
        let mut s = Self::standard(fault);
        s.hub.nrap_on = false;
        s
    }

    pub fn host_config(&self) -> HostConfig {
        HostConfig {
            btr: btr(STAR_BRP, STAR_TSEG1, STAR_TSEG2, STAR_SJW, false, 96),
            redundancy: true,
            policy: Policy::KFailed(2),
            // The copy on channel B goes out only when no echo came (DRCC contract
            // §4.4), i.e. only after the hubs decoupled: then the node sends on both
            // stars, as it must once NRAP splits the network (hub contract §9).
            dual_tx: true,
            // One domain: the other channel's echo of an own frame completes it
            // (DRCC contract §4.4).
            star: true,
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
    /// Bytes 3..7 lie past the DLC and hold junk, as a host's TX_DATA registers may:
    /// they are not sent, receivers deliver them as 0 ([`Frame::normalized`]), and a
    /// star node must still recognise the echo of its frame (DRCC contract §4.4 and
    /// §6, frames normalized at push).
    pub fn frame(node: usize, k: usize) -> Frame {
        let mut data = [0xA5 ^ k as u8; 8];
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
        if self.fault_bits >= PERMANENT_BITS {
            // The fault never ends: the traffic, and time for the last frames.
            return traffic + 4_000;
        }
        let fault_end = self.fault_start_bits + self.fault_bits;
        traffic.max(fault_end + self.hub.restore_bits as u64 + 1_408 + 2_000)
    }
}

/// Bit times after the end of `all_interlinks_lost` at which the hubs' hosts
/// re-couple them, when NRAP is off (with NRAP the hubs decide themselves).
pub const RECOUPLE_AFTER_BITS: u64 = 200;

/// A fault window this long outlasts every run: the fault is permanent.
pub const PERMANENT_BITS: u64 = 1 << 40;

/// A hub engine by kind: hub `hub_id` (0 = hub 1 of the scenarios, `hub.v`; 1 =
/// hub 2, `hub_b.v`), which decides the identification frame it sends (hub
/// contract §9.1).
pub fn hub_engine(
    kind: EngineKind,
    hub_id: u8,
    n: usize,
    m: usize,
) -> Result<Box<dyn HubEngine>, String> {
    match kind {
        EngineKind::Model => drcc_cosim::engine::hub_model::HubModelEngine::new_hub(hub_id, n, m)
            .map(|e| Box::new(e) as Box<dyn HubEngine>),
        EngineKind::Verilator => {
            if (n, m) != (HUB_N, HUB_M) {
                return Err(format!(
                    "the Verilator hub is the emitted hub.v with {HUB_N} node ports and \
                     {HUB_M} interlinks (asked for {n} and {m}): use --engine model or rust-hdl"
                ));
            }
            drcc_cosim::engine::hub_verilator::HubVerilatorEngine::new_hub(hub_id)
                .map(|e| Box::new(e) as Box<dyn HubEngine>)
                .map_err(|e| format!("{e}; {VERILATOR_HINT}"))
        }
        EngineKind::RustHdl => {
            drcc_cosim::engine::hub_rusthdl::HubRustHdlEngine::new_hub(hub_id, n, m)
                .map(|e| Box::new(e) as Box<dyn HubEngine>)
        }
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
    let hub = |id: u8| match (s.ack_units, kind) {
        (true, _) => hub_engine(kind, id, HUB_N, HUB_M),
        (false, EngineKind::Model) => {
            drcc_cosim::engine::hub_model::HubModelEngine::without_ack_unit(id, HUB_N, HUB_M)
                .map(|e| Box::new(e) as Box<dyn HubEngine>)
        }
        (false, k) => Err(format!(
            "a hub without its ACK unit exists only in the model (asked for {})",
            k.name()
        )),
    };
    let hubs = [hub(0)?, hub(1)?];
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
