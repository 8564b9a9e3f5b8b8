//! Which fast evaluation a Verilated model allows: its "previous clk" member
//! (one eval per clock), and whether its evaluation loop is the one the shim's fast path
//! copies (`drcc::evalStep` in shim/drcc_shim_common.h): the model's
//! `V<top>::eval_step()` and `V<top>___024root___eval()`, normalised, compared
//! with `eval_5006.txt`. Only then does build.rs define `DRCC_<TOP>_EVAL_STEP`;
//! any other Verilator steps through `eval()`.

use std::fs;
use std::path::Path;

use crate::tables::TopTable;

/// The evaluation code that `drcc::evalStep` (shim/drcc_shim_common.h) copies,
/// normalised as [`normalise_eval_code`] does (see the file's header).
const EVAL_CODE: &str = include_str!("eval_5006.txt");

/// Ok when the model's `V<top>::eval_step()` and `V<top>___024root___eval()` are,
/// once normalised, exactly the code the shim's fast path copies; else why not.
pub fn eval_code_matches(top: &TopTable, mdir: &Path) -> Result<(), String> {
    let name = &top.name;
    let read =
        |p: &Path| fs::read_to_string(p).map_err(|e| format!("cannot read {}: {e}", p.display()));
    let step = function(
        &read(&mdir.join(format!("V{name}.cpp")))?,
        &format!("void V{name}::eval_step() {{"),
    )
    .ok_or_else(|| format!("no V{name}::eval_step() in V{name}.cpp"))?;
    // `___eval` is in one of the root's "fast" files (DepSet_<hash>__<n>.cpp).
    let head = format!("void V{name}___024root___eval(V{name}___024root* vlSelf) {{");
    let mut evals = Vec::new();
    for e in fs::read_dir(mdir).map_err(|e| format!("cannot list {}: {e}", mdir.display()))? {
        let p = e.map_err(|e| e.to_string())?.path();
        let file = p.file_name().and_then(|f| f.to_str()).unwrap_or("");
        if file.starts_with(&format!("V{name}___024root__DepSet_"))
            && file.ends_with(".cpp")
            && !file.ends_with("__Slow.cpp")
        {
            evals.extend(function(&read(&p)?, &head));
        }
    }
    let [eval] = &evals[..] else {
        return Err(format!(
            "{} definitions of V{name}___024root___eval()",
            evals.len()
        ));
    };
    let expected = EVAL_CODE
        .split_once("\n\n")
        .map_or("", |(_, code)| code)
        .trim_end();
    let found = normalise_eval_code(name, &format!("{step}\n\n{eval}"));
    if found.trim_end() == expected {
        Ok(())
    } else {
        Err(
            "its evaluation loop is not the one the shim's fast path copies (build/eval_5006.txt)"
                .into(),
        )
    }
}

/// The lines of the C++ function that opens with the line `head`, up to its
/// closing `}` line.
fn function(text: &str, head: &str) -> Option<String> {
    let mut lines = text.lines().skip_while(|l| *l != head);
    let first = lines.next()?;
    let mut out = vec![first];
    for l in lines {
        out.push(l);
        if l == "}" {
            return Some(out.join("\n"));
        }
    }
    None
}

/// `V<name>` -> `VTOP`, `VlTriggerVec<3>` -> `VlTriggerVec<N>`, and the file and
/// line of `VL_FATAL_MT("<file>", <line>, ...)` -> `FILE, LINE`: what differs
/// between tops and checkouts but not in what the code does.
fn normalise_eval_code(name: &str, code: &str) -> String {
    let code = code
        .replace(&format!("V{name}::"), "VTOP::")
        .replace(&format!("V{name}___024root"), "VTOP___024root")
        .replace(&format!("V{name}__Syms"), "VTOP__Syms");
    let mut out = String::new();
    for line in code.lines() {
        let mut line = line.to_string();
        if let Some(i) = line.find("VlTriggerVec<") {
            let from = i + "VlTriggerVec<".len();
            if let Some(len) = line[from..].find('>') {
                line.replace_range(from..from + len, "N");
            }
        }
        if let Some(i) = line.find("VL_FATAL_MT(\"") {
            let from = i + "VL_FATAL_MT(".len();
            // The quoted file name, then ", <line>,".
            let rest = &line[from + 1..];
            if let Some(q) = rest.find('"') {
                let after = &rest[q + 1..];
                if let Some(c) = after.strip_prefix(", ").and_then(|a| a.find(',')) {
                    let end = from + 1 + q + 1 + 2 + c;
                    line.replace_range(from..end, "FILE, LINE");
                }
            }
        }
        out.push_str(&line);
        out.push('\n');
    }
    out
}

/// The model's internal "value of clk at the previous eval" member, if exactly one
/// member of `V<top>___024root.h` looks like it (5.006: `__Vtrigrprev__TOP__clk`).
/// The shim then makes one eval per clock instead of two (see drcc_shim_common.h);
/// the tests check that both ways give the same outputs.
pub fn clk_prev_member(top: &TopTable, mdir: &Path) -> Option<String> {
    let text = fs::read_to_string(mdir.join(format!("V{}___024root.h", top.name))).ok()?;
    let mut found: Vec<String> = text
        .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| {
            w.starts_with("__Vtrig")
                && w.contains("prev")
                && (w.ends_with("__clk") || w.contains("__clk__"))
        })
        .map(str::to_string)
        .collect();
    found.sort();
    found.dedup();
    (found.len() == 1).then(|| found.remove(0))
}
