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
            engines,
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

    /// One clock cycle for every node. Returns the new sample.
    pub fn step(&mut self) -> &Sample {
        let cycle = self.steps;
        let rst = cycle < self.reset_cycles;
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
        self.sample.rst = rst;
        self.sample.bus = line;
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
            if !rst && !tx_abort && !self.sample.outputs[i].tx_pending && !self.sample.tx_req[i] {
                if let Some(head) = self.queues[i].front() {
                    if head.due <= cycle {
                        tx_req = true;
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
            };
            let out = self.engines[i].step(&inputs);
            self.sample.tx_req[i] = tx_req;
            self.sample.tx_abort[i] = tx_abort;
            self.sample.outputs[i] = out;
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
        self.steps += 1;
        &self.sample
    }

    /// Steps until [`System::is_quiescent`] or until `max_cycles` cycles have been
    /// run in total.
    pub fn run_until_idle(&mut self, max_cycles: u64) -> RunOutcome {
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

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::bus::{FaultKind, FaultTarget};
    use crate::engine::Mode;

    /// A toy engine for testing the plumbing: a requested frame is sent as one
    /// dominant pulse of `dlc + 1` clocks once the line has been recessive for 3
    /// clocks; a receiver measures the pulse and reports a frame with that `dlc`.
    /// In listen-only mode a request is refused (`tx_failed`); `tx_abort` drops a
    /// pending frame that is not being sent (`tx_failed`).
    pub(crate) struct Ideal {
        pending: Option<Frame>,
        sending: u32,
        own: bool,
        quiet: u32,
        low_run: u32,
        out: ChannelOutputs,
    }

    impl Ideal {
        pub(crate) fn boxed() -> Box<dyn ChannelEngine> {
            Box::new(Ideal {
                pending: None,
                sending: 0,
                own: false,
                quiet: 0,
                low_run: 0,
                out: idle_outputs(),
            })
        }
    }

    impl ChannelEngine for Ideal {
        fn name(&self) -> &'static str {
            "ideal"
        }
        fn step(&mut self, i: &ChannelInputs) -> ChannelOutputs {
            let mut o = ChannelOutputs {
                tx: true,
                rx_frame: self.out.rx_frame,
                ..Default::default()
            };
            if i.rst {
                *self = Ideal {
                    pending: None,
                    sending: 0,
                    own: false,
                    quiet: 0,
                    low_run: 0,
                    out: idle_outputs(),
                };
                return self.out;
            }
            if i.tx_abort && self.pending.is_some() && self.sending == 0 {
                self.pending = None;
                o.tx_failed = true;
            }
            if i.tx_req && self.pending.is_none() {
                if i.config.mode == Mode::ListenOnly {
                    o.tx_failed = true;
                } else {
                    self.pending = Some(i.tx_frame);
                }
            }
            // Receiver: measure dominant pulses not sent by ourselves.
            if !i.rx {
                self.low_run += 1;
                self.quiet = 0;
            } else {
                if self.low_run > 0 && !self.own {
                    o.rx_valid = true;
                    o.rx_frame = Frame {
                        dlc: (self.low_run - 1) as u8,
                        ..Default::default()
                    };
                }
                if self.low_run > 0 {
                    self.own = false;
                }
                self.low_run = 0;
                self.quiet += 1;
            }
            // Transmitter.
            if let Some(f) = self.pending {
                if self.sending == 0 && self.quiet >= 3 && i.rx {
                    self.sending = f.dlc as u32 + 1;
                    self.own = true;
                }
                if self.sending > 0 {
                    o.tx = false;
                    self.sending -= 1;
                    if self.sending == 0 {
                        self.pending = None;
                        o.tx_done = true;
                    }
                }
            }
            o.tx_pending = self.pending.is_some();
            self.out = o;
            o
        }
    }

    fn frame(dlc: u8) -> Frame {
        Frame {
            id: 0x100 + dlc as u32,
            dlc,
            ..Default::default()
        }
    }

    fn system(n: usize) -> System {
        System::new(
            (0..n).map(|_| Ideal::boxed()).collect(),
            BitTiming::default(),
        )
        .unwrap()
    }

    #[test]
    fn rx_is_the_and_of_the_previous_tx() {
        let mut s = system(3);
        s.submit(1, 0, frame(4)).unwrap();
        let mut prev_tx = vec![true; 3];
        for _ in 0..60 {
            let sample = s.step().clone();
            let expect = prev_tx.iter().all(|&t| t);
            assert_eq!(sample.bus, expect, "cycle {}", sample.cycle);
            assert!(sample.rx.iter().all(|&r| r == expect));
            prev_tx = sample.outputs.iter().map(|o| o.tx).collect();
        }
    }

    #[test]
    fn frames_are_delivered_to_the_others_in_order() {
        let mut s = system(3);
        s.submit(0, 0, frame(3)).unwrap();
        s.submit(0, 0, frame(1)).unwrap();
        s.submit(2, 50, frame(5)).unwrap();
        let out = s.run_until_idle(10_000);
        assert!(out.is_idle(), "{out:?}");
        let sent: Vec<(usize, u8)> = s.tx_done().iter().map(|e| (e.node, e.frame.dlc)).collect();
        assert_eq!(sent, vec![(0, 3), (0, 1), (2, 5)]);
        let got: Vec<(usize, u8)> = s
            .deliveries()
            .iter()
            .map(|e| (e.node, e.frame.dlc))
            .collect();
        assert_eq!(got, vec![(1, 3), (2, 3), (1, 1), (2, 1), (0, 5), (1, 5)]);
        // Bus idle for 11 bits at the end.
        assert!(s.cycle() >= 11 * 8);
    }

    #[test]
    fn no_request_before_due_or_during_reset() {
        let mut s = system(2);
        s.set_reset_cycles(10);
        s.submit(0, 0, frame(0)).unwrap();
        s.submit(1, 40, frame(0)).unwrap();
        for _ in 0..100 {
            let sm = s.step();
            if sm.cycle < 10 {
                assert!(sm.rst && !sm.tx_req[0]);
            }
            if sm.tx_req[0] {
                assert_eq!(sm.cycle, 10);
            }
            if sm.tx_req[1] {
                assert!(sm.cycle >= 40);
            }
        }
        assert_eq!(s.tx_done().len(), 2);
        assert!(s.submit(2, 0, frame(0)).is_err());
    }

    #[test]
    fn queue_keeps_due_order_then_submission_order() {
        let mut s = system(2);
        s.submit(0, 100, frame(7)).unwrap();
        s.submit(0, 0, frame(2)).unwrap();
        s.submit(0, 100, frame(3)).unwrap();
        assert!(s.run_until_idle(10_000).is_idle());
        let sent: Vec<u8> = s.tx_done().iter().map(|e| e.frame.dlc).collect();
        assert_eq!(sent, vec![2, 7, 3]);
    }

    #[test]
    fn cycle_limit_and_faults() {
        let mut s = system(2);
        s.add_fault(Fault {
            target: FaultTarget::Bus,
            kind: FaultKind::StuckDominant,
            start: 20,
            cycles: 1_000_000,
        })
        .unwrap();
        s.submit(0, 0, frame(1)).unwrap();
        let out = s.run_until_idle(500);
        assert_eq!(out, RunOutcome::CycleLimit { cycle: 500 });
        assert!(!s.sample().bus);
    }

    /// Per clock: (step, config, tx_abort, tx_req) as a node was given them.
    type Seen = std::rc::Rc<std::cell::RefCell<Vec<(u64, ControllerConfig, bool, bool)>>>;

    /// Records the configuration and `tx_abort` it is given, around an `Ideal`.
    struct Spy {
        inner: Box<dyn ChannelEngine>,
        seen: Seen,
        n: u64,
    }

    impl ChannelEngine for Spy {
        fn name(&self) -> &'static str {
            "spy"
        }
        fn step(&mut self, i: &ChannelInputs) -> ChannelOutputs {
            self.seen
                .borrow_mut()
                .push((self.n, i.config, i.tx_abort, i.tx_req));
            self.n += 1;
            self.inner.step(i)
        }
    }

    #[test]
    fn config_reaches_every_node_and_failures_are_recorded() {
        let seen = Seen::default();
        let engines: Vec<Box<dyn ChannelEngine>> = vec![
            Ideal::boxed(),
            Box::new(Spy {
                inner: Ideal::boxed(),
                seen: seen.clone(),
                n: 0,
            }),
        ];
        let mut s = System::new(engines, BitTiming::default()).unwrap();
        assert_eq!(s.configs(), &[ControllerConfig::default(); 2]);
        let quiet = ControllerConfig {
            mode: Mode::ListenOnly,
            ewl: 10,
            single_shot: true,
        };
        s.set_config(ControllerConfig {
            ewl: 50,
            ..ControllerConfig::default()
        });
        s.set_node_config(1, quiet).unwrap();
        assert!(s.set_node_config(2, quiet).is_err());
        s.submit(0, 0, frame(2)).unwrap();
        s.submit(1, 0, frame(3)).unwrap();
        assert!(s.run_until_idle(10_000).is_idle());
        // Node 1 (listen-only) had its request refused: a tx_failed, nothing sent.
        let failed: Vec<(usize, u8)> = s
            .tx_failed()
            .iter()
            .map(|e| (e.node, e.frame.dlc))
            .collect();
        assert_eq!(failed, vec![(1, 3)]);
        let sent: Vec<(usize, u8)> = s.tx_done().iter().map(|e| (e.node, e.frame.dlc)).collect();
        assert_eq!(sent, vec![(0, 2)]);
        assert_eq!(s.configs()[0].ewl, 50);
        let seen = seen.borrow();
        assert!(seen.iter().all(|&(_, c, abort, _)| c == quiet && !abort));
    }

    #[test]
    fn abort_is_one_clock_after_reset_without_a_request() {
        let seen = Seen::default();
        let engines: Vec<Box<dyn ChannelEngine>> = vec![
            Ideal::boxed(),
            Box::new(Spy {
                inner: Ideal::boxed(),
                seen: seen.clone(),
                n: 0,
            }),
        ];
        let mut s = System::new(engines, BitTiming::default()).unwrap();
        // Node 0 keeps the line busy so node 1's frame stays pending for a while.
        s.submit(0, 0, frame(40)).unwrap();
        s.submit(1, 10, frame(1)).unwrap();
        s.submit(1, 12, frame(2)).unwrap();
        s.abort(1, 0).unwrap(); // during reset: raised at the first cycle after it
        s.abort(1, 20).unwrap();
        s.abort(1, 20).unwrap(); // the same cycle: one pulse
        assert!(s.abort(5, 0).is_err());
        assert!(s.run_until_idle(10_000).is_idle());
        let seen = seen.borrow();
        let aborts: Vec<u64> = seen.iter().filter(|x| x.2).map(|x| x.0).collect();
        assert_eq!(aborts, vec![DEFAULT_RESET_CYCLES, 20]);
        assert!(
            seen.iter().all(|x| !(x.2 && x.3)),
            "no request with an abort"
        );
        // The frame pending at cycle 20 (requested at cycle 10) was dropped; the
        // next one was requested after it and sent.
        let failed: Vec<(u64, u8)> = s
            .tx_failed()
            .iter()
            .map(|e| (e.cycle, e.frame.dlc))
            .collect();
        assert_eq!(failed, vec![(20, 1)]);
        let sent: Vec<(usize, u8)> = s.tx_done().iter().map(|e| (e.node, e.frame.dlc)).collect();
        assert_eq!(sent, vec![(0, 40), (1, 2)]);
    }
}
