//! A system of N CAN channels (any mix of engines) on one wired-AND bus, sharing one
//! bit timing, stepped clock by clock per the timing contract
//! (`crate::model`, section 1): the `rx` of every node in cycle n is the wired AND
//! of every node's `tx` returned by step n-1, after fault injection.
//!
//! The system plays the host of every node: each node has a transmit queue of
//! frames due at given clock cycles. When a node's `tx_pending` is low and the
//! frame at the head of its queue is due, the system raises `tx_req` for one clock
//! with that frame (frames leave a queue in the order of their due cycles; frames
//! due at the same cycle keep their submission order). It records every delivered
//! frame (`rx_valid`), every `tx_done`, every `tx_failed` and every `arb_lost`,
//! with its cycle.
//!
//! Every node gets the system's [`ControllerConfig`] (mode, error warning limit,
//! single shot; default [`ControllerConfig::default`], settable for all nodes or
//! per node before the first step), which the channels capture during reset
//! (timing contract §6). `tx_abort` stays low except for the one-clock aborts
//! requested with [`System::abort`]; in a clock that raises `tx_abort` the node
//! gets no new `tx_req` (the host aborts first, the next frame follows).
//!
//! All nodes are held in reset for the first [`System::reset_cycles`] cycles
//! (default [`DEFAULT_RESET_CYCLES`]); no request and no abort is raised during
//! reset.
//!
//! [`System::step`] makes one clock and keeps its [`Sample`]: what traces and
//! lock-step comparisons watch. [`System::run_for`] and [`System::run_until_idle`]
//! make the same clocks with the same events for runs nobody watches clock by
//! clock: where the host raises nothing for a while they step the nodes through
//! [`ChannelEngine::step_quiet`] and keep only the last sample.

use std::collections::VecDeque;
use std::convert::Infallible;

use crate::bus::{Bus, Fault};
use crate::engine::{BitTiming, ChannelEngine, ChannelInputs, ChannelOutputs, ControllerConfig};
use crate::frame::Frame;

/// Cycles of reset at the start of every run.
pub const DEFAULT_RESET_CYCLES: u64 = 4;

/// Recessive bits after which the bus counts as idle (ACK delimiter + EOF +
/// intermission = 11 bits, the same count a node integrates after reset).
pub const IDLE_BITS: u64 = 11;

/// Everything that happened in one clock cycle: the inputs applied and the outputs
/// returned by every node. This is what traces record.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sample {
    /// Clock cycle (index of the step, from 0).
    pub cycle: u64,
    /// Reset applied in this cycle.
    pub rst: bool,
    /// The line value in this cycle (wired AND of the previous step's `tx`, after
    /// line and transmitter faults).
    pub bus: bool,
    /// Per node: the `rx` input applied (the line after receiver faults).
    pub rx: Vec<bool>,
    /// Per node: the `tx_req` input applied.
    pub tx_req: Vec<bool>,
    /// Per node: the `tx_abort` input applied.
    pub tx_abort: Vec<bool>,
    /// Per node: the outputs after the clock edge.
    pub outputs: Vec<ChannelOutputs>,
}

/// One recorded host event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NodeEvent {
    /// Cycle whose outputs carried the pulse.
    pub cycle: u64,
    /// Node index.
    pub node: usize,
    /// The frame received (`rx_valid`) or sent (`tx_done`, `tx_failed`,
    /// `arb_lost`: the frame latched by the node's last request).
    pub frame: Frame,
}

/// How a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RunOutcome {
    /// Every queue is empty, no frame is pending and the bus has been recessive for
    /// [`IDLE_BITS`] bit times; `cycle` is the number of cycles run.
    Idle {
        /// Cycles run.
        cycle: u64,
    },
    /// The cycle limit was hit first.
    CycleLimit {
        /// Cycles run.
        cycle: u64,
    },
}

impl RunOutcome {
    /// Cycles run.
    pub fn cycles(&self) -> u64 {
        match *self {
            RunOutcome::Idle { cycle } | RunOutcome::CycleLimit { cycle } => cycle,
        }
    }
    /// Whether the run ended idle.
    pub fn is_idle(&self) -> bool {
        matches!(self, RunOutcome::Idle { .. })
    }
}

#[derive(Clone, Copy, Debug)]
struct Queued {
    due: u64,
    frame: Frame,
    /// Requested with `tx_single` (timing contract §8).
    single: bool,
}

/// N channel engines on one bus.
pub struct System {
    names: Vec<String>,
    engines: Vec<Box<dyn ChannelEngine>>,
    queues: Vec<VecDeque<Queued>>,
    in_flight: Vec<Option<Frame>>,
    tx_frame: Vec<Frame>,
    /// Due cycles of the aborts still to raise, per node, sorted.
    aborts: Vec<VecDeque<u64>>,
    timing: BitTiming,
    config: Vec<ControllerConfig>,
    bus: Bus,
    reset_cycles: u64,
    sample: Sample,
    tx: Vec<bool>,
    deliveries: Vec<NodeEvent>,
    sent: Vec<NodeEvent>,
    failed: Vec<NodeEvent>,
    arb_lost: Vec<NodeEvent>,
    recessive_cycles: u64,
    steps: u64,
    /// Per node: the inputs of the current quiet stretch (`run_quiet`).
    quiet_inputs: Vec<ChannelInputs>,
    /// Every engine gains from quiet stretches.
    quiet_gains: bool,
}

impl System {
    /// A system of the given engines (node i = `engines[i]`, named `node{i}`) with
    /// one shared bit timing and the default [`ControllerConfig`]. Refuses an empty
    /// node list and an illegal timing.
    pub fn new(engines: Vec<Box<dyn ChannelEngine>>, timing: BitTiming) -> Result<Self, String> {
        if engines.is_empty() {
            return Err("a system needs at least one node".to_string());
        }
        timing.validate()?;
        let n = engines.len();
        Ok(System {
            names: (0..n).map(|i| format!("node{i}")).collect(),
            queues: vec![VecDeque::new(); n],
            in_flight: vec![None; n],
            tx_frame: vec![Frame::default(); n],
            aborts: vec![VecDeque::new(); n],
            timing,
            config: vec![ControllerConfig::default(); n],
            bus: Bus::new(n),
            reset_cycles: DEFAULT_RESET_CYCLES,
            sample: Sample {
                cycle: 0,
                rst: false,
                bus: true,
                rx: vec![true; n],
                tx_req: vec![false; n],
                tx_abort: vec![false; n],
                outputs: vec![idle_outputs(); n],
            },
            tx: vec![true; n],
            deliveries: Vec::new(),
            sent: Vec::new(),
            failed: Vec::new(),
            arb_lost: Vec::new(),
            recessive_cycles: 0,
            steps: 0,
            quiet_inputs: Vec::with_capacity(n),
            quiet_gains: engines.iter().all(|e| e.gains_from_quiet()),
            engines,
        })
    }

    /// Gives the nodes names (used in reports; traces always use `node{i}`).
    pub fn set_names(&mut self, names: Vec<String>) -> Result<(), String> {
        if names.len() != self.engines.len() {
            return Err(format!(
                "{} names given for {} nodes",
                names.len(),
                self.engines.len()
            ));
        }
        self.names = names;
        Ok(())
    }

    /// Sets the number of reset cycles at the start (at least 1). Call before the
    /// first step.
    pub fn set_reset_cycles(&mut self, cycles: u64) {
        self.reset_cycles = cycles.max(1);
    }

    /// Cycles of reset at the start.
    pub fn reset_cycles(&self) -> u64 {
        self.reset_cycles
    }

    /// Injects a fault (node indices are checked).
    pub fn add_fault(&mut self, fault: Fault) -> Result<(), String> {
        self.bus.add_fault(fault)
    }

    /// Repairs the bus at clock `at` ([`Bus::end_faults`]).
    pub fn end_faults(&mut self, at: u64) {
        self.bus.end_faults(at);
    }

    /// The bus (with its faults).
    pub fn bus(&self) -> &Bus {
        &self.bus
    }

    /// Number of nodes.
    pub fn nodes(&self) -> usize {
        self.engines.len()
    }

    /// Node names.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Engine names, per node.
    pub fn engine_names(&self) -> Vec<&'static str> {
        self.engines.iter().map(|e| e.name()).collect()
    }

    /// A short description of the engines: `model`, or `model+verilator` if mixed.
    pub fn engine_label(&self) -> String {
        let mut names: Vec<&str> = self.engine_names();
        names.dedup();
        names.join("+")
    }

    /// The shared bit timing.
    pub fn timing(&self) -> BitTiming {
        self.timing
    }

    /// Gives every node `config` (mode, error warning limit, single shot). The
    /// channels capture it while in reset: call before the first step.
    pub fn set_config(&mut self, config: ControllerConfig) {
        self.config.fill(config);
    }

    /// Gives one node its own `config` (see [`System::set_config`]).
    pub fn set_node_config(&mut self, node: usize, config: ControllerConfig) -> Result<(), String> {
        let nodes = self.nodes();
        let c = self
            .config
            .get_mut(node)
            .ok_or_else(|| no_such_node(node, nodes))?;
        *c = config;
        Ok(())
    }

    /// The configuration of every node (index = node).
    pub fn configs(&self) -> &[ControllerConfig] {
        &self.config
    }

    /// Number of steps made so far (= index of the next cycle).
    pub fn cycle(&self) -> u64 {
        self.steps
    }

    /// The last step's inputs and outputs.
    pub fn sample(&self) -> &Sample {
        &self.sample
    }

    /// Queues `frame` on `node`, to be requested at `at_cycle` or later.
    pub fn submit(&mut self, node: usize, at_cycle: u64, frame: Frame) -> Result<(), String> {
        self.enqueue(node, at_cycle, frame, false)
    }

    /// [`System::submit`], requested with `tx_single`: the frame is dropped at
    /// its first failed attempt whatever the node's configuration (timing
    /// contract §8).
    pub fn submit_single_shot(
        &mut self,
        node: usize,
        at_cycle: u64,
        frame: Frame,
    ) -> Result<(), String> {
        self.enqueue(node, at_cycle, frame, true)
    }

    fn enqueue(
        &mut self,
        node: usize,
        at_cycle: u64,
        frame: Frame,
        single: bool,
    ) -> Result<(), String> {
        let nodes = self.nodes();
        let q = self
            .queues
            .get_mut(node)
            .ok_or_else(|| no_such_node(node, nodes))?;
        // Keep the queue sorted by due cycle, stable for equal due cycles.
        let pos = q.partition_point(|e| e.due <= at_cycle);
        q.insert(
            pos,
            Queued {
                due: at_cycle,
                frame,
                single,
            },
        );
        Ok(())
    }

    /// Raises `tx_abort` on `node` for one clock at `at_cycle`, or at the first
    /// cycle after reset if that is later (timing contract §8: the pending frame
    /// is dropped with `tx_failed` unless it is being sent; nothing happens when no
    /// frame is pending). No `tx_req` is raised on that node in that clock.
    pub fn abort(&mut self, node: usize, at_cycle: u64) -> Result<(), String> {
        let nodes = self.nodes();
        let q = self
            .aborts
            .get_mut(node)
            .ok_or_else(|| no_such_node(node, nodes))?;
        let pos = q.partition_point(|&c| c <= at_cycle);
        q.insert(pos, at_cycle);
        Ok(())
    }

    /// Frames still waiting in `node`'s queue (not yet requested).
    pub fn queued(&self, node: usize) -> usize {
        self.queues.get(node).map_or(0, |q| q.len())
    }

    /// Every `rx_valid`, in order.
    pub fn deliveries(&self) -> &[NodeEvent] {
        &self.deliveries
    }

    /// Every `tx_done`, in order.
    pub fn tx_done(&self) -> &[NodeEvent] {
        &self.sent
    }

    /// Every `tx_failed` (frames dropped: single shot, abort, listen-only), in order.
    pub fn tx_failed(&self) -> &[NodeEvent] {
        &self.failed
    }

    /// Every `arb_lost`, in order.
    pub fn arb_lost(&self) -> &[NodeEvent] {
        &self.arb_lost
    }

    /// Every queue empty, nothing pending, and the bus recessive for
    /// [`IDLE_BITS`] bit times after reset.
    pub fn is_quiescent(&self) -> bool {
        self.steps > self.reset_cycles
            && self.queues.iter().all(|q| q.is_empty())
            && self.sample.outputs.iter().all(|o| !o.tx_pending)
            && self.recessive_cycles >= IDLE_BITS * self.timing.clocks_per_bit() as u64
    }

    /// The bus of `cycle` from the nodes' `tx` of the last clock: each node's
    /// `rx`, the line and the recessive run, into the sample.
    #[inline(always)]
    fn resolve_bus(&mut self, cycle: u64) {
        for (t, o) in self.tx.iter_mut().zip(&self.sample.outputs) {
            *t = o.tx;
        }
        let line = self.bus.resolve(cycle, &self.tx, &mut self.sample.rx);
        if line {
            self.recessive_cycles = self.recessive_cycles.saturating_add(1);
        } else {
            self.recessive_cycles = 0;
        }
        self.sample.cycle = cycle;
        self.sample.bus = line;
    }

    /// One clock cycle for every node. Returns the new sample.
    pub fn step(&mut self) -> &Sample {
        let cycle = self.steps;
        let rst = cycle < self.reset_cycles;
        self.resolve_bus(cycle);
        self.sample.rst = rst;
        for i in 0..self.engines.len() {
            let mut tx_abort = false;
            if !rst {
                // Aborts due now (several due by now make one pulse).
                while self.aborts[i].front().is_some_and(|&c| c <= cycle) {
                    self.aborts[i].pop_front();
                    tx_abort = true;
                }
            }
            let mut tx_req = false;
            let mut tx_single = false;
            if !rst && !tx_abort && !self.sample.outputs[i].tx_pending && !self.sample.tx_req[i] {
                if let Some(head) = self.queues[i].front() {
                    if head.due <= cycle {
                        tx_req = true;
                        tx_single = head.single;
                        self.tx_frame[i] = head.frame;
                        self.in_flight[i] = Some(head.frame);
                        self.queues[i].pop_front();
                    }
                }
            }
            let inputs = ChannelInputs {
                rst,
                rx: self.sample.rx[i],
                timing: self.timing,
                config: self.config[i],
                tx_req,
                tx_frame: self.tx_frame[i],
                tx_abort,
                tx_single,
                err_reset: false,
                boff_hold: false,
            };
            let out = self.engines[i].step(&inputs);
            self.sample.tx_req[i] = tx_req;
            self.sample.tx_abort[i] = tx_abort;
            self.sample.outputs[i] = out;
            self.record(cycle, i, &out);
        }
        self.steps += 1;
        &self.sample
    }

    /// Records the host events of node `i`'s outputs `out` in `cycle`. Inlined:
    /// `step` calls it for every node every clock.
    #[inline(always)]
    fn record(&mut self, cycle: u64, i: usize, out: &ChannelOutputs) {
        let mine = self.in_flight[i].unwrap_or_default();
        if out.rx_valid {
            self.deliveries.push(NodeEvent {
                cycle,
                node: i,
                frame: out.rx_frame,
            });
        }
        if out.arb_lost {
            self.arb_lost.push(NodeEvent {
                cycle,
                node: i,
                frame: mine,
            });
        }
        if out.tx_done {
            self.sent.push(NodeEvent {
                cycle,
                node: i,
                frame: mine,
            });
            self.in_flight[i] = None;
        }
        if out.tx_failed {
            self.failed.push(NodeEvent {
                cycle,
                node: i,
                frame: mine,
            });
            self.in_flight[i] = None;
        }
    }

    /// [`System::run_until_idle`] clock by clock (every sample is a step's): what
    /// `run_until_idle` must equal.
    pub fn run_until_idle_stepwise(&mut self, max_cycles: u64) -> RunOutcome {
        match self.run_until_idle_with(max_cycles, |_| Ok::<(), Infallible>(())) {
            Ok(o) => o,
            Err(never) => match never {},
        }
    }

    /// As [`System::run_until_idle`], calling `observe` with every sample; stops
    /// at the observer's first error.
    pub fn run_until_idle_with<F, E>(
        &mut self,
        max_cycles: u64,
        mut observe: F,
    ) -> Result<RunOutcome, E>
    where
        F: FnMut(&Sample) -> Result<(), E>,
    {
        loop {
            if self.is_quiescent() {
                return Ok(RunOutcome::Idle { cycle: self.steps });
            }
            if self.steps >= max_cycles {
                return Ok(RunOutcome::CycleLimit { cycle: self.steps });
            }
            self.step();
            observe(&self.sample)?;
        }
    }
}

fn no_such_node(node: usize, nodes: usize) -> String {
    format!(
        "node {node} does not exist: the system has {nodes} nodes (0..={})",
        nodes - 1
    )
}

/// Outputs of a node that has not been clocked yet: everything recessive/idle.
fn idle_outputs() -> ChannelOutputs {
    ChannelOutputs {
        tx: true,
        ..ChannelOutputs::default()
    }
}

pub mod node;
mod quiet;

pub use node::{DrccNode, NodeSystem};

#[cfg(test)]
pub(crate) mod tests;
