//! `drcc sim`, `drcc cosim` and `drcc demo`: run scenarios, print per-node tables
//! of sent and received frames, check expectations, write traces.

use std::path::{Path, PathBuf};

use drcc_cosim::cosim::CosimError;
use drcc_cosim::system::{NodeEvent, Sample, System};
use drcc_cosim::trace::{BusVcdWriter, VcdWriter};
use drcc_cosim::traffic::ChannelTap;
use drcc_cosim::ControllerConfig;
use drcc_testbench::bitrate::sample_point_percent;
use drcc_testbench::engines::{available, EngineKind, VERILATOR_HINT};
use drcc_testbench::run::{self, RunResult};
use drcc_testbench::scenario::mode_name;
use drcc_testbench::Scenario;

use super::traffic::{TrafficArgs, TrafficFiles};
use super::{check_outputs, AtomicFile, CliError, CliResult};

/// The demo scenario, built in so `drcc demo` runs from anywhere.
const DEMO_TOML: &str = include_str!("../../testbench/scenarios/demo.toml");

fn load(path: &Path) -> Result<Scenario, CliError> {
    Scenario::load(path).map_err(|e| CliError::Error(e.to_string()))
}

fn engine_role(kind: EngineKind) -> &'static str {
    match kind {
        EngineKind::Model => "the Rust reference model",
        EngineKind::RustHdl => "the hdl blocks in rust-hdl's simulator",
        EngineKind::Verilator => "the emitted Verilog, verilated",
    }
}

fn print_header(sc: &Scenario, engines: &str) {
    let t = &sc.timing;
    println!("scenario  {} ({})", sc.name, sc.source);
    if !sc.description.is_empty() {
        println!("          {}", sc.description);
    }
    println!("engine    {engines}");
    println!(
        "timing    {} Hz clock, {:.0} bit/s: brp {}, tseg1 {}, tseg2 {}, sjw {}{} \
         ({} tq of {} clocks, sample point {:.1} %)",
        sc.clock_hz,
        sc.bitrate(),
        t.brp,
        t.tseg1,
        t.tseg2,
        t.sjw,
        if t.triple_sampling {
            ", triple sampling"
        } else {
            ""
        },
        t.tq_per_bit(),
        t.brp as u32 + 1,
        sample_point_percent(t)
    );
    println!(
        "nodes     {}",
        sc.nodes
            .iter()
            .enumerate()
            .map(|(i, n)| format!("{i}:{n}"))
            .collect::<Vec<_>>()
            .join("  ")
    );
}

fn print_tables(sc: &Scenario, r: &RunResult) {
    let cpb = sc.clocks_per_bit();
    let row = |what: &str, e: &NodeEvent| {
        println!(
            "  {what:<9} cycle {:>9}  bit {:>7}  {}",
            e.cycle,
            e.cycle / cpb,
            e.frame
        )
    };
    for (i, name) in sc.nodes.iter().enumerate() {
        let sent: Vec<&NodeEvent> = r.sent.iter().filter(|e| e.node == i).collect();
        let got: Vec<&NodeEvent> = r.deliveries.iter().filter(|e| e.node == i).collect();
        let failed: Vec<&NodeEvent> = r.failed.iter().filter(|e| e.node == i).collect();
        let config = sc.configs.get(i).copied().unwrap_or_default();
        println!(
            "\nnode {i} `{name}`: sent {} frame(s), received {} frame(s){}{}",
            sent.len(),
            got.len(),
            if failed.is_empty() {
                String::new()
            } else {
                format!(", dropped {} frame(s)", failed.len())
            },
            if config == ControllerConfig::default() {
                String::new()
            } else {
                format!(
                    " [mode {}, ewl {}{}]",
                    mode_name(config.mode),
                    config.ewl,
                    if config.single_shot {
                        ", single shot"
                    } else {
                        ""
                    }
                )
            }
        );
        for e in &sent {
            row("sent", e);
        }
        for e in &failed {
            row("dropped", e);
        }
        for e in &got {
            row("received", e);
        }
    }
    println!(
        "\n{} cycles ({} bit times, {:.3} ms), {} arbitration(s) lost, {}",
        r.outcome.cycles(),
        r.outcome.cycles() / cpb,
        r.outcome.cycles() as f64 * 1000.0 / sc.clock_hz as f64,
        r.arb_lost,
        if r.outcome.is_idle() {
            "bus idle at the end"
        } else {
            "cycle limit reached"
        }
    );
}

fn verdict(r: &RunResult) -> CliResult {
    if r.passed() {
        println!("PASS: every expected frame was sent and delivered exactly once");
        Ok(())
    } else {
        for p in &r.problems {
            println!("  - {p}");
        }
        Err(CliError::Failed(format!(
            "{} expectation(s) not met",
            r.problems.len()
        )))
    }
}

/// Progress of a long run on stderr: after the first 5 s of wall time, one line
/// every 5 s with the cycle reached, the share of the run's limit and the speed
/// (a short run prints nothing).
struct Progress {
    limit: u64,
    start: std::time::Instant,
    next: std::time::Duration,
}

impl Progress {
    const EVERY: std::time::Duration = std::time::Duration::from_secs(5);

    fn new(limit: u64) -> Self {
        Progress {
            limit,
            start: std::time::Instant::now(),
            next: Self::EVERY,
        }
    }

    fn at(&mut self, cycle: u64) {
        if !cycle.is_multiple_of(65_536) {
            return;
        }
        let t = self.start.elapsed();
        if t < self.next {
            return;
        }
        self.next = t + Self::EVERY;
        let rate = cycle as f64 / t.as_secs_f64();
        let left = self.limit.saturating_sub(cycle) as f64 / rate.max(1.0);
        eprintln!(
            "drcc: cycle {cycle} of at most {} ({:.1} %), {:.2} M cycles/s, at most {:.0} s left",
            self.limit,
            100.0 * cycle as f64 / self.limit.max(1) as f64,
            rate / 1e6,
            left
        );
    }
}

/// Every node's configuration (a node the scenario leaves out has the default).
fn node_configs(sc: &Scenario) -> Vec<ControllerConfig> {
    (0..sc.nodes.len())
        .map(|i| sc.configs.get(i).copied().unwrap_or_default())
        .collect()
}

/// Runs a scenario on one engine, writing the requested traces and the traffic.
fn run_traced(
    sc: &Scenario,
    kind: EngineKind,
    vcd: Option<&Path>,
    bus_vcd: Option<&Path>,
    mut traffic: TrafficFiles,
) -> Result<(RunResult, Written), CliError> {
    if vcd.is_none() && bus_vcd.is_none() && traffic.is_empty() {
        // Nothing watches single clocks: the quiet stretches of
        // `System::run_until_idle` (the same events, faster on Verilator).
        let mut progress = Progress::new(sc.max_cycles);
        let result = run::run_with_progress(sc, kind, |cycle| progress.at(cycle))?;
        return Ok((result, traffic.commit()?));
    }
    let mut full_file = vcd.map(AtomicFile::create).transpose()?;
    let mut bus_file = bus_vcd.map(AtomicFile::create).transpose()?;
    let comment = format!(
        "drcc sim {} on {}; clock_hz={}",
        sc.name,
        kind.name(),
        sc.clock_hz
    );
    let io = |p: Option<&Path>| {
        let p = p.map(|p| p.display().to_string()).unwrap_or_default();
        move |e: std::io::Error| format!("cannot write {p}: {e}")
    };
    let mut full = match full_file.as_mut() {
        Some(f) => Some(
            VcdWriter::new(f.writer(), sc.clock_hz, &[("tb", sc.nodes.len())], &comment)
                .map_err(io(vcd))?,
        ),
        None => None,
    };
    let mut bus = match bus_file.as_mut() {
        Some(f) => Some(
            BusVcdWriter::new(f.writer(), sc.clock_hz, sc.nodes.len(), &comment)
                .map_err(io(bus_vcd))?,
        ),
        None => None,
    };
    let mut progress = Progress::new(sc.max_cycles);
    let (configs, mut tap) = (node_configs(sc), ChannelTap::new(sc.nodes.len()));
    let result = run::run_observed(sc, kind, |s: &Sample| {
        progress.at(s.cycle);
        if let Some(w) = full.as_mut() {
            w.write_cycle(&[s]).map_err(io(vcd))?;
        }
        if let Some(w) = bus.as_mut() {
            w.write_cycle(s).map_err(io(bus_vcd))?;
        }
        traffic.take(|out| {
            tap.observe_sample(s, &configs);
            tap.drain(out)
        })
    })?;
    if let Some(w) = full.as_mut() {
        w.finish().map_err(io(vcd))?;
    }
    if let Some(w) = bus.as_mut() {
        w.finish().map_err(io(bus_vcd))?;
    }
    drop(full);
    drop(bus);
    for f in [full_file, bus_file].into_iter().flatten() {
        f.commit()?;
    }
    Ok((result, traffic.commit()?))
}

/// The traffic files written: what, where.
type Written = Vec<(&'static str, PathBuf)>;

/// Names the traffic files written.
fn print_written(files: Written) {
    for (what, p) in files {
        println!("{what}: {}", p.display());
    }
}

/// `drcc sim SCENARIO [--engine E] [--vcd FILE] [--bus-vcd FILE] [--candump FILE]
/// [--pcap FILE]`.
pub fn sim(
    path: &Path,
    engine: &str,
    vcd: Option<&Path>,
    bus_vcd: Option<&Path>,
    traffic: &TrafficArgs,
) -> CliResult {
    let kind: EngineKind = engine.parse()?;
    let mut outputs: Vec<(&str, &Path)> = [("--vcd", vcd), ("--bus-vcd", bus_vcd)]
        .into_iter()
        .filter_map(|(o, p)| p.map(|p| (o, p)))
        .collect();
    outputs.extend(traffic.outputs());
    check_outputs(&[path], &outputs)?;
    let sc = load(path)?;
    available(kind)?;
    // created before anything is printed: a bad path stops the run at once
    let files = TrafficFiles::create(traffic, sc.clock_hz)?;
    print_header(&sc, &format!("{} ({})", kind.name(), engine_role(kind)));
    let (r, written) = run_traced(&sc, kind, vcd, bus_vcd, files)?;
    print_tables(&sc, &r);
    for (what, p) in [("trace", vcd), ("bus trace", bus_vcd)] {
        if let Some(p) = p {
            println!("{what}: {}", p.display());
        }
    }
    print_written(written);
    verdict(&r)
}

/// `drcc cosim SCENARIO [--engines A,B] [--vcd-dir DIR] [--candump FILE] [--pcap
/// FILE]`: the traffic is the first engine's (both agree every clock).
pub fn cosim(
    path: &Path,
    engines: &str,
    vcd_dir: Option<PathBuf>,
    traffic: &TrafficArgs,
) -> CliResult {
    let kinds: Vec<EngineKind> = engines
        .split(',')
        .map(|s| s.parse::<EngineKind>())
        .collect::<Result<_, _>>()?;
    let [a, b] = kinds[..] else {
        return Err(CliError::Error(format!(
            "--engines {engines:?}: give exactly two engines, e.g. model,verilator"
        )));
    };
    check_outputs(&[path], &traffic.outputs())?;
    let sc = load(path)?;
    available(a)?;
    available(b)?;
    let mut files = TrafficFiles::create(traffic, sc.clock_hz)?;
    print_header(&sc, &format!("{} vs {} in lock step", a.name(), b.name()));
    // the lock-step observer cannot fail: the first write error waits here
    let (mut tap, mut write_error) = (ChannelTap::new(sc.nodes.len()), None);
    let mut observe = |sys: &System| {
        if write_error.is_none() {
            write_error = files.take(|out| tap.poll(sys, out)).err();
        }
    };
    match run::cosim_observed(&sc, a, b, vcd_dir, &mut observe) {
        Ok(c) => {
            if let Some(e) = write_error {
                return Err(CliError::Error(e));
            }
            print_tables(&sc, &c.result);
            print_written(files.commit()?);
            println!(
                "no divergence between {} and {} in {} cycles (every output and probe of every node, every clock)",
                c.report.engine_a,
                c.report.engine_b,
                c.report.outcome.cycles()
            );
            verdict(&c.result)
        }
        Err(CosimError::Setup(e)) => Err(CliError::Error(e)),
        Err(CosimError::Divergence(d)) => Err(CliError::Failed(d.to_string())),
    }
}

/// `drcc demo`: the demo scenario on Verilator (or rust-hdl), tables, and
/// out/demo_bus.vcd.
pub fn demo() -> CliResult {
    let disk = super::workspace_path("testbench/scenarios/demo.toml");
    let sc = if disk.exists() {
        load(&disk)?
    } else {
        Scenario::parse(DEMO_TOML, "demo.toml (built in)")
            .map_err(|e| CliError::Error(e.to_string()))?
    };
    let kind = match available(EngineKind::Verilator) {
        Ok(()) => EngineKind::Verilator,
        Err(e) => {
            println!("note: Verilator not found: {VERILATOR_HINT}; running on the rust-hdl engine");
            println!("      ({e})");
            EngineKind::RustHdl
        }
    };
    print_header(&sc, &format!("{} ({})", kind.name(), engine_role(kind)));
    let out = Path::new("out").join("demo_bus.vcd");
    let (r, _) = run_traced(&sc, kind, None, Some(&out), TrafficFiles::none())?;
    print_tables(&sc, &r);
    println!("\nengine that ran: {} ({})", kind.name(), engine_role(kind));
    println!("bus trace: {}", out.display());
    println!(
        "  decode it: sigrok-cli -I vcd -i {} -P can:can_rx=bus:nominal_bitrate={:.0} -A can=fields",
        out.display(),
        sc.bitrate()
    );
    let channel = verdict(&r);
    let drcc = demo_drcc(kind);
    channel.and(drcc)
}

/// The second half of the demo: the DRCC paper's Figs. 5-8 experiment (channel A
/// without acknowledgement, switch to B) with the fastest policy, on the Verilated
/// DRCC or, without Verilator, on the reference model (the DRCC has no rust-hdl
/// engine run here: too slow for two nodes of two channels each).
fn demo_drcc(channel_engine: EngineKind) -> CliResult {
    use drcc_cosim::host::Policy;
    use drcc_testbench::paper::{run_paper, Rate};
    let kind = if channel_engine == EngineKind::Verilator {
        EngineKind::Verilator
    } else {
        println!("\nnote: the DRCC part runs on the reference model (Verilator not found)");
        EngineKind::Model
    };
    println!(
        "\nDRCC, paper Figs. 5-8 at 500 kbit/s: node 0 in redundancy mode (switch after 1 failed \
         attempt), nobody acknowledges on line A, node 1 acknowledges on line B; engine {kind}"
    );
    let mut vcd = Vec::new();
    let r = run_paper(Policy::KFailed(1), Rate::K500, kind, None, Some(&mut vcd))
        .map_err(CliError::Error)?;
    let out = Path::new("out").join("drcc_paper.vcd");
    super::write_atomic(&out, &vcd)?;
    let names = [
        "idle1", "wait1", "ch1", "abort1", "wait2", "idle2", "wait3", "ch2", "abort2", "wait4",
    ];
    let path: Vec<&str> = r
        .states
        .iter()
        .map(|&st| names.get(st as usize).copied().unwrap_or("?"))
        .collect();
    println!("  main FSM (Table 1): {}", path.join(" -> "));
    println!("  TEC of channel A: {:?}", r.tec_a);
    println!(
        "  on line B {:.0} bit times after the first attempt on A ({:.3} ms), tx_success after {:.0} \
         ({:.3} ms); the paper needed ~25 ms",
        r.bits_to_b().unwrap_or(f64::NAN),
        r.bits_to_b().unwrap_or(f64::NAN) / 500.0,
        r.bits_to_success().unwrap_or(f64::NAN),
        r.bits_to_success().unwrap_or(f64::NAN) / 500.0
    );
    println!("  trace with the paper's signal names: {}", out.display());
    let ok = r.tx_ok_channel == 0b10 && r.received_by_node1.len() == 1;
    if ok {
        println!("PASS: the message reached node 1 once, on channel B");
        Ok(())
    } else {
        Err(CliError::Failed(format!(
            "DRCC demo: tx_ok_channel {:#04b}, node 1 received {:?}",
            r.tx_ok_channel, r.received_by_node1
        )))
    }
}
