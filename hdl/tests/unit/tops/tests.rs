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
