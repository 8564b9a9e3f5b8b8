//! `--candump FILE` and `--pcap FILE` of `sim`, `cosim`, `redundancy`, `star`,
//! `ring` and `serve`: the options, and the files they write (through
//! [`AtomicFile`]: a run that fails half way leaves any older file as it was) from
//! the events of a traffic tap (`drcc_cosim::traffic`).

use std::io::Write;
use std::path::{Path, PathBuf};

use drcc_cosim::traffic::candump::CandumpWriter;
use drcc_cosim::traffic::pcap::PcapWriter;
use drcc_cosim::traffic::TrafficEvent;

use super::{AtomicFile, CliError};

/// The traffic export options, shared by the commands that run a network.
#[derive(clap::Args, Clone, Debug, Default)]
pub struct TrafficArgs {
    /// Write every frame each node delivered, and the error frames of every error
    /// and error-state change, as a candump log in simulated time:
    /// `(0.000123) node0 123#DEADBEEF`. Interfaces: `nodeN` on a bus of channels
    /// or a REDCAN ring, `nodeNa` / `nodeNb` for line A / B of a dual bus or star.
    /// Name it `*.log` for python-can's `can.LogReader`.
    #[arg(long, value_name = "FILE")]
    pub candump: Option<PathBuf>,
    /// Write the same events as a pcap file (LINKTYPE_CAN_SOCKETCAN, nanosecond
    /// timestamps) for Wireshark and tshark. The link type has no interface name:
    /// record n is line n of the candump log, which names node and line.
    #[arg(long, value_name = "FILE")]
    pub pcap: Option<PathBuf>,
}

impl TrafficArgs {
    /// The options given, with their paths (for `check_outputs`).
    pub fn outputs(&self) -> Vec<(&'static str, &Path)> {
        [("--candump", &self.candump), ("--pcap", &self.pcap)]
            .into_iter()
            .filter_map(|(o, p)| p.as_deref().map(|p| (o, p)))
            .collect()
    }

    /// [`TrafficArgs::outputs`] with owned paths.
    pub fn owned_outputs(&self) -> Vec<(&'static str, PathBuf)> {
        let outputs = self.outputs().into_iter();
        outputs.map(|(o, p)| (o, p.to_path_buf())).collect()
    }

    /// The files of one run among several (`all`): `t.log` becomes `t_<run>.log`.
    pub fn for_run(&self, run: &str) -> TrafficArgs {
        TrafficArgs {
            candump: self.candump.as_deref().map(|p| suffixed(p, run)),
            pcap: self.pcap.as_deref().map(|p| suffixed(p, run)),
        }
    }

    /// The files of fault `fault` when running `what`: named after the fault with
    /// `all` (one file per fault), as given for a single fault.
    pub fn for_fault(&self, what: &str, fault: &str) -> TrafficArgs {
        match what {
            "all" => self.for_run(fault),
            _ => self.clone(),
        }
    }

    /// Refuses the options for `what`, a command that writes no traffic.
    pub fn refuse(&self, what: &str, instead: &str) -> Result<(), CliError> {
        match self.outputs().first() {
            None => Ok(()),
            Some((opt, path)) => Err(CliError::Error(format!(
                "{opt} {}: `{what}` runs many scenarios and exports no traffic; give {instead}",
                path.display()
            ))),
        }
    }
}

/// [`check_outputs`](super::check_outputs) of outputs without an input (the
/// generated scenarios), with owned paths.
pub fn check_owned(outputs: &[(&'static str, PathBuf)]) -> Result<(), CliError> {
    let borrowed: Vec<(&str, &Path)> = outputs.iter().map(|(o, p)| (*o, p.as_path())).collect();
    super::check_outputs(&[], &borrowed)
}

/// `path` with `_<run>` added to its stem, the extension kept.
fn suffixed(path: &Path, run: &str) -> PathBuf {
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("traffic");
    let name = match path.extension().and_then(|e| e.to_str()) {
        Some(ext) => format!("{stem}_{run}.{ext}"),
        None => format!("{stem}_{run}"),
    };
    path.with_file_name(name)
}

/// The export files of one run, being written.
pub struct TrafficFiles {
    candump: Option<(PathBuf, CandumpWriter<AtomicFile>)>,
    pcap: Option<(PathBuf, PcapWriter<AtomicFile>)>,
    batch: Vec<TrafficEvent>,
}

impl TrafficFiles {
    /// Creates the files `args` names (temporary until [`TrafficFiles::commit`]);
    /// events are timed by `clock_hz`. A file that cannot be created is named with
    /// its option.
    pub fn create(args: &TrafficArgs, clock_hz: u64) -> Result<Self, CliError> {
        let open = |opt: &str, path: &Path| {
            AtomicFile::create(path).map_err(|e| match e {
                CliError::Error(m) | CliError::Failed(m) => {
                    CliError::Error(format!("{opt} {}: {m}", path.display()))
                }
            })
        };
        let candump = match args.candump.as_deref() {
            Some(p) => Some((
                p.to_path_buf(),
                CandumpWriter::new(open("--candump", p)?, clock_hz),
            )),
            None => None,
        };
        let pcap = match args.pcap.as_deref() {
            Some(p) => {
                let w =
                    PcapWriter::new(open("--pcap", p)?, clock_hz).map_err(|e| write_error(p, e))?;
                Some((p.to_path_buf(), w))
            }
            None => None,
        };
        Ok(TrafficFiles {
            candump,
            pcap,
            batch: Vec::new(),
        })
    }

    /// No file: a run that exports nothing.
    pub fn none() -> Self {
        TrafficFiles {
            candump: None,
            pcap: None,
            batch: Vec::new(),
        }
    }

    /// Whether no file is written (the tap need not run).
    pub fn is_empty(&self) -> bool {
        self.candump.is_none() && self.pcap.is_none()
    }

    /// Lets `tap` append the new events and writes them to every file.
    pub fn take(&mut self, tap: impl FnOnce(&mut Vec<TrafficEvent>)) -> Result<(), String> {
        if self.is_empty() {
            return Ok(());
        }
        tap(&mut self.batch);
        for ev in &self.batch {
            if let Some((p, w)) = self.candump.as_mut() {
                w.write(ev).map_err(|e| write_message(p, e))?;
            }
            if let Some((p, w)) = self.pcap.as_mut() {
                w.write(ev).map_err(|e| write_message(p, e))?;
            }
        }
        self.batch.clear();
        Ok(())
    }

    /// Renames the files into place; returns what was written, for the report.
    pub fn commit(self) -> Result<Vec<(&'static str, PathBuf)>, CliError> {
        let mut written = Vec::new();
        if let Some((p, w)) = self.candump {
            finish(w.into_inner(), &p)?;
            written.push(("candump log", p));
        }
        if let Some((p, w)) = self.pcap {
            finish(w.into_inner(), &p)?;
            written.push(("pcap", p));
        }
        Ok(written)
    }
}

fn finish(mut f: AtomicFile, path: &Path) -> Result<(), CliError> {
    f.flush().map_err(|e| write_error(path, e))?;
    f.commit()
}

fn write_message(path: &Path, e: std::io::Error) -> String {
    format!("cannot write {}: {e}", path.display())
}

fn write_error(path: &Path, e: std::io::Error) -> CliError {
    CliError::Error(write_message(path, e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_run_among_several_gets_its_name_in_the_stem() {
        let a = TrafficArgs {
            candump: Some(PathBuf::from("out/t.log")),
            pcap: Some(PathBuf::from("cap")),
        };
        let r = a.for_run("cut_a");
        assert_eq!(r.candump, Some(PathBuf::from("out/t_cut_a.log")));
        assert_eq!(r.pcap, Some(PathBuf::from("cap_cut_a")));
    }
}
