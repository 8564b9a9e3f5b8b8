//! `drcc ring`: REDCAN rings of DRCC nodes (seed 000) running the centralized
//! algorithm on a CanKingdom King (seed 002): `table` (every single fault at every
//! position on rings of `--nodes` sizes, as Markdown) or one fault
//! (`no_fault`, `section_open`, `section_short`, `babbling_idiot`, `node_crash`)
//! at `--position` on a ring of the first size. `table --markdown` also rewrites
//! the table between the `ring-table` markers of docs/redcan.md. A fault can run
//! again on a second engine in lock step (`--cosim`, `drcc_testbench::ring::lockstep`)
//! and export its traffic (`--candump`, `--pcap`: the `--engine` run's, through
//! `NodeTap`); `table` refuses all three.

use super::traffic::{check_owned, TrafficArgs, TrafficFiles};
use super::{project_root, rewrite_between_atomic, CliError, CliResult};
use drcc_cosim::ring::RingSystem;
use drcc_cosim::traffic::NodeTap;
use drcc_testbench::ring::lockstep::run_lockstep;
use drcc_testbench::ring::table::{fault_from_name, ring_table, row, RingTable, HEADER};
use drcc_testbench::ring::{run_observed, Algorithm, RingScenario, CLOCK_HZ};
use drcc_testbench::EngineKind;

/// Ring sizes from `3,6,10`: each 3..=10.
fn sizes(list: &str) -> Result<Vec<usize>, CliError> {
    let v: Result<Vec<usize>, _> = list.split(',').map(|s| s.trim().parse::<usize>()).collect();
    match v {
        Ok(v) if !v.is_empty() && v.iter().all(|n| (3..=10).contains(n)) => Ok(v),
        _ => Err(CliError::Error(format!(
            "--nodes {list:?}: give ring sizes of 3..=10 ring nodes, comma-separated (e.g. 3,6,10)"
        ))),
    }
}

/// The options of `drcc ring`.
#[derive(Clone, Copy, Debug)]
pub struct RingArgs<'a> {
    /// `table` or a fault name.
    pub what: &'a str,
    /// `--nodes`: ring sizes, comma-separated.
    pub nodes: &'a str,
    /// `--position`: the faulty section or ring node.
    pub position: usize,
    /// `--engine`.
    pub engine: &'a str,
    /// `--algorithm`: centralized, distributed or both.
    pub algorithm: &'a str,
    /// `--markdown` (with `table`).
    pub markdown: bool,
    /// `--cosim`: the second engine of a lock-step run.
    pub cosim: Option<&'a str>,
    /// `--candump`, `--pcap`.
    pub traffic: &'a TrafficArgs,
}

/// The engine named by option `opt`: model or verilator.
fn ring_engine(name: &str, opt: &str) -> Result<EngineKind, CliError> {
    let kind = name.parse::<EngineKind>().map_err(CliError::Error)?;
    if kind == EngineKind::RustHdl {
        return Err(CliError::Error(format!(
            "a ring runs DRCC nodes on the model or verilator engines: use {opt} model or verilator"
        )));
    }
    Ok(kind)
}

/// Runs `a.what` (see the module docs).
pub fn run_ring(a: &RingArgs) -> CliResult {
    let RingArgs {
        what,
        nodes,
        position,
        engine: engine_name,
        algorithm,
        markdown,
        cosim,
        traffic,
    } = *a;
    let kind = ring_engine(engine_name, "--engine")?;
    let other = cosim.map(|c| ring_engine(c, "--cosim")).transpose()?;
    let sizes = sizes(nodes)?;
    let algorithms = match algorithm {
        "both" => vec![Algorithm::Centralized, Algorithm::Distributed],
        "centralized" => vec![Algorithm::Centralized],
        "distributed" => vec![Algorithm::Distributed],
        other => {
            return Err(CliError::Error(format!(
                "--algorithm {other:?}: give centralized, distributed or both"
            )))
        }
    };
    if markdown && what != "table" {
        return Err(CliError::Error(
            "--markdown rewrites the fault table: use it with `drcc ring table`".to_string(),
        ));
    }
    if what == "table" {
        if let Some(c) = cosim {
            return Err(CliError::Error(format!(
                "--cosim {c}: `table` runs many scenarios on one engine; give one fault to \
                 compare in lock step (e.g. `drcc ring section_short --cosim {c}`)"
            )));
        }
        traffic.refuse(what, "one fault")?;
        let root = match markdown {
            true => Some(project_root(
                ", or leave out --markdown to print the table only",
            )?),
            false => None,
        };
        let RingTable {
            text: table,
            broken,
        } = ring_table(&sizes, &algorithms, kind).map_err(CliError::Error)?;
        print!("{table}");
        if !broken.is_empty() {
            return Err(CliError::Failed(format!(
                "{} row(s) end partitioned or badly terminated: {}; the files were not changed",
                broken.len(),
                broken.join("; ")
            )));
        }
        if let Some(root) = root {
            let paths = [root.join("docs/redcan.md")];
            rewrite_between_atomic(&paths, TABLE_BEGIN, TABLE_END, &table)?;
            for p in &paths {
                println!("wrote the table in {}", p.display());
            }
        }
        return Ok(());
    }
    let n = sizes[0];
    let fault = fault_from_name(what, position).map_err(CliError::Error)?;
    let s = match algorithms[0] {
        Algorithm::Centralized => RingScenario::standard(n, fault),
        Algorithm::Distributed => RingScenario::distributed(n, fault),
    };
    check_owned(&traffic.owned_outputs())?;
    let mut files = TrafficFiles::create(traffic, CLOCK_HZ)?;
    let mut tap = NodeTap::new(n * (1 + s.plain_per_section));
    let observe = |sys: &RingSystem| files.take(|out| tap.poll(sys, out));
    let (r, lockstep) = match other {
        None => (run_observed(&s, kind, observe), None),
        Some(o) => match run_lockstep(&s, kind, o, observe) {
            Ok(l) => (Ok(l.report), Some((o, l.clocks, l.divergence))),
            Err(e) => (Err(e), None),
        },
    };
    let r = r.map_err(CliError::Error)?;
    for (_, p) in files.commit()? {
        println!("wrote {}", p.display());
    }
    print!("{HEADER}{}", row(&s, &r));
    if let Some((o, clocks, divergence)) = lockstep {
        if let Some(d) = divergence {
            return Err(CliError::Failed(d.to_string()));
        }
        println!(
            "no divergence between {kind} and {o} in {clocks} clocks (every input and output \
             of every DRCC node and every relay module output, every clock)"
        );
    }
    if !(r.no_partition && r.single_termination) {
        return Err(CliError::Failed(format!(
            "{what} at {}: the ring ended partitioned or badly terminated",
            fault.position()
        )));
    }
    Ok(())
}

const TABLE_BEGIN: &str = "<!-- ring-table:begin (generated by `drcc ring table`) -->";
const TABLE_END: &str = "<!-- ring-table:end -->";
