//! `drcc serve`: checks the options, builds the network, binds the port (a port in
//! use is refused naming it), installs the Ctrl-C / SIGTERM handler that stops the
//! server cleanly (the export files are then completed and renamed into place),
//! and runs the server of `drcc_serve` on a network of `drcc_testbench::served`.

use std::net::{IpAddr, SocketAddr};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

use drcc_serve::{bind, serve, Network, Pacing, ServeOptions};
use drcc_testbench::served::{BusNetwork, DualNetwork, StarNetwork};
use drcc_testbench::{EngineKind, Scenario};

use super::traffic::{TrafficArgs, TrafficFiles};
use super::{check_outputs, CliError, CliResult};

/// The options of `drcc serve`, as parsed.
pub struct ServeArgs {
    pub scenario: Option<PathBuf>,
    pub port: u16,
    pub listen: String,
    pub topology: String,
    pub nodes: usize,
    pub engine: String,
    pub realtime: bool,
    pub beacon: bool,
    pub stop_after: Option<f64>,
    pub traffic: TrafficArgs,
}

fn engine(name: &str) -> Result<EngineKind, CliError> {
    name.parse::<EngineKind>().map_err(CliError::Error)
}

/// The network the options ask for.
fn network(a: &ServeArgs) -> Result<Box<dyn Network>, CliError> {
    let kind = engine(&a.engine)?;
    if let Some(path) = &a.scenario {
        if a.topology != "dual" || a.nodes != 4 {
            return Err(CliError::Error(
                "a scenario file gives its own bus of channels: drop --topology and --nodes, \
                 or drop the scenario to serve a dual bus or a star"
                    .into(),
            ));
        }
        let sc = Scenario::load(path).map_err(|e| CliError::Error(e.to_string()))?;
        return Ok(Box::new(BusNetwork::new(&sc, kind)?));
    }
    match a.topology.as_str() {
        "dual" => Ok(Box::new(DualNetwork::new(a.nodes, kind)?)),
        "star" => {
            if a.nodes != 4 {
                return Err(CliError::Error(format!(
                    "--nodes {}: the served star has the 4 node ports of the emitted hub; \
                     drop --nodes",
                    a.nodes
                )));
            }
            Ok(Box::new(StarNetwork::new(kind)?))
        }
        t => Err(CliError::Error(format!(
            "--topology {t}: give dual or star (or a scenario file for a bus of channels)"
        ))),
    }
}

/// `drcc serve`.
pub fn run(a: ServeArgs) -> CliResult {
    let ip: IpAddr = a.listen.parse().map_err(|_| {
        CliError::Error(format!(
            "--listen {}: give an IP address such as 127.0.0.1 (the default) or ::1",
            a.listen
        ))
    })?;
    if a.port == 0 {
        return Err(CliError::Error(
            "--port 0: give a port number 1..65535 (socketcand's is 29536)".into(),
        ));
    }
    let stop_after = match a.stop_after {
        None => None,
        Some(s) if s.is_finite() && s > 0.0 && s <= 1e7 => Some(Duration::from_secs_f64(s)),
        Some(s) => {
            return Err(CliError::Error(format!(
                "--stop-after {s}: give a number of seconds > 0"
            )))
        }
    };
    let inputs: Vec<&Path> = a.scenario.iter().map(PathBuf::as_path).collect();
    check_outputs(&inputs, &a.traffic.outputs())?;
    let mut net = network(&a)?;
    let addr = SocketAddr::new(ip, a.port);
    let listener = bind(addr).map_err(CliError::Error)?;
    let mut export = TrafficFiles::create(&a.traffic, net.clock_hz())?;
    let stop = Arc::new(AtomicBool::new(false));
    {
        let stop = stop.clone();
        ctrlc::set_handler(move || stop.store(true, Ordering::Relaxed))
            .map_err(|e| CliError::Error(format!("cannot install the Ctrl-C handler: {e}")))?;
    }
    let opts = ServeOptions {
        pacing: if a.realtime {
            Pacing::Realtime
        } else {
            Pacing::Fast
        },
        beacon: a.beacon,
        stop_after,
        progress: Some(Duration::from_secs(30)),
    };
    eprintln!(
        "drcc serve: {}; buses {}; socketcand on {addr}{}; {}; Ctrl-C stops",
        net.describe(),
        net.names().join(", "),
        if a.beacon { " with the beacon" } else { "" },
        if a.realtime {
            "simulated time follows the wall clock"
        } else {
            "as fast as the engine runs"
        }
    );
    let summary = serve(net.as_mut(), listener, &opts, stop, |events| {
        export.take(|batch| batch.extend_from_slice(events))
    })
    .map_err(CliError::Error)?;
    for (what, path) in export.commit()? {
        eprintln!("drcc serve: wrote the {what} {}", path.display());
    }
    eprintln!(
        "drcc serve: stopped after {} clocks ({} s simulated): {} frames delivered, {} error \
         frames, {} connections",
        summary.cycles,
        drcc_serve::protocol::timestamp(
            (summary.cycles as u128 * 1_000_000_000 / net.clock_hz() as u128) as u64
        ),
        summary.frames,
        summary.errors,
        summary.clients
    );
    Ok(())
}
