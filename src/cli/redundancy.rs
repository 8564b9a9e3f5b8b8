//! `drcc redundancy`: the DRCC's redundancy scenarios on a dual bus — the paper's
//! Figs. 5-8 experiment (`paper`), the fault scenarios of 4 DRCC nodes (`cut_a`,
//! `a_stuck_dominant`, ..., or `all`), the switchover table (`switchover`) and the
//! ECSS bus-selection table (`ecss`, DRCC contract §12) — on
//! one engine, or on two in lock step with `--cosim`. `paper` and the faults can
//! export their traffic (`--candump`, `--pcap`; `all`: one file per fault).

use super::traffic::{check_owned, TrafficArgs, TrafficFiles};
use super::{check_outputs, write_atomic, CliError, CliResult};
use drcc_cosim::dual::DualBusSystem;
use drcc_cosim::host::Policy;
use drcc_cosim::traffic::NodeTap;
use drcc_testbench::dual::{run_dual_observed, DualFault, DualScenario, CLOCK_HZ};
use drcc_testbench::paper::{run_paper_observed, switchover_table, Rate};
use drcc_testbench::EngineKind;
use std::path::{Path, PathBuf};

fn engine(name: &str) -> Result<EngineKind, CliError> {
    name.parse::<EngineKind>().map_err(CliError::Error)
}

fn policy(name: &str) -> Result<Policy, CliError> {
    match name {
        "error-passive" => Ok(Policy::ErrorPassive),
        "none" => Ok(Policy::None),
        "warning" => Ok(Policy::Warning),
        k if k.starts_with("k") => match k[1..].parse::<u8>() {
            Ok(k @ 1..=15) => Ok(Policy::KFailed(k)),
            _ => Err(CliError::Error(format!(
                "--policy {name}: give k1 .. k15 (switch after k failed attempts)"
            ))),
        },
        other => Err(CliError::Error(format!(
            "--policy {other}: the policies are error-passive, warning, none, k1 .. k15"
        ))),
    }
}

/// A run's tap writing into `files` (nothing when no file is asked for).
fn observer<'a>(
    files: &'a mut TrafficFiles,
    nodes: usize,
) -> impl FnMut(&DualBusSystem) -> Result<(), String> + 'a {
    let mut tap = NodeTap::new(nodes);
    move |sys| files.take(|out| tap.poll(sys, out))
}

/// Names the traffic files written.
fn print_written(files: TrafficFiles) -> CliResult {
    for (_, p) in files.commit()? {
        println!("wrote {}", p.display());
    }
    Ok(())
}

/// The trace file of fault `f` (with `all`: named after it).
fn vcd_of(path: &Path, what: &str, f: DualFault) -> PathBuf {
    if what == "all" {
        path.with_file_name(format!(
            "{}_{}.vcd",
            path.file_stem().and_then(|x| x.to_str()).unwrap_or("drcc"),
            f.name()
        ))
    } else {
        path.to_path_buf()
    }
}

/// Refuses outputs that name the same file, over every fault run.
fn check_fault_outputs(
    what: &str,
    faults: &[DualFault],
    vcd: Option<&Path>,
    traffic: &TrafficArgs,
) -> CliResult {
    let mut every = Vec::new();
    for &f in faults {
        every.extend(vcd.map(|p| ("--vcd", vcd_of(p, what, f))));
        every.extend(traffic.for_fault(what, f.name()).owned_outputs());
    }
    check_owned(&every)
}

/// Runs `what` (see the module docs).
pub fn run(
    what: &str,
    engine_name: &str,
    cosim: Option<&str>,
    policy_name: Option<&str>,
    vcd: Option<&Path>,
    traffic: &TrafficArgs,
) -> CliResult {
    let kind = engine(engine_name)?;
    let other = cosim.map(engine).transpose()?;
    if let (Some(p), false) = (policy_name, what == "paper") {
        policy(p)?;
        return Err(CliError::Error(format!(
            "--policy {p} applies to `drcc redundancy paper` only: the fault scenarios and \
             tables run their own documented policies (docs/drcc.md); leave out --policy"
        )));
    }
    if let (Some(path), "table" | "switchover" | "ecss") = (vcd, what) {
        return Err(CliError::Error(format!(
            "--vcd {}: `{what}` runs many scenarios and writes no trace; give `paper` or \
             one fault (or `all`, one file per fault) to trace it",
            path.display()
        )));
    }
    if let "table" | "switchover" | "ecss" = what {
        traffic.refuse(what, "`paper` or one fault (or `all`, one file per fault)")?;
    }
    match what {
        "paper" => {
            let policy_name = policy_name.unwrap_or("error-passive");
            let p = policy(policy_name)?;
            let mut outputs = traffic.outputs();
            outputs.extend(vcd.map(|v| ("--vcd", v)));
            check_outputs(&[], &outputs)?;
            let mut files = TrafficFiles::create(traffic, CLOCK_HZ)?;
            let mut buf = Vec::new();
            let r = run_paper_observed(
                p,
                Rate::M1,
                kind,
                other,
                vcd.map(|_| &mut buf),
                &mut observer(&mut files, 2),
            )
            .map_err(CliError::Error)?;
            if let Some(path) = vcd {
                write_atomic(path, &buf)?;
                println!("wrote {}", path.display());
            }
            print_written(files)?;
            println!(
                "paper scenario ({policy_name}, 1 Mbit/s): TEC of A {:?}; main FSM {:?}; \
                 tx_ok_channel {:#04b}; on B after {:.0} bit times, tx_success after {:.0}",
                r.tec_a,
                r.states,
                r.tx_ok_channel,
                r.bits_to_b().unwrap_or(f64::NAN),
                r.bits_to_success().unwrap_or(f64::NAN)
            );
            Ok(())
        }
        "table" => {
            print!(
                "{}",
                drcc_testbench::dual::fault_table(kind, other).map_err(CliError::Error)?
            );
            Ok(())
        }
        "switchover" => {
            print!("{}", switchover_table(kind).map_err(CliError::Error)?);
            Ok(())
        }
        "ecss" => {
            print!(
                "{}",
                drcc_testbench::ecss::ecss_table(kind, other).map_err(CliError::Error)?
            );
            Ok(())
        }
        _ => {
            let faults: Vec<DualFault> = if what == "all" {
                DualFault::ALL.to_vec()
            } else {
                match DualFault::ALL.iter().find(|f| f.name() == what) {
                    Some(f) => vec![*f],
                    None => {
                        let names: Vec<_> = DualFault::ALL.iter().map(|f| f.name()).collect();
                        return Err(CliError::Error(format!(
                            "unknown scenario {what:?}: give paper, switchover, table, ecss, all, or one of {}",
                            names.join(", ")
                        )));
                    }
                }
            };
            check_fault_outputs(what, &faults, vcd, traffic)?;
            let mut failed = 0;
            for f in faults {
                let s = DualScenario::standard(f);
                let mut files = TrafficFiles::create(&traffic.for_fault(what, f.name()), CLOCK_HZ)?;
                let mut buf = Vec::new();
                let r = run_dual_observed(
                    &s,
                    kind,
                    other,
                    vcd.map(|_| &mut buf),
                    &mut observer(&mut files, s.nodes),
                )
                .map_err(CliError::Error)?;
                if let Some(path) = vcd {
                    let path = vcd_of(path, what, f);
                    write_atomic(&path, &buf)?;
                    println!("wrote {}", path.display());
                }
                print_written(files)?;
                let ok = r.exactly_once();
                failed += !ok as usize;
                println!(
                    "{:<18} {}: {} of {} deliveries, missing {}, duplicates {}, back on A {} of the {} that left it",
                    f.name(),
                    if ok { "exactly once" } else { "FAILED" },
                    r.delivered,
                    s.nodes * (s.nodes - 1) * s.frames_per_node,
                    r.missing.len(),
                    r.duplicates.len(),
                    r.back_on_a.iter().filter(|b| b.is_some()).count(),
                    r.a_failed.iter().filter(|&&f| f).count()
                );
            }
            if failed > 0 {
                return Err(CliError::Error(format!(
                    "{failed} scenario(s) lost or duplicated frames"
                )));
            }
            Ok(())
        }
    }
}
