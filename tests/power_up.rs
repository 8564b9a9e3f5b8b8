//! Power-up safety of the CAN pins: from the end of FPGA configuration on, before
//! any clock edge and with `rst` never asserted, every CAN transmit pin of every
//! top is recessive (1, ISO 11898-1's recessive level on the controller side),
//! so a node that is still waiting for its clock or reset never holds a bus
//! dominant.
//!
//! - The emitted RTL (`rtl-out/<top>.v`) on Icarus: a testbench with the clock
//!   held at 0, `rst` at 0, every `rx` recessive and every other input 0 reads
//!   every pin at 1 ns and at 5 µs.
//! - The netlists of yosys `synth_ice40` and `synth_xilinx`: the same testbench
//!   on the gate-level netlist with yosys's cell models, so the flip-flops'
//!   initial values are checked where they end up (the `INIT` of the Xilinx
//!   flip-flop, the iCE40 flip-flop's fixed power-up 0), not in the source.
//!
//! Without Icarus or yosys the tests are skipped with one line, except in CI
//! (`drcc_tools::need`), where they fail.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The CAN pins a top drives onto a bus (1 = recessive), by top.
fn can_pins(top: &str) -> &'static [&'static str] {
    match top {
        "can_channel" => &["tx"],
        "drcc" | "drcc_m0" | "drcc_small" => &["chan_a_tx", "chan_b_tx"],
        "hub" | "hub_b" => &["downlink", "sublink_out", "hub_tx"],
        _ => &[],
    }
}

/// One port of a top, from the port table in its generated header.
struct Port {
    input: bool,
    width: u32,
    name: String,
}

fn workspace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The ports of `rtl-out/<top>.v`, read from its header's port table
/// (`// input      1  clk   meaning`).
fn ports(top: &str) -> Vec<Port> {
    let text = std::fs::read_to_string(workspace().join(format!("rtl-out/{top}.v")))
        .unwrap_or_else(|e| panic!("rtl-out/{top}.v: {e}"));
    let mut ports = Vec::new();
    for line in text.lines().take_while(|l| l.starts_with("//")) {
        let f: Vec<&str> = line.trim_start_matches("//").split_whitespace().collect();
        if f.len() >= 3 && (f[0] == "input" || f[0] == "output") {
            if let Ok(width) = f[1].parse() {
                ports.push(Port {
                    input: f[0] == "input",
                    width,
                    name: f[2].to_string(),
                });
            }
        }
    }
    assert!(
        ports.iter().any(|p| p.name == "clk"),
        "{top}: no port table"
    );
    ports
}

/// A testbench for `top`: no clock edge, no reset, `rx` pins recessive, every
/// other input 0; prints `PIN <name> <value>` for each CAN pin at 1 ns and 5 µs.
fn testbench(top: &str) -> String {
    let ports = ports(top);
    let mut tb = String::from("`timescale 1ns/1ps\nmodule power_up_tb;\n");
    for p in &ports {
        let range = if p.width > 1 {
            format!("[{}:0] ", p.width - 1)
        } else {
            String::new()
        };
        let kind = if p.input { "reg" } else { "wire" };
        tb.push_str(&format!("  {kind} {range}{};\n", p.name));
    }
    tb.push_str("  initial begin\n");
    for p in ports.iter().filter(|p| p.input) {
        let recessive = p.name == "rx"
            || p.name.ends_with("_rx")
            || p.name == "uplink"
            || p.name == "sublink_in";
        let v = if recessive { "~0" } else { "0" };
        tb.push_str(&format!("    {} = {v};\n", p.name));
    }
    for t in ["1", "4999"] {
        tb.push_str(&format!("    #{t};\n"));
        for pin in can_pins(top) {
            tb.push_str(&format!(
                "    $display(\"PIN {pin} %b at %0t\", {pin}, $time);\n"
            ));
        }
    }
    tb.push_str("    $finish;\n  end\n");
    let conns: Vec<String> = ports.iter().map(|p| format!(".{0}({0})", p.name)).collect();
    tb.push_str(&format!("  {top} uut({});\nendmodule\n", conns.join(", ")));
    tb
}

/// Runs the testbench on `sources` with Icarus and checks every pin line.
fn run_icarus(dir: &Path, top: &str, what: &str, sources: &[PathBuf]) {
    let tb = dir.join(format!("{top}_{what}_power_up_tb.v"));
    std::fs::write(&tb, testbench(top)).unwrap();
    let vvp = dir.join(format!("{top}_{what}.vvp"));
    let out = Command::new("iverilog")
        // Icarus does not take default values on ports (yosys's iCE40 models).
        .args(["-g2012", "-DNO_ICE40_DEFAULT_ASSIGNMENTS", "-o"])
        .arg(&vvp)
        .args(["-s", "power_up_tb"])
        .arg(&tb)
        .args(sources)
        .output()
        .expect("iverilog runs");
    assert!(
        out.status.success(),
        "{top} ({what}): iverilog failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = Command::new("vvp")
        .arg("-n")
        .arg(&vvp)
        .output()
        .expect("vvp runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let lines: Vec<&str> = stdout.lines().filter(|l| l.starts_with("PIN ")).collect();
    assert_eq!(
        lines.len(),
        2 * can_pins(top).len(),
        "{top} ({what}): every pin read twice:\n{stdout}"
    );
    for l in lines {
        let value = l.split_whitespace().nth(2).unwrap();
        assert!(
            value.chars().all(|c| c == '1'),
            "{top} ({what}): a CAN pin is not recessive before any clock or reset: {l}"
        );
    }
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("drcc-power-up-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Every top with CAN pins, in the emitted RTL.
#[test]
fn rtl_pins_are_recessive_before_any_clock_or_reset() {
    if !drcc_tools::need(&drcc_tools::IVERILOG) {
        return;
    }
    let dir = scratch("rtl");
    let mut checked = 0;
    for top in [
        "can_channel",
        "drcc",
        "drcc_m0",
        "drcc_small",
        "drcc_pelican",
        "hub",
        "hub_b",
    ] {
        let rtl = workspace().join(format!("rtl-out/{top}.v"));
        run_icarus(&dir, top, "rtl", &[rtl]);
        checked += 1;
    }
    assert_eq!(checked, 7);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The gate-level netlist of `top` after yosys's `synth_<family>`, written
/// without attributes, and the cell models it needs.
fn netlist(dir: &Path, top: &str, family: &str) -> Vec<PathBuf> {
    let rtl = workspace().join(format!("rtl-out/{top}.v"));
    let net = dir.join(format!("{top}_{family}.v"));
    let script = format!(
        "read_verilog {}; synth_{family} -top {top}; write_verilog -noattr {}",
        rtl.display(),
        net.display()
    );
    let out = Command::new("yosys")
        .args(["-q", "-p", &script])
        .output()
        .expect("yosys runs");
    assert!(
        out.status.success(),
        "{top}: yosys synth_{family} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cells = yosys_share().join(family).join("cells_sim.v");
    assert!(
        cells.exists(),
        "yosys's {family} cell models: {} is missing",
        cells.display()
    );
    vec![net, cells]
}

/// yosys's data directory (`/usr/share/yosys` for Debian's package).
fn yosys_share() -> PathBuf {
    let yosys = which("yosys").expect("yosys on PATH");
    yosys
        .parent()
        .and_then(Path::parent)
        .map(|p| p.join("share/yosys"))
        .expect("yosys's share directory")
}

fn which(cmd: &str) -> Option<PathBuf> {
    std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|d| d.join(cmd))
            .find(|p| p.is_file())
    })
}

/// The channel (iCE40 and Xilinx 7-series) and the hub (iCE40) after synthesis.
#[test]
fn synthesized_pins_are_recessive_before_any_clock_or_reset() {
    if !drcc_tools::need_all(&[drcc_tools::IVERILOG, drcc_tools::YOSYS]) {
        return;
    }
    let dir = scratch("net");
    // one thread per netlist: the yosys runs take the test's time
    std::thread::scope(|scope| {
        for (top, family) in [
            ("can_channel", "ice40"),
            ("can_channel", "xilinx"),
            ("hub", "ice40"),
        ] {
            let dir = &dir;
            scope.spawn(move || {
                let sources = netlist(dir, top, family);
                run_icarus(dir, top, family, &sources);
            });
        }
    });
    let _ = std::fs::remove_dir_all(&dir);
}
