//! Tests of the top table: parameters, headers, port docs and the finished Verilog of each top.

use super::*;

/// The DRCC tops' header parameters are their configurations', and
/// `drcc_with_config` of a named configuration is that top's Verilog body.
#[test]
fn drcc_tops_follow_their_configurations() {
    for (name, cfg) in [
        ("drcc", DrccConfig::DEFAULT),
        ("drcc_m0", DrccConfig::M0),
        ("drcc_small", DrccConfig::SMALL),
    ] {
        let t = top(name).unwrap();
        let want: Vec<(&str, String)> = cfg.params();
        let got: Vec<(&str, String)> = t.params.iter().map(|(k, v)| (*k, v.to_string())).collect();
        assert_eq!(got, want, "{name}");
    }
    let small = top("drcc_small").unwrap().verilog();
    let custom = drcc_with_config("drcc_small", &DrccConfig::SMALL).unwrap();
    let body = |t: &str| t[t.find("module drcc_small(").unwrap()..].to_string();
    assert_eq!(body(&small), body(&custom));
    let bad = DrccConfig {
        rx_fifo_depth: 3,
        ..DrccConfig::SMALL
    };
    assert!(drcc_with_config("x", &bad).is_err());
}

/// The probe walk finds exactly the ports the Verilog module header declares.
#[test]
fn ports_match_the_emitted_module_header() {
    for t in TOPS {
        let text = t.verilog();
        let header_start = text
            .find(&format!("module {}(", t.name))
            .expect("module header");
        let header = &text[header_start..];
        let header = &header[..header.find(");").expect("end of port list")];
        let declared: Vec<&str> = header
            .split(['(', ','])
            .skip(1)
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .collect();
        let probed: Vec<String> = t.ports().into_iter().map(|p| p.name).collect();
        assert_eq!(declared, probed, "ports of {}", t.name);
    }
}

#[test]
fn channel_ports_have_their_widths_and_directions() {
    let ports = top("can_channel").unwrap().ports();
    let find = |n: &str| ports.iter().find(|p| p.name == n).unwrap().clone();
    assert!(find("clk").is_clock);
    assert_eq!(find("tx_id").width, 29);
    assert_eq!(find("tx_id").direction, Direction::Input);
    assert_eq!(find("rx_data").width, 64);
    assert_eq!(find("rx_data").direction, Direction::Output);
    assert_eq!(find("tec").width, 9);
}

/// Every port of every top says what it means (fails when a port is added
/// without a `///` comment, or renamed so its comment no longer matches).
#[test]
fn every_port_is_documented() {
    for t in TOPS {
        for p in t.ports() {
            assert!(
                p.doc.split_whitespace().count() >= 3,
                "port `{}` of `{}` has no `///` doc in {} (struct {})",
                p.name,
                t.name,
                t.source_path,
                t.block
            );
        }
    }
}

/// What [`scan_block_ports`] found in one source text.
#[derive(Debug, Default, PartialEq)]
struct PortScan {
    /// Structs deriving `LogicBlock`.
    blocks: usize,
    /// Their `pub` fields.
    ports: usize,
    /// `(line, field)` of every `pub` field without a `///` directly above it
    /// (1-based lines; attributes may sit between the doc and the field).
    undocumented: Vec<(usize, String)>,
}

/// The text of `line` before a `//` comment (a rough cut: good enough for
/// counting the braces of a struct declaration).
fn code_part(line: &str) -> &str {
    line.find("//").map_or(line, |i| &line[..i])
}

/// The brackets still open after `code`, a line of a field declaration that
/// began with `open` of them; `None` once the field is complete (all closed and
/// the line ends with its comma).
fn field_end(open: i64, code: &str) -> Option<i64> {
    let open = code.chars().fold(open, |n, c| match c {
        '<' | '(' | '[' => n + 1,
        '>' | ')' | ']' => n - 1,
        _ => n,
    });
    (open > 0 || !code.trim_end().ends_with(',')).then_some(open)
}

/// Scans `source` for structs with `#[derive(..LogicBlock..)]` and checks that
/// every `pub` field (a port; private fields are sub-blocks, registers and
/// locals) has a `///` doc comment directly above it. A blank line, a `//`
/// comment or another field between the doc and the field breaks the link;
/// `#[...]` attributes do not.
fn scan_block_ports(source: &str) -> PortScan {
    let lines: Vec<&str> = source.lines().collect();
    let mut scan = PortScan::default();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i].trim();
        i += 1;
        let derives_block = line.starts_with("#[derive(")
            && line["#[derive(".len()..]
                .split(|c: char| !(c.is_alphanumeric() || c == '_'))
                .any(|w| w == "LogicBlock");
        if !derives_block {
            continue;
        }
        // the struct's opening brace (after more attributes, docs, generics)
        while i < lines.len() && !code_part(lines[i]).contains('{') {
            i += 1;
        }
        if i >= lines.len() {
            break;
        }
        scan.blocks += 1;
        let opening = code_part(lines[i]);
        let mut depth = opening.matches('{').count() as i64 - opening.matches('}').count() as i64;
        i += 1;
        let mut doc_above = false;
        let mut in_attribute = false;
        // brackets still open in the field being read (a type over several lines)
        let mut field_open: Option<i64> = None;
        while i < lines.len() && depth > 0 {
            let raw = lines[i];
            let line = raw.trim();
            i += 1;
            let code = code_part(raw);
            depth += code.matches('{').count() as i64 - code.matches('}').count() as i64;
            if depth <= 0 {
                break;
            }
            if let Some(open) = field_open {
                field_open = field_end(open, code);
                continue;
            }
            if line.starts_with("///") || line.starts_with("#[doc") {
                doc_above = true;
                continue;
            }
            if in_attribute || line.starts_with("#[") {
                in_attribute = !code.trim_end().ends_with(']');
                continue;
            }
            if line.starts_with("pub ") || line.starts_with("pub(") {
                let rest = line.strip_prefix("pub").unwrap_or(line).trim_start();
                let rest = match rest.strip_prefix('(') {
                    Some(r) => r.split_once(')').map_or(r, |(_, after)| after).trim_start(),
                    None => rest,
                };
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                scan.ports += 1;
                if !doc_above {
                    scan.undocumented.push((i, name));
                }
            }
            if !line.is_empty() && !line.starts_with("//") {
                field_open = field_end(0, code);
            }
            doc_above = false;
        }
    }
    scan
}

/// Every `.rs` file under `dir`, sorted.
fn rust_files(dir: &std::path::Path) -> Vec<std::path::PathBuf> {
    let mut files = Vec::new();
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            files.extend(rust_files(&path));
        } else if path.extension().is_some_and(|x| x == "rs") {
            files.push(path);
        }
    }
    files
}

/// Every port of every rust-hdl block in drcc-hdl (and its hub shapes) has a
/// `///` doc comment (docs/design.md, "Conventions"), not only the tops' (the
/// test above): the scan names `file:line field` of each one without.
#[test]
fn every_port_of_every_block_is_documented() {
    let hdl = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let repo = hdl.parent().expect("the workspace root");
    let (mut blocks, mut ports, mut missing) = (0, 0, Vec::new());
    for dir in ["src", "shapes/src"] {
        for file in rust_files(&hdl.join(dir)) {
            let source = std::fs::read_to_string(&file).unwrap();
            let scan = scan_block_ports(&source);
            blocks += scan.blocks;
            ports += scan.ports;
            let name = file
                .strip_prefix(repo)
                .unwrap_or(&file)
                .display()
                .to_string();
            for (line, field) in scan.undocumented {
                missing.push(format!("{name}:{line} {field}"));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "{} block ports have no `///` doc comment:\n{}",
        missing.len(),
        missing.join("\n")
    );
    // the scan found the blocks: it cannot pass by checking nothing
    assert!(blocks > 50, "only {blocks} LogicBlock structs found");
    assert!(ports > 1000, "only {ports} ports found in {blocks} blocks");
}

/// The scanner reports exactly the undocumented `pub` field of a block, past
/// group comments, attributes, multi-line types and private fields, and
/// ignores structs that are not blocks.
#[test]
fn every_port_scan_reports_only_undocumented_pub_fields() {
    const SOURCE: &str = "
/// Not a block: its fields are not ports.
#[derive(Clone, Debug)]
pub struct Plain {
    pub undocumented_but_no_port: u8,
}

/// A block.
#[derive(LogicBlock, Default)]
pub struct Blk<const N: usize> {
    // ---- group comment, not a doc ----
    /// Documented, with an attribute between doc and field.
    #[allow(dead_code)]
    pub documented: Signal<In, Bits<N>>,
    /// A doc comment
    /// over two lines, a type over two.
    pub wide: Signal<
        Out,
        Bits<N>,
    >,
    pub undocumented: Signal<Out, Bit>,
    inner: DFF<Bit>,
    /// Doc of a private field.
    local: Signal<Local, Bit>,
}
";
    let scan = scan_block_ports(SOURCE);
    assert_eq!(
        scan,
        PortScan {
            blocks: 1,
            ports: 3,
            undocumented: vec![(21, "undocumented".to_string())],
        }
    );
    assert_eq!(
        SOURCE.lines().nth(20).map(str::trim),
        Some("pub undocumented: Signal<Out, Bit>,"),
        "line numbers are 1-based"
    );
}

/// The header's port table lists exactly the probed ports, in order, with
/// their direction and width, and each declaration is preceded by its doc.
#[test]
fn header_lists_exactly_the_probed_ports() {
    for t in TOPS {
        let text = t.verilog();
        let header: Vec<&str> = text.lines().take_while(|l| l.starts_with("//")).collect();
        let start = header
            .iter()
            .position(|l| l.starts_with("// Ports:"))
            .expect("port table")
            + 2;
        let rows: Vec<(String, String, String)> = header[start..]
            .iter()
            .map(|l| l.trim_start_matches("//"))
            .take_while(|l| !l.trim().is_empty())
            .filter(|l| l.starts_with(" input") || l.starts_with(" output"))
            .map(|l| {
                let f: Vec<&str> = l.split_whitespace().collect();
                (f[0].to_string(), f[1].to_string(), f[2].to_string())
            })
            .collect();
        let probed: Vec<(String, String, String)> = t
            .ports()
            .into_iter()
            .map(|p| {
                let dir = match p.direction {
                    Direction::Input => "input",
                    Direction::Output => "output",
                };
                (dir.to_string(), p.width.to_string(), p.name)
            })
            .collect();
        assert_eq!(rows, probed, "header port table of {}", t.name);
        for p in t.ports() {
            let first_doc_line: String = drcc_hdl::tops::port_docs::wrap(&p.doc, 60)[0]
                .split_whitespace()
                .take(3)
                .collect::<Vec<_>>()
                .join(" ");
            let decl = text
                .lines()
                .position(|l| {
                    let l = l.trim();
                    (l.starts_with("input ") || l.starts_with("output "))
                        && l.ends_with(&format!(" {};", p.name))
                })
                .unwrap_or_else(|| panic!("declaration of {}", p.name));
            let above: Vec<&str> = text.lines().take(decl).collect();
            let comment: Vec<&str> = above
                .iter()
                .rev()
                .take_while(|l| l.trim().starts_with("//"))
                .copied()
                .collect();
            let comment = comment.iter().rev().copied().collect::<Vec<_>>().join(" ");
            assert!(
                comment.contains(&first_doc_line),
                "declaration of {}.{} lacks its doc: {comment:?}",
                t.name,
                p.name
            );
        }
    }
}

/// The channel header states the frame layout, which differs from the
/// DRCC's registers (timing contract §4.4, drcc contract §3).
#[test]
fn channel_header_states_the_frame_layout() {
    let text = top("can_channel").unwrap().verilog();
    assert!(text.contains("tx_data/rx_data[63:56]           TX_DATA0/RX_DATA0[7:0]"));
    assert!(text.contains("tx_id/rx_id[10:0], [28:11] = 0"));
}
