//! The networks `drcc serve` serves, built from the testbench's scenarios, behind
//! the server's one interface ([`drcc_serve::Network`]): a bus of CAN channels
//! (from a scenario file), and DRCC nodes on a dual bus or a replicated star (one
//! body, [`NodeNetwork`], over the topology's [`ServedSystem`]). Each is stepped
//! one clock at a time by the server, takes frames to send from clients (`send`),
//! hands out what its nodes delivered (`poll`, through the traffic taps of
//! `drcc_cosim::traffic`) and takes faults while it runs (`fault`, the
//! `< fault ... >` command of docs/serve.md).

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::dual::{fault::Detach, DualBusSystem, Line, LineCut};
use drcc_cosim::star::{Link, LinkFault, LinkFaultKind, StarSystem};
use drcc_cosim::system::{NodeSystem, System};
use drcc_cosim::traffic::{ChannelTap, NodeTap, TrafficEvent};
use drcc_cosim::Frame;
pub use drcc_serve::Network;

use crate::dual::{drcc_engine, DualFault, DualScenario, CLOCKS_PER_BIT as DUAL_CLOCKS_PER_BIT};
use crate::engines::EngineKind;
use crate::run::build_system;
use crate::scenario::Scenario;
use crate::star::{build_star, StarFault, StarScenario, CLOCKS_PER_BIT as STAR_CLOCKS_PER_BIT};

/// The node names `node0`, `node1`, ...
pub fn default_names(n: usize) -> Vec<String> {
    (0..n).map(|i| format!("node{i}")).collect()
}

/// An optional trailing duration in bit times: `None` for a fault that lasts until
/// `heal`.
fn duration(args: &[String], fixed: usize, usage: &str) -> Result<Option<u64>, String> {
    match &args[fixed..] {
        [] => Ok(None),
        [b] => match b.parse::<u64>() {
            Ok(bits) if bits > 0 => Ok(Some(bits)),
            _ => Err(format!(
                "duration `{b}`: give a number of bit times >= 1, or none for a fault \
                 that lasts until `fault heal` ({usage})"
            )),
        },
        _ => Err(format!("too many arguments: {usage}")),
    }
}

/// `start`, `cycles` of a fault starting at `now` for `bits` bit times (or until
/// healed).
fn window(now: u64, bits: Option<u64>, clocks_per_bit: u64) -> (u64, u64) {
    let cycles = bits.map_or(u64::MAX - now, |b| b.saturating_mul(clocks_per_bit));
    (now, cycles.max(1))
}

fn for_text(bits: Option<u64>) -> String {
    bits.map_or("until healed".to_string(), |b| format!("for {b} bit times"))
}

/// An index argument in `0..n`.
fn index(text: &str, what: &str, n: usize) -> Result<usize, String> {
    match text.parse::<usize>() {
        Ok(i) if i < n => Ok(i),
        _ => Err(format!("{what} `{text}`: give 0..{}", n - 1)),
    }
}

fn line(text: &str) -> Result<Line, String> {
    match text {
        "a" | "A" => Ok(Line::A),
        "b" | "B" => Ok(Line::B),
        _ => Err(format!("line `{text}`: give a or b")),
    }
}

/// A bus of CAN channels built from a scenario file: its frames, faults and aborts
/// run as scheduled, and clients add frames.
pub struct BusNetwork {
    sys: System,
    tap: ChannelTap,
    clock_hz: u64,
    clocks_per_bit: u64,
    engine: EngineKind,
    name: String,
}

/// Usage of the bus's fault command.
pub const BUS_FAULTS: &str = "`fault stuck_dominant|stuck_recessive|flip [BITS]`, \
     `fault heal`";

impl BusNetwork {
    /// The scenario's bus on `kind`.
    pub fn new(sc: &Scenario, kind: EngineKind) -> Result<Self, String> {
        let sys = build_system(sc, kind)?;
        Ok(BusNetwork {
            tap: ChannelTap::new(sys.nodes()),
            sys,
            clock_hz: sc.clock_hz,
            clocks_per_bit: sc.clocks_per_bit(),
            engine: kind,
            name: sc.name.clone(),
        })
    }
}

impl Network for BusNetwork {
    fn names(&self) -> &[String] {
        self.sys.names()
    }
    fn clock_hz(&self) -> u64 {
        self.clock_hz
    }
    fn cycle(&self) -> u64 {
        self.sys.cycle()
    }
    fn clocks_per_bit(&self) -> u64 {
        self.clocks_per_bit
    }
    fn step(&mut self) {
        self.sys.step();
        self.tap.observe(&self.sys);
    }
    fn send(&mut self, node: usize, frame: Frame) -> Result<(), String> {
        let now = self.sys.cycle();
        self.sys.submit(node, now, frame)
    }
    fn poll(&mut self, out: &mut Vec<TrafficEvent>) {
        self.tap.drain(out);
    }
    fn fault(&mut self, args: &[String]) -> Result<String, String> {
        let now = self.sys.cycle();
        let kind = match args.first().map(String::as_str) {
            Some("heal") if args.len() == 1 => {
                self.sys.end_faults(now);
                return Ok("every fault ended".into());
            }
            Some("stuck_dominant") => FaultKind::StuckDominant,
            Some("stuck_recessive") => FaultKind::StuckRecessive,
            Some("flip") => FaultKind::Flip,
            _ => return Err(format!("give {BUS_FAULTS}")),
        };
        let bits = duration(args, 1, BUS_FAULTS)?;
        let (start, cycles) = window(now, bits, self.clocks_per_bit);
        self.sys.add_fault(Fault {
            target: FaultTarget::Bus,
            kind,
            start,
            cycles,
        })?;
        Ok(format!("bus {} {}", args[0], for_text(bits)))
    }
    fn describe(&self) -> String {
        format!(
            "scenario `{}`: a bus of {} CAN channels on the {} engine",
            self.name,
            self.sys.nodes(),
            self.engine.name()
        )
    }
}

/// What a topology of DRCC nodes adds to the body every served DRCC network
/// shares ([`NodeNetwork`]): its clock, its fault command, what it refuses to
/// send, and its description.
pub trait ServedSystem: NodeSystem {
    /// The clock of every node, in Hz.
    const CLOCK_HZ: u64;
    /// Clock cycles per bit time.
    const CLOCKS_PER_BIT: u64;
    /// Refuses a frame the topology cannot carry (the default takes every frame).
    fn check_send(&self, _frame: &Frame) -> Result<(), String> {
        Ok(())
    }
    /// Applies a `< fault ... >` command now; returns what was done.
    fn fault(&mut self, args: &[String]) -> Result<String, String>;
    /// One line naming the topology, its `nodes` and the engine.
    fn describe(&self, nodes: usize, engine: &str) -> String;
}

/// DRCC nodes on a served topology, with the tap that hands out what their hosts
/// popped.
pub struct NodeNetwork<S> {
    sys: S,
    tap: NodeTap,
    names: Vec<String>,
    engine: EngineKind,
}

impl<S: ServedSystem> NodeNetwork<S> {
    fn with(sys: S, engine: EngineKind) -> Self {
        let n = sys.nodes().len();
        NodeNetwork {
            sys,
            tap: NodeTap::new(n),
            names: default_names(n),
            engine,
        }
    }
}

impl<S: ServedSystem> Network for NodeNetwork<S> {
    fn names(&self) -> &[String] {
        &self.names
    }
    fn clock_hz(&self) -> u64 {
        S::CLOCK_HZ
    }
    fn cycle(&self) -> u64 {
        self.sys.cycle()
    }
    fn clocks_per_bit(&self) -> u64 {
        S::CLOCKS_PER_BIT
    }
    fn step(&mut self) {
        self.sys.step();
        self.tap.observe(&self.sys);
    }
    fn send(&mut self, node: usize, frame: Frame) -> Result<(), String> {
        self.sys.check_send(&frame)?;
        let now = self.sys.cycle();
        self.sys.host_mut(node).submit(now, frame, 0);
        Ok(())
    }
    fn poll(&mut self, out: &mut Vec<TrafficEvent>) {
        self.tap.drain(out);
    }
    fn fault(&mut self, args: &[String]) -> Result<String, String> {
        self.sys.fault(args)
    }
    fn describe(&self) -> String {
        self.sys.describe(self.names.len(), self.engine.name())
    }
}

/// DRCC nodes in redundancy mode on a dual bus (the default network).
pub type DualNetwork = NodeNetwork<DualBusSystem>;

/// Usage of the dual bus's fault command.
pub const DUAL_FAULTS: &str = "`fault cut a|b AT [BITS]` (the line broken between \
     node AT-1 and node AT), `fault stuck_dominant a|b [BITS]`, `fault \
     stuck_recessive a|b [BITS]` (a short circuit: every node reads recessive), \
     `fault detach NODE a|b [BITS]`, `fault heal`";

impl NodeNetwork<DualBusSystem> {
    /// `n` DRCC nodes on `kind` in the product's recommended redundancy
    /// configuration (the dual-bus scenarios': switch after 2 failed attempts,
    /// every message on both lines, duplicate window 2,000 bit times), so that a
    /// line cut is hidden from the application.
    pub fn new(n: usize, kind: EngineKind) -> Result<Self, String> {
        if !(2..=32).contains(&n) {
            return Err(format!("--nodes {n}: a dual bus serves 2..=32 nodes"));
        }
        let engines = (0..n)
            .map(|_| drcc_engine(kind))
            .collect::<Result<Vec<_>, _>>()?;
        let config = DualScenario::standard(DualFault::None).host_config();
        let sys = DualBusSystem::new(engines, vec![config; n])?;
        Ok(Self::with(sys, kind))
    }
}

impl ServedSystem for DualBusSystem {
    const CLOCK_HZ: u64 = crate::dual::CLOCK_HZ;
    const CLOCKS_PER_BIT: u64 = DUAL_CLOCKS_PER_BIT;
    fn fault(&mut self, args: &[String]) -> Result<String, String> {
        let now = NodeSystem::cycle(self);
        let n = self.len();
        let words: Vec<&str> = args.iter().map(String::as_str).collect();
        let cpb = DUAL_CLOCKS_PER_BIT;
        match words.as_slice() {
            ["heal"] => {
                self.end_faults(now);
                Ok("every fault ended".into())
            }
            ["cut", l, at, ..] => {
                let bits = duration(args, 3, DUAL_FAULTS)?;
                let at = match at.parse::<usize>() {
                    Ok(a) if (1..n).contains(&a) => a,
                    _ => return Err(format!("cut at `{at}`: give 1..{}", n - 1)),
                };
                let (start, cycles) = window(now, bits, cpb);
                self.add_cut(line(l)?, LineCut { at, start, cycles })?;
                Ok(format!(
                    "line {l} cut between node{} and node{at} {}",
                    at - 1,
                    for_text(bits)
                ))
            }
            [kind @ ("stuck_dominant" | "stuck_recessive"), l, ..] => {
                let bits = duration(args, 2, DUAL_FAULTS)?;
                let (start, cycles) = window(now, bits, cpb);
                let fault = Fault {
                    target: FaultTarget::Bus,
                    kind: if *kind == "stuck_dominant" {
                        FaultKind::StuckDominant
                    } else {
                        FaultKind::StuckRecessive
                    },
                    start,
                    cycles,
                };
                self.add_fault(line(l)?, fault)?;
                Ok(format!("line {l} {kind} {}", for_text(bits)))
            }
            ["detach", node, l, ..] => {
                let bits = duration(args, 3, DUAL_FAULTS)?;
                let node = index(node, "node", n)?;
                let (start, cycles) = window(now, bits, cpb);
                self.detach(
                    line(l)?,
                    Detach {
                        node,
                        start,
                        cycles,
                    },
                )?;
                Ok(format!(
                    "node{node} detached from line {l} {}",
                    for_text(bits)
                ))
            }
            _ => Err(format!("give {DUAL_FAULTS}")),
        }
    }
    fn describe(&self, nodes: usize, engine: &str) -> String {
        format!(
            "a dual bus of {nodes} DRCC nodes in redundancy mode (dual_tx) on the {engine} engine, 1 Mbit/s"
        )
    }
}

/// DRCC nodes on a ReCANcentrate replicated star (two coupled hubs, NRAP on).
pub type StarNetwork = NodeNetwork<StarSystem>;

/// Usage of the star's fault command.
pub const STAR_FAULTS: &str = "`fault uplink|downlink NODE HUB KIND [BITS]`, \
     `fault sublink HUB INTERLINK KIND [BITS]` with KIND stuck_dominant, \
     stuck_recessive (a cut) or flip (1 bit time in every 23), `fault heal`";

impl NodeNetwork<StarSystem> {
    /// The star of the star scenarios (4 nodes, NRAP on) on `kind`, no traffic.
    pub fn new(kind: EngineKind) -> Result<Self, String> {
        let s = StarScenario {
            frames_per_node: 0,
            ..StarScenario::standard(StarFault::None)
        };
        Ok(Self::with(build_star(&s, kind)?, kind))
    }
}

/// Whether a node's frame uses an identifier the hubs reserve (hub contract §9.1 and
/// rule RID: the first ten identifier bits all dominant, judged before IDE is known).
pub fn reserved_on_star(f: &Frame) -> bool {
    let base = if f.ide { f.id >> 18 } else { f.id } & 0x7FF;
    base >> 1 == 0
}

fn link_kind(text: &str) -> Result<LinkFaultKind, String> {
    match text {
        "stuck_dominant" => Ok(LinkFaultKind::StuckDominant),
        "stuck_recessive" => Ok(LinkFaultKind::StuckRecessive),
        "flip" => Ok(LinkFaultKind::BitFlip {
            period: 23 * STAR_CLOCKS_PER_BIT,
            width: STAR_CLOCKS_PER_BIT,
        }),
        _ => Err(format!(
            "fault kind `{text}`: give stuck_dominant, stuck_recessive or flip"
        )),
    }
}

impl ServedSystem for StarSystem {
    const CLOCK_HZ: u64 = crate::star::CLOCK_HZ;
    const CLOCKS_PER_BIT: u64 = STAR_CLOCKS_PER_BIT;
    fn check_send(&self, frame: &Frame) -> Result<(), String> {
        if reserved_on_star(frame) {
            return Err(format!(
                "identifier {:X}: on the star, base identifiers 000 and 001 (and extended \
                 ones below 00080000, whose base part is 000 or 001) are the hubs' \
                 identification frames; a node that sends one is isolated (hub contract \
                 §9.1, rule RID): give a larger identifier",
                frame.id
            ));
        }
        Ok(())
    }
    fn fault(&mut self, args: &[String]) -> Result<String, String> {
        let now = NodeSystem::cycle(self);
        let n = self.len();
        let words: Vec<&str> = args.iter().map(String::as_str).collect();
        let (link, kind, what) = match words.as_slice() {
            ["heal"] => {
                self.end_faults(now);
                return Ok("every fault ended".into());
            }
            [dir @ ("uplink" | "downlink"), node, hub, kind, ..] => {
                let node = index(node, "node", n)?;
                let hub = index(hub, "hub", 2)?;
                let link = if *dir == "uplink" {
                    Link::Uplink { hub, node }
                } else {
                    Link::Downlink { hub, node }
                };
                (link, kind, format!("node{node} {dir} of hub {hub}"))
            }
            ["sublink", hub, interlink, kind, ..] => {
                let from = index(hub, "hub", 2)?;
                let interlink = index(interlink, "interlink", crate::star::HUB_M)?;
                (
                    Link::Sublink { from, interlink },
                    kind,
                    format!("sublink {interlink} from hub {from}"),
                )
            }
            _ => return Err(format!("give {STAR_FAULTS}")),
        };
        let bits = duration(args, 4, STAR_FAULTS)?;
        let (start, cycles) = window(now, bits, STAR_CLOCKS_PER_BIT);
        self.add_fault(LinkFault {
            link,
            kind: link_kind(kind)?,
            start,
            cycles,
        })?;
        Ok(format!("{what} {kind} {}", for_text(bits)))
    }
    fn describe(&self, nodes: usize, engine: &str) -> String {
        format!(
            "a replicated star (2 hubs, NRAP on) of {nodes} DRCC nodes on the {engine} engine, 1 Mbit/s"
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(s: &str) -> Vec<String> {
        s.split(' ').map(str::to_string).collect()
    }

    #[test]
    fn the_star_refuses_the_hubs_identifiers() {
        // hub contract §9.1: 0x000 and 0x001 are the identification frames; rule RID
        // judges the first ten identifier bits, so extended ids below 0x80000 too
        let f = |id, ide| Frame {
            id,
            ide,
            ..Frame::base(0, &[])
        };
        assert!(reserved_on_star(&f(0x000, false)));
        assert!(reserved_on_star(&f(0x001, false)));
        assert!(!reserved_on_star(&f(0x002, false)));
        assert!(reserved_on_star(&f(0x0007_FFFF, true)));
        assert!(!reserved_on_star(&f(0x0008_0000, true)));
    }

    #[test]
    fn dual_bus_fault_commands_are_checked() {
        let mut d = DualNetwork::new(4, EngineKind::Model).unwrap();
        assert!(d
            .fault(&args("cut a 2"))
            .unwrap()
            .contains("node1 and node2"));
        assert!(d
            .fault(&args("detach 3 b 100"))
            .unwrap()
            .contains("for 100 bit times"));
        for (bad, why) in [
            ("cut a 4", "give 1..3"),
            ("cut a 0", "give 1..3"),
            ("cut c 2", "line `c`"),
            ("detach 4 a", "node `4`"),
            ("stuck_dominant a 0", "duration"),
            ("stuck_dominant a 5 6", "too many"),
            ("melt a", "give"),
        ] {
            let e = d.fault(&args(bad)).expect_err(bad);
            assert!(e.contains(why), "{bad}: {e}");
        }
        assert!(d.sys.has_faults_from(d.sys.cycle()));
        d.fault(&args("heal")).unwrap();
        assert!(!d.sys.has_faults_from(d.sys.cycle()));
    }
}
