//! What every system of DRCC nodes shares, whatever joins them (the dual bus of
//! [`crate::dual`], the replicated star of [`crate::star`], the REDCAN ring of
//! [`crate::ring`]): a node is a DRCC engine driven by its host
//! ([`crate::host::HostDriver`]), and a system steps all of them clock by clock.
//! Campaigns, traffic taps and the served networks work on [`NodeSystem`], so one
//! body serves every topology.

use crate::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use crate::host::HostDriver;

/// One DRCC node: its engine, its host, and the engine's inputs and outputs of
/// the last clock.
pub struct DrccNode {
    pub engine: Box<dyn DrccEngine>,
    pub host: HostDriver,
    pub inputs: DrccInputs,
    pub outputs: DrccOutputs,
}

/// A system of DRCC nodes stepped clock by clock.
pub trait NodeSystem {
    /// One clock for every node (and every hub or relay module).
    fn step(&mut self);
    /// Clocks stepped so far.
    fn cycle(&self) -> u64;
    /// Every node, in the system's numbering.
    fn nodes(&self) -> &[DrccNode];
    /// Node `n`.
    fn node_mut(&mut self, n: usize) -> &mut DrccNode;
    /// Whether the nodes' channel B is on a network (false on a REDCAN ring,
    /// where channel A is a node's only connection and B's `rx` is recessive).
    fn channel_b_wired(&self) -> bool {
        true
    }
    /// Node `n`'s host.
    fn host_mut(&mut self, n: usize) -> &mut HostDriver {
        &mut self.node_mut(n).host
    }
    /// Node `n`'s outputs after the last clock.
    fn outputs(&self, n: usize) -> &DrccOutputs {
        &self.nodes()[n].outputs
    }
    /// Every node's host and outputs.
    fn views(&self) -> Vec<(&HostDriver, &DrccOutputs)> {
        self.nodes().iter().map(|n| (&n.host, &n.outputs)).collect()
    }
}
