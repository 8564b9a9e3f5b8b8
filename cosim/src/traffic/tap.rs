//! Taps: they watch a running system after every clock and turn what its nodes
//! deliver, the errors they detect and their fault-confinement state changes into
//! [`TrafficEvent`]s. Two taps: [`ChannelTap`] for a bus of CAN channels
//! ([`System`]), [`NodeTap`] for any system of DRCC nodes ([`NodeSystem`]: the
//! dual bus, the replicated star, the REDCAN ring). The module docs of [`super`]
//! say which signal becomes which event.
//!
//! Use: after every `step`, [`ChannelTap::observe`] (or [`NodeTap::observe`])
//! the system; [`ChannelTap::drain`] hands out the events collected since the last
//! drain, oldest first. [`ChannelTap::poll`] does both. A tap must see every clock:
//! pulses (`rx_valid`, `err_valid`) and field changes of a clock it did not see are
//! lost; a clock seen twice is counted once.

use super::error::ErrorFrame;
use super::state::Confinement;
use super::{TrafficEvent, TrafficKind};
use crate::engine::drcc::DrccOutputs;
use crate::engine::{ChannelOutputs, ControllerConfig};
use crate::host::HostDriver;
use crate::model::field;
use crate::system::{NodeSystem, Sample, System};
use drcc_hdl::host::registers::MAP;

/// Events collected and not yet drained, and the last clock seen.
#[derive(Debug, Default)]
struct Pending {
    events: Vec<TrafficEvent>,
    last_cycle: Option<u64>,
}

impl Pending {
    /// Whether `cycle` is new (and remembers it).
    fn is_new(&mut self, cycle: u64) -> bool {
        if self.last_cycle.is_some_and(|c| c >= cycle) {
            return false;
        }
        self.last_cycle = Some(cycle);
        true
    }

    fn drain(&mut self, out: &mut Vec<TrafficEvent>) {
        out.append(&mut self.events);
    }
}

/// The tap of a bus of CAN channels ([`System`]): deliveries, error frames and
/// state changes of every node, `line` always `None`.
#[derive(Debug, Default)]
pub struct ChannelTap {
    nodes: Vec<Confinement>,
    pending: Pending,
}

impl ChannelTap {
    /// A tap for a system of `nodes` channels.
    pub fn new(nodes: usize) -> Self {
        ChannelTap {
            nodes: vec![Confinement::default(); nodes],
            pending: Pending::default(),
        }
    }

    /// Takes the clock the system just made ([`System::sample`]; nothing before
    /// the first step, whose sample would carry the same cycle 0).
    pub fn observe(&mut self, sys: &System) {
        if sys.cycle() > 0 {
            self.observe_sample(sys.sample(), sys.configs());
        }
    }

    /// Takes one clock's sample (as a run's observer gets it); `configs` gives
    /// every node's error warning limit (a node without one has the default).
    pub fn observe_sample(&mut self, s: &Sample, configs: &[ControllerConfig]) {
        if !self.pending.is_new(s.cycle) {
            return;
        }
        for (node, o) in s.outputs.iter().enumerate() {
            let ewl = configs.get(node).copied().unwrap_or_default().ewl;
            if node >= self.nodes.len() {
                self.nodes.resize(node + 1, Confinement::default());
            }
            let state = &mut self.nodes[node];
            channel_events(o, ewl, state, &mut |kind| {
                self.pending.events.push(TrafficEvent {
                    cycle: s.cycle,
                    node,
                    line: None,
                    kind,
                })
            });
        }
    }

    /// Moves the events collected since the last drain to `out`, oldest first.
    pub fn drain(&mut self, out: &mut Vec<TrafficEvent>) {
        self.pending.drain(out);
    }

    /// [`ChannelTap::observe`], then [`ChannelTap::drain`].
    pub fn poll(&mut self, sys: &System, out: &mut Vec<TrafficEvent>) {
        self.observe(sys);
        self.drain(out);
    }
}

/// One channel's clock: its delivery (`rx_valid`), its captured error
/// (`err_valid`), then its state change, in that order (cause before effect).
fn channel_events(
    o: &ChannelOutputs,
    ewl: u8,
    state: &mut Confinement,
    emit: &mut dyn FnMut(TrafficKind),
) {
    if o.rx_valid {
        emit(TrafficKind::Frame(o.rx_frame));
    }
    let (p, d) = (&o.probes, &o.diag);
    if d.err_valid {
        let f = ErrorFrame::bus_error(d.err_kind, d.err_field, d.err_tx, o.tx);
        emit(TrafficKind::Error(f.with_counters(p.tec, p.rec)));
    }
    if let Some(f) = state.update(p.tec, p.rec, p.err_state, ewl) {
        emit(TrafficKind::Error(f));
    }
}

/// What a DRCC channel's probes showed at the last clock.
#[derive(Clone, Copy, Debug, Default)]
struct LineWatch {
    field: u8,
    state: Confinement,
}

/// One DRCC node: host frames handed out so far, the error warning limit its host
/// configured (read once: the `BTR` lookup is by name), and both channels.
#[derive(Clone, Copy, Debug, Default)]
struct DrccWatch {
    received: usize,
    ewl: Option<u8>,
    lines: [LineWatch; 2],
}

/// One DRCC channel's clock: an error flag that starts (the `field` probe enters
/// ERROR_FLAG; the field it left is where the error was), then a state change.
fn drcc_line_events(
    o: &DrccOutputs,
    line: u8,
    ewl: u8,
    w: &mut LineWatch,
    emit: &mut dyn FnMut(TrafficKind),
) {
    let p = &o.probes;
    let (field, tec, rec, err_state) = if line == 0 {
        (
            p.chan_a_field,
            p.chan_a_bsp_tx_err_cnt,
            p.chan_a_rec,
            p.chan_a_err_state,
        )
    } else {
        (
            p.chan_b_field,
            p.chan_b_bsp_tx_err_cnt,
            p.chan_b_rec,
            p.chan_b_err_state,
        )
    };
    let was = std::mem::replace(&mut w.field, field);
    if field == field::ERROR_FLAG && was != field::ERROR_FLAG {
        let f = ErrorFrame::unknown_bus_error(was).with_counters(tec, rec);
        emit(TrafficKind::Error(f));
    }
    if let Some(f) = w.state.update(tec, rec, err_state, ewl) {
        emit(TrafficKind::Error(f));
    }
}

/// The tap of a system of DRCC nodes ([`NodeSystem`]: the dual bus, the star,
/// the ring): the frames every host popped from its DRCC's RX FIFO (`line` = the
/// channel it came from), and per channel the error flags and state changes
/// (`line` 0 = A, 1 = B; on a replicated star A is on hub 1, B on hub 2; the
/// hubs' own traffic is not tapped, what they relay reaches the nodes).
///
/// On a REDCAN ring ([`NodeSystem::channel_b_wired`] false) every node, ring and
/// plain, is tapped in the ring's numbering (ring nodes `0..N`, then the plain
/// nodes section by section) with `line` always `None` (interface `node<i>`): a
/// ring node's channel A is its only CAN connection, on whichever section its
/// relay puts it; channel B is unwired (`rx` recessive) and, the hosts running
/// normal mode with every frame in TX queue A, never transmits, so it is not
/// watched. The relay modules have no CAN traffic.
#[derive(Debug, Default)]
pub struct NodeTap {
    /// Per DRCC node (with its host): what was already reported.
    nodes: Vec<DrccWatch>,
    pending: Pending,
    /// Only channel A is wired (the ring): events without a line, channel B
    /// not watched.
    channel_a_only: bool,
}

impl NodeTap {
    /// A tap for a system of `nodes` DRCC nodes.
    pub fn new(nodes: usize) -> Self {
        NodeTap {
            nodes: vec![DrccWatch::default(); nodes],
            pending: Pending::default(),
            channel_a_only: false,
        }
    }

    /// Takes the clock the system just made.
    pub fn observe(&mut self, sys: &impl NodeSystem) {
        let Some(cycle) = sys.cycle().checked_sub(1) else {
            return;
        };
        self.channel_a_only = !sys.channel_b_wired();
        let nodes = sys.nodes().iter().map(|n| (&n.host, &n.outputs));
        self.observe_nodes(cycle, nodes);
    }

    /// Takes the clock `cycle` of the nodes `(host, outputs)`.
    fn observe_nodes<'a>(
        &mut self,
        cycle: u64,
        nodes: impl Iterator<Item = (&'a HostDriver, &'a DrccOutputs)>,
    ) {
        if !self.pending.is_new(cycle) {
            return;
        }
        let a_only = self.channel_a_only;
        let channels = if a_only { 1 } else { 2 };
        for (node, (host, o)) in nodes.enumerate() {
            if node >= self.nodes.len() {
                self.nodes.resize(node + 1, DrccWatch::default());
            }
            let w = &mut self.nodes[node];
            let events = &mut self.pending.events;
            for rx in &host.received[w.received.min(host.received.len())..] {
                events.push(TrafficEvent {
                    cycle: rx.cycle,
                    node,
                    line: (!a_only).then_some(rx.channel),
                    kind: TrafficKind::Frame(rx.frame),
                });
            }
            w.received = host.received.len();
            let ewl = *w
                .ewl
                .get_or_insert_with(|| MAP.field("BTR", "ewl").get(host.config().btr) as u8);
            for (line, watch) in w.lines.iter_mut().enumerate().take(channels) {
                let line = line as u8;
                let tag = (!a_only).then_some(line);
                drcc_line_events(o, line, ewl, watch, &mut |kind| {
                    events.push(TrafficEvent {
                        cycle,
                        node,
                        line: tag,
                        kind,
                    })
                });
            }
        }
    }

    /// Moves the events collected since the last drain to `out`, oldest first.
    pub fn drain(&mut self, out: &mut Vec<TrafficEvent>) {
        self.pending.drain(out);
    }

    /// [`NodeTap::observe`], then [`NodeTap::drain`].
    pub fn poll(&mut self, sys: &impl NodeSystem, out: &mut Vec<TrafficEvent>) {
        self.observe(sys);
        self.drain(out);
    }
}
