//! Scenario errors: the file, line and dotted field name of what is wrong, with
//! TOML/serde messages made readable.

use super::*;

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
            write!(f, "{}: ", clip(field, 80))?;
        }
        write!(f, "{}", clip(&self.message, 400))
    }
}

/// At most `n` characters of `s` (text from the file can be anything, e.g. a
/// 200 KB key), on one line, saying how much was left out.
pub(super) fn clip(s: &str, n: usize) -> String {
    let one_line = s.replace(['\n', '\r'], " ");
    let total = one_line.chars().count();
    if total <= n {
        return one_line;
    }
    let head: String = one_line.chars().take(n).collect();
    format!("{head}... ({} more characters)", total - n)
}

impl std::error::Error for ScenarioError {}

/// A TOML/serde message on one line, with integer types spelled as ranges.
pub(super) fn friendly(msg: &str) -> String {
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

pub(super) fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// The dotted field name at a byte offset: the enclosing table (`frame[2]`,
/// `timing`) and the key of the line, as far as they can be told from the text.
pub(super) fn field_at(text: &str, offset: usize) -> Option<String> {
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
