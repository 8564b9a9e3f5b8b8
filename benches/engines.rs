//! Engine benchmark (`cargo bench`, same as `drcc bench`): the same workloads —
//! one channel, a 3-node random-traffic system, four DRCC nodes on a dual bus and
//! one hub — on every available engine in one run; prints simulated clock cycles
//! per second per engine and the ratios to the model side by side
//! (`drcc_testbench::bench`). No assertions on time.
//!
//! `DRCC_BENCH_SECONDS` sets the time per measurement (default 1 s);
//! `DRCC_BENCH_ENGINES` (e.g. `model,verilator`) limits the engines, to profile one.

use std::time::Duration;

use drcc_testbench::EngineKind;

fn main() {
    let seconds = std::env::var("DRCC_BENCH_SECONDS")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .filter(|s| s.is_finite() && *s > 0.0 && *s <= 600.0)
        .unwrap_or(1.0);
    let engines: Vec<EngineKind> = match std::env::var("DRCC_BENCH_ENGINES") {
        Ok(list) if !list.trim().is_empty() => {
            match list.split(',').map(str::parse).collect::<Result<_, _>>() {
                Ok(e) => e,
                Err(e) => {
                    eprintln!("engines bench: DRCC_BENCH_ENGINES: {e}");
                    std::process::exit(2);
                }
            }
        }
        _ => EngineKind::ALL.to_vec(),
    };
    let mut out = std::io::stdout().lock();
    let budget = Duration::from_secs_f64(seconds);
    if let Err(e) = drcc_testbench::bench::run_engines(&mut out, budget, &engines) {
        eprintln!("engines bench: cannot write the report: {e}");
        std::process::exit(2);
    }
}
