//! Engine benchmark (`cargo bench`, same as `drcc bench`): the same workloads —
//! one channel, and a 3-node random-traffic system — on every available engine in
//! one run; prints simulated clock cycles per second per engine and the ratios
//! side by side. No assertions on time.
//!
//! `DRCC_BENCH_SECONDS` sets the time per measurement (default 1 s).

use std::time::Duration;

fn main() {
    let seconds = std::env::var("DRCC_BENCH_SECONDS")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .filter(|s| s.is_finite() && *s > 0.0 && *s <= 600.0)
        .unwrap_or(1.0);
    let mut out = std::io::stdout().lock();
    if let Err(e) = drcc_testbench::bench::run(&mut out, Duration::from_secs_f64(seconds)) {
        eprintln!("engines bench: cannot write the report: {e}");
        std::process::exit(2);
    }
}
