//! What a campaign scenario showed, from the hosts' point of view, on any topology
//! of DRCC nodes: frames lost (a host never popped another host's frame),
//! duplicated (popped once from each channel) or foreign (popped but never sent),
//! CAN's own double reception counted apart, and nodes not back to normal.

use drcc_cosim::engine::drcc::DrccOutputs;
use drcc_cosim::host::HostDriver;
use drcc_cosim::model::field;
use drcc_cosim::system::NodeSystem;

use super::dual::{frame, frames};
use super::{Outcome, ScenarioSpec, Topology};

/// Submits the drawn traffic of `spec` to every host: the drawn frames, then the
/// tail frames from bit time `tail_start`, one every `tail_period` bit times.
pub fn submit_traffic(
    spec: &ScenarioSpec,
    sys: &mut impl NodeSystem,
    tail_start: u64,
    tail_period: u64,
    clocks_per_bit: u64,
) {
    for n in 0..spec.nodes {
        for k in 0..frames(spec) {
            let due = match k.checked_sub(spec.frames_per_node) {
                None => 100 + k as u64 * spec.period_bits + spec.jitter[n][k],
                Some(j) => tail_start + j as u64 * tail_period + n as u64 * 37,
            };
            sys.host_mut(n)
                .submit(due * clocks_per_bit, frame(spec, n, k), 0);
        }
    }
}

/// Runs `sys` to clock `end` (`observe` sees it after every clock) and tallies the
/// hosts' deliveries.
pub fn run_and_tally<S: NodeSystem>(
    spec: &ScenarioSpec,
    sys: &mut S,
    end: u64,
    clocks_per_bit: u64,
    mut observe: impl FnMut(&S) -> Result<(), String>,
) -> Result<Outcome, String> {
    let mut overloads = LineEvents::new(spec.nodes);
    while sys.cycle() < end {
        sys.step();
        let cycle = sys.cycle();
        for n in 0..spec.nodes {
            overloads.observe(n, sys.outputs(n), cycle);
        }
        observe(sys)?;
    }
    // the first `spec.nodes` are the scenario's nodes (a monitor may follow)
    Ok(tally(
        spec,
        frames(spec),
        &sys.views()[..spec.nodes],
        &overloads,
        sys.cycle(),
        clocks_per_bit,
    ))
}

/// What the campaign watches on every node's two channels (field probes) to tell
/// CAN's own double reception, which no controller can avoid, from a duplicate the
/// DRCC should have removed.
///
/// - `overload`: the channel, as receiver, met a dominant last EOF bit (its `field`
///   goes EOF -> overload flag): it had taken the frame, and the transmitter sends
///   it again (ISO 11898-1 double reception).
/// - `accepted`: the channel completed an EOF (EOF -> intermission): it took the
///   frame on the line.
/// - `late_error`: the channel started an error flag from the ACK slot, the ACK
///   delimiter or the EOF (an ACK or form error), while its node's main FSM was
///   using that line (Table 1 states ch1/abort1/wait2 for A, ch2/abort2/wait4 for
///   B): as transmitter, it will repeat a frame that receivers it could not reach
///   may already have taken (an inconsistent message duplicate: campaign finding
///   `dual-s5-i2237`, a line cut in the ACK slot).
#[derive(Clone, Debug)]
pub struct LineEvents {
    prev: Vec<[u8; 2]>,
    overload: Vec<[Vec<u64>; 2]>,
    accepted: Vec<[Vec<u64>; 2]>,
    late_error: Vec<[Vec<u64>; 2]>,
}

impl LineEvents {
    pub fn new(nodes: usize) -> Self {
        let lists = vec![[Vec::new(), Vec::new()]; nodes];
        LineEvents {
            prev: vec![[0; 2]; nodes],
            overload: lists.clone(),
            accepted: lists.clone(),
            late_error: lists,
        }
    }

    /// Watches node `n`'s channel fields after the edge of clock `cycle`.
    pub fn observe(&mut self, n: usize, o: &DrccOutputs, cycle: u64) {
        let p = &o.probes;
        let on_line = [matches!(p.state, 2..=4), matches!(p.state, 7..=9)];
        for (l, f) in [p.chan_a_field, p.chan_b_field].into_iter().enumerate() {
            let before = self.prev[n][l];
            if before != f {
                if before == field::EOF && f == field::OVERLOAD_FLAG {
                    self.overload[n][l].push(cycle);
                }
                if before == field::EOF && f == field::INTERMISSION {
                    self.accepted[n][l].push(cycle);
                }
                if matches!(before, field::ACK_SLOT | field::ACK_DELIM | field::EOF)
                    && f == field::ERROR_FLAG
                    && on_line[l]
                {
                    self.late_error[n][l].push(cycle);
                }
            }
            self.prev[n][l] = f;
        }
    }

    /// Receiver `rx` took a frame on `line` in `[from, to]` while the frame's
    /// sender, using that line, raised a late error flag (at most 12 bit times
    /// before): the line will carry that frame again.
    fn inconsistent_on(
        &self,
        rx: usize,
        sender: usize,
        line: usize,
        from: u64,
        to: u64,
        cpb: u64,
    ) -> bool {
        self.accepted[rx][line]
            .iter()
            .filter(|&&c| c >= from && c <= to)
            .any(|&c| {
                self.late_error[sender][line]
                    .iter()
                    .any(|&e| e <= c && e + 12 * cpb >= c)
            })
    }
}

/// The node is back to normal: both auxiliary FSMs judge their channel valid,
/// neither channel is bus-off, and the main FSM is on channel A (Table 1 states
/// idle1 0 .. wait2 4). A channel may still be error passive: ISO 11898-1 lowers
/// TEC by one per successful transmission, so a transmitter that reached TEC 200
/// needs over 70 frames to be error active again, which is CAN's rule, not a lockup.
pub fn node_normal(o: &DrccOutputs) -> bool {
    let p = &o.probes;
    p.aux_a_state == 0
        && p.aux_b_state == 0
        && p.chan_a_err_state != 2
        && p.chan_b_err_state != 2
        && p.state <= 4
}

/// A node in DMR mode is back to normal: "redundancy active" (no fault flag on
/// either line, DMR contract §6) and neither channel bus-off.
pub fn dmr_normal(o: &DrccOutputs) -> bool {
    let p = &o.probes;
    p.dmr_state == 0 && p.chan_a_err_state != 2 && p.chan_b_err_state != 2
}

/// Tallies the deliveries of every node (`nodes[i]`: its host and outputs at the
/// end), `frames` per sender, over `cycles` clocks of `clocks_per_bit`.
pub fn tally(
    spec: &ScenarioSpec,
    frames: usize,
    nodes: &[(&HostDriver, &DrccOutputs)],
    overloads: &LineEvents,
    cycles: u64,
    clocks_per_bit: u64,
) -> Outcome {
    let mut o = Outcome {
        bits: cycles / clocks_per_bit,
        ..Outcome::default()
    };
    for (rx_node, (host, outputs)) in nodes.iter().enumerate() {
        // per (sender, k): (channel, clock) of every delivery
        let mut seen: Vec<Vec<Vec<(u8, u64)>>> = vec![vec![Vec::new(); frames]; spec.nodes];
        for got in &host.received {
            let f = got.frame;
            if spec.topology == Topology::Ecss && f.id == crate::ecss::HB_ID as u32 {
                continue; // the master's heartbeat, not traffic
            }
            let (sender, k) = (f.data[0] as usize, f.data[1] as usize);
            if sender < spec.nodes && k < frames && f == frame(spec, sender, k) {
                seen[sender][k].push((got.channel, got.cycle));
            } else {
                o.foreign += 1;
            }
        }
        // A second copy from the other channel is CAN's double reception too when
        // that channel carried the frame twice: this receiver met a dominant last
        // EOF bit on it between the two deliveries (its first copy there
        // cancelled the other channel's; the retransmission found none).
        // Or the line carried it twice because its transmitter, cut off from
        // this receiver, saw an error after this receiver had taken it
        // ([`LineEvents`]): an inconsistent message duplicate, also CAN's own.
        let twice_on = |line: u8, sender: usize, from: u64, to: u64| {
            overloads.overload[rx_node][line as usize]
                .iter()
                .any(|&c| c + 200 * clocks_per_bit >= from && c <= to)
                || overloads.inconsistent_on(
                    rx_node,
                    sender,
                    line as usize,
                    from.saturating_sub(300 * clocks_per_bit),
                    to,
                    clocks_per_bit,
                )
        };
        for (sender, frames) in seen.iter().enumerate() {
            if sender == rx_node {
                continue;
            }
            for (k, channels) in frames.iter().enumerate() {
                o.deliveries += 1;
                let on = |c: u8| channels.iter().filter(|d| d.0 == c).count();
                match channels.as_slice() {
                    [] => o.lost.push((rx_node, sender, k)),
                    [_] => {}
                    // Every frame is submitted once: a repeat from one channel is
                    // that channel carrying it twice (CAN's double reception).
                    _ if on(0) > 1 || on(1) > 1 => o.double_received.push((rx_node, sender, k)),
                    [(_, t0), (l1, t1)] if twice_on(*l1, sender, *t0, *t1) => {
                        o.double_received.push((rx_node, sender, k))
                    }
                    _ => o.duplicated.push((rx_node, sender, k)),
                }
            }
        }
        let normal = match spec.topology {
            Topology::Dmr => dmr_normal(outputs),
            _ => node_normal(outputs),
        };
        if !normal {
            o.lockups.push(rx_node);
        }
    }
    o
}
