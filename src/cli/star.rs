//! `drcc star`: DRCC nodes on a ReCANcentrate replicated star (two coupled hubs), the
//! fault scenarios of the hub issue (`uplink_stuck_dominant`, ..., `all`) and their
//! Markdown table (`table`), on one engine or on two in lock step with `--cosim`.

use super::{CliError, CliResult};
use drcc_testbench::star::{run_star, star_table, table_row, StarFault, StarScenario};
use drcc_testbench::EngineKind;

fn engine(name: &str) -> Result<EngineKind, CliError> {
    name.parse::<EngineKind>().map_err(CliError::Error)
}

/// Runs `what` (see the module docs).
pub fn run(what: &str, engine_name: &str, cosim: Option<&str>) -> CliResult {
    let kind = engine(engine_name)?;
    let other = cosim.map(engine).transpose()?;
    if what == "table" {
        print!("{}", star_table(kind, other).map_err(CliError::Error)?);
        return Ok(());
    }
    let faults: Vec<StarFault> = if what == "all" {
        StarFault::ALL.to_vec()
    } else {
        match StarFault::from_name(what) {
            Some(f) => vec![f],
            None => {
                let names: Vec<_> = StarFault::ALL.iter().map(|f| f.name()).collect();
                return Err(CliError::Error(format!(
                    "unknown star scenario {what:?}: give table, all, or one of {}",
                    names.join(", ")
                )));
            }
        }
    };
    let mut lost = 0;
    for f in faults {
        let s = StarScenario::standard(f);
        let r = run_star(&s, kind, other).map_err(CliError::Error)?;
        lost += !r.exactly_once() as usize;
        print!("{}", table_row(&s, &r));
        for &(rx, tx, k) in &r.missing {
            eprintln!("  {}: node {rx} never received frame {k} of node {tx}", f.name());
        }
        for &(rx, tx, k) in &r.duplicates {
            eprintln!("  {}: node {rx} received frame {k} of node {tx} more than once", f.name());
        }
    }
    if lost > 0 {
        return Err(CliError::Error(format!(
            "{lost} scenario(s) lost or duplicated frames at the application level"
        )));
    }
    Ok(())
}
