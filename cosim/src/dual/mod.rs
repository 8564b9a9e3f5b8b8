//! A dual-bus network of DRCC nodes: every node's channel A on line A, channel B on
//! line B (two independent wired-AND lines, DRCC paper Fig. 1), each node driven by
//! its own [`crate::host::HostDriver`]. Faults: everything [`crate::bus::Bus`] injects, per
//! line, plus a cut of a line between two nodes ([`LineCut`]), a node detached from a
//! line ([`fault::Detach`]) and the short circuit of a line ([`fault::short_circuit`]).
//!
//! Clock contract as for one channel: the `rx` inputs of clock n are computed from
//! the `tx` outputs of step n-1.

pub mod fault;
pub mod lockstep;
pub mod vcd;

use crate::bus::{Bus, Fault};
use crate::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use crate::host::{HostConfig, HostDriver};
use crate::system::{DrccNode, NodeSystem};
use fault::Detach;

/// Which line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Line {
    A,
    B,
}

/// A break in a line between node `at - 1` and node `at` during clocks
/// `start .. start + cycles`: nodes `0..at` and `at..n` form two separate lines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineCut {
    pub at: usize,
    pub start: u64,
    pub cycles: u64,
}

impl LineCut {
    fn active(&self, cycle: u64) -> bool {
        cycle >= self.start && cycle - self.start < self.cycles
    }
}

#[derive(Clone, Debug)]
struct Wire {
    bus: Bus,
    cuts: Vec<LineCut>,
    detaches: Vec<Detach>,
    /// `tx` of the detached nodes, kept while the line is resolved without them.
    detached_tx: Vec<(usize, bool)>,
    tx: Vec<bool>,
    rx: Vec<bool>,
    scratch_tx: Vec<bool>,
    scratch_rx: Vec<bool>,
}

impl Wire {
    fn new(n: usize) -> Self {
        Wire {
            bus: Bus::new(n),
            cuts: Vec::new(),
            detaches: Vec::new(),
            detached_tx: Vec::new(),
            tx: vec![true; n],
            rx: vec![true; n],
            scratch_tx: Vec::new(),
            scratch_rx: Vec::new(),
        }
    }

    /// Computes `rx` for `cycle` from `tx`. A detached node drives recessive into
    /// the line of the others and hears only its own `tx` (`fault` module docs).
    fn resolve(&mut self, cycle: u64) -> bool {
        self.detached_tx.clear();
        for d in &self.detaches {
            if d.active(cycle) && !self.detached_tx.iter().any(|&(i, _)| i == d.node) {
                self.detached_tx.push((d.node, self.tx[d.node]));
            }
        }
        if self.detached_tx.is_empty() {
            return self.resolve_connected(cycle);
        }
        for &(i, _) in &self.detached_tx {
            self.tx[i] = true;
        }
        let line = self.resolve_connected(cycle);
        for &(i, t) in &self.detached_tx {
            self.tx[i] = t;
            self.rx[i] = t;
        }
        line
    }

    /// Computes `rx` for `cycle` from `tx` for nodes connected to the line (bus
    /// faults and cuts apply).
    fn resolve_connected(&mut self, cycle: u64) -> bool {
        let cut = self.cuts.iter().find(|c| c.active(cycle)).copied();
        match cut {
            None => self.bus.resolve(cycle, &self.tx, &mut self.rx),
            Some(c) => {
                // Each segment is a line of its own: resolve it with the others
                // recessive, then keep only its own nodes' receive values.
                let n = self.tx.len();
                let at = c.at.min(n);
                let mut line = true;
                for seg in [0..at, at..n] {
                    self.scratch_tx.clear();
                    self.scratch_tx.extend((0..n).map(|i| {
                        if seg.contains(&i) {
                            self.tx[i]
                        } else {
                            true
                        }
                    }));
                    self.scratch_rx.clear();
                    self.scratch_rx.resize(n, true);
                    line &= self
                        .bus
                        .resolve(cycle, &self.scratch_tx, &mut self.scratch_rx);
                    for i in seg {
                        self.rx[i] = self.scratch_rx[i];
                    }
                }
                line
            }
        }
    }
}

/// N DRCC nodes on two lines.
pub struct DualBusSystem {
    nodes: Vec<DrccNode>,
    wires: [Wire; 2],
    cycle: u64,
    reset_cycles: u64,
}

impl DualBusSystem {
    /// A system of `engines` (node i = `engines[i]`), every host configured with
    /// `configs[i]`. Refuses an empty node list or a length mismatch.
    pub fn new(
        engines: Vec<Box<dyn DrccEngine>>,
        configs: Vec<HostConfig>,
    ) -> Result<Self, String> {
        if engines.is_empty() {
            return Err("a dual-bus system needs at least one node".into());
        }
        if engines.len() != configs.len() {
            return Err(format!(
                "{} engines but {} host configurations",
                engines.len(),
                configs.len()
            ));
        }
        let n = engines.len();
        Ok(DualBusSystem {
            nodes: engines
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
                .collect(),
            wires: [Wire::new(n), Wire::new(n)],
            cycle: 0,
            reset_cycles: 4,
        })
    }

    fn wire(&mut self, line: Line) -> &mut Wire {
        &mut self.wires[line as usize]
    }

    /// Injects a fault on one line (node indices are checked).
    pub fn add_fault(&mut self, line: Line, fault: Fault) -> Result<(), String> {
        self.wire(line).bus.add_fault(fault)
    }

    /// Cuts one line between node `cut.at - 1` and node `cut.at` for a while.
    pub fn add_cut(&mut self, line: Line, cut: LineCut) -> Result<(), String> {
        let n = self.nodes.len();
        if cut.at == 0 || cut.at >= n {
            return Err(format!(
                "a cut at node {} does not split {n} nodes: give 1..={}",
                cut.at,
                n.saturating_sub(1)
            ));
        }
        self.wire(line).cuts.push(cut);
        Ok(())
    }

    /// Detaches node `d.node` from one line for a while (`fault::Detach`): F1..F8 of
    /// the CiA 701 test plan. Refuses a node index out of range or an empty window.
    pub fn detach(&mut self, line: Line, d: Detach) -> Result<(), String> {
        let n = self.nodes.len();
        if d.node >= n {
            return Err(format!(
                "cannot detach node {}: the system has {n} nodes (0..={})",
                d.node,
                n - 1
            ));
        }
        if d.cycles == 0 {
            return Err("a detach lasting 0 cycles: give a duration of at least 1".into());
        }
        self.wire(line).detaches.push(d);
        Ok(())
    }

    /// Short-circuits one whole line for a while (`fault::short_circuit`: every node
    /// reads recessive): F9/F10 of the CiA 701 test plan.
    pub fn short_circuit(&mut self, line: Line, start: u64, cycles: u64) -> Result<(), String> {
        self.add_fault(line, fault::short_circuit(start, cycles))
    }

    /// Repairs both lines at clock `at`: every fault, cut and detach still active
    /// then ends just before `at`; those not started yet are dropped.
    pub fn end_faults(&mut self, at: u64) {
        for w in &mut self.wires {
            w.bus.end_faults(at);
            w.cuts.retain(|c| c.start < at);
            for c in &mut w.cuts {
                c.cycles = c.cycles.min(at - c.start);
            }
            w.detaches.retain(|d| d.start < at);
            for d in &mut w.detaches {
                d.cycles = d.cycles.min(at - d.start);
            }
        }
    }

    /// Whether a fault, cut or detach of either line is active at `cycle` or starts
    /// later.
    pub fn has_faults_from(&self, cycle: u64) -> bool {
        self.wires.iter().any(|w| {
            w.bus.has_faults_from(cycle)
                || w.cuts
                    .iter()
                    .any(|c| c.start.saturating_add(c.cycles) > cycle)
                || w.detaches.iter().any(|d| d.end() > cycle)
        })
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Never empty (refused by `new`).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Node `i`.
    pub fn node(&self, i: usize) -> &DrccNode {
        &self.nodes[i]
    }

    /// Node `i`, mutable (to submit frames or ask for register reads).
    pub fn node_mut(&mut self, i: usize) -> &mut DrccNode {
        &mut self.nodes[i]
    }

    /// The nodes.
    pub fn nodes(&self) -> &[DrccNode] {
        &self.nodes
    }

    /// Clocks stepped so far.
    pub fn cycle(&self) -> u64 {
        self.cycle
    }

    /// Line values (A, B) of the last step.
    pub fn lines(&self) -> (bool, bool) {
        (
            self.wires[0].tx.iter().all(|&b| b),
            self.wires[1].tx.iter().all(|&b| b),
        )
    }

    /// One clock for every node.
    pub fn step(&mut self) {
        let cycle = self.cycle;
        let rst = cycle < self.reset_cycles;
        for (w, line) in self.wires.iter_mut().zip([Line::A, Line::B]) {
            for (i, n) in self.nodes.iter().enumerate() {
                w.tx[i] = match line {
                    Line::A => n.outputs.chan_a_tx,
                    Line::B => n.outputs.chan_b_tx,
                };
            }
            w.resolve(cycle);
        }
        for (i, n) in self.nodes.iter_mut().enumerate() {
            n.inputs.rst = rst;
            n.inputs.chan_a_rx = self.wires[0].rx[i];
            n.inputs.chan_b_rx = self.wires[1].rx[i];
            let prev = n.outputs;
            n.host.drive(cycle, &prev, rst, &mut n.inputs);
            n.outputs = n.engine.step(&n.inputs);
        }
        self.cycle += 1;
    }

    /// Steps until every host is idle and both lines have been recessive for
    /// `quiet` clocks, or `max` clocks passed; returns whether it settled.
    pub fn run_until_quiet(&mut self, quiet: u64, max: u64) -> bool {
        let end = self.cycle + max;
        let mut recessive = 0;
        while self.cycle < end {
            self.step();
            let (a, b) = self.lines();
            let busy = self
                .nodes
                .iter()
                .any(|n| !n.host.is_idle() || n.outputs.probes.tx_going_on);
            recessive = if a && b && !busy { recessive + 1 } else { 0 };
            if recessive >= quiet {
                return true;
            }
        }
        false
    }
}

impl NodeSystem for DualBusSystem {
    fn step(&mut self) {
        DualBusSystem::step(self)
    }
    fn cycle(&self) -> u64 {
        DualBusSystem::cycle(self)
    }
    fn nodes(&self) -> &[DrccNode] {
        DualBusSystem::nodes(self)
    }
    fn node_mut(&mut self, n: usize) -> &mut DrccNode {
        DualBusSystem::node_mut(self, n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bus::FaultTarget;

    fn wire(n: usize) -> Wire {
        Wire::new(n)
    }

    #[test]
    fn a_detached_node_hears_only_itself_and_the_others_do_not_see_it() {
        let mut w = wire(3);
        w.detaches.push(Detach {
            node: 1,
            start: 5,
            cycles: 10,
        });
        // Before the window node 1's dominant bit reaches everyone.
        w.tx = vec![true, false, true];
        assert!(!w.resolve(4));
        assert_eq!(w.rx, [false, false, false]);
        // Inside it the line ignores node 1, which hears its own dominant bit.
        assert!(w.resolve(5));
        assert_eq!(w.rx, [true, false, true]);
        assert_eq!(w.tx, [true, false, true], "tx is left as driven");
        // Another node's dominant bit does not reach node 1 (no acknowledgement).
        w.tx = vec![false, true, true];
        assert!(!w.resolve(6));
        assert_eq!(w.rx, [false, true, false]);
        // After the window it is connected again.
        assert!(!w.resolve(15));
        assert_eq!(w.rx, [false, false, false]);
    }

    #[test]
    fn line_faults_act_on_the_connected_nodes_only_while_one_is_detached() {
        let mut w = wire(3);
        w.detaches.push(Detach {
            node: 0,
            start: 0,
            cycles: u64::MAX,
        });
        w.bus
            .add_fault(fault::short_circuit(0, 100))
            .expect("a valid fault");
        w.tx = vec![false, false, true];
        // The short circuit hides node 1's dominant bit from node 1 and node 2; node
        // 0's open stub still echoes its own.
        assert!(w.resolve(0));
        assert_eq!(w.rx, [false, true, true]);
        assert_eq!(w.bus.faults()[0].target, FaultTarget::Bus);
    }

    #[test]
    fn a_short_circuit_makes_every_node_read_recessive() {
        let mut w = wire(4);
        w.bus
            .add_fault(fault::short_circuit(2, 3))
            .expect("a valid fault");
        w.tx = vec![false, true, false, true];
        assert!(!w.resolve(1));
        assert!(w.resolve(2));
        assert_eq!(w.rx, [true; 4]);
        assert!(!w.resolve(5));
    }
}
