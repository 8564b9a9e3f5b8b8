//! A REDCAN ring (seed 000) of DRCC nodes (`ring_contract.md`): N ring nodes, each
//! a DRCC with its relay module (RCM), joined by bus sections that may carry plain
//! DRCC nodes; the RCMs' relays, applied after their operate time, decide which
//! sections form a bus ([`wiring`]). Every node's channel A is on the ring (channel
//! B unused, its `rx` recessive); its host is the Wishbone driver of the dual bus
//! ([`HostDriver`]), and a ring node's host also writes its RCM's control word.
//!
//! Clock contract as for the dual bus and the star: every input of clock n comes
//! from the outputs of step n-1; a section is a wire.

pub mod wiring;

use crate::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use crate::engine::rcm::{RcmEngine, RcmInputs, RcmOutputs};
use crate::host::{HostConfig, HostDriver};
use crate::system::{DrccNode, NodeSystem};
pub use wiring::{BusShape, End, Relay, SectionFaults, Shape, Wiring};

/// One ring node's relay module and the relay it drives.
pub struct RingModule {
    pub engine: Box<dyn RcmEngine>,
    pub outputs: RcmOutputs,
    /// Control word to write at the next clock (`ctl_we` pulse), set by the host.
    pub command: Option<u8>,
    /// The relay state in force on the wires.
    pub applied: Relay,
    /// A state the coil is driving towards, and the clock it is reached.
    pending: Option<(Relay, u64)>,
}

/// Node faults of `ring_contract.md` §3 (section faults are in the wiring).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NodeFault {
    /// The node's `tx` stuck dominant from `start` on.
    Babbling { node: usize, start: u64 },
    /// The node loses power at `start`: no `tx`, no host, relay at rest.
    Crash { node: usize, start: u64 },
}

/// A ring of DRCC nodes.
pub struct RingSystem {
    wiring: Wiring,
    nodes: Vec<DrccNode>,
    modules: Vec<RingModule>,
    /// Relay operate time in clocks (§1).
    relay_clocks: u64,
    /// Section faults and their onset (applied at the onset clock).
    section_faults: Option<(SectionFaults, u64)>,
    node_faults: Vec<NodeFault>,
    crashed: Vec<bool>,
    tx: Vec<bool>,
    rx: Vec<bool>,
    cycle: u64,
    reset_cycles: u64,
}

impl RingSystem {
    /// A ring of `shape` with `engines` (one per node: ring nodes first, then plain
    /// nodes section by section), `rcms` (one per ring node) and one host
    /// configuration for every node; relays switch `relay_clocks` after their RCM.
    pub fn new(
        shape: Shape,
        engines: Vec<Box<dyn DrccEngine>>,
        rcms: Vec<Box<dyn RcmEngine>>,
        config: HostConfig,
        relay_clocks: u64,
    ) -> Result<Self, String> {
        let wiring = Wiring::new(shape)?;
        let (n, total) = (wiring.shape().ring_nodes(), wiring.shape().nodes());
        if engines.len() != total || rcms.len() != n {
            return Err(format!(
                "a ring of {n} ring nodes and {total} nodes needs {total} DRCC engines and {n} RCMs, got {} and {}",
                engines.len(),
                rcms.len()
            ));
        }
        Ok(RingSystem {
            nodes: engines
                .into_iter()
                .map(|engine| DrccNode {
                    engine,
                    host: HostDriver::new(config),
                    inputs: DrccInputs::default(),
                    outputs: DrccOutputs {
                        chan_a_tx: true,
                        chan_b_tx: true,
                        ..DrccOutputs::default()
                    },
                })
                .collect(),
            modules: rcms
                .into_iter()
                .map(|engine| RingModule {
                    engine,
                    outputs: RcmOutputs {
                        relay: true,
                        mode: 3,
                        ..RcmOutputs::default()
                    },
                    command: None,
                    applied: Relay::Transparent,
                    pending: None,
                })
                .collect(),
            wiring,
            relay_clocks,
            section_faults: None,
            node_faults: Vec::new(),
            crashed: vec![false; total],
            tx: vec![true; total],
            rx: vec![true; total],
            cycle: 0,
            reset_cycles: 4,
        })
    }

    /// Section faults from clock `start` on (checked against the shape now).
    pub fn add_section_faults(&mut self, faults: SectionFaults, start: u64) -> Result<(), String> {
        let mut probe = self.wiring.clone();
        probe.set_faults(faults.clone())?;
        self.section_faults = Some((faults, start));
        Ok(())
    }

    /// A node fault (the node index is checked).
    pub fn add_node_fault(&mut self, f: NodeFault) -> Result<(), String> {
        let (NodeFault::Babbling { node, .. } | NodeFault::Crash { node, .. }) = f;
        if node >= self.nodes.len() {
            return Err(format!(
                "node {node} does not exist: the ring has nodes 0..{}",
                self.nodes.len()
            ));
        }
        self.node_faults.push(f);
        Ok(())
    }

    /// The wiring in force.
    pub fn wiring(&self) -> &Wiring {
        &self.wiring
    }

    /// Every node: ring nodes `0..N`, then the plain nodes section by section.
    pub fn nodes(&self) -> &[DrccNode] {
        &self.nodes
    }

    /// Every ring node's module, in ring node order.
    pub fn modules(&self) -> &[RingModule] {
        &self.modules
    }

    /// Node `i`.
    pub fn node(&self, i: usize) -> &DrccNode {
        &self.nodes[i]
    }

    /// Node `i`, mutable (its host).
    pub fn node_mut(&mut self, i: usize) -> &mut DrccNode {
        &mut self.nodes[i]
    }

    /// Ring node `i`'s module.
    pub fn module(&self, i: usize) -> &RingModule {
        &self.modules[i]
    }

    /// Ring node `i`'s module, mutable (to give it a command).
    pub fn module_mut(&mut self, i: usize) -> &mut RingModule {
        &mut self.modules[i]
    }

    /// Whether node `i` has crashed by now.
    pub fn crashed(&self, i: usize) -> bool {
        self.crashed[i]
    }

    /// Clocks stepped so far.
    pub fn cycle(&self) -> u64 {
        self.cycle
    }

    /// One clock for every node and module.
    pub fn step(&mut self) {
        let cycle = self.cycle;
        let rst = cycle < self.reset_cycles;
        if let Some((f, start)) = &self.section_faults {
            if *start == cycle {
                let f = f.clone();
                self.wiring
                    .set_faults(f)
                    .expect("checked by add_section_faults");
            }
        }
        let mut babbling = vec![false; self.nodes.len()];
        for f in &self.node_faults {
            match *f {
                NodeFault::Babbling { node, start } if cycle >= start => babbling[node] = true,
                NodeFault::Crash { node, start } if cycle >= start => self.crashed[node] = true,
                _ => {}
            }
        }
        for (i, n) in self.nodes.iter().enumerate() {
            self.tx[i] = !babbling[i] && (self.crashed[i] || n.outputs.chan_a_tx);
        }
        self.wiring.resolve(&self.tx, &mut self.rx);
        for (i, n) in self.nodes.iter_mut().enumerate() {
            if self.crashed[i] {
                continue;
            }
            n.inputs.rst = rst;
            n.inputs.chan_a_rx = self.rx[i];
            n.inputs.chan_b_rx = true;
            let prev = n.outputs;
            n.host.drive(cycle, &prev, rst, &mut n.inputs);
            n.outputs = n.engine.step(&n.inputs);
        }
        // Modules: the host's command, then the relay operate time (§1). A crashed
        // node's relay falls back to its rest position, transparent.
        let mut relays = Vec::with_capacity(self.modules.len());
        for (i, m) in self.modules.iter_mut().enumerate() {
            let command = if rst || self.crashed[i] {
                None
            } else {
                m.command.take()
            };
            m.outputs = m.engine.step(&RcmInputs {
                rst,
                ctl_we: command.is_some(),
                ctl: command.unwrap_or(0),
            });
            let target = if self.crashed[i] {
                Relay::Transparent
            } else {
                Relay::from_mode(m.outputs.mode)
            };
            if target == m.applied {
                m.pending = None;
            } else if m.pending.map(|(r, _)| r) != Some(target) {
                m.pending = Some((target, cycle + self.relay_clocks));
            }
            if let Some((r, due)) = m.pending {
                if cycle >= due {
                    m.applied = r;
                    m.pending = None;
                }
            }
            relays.push(m.applied);
        }
        self.wiring.set_relays(&relays);
        self.cycle += 1;
    }
}

impl NodeSystem for RingSystem {
    fn step(&mut self) {
        RingSystem::step(self)
    }
    fn cycle(&self) -> u64 {
        RingSystem::cycle(self)
    }
    fn nodes(&self) -> &[DrccNode] {
        RingSystem::nodes(self)
    }
    fn node_mut(&mut self, n: usize) -> &mut DrccNode {
        RingSystem::node_mut(self, n)
    }
    fn channel_b_wired(&self) -> bool {
        false
    }
}
