//! `drcc`: the command-line tool of the DRCC project.
//!
//! - `generate` writes the Verilog of every top into `rtl-out/` (`--check`
//!   compares instead and names stale files),
//! - `sim` runs a scenario on one engine, `cosim` on two in lock step,
//! - `wave-diff` compares two VCD files,
//! - `demo` runs the bundled demo scenario, `bench` compares engine speeds,
//! - `coverage` prints the functional coverage bins and their counts,
//! - `dmr` runs the CiA 701 DMR test plan (`table` or one fault row),
//! - `synth` synthesises a top for an FPGA family (yosys; nextpnr and icepack
//!   for iCE40) and reports its area and Fmax.
//!
//! Exit codes: 0 success; 1 a check failed (expectations not met, divergence,
//! waveforms differ, stale Verilog); 2 an error (bad input, missing tool). Errors
//! print one clear message, never a panic or a backtrace.

mod cli;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Dual-redundancy CAN 2.0B controller: generate Verilog, simulate, co-simulate,
/// compare waveforms.
#[derive(Parser, Debug)]
#[command(name = "drcc", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Write `<top>.v` for every top into rtl-out/ (or check it is up to date).
    Generate {
        /// Output directory (default: rtl-out/ of the workspace).
        #[arg(long, value_name = "DIR")]
        out: Option<PathBuf>,
        /// Compare with the files on disk instead of writing; fail naming stale files.
        #[arg(long)]
        check: bool,
        /// Generate only the DRCC of one configuration: default, m0, small, or a
        /// TOML file (name, mailboxes, rx_fifo_depth, tx_queue_depth, history).
        #[arg(long, value_name = "NAME|FILE")]
        config: Option<String>,
    },
    /// Run a scenario on one engine and check its expected deliveries.
    Sim {
        /// Scenario file (TOML).
        scenario: PathBuf,
        /// Engine: model, rust-hdl or verilator.
        #[arg(long, default_value = "model")]
        engine: String,
        /// Write the full trace (clk, bus, every node's signals and probes).
        #[arg(long, value_name = "FILE")]
        vcd: Option<PathBuf>,
        /// Write the bus-only trace (1-bit signals, for sigrok / PulseView).
        #[arg(long, value_name = "FILE")]
        bus_vcd: Option<PathBuf>,
        #[command(flatten)]
        traffic: cli::traffic::TrafficArgs,
    },
    /// Run a scenario on two engines in lock step and compare every clock.
    Cosim {
        /// Scenario file (TOML).
        scenario: PathBuf,
        /// The two engines, comma separated.
        #[arg(long, default_value = "model,verilator", value_name = "A,B")]
        engines: String,
        /// Where to write VCDs of both engines around a divergence.
        #[arg(long, value_name = "DIR")]
        vcd_dir: Option<PathBuf>,
        #[command(flatten)]
        traffic: cli::traffic::TrafficArgs,
    },
    /// Compare two VCD files and report the first difference.
    WaveDiff {
        /// First VCD file.
        a: PathBuf,
        /// Second VCD file.
        b: PathBuf,
        /// Compare only these signals (full name or dotted suffix: node0.tx, node1.field).
        #[arg(long = "signal", value_name = "S")]
        signals: Vec<String>,
    },
    /// Run the demo scenario (Verilator if available, else rust-hdl); writes out/demo_bus.vcd.
    Demo,
    /// DRCC redundancy scenarios on a dual bus: `paper` (Figs. 5-8), `switchover`
    /// (the benchmark table), `table` (the fault scenarios as Markdown), `ecss` (the ECSS
    /// bus-selection rows as Markdown), a fault (`cut_a`, `a_stuck_dominant`,
    /// `a_stuck_recessive`, `dead_transceiver`, `a_bus_off`, `no_fault`) or `all`.
    Redundancy {
        /// What to run.
        what: String,
        /// Engine: model or verilator.
        #[arg(long, default_value = "model")]
        engine: String,
        /// Also run this engine in lock step and compare every clock.
        #[arg(long, value_name = "ENGINE")]
        cosim: Option<String>,
        /// Switch policy of `paper`: error-passive (the default), none, k1 .. k15.
        #[arg(long)]
        policy: Option<String>,
        /// `paper` or a fault: write the trace with the paper's signal names
        /// (with `all`: one file per fault, named after it).
        #[arg(long, value_name = "FILE")]
        vcd: Option<PathBuf>,
        #[command(flatten)]
        traffic: cli::traffic::TrafficArgs,
    },
    /// DRCC nodes on a ReCANcentrate replicated star of two coupled hubs: `table` (the
    /// fault scenarios as Markdown), a fault (`uplink_stuck_dominant`, `uplink_bit_flipping`,
    /// `uplink_stuck_recessive`, `downlink_cut`, `sublink_stuck_dominant`, `interlink_lost`,
    /// `all_interlinks_lost`, `no_fault`) or `all`.
    Star {
        /// What to run.
        what: String,
        /// Engine: model, verilator, or rust-hdl (rust-hdl hubs with model nodes).
        #[arg(long, default_value = "model")]
        engine: String,
        /// Also run this engine in lock step and compare every clock.
        #[arg(long, value_name = "ENGINE")]
        cosim: Option<String>,
        /// With `table`: rewrite the table in docs/hub.md.
        #[arg(long)]
        markdown: bool,
        #[command(flatten)]
        traffic: cli::traffic::TrafficArgs,
    },
    /// REDCAN rings of DRCC nodes (seed 000) running the centralized algorithm on a
    /// CanKingdom King (seed 002): `table` (every single fault at every position, as
    /// Markdown) or one fault: `no_fault`, `section_open`, `section_short`,
    /// `babbling_idiot`, `node_crash` (at `--position`). A fault can run on two
    /// engines in lock step (`--cosim`) and export its traffic (`--candump`, `--pcap`).
    Ring {
        /// `table` or a fault.
        what: String,
        /// Ring sizes (ring nodes, 3..=10), comma-separated; one fault runs on the first.
        #[arg(long, default_value = "3,6,10")]
        nodes: String,
        /// The faulty section or ring node (node faults: 1.., ring node 0 is the master).
        #[arg(long, default_value_t = 1)]
        position: usize,
        /// Engine of the DRCC nodes and relay modules: model or verilator.
        #[arg(long, default_value = "model")]
        engine: String,
        /// REDCAN algorithm: centralized, distributed, or both (one fault: the first).
        #[arg(long, default_value = "both")]
        algorithm: String,
        /// With `table`: rewrite the table in docs/redcan.md.
        #[arg(long)]
        markdown: bool,
        /// One fault: run it again on this engine and compare every input and output
        /// of every DRCC node and every relay module output, every clock, with the
        /// `--engine` run (whose traffic `--candump` / `--pcap` export).
        #[arg(long, value_name = "ENGINE")]
        cosim: Option<String>,
        #[command(flatten)]
        traffic: cli::traffic::TrafficArgs,
    },
    /// The CiA 701 DMR test plan (seed Figure 9, Tables 2 and 3) on four DRCC devices
    /// COS1, COS2, COS3, COM1: `table` (every row as Markdown), or one row: a fault
    /// marker `F1` .. `F10` (F1..F8: a device disconnected from the DCL / RCL; F9 / F10:
    /// the DCL / RCL short-circuited) or `baseline`.
    Dmr {
        /// `table`, `baseline` or `F1` .. `F10`.
        what: String,
        /// The fault is present at power-on (the default).
        #[arg(long)]
        startup: bool,
        /// The fault arises at run time.
        #[arg(long)]
        runtime: bool,
        /// With `table`: rewrite the table in docs/dmr.md.
        #[arg(long)]
        markdown: bool,
        /// Engine: model or verilator (verilator runs with the model in lock step).
        #[arg(long, default_value = "model")]
        engine: String,
        /// Also run this engine in lock step and compare every clock.
        #[arg(long, value_name = "ENGINE")]
        cosim: Option<String>,
        /// One row: write its trace (every device's signals and probes).
        #[arg(long, value_name = "FILE")]
        vcd: Option<PathBuf>,
        /// DMR recovery delay in ms (default 200; the seed's is 2000).
        #[arg(long, value_name = "MS")]
        recovery_ms: Option<u16>,
        /// Deviation limit of every mailbox, 1..127 (default 3): a smaller one finds
        /// a line fault sooner (less extra latency) and tolerates less skew.
        #[arg(long, value_name = "N")]
        limit: Option<u8>,
        /// One row with first-copy delivery (`CTRL.first_copy`, DMR contract §8.1)
        /// instead of the seed's ACL rule; the table always has both.
        #[arg(long)]
        first_copy: bool,
    },
    /// Serve a simulated network over the socketcand protocol (python-can's
    /// `socketcand` interface and other tools): every node is a bus named after it.
    /// Without a scenario: four DRCC nodes in redundancy mode on a dual bus
    /// (`node0`..`node3`). Ctrl-C stops it. docs/serve.md describes the protocol,
    /// the `< fault ... >` command and the pacing.
    Serve {
        /// Scenario file (TOML): serve its bus of CAN channels, with its frames and
        /// faults as scheduled.
        scenario: Option<PathBuf>,
        /// TCP port (socketcand's default: 29536).
        #[arg(long, default_value_t = 29536)]
        port: u16,
        /// Address to listen on (default: localhost only).
        #[arg(long, default_value = "127.0.0.1", value_name = "ADDR")]
        listen: String,
        /// Without a scenario: `dual` (DRCC nodes on a dual bus) or `star` (DRCC nodes
        /// on a ReCANcentrate replicated star).
        #[arg(long, default_value = "dual")]
        topology: String,
        /// Nodes of the dual bus (2..=32).
        #[arg(long, default_value_t = 4)]
        nodes: usize,
        /// Engine: model or verilator (a scenario's bus also: rust-hdl).
        #[arg(long, default_value = "model")]
        engine: String,
        /// Pace simulated time with the wall clock (as far as the engine keeps up).
        #[arg(long, conflicts_with = "fast")]
        realtime: bool,
        /// Run as fast as the engine allows (the default).
        #[arg(long)]
        fast: bool,
        /// Announce the buses with socketcand's UDP discovery beacon (port 42000; to
        /// 127.0.0.1 when listening on localhost, else broadcast).
        #[arg(long)]
        beacon: bool,
        /// Stop after this many seconds of wall time.
        #[arg(long, value_name = "SECONDS")]
        stop_after: Option<f64>,
        #[command(flatten)]
        traffic: cli::traffic::TrafficArgs,
    },
    /// Random fault campaigns: `drcc campaign [options]` runs one (shard of a)
    /// campaign, `drcc campaign merge FILE...` sums result files, `drcc campaign
    /// replay FILE` runs a failing scenario again.
    Campaign {
        /// Nothing (run), `merge FILE...` or `replay FILE`.
        args: Vec<String>,
        /// Topology: dual, dmr, star or ecss.
        #[arg(long, default_value = "dual")]
        topology: String,
        /// Faults per scenario: single (judged) or double (reported).
        #[arg(long, default_value = "single")]
        faults: String,
        /// Scenarios in the whole campaign (all shards).
        #[arg(long, default_value_t = 1000)]
        count: u64,
        /// Seed: a scenario is named by its seed and index.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// This shard, i/n: the indices k with k mod n = i - 1.
        #[arg(long, value_name = "I/N")]
        shard: Option<String>,
        /// Worker threads (default: every core).
        #[arg(long)]
        jobs: Option<usize>,
        /// Write one JSON line per scenario here (a new file).
        #[arg(long, value_name = "FILE")]
        out: Option<PathBuf>,
        /// Engine: model or verilator.
        #[arg(long, default_value = "model")]
        engine: String,
    },
    /// Functional coverage: run the test suite's workloads on the model and print
    /// every coverage bin with its count (exit 1 if a bin is never hit).
    Coverage,
    /// Measure simulated clock cycles per second of every available engine.
    Bench {
        /// Seconds per measurement.
        #[arg(long, default_value_t = 1.0)]
        seconds: f64,
    },
    /// Synthesise a top with yosys (iCE40: also nextpnr and icepack): LUTs, FFs, BRAM, Fmax.
    Synth {
        /// FPGA family and board: ice40 (iCEBreaker), ice40hx (iCE40-HX8K Breakout),
        /// xc3s (Spartan-3 Starter Board) or xc7 (Arty A7-35T).
        #[arg(long, value_name = "FAMILY")]
        target: Option<String>,
        /// Top to synthesise (default: can_channel, the first top).
        #[arg(long, value_name = "NAME")]
        top: Option<String>,
        /// Every top on every family.
        #[arg(long)]
        all: bool,
        /// With --all: rewrite docs/synthesis.md (the results table, the area by block,
        /// the scan wrapper and the clock).
        #[arg(long)]
        markdown: bool,
        /// Print the results as JSON.
        #[arg(long)]
        json: bool,
        /// Also the area block by block (each block the top instantiates, or the
        /// DRCC core it wraps, kept apart in one more yosys run; a block used
        /// twice counts twice); --all --markdown always has it on ice40.
        #[arg(long)]
        breakdown: bool,
        /// Where netlists, logs, the scan wrapper and bitstreams go (default: out/synth).
        #[arg(long, value_name = "DIR")]
        build_dir: Option<PathBuf>,
        /// Minutes nextpnr may place and route one top (1 to 600, default 20); a
        /// top still routing then is reported as not routed.
        #[arg(long, value_name = "MINUTES")]
        pnr_minutes: Option<u64>,
    },
}

fn main() -> ExitCode {
    cli::install_panic_hook();
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => e.exit(),
    };
    match run(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => e.report(),
    }
}

/// Runs one subcommand: the tools (generate, sim, cosim, wave-diff, demo, bench,
/// coverage, synth) here, the systems' commands in [`run_system`].
fn run(command: Command) -> cli::CliResult {
    match command {
        Command::Generate {
            out,
            check,
            config: Some(spec),
        } => cli::generate::run_config(&spec, out, check),
        Command::Generate {
            out,
            check,
            config: None,
        } => cli::generate::run(out, check),
        Command::Sim {
            scenario,
            engine,
            vcd,
            bus_vcd,
            traffic,
        } => cli::run::sim(
            &scenario,
            &engine,
            vcd.as_deref(),
            bus_vcd.as_deref(),
            &traffic,
        ),
        Command::Cosim {
            scenario,
            engines,
            vcd_dir,
            traffic,
        } => cli::run::cosim(&scenario, &engines, vcd_dir, &traffic),
        Command::WaveDiff { a, b, signals } => cli::wave::diff(&a, &b, &signals),
        Command::Demo => cli::run::demo(),
        Command::Bench { seconds } => cli::bench(seconds),
        Command::Coverage => cli::coverage(),
        Command::Synth {
            target,
            top,
            all,
            markdown,
            json,
            breakdown,
            build_dir,
            pnr_minutes,
        } => cli::synth::run(cli::synth::SynthArgs {
            target,
            top,
            all,
            json,
            markdown,
            breakdown,
            build_dir,
            pnr_minutes,
        }),
        command => run_system(command),
    }
}

/// Runs a command of the seed systems and their tables: redundancy, star, serve,
/// ring, dmr, campaign.
fn run_system(command: Command) -> cli::CliResult {
    match command {
        Command::Redundancy {
            what,
            engine,
            cosim,
            policy,
            vcd,
            traffic,
        } => cli::redundancy::run(
            &what,
            &engine,
            cosim.as_deref(),
            policy.as_deref(),
            vcd.as_deref(),
            &traffic,
        ),
        Command::Star {
            what,
            engine,
            cosim,
            markdown,
            traffic,
        } => cli::star::run(&what, &engine, cosim.as_deref(), markdown, &traffic),
        Command::Serve {
            scenario,
            port,
            listen,
            topology,
            nodes,
            engine,
            realtime,
            fast: _,
            beacon,
            stop_after,
            traffic,
        } => cli::serve::run(cli::serve::ServeArgs {
            scenario,
            port,
            listen,
            topology,
            nodes,
            engine,
            realtime,
            beacon,
            stop_after,
            traffic,
        }),
        Command::Ring {
            what,
            nodes,
            position,
            engine,
            algorithm,
            markdown,
            cosim,
            traffic,
        } => cli::ring::run_ring(&cli::ring::RingArgs {
            what: &what,
            nodes: &nodes,
            position,
            engine: &engine,
            algorithm: &algorithm,
            markdown,
            cosim: cosim.as_deref(),
            traffic: &traffic,
        }),
        Command::Dmr {
            what,
            startup,
            runtime,
            markdown,
            engine,
            cosim,
            vcd,
            recovery_ms,
            limit,
            first_copy,
        } => cli::dmr::run(&cli::dmr::DmrArgs {
            what: &what,
            startup,
            runtime,
            markdown,
            engine: &engine,
            cosim: cosim.as_deref(),
            vcd: vcd.as_deref(),
            recovery_ms,
            limit,
            first_copy,
        }),
        Command::Campaign {
            args,
            topology,
            faults,
            count,
            seed,
            shard,
            jobs,
            out,
            engine,
        } => cli::campaign::run(&cli::campaign::CampaignArgs {
            args: &args,
            topology: &topology,
            faults: &faults,
            count,
            seed,
            shard: shard.as_deref(),
            jobs,
            out: out.as_deref(),
            engine: &engine,
        }),
        _ => unreachable!("run sends only the systems' commands here"),
    }
}
