//! Tests of `drcc_hdl::tops::params`.

use drcc_hdl::tops::params::*;
use std::collections::{BTreeMap, BTreeSet};

mod tests {
    use super::*;
    use drcc_hdl::tops::top;

    /// `text` with the top's name `name` written as `drcc`, without comments and
    /// without the lines that hold a parameter's default.
    fn normalised(text: &str, name: &str) -> Vec<String> {
        text.lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .filter(|l| !l.trim_start().starts_with("parameter "))
            .map(|l| l.split(" // ").next().unwrap_or(l))
            .map(|l| {
                l.replace(&format!("{name}__"), "drcc__")
                    .replace(&format!("module {name}("), "module drcc(")
            })
            .collect()
    }

    /// `drcc_small` is `drcc_m0` with other parameter values (§1.1): the same
    /// text but for the defaults, so `drcc_m0 #(.RX_FIFO_DEPTH(8), ...)` elaborates
    /// the Verilog the lock-step suite proves as `drcc_small`.
    #[test]
    fn small_is_m0_with_other_parameter_values() {
        let m0 = top("drcc_m0").expect("drcc_m0").verilog();
        let small = top("drcc_small").expect("drcc_small").verilog();
        let (a, b) = (normalised(&m0, "drcc_m0"), normalised(&small, "drcc_small"));
        let diff: Vec<_> = a.iter().zip(&b).filter(|(x, y)| x != y).take(3).collect();
        assert!(diff.is_empty() && a.len() == b.len(), "{diff:?}");
        assert!(small.contains("parameter integer RX_FIFO_DEPTH = 8;"));
        assert!(m0.contains("parameter integer RX_FIFO_DEPTH = 32;"));
        assert!(small.contains("parameter integer DMR = 0;"));
    }

    /// Every instance of a module that declares a parameter passes it on, so no
    /// block falls back to its own default.
    #[test]
    fn every_parameter_is_passed_down() {
        for name in ["drcc", "drcc_m0", "drcc_small", "drcc_apb", "drcc_axi"] {
            let text = top(name).expect("a top").verilog();
            let mut declared: BTreeMap<String, Vec<String>> = BTreeMap::new();
            let mut current = String::new();
            for l in text.lines() {
                if let Some(m) = module_name(l) {
                    current = m.to_string();
                }
                if let Some(rest) = l.trim().strip_prefix("parameter ") {
                    let p = rest.split_whitespace().nth(1).expect("a name");
                    declared
                        .entry(current.clone())
                        .or_default()
                        .push(p.to_string());
                }
            }
            let modules: BTreeSet<&str> = declared.keys().map(|s| s.as_str()).collect();
            let mut instances = 0;
            for l in text.lines() {
                let t = l.trim_start();
                let ty = t.split_whitespace().next().unwrap_or("");
                if !modules.contains(ty) || t.starts_with("module ") {
                    continue;
                }
                instances += 1;
                for p in &declared[ty] {
                    assert!(t.contains(&format!(".{p}({p}")), "{name}: {t} lacks {p}");
                }
            }
            assert!(
                instances >= 5,
                "{name}: {instances} parameterised instances"
            );
            let sizes = verilog_parameters(top(name).expect("a top").params);
            assert_eq!(declared[name].len(), sizes.len(), "{name}");
        }
    }

    /// `DMR` is a parameter only without mailboxes; the channel and the hub have
    /// none.
    #[test]
    fn dmr_is_a_parameter_only_where_there_are_no_mailboxes() {
        let names = |t: &str| -> Vec<&str> {
            verilog_parameters(top(t).expect("a top").params)
                .into_iter()
                .map(|(n, _)| n)
                .collect()
        };
        assert!(!names("drcc").contains(&"DMR"));
        assert!(names("drcc_m0").contains(&"DMR"));
        assert!(names("can_channel").is_empty() && names("hub").is_empty());
    }

    #[test]
    fn literals_read_in_every_base() {
        assert_eq!(literal_value("5'b11111"), Some(31));
        assert_eq!(literal_value("4'h8"), Some(8));
        assert_eq!(literal_value("6'd32"), Some(32));
        assert_eq!(literal_value("32"), None);
    }
}
