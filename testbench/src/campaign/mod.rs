//! Fault campaigns (`drcc campaign`): many random fault scenarios on a topology,
//! each drawn from `(seed, index)` ([`draw`]), run ([`dual`]), and reported as one
//! JSON line: frames lost, duplicated and foreign, and lockups (nodes not back to
//! normal after the fault). Shards split the indices (`--shard i/n`: every index
//! `k` with `k mod n == i - 1`), so the union of the shards of a campaign is the
//! campaign; [`summary`] merges result files into a table per fault class.
//!
//! A single fault must lose, duplicate and lock up nothing; double faults are
//! reported, not judged.

pub mod draw;
pub mod dual;
pub mod star;
pub mod summary;
pub mod tally;

use std::io::Write;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use rayon::prelude::*;

use crate::engines::EngineKind;
pub use draw::{draw, FaultClass, ScenarioSpec, Topology};

/// What one scenario showed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Outcome {
    /// (receiver, sender, k) of frames a host never popped.
    pub lost: Vec<(usize, usize, usize)>,
    /// (receiver, sender, k) of frames a host popped once from each line.
    pub duplicated: Vec<(usize, usize, usize)>,
    /// (receiver, sender, k) of frames a host popped twice from one line: the line
    /// carried them twice (CAN's double reception).
    pub double_received: Vec<(usize, usize, usize)>,
    /// Frames popped that nobody sent.
    pub foreign: usize,
    /// Nodes not back to normal at the end.
    pub lockups: Vec<usize>,
    /// Deliveries expected (every frame to every other host).
    pub deliveries: usize,
    /// Bit times simulated.
    pub bits: u64,
}

impl Outcome {
    /// Nothing lost, duplicated by the DRCC, foreign or locked up (CAN's double
    /// reception is counted, not judged).
    pub fn clean(&self) -> bool {
        self.lost.is_empty()
            && self.duplicated.is_empty()
            && self.foreign == 0
            && self.lockups.is_empty()
    }
}

/// A campaign to run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Campaign {
    pub topology: Topology,
    /// Faults per scenario: 1 (single) or 2 (double).
    pub faults: usize,
    pub count: u64,
    pub seed: u64,
    /// `(i, n)`: this shard runs the indices `k` with `k mod n == i - 1`.
    pub shard: (u64, u64),
    pub engine: EngineKind,
}

impl Campaign {
    /// The scenario indices of this shard.
    pub fn indices(&self) -> impl Iterator<Item = u64> + '_ {
        let (i, n) = self.shard;
        (0..self.count).filter(move |k| k % n == i - 1)
    }
}

/// One scenario's result, as a JSON line.
pub fn json_line(spec: &ScenarioSpec, o: &Outcome, wall: Duration) -> String {
    let faults: Vec<serde_json::Value> = spec
        .faults
        .iter()
        .map(|f| {
            serde_json::json!({
                "class": f.class.name(),
                "line": f.line.name(),
                "node": f.node,
                "start_bit": f.start_bit,
                "bits": f.bits,
                "flips": f.flips,
            })
        })
        .collect();
    serde_json::json!({
        "topology": spec.topology.name(),
        "seed": spec.seed,
        "index": spec.index,
        "nodes": spec.nodes,
        "frames_per_node": spec.frames_per_node,
        "faults": faults,
        "deliveries": o.deliveries,
        "lost": o.lost.len(),
        "duplicated": o.duplicated.len(),
        "double_received": o.double_received.len(),
        "foreign": o.foreign,
        "lockups": o.lockups.len(),
        "bits": o.bits,
        "wall_ms": wall.as_secs_f64() * 1e3,
    })
    .to_string()
}

/// The lockups of an outcome in words: "none", or "node 2, hub 1" (on the star
/// the indices past the nodes are the hubs, hub 1 first).
pub fn describe_lockups(spec: &ScenarioSpec, o: &Outcome) -> String {
    if o.lockups.is_empty() {
        return "none".to_string();
    }
    o.lockups
        .iter()
        .map(|&i| match i.checked_sub(spec.nodes) {
            None => format!("node {i}"),
            Some(h) => format!("hub {} (a port left isolated or decoupled)", h + 1),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The replay file of a scenario (`drcc campaign replay FILE`): the topology,
/// seed and index name it; the rest says what was drawn, for a reader.
pub fn replay_file(spec: &ScenarioSpec, o: &Outcome) -> String {
    format!(
        "# drcc campaign scenario: replay it with `drcc campaign replay FILE`\n\
         # {}\n\
         # outcome: {} lost, {} duplicated, {} received twice from one line, {} foreign, \
         lockups: {}\n\
         topology = \"{}\"\n\
         faults = {}\n\
         seed = {}\n\
         index = {}\n",
        spec.describe(),
        o.lost.len(),
        o.duplicated.len(),
        o.double_received.len(),
        o.foreign,
        describe_lockups(spec, o),
        spec.topology.name(),
        spec.faults.len(),
        spec.seed,
        spec.index
    )
}

/// The fields of a replay file.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct ReplayFile {
    topology: String,
    faults: usize,
    seed: u64,
    index: u64,
}

/// Reads a replay file: (topology, faults, seed, index).
pub fn parse_replay(text: &str) -> Result<(Topology, usize, u64, u64), String> {
    let r: ReplayFile = toml::from_str(text).map_err(|e| {
        format!(
            "not a campaign replay file ({}); give one written by `drcc campaign`",
            e.message()
        )
    })?;
    let topology = Topology::from_name(&r.topology).ok_or_else(|| {
        format!(
            "unknown topology {:?}: the topologies are dual, dmr, star and ecss",
            r.topology
        )
    })?;
    if !(1..=2).contains(&r.faults) {
        return Err(format!(
            "faults = {}: a scenario has 1 or 2 faults",
            r.faults
        ));
    }
    Ok((topology, r.faults, r.seed, r.index))
}

/// Runs one scenario.
pub fn run_one(spec: &ScenarioSpec, engine: EngineKind) -> Result<Outcome, String> {
    match spec.topology {
        Topology::Dual | Topology::Dmr | Topology::Ecss => dual::run(spec, engine, |_| Ok(())),
        Topology::Star => star::run(spec, engine, |_| Ok(())),
    }
}

/// Progress of a running campaign, reported by [`run`] through `progress`.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    pub done: u64,
    pub total: u64,
    pub failed: u64,
    pub elapsed: Duration,
}

/// Runs the campaign on `jobs` threads, writing one JSON line per scenario (in
/// index order) to `out` and calling `failure` for every scenario that is not
/// clean (`faults == 1`) with its spec and outcome, and `progress` about every
/// `every`. Returns the results in index order.
pub fn run(
    c: &Campaign,
    jobs: usize,
    out: &mut dyn Write,
    mut failure: impl FnMut(&ScenarioSpec, &Outcome) -> Result<(), String>,
    progress: impl Fn(Progress) + Sync,
    every: Duration,
) -> Result<Vec<(ScenarioSpec, Outcome)>, String> {
    let indices: Vec<u64> = c.indices().collect();
    let total = indices.len() as u64;
    let done = AtomicU64::new(0);
    let failed = AtomicU64::new(0);
    let start = Instant::now();
    let last = Mutex::new(Instant::now());
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .map_err(|e| format!("cannot start {jobs} worker threads: {e}"))?;
    let results: Vec<Result<(ScenarioSpec, Outcome, Duration), String>> = pool.install(|| {
        indices
            .par_iter()
            .map(|&k| {
                let spec = draw(c.topology, c.faults, c.seed, k);
                let t = Instant::now();
                let o = run_one(&spec, c.engine)
                    .map_err(|e| format!("scenario {k} ({}): {e}", spec.describe()))?;
                let wall = t.elapsed();
                let d = done.fetch_add(1, Ordering::Relaxed) + 1;
                if !o.clean() {
                    failed.fetch_add(1, Ordering::Relaxed);
                }
                if let Ok(mut l) = last.try_lock() {
                    if l.elapsed() >= every {
                        *l = Instant::now();
                        progress(Progress {
                            done: d,
                            total,
                            failed: failed.load(Ordering::Relaxed),
                            elapsed: start.elapsed(),
                        });
                    }
                }
                Ok((spec, o, wall))
            })
            .collect()
    });
    let mut all = Vec::with_capacity(results.len());
    for r in results {
        let (spec, o, wall) = r?;
        writeln!(out, "{}", json_line(&spec, &o, wall))
            .map_err(|e| format!("cannot write the results: {e}"))?;
        if c.faults == 1 && !o.clean() {
            failure(&spec, &o)?;
        }
        all.push((spec, o));
    }
    progress(Progress {
        done: total,
        total,
        failed: failed.load(Ordering::Relaxed),
        elapsed: start.elapsed(),
    });
    Ok(all)
}
