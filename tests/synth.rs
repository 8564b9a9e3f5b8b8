//! The FPGA flow end to end: `drcc synth --target ice40 --top can_channel` runs
//! yosys, nextpnr-ice40 and icepack, writes a bitstream and reports non-zero
//! LUT / FF counts, the area block by block (`--breakdown`) and the Fmax
//! nextpnr measured (about 50 s on 2 cores).
//!
//! Without the tools the flow test is skipped, except under CI
//! (`verilator_sys::required()`: `CI` or `DRCC_REQUIRE_VERILATOR` set to anything
//! but empty, `0`, `false`, `no` or `off`), where it fails with the install hint.

use std::process::{Command, Output};

use drcc_fpga::SynthReport;

fn drcc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_drcc"))
        .args(args)
        .output()
        .expect("cannot run the drcc binary")
}

/// Whether missing tools fail the test: `drcc_tools::required`, the one rule
/// (`DRCC_REQUIRE_VERILATOR` or `CI` set to anything but empty, `0`, `false`,
/// `no` or `off`) every test that needs an external tool follows.
fn ci() -> bool {
    drcc_tools::required()
}

#[test]
fn ice40_flow_writes_a_bitstream_and_reports_area_and_fmax() {
    let dir = std::env::temp_dir().join(format!("drcc-synth-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let dir_s = dir.display().to_string();
    let out = drcc(&[
        "synth",
        "--target",
        "ice40",
        "--top",
        "can_channel",
        "--json",
        "--breakdown",
        "--build-dir",
        &dir_s,
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        if stderr.contains("not found on PATH") {
            assert!(
                !ci(),
                "the FPGA tools are required in CI: {}",
                stderr.trim()
            );
            eprintln!("skipped: {}", stderr.trim());
            return;
        }
        panic!("drcc synth failed ({}): {stderr}", out.status);
    }
    let report: SynthReport = serde_json::from_str(stdout.trim())
        .unwrap_or_else(|e| panic!("--json is not one report ({e}): {stdout}"));
    assert_eq!(
        (report.top.as_str(), report.target.name),
        ("can_channel", "ice40")
    );
    let m = report
        .measured
        .as_ref()
        .unwrap_or_else(|| panic!("no numbers: {report:?}"));
    let (lut, ff) = (m.top_area.lut, m.top_area.ff);
    assert!(lut > 0 && ff > 0, "LUT {lut}, FF {ff}: {report:?}");
    // The wrapper adds its scan chain on top of the channel.
    assert!(m.wrapper_area.ff > ff, "{report:?}");
    // By block: the channel's four blocks (rust-hdl fields of CanChannel), the
    // protocol block the largest, and with the boundaries kept the sum is at
    // least the flattened count (no sharing across them) but not far above it.
    let b = m.breakdown.as_ref().expect("--breakdown gives the blocks");
    let mut names: Vec<&str> = b.blocks.iter().map(|x| x.block.as_str()).collect();
    assert_eq!(b.blocks[0].block, "bsp", "{b:?}");
    names.sort();
    assert_eq!(names, ["bsp", "btl", "cfg_regs", "rx_sync"], "{b:?}");
    let sum: u64 = b.blocks.iter().map(|x| x.area.lut).sum::<u64>() + b.glue.lut;
    assert_eq!(sum, b.total.lut, "{b:?}");
    assert!(
        b.total.lut >= lut * 95 / 100 && b.total.lut <= lut * 125 / 100,
        "blocks' sum {} LUT4 against {lut} flattened: {b:?}",
        b.total.lut
    );
    let pnr = m.pnr.as_ref().expect("iCE40 is placed and routed");
    assert!(
        pnr.fmax_mhz > 1.0 && pnr.fmax_mhz < 1000.0,
        "Fmax {} MHz: {report:?}",
        pnr.fmax_mhz
    );
    assert_eq!(pnr.constraint_mhz, 12.0, "{report:?}");
    let bitstream = &pnr.bitstream;
    assert!(bitstream.starts_with(&dir), "{}", bitstream.display());
    let len = std::fs::metadata(bitstream)
        .unwrap_or_else(|e| panic!("no bitstream {}: {e}", bitstream.display()))
        .len();
    // An iCE40UP5K bitstream is about 100 kB.
    assert!(len > 50_000, "bitstream of {len} bytes");
    let wrapper = dir.join("can_channel-ice40").join("can_channel_scan.v");
    let v = std::fs::read_to_string(&wrapper).expect("the scan wrapper is kept");
    assert!(v.contains("module can_channel_scan("), "{v}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_missing_tool_is_named_with_its_package() {
    let empty = std::env::temp_dir().join(format!("drcc-synth-nopath-{}", std::process::id()));
    std::fs::create_dir_all(&empty).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_drcc"))
        .args(["synth", "--target", "ice40"])
        .env("PATH", &empty)
        .output()
        .expect("cannot run the drcc binary");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("yosys (Debian/Ubuntu package yosys)")
            && stderr.contains("icepack (Debian/Ubuntu package fpga-icestorm)")
            && stderr.contains("sudo apt-get install yosys nextpnr-ice40 fpga-icestorm"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    let _ = std::fs::remove_dir_all(&empty);
}

#[test]
fn bad_arguments_are_errors_not_panics() {
    for (args, want) in [
        (
            &["synth", "--target", "ecp5"][..],
            "--target ecp5: unknown FPGA family; legal values are ice40, ice40hx, xc3s, xc7",
        ),
        (
            &["synth", "--target", "ice40", "--top", "nope"][..],
            "--top nope: unknown top; the tops are can_channel",
        ),
        (&["synth"][..], "give --target"),
        (&["synth", "--markdown"][..], "use it with --all"),
    ] {
        let out = drcc(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(want), "{args:?}: {stderr}");
    }
}
