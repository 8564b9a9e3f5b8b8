//! Every offered configuration (drcc_contract.md §1.1, `drcc_hdl::config`) emits
//! the same Verilog as the proven top with its `M` (`drcc` or `drcc_m0`) except
//! for the defaults of the size parameters (`parameter ... = value;`, which set
//! the `localparam`s): the sizes and the mode switches (`dmr`, `star`) change
//! constants only, never the structure. So the lint of `drcc`, `drcc_m0` and
//! `drcc_small` (hdl/lint/lint.sh) speaks for every configuration's structure,
//! and the lock step of `drcc_small` (testbench/tests/drcc_small_faults.rs,
//! drcc_sizes.rs) for the constants' meaning.

use drcc_hdl::config::{DrccConfig, HISTORY_SIZES, RX_FIFO_DEPTHS, TX_QUEUE_DEPTHS};
use drcc_hdl::tops::drcc_with_config;

/// The Verilog with the header comment dropped and every parameter's and
/// localparam's value blanked (`parameter integer HISTORY = 32;` ->
/// `parameter integer HISTORY;`).
fn structure(cfg: &DrccConfig) -> String {
    let v = drcc_with_config("drcc_cfg", cfg).unwrap();
    let body = &v[v.find("module drcc_cfg(").expect("module")..];
    body.lines()
        .map(|l| {
            let t = l.trim_start();
            let constant = t.starts_with("localparam") || t.starts_with("parameter");
            match (constant, l.find('=')) {
                (true, Some(eq)) => format!("{};", l[..eq].trim_end()),
                _ => l.to_string(),
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Lines that differ between two texts of equal line count.
fn differing(a: &str, b: &str) -> Vec<String> {
    a.lines()
        .zip(b.lines())
        .filter(|(x, y)| x != y)
        .take(3)
        .map(|(x, y)| format!("{x:?} vs {y:?}"))
        .collect()
}

#[test]
fn sizes_change_localparam_values_only() {
    for m in [0, 16] {
        let base = DrccConfig {
            mailboxes: m,
            ..DrccConfig::DEFAULT
        };
        let reference = structure(&base);
        let mut variants = vec![DrccConfig {
            mailboxes: m,
            rx_fifo_depth: RX_FIFO_DEPTHS[0],
            tx_queue_depth: TX_QUEUE_DEPTHS[0],
            history: HISTORY_SIZES[0],
            star: false,
            ..base
        }];
        if m == 0 {
            variants.push(DrccConfig { dmr: false, ..base });
            variants.push(DrccConfig {
                star: false,
                ..base
            });
            variants.push(DrccConfig::SMALL);
            variants.extend(RX_FIFO_DEPTHS.iter().map(|&d| DrccConfig {
                rx_fifo_depth: d,
                ..base
            }));
            variants.extend(TX_QUEUE_DEPTHS.iter().map(|&d| DrccConfig {
                tx_queue_depth: d,
                ..base
            }));
            variants.extend(
                HISTORY_SIZES
                    .iter()
                    .map(|&d| DrccConfig { history: d, ..base }),
            );
        }
        for cfg in variants {
            let s = structure(&cfg);
            assert_eq!(
                s.lines().count(),
                reference.lines().count(),
                "{cfg:?}: line count"
            );
            assert!(s == reference, "{cfg:?}: {:?}", differing(&s, &reference));
        }
    }
}

/// And the values do change: the smallest configuration's parameter defaults
/// are its sizes, and they reach the masks and the full counts, so the test
/// above is not comparing two equal texts.
#[test]
fn the_size_localparams_carry_the_configuration() {
    let tiny = DrccConfig {
        mailboxes: 0,
        rx_fifo_depth: 4,
        tx_queue_depth: 2,
        history: 4,
        dmr: false,
        star: false,
    };
    let v = drcc_with_config("drcc_cfg", &tiny).unwrap();
    for line in [
        "parameter integer RX_FIFO_DEPTH = 4;",
        "parameter integer TX_QUEUE_DEPTH = 2;",
        "parameter integer HISTORY = 4;",
        "parameter integer DMR = 0;",  // no DMR function
        "parameter integer STAR = 0;", // no replicated-star node
        "localparam [4:0] mask = RX_FIFO_DEPTH[4:0] - 5'd1;", // RX FIFO pointer mask
        "localparam [4:0] hmask = HISTORY[4:0] - 5'd1;", // history index mask
        "localparam [5:0] last_scan = HISTORY;", // a scan of H + 1 clocks
        "localparam [5:0] fifo_depth = RX_FIFO_DEPTH;",
        "localparam [2:0] qmask = TX_QUEUE_DEPTH[2:0] - 3'd1;", // TX queue mask
        "localparam [3:0] queue_full = TX_QUEUE_DEPTH;",
        "localparam [0:0] dmr_present = DMR;",
        "localparam [0:0] star_present = STAR;",
    ] {
        assert!(v.contains(line), "missing {line}");
    }
}

/// The SJA1000 view's tops in `rtl-out/` are built with the generator's
/// default keys: their header parameters name those keys, and the `XMODE`
/// reset value in their Verilog is the one those keys give (§13, P-GEN-1).
#[test]
fn the_pelican_tops_carry_the_default_keys() {
    use drcc_hdl::pelican::PelicanKeys;
    let k = PelicanKeys::default();
    let want: Vec<(String, String)> = k
        .params()
        .into_iter()
        .filter(|(n, _)| n.starts_with("PELICAN_"))
        .map(|(n, v)| (n.to_string(), v))
        .collect();
    for name in ["drcc_pelican", "drcc_pelican_apb", "drcc_pelican_axi"] {
        let top = drcc_hdl::tops::top(name).expect(name);
        let have: Vec<(String, String)> = top
            .params
            .iter()
            .filter(|(n, _)| n.starts_with("PELICAN_"))
            .map(|(n, v)| (n.to_string(), v.to_string()))
            .collect();
        assert_eq!(have, want, "{name}: header parameters");
        let v = top.verilog();
        let line = format!("localparam  xmode_reset = 8'h{:02x};", k.xmode());
        assert!(v.contains(&line), "{name}: {line}");
    }
}
