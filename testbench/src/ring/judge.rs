//! The measures and properties of a ring run (`ring_contract.md` §5): who is
//! working and reachable at the end, no partition, a single termination, and the
//! application frames some working, reachable node never received.

use super::{RingFault, RingReport, RingScenario, APP_BASE, MS};
use drcc_cosim::ring::{RingSystem, Shape};

/// The measures and properties of `ring_contract.md` §5.
pub(super) fn judge(
    s: &RingScenario,
    sys: &RingSystem,
    shape: &Shape,
    sent: &[(usize, u32, u64)],
    r: &mut RingReport,
) {
    let (n, total) = (shape.ring_nodes(), shape.nodes());
    let mut working = vec![true; total];
    let cut_section = |sec: usize, w: &mut Vec<bool>| {
        for k in 0..shape.plain[sec] {
            w[shape.plain_node(sec, k)] = false;
        }
    };
    match s.fault {
        RingFault::None => {}
        RingFault::SectionOpen { section, .. } | RingFault::SectionShort { section } => {
            cut_section(section, &mut working)
        }
        RingFault::Babbling { node } => {
            // Its relay holds it on both sections: they go with it.
            working[node] = false;
            cut_section((node + n - 1) % n, &mut working);
            cut_section(node, &mut working);
        }
        RingFault::Crash { node } => working[node] = false,
    }
    let w = sys.wiring();
    let reference = (0..n).find(|&i| working[i]).unwrap_or(0);
    let bus = w.bus_of(reference);
    r.reachable = (0..total).map(|i| w.bus_of(i) == bus).collect();
    r.no_partition = (0..total).all(|i| !working[i] || r.reachable[i]);
    r.single_termination = w.bus_shape(bus).well_formed();
    r.final_modes = (0..n).map(|i| sys.module(i).outputs.mode).collect();
    r.refused = (0..n).filter(|&i| sys.module(i).outputs.illegal).count() as u32;
    let end = sys.cycle();
    // Frames sent after the onset, early enough to be delivered by the end.
    for &(from, seq, at) in sent {
        if at < r.onset || at + 100 * MS > end || !working[from] || !r.reachable[from] {
            continue;
        }
        r.app_frames += 1;
        r.ring_app_frames += (from < n) as usize;
        let id = APP_BASE + from as u32;
        let missed = (0..total).any(|to| {
            to != from
                && working[to]
                && r.reachable[to]
                && !sys.node(to).host.received.iter().any(|x| {
                    x.frame.id == id
                        && x.frame.data[0] == (seq >> 8) as u8
                        && x.frame.data[1] == seq as u8
                })
        });
        if missed {
            r.lost.push((from, seq));
        }
    }
    r.working = working;
    r.received = (0..total)
        .map(|i| {
            sys.node(i)
                .host
                .received
                .iter()
                .map(|x| (x.cycle, x.frame))
                .collect()
        })
        .collect();
}
