//! `drcc dmr`: the CiA 701 DMR test plan (seed 001 Figure 9, Tables 2 and 3; DMR
//! contract §10) on four DRCC devices in DMR mode. `table` runs every row (the
//! baseline, F1..F10 as startup failure and at run time) and prints the Markdown table
//! (`--markdown` also rewrites it between the `dmr-table` markers of docs/dmr.md);
//! `F1` .. `F10` (or `baseline`) runs one row
//! (`--startup`, the default, or `--runtime`), with `--vcd` and `--cosim`. An engine
//! other than the model always runs with the model in lock step (the plan's oracle).

use super::{project_root, rewrite_between_atomic, AtomicFile, CliError, CliResult};
use drcc_testbench::dmr::load::{schedule, summary};
use drcc_testbench::dmr::report::table_header;
use drcc_testbench::dmr::{
    dmr_table, row_line, run_row, run_row_traced, Marker, Onset, PlanConfig, Row, RowReport,
    DEVICES,
};
use drcc_testbench::EngineKind;
use std::path::Path;

/// The options of `drcc dmr`.
#[derive(Debug, Default)]
pub struct DmrArgs<'a> {
    pub what: &'a str,
    pub startup: bool,
    pub runtime: bool,
    pub markdown: bool,
    pub engine: &'a str,
    pub cosim: Option<&'a str>,
    pub vcd: Option<&'a Path>,
    pub recovery_ms: Option<u16>,
    pub limit: Option<u8>,
    pub first_copy: bool,
}

/// What `drcc dmr` was asked to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Job {
    Table { markdown: bool },
    One(Row),
}

fn error(m: String) -> CliError {
    CliError::Error(m)
}

/// Checks the arguments (everything that can be wrong before a long run).
pub fn parse(a: &DmrArgs) -> Result<(Job, PlanConfig, EngineKind, Option<EngineKind>), CliError> {
    let kind = a.engine.parse::<EngineKind>().map_err(error)?;
    let other = a
        .cosim
        .map(str::parse::<EngineKind>)
        .transpose()
        .map_err(error)?;
    let plan = match a.recovery_ms {
        None => PlanConfig::standard(),
        Some(0) => {
            return Err(error(
                "--recovery-ms 0: DMR_TIME.recovery_delay 0 is refused (DMR contract §2.2); \
                 give 1 .. 65535 ms (the seed's is 2000)"
                    .to_string(),
            ))
        }
        Some(ms) => PlanConfig::with_recovery(ms),
    };
    let plan = match a.limit {
        None => plan,
        Some(n @ 1..=127) if !a.markdown => PlanConfig { limit: n, ..plan },
        Some(1..=127) => {
            return Err(error(
                "--limit with --markdown: the table in docs/dmr.md is the standard plan (limit 3); print a table with another limit without --markdown"
                    .to_string(),
            ))
        }
        Some(n) => {
            return Err(error(format!(
                "--limit {n}: MB_CFG.limit is 1 .. 127 (0 is refused, DMR contract §2.2; the field has 7 bits); give 1 .. 127 (the plan's default is 3)"
            )))
        }
    };
    let plan = match (a.first_copy, a.what) {
        (false, _) => plan,
        (true, "table") => {
            return Err(error(
                "--first-copy chooses the rule of one row: the table has the seed's ACL rule                  and first-copy delivery side by side; leave it out, or give a row (F1 .. F10,                  baseline)"
                    .to_string(),
            ))
        }
        (true, _) => plan.first_copy(),
    };
    if a.startup && a.runtime {
        return Err(error(
            "--startup and --runtime: a row is one or the other; give one of them".to_string(),
        ));
    }
    let job = if a.what == "table" {
        if a.startup || a.runtime || a.vcd.is_some() {
            return Err(error(
                "--startup, --runtime and --vcd choose and trace one row: use them with \
                 `drcc dmr F1` .. `F10` (or `baseline`), not with `table`"
                    .to_string(),
            ));
        }
        Job::Table {
            markdown: a.markdown,
        }
    } else {
        if a.markdown {
            return Err(error(
                "--markdown rewrites the whole table: use it with `drcc dmr table`".to_string(),
            ));
        }
        let onset = if a.runtime {
            Onset::Runtime
        } else {
            Onset::Startup
        };
        match (a.what, Marker::parse(a.what)) {
            ("baseline", _) => Job::One(Row::BASELINE),
            (_, Some(m)) => Job::One(Row {
                marker: Some(m),
                onset,
            }),
            (other, None) => {
                return Err(error(format!(
                    "unknown fault marker {other:?}: give table, baseline, or one of F1 .. F10 \
                     (F1..F8: COS1, COS2, COS3, COM1 disconnected from the DCL / RCL; F9 / F10: \
                     the DCL / RCL short-circuited)"
                )))
            }
        }
    };
    Ok((job, plan, kind, other))
}

/// Runs `drcc dmr` (see the module docs).
pub fn run(a: &DmrArgs) -> CliResult {
    let (job, plan, kind, other) = parse(a)?;
    // the checkout whose table --markdown rewrites, found before the run
    let root = match job {
        Job::Table { markdown: true } => Some(project_root(
            ", or leave out --markdown to print the table only",
        )?),
        _ => None,
    };
    let sched = schedule(&plan);
    let load = summary(&plan, &sched);
    eprintln!(
        "traffic: 125 kbit/s (1 MHz clock, 8 clocks per bit), offered load {:.2} % from exact \
         frame lengths ({} .. {} bit times with stuff bits and intermission), recovery delay \
         {} ms, deviation limit {}, run {} ms, reception: {}",
        load.load * 100.0,
        load.min_bits,
        load.max_bits,
        plan.recovery_ms,
        plan.limit,
        plan.run_ms,
        match (job, plan.first_copy) {
            (Job::Table { .. }, _) => "the ACL rule and first copy (CTRL.first_copy), each row",
            (_, true) => "first copy (CTRL.first_copy, DMR contract §8.1)",
            (_, false) => "the seed's ACL rule",
        }
    );
    for (d, (frames, bits, period)) in load.devices.iter().enumerate() {
        eprintln!(
            "  {}: {frames} frames, mean {bits:.1} bit times, mean period {period:.3} ms",
            DEVICES[d]
        );
    }
    match job {
        Job::Table { markdown } => {
            let table = dmr_table(&plan, kind, other, |r| {
                eprintln!(
                    "  {:<12} {:<10} {:.1} s ({} clocks)",
                    r.row.name(),
                    if r.first_copy {
                        "first copy"
                    } else {
                        "ACL rule"
                    },
                    r.wall.as_secs_f64(),
                    r.cycles
                )
            })
            .map_err(error)?;
            print!("{table}");
            if let (true, Some(root)) = (markdown, &root) {
                let paths = [root.join(TABLE_PAGE)];
                rewrite_between_atomic(&paths, TABLE_BEGIN, TABLE_END, &table)?;
                for p in &paths {
                    println!("wrote the table in {}", p.display());
                }
            }
            Ok(())
        }
        Job::One(row) => one(&plan, row, kind, other, a.vcd),
    }
}

fn one(
    plan: &PlanConfig,
    row: Row,
    kind: EngineKind,
    other: Option<EngineKind>,
    vcd: Option<&Path>,
) -> CliResult {
    // An unwritable trace path is refused before the run, not after it; the trace
    // goes to a temporary file beside it and replaces it only when written.
    let mut out = vcd
        .map(|path| {
            let dir_ok = path
                .parent()
                .is_none_or(|d| d.as_os_str().is_empty() || d.is_dir());
            let file = if dir_ok {
                AtomicFile::create(path)
            } else {
                Err(CliError::Error(String::new()))
            };
            file.map_err(|_| {
                error(format!(
                    "--vcd {}: cannot write it; give a path in a writable directory",
                    path.display()
                ))
            })
        })
        .transpose()?;
    let mut save = |buf: &[u8]| -> CliResult {
        if let Some(mut f) = out.take() {
            std::io::Write::write_all(f.writer(), buf)
                .map_err(|e| error(format!("cannot write the trace: {e}")))?;
            f.commit()?;
        }
        Ok(())
    };
    let mut buf = Vec::new();
    let r = match run_row_traced(plan, row, kind, other, vcd.map(|_| &mut buf)) {
        Ok(r) => r,
        Err(e) => {
            // A divergence is what the trace is for: keep it up to that clock.
            if let (Some(path), false) = (vcd, buf.is_empty()) {
                if save(&buf).is_ok() {
                    return Err(error(format!(
                        "{e}; the trace up to there is in {}",
                        path.display()
                    )));
                }
            }
            return Err(error(e));
        }
    };
    // The fault-free run of the same traffic, for the latency column.
    let base = if row == Row::BASELINE {
        None
    } else {
        Some(run_row(plan, Row::BASELINE, kind, None).map_err(error)?)
    };
    if let Some(path) = vcd {
        save(&buf)?;
        println!("wrote {}", path.display());
    }
    print!("{}", table_header());
    print!("{}", row_line(&r, base.as_ref().or(Some(&r))));
    details(&r);
    if !r.exactly_once() {
        return Err(CliError::Failed(format!(
            "{}: {} frame(s) lost, {} duplicated, {} foreign at the application level",
            row.name(),
            r.lost.len(),
            r.duplicated.len(),
            r.foreign
        )));
    }
    Ok(())
}

/// The registers behind the row, and the first lost or duplicated frames.
fn details(r: &RowReport) {
    eprintln!(
        "{} on {}: {} clocks in {:.1} s; {} frames pushed, {} popped",
        r.row.name(),
        r.engine,
        r.cycles,
        r.wall.as_secs_f64(),
        r.pushed,
        r.deliveries
    );
    for (d, name) in DEVICES.iter().enumerate() {
        eprintln!(
            "  {name}: DMR_STATUS {:#010x} at the end of the fault window, {:#010x} at the end; \
             DMR_RX_STATS {:#010x}, DMR_CS_COUNT {:#010x}",
            r.during[d].word, r.end[d].word, r.rx_stats_end[d], r.cs_count_end[d]
        );
    }
    for &(rx, tx, seq) in r.lost.iter().take(10) {
        eprintln!(
            "  lost: {} never popped frame {seq} of {}",
            DEVICES[rx], DEVICES[tx]
        );
    }
    for &(rx, tx, seq) in r.duplicated.iter().take(10) {
        eprintln!(
            "  duplicated: {} popped frame {seq} of {} more than once",
            DEVICES[rx], DEVICES[tx]
        );
    }
}

const TABLE_BEGIN: &str = "<!-- dmr-table:begin (generated by `drcc dmr table --markdown`) -->";
const TABLE_END: &str = "<!-- dmr-table:end -->";
/// The page whose table `--markdown` rewrites (the README links to it).
const TABLE_PAGE: &str = "docs/dmr.md";

#[cfg(test)]
mod tests {
    use super::*;

    fn args(what: &str) -> DmrArgs<'_> {
        DmrArgs {
            what,
            engine: "model",
            ..DmrArgs::default()
        }
    }

    fn err(a: &DmrArgs) -> String {
        match parse(a) {
            Err(CliError::Error(m)) => m,
            other => panic!("expected an error, got {other:?}"),
        }
    }

    #[test]
    fn rows_and_the_table_parse() {
        let (job, plan, kind, other) = parse(&args("table")).unwrap();
        assert_eq!(job, Job::Table { markdown: false });
        assert_eq!(
            (plan, kind, other),
            (PlanConfig::standard(), EngineKind::Model, None)
        );
        let (job, ..) = parse(&args("F2")).unwrap();
        assert_eq!(
            job,
            Job::One(Row {
                marker: Some(Marker::F2),
                onset: Onset::Startup
            })
        );
        let a = DmrArgs {
            runtime: true,
            cosim: Some("verilator"),
            recovery_ms: Some(2000),
            ..args("f10")
        };
        let (job, plan, _, other) = parse(&a).unwrap();
        assert_eq!(
            job,
            Job::One(Row {
                marker: Some(Marker::F10),
                onset: Onset::Runtime
            })
        );
        assert_eq!(plan.recovery_ms, 2000);
        assert_eq!(other, Some(EngineKind::Verilator));
        assert_eq!(parse(&args("baseline")).unwrap().0, Job::One(Row::BASELINE));
    }

    #[test]
    fn bad_input_names_what_is_wrong_and_how_to_fix_it() {
        assert!(err(&args("F11")).contains("give table, baseline, or one of F1 .. F10"));
        let both = DmrArgs {
            startup: true,
            runtime: true,
            ..args("F1")
        };
        assert!(err(&both).contains("give one of them"));
        let md = DmrArgs {
            markdown: true,
            ..args("F1")
        };
        assert!(err(&md).contains("drcc dmr table"));
        let vcd = DmrArgs {
            vcd: Some(Path::new("x.vcd")),
            ..args("table")
        };
        assert!(err(&vcd).contains("not with `table`"));
        let zero = DmrArgs {
            recovery_ms: Some(0),
            ..args("F1")
        };
        assert!(err(&zero).contains("1 .. 65535"));
        // §2.2: limit 0 is refused; the field has 7 bits
        for n in [0u8, 128, 255] {
            let bad = DmrArgs {
                limit: Some(n),
                ..args("F1")
            };
            assert!(err(&bad).contains("give 1 .. 127"), "--limit {n}");
        }
        let md_limit = DmrArgs {
            limit: Some(1),
            markdown: true,
            ..args("table")
        };
        let m = err(&md_limit);
        assert!(
            m.contains("without --markdown") && m.contains(TABLE_PAGE),
            "{m}"
        );
        assert!(!m.contains("README"), "{m}");
        let one = DmrArgs {
            limit: Some(1),
            ..args("F1")
        };
        assert_eq!(parse(&one).unwrap().1.limit, 1);
        let engine = DmrArgs {
            engine: "spice",
            ..args("F1")
        };
        assert!(err(&engine).contains("the engines are"));
        // the table always has both rules; one row takes either
        let fc_table = DmrArgs {
            first_copy: true,
            ..args("table")
        };
        assert!(err(&fc_table).contains("side by side"));
        let fc_row = DmrArgs {
            first_copy: true,
            ..args("F1")
        };
        assert!(parse(&fc_row).unwrap().1.first_copy);
        assert!(!parse(&args("F1")).unwrap().1.first_copy);
    }

    /// `--markdown` rewrites the checkout's docs/dmr.md, which holds the markers;
    /// the README holds no copy of the table.
    #[test]
    fn the_table_lives_in_its_docs_page_only() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let page = std::fs::read_to_string(root.join(TABLE_PAGE)).unwrap();
        assert!(crate::cli::replace_between(&page, TABLE_BEGIN, TABLE_END, "| t |\n").is_ok());
        let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
        assert!(!readme.contains(TABLE_BEGIN) && !readme.contains(TABLE_END));
    }

    #[test]
    fn an_unwritable_trace_is_refused_before_the_run() {
        let plan = PlanConfig::standard();
        let m = match one(
            &plan,
            Row::BASELINE,
            EngineKind::Model,
            None,
            Some(Path::new("/nonexistent-dir/x.vcd")),
        ) {
            Err(CliError::Error(m)) => m,
            other => panic!("expected an error, got {other:?}"),
        };
        assert!(m.contains("writable directory"), "{m}");
    }
}
