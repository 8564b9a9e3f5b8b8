//! Running one dual-bus campaign scenario: DRCC nodes in redundancy mode on lines
//! A and B with the product's recommended configuration (the one of
//! `crate::dual::DualScenario::standard`: switch after 2 failed attempts, every
//! message on both lines, stall judgement after 500 bit times), the drawn traffic
//! and the drawn faults, then a fault-free tail. The outcome, from the hosts'
//! point of view: frames lost (a host never popped another host's frame),
//! duplicated (popped more than once) or foreign (popped but never sent), and
//! lockups: nodes not back to normal at the end.
//!
//! "Back to normal" is what the DRCC controls: after the fault every node sends
//! [`TAIL_FRAMES`] more frames (so a node that heals only through traffic gets
//! it: an error-passive receiver's REC falls with every frame it receives), and at
//! the end both auxiliary FSMs judge their channel "valid", no channel is bus-off,
//! and the main FSM is back on channel A (Table 1 states idle1..wait2). A channel
//! may still be error passive: ISO 11898-1 lowers TEC by one per successful
//! transmission, so a transmitter that reached TEC 200 needs over 70 frames to be
//! error active again, which is CAN's rule, not a lockup.
//!
//! The `dmr` topology runs the same scenarios with the nodes in CiA 701 DMR mode
//! and first-copy delivery (DMR contract §8.1), line A the DCL and line B the RCL
//! ([`dmr_config`]), beside a monitor node at the end of both lines that sends
//! nothing and is never faulted (the test system of the seed's Figure 9: devices
//! that start together send identical connection-service frames, which only a
//! node that is not sending acknowledges, DMR contract §7). Back to normal is
//! then "redundancy active" (both lines judged sound) with no channel bus-off.
//!
//! The `ecss` topology runs them under the ECSS bus selection (DRCC contract
//! §12) with the configuration of `drcc redundancy ecss`
//! (`crate::ecss::EcssScenario::standard`): node 0 the master, sending one copy
//! per message and its heartbeat every [`ECSS_HB_BITS`] bit times to the end
//! of the run, the others following it. Its heartbeats are not traffic: the
//! tally leaves them out.

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::dual::{DualBusSystem, Line, LineCut};
use drcc_cosim::host::dmr_config::{DmrConfig, DmrMailbox};
use drcc_cosim::host::HostConfig;
use drcc_cosim::Frame;

use super::draw::{FaultClass, ScenarioSpec, Side, Topology};
use super::tally::{run_and_tally, submit_traffic};
use super::Outcome;
use crate::dual::{drcc_engine, DualFault, DualScenario, CLOCKS_PER_BIT};
use crate::ecss::{EcssFault, EcssScenario};
use crate::engines::EngineKind;

/// Frames every host sends after the last fault and the last submission.
pub const TAIL_FRAMES: usize = 3;

/// Bit times from the later of the last fault's end and the last submission to
/// the first tail frame (bus-off recovery is 128 x 11 = 1408), between two tail
/// frames of a host, and after the last one to the end of the run.
pub const TAIL_START_BITS: u64 = 1_500;
pub const TAIL_PERIOD_BITS: u64 = 1_500;
pub const TAIL_END_BITS: u64 = 4_000;

/// The `ecss` topology's heartbeat period (the ECSS table's).
pub const ECSS_HB_BITS: u64 = 1_000;

/// The product's recommended redundancy configuration: the dual-bus table's.
fn host_config() -> HostConfig {
    DualScenario::standard(DualFault::None).host_config()
}

/// The DMR configuration of node `node` of `nodes` in the `dmr` topology: DMR
/// ticks of 16 bit times, a 40-tick mailbox and connection-service timeout (640
/// bit times: above the largest skew of a frame's two copies in the drawn
/// traffic, 465 bit times measured over the 2,000 scenarios of seed 1, as the
/// timeout must be, `docs/dmr.md` finding 11; a line missing a node's frames is
/// judged within a few frames), a 100-tick recovery delay (1600 bit times, so a
/// line is back within the tail), first-copy delivery; mailbox 0 counts the node's own
/// frames (`frame` gives node `n` the identifiers `0x100 + 0x40 n + k`), mailbox
/// `1 + i` those of the `i`-th other node, each with the deviation limit 3.
pub fn dmr_config(node: usize, nodes: usize) -> DmrConfig {
    let mut c = DmrConfig {
        timeout: 40,
        cs_period: 0,
        tick_bits: 16,
        recovery_delay: 100,
        first_copy: true,
        ..DmrConfig::default()
    };
    let mailbox = |n: usize, transmit: bool| DmrMailbox {
        transmit,
        ide: false,
        id: 0x100 + 0x40 * n as u32,
        mask: 0x7C0,
        limit: 3,
    };
    c.mailboxes[0] = Some(mailbox(node, true));
    for (slot, other) in (0..nodes).filter(|&m| m != node).enumerate() {
        c.mailboxes[1 + slot] = Some(mailbox(other, false));
    }
    c
}

/// The host configurations of the scenario's system: every node in redundancy
/// mode (`dual`), or in DMR mode with first-copy delivery and the monitor node
/// after them (`dmr`; normal mode, both channels on, sending nothing).
pub fn host_configs(spec: &ScenarioSpec) -> Vec<HostConfig> {
    let redundancy = host_config();
    match spec.topology {
        Topology::Dmr => (0..spec.nodes)
            .map(|n| {
                HostConfig::dmr(
                    redundancy.btr,
                    dmr_config(n, spec.nodes),
                    redundancy.dedup_window,
                )
            })
            .chain(std::iter::once(HostConfig {
                redundancy: false,
                dedup_window: 0,
                dmr: None,
                ..redundancy
            }))
            .collect(),
        Topology::Ecss => {
            let e = EcssScenario::standard(EcssFault::None);
            assert_eq!(e.hb_bits, ECSS_HB_BITS);
            (0..spec.nodes)
                .map(|n| {
                    if n == 0 {
                        e.master_config()
                    } else {
                        e.node_config()
                    }
                })
                .collect()
        }
        _ => vec![redundancy; spec.nodes],
    }
}

/// The `k`-th frame of host `node` (`k >= frames_per_node`: a tail frame, 8 bytes):
/// a unique base identifier per (node, k), the drawn length, data naming the node
/// and k.
pub fn frame(spec: &ScenarioSpec, node: usize, k: usize) -> Frame {
    let dlc = spec.dlc[node].get(k).copied().unwrap_or(8);
    let mut data = [0u8; 8];
    data[0] = node as u8;
    data[1] = k as u8;
    for (i, d) in data.iter_mut().enumerate().take(dlc as usize).skip(2) {
        *d = (k * 7 + node * 13 + i * 29) as u8;
    }
    Frame {
        id: 0x100 + (node as u32) * 0x40 + k as u32,
        ide: false,
        rtr: false,
        dlc,
        data,
    }
}

/// Frames each host sends, tail frames included.
pub fn frames(spec: &ScenarioSpec) -> usize {
    spec.frames_per_node + TAIL_FRAMES
}

/// The bit time at which the first tail frame is due.
fn tail_start(spec: &ScenarioSpec) -> u64 {
    spec.traffic_end_bits().max(spec.fault_end_bits()) + TAIL_START_BITS
}

fn line(s: Side) -> Line {
    match s {
        Side::A => Line::A,
        Side::B => Line::B,
    }
}

/// Builds the system of `spec` on `kind`, traffic and faults in place.
pub fn build(spec: &ScenarioSpec, kind: EngineKind) -> Result<DualBusSystem, String> {
    let configs = host_configs(spec);
    let engines = configs
        .iter()
        .map(|_| drcc_engine(kind))
        .collect::<Result<Vec<_>, _>>()?;
    let mut sys = DualBusSystem::new(engines, configs)?;
    submit_traffic(
        spec,
        &mut sys,
        tail_start(spec),
        TAIL_PERIOD_BITS,
        CLOCKS_PER_BIT,
    );
    if spec.topology == Topology::Ecss {
        let end = end_cycle(spec) / CLOCKS_PER_BIT;
        for seq in 0..end / ECSS_HB_BITS {
            let due = (50 + seq * ECSS_HB_BITS) * CLOCKS_PER_BIT;
            sys.node_mut(0)
                .host
                .submit(due, EcssScenario::heartbeat(seq), 0);
        }
    }
    for f in &spec.faults {
        let start = f.start_bit * CLOCKS_PER_BIT;
        let cycles = f.bits * CLOCKS_PER_BIT;
        let l = line(f.line);
        let fault = |target, kind| Fault {
            target,
            kind,
            start,
            cycles,
        };
        match f.class {
            FaultClass::StuckDominant => {
                sys.add_fault(l, fault(FaultTarget::Bus, FaultKind::StuckDominant))?
            }
            FaultClass::StuckRecessive => {
                sys.add_fault(l, fault(FaultTarget::Bus, FaultKind::StuckRecessive))?
            }
            FaultClass::Cut => sys.add_cut(
                l,
                LineCut {
                    at: f.node,
                    start,
                    cycles,
                },
            )?,
            FaultClass::DeadTransceiver => {
                sys.add_fault(l, fault(FaultTarget::Tx(f.node), FaultKind::StuckRecessive))?;
                sys.add_fault(l, fault(FaultTarget::Rx(f.node), FaultKind::StuckRecessive))?;
            }
            FaultClass::Babbling => {
                sys.add_fault(l, fault(FaultTarget::Tx(f.node), FaultKind::StuckDominant))?
            }
            FaultClass::DeafReceiver => {
                sys.add_fault(l, fault(FaultTarget::Rx(f.node), FaultKind::StuckRecessive))?
            }
            c @ (FaultClass::UplinkStuckDominant
            | FaultClass::UplinkStuckRecessive
            | FaultClass::UplinkBitFlips
            | FaultClass::DownlinkCut
            | FaultClass::DownlinkStuckDominant
            | FaultClass::DeadNodeTransceiver
            | FaultClass::SublinkStuckDominant
            | FaultClass::SublinkCut
            | FaultClass::InterlinkLost) => {
                return Err(format!("{} is a star fault, not a dual-bus one", c.name()))
            }
            FaultClass::BitFlips => {
                for &b in &f.flips {
                    sys.add_fault(
                        l,
                        Fault {
                            target: FaultTarget::Bus,
                            kind: FaultKind::Flip,
                            start: b * CLOCKS_PER_BIT,
                            cycles: CLOCKS_PER_BIT,
                        },
                    )?;
                }
            }
        }
    }
    Ok(sys)
}

/// The clock at which the run of `spec` ends.
pub fn end_cycle(spec: &ScenarioSpec) -> u64 {
    (tail_start(spec) + (TAIL_FRAMES as u64 - 1) * TAIL_PERIOD_BITS + TAIL_END_BITS)
        * CLOCKS_PER_BIT
}

/// Runs `spec` on `kind` and tallies the outcome; `observe` sees the system after
/// every clock (traces).
pub fn run(
    spec: &ScenarioSpec,
    kind: EngineKind,
    observe: impl FnMut(&DualBusSystem) -> Result<(), String>,
) -> Result<Outcome, String> {
    let mut sys = build(spec, kind)?;
    run_and_tally(spec, &mut sys, end_cycle(spec), CLOCKS_PER_BIT, observe)
}
