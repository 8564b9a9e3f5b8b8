//! Co-simulation of two dual-bus systems of DRCC nodes that differ only in their
//! engines (e.g. the reference model and the Verilated RTL): both are stepped in
//! lock step and every output of every node is compared after every clock. The hosts
//! react only to the DUT outputs, so as long as the outputs agree the stimulus is
//! identical; the first divergence is reported with cycle, node, signal and both
//! values.

use super::vcd::{DMR_SIGNALS, DRCC_SIGNALS, EXTRA_SIGNALS};
use super::DualBusSystem;

/// The first clock at which two systems differ.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DrccDivergence {
    pub cycle: u64,
    pub node: usize,
    pub signal: &'static str,
    pub left: u64,
    pub right: u64,
    pub left_engine: &'static str,
    pub right_engine: &'static str,
}

impl std::fmt::Display for DrccDivergence {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "divergence at cycle {} on node{}: `{}` is {:#x} in {} but {:#x} in {}",
            self.cycle,
            self.node,
            self.signal,
            self.left,
            self.left_engine,
            self.right,
            self.right_engine
        )
    }
}

/// Compares the outputs of every node of the two systems after their last step.
pub fn compare(left: &DualBusSystem, right: &DualBusSystem) -> Option<DrccDivergence> {
    for (i, (l, r)) in left.nodes().iter().zip(right.nodes()).enumerate() {
        if l.outputs == r.outputs && l.inputs == r.inputs {
            continue;
        }
        for s in DRCC_SIGNALS.iter().chain(EXTRA_SIGNALS).chain(DMR_SIGNALS) {
            let (a, b) = ((s.get)(l), (s.get)(r));
            if a != b {
                return Some(DrccDivergence {
                    cycle: left.cycle().saturating_sub(1),
                    node: i,
                    signal: s.name,
                    left: a,
                    right: b,
                    left_engine: l.engine.name(),
                    right_engine: r.engine.name(),
                });
            }
        }
        return Some(DrccDivergence {
            cycle: left.cycle().saturating_sub(1),
            node: i,
            signal: "inputs",
            left: 0,
            right: 0,
            left_engine: l.engine.name(),
            right_engine: r.engine.name(),
        });
    }
    None
}

/// Steps both systems `cycles` clocks (plus `each` after every clock on the pair,
/// e.g. to submit frames identically), stopping at the first divergence.
pub fn run_lockstep(
    left: &mut DualBusSystem,
    right: &mut DualBusSystem,
    cycles: u64,
    mut each: impl FnMut(&mut DualBusSystem, &mut DualBusSystem),
) -> Result<(), DrccDivergence> {
    for _ in 0..cycles {
        left.step();
        right.step();
        if let Some(d) = compare(left, right) {
            return Err(d);
        }
        each(left, right);
    }
    Ok(())
}
