//! `drcc campaign`: random fault campaigns (`drcc_testbench::campaign`).
//!
//! - `drcc campaign [--topology dual|dmr|star|ecss] [--faults single|double] [--count N] [--seed S]
//!   [--shard i/n] [--jobs J] [--out FILE] [--engine E]` runs the scenarios of one
//!   shard, writes one JSON line per scenario to `FILE` (never over an existing
//!   file), writes a replay file for every failing single-fault scenario into
//!   `FILE.failures/` (or `campaign-failures/` without `--out`), and prints the
//!   summary per fault class. Exit 1 if a single-fault scenario lost, duplicated or
//!   locked up anything; double faults are reported, not judged.
//! - `drcc campaign merge FILE...` prints the summary of result files (shards).
//! - `drcc campaign replay FILE` runs one scenario again from its replay file.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::time::Duration;

use drcc_testbench::campaign::summary::Summary;
use drcc_testbench::campaign::{self, draw, Campaign, Progress, Topology};
use drcc_testbench::engines::available;
use drcc_testbench::EngineKind;

use super::{write_atomic, AtomicFile, CliError, CliResult};

/// The options of `drcc campaign`.
#[derive(Debug, Default)]
pub struct CampaignArgs<'a> {
    pub args: &'a [String],
    pub topology: &'a str,
    pub faults: &'a str,
    pub count: u64,
    pub seed: u64,
    pub shard: Option<&'a str>,
    pub jobs: Option<usize>,
    pub out: Option<&'a Path>,
    pub engine: &'a str,
}

fn error(m: String) -> CliError {
    CliError::Error(m)
}

/// The largest campaign one command runs (a shard of a bigger one is fine).
const MAX_COUNT: u64 = 100_000_000;

/// Checks the options of a run.
pub fn parse(a: &CampaignArgs) -> Result<Campaign, CliError> {
    let topology = Topology::from_name(a.topology).ok_or_else(|| {
        error(format!(
            "--topology {}: the topologies are dual, dmr, star and ecss",
            a.topology
        ))
    })?;
    let faults = match a.faults {
        "single" => 1,
        "double" => 2,
        other => {
            return Err(error(format!(
                "--faults {other}: give single (judged: nothing may be lost) or double (reported)"
            )))
        }
    };
    if !(1..=MAX_COUNT).contains(&a.count) {
        return Err(error(format!(
            "--count {}: give 1 .. {MAX_COUNT} scenarios (split a larger campaign into seeds)",
            a.count
        )));
    }
    let shard = match a.shard {
        None => (1, 1),
        Some(s) => {
            let parsed = s
                .split_once('/')
                .and_then(|(i, n)| Some((i.parse::<u64>().ok()?, n.parse::<u64>().ok()?)));
            match parsed {
                Some((i, n)) if n >= 1 && (1..=n).contains(&i) => (i, n),
                _ => {
                    return Err(error(format!(
                        "--shard {s}: give i/n with 1 <= i <= n, e.g. --shard 3/8 (shard 3 of 8)"
                    )))
                }
            }
        }
    };
    let engine = a.engine.parse::<EngineKind>().map_err(error)?;
    if engine == EngineKind::RustHdl {
        return Err(error(
            "--engine rust-hdl: the DRCC runs campaigns on model or verilator (rust-hdl's \
             simulator is too slow for networks)"
                .to_string(),
        ));
    }
    if let Some(0) | Some(257..) = a.jobs {
        return Err(error(format!(
            "--jobs {}: give 1 .. 256 worker threads (default: every core)",
            a.jobs.unwrap_or(0)
        )));
    }
    Ok(Campaign {
        topology,
        faults,
        count: a.count,
        seed: a.seed,
        shard,
        engine,
    })
}

/// Runs `drcc campaign` (see the module docs).
pub fn run(a: &CampaignArgs) -> CliResult {
    match a.args.first().map(String::as_str) {
        None => run_campaign(a),
        Some("merge") => merge(&a.args[1..]),
        Some("replay") => match &a.args[1..] {
            [file] => replay(Path::new(file), a.engine),
            _ => Err(error(
                "campaign replay: give one replay file (written for a failing scenario)"
                    .to_string(),
            )),
        },
        Some(other) => Err(error(format!(
            "campaign {other}: give no action (run a campaign), `merge FILE...` or `replay FILE`"
        ))),
    }
}

fn run_campaign(a: &CampaignArgs) -> CliResult {
    let c = parse(a)?;
    available(c.engine).map_err(error)?;
    let jobs = a.jobs.unwrap_or_else(|| {
        std::thread::available_parallelism()
            .map(|n| n.get())
            .unwrap_or(1)
    });
    // Results are never written over an existing file; they go to a temporary
    // file and replace nothing until the campaign is done.
    let mut out = match a.out {
        Some(p) if p.exists() => {
            return Err(error(format!(
                "--out {}: the file exists; give a new file name (campaign results are never \
                 overwritten)",
                p.display()
            )))
        }
        Some(p) => Some(AtomicFile::create(p)?),
        None => None,
    };
    let fail_dir = match a.out {
        Some(p) => PathBuf::from(format!("{}.failures", p.display())),
        None => PathBuf::from("campaign-failures"),
    };
    let shard_count = c.indices().count();
    eprintln!(
        "drcc campaign: {} {} fault(s), seed {}, scenarios {} of {} (shard {}/{}), {} on {jobs} thread(s)",
        c.topology.name(),
        if c.faults == 1 { "single" } else { "double" },
        c.seed,
        shard_count,
        c.count,
        c.shard.0,
        c.shard.1,
        c.engine.name()
    );
    let tty = std::io::stderr().is_terminal();
    let progress = |p: Progress| report_progress(p, tty);
    let every = if tty {
        Duration::from_millis(250)
    } else {
        Duration::from_secs(10)
    };
    let mut sink = std::io::sink();
    let writer: &mut dyn std::io::Write = match out.as_mut() {
        Some(f) => f.writer(),
        None => &mut sink,
    };
    let mut failures = Vec::new();
    let results = campaign::run(
        &c,
        jobs,
        writer,
        |spec, o| {
            drcc_tools::atomic::create_dir(&fail_dir)?;
            let path = fail_dir.join(format!(
                "{}-s{}-i{}.toml",
                spec.topology.name(),
                spec.seed,
                spec.index
            ));
            write_atomic(&path, campaign::replay_file(spec, o)).map_err(|e| match e {
                CliError::Error(m) | CliError::Failed(m) => m,
            })?;
            failures.push(path);
            Ok(())
        },
        progress,
        every,
    )
    .map_err(error)?;
    if tty {
        eprintln!();
    }
    if let Some(f) = out {
        f.commit()?;
    }
    let mut summary = Summary::default();
    summary.add_results(&results).map_err(error)?;
    print!("{}", summary.table());
    if let Some(p) = a.out {
        println!("results: {}", p.display());
    }
    for f in &failures {
        println!(
            "failing scenario: {} (replay: drcc campaign replay {})",
            f.display(),
            f.display()
        );
    }
    if c.faults == 1 && summary.failing() > 0 {
        return Err(CliError::Failed(format!(
            "{} of {} single-fault scenarios lost, duplicated (across the lines), delivered a \
             foreign frame or locked up",
            summary.failing(),
            summary.scenarios()
        )));
    }
    Ok(())
}

fn report_progress(p: Progress, tty: bool) {
    let rate = p.done as f64 / p.elapsed.as_secs_f64().max(1e-9);
    let eta = p.total.saturating_sub(p.done) as f64 / rate.max(1e-9);
    let line = format!(
        "{}/{} scenarios ({:.0} %), {:.1} scenarios/s, {} failing, ETA {:.0} s",
        p.done,
        p.total,
        100.0 * p.done as f64 / p.total.max(1) as f64,
        rate,
        p.failed,
        eta
    );
    if tty {
        let width = 30;
        let filled = (width as u64 * p.done / p.total.max(1)) as usize;
        eprint!(
            "\r[{}{}] {line}   ",
            "#".repeat(filled),
            " ".repeat(width - filled)
        );
    } else {
        eprintln!("drcc campaign: {line}");
    }
}

fn merge(files: &[String]) -> CliResult {
    if files.is_empty() {
        return Err(error(
            "campaign merge: give the result files (`--out` of each shard)".to_string(),
        ));
    }
    let mut s = Summary::default();
    for f in files {
        let text =
            std::fs::read_to_string(f).map_err(|e| error(format!("{f}: cannot read it ({e})")))?;
        s.add_jsonl(f, &text).map_err(error)?;
    }
    print!("{}", s.table());
    println!(
        "{} scenario(s) from {} file(s); {:.1} s of simulation",
        s.scenarios(),
        files.len(),
        s.wall_ms / 1e3
    );
    Ok(())
}

fn replay(path: &Path, engine: &str) -> CliResult {
    let text = std::fs::read_to_string(path)
        .map_err(|e| error(format!("{}: cannot read it ({e})", path.display())))?;
    let (topology, faults, seed, index) =
        campaign::parse_replay(&text).map_err(|m| error(format!("{}: {m}", path.display())))?;
    let kind = engine.parse::<EngineKind>().map_err(error)?;
    available(kind).map_err(error)?;
    let spec = draw(topology, faults, seed, index);
    println!("scenario {index} of seed {seed}: {}", spec.describe());
    let o = campaign::run_one(&spec, kind).map_err(error)?;
    println!(
        "{} deliveries: {} lost {:?}, {} duplicated {:?}, {} received twice from one line {:?}, \
         {} foreign; lockups: {}",
        o.deliveries,
        o.lost.len(),
        o.lost,
        o.duplicated.len(),
        o.duplicated,
        o.double_received.len(),
        o.double_received,
        o.foreign,
        campaign::describe_lockups(&spec, &o)
    );
    if o.clean() {
        Ok(())
    } else {
        Err(CliError::Failed(
            "the scenario lost, duplicated or locked up".to_string(),
        ))
    }
}
