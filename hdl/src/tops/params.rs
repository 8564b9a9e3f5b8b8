//! The DRCC's sizes as Verilog parameters (drcc_contract.md §1.1): an integrator
//! sets `RX_FIFO_DEPTH`, `TX_QUEUE_DEPTH`, `HISTORY`, `STAR` (and `DMR` where there
//! are no mailboxes) per instance, `drcc #(.RX_FIFO_DEPTH(8)) u_can (...)`, without
//! Rust.
//!
//! Why this is sound: a size is a runtime parameter of the rust-hdl blocks that
//! only sets a few `localparam`s (`channel::sized::Param`); every width, port and
//! statement is the same for every value it offers (`hdl/tests/configurations.rs`).
//! This pass turns each of those `localparam`s into an expression of a module
//! `parameter` and threads the parameter from the top down the instances that lead
//! to it. The text of every configuration of one `M` is then the same but for the
//! parameter defaults (`tests` below), so overriding a parameter elaborates exactly
//! the Verilog `drcc generate --config` would have written for that size.
//!
//! `M` (the DMR mailboxes) stays a generation choice: it changes the structure
//! (the mailbox engines are instances or absent), so it is not a parameter. `DMR`
//! is one only where `M = 0`: mailboxes need the DMR function (§1.1).
//!
//! A value outside the offer stops elaboration in Verilator, Icarus, yosys and
//! the vendor tools alike: the top instantiates a module that does not exist and
//! whose name says what is allowed (`RX_FIFO_DEPTH_must_be_4_8_16_or_32`).

use crate::config::{HISTORY_SIZES, RX_FIFO_DEPTHS, TX_QUEUE_DEPTHS};
use std::collections::{BTreeMap, BTreeSet};

/// A size offered as a Verilog parameter.
struct SizeParam {
    /// Parameter name, as in the header's `Parameters:` line.
    name: &'static str,
    /// The values it may take.
    offered: &'static [usize],
    /// Bits that carry it below the top (the widest site).
    bits: usize,
    /// What it sets, for the comment above its declaration in the top.
    doc: &'static str,
}

const SIZE_PARAMS: &[SizeParam] = &[
    SizeParam {
        name: "RX_FIFO_DEPTH",
        offered: RX_FIFO_DEPTHS,
        bits: 6,
        doc: "RX FIFO entries (drcc_contract.md §7): a frame that arrives with this many waiting overruns",
    },
    SizeParam {
        name: "TX_QUEUE_DEPTH",
        offered: TX_QUEUE_DEPTHS,
        bits: 4,
        doc: "entries of each TX queue (§6): a push to a full queue is refused",
    },
    SizeParam {
        name: "HISTORY",
        offered: HISTORY_SIZES,
        bits: 6,
        doc: "frames duplicate removal remembers (§7)",
    },
    SizeParam {
        name: "DMR",
        offered: &[0, 1],
        bits: 1,
        doc: "1: the CiA 701 DMR function (CTRL.dmr); 0: a CTRL write with dmr is refused",
    },
    SizeParam {
        name: "STAR",
        offered: &[0, 1],
        bits: 1,
        doc: "1: the replicated-star node (CTRL.star, §4.4); 0: a CTRL write with star is refused",
    },
];

/// A `localparam` a size sets: in the module whose name ends in `__<module>`.
struct Site {
    module: &'static str,
    local: &'static str,
    param: &'static str,
    /// Width of the localparam.
    width: usize,
    /// The localparam is the size less one (a pointer mask), not the size.
    minus_one: bool,
}

const fn site(
    module: &'static str,
    local: &'static str,
    param: &'static str,
    width: usize,
    minus_one: bool,
) -> Site {
    Site {
        module,
        local,
        param,
        width,
        minus_one,
    }
}

/// Every localparam a size sets (the `Param` fields of `memory/rx_fifo.rs`,
/// `memory/dedup.rs`, `memory/tx_buffer.rs`, `host/wishbone.rs`,
/// `host/ctrl_reg.rs`, `host/ctrl_check.rs`, `host/dmr_check.rs`,
/// `host/status_words.rs`).
const SITES: &[Site] = &[
    site("rxfifo", "mask", "RX_FIFO_DEPTH", 5, true),
    site("rxw", "fifo_depth", "RX_FIFO_DEPTH", 6, false),
    site("rxw", "last_scan", "HISTORY", 6, false),
    site("rxw", "hmask", "HISTORY", 5, true),
    site("txbuf", "qmask", "TX_QUEUE_DEPTH", 3, true),
    site("regs", "queue_full", "TX_QUEUE_DEPTH", 4, false),
    site("ctrl", "dmr_present", "DMR", 1, false),
    site("ctrl", "star_present", "STAR", 1, false),
    site("ctrl_check", "dmr_present", "DMR", 1, false),
    site("ctrl_check", "star_present", "STAR", 1, false),
    site("dmr_check", "dmr_present", "DMR", 1, false),
    site("status", "sz_rx_fifo", "RX_FIFO_DEPTH", 6, false),
    site("status", "sz_tx_queue", "TX_QUEUE_DEPTH", 4, false),
    site("status", "sz_history", "HISTORY", 6, false),
    site("status", "sz_dmr", "DMR", 1, false),
    site("status", "sz_star", "STAR", 1, false),
];

/// The sizes of a top's `params` that are Verilog parameters, with their values:
/// none for a top without them (the channel, the hub).
pub fn verilog_parameters(params: &[(&str, &str)]) -> Vec<(&'static str, usize)> {
    let mailboxes = params.iter().find(|(k, _)| *k == "M").map(|(_, v)| *v);
    SIZE_PARAMS
        .iter()
        .filter(|p| !(p.name == "DMR" && mailboxes != Some("0")))
        .filter_map(|p| {
            let v = params.iter().find(|(k, _)| *k == p.name)?.1;
            Some((p.name, v.parse().ok()?))
        })
        .collect()
}

/// A size's meaning and its offer, for the FuseSoC core's parameter description.
pub fn describe(name: &str) -> String {
    SIZE_PARAMS
        .iter()
        .find(|p| p.name == name)
        .map(|p| {
            let offered: Vec<String> = p.offered.iter().map(|o| o.to_string()).collect();
            format!("{}; one of {}", p.doc, offered.join(", "))
        })
        .unwrap_or_default()
}

/// `module name(...)` of a line, if it opens a module.
pub fn module_name(line: &str) -> Option<&str> {
    line.strip_prefix("module ")?
        .split(|c: char| c == '(' || c.is_whitespace())
        .next()
}

/// The module an instance line (`    type inst(`) instantiates, if it is one.
fn instance_of<'a>(line: &'a str, modules: &BTreeSet<&str>) -> Option<&'a str> {
    let t = line.trim_start();
    let mut words = t.split_whitespace();
    let ty = words.next()?;
    let inst = words.next()?;
    (modules.contains(ty) && inst.ends_with('(')).then_some(ty)
}

/// Whether `line` is `localparam  <local> = <literal>;`.
fn is_site_line(line: &str, local: &str) -> bool {
    let t = line.trim();
    t.strip_prefix("localparam")
        .map(|r| r.trim_start().starts_with(&format!("{local} = ")))
        .unwrap_or(false)
}

/// The value of a Verilog sized literal (`5'b11111`, `4'h8`, `6'd32`).
pub fn literal_value(lit: &str) -> Option<u64> {
    let (_, rest) = lit.split_once('\'')?;
    let (base, digits) = rest.split_at(1);
    let radix = match base {
        "b" => 2,
        "h" => 16,
        "d" => 10,
        "o" => 8,
        _ => return None,
    };
    u64::from_str_radix(&digits.replace('_', ""), radix).ok()
}

/// `top`'s finished Verilog (`text`) with its sizes as parameters. Panics if a
/// size of `params` has no site or a site's value is not the size's: the
/// generator and this table disagree, a bug to fix here.
pub fn parameterize(top: &str, text: &str, params: &[(&str, &str)]) -> String {
    let sizes = verilog_parameters(params);
    if sizes.is_empty() {
        return text.to_string();
    }
    let lines: Vec<&str> = text.lines().collect();
    // Each module's line range and the modules it instantiates.
    let mut spans: BTreeMap<&str, (usize, usize)> = BTreeMap::new();
    let mut open: Option<(&str, usize)> = None;
    for (i, l) in lines.iter().enumerate() {
        if let Some(name) = module_name(l) {
            open = Some((name, i));
        } else if l.starts_with("endmodule") {
            if let Some((name, start)) = open.take() {
                spans.insert(name, (start, i));
            }
        }
    }
    let names: BTreeSet<&str> = spans.keys().copied().collect();
    let children: BTreeMap<&str, BTreeSet<&str>> = spans
        .iter()
        .map(|(m, &(s, e))| {
            let kids = lines[s + 1..e]
                .iter()
                .filter_map(|l| instance_of(l, &names))
                .collect();
            (*m, kids)
        })
        .collect();
    // Per module: the parameters it declares; per site line: its rewrite.
    let mut declares: BTreeMap<&str, Vec<&SizeParam>> = BTreeMap::new();
    let mut rewrites: BTreeMap<usize, String> = BTreeMap::new();
    for &(pname, value) in &sizes {
        let p = SIZE_PARAMS
            .iter()
            .find(|p| p.name == pname)
            .expect("a size");
        let mut holders: BTreeSet<&str> = BTreeSet::new();
        for s in SITES.iter().filter(|s| s.param == pname) {
            for (m, &(start, end)) in &spans {
                if !m.ends_with(&format!("__{}", s.module)) {
                    continue;
                }
                for (i, l) in lines.iter().enumerate().take(end).skip(start) {
                    if !is_site_line(l, s.local) {
                        continue;
                    }
                    let lit = l
                        .trim()
                        .trim_end_matches(';')
                        .rsplit(' ')
                        .next()
                        .unwrap_or("");
                    let want = if s.minus_one { value - 1 } else { value } as u64
                        & ((1u64 << s.width) - 1);
                    assert_eq!(
                        literal_value(lit),
                        Some(want),
                        "{top}: {m}.{} is {lit}, not {pname} = {value}",
                        s.local
                    );
                    rewrites.insert(i, site_expression(l, s, p));
                    holders.insert(*m);
                }
            }
        }
        assert!(!holders.is_empty(), "{top}: no localparam sets {pname}");
        // The holders and every module above them, up to the top.
        let mut needs = holders;
        loop {
            let above: Vec<&str> = children
                .iter()
                .filter(|(m, kids)| !needs.contains(*m) && kids.iter().any(|k| needs.contains(k)))
                .map(|(m, _)| *m)
                .collect();
            if above.is_empty() {
                break;
            }
            needs.extend(above);
        }
        assert!(needs.contains(top), "{top}: {pname} does not reach the top");
        for m in needs {
            declares.entry(m).or_default().push(p);
        }
    }
    let value_of = |name: &str| sizes.iter().find(|(n, _)| *n == name).map(|(_, v)| *v);
    let mut out = String::with_capacity(text.len() + 4096);
    let mut current: Option<&str> = None;
    for (i, l) in lines.iter().enumerate() {
        if let Some(r) = rewrites.get(&i) {
            out.push_str(r);
            out.push('\n');
            continue;
        }
        let inst = current.and_then(|_| instance_of(l, &names));
        match inst.and_then(|ty| declares.get(ty)) {
            Some(ps) => {
                let (indent, rest) = l.split_at(l.len() - l.trim_start().len());
                let (ty, inst_name) = rest.split_once(' ').expect("type and instance");
                let over: Vec<String> = ps
                    .iter()
                    .map(|p| {
                        if current == Some(top) {
                            format!(".{0}({0}[{1}:0])", p.name, p.bits - 1)
                        } else {
                            format!(".{0}({0})", p.name)
                        }
                    })
                    .collect();
                out.push_str(&format!(
                    "{indent}{ty} #({}) {inst_name}\n",
                    over.join(", ")
                ));
            }
            None => {
                out.push_str(l);
                out.push('\n');
            }
        }
        if let Some(name) = module_name(l) {
            current = Some(name);
            if let Some(ps) = declares.get(name) {
                let values: Vec<(&SizeParam, usize)> = ps
                    .iter()
                    .map(|p| (*p, value_of(p.name).expect("a size")))
                    .collect();
                if name == top {
                    out.push_str(&top_declarations(&values));
                } else {
                    for (p, v) in values {
                        out.push_str(&format!(
                            "    parameter [{}:0] {} = {}'d{v};\n",
                            p.bits - 1,
                            p.name,
                            p.bits
                        ));
                    }
                }
            }
        }
    }
    out
}

/// A site's localparam as an expression of its parameter, at the same width.
fn site_expression(line: &str, s: &Site, p: &SizeParam) -> String {
    let indent = &line[..line.len() - line.trim_start().len()];
    let w = s.width;
    let value = if w == p.bits {
        p.name.to_string()
    } else {
        format!("{}[{}:0]", p.name, w - 1)
    };
    let expr = if s.minus_one {
        format!("{value} - {w}'d1")
    } else {
        value
    };
    format!("{indent}localparam [{}:0] {} = {expr};", w - 1, s.local)
}

/// The top's parameter declarations, each with its doc, and the elaboration
/// check that refuses a value outside the offer.
fn top_declarations(values: &[(&SizeParam, usize)]) -> String {
    let mut t = String::from(
        "    // Sizes (drcc_contract.md §1.1), settable per instance; each default is\n\
         \x20   // this file's generated size. A value outside the offer stops elaboration.\n",
    );
    for (p, v) in values {
        for l in super::port_docs::wrap(&format!("{}.", describe(p.name)), 93) {
            t.push_str(&format!("    // {l}\n"));
        }
        t.push_str(&format!("    parameter integer {} = {v};\n", p.name));
    }
    t.push_str("    generate\n");
    for (p, _) in values {
        let test: Vec<String> = p
            .offered
            .iter()
            .map(|o| format!("{} != {o}", p.name))
            .collect();
        let words: Vec<String> = p.offered.iter().map(|o| o.to_string()).collect();
        let must = match words.split_last() {
            Some((last, rest)) if !rest.is_empty() => format!("{}_or_{last}", rest.join("_")),
            _ => words.join("_"),
        };
        t.push_str(&format!(
            "        if ({}) begin : refuse_{}\n            {}_must_be_{must} refused();\n        end\n",
            test.join(" && "),
            p.name.to_lowercase(),
            p.name
        ));
    }
    t.push_str("    endgenerate\n");
    t
}
