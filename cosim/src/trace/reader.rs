//! A VCD reader: every signal of a file with its full hierarchical name
//! (`tb.node0.field[4:0]`) and its value changes, for `wave-diff` and tests.
//!
//! Values are kept as strings of `0 1 x z`, MSB first, extended to the declared
//! width the way VCD defines it (a leading `0`/`1` extends with `0`, `x` with
//! `x`, `z` with `z`). Real and string values are kept as `r<value>` / `s<value>`.

use std::collections::HashMap;
use std::fs::File;
use std::io::{BufReader, Read};
use std::path::Path;

use vcd::{Command, IdCode, ScopeItem, TimescaleUnit, Value};

/// One signal of a trace.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TraceSignal {
    /// Full name: scopes, reference and index joined (`tb.node0.field[4:0]`).
    pub name: String,
    /// Declared width.
    pub width: u32,
    /// Value changes `(time, value)` in time order, one per time at most.
    pub changes: Vec<(u64, String)>,
}

impl TraceSignal {
    /// The value at `time` (the last change at or before it), if any.
    pub fn value_at(&self, time: u64) -> Option<&str> {
        let i = self.changes.partition_point(|(t, _)| *t <= time);
        i.checked_sub(1).map(|i| self.changes[i].1.as_str())
    }

    /// The name without a trailing `[msb:lsb]` index.
    pub fn base_name(&self) -> &str {
        match self.name.rfind('[') {
            Some(i) if self.name.ends_with(']') => &self.name[..i],
            _ => &self.name,
        }
    }

    /// Whether `pattern` names this signal: the full name or a dot-separated
    /// suffix of it, with or without the index (`node0.tx` names `tb.node0.tx`;
    /// `node0.field` names `tb.node0.field[4:0]`).
    pub fn matches(&self, pattern: &str) -> bool {
        let suffix_of = |name: &str| {
            name == pattern
                || (name.ends_with(pattern)
                    && name.as_bytes().get(name.len() - pattern.len() - 1) == Some(&b'.'))
        };
        suffix_of(&self.name) || suffix_of(self.base_name())
    }
}

/// A whole VCD file.
#[derive(Clone, Debug, PartialEq)]
pub struct Trace {
    /// The `$timescale` (default 1 ns if the file has none).
    pub timescale: (u32, TimescaleUnit),
    /// Every declared signal, in declaration order.
    pub signals: Vec<TraceSignal>,
    /// The last timestamp of the file.
    pub end_time: u64,
    /// The `$comment` of the header, if any.
    pub comment: Option<String>,
}

impl Trace {
    /// One time unit of this trace in femtoseconds.
    pub fn unit_fs(&self) -> u64 {
        let (n, unit) = self.timescale;
        let fs_per_unit = 1_000_000_000_000_000 / unit.divisor();
        n as u64 * fs_per_unit
    }

    /// The signals that `pattern` names (see [`TraceSignal::matches`]).
    pub fn find(&self, pattern: &str) -> Vec<&TraceSignal> {
        self.signals.iter().filter(|s| s.matches(pattern)).collect()
    }

    /// The clock frequency recorded by DRCC's writers in the header comment
    /// (`clock_hz=N`), if any.
    pub fn clock_hz(&self) -> Option<u64> {
        let c = self.comment.as_deref()?;
        let rest = &c[c.find("clock_hz=")? + "clock_hz=".len()..];
        let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
        digits.parse().ok()
    }

    /// The signal with exactly this full name.
    pub fn signal(&self, name: &str) -> Option<&TraceSignal> {
        self.signals.iter().find(|s| s.name == name)
    }
}

/// Reads a VCD file; errors name the file.
pub fn read_vcd(path: &Path) -> Result<Trace, String> {
    let f =
        File::open(path).map_err(|e| format!("cannot open VCD file {}: {e}", path.display()))?;
    read_vcd_from(BufReader::new(f), &path.display().to_string()).map_err(|e| {
        match file_end(path) {
            Some(end) => format!("{e}; {end}"),
            None => e,
        }
    })
}

/// Where a file that did not parse ends, so that a user sees a truncated file
/// for what it is: inside a line (cut) or after its last line.
fn file_end(path: &Path) -> Option<String> {
    let bytes = std::fs::read(path).ok()?;
    let lines = bytes.iter().filter(|&&b| b == b'\n').count();
    Some(match bytes.last() {
        Some(&last) if last != b'\n' => format!(
            "the file ends inside line {} (byte {}): it was cut or is still being written",
            lines + 1,
            bytes.len()
        ),
        _ => format!("the file ends after line {lines} (byte {})", bytes.len()),
    })
}

fn format_value(width: u32, v: &[Value]) -> String {
    let mut s: String = v.iter().map(|b| b.to_string()).collect();
    let w = width as usize;
    if s.len() < w {
        let fill = match s.chars().next() {
            Some('x') => 'x',
            Some('z') => 'z',
            _ => '0',
        };
        let pad: String = std::iter::repeat_n(fill, w - s.len()).collect();
        s = pad + &s;
    }
    s
}

fn collect(items: &[ScopeItem], prefix: &str, out: &mut Vec<(IdCode, TraceSignal)>) {
    for item in items {
        match item {
            ScopeItem::Scope(sc) => {
                let p = if prefix.is_empty() {
                    sc.identifier.clone()
                } else {
                    format!("{prefix}.{}", sc.identifier)
                };
                collect(&sc.children, &p, out);
            }
            ScopeItem::Var(v) => {
                let mut name = if prefix.is_empty() {
                    v.reference.clone()
                } else {
                    format!("{prefix}.{}", v.reference)
                };
                if let Some(idx) = v.index {
                    name.push_str(&idx.to_string());
                }
                out.push((
                    v.code,
                    TraceSignal {
                        name,
                        width: v.size,
                        changes: Vec::new(),
                    },
                ));
            }
        }
    }
}

/// Reads a VCD from any reader; `name` is used in error messages.
pub fn read_vcd_from<R: Read>(r: R, name: &str) -> Result<Trace, String> {
    let bad = |e: std::io::Error| format!("{name}: not a valid VCD file: {e}");
    let mut parser = vcd::Parser::new(r);
    let header = parser.parse_header().map_err(bad)?;
    let mut vars = Vec::new();
    collect(&header.items, "", &mut vars);
    let mut by_code: HashMap<IdCode, Vec<usize>> = HashMap::new();
    let mut signals = Vec::with_capacity(vars.len());
    for (i, (code, sig)) in vars.into_iter().enumerate() {
        by_code.entry(code).or_default().push(i);
        signals.push(sig);
    }
    let mut now = 0u64;
    let set = |signals: &mut Vec<TraceSignal>, code: IdCode, now: u64, v: String| {
        if let Some(idx) = by_code.get(&code) {
            for &i in idx {
                let ch = &mut signals[i].changes;
                match ch.last_mut() {
                    Some((t, val)) if *t == now => *val = v.clone(),
                    Some((_, val)) if *val == v => {}
                    _ => ch.push((now, v.clone())),
                }
            }
        }
    };
    for cmd in parser {
        match cmd.map_err(bad)? {
            Command::Timestamp(t) => {
                if t < now {
                    return Err(format!(
                        "{name}: timestamps go backwards (#{t} after #{now})"
                    ));
                }
                now = t;
            }
            Command::ChangeScalar(code, v) => {
                let w = by_code
                    .get(&code)
                    .and_then(|i| i.first())
                    .map_or(1, |&i| signals[i].width);
                let s = format_value(w, &[v]);
                set(&mut signals, code, now, s);
            }
            Command::ChangeVector(code, v) => {
                let w = by_code
                    .get(&code)
                    .and_then(|i| i.first())
                    .map_or(v.len() as u32, |&i| signals[i].width);
                let s = format_value(w, &v);
                set(&mut signals, code, now, s);
            }
            Command::ChangeReal(code, v) => set(&mut signals, code, now, format!("r{v}")),
            Command::ChangeString(code, v) => set(&mut signals, code, now, format!("s{v}")),
            _ => {}
        }
    }
    // A value set twice at one time may now equal its predecessor: merge.
    for s in signals.iter_mut() {
        s.changes.dedup_by(|b, a| a.1 == b.1);
    }
    Ok(Trace {
        timescale: header.timescale.unwrap_or((1, TimescaleUnit::NS)),
        signals,
        end_time: now,
        comment: header.comment,
    })
}
