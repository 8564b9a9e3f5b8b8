//! A dual-bus network of DRCC nodes: every node's channel A on line A, channel B on
//! line B (two independent wired-AND lines, DRCC paper Fig. 1), each node driven by
//! its own [`host::HostDriver`]. Faults: everything [`crate::bus::Bus`] injects, per
//! line, plus a cut of a line between two nodes ([`LineCut`]).
//!
//! Clock contract as for one channel: the `rx` inputs of clock n are computed from
//! the `tx` outputs of step n-1.

pub mod host;
pub mod lockstep;
pub mod vcd;

use crate::bus::{Bus, Fault};
use crate::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use host::{HostConfig, HostDriver};

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
            tx: vec![true; n],
            rx: vec![true; n],
            scratch_tx: Vec::new(),
            scratch_rx: Vec::new(),
        }
    }

    /// Computes `rx` for `cycle` from `tx`.
    fn resolve(&mut self, cycle: u64) -> bool {
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

/// One node: its DUT engine and its host.
pub struct DualNode {
    pub engine: Box<dyn DrccEngine>,
    pub host: HostDriver,
    pub inputs: DrccInputs,
    pub outputs: DrccOutputs,
}

/// N DRCC nodes on two lines.
pub struct DualBusSystem {
    nodes: Vec<DualNode>,
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
                .map(|(engine, c)| DualNode {
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

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Never empty (refused by `new`).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Node `i`.
    pub fn node(&self, i: usize) -> &DualNode {
        &self.nodes[i]
    }

    /// Node `i`, mutable (to submit frames or ask for register reads).
    pub fn node_mut(&mut self, i: usize) -> &mut DualNode {
        &mut self.nodes[i]
    }

    /// The nodes.
    pub fn nodes(&self) -> &[DualNode] {
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
