//! The port documentation of a top, read from the `///` comments of its rust-hdl
//! struct: the struct's source text is the one copy, so the emitted Verilog, the
//! shim tables and rustdoc say the same thing.

/// The `///` text before every `pub <name>: Signal<...>` field of `pub struct
/// <block>` in `source`, in declaration order, as `(name, doc)`. Doc lines are
/// joined with spaces; a field without `///` gets an empty doc. Any other line
/// (a `//` group comment, a private field) ends the doc being collected.
pub fn port_docs(source: &str, block: &str) -> Vec<(String, String)> {
    let mut lines = source.lines().map(str::trim);
    let opening = |l: &str| {
        l.strip_prefix("pub struct ")
            .and_then(|rest| rest.strip_prefix(block))
            .is_some_and(|rest| rest.starts_with(' ') || rest.starts_with('<'))
    };
    if !lines.by_ref().any(opening) {
        return Vec::new();
    }
    let mut docs = Vec::new();
    let mut pending: Vec<&str> = Vec::new();
    for line in lines {
        if line == "}" {
            break;
        }
        if let Some(text) = line.strip_prefix("///") {
            pending.push(text.trim());
            continue;
        }
        if line.starts_with("#[") {
            continue;
        }
        let field = line
            .strip_prefix("pub ")
            .and_then(|rest| rest.split_once(':'))
            .filter(|(_, ty)| ty.trim_start().starts_with("Signal<"));
        if let Some((name, _)) = field {
            let doc = pending
                .iter()
                .filter(|t| !t.is_empty())
                .copied()
                .collect::<Vec<_>>()
                .join(" ");
            docs.push((name.trim().to_string(), doc));
        }
        pending.clear();
    }
    docs
}

/// `text` broken into lines of at most `width` characters at spaces, never inside
/// a `code span` (a longer word or span gets a line of its own).
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    // Words, with a code span's words glued back together.
    let mut words: Vec<String> = Vec::new();
    let mut open = false;
    for word in text.split_whitespace() {
        match words.last_mut() {
            Some(last) if open => {
                last.push(' ');
                last.push_str(word);
            }
            _ => words.push(word.to_string()),
        }
        if word.matches('`').count() % 2 == 1 {
            open = !open;
        }
    }
    let mut lines = Vec::new();
    let mut line = String::new();
    for word in &words {
        if !line.is_empty() && line.len() + 1 + word.len() > width {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}
