//! Drawing one campaign scenario from `(seed, index)`: the traffic and the faults,
//! deterministic, so that a scenario is named by its seed and index alone and any
//! of them can be replayed.
//!
//! The dual-bus fault model (one fault of the topology's classes, on line A or B):
//! a line stuck dominant or recessive, a cut at a random position, a dead
//! transceiver (neither drives nor hears the line), a babbling transceiver (stuck
//! dominant: a babbling idiot), a deaf receiver, and a burst of one-bit flips on
//! the line. Onsets are random over the traffic, durations from one bit time to
//! a few thousand (short glitches, faults of a few frames, long outages).
//!
//! The star fault model (ReCANcentrate: two coupled hubs, every node on both; one
//! fault on one link of hub 1 or hub 2, the "line" naming the hub): a node's uplink
//! stuck dominant (a babbling node), stuck recessive, or flipping bits; its
//! downlink cut (reads recessive) or stuck dominant; its transceiver dead on that
//! hub (uplink and downlink recessive); one sublink of an interlink stuck dominant
//! or cut; a whole interlink lost (both sublinks). Losing every interlink is a
//! double fault here (each interlink is one fault).

use crate::random::SplitMix64;

/// Which topology a campaign runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Topology {
    /// DRCC nodes in redundancy mode on lines A and B.
    Dual,
    /// DRCC nodes in CiA 701 DMR mode with first-copy delivery (DMR contract
    /// §8.1) on lines A (the DCL) and B (the RCL), beside a monitor node.
    Dmr,
    /// DRCC nodes on two coupled ReCANcentrate hubs (channel A on hub 1, B on hub 2).
    Star,
    /// DRCC nodes on lines A and B under the ECSS bus selection (DRCC contract
    /// §12): node 0 the heartbeat master, the others following it.
    Ecss,
}

impl Topology {
    /// Name as the CLI and the results spell it.
    pub fn name(self) -> &'static str {
        match self {
            Topology::Dual => "dual",
            Topology::Dmr => "dmr",
            Topology::Star => "star",
            Topology::Ecss => "ecss",
        }
    }

    /// The topology of a name.
    pub fn from_name(s: &str) -> Option<Topology> {
        [
            Topology::Dual,
            Topology::Dmr,
            Topology::Star,
            Topology::Ecss,
        ]
        .into_iter()
        .find(|t| t.name() == s)
    }

    /// The fault classes of this topology's fault model.
    pub fn classes(self) -> &'static [FaultClass] {
        match self {
            Topology::Dual | Topology::Dmr | Topology::Ecss => &FaultClass::DUAL,
            Topology::Star => &FaultClass::STAR,
        }
    }
}

/// One line of the dual bus; on the star, the hub (A = hub 1, B = hub 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Side {
    A,
    B,
}

impl Side {
    pub fn name(self) -> &'static str {
        match self {
            Side::A => "A",
            Side::B => "B",
        }
    }
}

/// A fault class of the dual-bus or the star fault model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum FaultClass {
    // dual bus
    StuckDominant,
    StuckRecessive,
    Cut,
    DeadTransceiver,
    Babbling,
    DeafReceiver,
    BitFlips,
    // star (the link of one hub)
    UplinkStuckDominant,
    UplinkStuckRecessive,
    UplinkBitFlips,
    DownlinkCut,
    DownlinkStuckDominant,
    DeadNodeTransceiver,
    SublinkStuckDominant,
    SublinkCut,
    InterlinkLost,
}

impl FaultClass {
    /// The dual-bus classes, in report order.
    pub const DUAL: [FaultClass; 7] = [
        FaultClass::StuckDominant,
        FaultClass::StuckRecessive,
        FaultClass::Cut,
        FaultClass::DeadTransceiver,
        FaultClass::Babbling,
        FaultClass::DeafReceiver,
        FaultClass::BitFlips,
    ];

    /// The star classes, in report order.
    pub const STAR: [FaultClass; 9] = [
        FaultClass::UplinkStuckDominant,
        FaultClass::UplinkStuckRecessive,
        FaultClass::UplinkBitFlips,
        FaultClass::DownlinkCut,
        FaultClass::DownlinkStuckDominant,
        FaultClass::DeadNodeTransceiver,
        FaultClass::SublinkStuckDominant,
        FaultClass::SublinkCut,
        FaultClass::InterlinkLost,
    ];

    /// Every class.
    pub const ALL: [FaultClass; 16] = [
        FaultClass::StuckDominant,
        FaultClass::StuckRecessive,
        FaultClass::Cut,
        FaultClass::DeadTransceiver,
        FaultClass::Babbling,
        FaultClass::DeafReceiver,
        FaultClass::BitFlips,
        FaultClass::UplinkStuckDominant,
        FaultClass::UplinkStuckRecessive,
        FaultClass::UplinkBitFlips,
        FaultClass::DownlinkCut,
        FaultClass::DownlinkStuckDominant,
        FaultClass::DeadNodeTransceiver,
        FaultClass::SublinkStuckDominant,
        FaultClass::SublinkCut,
        FaultClass::InterlinkLost,
    ];

    /// Bit flips: the fault is a list of one-bit inversions.
    pub fn flips(self) -> bool {
        matches!(self, FaultClass::BitFlips | FaultClass::UplinkBitFlips)
    }

    /// The fault concerns one node (its transceiver or its links).
    pub fn of_node(self) -> bool {
        matches!(
            self,
            FaultClass::DeadTransceiver
                | FaultClass::Babbling
                | FaultClass::DeafReceiver
                | FaultClass::UplinkStuckDominant
                | FaultClass::UplinkStuckRecessive
                | FaultClass::UplinkBitFlips
                | FaultClass::DownlinkCut
                | FaultClass::DownlinkStuckDominant
                | FaultClass::DeadNodeTransceiver
        )
    }

    /// The fault concerns one interlink.
    pub fn of_interlink(self) -> bool {
        matches!(
            self,
            FaultClass::SublinkStuckDominant | FaultClass::SublinkCut | FaultClass::InterlinkLost
        )
    }

    /// Name as the results spell it.
    pub fn name(self) -> &'static str {
        match self {
            FaultClass::StuckDominant => "line_stuck_dominant",
            FaultClass::StuckRecessive => "line_stuck_recessive",
            FaultClass::Cut => "line_cut",
            FaultClass::DeadTransceiver => "dead_transceiver",
            FaultClass::Babbling => "babbling_transceiver",
            FaultClass::DeafReceiver => "deaf_receiver",
            FaultClass::BitFlips => "bit_flips",
            FaultClass::UplinkStuckDominant => "uplink_stuck_dominant",
            FaultClass::UplinkStuckRecessive => "uplink_stuck_recessive",
            FaultClass::UplinkBitFlips => "uplink_bit_flips",
            FaultClass::DownlinkCut => "downlink_cut",
            FaultClass::DownlinkStuckDominant => "downlink_stuck_dominant",
            FaultClass::DeadNodeTransceiver => "dead_node_transceiver",
            FaultClass::SublinkStuckDominant => "sublink_stuck_dominant",
            FaultClass::SublinkCut => "sublink_cut",
            FaultClass::InterlinkLost => "interlink_lost",
        }
    }

    /// The class of a name.
    pub fn from_name(s: &str) -> Option<FaultClass> {
        FaultClass::ALL.into_iter().find(|c| c.name() == s)
    }
}

/// One drawn fault.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DrawnFault {
    pub class: FaultClass,
    /// The line (dual bus) or the hub (star; a sublink fault: the hub it comes from).
    pub line: Side,
    /// The node it concerns (transceiver, receiver and node-link faults), the cut
    /// position (the cut is between node `node - 1` and `node`), or the interlink
    /// (star sublink and interlink faults); 0 for line faults.
    pub node: usize,
    /// Onset and duration in bit times.
    pub start_bit: u64,
    pub bits: u64,
    /// `BitFlips`: the bit times of the flips (within the window).
    pub flips: Vec<u64>,
}

/// One scenario of a campaign: everything the run needs, drawn from the seed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ScenarioSpec {
    pub topology: Topology,
    pub seed: u64,
    pub index: u64,
    pub nodes: usize,
    pub frames_per_node: usize,
    /// Bit times between two submissions of one host (before jitter).
    pub period_bits: u64,
    /// Per node, per frame: extra delay in bit times (jitter) and data length.
    pub jitter: Vec<Vec<u64>>,
    pub dlc: Vec<Vec<u8>>,
    pub faults: Vec<DrawnFault>,
}

impl ScenarioSpec {
    /// The bit time at which the last host submission is due.
    pub fn traffic_end_bits(&self) -> u64 {
        100 + self.period_bits * self.frames_per_node as u64 + 200
    }

    /// The bit time at which the last fault ends.
    pub fn fault_end_bits(&self) -> u64 {
        self.faults
            .iter()
            .map(|f| f.start_bit + f.bits)
            .max()
            .unwrap_or(0)
    }

    /// A one-line description of the faults, for reports.
    pub fn describe(&self) -> String {
        self.faults
            .iter()
            .map(|f| {
                let on = match self.topology {
                    Topology::Dual | Topology::Dmr | Topology::Ecss => {
                        format!("on line {}", f.line.name())
                    }
                    Topology::Star => format!("on hub {}", f.line as usize + 1),
                };
                let at = match f.class {
                    FaultClass::Cut => format!(" between nodes {} and {}", f.node - 1, f.node),
                    c if c.of_node() => format!(" of node {}", f.node),
                    c if c.of_interlink() => format!(" of interlink {}", f.node),
                    _ => String::new(),
                };
                let what = if f.class.flips() {
                    format!("{} flips in", f.flips.len())
                } else {
                    "from".to_string()
                };
                format!(
                    "{} {on}{at}, {what} bit {} for {} bits",
                    f.class.name(),
                    f.start_bit,
                    f.bits
                )
            })
            .collect::<Vec<_>>()
            .join("; ")
    }
}

/// Interlinks of the star campaign's hubs (the emitted `hub.v`).
pub const STAR_INTERLINKS: usize = 2;

/// The generator of scenario `index` of the campaign `seed` (independent streams
/// for every index, so shards and threads draw the same scenarios).
fn rng(seed: u64, index: u64) -> SplitMix64 {
    let mut r = SplitMix64::new(seed ^ 0xD6E8_FEB8_6659_FD93);
    let base = r.next_u64();
    let mut r = SplitMix64::new(base ^ index.wrapping_mul(0x9E37_79B9_7F4A_7C15));
    r.next_u64();
    r
}

/// Draws scenario `index` of campaign `seed` with `faults` faults (1 or 2).
pub fn draw(topology: Topology, faults: usize, seed: u64, index: u64) -> ScenarioSpec {
    let mut r = rng(seed, index);
    let nodes = match topology {
        Topology::Dual | Topology::Dmr | Topology::Ecss => 3 + r.below(4) as usize, // 3..=6
        // the emitted hub.v has 4 node ports; a free port is isolated as silent
        Topology::Star => 4,
    };
    let frames_per_node = 6 + r.below(11) as usize; // 6..=16
                                                    // Offered load 20..50 % of each line: a frame is at most ~130 bit times (8
                                                    // data bytes, worst-case stuffing, intermission), so a host submits one every
                                                    // `nodes x 130 / load` bit times. More would keep frames waiting for
                                                    // arbitration longer than the stall judgement (500 bit times) allows, which the
                                                    // DRCC then takes for a channel failure: an overload, not a fault.
    let load_percent = 20 + r.below(31);
    let period_bits = nodes as u64 * 130 * 100 / load_percent;
    let jitter = (0..nodes)
        .map(|_| {
            (0..frames_per_node)
                .map(|_| r.below(period_bits / 2))
                .collect()
        })
        .collect();
    let dlc = (0..nodes)
        .map(|_| (0..frames_per_node).map(|_| 2 + r.below(7) as u8).collect())
        .collect();
    let mut spec = ScenarioSpec {
        topology,
        seed,
        index,
        nodes,
        frames_per_node,
        period_bits,
        jitter,
        dlc,
        faults: Vec::new(),
    };
    let traffic = spec.traffic_end_bits();
    for _ in 0..faults {
        let classes = topology.classes();
        let class = classes[r.below(classes.len() as u64) as usize];
        let line = if r.below(2) == 0 { Side::A } else { Side::B };
        let node = match class {
            FaultClass::Cut => 1 + r.below(nodes as u64 - 1) as usize,
            c if c.of_node() => r.below(nodes as u64) as usize,
            c if c.of_interlink() => r.below(STAR_INTERLINKS as u64) as usize,
            _ => 0,
        };
        // Durations: a glitch (1..20 bit times), a few frames (20..1000), or a
        // long outage (1000..8000), one in three each.
        let bits = match r.below(3) {
            0 => 1 + r.below(20),
            1 => 20 + r.below(980),
            _ => 1000 + r.below(7000),
        };
        let start_bit = 150 + r.below(traffic.saturating_sub(300).max(1));
        let flips = if class.flips() {
            let n = 1 + r.below(8);
            let mut v: Vec<u64> = (0..n).map(|_| start_bit + r.below(bits)).collect();
            v.sort_unstable();
            v.dedup();
            v
        } else {
            Vec::new()
        };
        spec.faults.push(DrawnFault {
            class,
            line,
            node,
            start_bit,
            bits,
            flips,
        });
    }
    spec
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2000 single-fault scenarios of `topology`: each of its classes is drawn on
    /// both lines (hubs).
    fn every_class_on_both_sides(topology: Topology) -> Vec<ScenarioSpec> {
        let specs: Vec<ScenarioSpec> = (0..2000).map(|i| draw(topology, 1, 1, i)).collect();
        for &c in topology.classes() {
            for l in [Side::A, Side::B] {
                assert!(
                    specs
                        .iter()
                        .any(|s| s.faults[0].class == c && s.faults[0].line == l),
                    "{} on {}",
                    c.name(),
                    l.name()
                );
            }
        }
        specs
    }

    #[test]
    fn a_scenario_is_named_by_its_seed_and_index() {
        assert_eq!(
            draw(Topology::Dual, 1, 7, 42),
            draw(Topology::Dual, 1, 7, 42)
        );
        assert_ne!(
            draw(Topology::Dual, 1, 7, 42),
            draw(Topology::Dual, 1, 7, 43)
        );
        assert_ne!(
            draw(Topology::Dual, 1, 7, 42),
            draw(Topology::Dual, 1, 8, 42)
        );
    }

    #[test]
    fn every_class_line_and_position_is_drawn() {
        let specs = every_class_on_both_sides(Topology::Dual);
        for s in &specs {
            let f = &s.faults[0];
            assert!((3..=6).contains(&s.nodes));
            match f.class {
                FaultClass::Cut => assert!((1..s.nodes).contains(&f.node)),
                _ => assert!(f.node < s.nodes),
            }
            assert!(f.bits >= 1 && f.start_bit >= 150);
            assert!(f
                .flips
                .iter()
                .all(|&b| b >= f.start_bit && b < f.start_bit + f.bits));
        }
        assert!(specs.iter().any(|s| s.faults[0].bits < 20));
        assert!(specs.iter().any(|s| s.faults[0].bits > 5000));
    }

    #[test]
    fn every_star_class_hub_and_link_is_drawn() {
        let specs = every_class_on_both_sides(Topology::Star);
        for s in &specs {
            let f = &s.faults[0];
            assert!(FaultClass::STAR.contains(&f.class));
            assert_eq!(s.nodes, 4);
            if f.class.of_interlink() {
                assert!(f.node < STAR_INTERLINKS);
            } else {
                assert!(f.node < s.nodes);
            }
        }
        for i in 0..STAR_INTERLINKS {
            assert!(specs
                .iter()
                .any(|s| s.faults[0].class.of_interlink() && s.faults[0].node == i));
        }
    }
}
