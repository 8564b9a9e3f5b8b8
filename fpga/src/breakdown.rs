//! Where a top's logic goes: yosys synthesises the top once more with each of
//! its blocks (the modules the top instantiates, or the DRCC core it wraps
//! instantiates: channels, FSMs, memories, register block ...) kept as a module
//! of its own (`keep_hierarchy` on those modules only; everything inside a
//! block is flattened as in the main run), and counts each module's cells, once
//! per instance. A kept boundary stops constant
//! propagation and logic sharing between two blocks, so the sum of the blocks
//! is a little larger than the flattened top: the report shows both, and the
//! blocks' shares are of their sum.

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::target::Target;
use crate::yosys::{self, quote, Area};
use crate::Error;

/// One block of a top and its cells.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct BlockArea {
    /// The instance name in the top (`chan_a`, `rxw`, ...; rust-hdl's field name).
    pub block: String,
    /// Its cells, with everything below it.
    pub area: Area,
}

/// A top's area block by block.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Breakdown {
    /// Each direct child of the top, largest (LUTs) first.
    pub blocks: Vec<BlockArea>,
    /// The top's own logic between its children (output assembly, glue).
    pub glue: Area,
    /// Sum of the blocks and the glue.
    pub total: Area,
}

impl Breakdown {
    /// The rows: each block, then the glue, then the sum, as
    /// `(name, area)`.
    pub fn rows(&self) -> Vec<(&str, &Area)> {
        let mut rows: Vec<(&str, &Area)> = self
            .blocks
            .iter()
            .map(|b| (b.block.as_str(), &b.area))
            .collect();
        rows.push(("(glue in the top)", &self.glue));
        rows
    }

    /// The text report: one line per block with its share of the sum and, when
    /// a reference LUT count is known, its size against it; `lut` names the
    /// family's LUT, `flat` is the flattened top's area.
    pub fn text(&self, lut: &str, flat: &Area, reference_lut: Option<u64>) -> String {
        let mut s = format!(
            "  by block (each block kept apart; their sum, {} {lut}, is {:.0} % of the flattened top's {}):\n",
            self.total.lut,
            percent(self.total.lut, flat.lut),
            flat.lut
        );
        for (name, a) in self.rows() {
            let vs = reference_lut
                .map(|r| format!("  {:.2}x the reference", a.lut as f64 / r as f64))
                .unwrap_or_default();
            s.push_str(&format!(
                "    {name:<20} {:>6} {lut} {:>3.0} %  FF {:>5}  BRAM {:>2}{vs}\n",
                a.lut,
                percent(a.lut, self.total.lut),
                a.ff,
                a.bram
            ));
        }
        s
    }
}

/// `100 * a / b` (0 when `b` is 0).
pub fn percent(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        100.0 * a as f64 / b as f64
    }
}

/// The blocks of `top` in its rust-hdl Verilog, in the order of their first
/// instance: its direct children, except that a DRCC core (a child module named
/// `*__core`, which the native and the bus tops wrap whole) stands for its own
/// children, so that the report names the channels, FSMs and memories rather
/// than one core. rust-hdl names the module of a child field `x` of `top`
/// `top__x` and instantiates it as `top__x x(...)`.
pub fn children(verilog: &str, top: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    for c in direct_children(verilog, top) {
        let inner = if c.ends_with("__core") {
            direct_children(verilog, &c)
        } else {
            Vec::new()
        };
        if inner.is_empty() {
            blocks.push(c);
        } else {
            blocks.extend(inner);
        }
    }
    blocks
}

fn direct_children(verilog: &str, top: &str) -> Vec<String> {
    let head = format!("module {top}(");
    let Some(start) = verilog.find(&head) else {
        return Vec::new();
    };
    let body = &verilog[start..];
    let body = &body[..body.find("\nendmodule").unwrap_or(body.len())];
    let prefix = format!("{top}__");
    let mut found: Vec<String> = Vec::new();
    for line in body.lines() {
        let mut words = line.split_whitespace();
        if let (Some(module), Some(_instance)) = (words.next(), words.next()) {
            if module.starts_with(&prefix) && !found.iter().any(|m| m == module) {
                found.push(module.to_string());
            }
        }
    }
    found
}

/// The yosys script: the family's synthesis of `top` (Verilog `rtl`, in which
/// [`keep`] has marked the blocks).
pub fn script(t: &Target, rtl: &Path, top: &str) -> String {
    format!(
        "read_verilog {}\nhierarchy -top {top}\n{} -top {top}\n",
        quote(rtl),
        t.synth
    )
}

/// `verilog` with `(* keep_hierarchy *)` on the declarations of the `children`
/// modules. An attribute in the source, unlike a `setattr` after `hierarchy`,
/// also reaches the copies yosys derives for a module with parameters
/// (`$paramod...`), which the sized blocks are.
pub fn keep(verilog: &str, children: &[String]) -> String {
    let mut out = String::with_capacity(verilog.len() + 32 * children.len());
    for line in verilog.split_inclusive('\n') {
        let kept = line
            .strip_prefix("module ")
            .and_then(|r| r.split(['(', ' ', '#']).next())
            .is_some_and(|name| children.iter().any(|c| c == name));
        if kept {
            out.push_str("(* keep_hierarchy *)\n");
        }
        out.push_str(line);
    }
    out
}

/// A module name as the top's Verilog spells it: yosys names the copy of a
/// module with parameters `$paramod\name\P=...` (or `$paramod$hash\name`).
fn base_name(name: &str) -> &str {
    match name.strip_prefix("$paramod") {
        Some(rest) => {
            let rest = &rest[rest.find('\\').map_or(0, |i| i + 1)..];
            rest.split('\\').next().unwrap_or(rest)
        }
        None => name,
    }
}

/// Cell counts of every module section (`=== name ===`) of a yosys `stat`
/// report, without the "design hierarchy" summary.
pub fn parse_sections(text: &str) -> BTreeMap<String, BTreeMap<String, u64>> {
    let mut out: BTreeMap<String, BTreeMap<String, u64>> = BTreeMap::new();
    let mut current: Option<String> = None;
    let mut in_cells = false;
    for line in text.lines() {
        let t = line.trim();
        if let Some(name) = t.strip_prefix("=== ").and_then(|r| r.strip_suffix(" ===")) {
            current = (name != "design hierarchy").then(|| base_name(name).to_string());
            in_cells = false;
            continue;
        }
        let Some(module) = &current else { continue };
        if t.starts_with("Number of cells:") {
            in_cells = true;
            out.entry(module.clone()).or_default();
            continue;
        }
        if !in_cells {
            continue;
        }
        let toks: Vec<&str> = t.split_whitespace().collect();
        match (toks.as_slice(), toks.get(1).map(|n| n.parse::<u64>())) {
            ([name, _], Some(Ok(n))) => {
                *out.entry(module.clone())
                    .or_default()
                    .entry(base_name(name).to_string())
                    .or_insert(0) += n;
            }
            _ => in_cells = false,
        }
    }
    out
}

/// The breakdown of `top` from its stat report sections: each child module's
/// cells (instances of other kept modules are not cells of a family), the top's
/// own cells as the glue.
pub fn from_sections(
    t: &Target,
    top: &str,
    sections: &BTreeMap<String, BTreeMap<String, u64>>,
) -> Result<Breakdown, String> {
    let prefix = format!("{top}__");
    let area = |cells: &BTreeMap<String, u64>| {
        let own = cells
            .iter()
            .filter(|(c, _)| !c.starts_with(&prefix))
            .map(|(c, n)| (c.clone(), *n))
            .collect();
        Area::from_cells(t.arch, own)
    };
    let top_cells = sections
        .get(top)
        .ok_or_else(|| format!("no section for {top} in the yosys statistics"))?;
    let glue = area(top_cells);
    // A module the top instantiates n times (the two channels share one since
    // the readable Verilog) counts n times, and says so in its name.
    let mut blocks: Vec<BlockArea> = sections
        .iter()
        .filter_map(|(m, cells)| {
            let name = m.strip_prefix(&prefix)?;
            let name = name.strip_prefix("core__").unwrap_or(name);
            let n = top_cells.get(m).copied().unwrap_or(1).max(1);
            let one = area(cells);
            let mut all = one.clone();
            for _ in 1..n {
                all = all.plus(&one);
            }
            Some(BlockArea {
                block: if n > 1 {
                    format!("{name} (x{n})")
                } else {
                    name.to_string()
                },
                area: all,
            })
        })
        .collect();
    blocks.sort_by(|a, b| b.area.lut.cmp(&a.area.lut).then(a.block.cmp(&b.block)));
    let mut total = glue.clone();
    for b in &blocks {
        total = total.plus(&b.area);
    }
    Ok(Breakdown {
        blocks,
        glue,
        total,
    })
}

/// Runs the breakdown synthesis of `top` (its Verilog text `verilog`) in
/// `dir` (`<top>_blocks.ys`, `_blocks_stat.txt`, `_blocks_yosys.log`).
pub fn run(dir: &Path, t: &Target, top: &str, verilog: &str) -> Result<Breakdown, Error> {
    let children = children(verilog, top);
    let marked = dir.join(format!("{top}_blocks.v"));
    crate::write_file(&marked, &keep(verilog, &children))?;
    let (text, stat_path) =
        yosys::run_stat(dir, &format!("{top}_blocks"), &script(t, &marked, top))?;
    from_sections(t, top, &parse_sections(&text))
        .map_err(|m| Error(format!("{}: {m}", stat_path.display())))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The direct children come from the top module's body only, once each.
    #[test]
    fn children_are_the_top_modules_instances() {
        let v = "module t(clk);\n  input wire clk;\n  t__a a(.clk(clk));\n  t__b__x bx(.clk(clk));\n  t__a a2(.clk(clk));\nendmodule\nmodule t__a(clk);\n  t__a__inner inner(.clk(clk));\nendmodule\n";
        assert_eq!(children(v, "t"), vec!["t__a", "t__b__x"]);
        assert!(children(v, "missing").is_empty());
    }

    /// A core the top wraps stands for its own children.
    #[test]
    fn a_core_stands_for_its_blocks() {
        let v = "module t(clk);\n  t__core core(.clk(clk));\n  t__view view(.clk(clk));\nendmodule\nmodule t__core(clk);\n  t__core__rxw rxw(.clk(clk));\n  t__core__chan chan_a(.clk(clk));\nendmodule\n";
        assert_eq!(
            children(v, "t"),
            vec!["t__core__rxw", "t__core__chan", "t__view"]
        );
    }

    /// A stat report of two kept children: each block counts its own cells, the
    /// top's SB_LUT4 are the glue, and instances of kept modules are not cells.
    #[test]
    fn sections_become_blocks_and_glue() {
        let text = "\n=== t ===\n\n   Number of wires:   5\n   Number of cells:   4\n     SB_LUT4    2\n     t__a       1\n     t__b       1\n\n=== t__a ===\n\n   Number of cells:   13\n     SB_DFF     3\n     SB_LUT4   10\n\n=== t__b ===\n\n   Number of cells:   25\n     SB_LUT4   20\n     SB_RAM40_4K  5\n\n=== design hierarchy ===\n\n   t    1\n     t__a    1\n\n   Number of cells:   40\n     SB_LUT4   32\n";
        let s = parse_sections(text);
        assert_eq!(s.len(), 3);
        let t = Target::by_name("ice40").unwrap();
        let b = from_sections(t, "t", &s).unwrap();
        assert_eq!(b.blocks[0].block, "b");
        assert_eq!((b.blocks[0].area.lut, b.blocks[0].area.bram), (20, 5));
        assert_eq!((b.blocks[1].area.lut, b.blocks[1].area.ff), (10, 3));
        assert_eq!(b.glue.lut, 2);
        assert_eq!((b.total.lut, b.total.ff, b.total.bram), (32, 3, 5));
    }

    /// The kept blocks carry the attribute in the source; others do not.
    #[test]
    fn keep_marks_the_blocks_declarations() {
        let v = "module t(clk);\nendmodule\nmodule t__a #(parameter D = 4) (clk);\nendmodule\nmodule t__ab(clk);\nendmodule\n";
        let k = keep(v, &["t__a".to_string()]);
        assert!(k.contains("(* keep_hierarchy *)\nmodule t__a #"));
        assert_eq!(k.matches("keep_hierarchy").count(), 1);
    }

    /// Derived copies of a module with parameters count as the module.
    #[test]
    fn paramod_names_are_the_modules() {
        assert_eq!(base_name("$paramod\\t__rxw\\DEPTH=s32'00100000"), "t__rxw");
        assert_eq!(base_name("$paramod$3f2a\\t__rxw"), "t__rxw");
        assert_eq!(base_name("t__chan"), "t__chan");
    }

    /// A module instantiated twice (a core's two channels) counts twice.
    #[test]
    fn a_shared_module_counts_once_per_instance() {
        let text = "\n=== t ===\n\n   Number of cells:   3\n     SB_LUT4    1\n     t__core__chan  2\n\n=== t__core__chan ===\n\n   Number of cells:   12\n     SB_DFF     4\n     SB_LUT4    8\n";
        let t = Target::by_name("ice40").unwrap();
        let b = from_sections(t, "t", &parse_sections(text)).unwrap();
        assert_eq!(b.blocks[0].block, "chan (x2)");
        assert_eq!((b.blocks[0].area.lut, b.blocks[0].area.ff), (16, 8));
        assert_eq!(b.total.lut, 17);
    }
}
