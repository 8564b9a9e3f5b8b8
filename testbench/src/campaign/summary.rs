//! The summary of a campaign, per fault class (for double faults, per pair of
//! classes): scenarios, failing scenarios, frames lost, duplicated and foreign,
//! lockups, simulated bit times. Built from the results of a run or merged from
//! JSON-lines files (`drcc campaign merge`), which must not overlap.

use std::collections::{BTreeMap, BTreeSet};

use super::{Outcome, ScenarioSpec};

/// Totals of one fault class.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ClassTotals {
    pub scenarios: u64,
    pub failing: u64,
    pub lost: u64,
    pub duplicated: u64,
    pub double_received: u64,
    pub foreign: u64,
    pub lockups: u64,
    pub deliveries: u64,
    pub bits: u64,
}

/// A campaign summary.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Summary {
    /// Per topology and fault class.
    pub classes: BTreeMap<(String, String), ClassTotals>,
    /// Scenarios seen, as (topology, faults, seed, index), to refuse overlaps.
    seen: BTreeSet<(String, usize, u64, u64)>,
    /// Wall time of all scenarios, ms (on one core each).
    pub wall_ms: f64,
}

/// One scenario's numbers, from a run or a JSON line.
struct Row {
    topology: String,
    faults: usize,
    seed: u64,
    index: u64,
    class: String,
    lost: u64,
    duplicated: u64,
    double_received: u64,
    foreign: u64,
    lockups: u64,
    deliveries: u64,
    bits: u64,
    wall_ms: f64,
}

fn class_key(mut names: Vec<String>) -> String {
    names.sort();
    names.join(" + ")
}

impl Summary {
    fn add(&mut self, r: Row) -> Result<(), String> {
        if !self
            .seen
            .insert((r.topology.clone(), r.faults, r.seed, r.index))
        {
            return Err(format!(
                "scenario {} of the {} campaign with seed {} ({} fault(s)) appears twice: \
                 merge result files of different shards or seeds only",
                r.index, r.topology, r.seed, r.faults
            ));
        }
        let t = self.classes.entry((r.topology, r.class)).or_default();
        t.scenarios += 1;
        let bad = r.lost + r.duplicated + r.foreign + r.lockups > 0;
        t.failing += bad as u64;
        t.lost += r.lost;
        t.duplicated += r.duplicated;
        t.double_received += r.double_received;
        t.foreign += r.foreign;
        t.lockups += r.lockups;
        t.deliveries += r.deliveries;
        t.bits += r.bits;
        self.wall_ms += r.wall_ms;
        Ok(())
    }

    /// Adds the results of a run.
    pub fn add_results(&mut self, results: &[(ScenarioSpec, Outcome)]) -> Result<(), String> {
        for (s, o) in results {
            self.add(Row {
                topology: s.topology.name().to_string(),
                faults: s.faults.len(),
                seed: s.seed,
                index: s.index,
                class: class_key(
                    s.faults
                        .iter()
                        .map(|f| f.class.name().to_string())
                        .collect(),
                ),
                lost: o.lost.len() as u64,
                duplicated: o.duplicated.len() as u64,
                double_received: o.double_received.len() as u64,
                foreign: o.foreign as u64,
                lockups: o.lockups.len() as u64,
                deliveries: o.deliveries as u64,
                bits: o.bits,
                wall_ms: 0.0,
            })?;
        }
        Ok(())
    }

    /// Adds the JSON lines of a result file (`name` names it in errors).
    pub fn add_jsonl(&mut self, name: &str, text: &str) -> Result<(), String> {
        for (i, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let at = || format!("{name}:{}", i + 1);
            let v: serde_json::Value = serde_json::from_str(line).map_err(|e| {
                format!("{}: not a campaign result line ({e}); give files written by `drcc campaign --out`", at())
            })?;
            let num = |k: &str| -> Result<u64, String> {
                v.get(k)
                    .and_then(serde_json::Value::as_u64)
                    .ok_or_else(|| format!("{}: no number `{k}`: not a campaign result line", at()))
            };
            let faults = v
                .get("faults")
                .and_then(serde_json::Value::as_array)
                .ok_or_else(|| format!("{}: no `faults` list: not a campaign result line", at()))?;
            let classes = faults
                .iter()
                .map(|f| {
                    f.get("class")
                        .and_then(serde_json::Value::as_str)
                        .map(str::to_string)
                        .ok_or_else(|| format!("{}: a fault without `class`", at()))
                })
                .collect::<Result<Vec<_>, _>>()?;
            self.add(Row {
                topology: v
                    .get("topology")
                    .and_then(serde_json::Value::as_str)
                    .ok_or_else(|| format!("{}: no `topology`", at()))?
                    .to_string(),
                faults: faults.len(),
                seed: num("seed")?,
                index: num("index")?,
                class: class_key(classes),
                lost: num("lost")?,
                duplicated: num("duplicated")?,
                double_received: num("double_received")?,
                foreign: num("foreign")?,
                lockups: num("lockups")?,
                deliveries: num("deliveries")?,
                bits: num("bits")?,
                wall_ms: v
                    .get("wall_ms")
                    .and_then(serde_json::Value::as_f64)
                    .unwrap_or(0.0),
            })?;
        }
        Ok(())
    }

    /// Scenarios in total.
    pub fn scenarios(&self) -> u64 {
        self.classes.values().map(|t| t.scenarios).sum()
    }

    /// Failing scenarios in total.
    pub fn failing(&self) -> u64 {
        self.classes.values().map(|t| t.failing).sum()
    }

    /// The Markdown table.
    pub fn table(&self) -> String {
        let mut s = String::from(
            "| topology | fault class | scenarios | failing | frames lost | duplicated | received twice from one line (CAN) | foreign | lockups | deliveries | bit times |\n\
             |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
        );
        let mut total = ClassTotals::default();
        for ((topo, class), t) in &self.classes {
            s.push_str(&format!(
                "| {topo} | {class} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                t.scenarios,
                t.failing,
                t.lost,
                t.duplicated,
                t.double_received,
                t.foreign,
                t.lockups,
                t.deliveries,
                t.bits
            ));
            total.scenarios += t.scenarios;
            total.failing += t.failing;
            total.lost += t.lost;
            total.duplicated += t.duplicated;
            total.double_received += t.double_received;
            total.foreign += t.foreign;
            total.lockups += t.lockups;
            total.deliveries += t.deliveries;
            total.bits += t.bits;
        }
        s.push_str(&format!(
            "| all | | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            total.scenarios,
            total.failing,
            total.lost,
            total.duplicated,
            total.double_received,
            total.foreign,
            total.lockups,
            total.deliveries,
            total.bits
        ));
        s
    }
}
