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
//! brp = 0                      # 0..=63: one tq = brp+1 clocks
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

/// A frame to send: by whom, when, what.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScheduledFrame {
    /// Sending node.
    pub node: usize,
    /// Clock cycle from which the frame may be requested.
    pub at_cycle: u64,
    /// The frame.
    pub frame: Frame,
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
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ScenarioError {
            file: file.clone(),
            line: None,
            field: None,
            message: format!("cannot read the scenario file: {e}"),
        })?;
        Scenario::parse(&text, &file)
    }

    /// Parses and checks scenario text; `file` names it in errors.
    pub fn parse(text: &str, file: &str) -> Result<Scenario, ScenarioError> {
        let raw: RawScenario = toml::from_str(text).map_err(|e| {
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

    /// The scenario as TOML (frames with `at_cycle`), loadable with
    /// [`Scenario::parse`]; used to save generated scenarios for `drcc sim`.
    pub fn to_toml(&self) -> String {
        use std::fmt::Write;
        let mut s = String::new();
        let q = |x: &str| toml::Value::String(x.to_string()).to_string();
        let _ = writeln!(s, "name = {}", q(&self.name));
        let _ = writeln!(s, "description = {}", q(&self.description));
        let _ = writeln!(s, "clock_hz = {}", self.clock_hz);
        let nodes: Vec<String> = self.nodes.iter().map(|n| q(n)).collect();
        let _ = writeln!(s, "nodes = [{}]", nodes.join(", "));
        let _ = writeln!(s, "max_cycles = {}", self.max_cycles);
        let _ = writeln!(s, "reset_cycles = {}", self.reset_cycles);
        // The configuration: as scenario keys when every node shares it, else per node.
        let same = self.configs.windows(2).all(|w| w[0] == w[1]);
        let default = ControllerConfig::default();
        let write_config = |s: &mut String, c: &ControllerConfig| {
            if c.mode != default.mode {
                let _ = writeln!(s, "mode = {}", q(mode_name(c.mode)));
            }
            if c.ewl != default.ewl {
                let _ = writeln!(s, "ewl = {}", c.ewl);
            }
            if c.single_shot != default.single_shot {
                let _ = writeln!(s, "single_shot = {}", c.single_shot);
            }
        };
        if same {
            if let Some(c) = self.configs.first() {
                write_config(&mut s, c);
            }
        }
        let t = &self.timing;
        let _ = writeln!(
            s,
            "\n[timing]\nbrp = {}\ntseg1 = {}\ntseg2 = {}\nsjw = {}\ntriple_sampling = {}",
            t.brp, t.tseg1, t.tseg2, t.sjw, t.triple_sampling
        );
        if !same {
            for (name, c) in self.nodes.iter().zip(&self.configs) {
                if *c != default {
                    let _ = writeln!(s, "\n[[node_config]]\nnode = {}", q(name));
                    write_config(&mut s, c);
                }
            }
        }
        for (i, f) in self.frames.iter().enumerate() {
            let fr = &f.frame;
            let _ = writeln!(s, "\n[[frame]] # {i}");
            let _ = writeln!(s, "node = {}", q(&self.nodes[f.node]));
            let _ = writeln!(s, "at_cycle = {}", f.at_cycle);
            let _ = writeln!(s, "id = 0x{:X}", fr.id);
            let _ = writeln!(s, "extended = {}", fr.ide);
            let _ = writeln!(s, "remote = {}", fr.rtr);
            let _ = writeln!(s, "dlc = {}", fr.dlc);
            if !fr.rtr {
                let d: Vec<String> = fr.data[..fr.data_len()]
                    .iter()
                    .map(|b| format!("0x{b:02X}"))
                    .collect();
                let _ = writeln!(s, "data = [{}]", d.join(", "));
            }
        }
        if let Expectations::Explicit(list) = &self.expect {
            for e in list {
                let _ = writeln!(s, "\n[[expect]]\nnode = {}", q(&self.nodes[e.node]));
                if let Some(r) = &e.receives {
                    let _ = writeln!(s, "receives = {r:?}");
                }
                if let Some(r) = &e.sends {
                    let _ = writeln!(s, "sends = {r:?}");
                }
                if let Some(r) = &e.fails {
                    let _ = writeln!(s, "fails = {r:?}");
                }
            }
        }
        for a in &self.aborts {
            let _ = writeln!(
                s,
                "\n[[abort]]\nnode = {}\nat_cycle = {}",
                q(&self.nodes[a.node]),
                a.at_cycle
            );
        }
        for f in &self.faults {
            let _ = writeln!(s, "\n[[fault]]\nkind = {}", q(f.kind.name()));
            match f.target {
                FaultTarget::Bus => {
                    let _ = writeln!(s, "target = \"bus\"");
                }
                FaultTarget::Tx(n) | FaultTarget::Rx(n) => {
                    let side = if matches!(f.target, FaultTarget::Tx(_)) {
                        "tx"
                    } else {
                        "rx"
                    };
                    let _ = writeln!(s, "target = \"{side}\"\nnode = {}", q(&self.nodes[n]));
                }
            }
            let _ = writeln!(s, "at_cycle = {}\ncycles = {}", f.start, f.cycles);
        }
        s
    }
}

/// A scenario error: file, line, field and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ScenarioError {
    /// The file.
    pub file: String,
    /// 1-based line, when known.
    pub line: Option<usize>,
    /// The field (`frame[1].dlc`, `timing.tseg1`, ...), when known.
    pub field: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let Some(l) = self.line {
            write!(f, ":{l}")?;
        }
        write!(f, ": ")?;
        if let Some(field) = &self.field {
            write!(f, "{field}: ")?;
        }
        write!(f, "{}", self.message)
    }
}

impl std::error::Error for ScenarioError {}

/// The scenario spelling of a mode.
pub fn mode_name(m: Mode) -> &'static str {
    match m {
        Mode::Normal => "normal",
        Mode::ListenOnly => "listen_only",
        Mode::SelfTest => "self_test",
        Mode::Loopback => "loopback",
    }
}

/// A TOML/serde message on one line, with integer types spelled as ranges.
fn friendly(msg: &str) -> String {
    let one_line: Vec<&str> = msg
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    one_line
        .join("; ")
        .replace("expected u8", "expected an integer 0..=255")
        .replace("expected u32", "expected an integer 0..=4294967295")
        .replace("expected u64", "expected a non-negative integer")
        .replace("expected usize", "expected a non-negative integer")
        .replace("expected i64", "expected an integer")
}

fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// The dotted field name at a byte offset: the enclosing table (`frame[2]`,
/// `timing`) and the key of the line, as far as they can be told from the text.
fn field_at(text: &str, offset: usize) -> Option<String> {
    let line_no = line_of(text, offset);
    let mut table: Option<String> = None;
    let mut counts: Vec<(String, usize)> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if i + 1 > line_no {
            break;
        }
        let t = line.trim();
        if let Some(rest) = t.strip_prefix("[[") {
            let name = rest.split("]]").next().unwrap_or("").trim().to_string();
            let n = match counts.iter_mut().find(|(k, _)| *k == name) {
                Some((_, c)) => {
                    *c += 1;
                    *c
                }
                None => {
                    counts.push((name.clone(), 0));
                    0
                }
            };
            table = Some(format!("{name}[{n}]"));
        } else if let Some(rest) = t.strip_prefix('[') {
            table = Some(rest.split(']').next().unwrap_or("").trim().to_string());
        }
    }
    let line = text.lines().nth(line_no - 1).unwrap_or("");
    let key = line
        .split_once('=')
        .map(|(k, _)| k.trim())
        .filter(|k| !k.is_empty() && !k.starts_with('[') && !k.starts_with('#'))
        .map(|k| k.trim_matches('"').to_string());
    match (table, key) {
        (Some(t), Some(k)) => Some(format!("{t}.{k}")),
        (None, Some(k)) => Some(k),
        (Some(t), None) => Some(t),
        (None, None) => None,
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScenario {
    name: Spanned<String>,
    description: Option<String>,
    clock_hz: Spanned<u64>,
    bitrate: Option<Spanned<u64>>,
    timing: Option<Spanned<RawTiming>>,
    nodes: Spanned<toml::Value>,
    #[serde(default)]
    frame: Vec<Spanned<RawFrame>>,
    expect: Option<Vec<Spanned<RawExpect>>>,
    #[serde(default)]
    fault: Vec<Spanned<RawFault>>,
    #[serde(default)]
    abort: Vec<Spanned<RawAbort>>,
    max_cycles: Option<Spanned<u64>>,
    max_bits: Option<Spanned<u64>>,
    max_ms: Option<Spanned<f64>>,
    reset_cycles: Option<Spanned<u64>>,
    mode: Option<Spanned<String>>,
    ewl: Option<Spanned<i64>>,
    single_shot: Option<bool>,
    #[serde(default)]
    node_config: Vec<Spanned<RawNodeConfig>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawNodeConfig {
    node: Spanned<toml::Value>,
    mode: Option<Spanned<String>>,
    ewl: Option<Spanned<i64>>,
    single_shot: Option<bool>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTiming {
    brp: Spanned<i64>,
    tseg1: Spanned<i64>,
    tseg2: Spanned<i64>,
    sjw: Option<Spanned<i64>>,
    #[serde(default)]
    triple_sampling: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFrame {
    node: Spanned<toml::Value>,
    at_cycle: Option<Spanned<u64>>,
    at_bit: Option<Spanned<u64>>,
    id: Spanned<i64>,
    #[serde(default)]
    extended: bool,
    #[serde(default)]
    remote: bool,
    dlc: Option<Spanned<i64>>,
    data: Option<Spanned<Vec<i64>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawExpect {
    node: Spanned<toml::Value>,
    receives: Option<Spanned<Vec<usize>>>,
    sends: Option<Spanned<Vec<usize>>>,
    fails: Option<Spanned<Vec<usize>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAbort {
    node: Spanned<toml::Value>,
    at_cycle: Option<Spanned<u64>>,
    at_bit: Option<Spanned<u64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFault {
    kind: Spanned<String>,
    target: Option<Spanned<String>>,
    node: Option<Spanned<toml::Value>>,
    at_cycle: Option<Spanned<u64>>,
    at_bit: Option<Spanned<u64>>,
    cycles: Option<Spanned<u64>>,
    bits: Option<Spanned<u64>>,
}

struct Loader<'a> {
    text: &'a str,
    file: &'a str,
}

impl Loader<'_> {
    fn err(&self, span: Range<usize>, field: &str, message: impl Into<String>) -> ScenarioError {
        ScenarioError {
            file: self.file.to_string(),
            line: Some(line_of(self.text, span.start)),
            field: Some(field.to_string()),
            message: message.into(),
        }
    }

    fn node_ref(
        &self,
        v: &Spanned<toml::Value>,
        names: &[String],
        field: &str,
    ) -> Result<usize, ScenarioError> {
        let n = names.len();
        match v.get_ref() {
            toml::Value::Integer(i) if *i >= 0 && (*i as u64) < n as u64 => Ok(*i as usize),
            toml::Value::Integer(i) => Err(self.err(
                v.span(),
                field,
                format!("node {i} does not exist: nodes are 0..={}", n - 1),
            )),
            toml::Value::String(s) => names.iter().position(|x| x == s).ok_or_else(|| {
                self.err(
                    v.span(),
                    field,
                    format!("no node named {s:?} (nodes: {})", names.join(", ")),
                )
            }),
            other => Err(self.err(
                v.span(),
                field,
                format!("expected a node name or index, found {}", other.type_str()),
            )),
        }
    }

    fn resolve(&self, raw: RawScenario) -> Result<Scenario, ScenarioError> {
        // Nodes.
        let names: Vec<String> = match raw.nodes.get_ref() {
            toml::Value::Integer(n) if (1..=64).contains(n) => {
                (0..*n).map(|i| format!("node{i}")).collect()
            }
            toml::Value::Integer(n) => {
                return Err(self.err(
                    raw.nodes.span(),
                    "nodes",
                    format!("{n} nodes: legal counts are 1..=64"),
                ))
            }
            toml::Value::Array(list) => {
                let mut v = Vec::new();
                for item in list {
                    match item {
                        toml::Value::String(s)
                            if !s.is_empty() && !s.contains(char::is_whitespace) =>
                        {
                            if v.contains(s) {
                                return Err(self.err(
                                    raw.nodes.span(),
                                    "nodes",
                                    format!("node name {s:?} appears twice"),
                                ));
                            }
                            v.push(s.clone());
                        }
                        _ => {
                            return Err(self.err(
                                raw.nodes.span(),
                                "nodes",
                                "node names must be non-empty strings without spaces",
                            ))
                        }
                    }
                }
                if v.is_empty() || v.len() > 64 {
                    return Err(self.err(
                        raw.nodes.span(),
                        "nodes",
                        format!("{} nodes: legal counts are 1..=64", v.len()),
                    ));
                }
                v
            }
            other => {
                return Err(self.err(
                    raw.nodes.span(),
                    "nodes",
                    format!(
                        "expected a node count or a list of names, found {}",
                        other.type_str()
                    ),
                ))
            }
        };

        // Clock and bit timing.
        let clock_hz = *raw.clock_hz.get_ref();
        if clock_hz == 0 {
            return Err(self.err(raw.clock_hz.span(), "clock_hz", "must be at least 1 Hz"));
        }
        let timing = match (&raw.bitrate, &raw.timing) {
            (Some(_), Some(t)) => {
                return Err(self.err(
                    t.span(),
                    "timing",
                    "give either `bitrate` or a [timing] table, not both",
                ))
            }
            (None, None) => {
                return Err(ScenarioError {
                    file: self.file.to_string(),
                    line: None,
                    field: Some("bitrate".to_string()),
                    message: "missing: give `bitrate` (bit/s) or a [timing] table".to_string(),
                })
            }
            (Some(b), None) => bitrate::solve(clock_hz, *b.get_ref())
                .map_err(|e| self.err(b.span(), "bitrate", e))?,
            (None, Some(t)) => self.timing(t.get_ref(), t.span())?,
        };
        let cpb = timing.clocks_per_bit() as u64;

        // Controller configuration: scenario keys, then per-node overrides.
        let base = self.config(
            ControllerConfig::default(),
            &raw.mode,
            &raw.ewl,
            raw.single_shot,
            "",
        )?;
        let mut configs = vec![base; names.len()];
        let mut configured: Vec<usize> = Vec::new();
        for (i, nc) in raw.node_config.iter().enumerate() {
            let nc = nc.get_ref();
            let field = format!("node_config[{i}]");
            let node = self.node_ref(&nc.node, &names, &format!("{field}.node"))?;
            if configured.contains(&node) {
                return Err(self.err(
                    nc.node.span(),
                    &format!("{field}.node"),
                    format!("node {:?} has two [[node_config]] entries", names[node]),
                ));
            }
            configured.push(node);
            configs[node] = self.config(
                base,
                &nc.mode,
                &nc.ewl,
                nc.single_shot,
                &format!("{field}."),
            )?;
        }

        // Frames.
        let mut frames = Vec::new();
        for (i, sf) in raw.frame.iter().enumerate() {
            frames.push(self.frame(i, sf, &names, cpb)?);
        }

        // Expectations.
        let expect = match &raw.expect {
            None => Expectations::EveryFrameToEveryOtherNode,
            Some(list) => {
                let mut v: Vec<NodeExpectation> = Vec::new();
                for (i, e) in list.iter().enumerate() {
                    let e = e.get_ref();
                    let node = self.node_ref(&e.node, &names, &format!("expect[{i}].node"))?;
                    if v.iter().any(|x| x.node == node) {
                        return Err(self.err(
                            e.node.span(),
                            &format!("expect[{i}].node"),
                            format!("node {:?} has two [[expect]] entries", names[node]),
                        ));
                    }
                    let check = |l: &Option<Spanned<Vec<usize>>>, what: &str| {
                        if let Some(l) = l {
                            if let Some(bad) = l.get_ref().iter().find(|&&k| k >= frames.len()) {
                                return Err(self.err(
                                    l.span(),
                                    &format!("expect[{i}].{what}"),
                                    format!(
                                        "frame {bad} does not exist: the file has {} frame(s), numbered from 0 in file order",
                                        frames.len()
                                    ),
                                ));
                            }
                        }
                        Ok(l.as_ref().map(|l| l.get_ref().clone()))
                    };
                    let receives = check(&e.receives, "receives")?;
                    let sends = check(&e.sends, "sends")?;
                    let fails = check(&e.fails, "fails")?;
                    v.push(NodeExpectation {
                        node,
                        receives,
                        sends,
                        fails,
                    });
                }
                Expectations::Explicit(v)
            }
        };

        // Faults.
        let mut faults = Vec::new();
        for (i, f) in raw.fault.iter().enumerate() {
            faults.push(self.fault(i, f.get_ref(), &names, cpb)?);
        }

        // Aborts.
        let mut aborts = Vec::new();
        for (i, a) in raw.abort.iter().enumerate() {
            let a = a.get_ref();
            let field = format!("abort[{i}]");
            aborts.push(ScheduledAbort {
                node: self.node_ref(&a.node, &names, &format!("{field}.node"))?,
                at_cycle: self.at(&a.at_cycle, &a.at_bit, &field, cpb)?,
            });
        }

        // Limits.
        let mut limits: Vec<(Range<usize>, &str)> = [
            raw.max_cycles.as_ref().map(|s| (s.span(), "max_cycles")),
            raw.max_bits.as_ref().map(|s| (s.span(), "max_bits")),
            raw.max_ms.as_ref().map(|s| (s.span(), "max_ms")),
        ]
        .into_iter()
        .flatten()
        .collect();
        limits.sort_by_key(|(sp, _)| sp.start);
        if let Some((span, name)) = limits.get(1) {
            return Err(self.err(
                span.clone(),
                name,
                "give at most one of `max_cycles`, `max_bits`, `max_ms`",
            ));
        }
        let max_cycles = if let Some(c) = &raw.max_cycles {
            *c.get_ref()
        } else if let Some(b) = &raw.max_bits {
            b.get_ref().saturating_mul(cpb)
        } else if let Some(ms) = &raw.max_ms {
            let v = *ms.get_ref();
            if !(v.is_finite() && v > 0.0) {
                return Err(self.err(ms.span(), "max_ms", "must be a positive number"));
            }
            (v * clock_hz as f64 / 1000.0).ceil() as u64
        } else {
            Scenario::default_max_cycles(&frames, cpb)
        };
        let reset_cycles = match &raw.reset_cycles {
            Some(r) if (1..=1000).contains(r.get_ref()) => *r.get_ref(),
            Some(r) => return Err(self.err(r.span(), "reset_cycles", "legal values are 1..=1000")),
            None => DEFAULT_RESET_CYCLES,
        };
        let name = raw.name.get_ref().trim().to_string();
        if name.is_empty() {
            return Err(self.err(raw.name.span(), "name", "must not be empty"));
        }
        Ok(Scenario {
            name,
            description: raw.description.unwrap_or_default(),
            source: self.file.to_string(),
            clock_hz,
            timing,
            nodes: names,
            configs,
            frames,
            expect,
            faults,
            aborts,
            max_cycles,
            reset_cycles,
        })
    }

    fn timing(&self, t: &RawTiming, span: Range<usize>) -> Result<BitTiming, ScenarioError> {
        // Legal ranges as BitTiming::validate() states them.
        let field = |v: &Spanned<i64>, name: &str, lo: i64, hi: i64| {
            let x = *v.get_ref();
            if (lo..=hi).contains(&x) {
                Ok(x as u8)
            } else {
                Err(self.err(
                    v.span(),
                    &format!("timing.{name}"),
                    format!(
                        "bit timing field `{name}` = {x} is out of range: legal values are {lo}..={hi}"
                    ),
                ))
            }
        };
        let tseg2 = field(&t.tseg2, "tseg2", 1, 8)?;
        let bt = BitTiming {
            brp: field(&t.brp, "brp", 0, 63)?,
            tseg1: field(&t.tseg1, "tseg1", 1, 16)?,
            tseg2,
            sjw: match &t.sjw {
                Some(s) => field(s, "sjw", 1, 4)?,
                None => tseg2.clamp(1, 4),
            },
            triple_sampling: t.triple_sampling,
        };
        let field_span = |name: &str| match name {
            "brp" => Some(t.brp.span()),
            "tseg1" => Some(t.tseg1.span()),
            "tseg2" => Some(t.tseg2.span()),
            "sjw" => t.sjw.as_ref().map(|s| s.span()),
            _ => None,
        };
        // validate() also refuses a TSEG1 shorter than 3 clocks, naming `tseg1`.
        if let Err(e) = bt.validate() {
            // The message names the field between backticks.
            let field = e.split('`').nth(1).unwrap_or("").to_string();
            let (sp, f) = match field_span(&field) {
                Some(sp) => (sp, format!("timing.{field}")),
                None => (span, "timing".to_string()),
            };
            return Err(self.err(sp, &f, e));
        }
        Ok(bt)
    }

    /// `base` with the given keys applied; `prefix` is `""` for the scenario keys
    /// or `node_config[i].`.
    fn config(
        &self,
        base: ControllerConfig,
        mode: &Option<Spanned<String>>,
        ewl: &Option<Spanned<i64>>,
        single_shot: Option<bool>,
        prefix: &str,
    ) -> Result<ControllerConfig, ScenarioError> {
        let mut c = base;
        if let Some(m) = mode {
            c.mode = match m.get_ref().as_str() {
                "normal" => Mode::Normal,
                "listen_only" => Mode::ListenOnly,
                "self_test" => Mode::SelfTest,
                "loopback" => Mode::Loopback,
                other => {
                    return Err(self.err(
                        m.span(),
                        &format!("{prefix}mode"),
                        format!(
                            "{other:?}: legal modes are normal, listen_only, self_test, loopback"
                        ),
                    ))
                }
            };
        }
        if let Some(e) = ewl {
            let v = *e.get_ref();
            if !(0..=255).contains(&v) {
                return Err(self.err(
                    e.span(),
                    &format!("{prefix}ewl"),
                    format!("{v} is out of range: legal values are 0..=255"),
                ));
            }
            c.ewl = v as u8;
        }
        if let Some(s) = single_shot {
            c.single_shot = s;
        }
        Ok(c)
    }

    fn at(
        &self,
        at_cycle: &Option<Spanned<u64>>,
        at_bit: &Option<Spanned<u64>>,
        field: &str,
        cpb: u64,
    ) -> Result<u64, ScenarioError> {
        match (at_cycle, at_bit) {
            (Some(_), Some(b)) => Err(self.err(
                b.span(),
                &format!("{field}.at_bit"),
                "give either `at_cycle` or `at_bit`, not both",
            )),
            (Some(c), None) => Ok(*c.get_ref()),
            (None, Some(b)) => Ok(b.get_ref().saturating_mul(cpb)),
            (None, None) => Ok(0),
        }
    }

    fn frame(
        &self,
        i: usize,
        sf: &Spanned<RawFrame>,
        names: &[String],
        cpb: u64,
    ) -> Result<ScheduledFrame, ScenarioError> {
        let f = sf.get_ref();
        let field = format!("frame[{i}]");
        let node = self.node_ref(&f.node, names, &format!("{field}.node"))?;
        let at_cycle = self.at(&f.at_cycle, &f.at_bit, &field, cpb)?;
        let id = *f.id.get_ref();
        let max_id: i64 = if f.extended { 0x1FFF_FFFF } else { 0x7FF };
        if !(0..=max_id).contains(&id) {
            return Err(self.err(
                f.id.span(),
                &format!("{field}.id"),
                format!(
                    "{} does not fit {} identifier: legal values are 0..=0x{max_id:X}{}",
                    if id < 0 {
                        id.to_string()
                    } else {
                        format!("0x{id:X}")
                    },
                    if f.extended { "a 29-bit" } else { "an 11-bit" },
                    if f.extended {
                        ""
                    } else {
                        " (set `extended = true` for 29-bit identifiers)"
                    }
                ),
            ));
        }
        let data_span = f.data.as_ref().map(|d| d.span()).unwrap_or(sf.span());
        let raw_data: Vec<i64> = f
            .data
            .as_ref()
            .map(|d| d.get_ref().clone())
            .unwrap_or_default();
        if let Some((k, b)) = raw_data
            .iter()
            .enumerate()
            .find(|(_, b)| !(0..=255).contains(*b))
        {
            return Err(self.err(
                data_span,
                &format!("{field}.data"),
                format!("byte {k} = {b} is out of range: legal values are 0..=255"),
            ));
        }
        let data: Vec<u8> = raw_data.iter().map(|&b| b as u8).collect();
        if f.remote && !data.is_empty() {
            return Err(self.err(
                data_span,
                &format!("{field}.data"),
                "a remote frame carries no data: remove `data` (use `dlc` for the requested length)",
            ));
        }
        if data.len() > 8 {
            return Err(self.err(
                data_span,
                &format!("{field}.data"),
                format!("{} bytes: a CAN 2.0 frame carries at most 8", data.len()),
            ));
        }
        let dlc = match &f.dlc {
            Some(d) if !(0..=15).contains(d.get_ref()) => {
                return Err(self.err(
                    d.span(),
                    &format!("{field}.dlc"),
                    format!("{} is out of range: legal values are 0..=15", d.get_ref()),
                ))
            }
            Some(d) => *d.get_ref() as u8,
            None => data.len() as u8,
        };
        let mut frame = Frame {
            id: id as u32,
            ide: f.extended,
            rtr: f.remote,
            dlc,
            data: [0; 8],
        };
        if !f.remote && data.len() != frame.data_len() {
            return Err(self.err(
                data_span,
                &format!("{field}.data"),
                format!(
                    "{} data bytes, but dlc = {dlc} needs {}",
                    data.len(),
                    frame.data_len()
                ),
            ));
        }
        frame.data[..data.len()].copy_from_slice(&data);
        Ok(ScheduledFrame {
            node,
            at_cycle,
            frame,
        })
    }

    fn fault(
        &self,
        i: usize,
        f: &RawFault,
        names: &[String],
        cpb: u64,
    ) -> Result<Fault, ScenarioError> {
        let field = format!("fault[{i}]");
        let kind = match f.kind.get_ref().as_str() {
            "stuck_dominant" => FaultKind::StuckDominant,
            "stuck_recessive" => FaultKind::StuckRecessive,
            "flip" => FaultKind::Flip,
            other => {
                return Err(self.err(
                    f.kind.span(),
                    &format!("{field}.kind"),
                    format!("{other:?}: legal kinds are stuck_dominant, stuck_recessive, flip"),
                ))
            }
        };
        let side = f.target.as_ref().map_or("bus", |t| t.get_ref().as_str());
        let node = match &f.node {
            Some(n) => Some(self.node_ref(n, names, &format!("{field}.node"))?),
            None => None,
        };
        let target_span = f.target.as_ref().map(|t| t.span()).unwrap_or(f.kind.span());
        let target = match (side, node) {
            ("bus", None) => FaultTarget::Bus,
            ("tx", Some(n)) => FaultTarget::Tx(n),
            ("rx", Some(n)) => FaultTarget::Rx(n),
            ("bus", Some(_)) => return Err(self.err(
                target_span,
                &format!("{field}.node"),
                "a fault on the bus has no node: set `target = \"tx\"` or `\"rx\"` to hit one node",
            )),
            ("tx" | "rx", None) => {
                return Err(self.err(
                    target_span,
                    &format!("{field}.node"),
                    format!("a fault on a node's {side} needs `node`"),
                ))
            }
            (other, _) => {
                return Err(self.err(
                    target_span,
                    &format!("{field}.target"),
                    format!("{other:?}: legal targets are bus, tx, rx"),
                ))
            }
        };
        let start = self.at(&f.at_cycle, &f.at_bit, &field, cpb)?;
        let cycles = match (&f.cycles, &f.bits) {
            (Some(_), Some(b)) => {
                return Err(self.err(
                    b.span(),
                    &format!("{field}.bits"),
                    "give either `cycles` or `bits`, not both",
                ))
            }
            (Some(c), None) => *c.get_ref(),
            (None, Some(b)) => b.get_ref().saturating_mul(cpb),
            (None, None) => cpb,
        };
        if cycles == 0 {
            let sp = f
                .cycles
                .as_ref()
                .or(f.bits.as_ref())
                .map(|s| s.span())
                .unwrap_or(f.kind.span());
            return Err(self.err(
                sp,
                &format!("{field}.cycles"),
                "a fault lasts at least 1 cycle",
            ));
        }
        Ok(Fault {
            target,
            kind,
            start,
            cycles,
        })
    }
}
