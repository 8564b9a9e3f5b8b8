//! Makes rust-hdl's Verilog of a top readable without changing its logic:
//!
//! 1. **Flip-flops inline.** rust-hdl emits every `DFF` as a module of its own
//!    (`module x__tx_q(d,q,clock)` holding `always @(posedge clock) q <= d;`) and
//!    instantiates it through three stub signals. Each such instance becomes a
//!    line `tx_q__q <= tx_q__d;` in one `always @(posedge clk)` block of the
//!    module that owns it, its `q` stub becomes a `reg`, and its clock stub (a
//!    copy of the block's clock) goes away.
//! 2. **One module per block kind.** Modules whose text is the same but for their
//!    own name and the names of the modules they instantiate (channel A's blocks
//!    and channel B's, the hub's identical port guards) become one module,
//!    instantiated as often as before. It takes the name the copies share
//!    (`drcc__chan_a__bsp` and `drcc__chan_b__bsp` become `drcc__chan__bsp`).
//!
//! Both steps only move text: every statement, signal name and expression of the
//! logic stays as rust-hdl wrote it, so the register names the traces and the
//! probes use are unchanged. `tests` below checks the result against the input
//! with yosys's equivalence checker; the lock-step suite runs on the result.

use std::collections::{BTreeMap, HashMap};

/// One `module ... endmodule` of the file.
#[derive(Clone, Debug)]
struct Module {
    name: String,
    lines: Vec<String>,
}

/// The file split into the text before the first module and the modules.
fn split_modules(text: &str) -> (String, Vec<Module>) {
    let mut preamble = String::new();
    let mut modules = Vec::new();
    let mut current: Option<Module> = None;
    for line in text.lines() {
        if let Some(m) = current.as_mut() {
            m.lines.push(line.to_string());
            if line.starts_with("endmodule") {
                modules.push(current.take().expect("in a module"));
            }
            continue;
        }
        if let Some(rest) = line.strip_prefix("module ") {
            let name = rest
                .split(|c: char| c == '(' || c.is_whitespace())
                .next()
                .unwrap_or("")
                .to_string();
            current = Some(Module {
                name,
                lines: vec![line.to_string()],
            });
        } else if modules.is_empty() {
            preamble.push_str(line);
            preamble.push('\n');
        }
    }
    (preamble, modules)
}

/// Whether `m` is rust-hdl's `DFF`: ports `(d,q,clock)` and nothing but
/// `always @(posedge clock) q <= d;`.
fn is_dff(m: &Module) -> bool {
    let first = m.lines[0].trim();
    if !first.ends_with("(d,q,clock);") {
        return false;
    }
    let body: Vec<&str> = m.lines[1..]
        .iter()
        .map(|l| l.trim())
        .filter(|l| !l.is_empty() && !l.starts_with("//") && !l.starts_with("endmodule"))
        .filter(|l| !l.starts_with("input wire") && !l.starts_with("output reg"))
        .filter(|l| !l.starts_with("localparam")) // an enum's codes
        .collect();
    body == ["always @(posedge clock) begin", "q <= d;", "end"]
}

/// An instance of a flip-flop module found in a parent.
struct DffInstance {
    /// Line range of the instance statement in the parent.
    first: usize,
    last: usize,
    d: String,
    q: String,
    clock: String,
}

/// The connection `.port(expr)` on a line, if it is one.
fn connection<'a>(line: &'a str, port: &str) -> Option<&'a str> {
    let t = line.trim().trim_end_matches(',');
    t.strip_prefix(&format!(".{port}("))
        .and_then(|r| r.strip_suffix(')'))
}

/// The flip-flop instances of `m` (`dffs`: the names of flip-flop modules).
fn dff_instances(m: &Module, dffs: &HashMap<String, ()>) -> Vec<DffInstance> {
    let mut found = Vec::new();
    let mut i = 0;
    while i < m.lines.len() {
        let t = m.lines[i].trim();
        let ty = t.split_whitespace().next().unwrap_or("");
        if t.ends_with('(') && dffs.contains_key(ty) && i + 4 < m.lines.len() {
            let d = connection(&m.lines[i + 1], "d");
            let q = connection(&m.lines[i + 2], "q");
            let c = connection(&m.lines[i + 3], "clock");
            if let (Some(d), Some(q), Some(c)) = (d, q, c) {
                if m.lines[i + 4].trim() == ");" {
                    found.push(DffInstance {
                        first: i,
                        last: i + 4,
                        d: d.to_string(),
                        q: q.to_string(),
                        clock: c.to_string(),
                    });
                    i += 5;
                    continue;
                }
            }
        }
        i += 1;
    }
    found
}

/// Inlines the flip-flop instances of `m`; `None` when one does not have the
/// shape rust-hdl gives it (then the module is left as it is).
fn inline_dffs(m: &Module, dffs: &HashMap<String, ()>) -> Option<Module> {
    let insts = dff_instances(m, dffs);
    if insts.is_empty() {
        return Some(m.clone());
    }
    // Each clock stub is assigned once from a plain signal: `x__clock = clk;`.
    let mut clock_src: HashMap<&str, String> = HashMap::new();
    let mut drop_line = vec![false; m.lines.len()];
    for inst in &insts {
        let prefix = format!("{} = ", inst.clock);
        let mut src = None;
        for (j, l) in m.lines.iter().enumerate() {
            let t = l.trim();
            if let Some(rest) = t.strip_prefix(&prefix) {
                let s = rest.strip_suffix(';')?;
                if src.is_some() || !s.chars().all(|c| c.is_alphanumeric() || c == '_') {
                    return None;
                }
                src = Some(s.to_string());
                drop_line[j] = true;
            } else if t == format!("reg  {};", inst.clock) {
                drop_line[j] = true;
            }
        }
        clock_src.insert(inst.clock.as_str(), src?);
        for l in &mut drop_line[inst.first..=inst.last] {
            *l = true;
        }
    }
    // No other use of a clock stub may remain.
    for inst in &insts {
        let uses = m
            .lines
            .iter()
            .enumerate()
            .filter(|(j, l)| !drop_line[*j] && contains_word(l, &inst.clock))
            .count();
        if uses != 0 {
            return None;
        }
    }
    let q_decl: HashMap<&str, ()> = insts.iter().map(|i| (i.q.as_str(), ())).collect();
    let mut lines = Vec::with_capacity(m.lines.len());
    for (j, l) in m.lines.iter().enumerate() {
        if drop_line[j] {
            continue;
        }
        // `wire  [7:0] x__q;` of an inlined flip-flop becomes a `reg`.
        let t = l.trim();
        if let Some(rest) = t.strip_prefix("wire ") {
            let name = rest
                .trim_end_matches(';')
                .split_whitespace()
                .last()
                .unwrap_or("");
            if q_decl.contains_key(name) {
                lines.push(l.replacen("wire ", "reg ", 1));
                continue;
            }
        }
        lines.push(l.clone());
    }
    // The flip-flops, one `always` block per clock, before `endmodule`.
    let mut by_clock: BTreeMap<&str, Vec<&DffInstance>> = BTreeMap::new();
    for inst in &insts {
        by_clock
            .entry(clock_src[inst.clock.as_str()].as_str())
            .or_default()
            .push(inst);
    }
    let end = lines.iter().rposition(|l| l.starts_with("endmodule"))?;
    let mut ff = vec!["    // Flip-flops".to_string()];
    for (clk, insts) in by_clock {
        ff.push(format!("    always @(posedge {clk}) begin"));
        for i in insts {
            ff.push(format!("        {} <= {};", i.q, i.d));
        }
        ff.push("    end".to_string());
    }
    ff.push("    ".to_string());
    lines.splice(end..end, ff);
    remove_empty_section(&mut lines, "// Sub module instances");
    Some(Module {
        name: m.name.clone(),
        lines,
    })
}

/// Drops a `// <section>` comment with nothing but blank lines after it.
fn remove_empty_section(lines: &mut Vec<String>, section: &str) {
    if let Some(i) = lines.iter().position(|l| l.trim() == section) {
        let next = lines[i + 1..]
            .iter()
            .position(|l| !l.trim().is_empty())
            .map(|k| i + 1 + k);
        let empty = next.is_none_or(|k| lines[k].trim().starts_with("//"));
        if empty {
            let stop = next.unwrap_or(lines.len());
            lines.drain(i..stop);
        }
    }
}

/// Whether `word` occurs in `line` as a whole identifier.
pub fn contains_word(line: &str, word: &str) -> bool {
    let bytes = line.as_bytes();
    let ident = |c: u8| c.is_ascii_alphanumeric() || c == b'_' || c == b'$';
    let mut from = 0;
    while let Some(k) = line[from..].find(word) {
        let s = from + k;
        let e = s + word.len();
        let before = s == 0 || !ident(bytes[s - 1]);
        let after = e == bytes.len() || !ident(bytes[e]);
        if before && after {
            return true;
        }
        from = e;
    }
    false
}

/// The module type an instance line starts (`type name(`), if it is one.
fn instance_type<'a>(line: &'a str, names: &HashMap<String, usize>) -> Option<&'a str> {
    let t = line.trim();
    if !t.ends_with('(') || t.starts_with("module ") {
        return None;
    }
    let ty = t.split_whitespace().next()?;
    names.contains_key(ty).then_some(ty)
}

/// The name a group of identical modules takes: the segments (`__`) they share,
/// with a differing segment cut to the prefix its versions share (`chan_a`,
/// `chan_b`: `chan`) or dropped when they share none; the first name when the
/// names have different depths.
pub fn shared_name(names: &[&str]) -> String {
    if names.len() == 1 {
        return names[0].to_string();
    }
    let split: Vec<Vec<&str>> = names.iter().map(|n| n.split("__").collect()).collect();
    if split.iter().any(|s| s.len() != split[0].len()) {
        return names[0].to_string();
    }
    let mut out: Vec<String> = Vec::new();
    for k in 0..split[0].len() {
        let first = split[0][k];
        if split.iter().all(|s| s[k] == first) {
            out.push(first.to_string());
            continue;
        }
        let mut prefix = first.to_string();
        for s in &split {
            while !s[k].starts_with(&prefix) {
                prefix.pop();
            }
        }
        let prefix = prefix.trim_end_matches('_');
        if !prefix.is_empty() {
            out.push(prefix.to_string());
        }
    }
    out.join("__")
}

/// Merges modules that are the same but for names (step 2 of the file doc).
fn merge_identical(modules: Vec<Module>) -> Vec<Module> {
    let index: HashMap<String, usize> = modules
        .iter()
        .enumerate()
        .map(|(i, m)| (m.name.clone(), i))
        .collect();
    // Children (more `__` segments) before their parents.
    let mut order: Vec<usize> = (0..modules.len()).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(modules[i].name.matches("__").count()));
    let mut group_of = vec![usize::MAX; modules.len()];
    let mut keys: HashMap<String, usize> = HashMap::new();
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for &i in &order {
        let m = &modules[i];
        let mut key = String::new();
        for l in &m.lines[1..m.lines.len() - 1] {
            match instance_type(l, &index) {
                Some(ty) => {
                    let g = group_of[index[ty]];
                    key.push_str(&l.replacen(ty, &format!("@group{g}"), 1));
                }
                None => key.push_str(l),
            }
            key.push('\n');
        }
        // The port list (first line) without the name.
        key.push_str(m.lines[0].split_once('(').map_or("", |(_, p)| p));
        let g = *keys.entry(key).or_insert_with(|| {
            groups.push(Vec::new());
            groups.len() - 1
        });
        groups[g].push(i);
        group_of[i] = g;
    }
    // Names: shared where the group has several members, unique in the file;
    // outer blocks choose first, so they get the plain names.
    let mut taken: HashMap<String, ()> = HashMap::new();
    let mut group_name = vec![String::new(); groups.len()];
    let depth = |g: usize| {
        groups[g]
            .iter()
            .map(|&i| modules[i].name.matches("__").count())
            .min()
            .unwrap_or(0)
    };
    let mut by_depth: Vec<usize> = (0..groups.len()).collect();
    by_depth.sort_by_key(|&g| (depth(g), groups[g].iter().min().copied()));
    for g in by_depth {
        let members = &groups[g];
        let mut sorted = members.clone();
        sorted.sort();
        let names: Vec<&str> = sorted.iter().map(|&i| modules[i].name.as_str()).collect();
        let mut name = shared_name(&names);
        if members.len() > 1
            && (taken.contains_key(&name)
                || index.contains_key(&name) && !names.contains(&name.as_str()))
        {
            name = names[0].to_string();
        }
        taken.insert(name.clone(), ());
        group_name[g] = name;
    }
    // Keep each group's first module in file order, renamed, with its
    // instances' types renamed.
    let mut emitted = vec![false; groups.len()];
    let mut out = Vec::new();
    for (i, m) in modules.iter().enumerate() {
        let g = group_of[i];
        if emitted[g] {
            continue;
        }
        emitted[g] = true;
        let name = &group_name[g];
        let mut lines = Vec::with_capacity(m.lines.len());
        for (k, l) in m.lines.iter().enumerate() {
            if k == 0 {
                lines.push(l.replacen(&m.name, name, 1));
            } else if l.starts_with("endmodule") {
                lines.push(format!("endmodule // {name}"));
            } else if let Some(ty) = instance_type(l, &index) {
                lines.push(l.replacen(ty, &group_name[group_of[index[ty]]], 1));
            } else {
                lines.push(l.clone());
            }
        }
        out.push(Module {
            name: name.clone(),
            lines,
        });
    }
    out
}

/// The readable text of a top's Verilog (`text`: rust-hdl's output after the
/// renames and with no `initial` blocks): flip-flops inline, identical modules
/// merged.
pub fn readable(text: &str) -> String {
    let (preamble, modules) = split_modules(text);
    let dffs: HashMap<String, ()> = modules
        .iter()
        .filter(|m| is_dff(m))
        .map(|m| (m.name.clone(), ()))
        .collect();
    let mut kept = Vec::new();
    let mut used_dffs: HashMap<String, ()> = HashMap::new();
    for m in &modules {
        if dffs.contains_key(&m.name) {
            continue;
        }
        match inline_dffs(m, &dffs) {
            Some(inlined) => kept.push(inlined),
            None => {
                // Left as it was: its flip-flop modules stay too.
                for l in &m.lines {
                    let ty = l.split_whitespace().next().unwrap_or("");
                    if dffs.contains_key(ty) {
                        used_dffs.insert(ty.to_string(), ());
                    }
                }
                kept.push(m.clone());
            }
        }
    }
    kept.extend(
        modules
            .iter()
            .filter(|m| used_dffs.contains_key(&m.name))
            .cloned(),
    );
    let merged = merge_identical(kept);
    let mut out = preamble;
    for (k, m) in merged.iter().enumerate() {
        if k > 0 {
            out.push_str("\n\n");
        }
        for l in &m.lines {
            out.push_str(l.trim_end());
            out.push('\n');
        }
    }
    out
}
