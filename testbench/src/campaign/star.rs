//! Running one star campaign scenario: 4 DRCC nodes on two coupled ReCANcentrate
//! hubs (channel A on hub 1, channel B on hub 2), with the star table's
//! configuration (`crate::star::StarScenario::standard`: nodes send through one hub
//! and switch after 2 failed attempts, the hubs with the contract's default
//! thresholds, ACK interdependence on), the drawn traffic and the drawn link
//! fault, then a fault-free tail.
//!
//! "Back to normal" at the end: every node as on the dual bus
//! ([`super::tally::node_normal`]), and on both hubs every port enabled (an
//! isolated port is restored after `restore_bits` symptom-free bit times, hub
//! contract §6) and the hubs coupled, not decoupled. A port left isolated or a hub
//! left decoupled is a lockup too; it is counted as the node or hub it belongs to
//! (`Outcome::lockups`: nodes 0..4, then hub 1 as 4 and hub 2 as 5).

use drcc_cosim::star::{Link, LinkFault, LinkFaultKind, StarSystem};

use super::draw::{FaultClass, ScenarioSpec};
use super::tally::{run_and_tally, submit_traffic};
use super::Outcome;
use crate::dual::drcc_engine;
use crate::engines::EngineKind;
use crate::star::{hub_engine, StarFault, StarScenario, CLOCKS_PER_BIT, HUB_M, HUB_N};

/// Frames every host sends after the last fault and the last submission.
pub use super::dual::TAIL_FRAMES;

/// Bit times from the later of the last fault's end and the last submission to
/// the first tail frame: the hubs' restoration (`restore_bits`, 1408), a bus-off
/// recovery (128 x 11 = 1408) and a margin; between two tail frames of a host; and
/// after the last one to the end of the run (a DRCC probation is 2000 bit times).
pub const TAIL_START_BITS: u64 = 3_000;
pub const TAIL_PERIOD_BITS: u64 = 1_500;
pub const TAIL_END_BITS: u64 = 4_000;

/// The star table's scenario, for its host and hub configurations.
fn standard() -> StarScenario {
    StarScenario::standard(StarFault::None)
}

fn tail_start(spec: &ScenarioSpec) -> u64 {
    spec.traffic_end_bits().max(spec.fault_end_bits()) + TAIL_START_BITS
}

/// The clock at which the run of `spec` ends.
pub fn end_cycle(spec: &ScenarioSpec) -> u64 {
    (tail_start(spec) + (TAIL_FRAMES as u64 - 1) * TAIL_PERIOD_BITS + TAIL_END_BITS)
        * CLOCKS_PER_BIT
}

/// Builds the system of `spec` on `kind` (rust-hdl: rust-hdl hubs, model nodes),
/// traffic and faults in place.
pub fn build(spec: &ScenarioSpec, kind: EngineKind) -> Result<StarSystem, String> {
    let s = standard();
    let node_kind = match kind {
        EngineKind::RustHdl => EngineKind::Model,
        k => k,
    };
    let engines = (0..spec.nodes)
        .map(|_| drcc_engine(node_kind))
        .collect::<Result<Vec<_>, _>>()?;
    let hubs = [
        hub_engine(kind, 0, HUB_N, HUB_M)?,
        hub_engine(kind, 1, HUB_N, HUB_M)?,
    ];
    let mut sys = StarSystem::new(engines, vec![s.host_config(); spec.nodes], hubs, [s.hub; 2])?;
    submit_traffic(
        spec,
        &mut sys,
        tail_start(spec),
        TAIL_PERIOD_BITS,
        CLOCKS_PER_BIT,
    );
    for f in &spec.faults {
        let hub = f.line as usize;
        let start = f.start_bit * CLOCKS_PER_BIT;
        let cycles = f.bits * CLOCKS_PER_BIT;
        let up = Link::Uplink { hub, node: f.node };
        let down = Link::Downlink { hub, node: f.node };
        let sub = |from| Link::Sublink {
            from,
            interlink: f.node,
        };
        let mut add = |link, kind| {
            sys.add_fault(LinkFault {
                link,
                kind,
                start,
                cycles,
            })
        };
        use LinkFaultKind::*;
        match f.class {
            FaultClass::UplinkStuckDominant => add(up, StuckDominant)?,
            FaultClass::UplinkStuckRecessive => add(up, StuckRecessive)?,
            FaultClass::DownlinkCut => add(down, StuckRecessive)?,
            FaultClass::DownlinkStuckDominant => add(down, StuckDominant)?,
            FaultClass::DeadNodeTransceiver => {
                add(up, StuckRecessive)?;
                add(down, StuckRecessive)?;
            }
            FaultClass::SublinkStuckDominant => add(sub(hub), StuckDominant)?,
            FaultClass::SublinkCut => add(sub(hub), StuckRecessive)?,
            FaultClass::InterlinkLost => {
                add(sub(0), StuckRecessive)?;
                add(sub(1), StuckRecessive)?;
            }
            FaultClass::UplinkBitFlips => {
                for &b in &f.flips {
                    sys.add_fault(LinkFault {
                        link: up,
                        kind: BitFlip {
                            period: 2 * CLOCKS_PER_BIT,
                            width: CLOCKS_PER_BIT,
                        },
                        start: b * CLOCKS_PER_BIT,
                        cycles: CLOCKS_PER_BIT,
                    })?;
                }
            }
            c => return Err(format!("{} is a dual-bus fault, not a star one", c.name())),
        }
    }
    Ok(sys)
}

/// Runs `spec` on `kind` and tallies the outcome; `observe` sees the system after
/// every clock (traces).
pub fn run(
    spec: &ScenarioSpec,
    kind: EngineKind,
    observe: impl FnMut(&StarSystem) -> Result<(), String>,
) -> Result<Outcome, String> {
    let mut sys = build(spec, kind)?;
    let mut o = run_and_tally(spec, &mut sys, end_cycle(spec), CLOCKS_PER_BIT, observe)?;
    let all_ports = ((1u32 << (HUB_N + HUB_M)) - 1) as u16;
    for h in 0..2 {
        let p = sys.hub(h).outputs.probes;
        if p.port_enabled & all_ports != all_ports || p.decoupled || !p.coupled {
            o.lockups.push(spec.nodes + h);
        }
    }
    Ok(o)
}
