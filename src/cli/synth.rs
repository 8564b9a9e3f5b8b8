//! `drcc synth`: the command line of the FPGA flow. The flow itself (tools,
//! yosys, nextpnr, icepack, the scan wrapper, the reports) is the `drcc-fpga`
//! crate; this file checks the arguments, runs it and prints the results.
//!
//! ```text
//! drcc synth --target ice40|ice40hx|xc3s|xc7 [--top NAME] [--json] [--build-dir DIR]
//! drcc synth --all [--markdown] [--json] [--build-dir DIR] [--pnr-minutes N]
//! ```

use std::path::{Path, PathBuf};
use std::time::Duration;

use drcc_fpga::markdown;
use drcc_fpga::{nextpnr, tools, Flow, SynthReport, Target, ToolEnv, TARGETS};
use drcc_hdl::tops::{self, Top};

use super::{project_root, workspace_path, write_atomic, CliError, CliResult};

/// The options of `drcc synth`.
#[derive(Debug, Default)]
pub struct SynthArgs {
    /// `--target`.
    pub target: Option<String>,
    /// `--top`.
    pub top: Option<String>,
    /// `--all`: every top on every target.
    pub all: bool,
    /// `--json`: machine-readable report on stdout.
    pub json: bool,
    /// `--markdown`: rewrite docs/synthesis.md (which holds the results table).
    pub markdown: bool,
    /// `--breakdown`: the area block by block on every selected target.
    pub breakdown: bool,
    /// `--build-dir`: where the netlists, logs and bitstreams go.
    pub build_dir: Option<PathBuf>,
    /// `--pnr-minutes`: nextpnr's time limit per top (default
    /// [`nextpnr::DEFAULT_LIMIT`]).
    pub pnr_minutes: Option<u64>,
}

impl From<drcc_fpga::Error> for CliError {
    fn from(e: drcc_fpga::Error) -> Self {
        CliError::Error(e.0)
    }
}

/// The tops and targets the arguments ask for.
fn selection(args: &SynthArgs) -> Result<(Vec<&'static Top>, Vec<&'static Target>), CliError> {
    if let Some(m @ (0 | 601..)) = args.pnr_minutes {
        return Err(CliError::Error(format!(
            "--pnr-minutes {m}: give 1 to 600 minutes (default {})",
            nextpnr::DEFAULT_LIMIT.as_secs() / 60
        )));
    }
    if args.markdown && !args.all {
        return Err(CliError::Error(
            "--markdown regenerates the whole results table: use it with --all".to_string(),
        ));
    }
    if args.all && (args.top.is_some() || args.target.is_some()) {
        return Err(CliError::Error(
            "--all runs every top on every target: leave out --top and --target".to_string(),
        ));
    }
    if args.all {
        return Ok((tops::TOPS.iter().collect(), TARGETS.iter().collect()));
    }
    let Some(target) = args.target.as_deref() else {
        return Err(CliError::Error(format!(
            "give --target {} (or --all)",
            drcc_fpga::target::names().join("|")
        )));
    };
    let target = Target::by_name(target).ok_or_else(|| {
        CliError::Error(format!(
            "--target {target}: unknown FPGA family; legal values are {}",
            drcc_fpga::target::names().join(", ")
        ))
    })?;
    let top = match args.top.as_deref() {
        None => &tops::TOPS[0],
        Some(name) => tops::top(name).ok_or_else(|| {
            CliError::Error(format!(
                "--top {name}: unknown top; the tops are {}",
                tops::names().join(", ")
            ))
        })?,
    };
    Ok((vec![top], vec![target]))
}

/// Runs the command.
pub fn run(args: SynthArgs) -> CliResult {
    let (tops, targets) = selection(&args)?;
    tools::check(&targets)?;
    // the checkout whose docs/synthesis.md --markdown rewrites, found before the long run
    let root = match args.markdown {
        true => Some(project_root(", or leave out --markdown (or use --json)")?),
        false => None,
    };
    let progress = |m: &str| eprintln!("drcc synth: {m}");
    // --breakdown: on every selected target; the document always has the
    // iCE40UP5K's (the family the DRCC's area target is judged on).
    let breakdown_on: Vec<&str> = if args.breakdown {
        targets.iter().map(|t| t.name).collect()
    } else if args.markdown {
        vec!["ice40"]
    } else {
        Vec::new()
    };
    let flow = Flow {
        // rtl-out/ and constraints/ of the current directory, else of the
        // workspace this binary was built from.
        workspace: workspace_path("rtl-out")
            .parent()
            .unwrap_or(Path::new(""))
            .to_path_buf(),
        build_root: args
            .build_dir
            .clone()
            .unwrap_or_else(|| PathBuf::from("out").join("synth")),
        env: ToolEnv::probe(&targets)?,
        progress: &progress,
        breakdown_on: &breakdown_on,
        pnr_limit: args
            .pnr_minutes
            .map_or(nextpnr::DEFAULT_LIMIT, |m| Duration::from_secs(60 * m)),
    };

    let mut results: Vec<SynthReport> = Vec::new();
    for top in &tops {
        for target in &targets {
            let r = flow.run(top, target)?;
            if let (Some(why), false) = (&r.unsupported, args.all) {
                return Err(CliError::Error(format!(
                    "--target {}: {why}; no numbers for {} from this yosys",
                    target.name, target.family
                )));
            }
            if !args.json && !args.markdown {
                print!("{}", r.text());
            }
            results.push(r);
        }
    }
    if args.json {
        let json = drcc_fpga::json::reports(&results, args.all)?;
        println!("{json}");
    }
    if let Some(root) = root {
        // the whole document, results table included, through a temporary file
        // and a rename: an interrupted run leaves the old file or the new one
        let doc_path = root.join(DOC_PAGE);
        write_atomic(&doc_path, markdown::doc(&results, &flow.env))?;
        if !args.json {
            print!("{}", markdown::table(&results));
            println!("wrote {}", doc_path.display());
        }
    }
    Ok(())
}

/// The document `--all --markdown` rewrites, whole (the README links to it).
const DOC_PAGE: &str = "docs/synthesis.md";

#[cfg(test)]
mod tests {
    use super::*;

    /// The results table lives in docs/synthesis.md, written whole; the README
    /// holds no generated copy of it.
    #[test]
    fn the_results_table_lives_in_the_document_only() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let doc = std::fs::read_to_string(root.join(DOC_PAGE)).unwrap();
        assert!(doc.starts_with("# Synthesis results\n"), "{DOC_PAGE}");
        assert!(
            doc.contains("\n| top | target: board (FPGA) | LUTs |"),
            "{DOC_PAGE}"
        );
        let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
        assert!(!readme.contains("synth-results:begin"), "README.md");
    }

    #[test]
    fn arguments_select_tops_and_targets() {
        let all = SynthArgs {
            all: true,
            ..SynthArgs::default()
        };
        let (t, f) = selection(&all).unwrap();
        assert_eq!((t.len(), f.len()), (tops::TOPS.len(), TARGETS.len()));
        let one = SynthArgs {
            target: Some("xc3s".into()),
            ..SynthArgs::default()
        };
        let (t, f) = selection(&one).unwrap();
        assert_eq!((t[0].name, f[0].name), ("can_channel", "xc3s"));
        let both = SynthArgs {
            all: true,
            top: Some("drcc".into()),
            ..SynthArgs::default()
        };
        assert!(selection(&both).is_err());
        for m in [0, 601] {
            let limit = SynthArgs {
                all: true,
                pnr_minutes: Some(m),
                ..SynthArgs::default()
            };
            let Err(CliError::Error(e)) = selection(&limit) else {
                panic!("--pnr-minutes {m} accepted");
            };
            assert!(
                e.starts_with(&format!("--pnr-minutes {m}: give 1 to 600")),
                "{e}"
            );
        }
    }
}
