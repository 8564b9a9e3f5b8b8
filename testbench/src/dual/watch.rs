//! What a dual-bus fault run measures: channel A on every node, clock by clock
//! (when its auxiliary FSM failed it, when the node came back to A, its frames
//! on A after the fault), and the tally of the hosts' deliveries at the end.

use super::*;

/// What the dual-bus run follows of channel A on every node, clock by clock:
/// when its auxiliary FSM failed it, when the node came back to A, and the
/// frames it sent on A after the fault.
pub(super) struct ChannelAWatch {
    prev_state: Vec<u8>,
    prev_aux: Vec<u8>,
    awaiting_return: Vec<bool>,
    counted_frame: Vec<bool>,
}

impl ChannelAWatch {
    pub(super) fn new(nodes: usize) -> Self {
        ChannelAWatch {
            prev_state: vec![0; nodes],
            prev_aux: vec![0; nodes],
            awaiting_return: vec![false; nodes],
            counted_frame: vec![false; nodes],
        }
    }

    /// The probes of every node of `main` after clock `cycle`, into `report`.
    pub(super) fn sample(
        &mut self,
        main: &DualBusSystem,
        cycle: u64,
        fault_end: u64,
        report: &mut DualReport,
    ) {
        for (i, n) in main.nodes().iter().enumerate() {
            let p = &n.outputs.probes;
            if report.first_aux_failure.is_none() && p.aux_a_state != 0 {
                report.first_aux_failure = Some(cycle);
            }
            if p.aux_a_state != 0 {
                report.a_failed[i] = true;
                report.back_on_a[i] = None;
                self.awaiting_return[i] = false;
            } else if self.prev_aux[i] != 0 {
                self.awaiting_return[i] = true;
            }
            self.prev_aux[i] = p.aux_a_state;
            if self.awaiting_return[i] && self.prev_state[i] == 9 && p.state == 0 {
                report.back_on_a[i] = Some(cycle);
                self.awaiting_return[i] = false;
            }
            self.prev_state[i] = p.state;
            // Transmitter on A: a dominant bit of its own in a data field.
            if p.chan_a_field == FIELD_DATA && !n.outputs.chan_a_tx {
                if !self.counted_frame[i] && report.back_on_a[i].is_some() && cycle >= fault_end {
                    report.a_frames_after[i] += 1;
                }
                self.counted_frame[i] = true;
            } else if p.chan_a_field != FIELD_DATA {
                self.counted_frame[i] = false;
            }
        }
    }
}

pub(super) fn tally(s: &DualScenario, sys: &DualBusSystem, r: &mut DualReport) {
    r.submitted = s.nodes * s.frames_per_node;
    for (rx_node, n) in sys.nodes().iter().enumerate() {
        let received = n.host.received.iter().map(|got| got.frame);
        let d = Deliveries::count(
            received,
            s.nodes,
            s.frames_per_node,
            |_| false,
            DualScenario::frame,
        );
        r.foreign += d.foreign;
        r.delivered += n.host.received.len();
        d.judge(rx_node, |_, _| true, &mut r.missing, &mut r.duplicates);
        let reads = &n.host.reads;
        let get = |idx: usize| reads.get(idx).map(|x| x.value).unwrap_or(0);
        r.aux_a_during.push(get(0));
        r.status_during.push(get(1));
        r.status_end.push(get(2));
        r.aux_a_end.push(get(3));
        r.stats0_end.push(get(4));
    }
}
