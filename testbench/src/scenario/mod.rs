//! The scenario format (TOML) and its loader.
//!
//! ```toml
//! name = "demo"
//! description = "three nodes, base and extended frames"
//! clock_hz = 8_000_000
//! bitrate = 500_000            # or a [timing] table (not both)
//! nodes = ["ecu", "gateway", "sensor"]   # or a count: nodes = 3 (named node0..)
//! max_ms = 20                  # optional; or max_bits / max_cycles
//! reset_cycles = 4             # optional
//! mode = "normal"              # optional: normal | listen_only | self_test | loopback
//! ewl = 96                     # optional: error warning limit 0..=255 (default 96)
//! single_shot = false          # optional: no automatic retransmission
//!
//! [timing]                     # explicit bit timing instead of `bitrate`
//! brp = 0                      # 0..=1023: one tq = brp+1 clocks
//! tseg1 = 12                   # 1..=16 tq
//! tseg2 = 3                    # 1..=8 tq
//! sjw = 3                      # 1..=4, <= tseg2 (default min(4, tseg2))
//! triple_sampling = false
//!
//! [[node_config]]              # optional, per node: overrides mode / ewl / single_shot
//! node = "sensor"
//! mode = "listen_only"
//!
//! [[frame]]                    # frames are numbered 0, 1, ... in file order
//! node = "ecu"                 # sender: name or index
//! at_bit = 20                  # due time: at_bit (bit times) or at_cycle; default 0
//! id = 0x123
//! extended = false             # 29-bit identifier
//! remote = false               # remote frame (no data)
//! dlc = 2                      # 0..=15; default: number of data bytes
//! data = [0x11, 0x22]          # min(dlc, 8) bytes; none for remote frames
//!
//! [[expect]]                   # optional; default: every frame is sent once by its
//! node = "gateway"             # sender and delivered once to every other node
//! receives = [0, 2]            # frame numbers this node must receive (any order)
//! sends = []                   # frame numbers this node must send (tx_done)
//! fails = []                   # frame numbers dropped with tx_failed (single shot,
//!                              # abort, listen-only); not checked when absent
//!
//! [[abort]]                    # optional: a one-clock tx_abort (timing contract §8)
//! node = "ecu"
//! at_bit = 60                  # or at_cycle
//!
//! [[fault]]                    # optional
//! kind = "stuck_dominant"      # stuck_dominant | stuck_recessive | flip
//! target = "rx"                # bus (default) | tx | rx
//! node = "sensor"              # for tx / rx
//! at_bit = 400                 # or at_cycle
//! bits = 2                     # duration: bits or cycles; default 1 bit
//! ```
//!
//! Errors name the file, the line and the field (`demo.toml:14: frame[1].dlc: ...`);
//! bit-timing errors name the field and its legal range.
//!
//! The default expectation assumes every node transmits normally; with
//! listen-only or loop-back nodes, or single shot, give [[expect]] lists.

use std::fmt;
use std::ops::Range;
use std::path::Path;

use drcc_cosim::bus::{Fault, FaultKind, FaultTarget};
use drcc_cosim::system::DEFAULT_RESET_CYCLES;
use drcc_cosim::{BitTiming, ControllerConfig, Frame, Mode};
use serde::Deserialize;
use toml::Spanned;

use crate::bitrate;

mod error;
mod fields;
mod loader;
mod raw;
mod to_toml;

pub use error::ScenarioError;
use error::{field_at, friendly, line_of};
use loader::Loader;
use raw::*;

/// The longest run a scenario may ask for, in clock cycles (about 5 minutes of
/// the model on one core for a few nodes): a due time, a fault or a run limit
/// beyond it is refused instead of running for days.
pub const MAX_RUN_CYCLES: u64 = 1_000_000_000;

/// The largest scenario file read (a scenario is a small TOML file; `drcc sim
/// /dev/zero` must not read without end).
pub const MAX_SCENARIO_BYTES: u64 = 1 << 20;

/// The largest clock, 1 GHz: far above any FPGA clock of a CAN controller, and a
/// trace keeps every clock edge apart (its timescale is 1 ns up to 250 MHz, 1 ps
/// above: a half period of 500 ps is 500 steps), which a clock of terahertz would
/// not.
pub const MAX_CLOCK_HZ: u64 = 1_000_000_000;

/// A frame to send: by whom, when, what.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScheduledFrame {
    /// Sending node.
    pub node: usize,
    /// Clock cycle from which the frame may be requested.
    pub at_cycle: u64,
    /// The frame.
    pub frame: Frame,
    /// Requested single shot (`tx_single`, timing contract §8): dropped at its
    /// first failed attempt whatever the node's configuration.
    pub single_shot: bool,
}

/// A one-clock `tx_abort` request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScheduledAbort {
    /// The node.
    pub node: usize,
    /// Clock cycle of the pulse (raised at the first cycle after reset if earlier).
    pub at_cycle: u64,
}

/// What one node must receive and send.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NodeExpectation {
    /// Node index.
    pub node: usize,
    /// Frame numbers it must receive, each exactly once (None: not checked).
    pub receives: Option<Vec<usize>>,
    /// Frame numbers it must send (`tx_done`), each exactly once (None: not checked).
    pub sends: Option<Vec<usize>>,
    /// Frame numbers it must drop (`tx_failed`), each exactly once (None: not checked).
    pub fails: Option<Vec<usize>>,
}

/// Expected outcome of a scenario.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Expectations {
    /// Every frame is sent once by its sender and received once by every other node.
    EveryFrameToEveryOtherNode,
    /// Per-node lists; nodes not listed are not checked.
    Explicit(Vec<NodeExpectation>),
}

/// A loaded, checked scenario.
#[derive(Clone, Debug, PartialEq)]
pub struct Scenario {
    /// Name.
    pub name: String,
    /// One-line description.
    pub description: String,
    /// Where it came from (file path, or a generator description).
    pub source: String,
    /// Clock frequency of every node.
    pub clock_hz: u64,
    /// The shared bit timing.
    pub timing: BitTiming,
    /// Node names (index = node number).
    pub nodes: Vec<String>,
    /// Controller configuration per node (index = node number): mode, error
    /// warning limit, single shot.
    pub configs: Vec<ControllerConfig>,
    /// Frames, numbered by position.
    pub frames: Vec<ScheduledFrame>,
    /// Expected deliveries.
    pub expect: Expectations,
    /// Injected faults.
    pub faults: Vec<Fault>,
    /// Host aborts.
    pub aborts: Vec<ScheduledAbort>,
    /// Cycle limit of a run.
    pub max_cycles: u64,
    /// Reset cycles at the start.
    pub reset_cycles: u64,
}

impl Scenario {
    /// Bit rate in bit/s.
    pub fn bitrate(&self) -> f64 {
        self.clock_hz as f64 / self.timing.clocks_per_bit() as f64
    }

    /// Clocks per bit.
    pub fn clocks_per_bit(&self) -> u64 {
        self.timing.clocks_per_bit() as u64
    }

    /// Node index of a name.
    pub fn node_index(&self, name: &str) -> Option<usize> {
        self.nodes.iter().position(|n| n == name)
    }

    /// A default cycle limit: the last due time plus a generous budget per frame.
    pub fn default_max_cycles(frames: &[ScheduledFrame], clocks_per_bit: u64) -> u64 {
        let last = frames.iter().map(|f| f.at_cycle).max().unwrap_or(0);
        let budget_bits = (frames.len() as u64)
            .saturating_mul(300)
            .saturating_add(1000);
        last.saturating_add(budget_bits.saturating_mul(clocks_per_bit))
    }

    /// Loads and checks a scenario file.
    pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
        use std::io::Read;
        let file = path.display().to_string();
        let err = |message: String| ScenarioError {
            file: file.clone(),
            line: None,
            field: None,
            message,
        };
        let mut bytes = Vec::new();
        std::fs::File::open(path)
            .and_then(|f| f.take(MAX_SCENARIO_BYTES + 1).read_to_end(&mut bytes))
            .map_err(|e| err(format!("cannot read the scenario file: {e}")))?;
        if bytes.len() as u64 > MAX_SCENARIO_BYTES {
            return Err(err(format!(
                "larger than {MAX_SCENARIO_BYTES} bytes: a scenario is a small TOML file; \
                 give one (see README.md, \"Scenario format\")"
            )));
        }
        let text = String::from_utf8(bytes).map_err(|e| {
            err(format!(
                "not UTF-8 text (byte {}): give a TOML file",
                e.utf8_error().valid_up_to()
            ))
        })?;
        Scenario::parse(&text, &file)
    }

    /// Parses and checks scenario text; `file` names it in errors.
    pub fn parse(text: &str, file: &str) -> Result<Scenario, ScenarioError> {
        let raw: RawScenario = toml::from_str(text).map_err(|e| {
            // a missing key has no place of its own: serde reports the table that
            // lacks it (for the top level the whole document, i.e. line 1 and
            // whatever key is there), so name the key and the table
            if let Some(key) = e
                .message()
                .strip_prefix("missing field `")
                .and_then(|m| m.split('`').next())
            {
                let table = e
                    .span()
                    .filter(|s| s.start > 0)
                    .and_then(|s| field_at(text, s.start).map(|f| (line_of(text, s.start), f)));
                let (line, field, place) = match table {
                    Some((l, t)) => {
                        let t = t.split('.').next().unwrap_or(&t).to_string();
                        (Some(l), Some(format!("{t}.{key}")), format!("in {t}"))
                    }
                    None => (None, Some(key.to_string()), "at the top level".to_string()),
                };
                return ScenarioError {
                    file: file.to_string(),
                    line,
                    field,
                    message: format!(
                        "missing: `{key}` is required {place} (see README.md, \"Scenario format\")"
                    ),
                };
            }
            let span = e.span();
            let (line, field) = match &span {
                Some(s) => (Some(line_of(text, s.start)), field_at(text, s.start)),
                None => (None, None),
            };
            ScenarioError {
                file: file.to_string(),
                line,
                field,
                message: friendly(e.message()),
            }
        })?;
        Loader { text, file }.resolve(raw)
    }
}

/// The scenario spelling of a mode.
pub fn mode_name(m: Mode) -> &'static str {
    match m {
        Mode::Normal => "normal",
        Mode::ListenOnly => "listen_only",
        Mode::SelfTest => "self_test",
        Mode::Loopback => "loopback",
    }
}
