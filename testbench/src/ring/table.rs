//! The REDCAN fault table (`drcc ring table`): per fault kind and position, on
//! rings of several sizes, the time to detection and to the rebuilt bus, the
//! frames lost meanwhile, who is reachable afterwards and the two properties of
//! `ring_contract.md` §5, beside the paper's figures (seed 000 §3: T1 = 30 ms,
//! T2 = 500 ms, recovery "at maximum 1 s").

use super::{run, Algorithm, RingFault, RingReport, RingScenario, CLOCKS_PER_BIT};
use crate::engines::EngineKind;
use rayon::prelude::*;

/// Every single fault of §3 at every position of an `n`-node ring; node faults of
/// ring node 0 only with `master_too` (the centralized algorithm's master: the
/// paper leaves its replacement open).
pub fn faults(n: usize, master_too: bool) -> Vec<RingFault> {
    let mut v = vec![RingFault::None];
    for s in 0..n {
        v.push(RingFault::SectionOpen {
            section: s,
            point: 1,
        });
        v.push(RingFault::SectionShort { section: s });
    }
    for i in (if master_too { 0 } else { 1 })..n {
        v.push(RingFault::Babbling { node: i });
        v.push(RingFault::Crash { node: i });
    }
    v
}

/// A fault by CLI name and position (section or ring node index).
pub fn fault_from_name(name: &str, position: usize) -> Result<RingFault, String> {
    Ok(match name {
        "no_fault" => RingFault::None,
        "section_open" => RingFault::SectionOpen {
            section: position,
            point: 1,
        },
        "section_short" => RingFault::SectionShort { section: position },
        "babbling_idiot" => RingFault::Babbling { node: position },
        "node_crash" => RingFault::Crash { node: position },
        other => {
            return Err(format!(
                "unknown ring fault {other:?}: give table, no_fault, section_open, section_short, babbling_idiot or node_crash"
            ))
        }
    })
}

fn ms(us: u64) -> String {
    format!("{} ({:.1} ms)", us / CLOCKS_PER_BIT, us as f64 / 1000.0)
}

/// The header of the table.
pub const HEADER: &str = "| algorithm | ring nodes | fault | position | detection: bit times (ms) | rebuilt: bit times (ms) | ring nodes' frames lost (of sent) | plain nodes' frames lost (of sent) | resent | reachable afterwards | no partition | single termination | paper (seed 000 §3) |\n|---|---:|---|---|---|---|---:|---:|---:|---|---|---|---|\n";

/// One row.
pub fn row(s: &RingScenario, r: &RingReport) -> String {
    let det = r.detected.map_or("-".into(), |(_, t)| ms(t - r.onset));
    let rebuilt = r.last_relay_change.map_or("-".into(), |t| ms(t - r.onset));
    let reach: Vec<String> = r
        .reachable
        .iter()
        .enumerate()
        .filter(|&(i, &x)| x && r.working[i])
        .map(|(i, _)| i.to_string())
        .collect();
    let yes = |b: bool| if b { "yes" } else { "**no**" };
    let ring_lost = r
        .lost
        .iter()
        .filter(|&&(from, _)| from < s.ring_nodes)
        .count();
    format!(
        "| {} | {} | {} | {} | {} | {} | {} of {} | {} of {} | {} | {} of {} working: {} | {} | {} | T1 30 ms, T2 500 ms, recovery <= ~1 s |\n",
        match s.algorithm {
            Algorithm::Centralized => "centralized",
            Algorithm::Distributed => "distributed",
        },
        s.ring_nodes,
        s.fault.kind_name(),
        s.fault.position(),
        det,
        rebuilt,
        ring_lost,
        r.ring_app_frames,
        r.lost.len() - ring_lost,
        r.app_frames - r.ring_app_frames,
        r.resent,
        reach.len(),
        r.working.iter().filter(|&&w| w).count(),
        reach.join(" "),
        yes(r.no_partition),
        yes(r.single_termination),
    )
}

/// The table for rings of `sizes` ring nodes, rows run in parallel, with the rows
/// that break a property; an error if a run cannot be made.
pub fn ring_table(
    sizes: &[usize],
    algorithms: &[Algorithm],
    kind: EngineKind,
) -> Result<RingTable, String> {
    let scenarios: Vec<RingScenario> = algorithms
        .iter()
        .flat_map(|&a| {
            sizes.iter().flat_map(move |&n| {
                faults(n, a == Algorithm::Distributed)
                    .into_iter()
                    .map(move |f| match a {
                        Algorithm::Centralized => RingScenario::standard(n, f),
                        Algorithm::Distributed => RingScenario::distributed(n, f),
                    })
            })
        })
        .collect();
    let reports: Vec<Result<RingReport, String>> =
        scenarios.par_iter().map(|s| run(s, kind)).collect();
    let mut out = String::from(HEADER);
    let mut broken = Vec::new();
    for (s, r) in scenarios.iter().zip(reports) {
        let r = r?;
        if !(r.no_partition && r.single_termination) {
            broken.push(format!("{} ring nodes, {:?}", s.ring_nodes, s.fault));
        }
        out.push_str(&row(s, &r));
    }
    Ok(RingTable { text: out, broken })
}

/// The table of [`ring_table`] and the rows that ended partitioned or badly
/// terminated (a check failure, not an error).
#[derive(Clone, Debug)]
pub struct RingTable {
    /// The Markdown table.
    pub text: String,
    /// `"N ring nodes, FAULT"` of every row that ended partitioned or badly terminated.
    pub broken: Vec<String>,
}
