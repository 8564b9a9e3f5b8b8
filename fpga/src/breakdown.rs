//! Where a top's logic goes: yosys synthesises the top once more with each of
//! its direct children (the blocks the top instantiates: channels, FSMs,
//! memories, register block ...) kept as a module of its own (`keep_hierarchy`
//! on those modules only; everything inside a child is flattened as in the main
//! run), and counts each module's cells. A kept boundary stops constant
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

/// The modules of the direct children of `top` in its rust-hdl Verilog, in the
/// order of their first instance. rust-hdl names the module of a child field
/// `x` of `top` `top__x` and instantiates it as `top__x x(...)`.
pub fn children(verilog: &str, top: &str) -> Vec<String> {
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

/// The yosys script: the family's synthesis of `top` with the `children`
/// modules kept.
pub fn script(t: &Target, rtl: &Path, top: &str, children: &[String]) -> String {
    let mut s = format!("read_verilog {}\nhierarchy -top {top}\n", quote(rtl));
    for c in children {
        s.push_str(&format!("setattr -mod -set keep_hierarchy 1 {c}\n"));
    }
    s.push_str(&format!("{} -top {top}\n", t.synth));
    s
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
            current = (name != "design hierarchy").then(|| name.to_string());
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
                    .entry(name.to_string())
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
    let glue = area(
        sections
            .get(top)
            .ok_or_else(|| format!("no section for {top} in the yosys statistics"))?,
    );
    let mut blocks: Vec<BlockArea> = sections
        .iter()
        .filter_map(|(m, cells)| {
            m.strip_prefix(&prefix).map(|b| BlockArea {
                block: b.to_string(),
                area: area(cells),
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

/// Runs the breakdown synthesis of `top` (Verilog `rtl`, text `verilog`) in
/// `dir` (`<top>_blocks.ys`, `_blocks_stat.txt`, `_blocks_yosys.log`).
pub fn run(
    dir: &Path,
    t: &Target,
    rtl: &Path,
    top: &str,
    verilog: &str,
) -> Result<Breakdown, Error> {
    let children = children(verilog, top);
    let (text, stat_path) = yosys::run_stat(
        dir,
        &format!("{top}_blocks"),
        &script(t, rtl, top, &children),
    )?;
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
}
