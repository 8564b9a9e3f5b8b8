//! `drcc redundancy`: the DRCC's redundancy scenarios on a dual bus — the paper's
//! Figs. 5-8 experiment (`paper`), the fault scenarios of 4 DRCC nodes (`cut_a`,
//! `a_stuck_dominant`, ..., or `all`), and the switchover table (`switchover`) — on
//! one engine, or on two in lock step with `--cosim`.

use super::{write_atomic, CliError, CliResult};
use drcc_cosim::dual::host::Policy;
use drcc_testbench::dual::{run_dual_traced, DualFault, DualScenario};
use drcc_testbench::paper::{run_paper, switchover_table, Rate};
use drcc_testbench::EngineKind;
use std::path::Path;

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

/// Runs `what` (see the module docs).
pub fn run(
    what: &str,
    engine_name: &str,
    cosim: Option<&str>,
    policy_name: Option<&str>,
    vcd: Option<&Path>,
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
    if let (Some(path), "table" | "switchover") = (vcd, what) {
        return Err(CliError::Error(format!(
            "--vcd {}: `{what}` runs many scenarios and writes no trace; give `paper` or \
             one fault (or `all`, one file per fault) to trace it",
            path.display()
        )));
    }
    match what {
        "paper" => {
            let policy_name = policy_name.unwrap_or("error-passive");
            let p = policy(policy_name)?;
            let mut buf = Vec::new();
            let r = run_paper(p, Rate::M1, kind, other, vcd.map(|_| &mut buf))
                .map_err(CliError::Error)?;
            if let Some(path) = vcd {
                write_atomic(path, &buf)?;
                println!("wrote {}", path.display());
            }
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
        _ => {
            let faults: Vec<DualFault> = if what == "all" {
                DualFault::ALL.to_vec()
            } else {
                match DualFault::ALL.iter().find(|f| f.name() == what) {
                    Some(f) => vec![*f],
                    None => {
                        let names: Vec<_> = DualFault::ALL.iter().map(|f| f.name()).collect();
                        return Err(CliError::Error(format!(
                            "unknown scenario {what:?}: give paper, switchover, table, all, or one of {}",
                            names.join(", ")
                        )));
                    }
                }
            };
            let mut failed = 0;
            for f in faults {
                let s = DualScenario::standard(f);
                let mut buf = Vec::new();
                let r = run_dual_traced(&s, kind, other, vcd.map(|_| &mut buf))
                    .map_err(CliError::Error)?;
                if let Some(path) = vcd {
                    let path = if what == "all" {
                        path.with_file_name(format!(
                            "{}_{}.vcd",
                            path.file_stem().and_then(|x| x.to_str()).unwrap_or("drcc"),
                            f.name()
                        ))
                    } else {
                        path.to_path_buf()
                    };
                    write_atomic(&path, &buf)?;
                    println!("wrote {}", path.display());
                }
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
