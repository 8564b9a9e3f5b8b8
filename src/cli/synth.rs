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

use drcc_fpga::markdown::{self, README_BEGIN, README_END};
use drcc_fpga::{nextpnr, tools, Flow, SynthReport, Target, ToolEnv, TARGETS};
use drcc_hdl::tops::{self, Top};

use super::{
    project_root, rewrite_between_atomic, workspace_path, write_atomic, CliError, CliResult,
};

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
    /// `--markdown`: rewrite docs/synthesis.md and the README table.
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
    // the checkout whose tables --markdown rewrites, found before the long run
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
        let table = markdown::table(&results);
        let doc_path = root.join("docs/synthesis.md");
        let readme_path = root.join("README.md");
        // the README's markers are checked (and its new text staged) before the
        // document is replaced, so a bad README changes neither file
        rewrite_between_atomic(
            std::slice::from_ref(&readme_path),
            README_BEGIN,
            README_END,
            &table,
        )?;
        write_atomic(&doc_path, markdown::doc(&results, &flow.env))?;
        if !args.json {
            print!("{table}");
            println!(
                "wrote {} and the table in {}",
                doc_path.display(),
                readme_path.display()
            );
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markers_are_replaced() {
        let text = format!("head\n{README_BEGIN}\nold\n{README_END}\ntail\n");
        let new =
            crate::cli::replace_between(&text, README_BEGIN, README_END, "| new |\n").unwrap();
        assert_eq!(
            new,
            format!("head\n{README_BEGIN}\n| new |\n{README_END}\ntail\n")
        );
        assert!(crate::cli::replace_between("nothing", README_BEGIN, README_END, "x").is_err());
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
