//! A replicated star (ReCANcentrate, seed 004 Fig. 1) of DRCC nodes: two coupled
//! hubs joined by M interlinks of two sublinks each; every node has channel A on hub 1
//! (index 0) and channel B on hub 2 (index 1), each through its own uplink and
//! downlink (paper Fig. 2: one controller per hub). Each node transmits through one
//! hub (its DRCC's current channel) and receives from both; because the hubs are
//! coupled, every frame reaches both of its controllers and the DRCC's duplicate
//! removal keeps one copy.
//!
//! Faults act on single links ([`LinkFault`]): an uplink, a downlink or one sublink,
//! stuck at dominant, stuck at recessive (a cut wire: CAN transceivers read a
//! disconnected line as recessive) or bit-flipping.
//!
//! Clock contract as for the dual bus: every input of clock n is computed from the
//! outputs of step n-1 (a link is a wire; the hubs' and nodes' own synchronizers and
//! output registers make up the whole delay).

pub mod hub_host;
pub mod lockstep;

use crate::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use crate::engine::hub::{HubEngine, HubInputs, HubOutputs};
use crate::host::{HostConfig, HostDriver};
use crate::system::{DrccNode, NodeSystem};
use hub_host::{HubConfig, HubHost};

/// A link of the star.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Link {
    /// Node `node`'s transmitter towards hub `hub` (0 = hub 1 / channel A).
    Uplink { hub: usize, node: usize },
    /// Hub `hub`'s downlink towards node `node`.
    Downlink { hub: usize, node: usize },
    /// The sublink of interlink `interlink` going from hub `from` to the twin.
    Sublink { from: usize, interlink: usize },
}

/// What a link fault does to the value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkFaultKind {
    /// Forced dominant.
    StuckDominant,
    /// Forced recessive (also: a cut link).
    StuckRecessive,
    /// Inverted during the first `width` clocks of every `period` clocks (from the
    /// fault's start): a transceiver that flips bits.
    BitFlip { period: u64, width: u64 },
}

/// A fault on one link during clocks `start .. start + cycles`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LinkFault {
    pub link: Link,
    pub kind: LinkFaultKind,
    pub start: u64,
    pub cycles: u64,
}

impl LinkFault {
    fn apply(&self, cycle: u64, v: bool) -> bool {
        if cycle < self.start || cycle - self.start >= self.cycles {
            return v;
        }
        match self.kind {
            LinkFaultKind::StuckDominant => false,
            LinkFaultKind::StuckRecessive => true,
            LinkFaultKind::BitFlip { period, width } => {
                if (cycle - self.start) % period.max(1) < width {
                    !v
                } else {
                    v
                }
            }
        }
    }
}

/// One hub with its host.
pub struct StarHub {
    pub engine: Box<dyn HubEngine>,
    pub host: HubHost,
    pub inputs: HubInputs,
    pub outputs: HubOutputs,
}

/// Two hubs and their DRCC nodes.
pub struct StarSystem {
    nodes: Vec<DrccNode>,
    hubs: Vec<StarHub>,
    faults: Vec<LinkFault>,
    cycle: u64,
    reset_cycles: u64,
}

impl StarSystem {
    /// A star of `engines` (node i = `engines[i]`, host configured with `configs[i]`)
    /// on the two hubs `hubs` (configured with `hub_configs`). The hubs must have the
    /// same shape, at least as many node ports as there are nodes.
    pub fn new(
        engines: Vec<Box<dyn DrccEngine>>,
        configs: Vec<HostConfig>,
        hubs: [Box<dyn HubEngine>; 2],
        hub_configs: [HubConfig; 2],
    ) -> Result<Self, String> {
        if engines.is_empty() {
            return Err("a star needs at least one node".into());
        }
        if engines.len() != configs.len() {
            return Err(format!(
                "{} engines but {} host configurations",
                engines.len(),
                configs.len()
            ));
        }
        let shape = hubs[0].shape();
        if hubs[1].shape() != shape {
            return Err(format!(
                "the two hubs differ: {:?} and {:?} (node ports, interlinks)",
                shape,
                hubs[1].shape()
            ));
        }
        if engines.len() > shape.0 {
            return Err(format!(
                "{} nodes do not fit hubs with {} node ports",
                engines.len(),
                shape.0
            ));
        }
        let nodes = engines
            .into_iter()
            .zip(configs)
            .map(|(engine, c)| DrccNode {
                engine,
                host: HostDriver::new(c),
                inputs: DrccInputs::default(),
                outputs: DrccOutputs {
                    chan_a_tx: true,
                    chan_b_tx: true,
                    ..DrccOutputs::default()
                },
            })
            .collect();
        let hubs = hubs
            .into_iter()
            .zip(hub_configs)
            .map(|(engine, c)| StarHub {
                engine,
                host: HubHost::new(c),
                inputs: HubInputs::default(),
                outputs: HubOutputs {
                    downlink: 0xFFFF,
                    sublink_out: 0xFF,
                    ..HubOutputs::default()
                },
            })
            .collect();
        Ok(StarSystem {
            nodes,
            hubs,
            faults: Vec::new(),
            cycle: 0,
            reset_cycles: 4,
        })
    }

    /// Injects a fault on one link (indices are checked).
    pub fn add_fault(&mut self, f: LinkFault) -> Result<(), String> {
        let (n, m) = self.hubs[0].engine.shape();
        let ok = match f.link {
            Link::Uplink { hub, node } | Link::Downlink { hub, node } => {
                hub < 2 && node < self.nodes.len()
            }
            Link::Sublink { from, interlink } => from < 2 && interlink < m,
        };
        if !ok {
            return Err(format!(
                "no such link {:?}: hubs 0..2, nodes 0..{}, interlinks 0..{m} ({n} node ports)",
                f.link,
                self.nodes.len()
            ));
        }
        if let LinkFaultKind::BitFlip { period, width } = f.kind {
            if period == 0 || width == 0 || width >= period {
                return Err(format!(
                    "bit-flipping fault needs 0 < width < period (got width {width}, period {period})"
                ));
            }
        }
        self.faults.push(f);
        Ok(())
    }

    /// Repairs every link at clock `at`: a fault still active then ends just before
    /// `at`, one not started yet is dropped.
    pub fn end_faults(&mut self, at: u64) {
        self.faults.retain(|f| f.start < at);
        for f in &mut self.faults {
            f.cycles = f.cycles.min(at - f.start);
        }
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Never empty (refused by `new`).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    pub fn node(&self, i: usize) -> &DrccNode {
        &self.nodes[i]
    }

    pub fn node_mut(&mut self, i: usize) -> &mut DrccNode {
        &mut self.nodes[i]
    }

    pub fn nodes(&self) -> &[DrccNode] {
        &self.nodes
    }

    /// Hub `h` (0 = hub 1, channel A side).
    pub fn hub(&self, h: usize) -> &StarHub {
        &self.hubs[h]
    }

    pub fn hub_mut(&mut self, h: usize) -> &mut StarHub {
        &mut self.hubs[h]
    }

    /// Clocks stepped so far.
    pub fn cycle(&self) -> u64 {
        self.cycle
    }

    fn faulty(&self, link: Link, v: bool) -> bool {
        self.faults
            .iter()
            .filter(|f| f.link == link)
            .fold(v, |v, f| f.apply(self.cycle, v))
    }

    /// One clock for every node and both hubs.
    pub fn step(&mut self) {
        let cycle = self.cycle;
        let rst = cycle < self.reset_cycles;
        let (_, m) = self.hubs[0].engine.shape();
        // Hub inputs from the previous outputs.
        for h in 0..2 {
            let mut uplink = 0xFFFFu16;
            for (i, n) in self.nodes.iter().enumerate() {
                let tx = if h == 0 {
                    n.outputs.chan_a_tx
                } else {
                    n.outputs.chan_b_tx
                };
                if !self.faulty(Link::Uplink { hub: h, node: i }, tx) {
                    uplink &= !(1 << i);
                }
            }
            let twin = self.hubs[1 - h].outputs.sublink_out;
            let mut sublink_in = 0xFFu8;
            for j in 0..m {
                let v = twin >> j & 1 != 0;
                if !self.faulty(
                    Link::Sublink {
                        from: 1 - h,
                        interlink: j,
                    },
                    v,
                ) {
                    sublink_in &= !(1 << j);
                }
            }
            let hub = &mut self.hubs[h];
            hub.inputs.rst = rst;
            hub.inputs.uplink = uplink;
            hub.inputs.sublink_in = sublink_in;
        }
        // Node inputs from the previous hub outputs.
        for i in 0..self.nodes.len() {
            let a = self.hubs[0].outputs.downlink >> i & 1 != 0;
            let b = self.hubs[1].outputs.downlink >> i & 1 != 0;
            let a = self.faulty(Link::Downlink { hub: 0, node: i }, a);
            let b = self.faulty(Link::Downlink { hub: 1, node: i }, b);
            let n = &mut self.nodes[i];
            n.inputs.rst = rst;
            n.inputs.chan_a_rx = a;
            n.inputs.chan_b_rx = b;
        }
        for n in self.nodes.iter_mut() {
            let prev = n.outputs;
            n.host.drive(cycle, &prev, rst, &mut n.inputs);
            n.outputs = n.engine.step(&n.inputs);
        }
        for hub in self.hubs.iter_mut() {
            let prev = hub.outputs;
            hub.host.drive(cycle, &prev, rst, &mut hub.inputs);
            hub.outputs = hub.engine.step(&hub.inputs);
        }
        self.cycle += 1;
    }
}

impl NodeSystem for StarSystem {
    fn step(&mut self) {
        StarSystem::step(self)
    }
    fn cycle(&self) -> u64 {
        StarSystem::cycle(self)
    }
    fn nodes(&self) -> &[DrccNode] {
        StarSystem::nodes(self)
    }
    fn node_mut(&mut self, n: usize) -> &mut DrccNode {
        StarSystem::node_mut(self, n)
    }
}
