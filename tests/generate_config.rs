//! `drcc generate --config`: configurations of your own come out lint-clean
//! (hdl/lint/lint.sh: Verilator -Wall with the repository's waivers, Icarus,
//! yosys `check -assert`). The DRCC's sizes change
//! localparams only (hdl/tests/configurations.rs), so one DRCC configuration with
//! every size at its smallest stands for them; the hub's shape changes port and
//! vector widths, so its extremes are linted: the smallest (N 2, M 2, hub A) and
//! the largest (N 8, M 4, hub B), and one hub on each of APB and AXI4-Lite (named
//! `*_apb` / `*_axi`, which the lint waivers for a bus top's unused probes
//! match), and the SJA1000 view on APB with keys of its own. Also: the files land only in `--out`, and `--check` passes on them.
//!
//! Without the tools the lint is skipped, except under CI, where it fails.

use std::path::Path;
use std::process::{Command, Output};

fn drcc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_drcc"))
        .args(args)
        .output()
        .expect("cannot run the drcc binary")
}

/// hdl/lint/lint.sh (its three checks) on `dir/<top>.v` for every top.
fn lint(dir: &Path, tops: &[&str]) {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/hdl/lint/lint.sh");
    let files: Vec<String> = tops
        .iter()
        .map(|t| dir.join(format!("{t}.v")).to_str().unwrap().to_string())
        .collect();
    let out = Command::new("bash")
        .arg(script)
        .args(&files)
        .output()
        .expect("cannot run bash");
    assert!(
        out.status.success(),
        "lint.sh failed:\n{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn configurations_of_your_own_are_lint_clean() {
    let dir = std::env::temp_dir().join(format!("drcc-genconfig-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let configs = [
        (
            "drcc_tiny",
            "name = \"drcc_tiny\"\nmailboxes = 0\nrx_fifo_depth = 4\ntx_queue_depth = 2\n\
             history = 4\ndmr = false\nstar = false\n",
        ),
        (
            "hub_2x2",
            "top = \"hub\"\nname = \"hub_2x2\"\nnodes = 2\ninterlinks = 2\n",
        ),
        (
            "hub_b_8x4",
            "top = \"hub\"\nname = \"hub_b_8x4\"\nnodes = 8\ninterlinks = 4\nhub_id = 1\n",
        ),
        (
            "hub_3x2_apb",
            "top = \"hub\"\nname = \"hub_3x2_apb\"\nnodes = 3\nbus = \"apb\"\n",
        ),
        (
            "hub_b_2x3_axi",
            "top = \"hub\"\nname = \"hub_b_2x3_axi\"\nnodes = 2\ninterlinks = 3\nhub_id = 1\n\
             bus = \"axi4-lite\"\ndata_width = 32\n",
        ),
        (
            "drcc_sja_apb",
            "name = \"drcc_sja_apb\"\nhost = \"pelican\"\nbus = \"apb\"\nmailboxes = 0\n\
             dmr = false\nrx_fifo_depth = 8\npelican_policy = \"k-failed\"\npelican_k = 3\n",
        ),
    ];
    let out_dir = dir.join("out");
    let out_s = out_dir.to_str().unwrap().to_string();
    for (top, text) in configs {
        let cfg = dir.join(format!("{top}.toml"));
        std::fs::write(&cfg, text).unwrap();
        let cfg_s = cfg.to_str().unwrap();
        let o = drcc(&["generate", "--config", cfg_s, "--out", &out_s]);
        assert!(
            o.status.success(),
            "{top}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let o = drcc(&["generate", "--config", cfg_s, "--out", &out_s, "--check"]);
        assert!(o.status.success(), "{top}: --check after writing");
    }
    let mut written: Vec<String> = std::fs::read_dir(&out_dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    written.sort();
    assert_eq!(
        written,
        [
            "drcc_sja_apb.v",
            "drcc_tiny.v",
            "hub_2x2.v",
            "hub_3x2_apb.v",
            "hub_b_2x3_axi.v",
            "hub_b_8x4.v"
        ]
    );
    // the bus is the one asked for, and named in the header
    let text = |top: &str| std::fs::read_to_string(out_dir.join(format!("{top}.v"))).unwrap();
    let apb = text("hub_3x2_apb");
    assert!(apb.contains("BUS = apb") && apb.contains("input wire  s_apb_psel;"));
    let header = apb
        .lines()
        .find(|l| l.starts_with("module hub_3x2_apb("))
        .expect("the top module");
    assert!(
        header.contains("s_apb_pready") && !header.contains("wb_cyc_i"),
        "APB ports and no Wishbone port on the APB hub's top: {header}"
    );
    let axi = text("hub_b_2x3_axi");
    assert!(axi.contains("BUS = axi4-lite") && axi.contains("output reg  s_axi_bvalid;"));
    assert!(
        axi.contains("input wire  [2:0] sublink_in;"),
        "3 interlinks"
    );
    // the SJA1000 view on APB: 128 registers at stride 4 need a 9-bit byte address
    let sja = text("drcc_sja_apb");
    assert!(
        sja.contains("BUS = apb")
            && sja.contains("PELICAN_POLICY = k-failed")
            && sja.contains("input wire  [8:0] s_apb_paddr;"),
        "the view's APB top with its keys and a 9-bit address"
    );
    if !drcc_tools::need_all(&[
        drcc_tools::VERILATOR,
        drcc_tools::IVERILOG,
        drcc_tools::YOSYS,
    ]) {
        return;
    }
    let tops: Vec<&str> = configs.iter().map(|(top, _)| *top).collect();
    lint(&out_dir, &tops);
    let _ = std::fs::remove_dir_all(&dir);
}
