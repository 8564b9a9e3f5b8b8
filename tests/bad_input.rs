//! Bad input on the command line: every case exits 2 with one
//! message that names what is wrong and how to fix it, and changes no file; the
//! run does not start. (Generated files and the checkout rule:
//! `tests/generated_files.rs`.)

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn drcc_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_drcc"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("cannot run the drcc binary")
}

/// A scratch directory holding a copy of the demo scenario as `x.toml`.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("drcc-bad-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    let demo = Path::new(env!("CARGO_MANIFEST_DIR")).join("testbench/scenarios/demo.toml");
    std::fs::copy(demo, d.join("x.toml")).unwrap();
    d
}

/// Every file in `d` (not recursive) with its content.
fn files(d: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut v: Vec<_> = std::fs::read_dir(d)
        .unwrap()
        .flatten()
        .map(|e| (e.path(), std::fs::read(e.path()).unwrap_or_default()))
        .collect();
    v.sort();
    v
}

/// Runs `args` in `d` and checks: exit 2, one line naming `what` and `fix`, and
/// every file of `d` as it was.
fn refused(d: &Path, args: &[&str], what: &str, fix: &str) {
    let before = files(d);
    let o = drcc_in(d, args);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "{args:?}: one message: {err}"
    );
    assert!(
        err.contains(what),
        "{args:?} names the problem ({what}): {err}"
    );
    assert!(err.contains(fix), "{args:?} names the fix ({fix}): {err}");
    assert!(o.stdout.is_empty(), "{args:?}: the run did not start");
    assert_eq!(files(d), before, "{args:?} changed a file");
}

#[test]
fn an_output_never_replaces_the_input_or_another_output() {
    let d = scratch("outputs");
    refused(
        &d,
        &["sim", "x.toml", "--vcd", "x.toml"],
        "that is the input x.toml",
        "give another file name",
    );
    refused(
        &d,
        &["sim", "x.toml", "--bus-vcd", "./x.toml"],
        "that is the input",
        "give another file name",
    );
    refused(
        &d,
        &[
            "sim",
            "x.toml",
            "--vcd",
            "t.vcd",
            "--bus-vcd",
            "sub/../t.vcd",
        ],
        "--vcd and --bus-vcd both name",
        "each output needs a file of its own",
    );
    // a good run writes both traces, through temporary files that do not stay
    let o = drcc_in(
        &d,
        &["sim", "x.toml", "--vcd", "t.vcd", "--bus-vcd", "b.vcd"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let names: Vec<String> = files(&d)
        .iter()
        .map(|(p, _)| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        names,
        ["b.vcd", "t.vcd", "x.toml"],
        "no temporary file left"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn redundancy_options_that_would_be_ignored_are_refused() {
    let d = scratch("redundancy");
    let policies = "the policies are error-passive, warning, none, k1 .. k15";
    refused(
        &d,
        &["redundancy", "cut_a", "--policy", "bogus"],
        "--policy bogus",
        policies,
    );
    refused(
        &d,
        &["redundancy", "table", "--policy", "bogus"],
        "--policy bogus",
        policies,
    );
    refused(
        &d,
        &["redundancy", "paper", "--policy", "k16"],
        "--policy k16",
        "k1 .. k15",
    );
    refused(
        &d,
        &["redundancy", "table", "--policy", "k2"],
        "applies to `drcc redundancy paper` only",
        "leave out --policy",
    );
    for what in ["table", "switchover"] {
        refused(
            &d,
            &["redundancy", what, "--vcd", "t.vcd"],
            "writes no trace",
            "give `paper` or one fault",
        );
    }
    let _ = std::fs::remove_dir_all(&d);
}

/// `--candump` and `--pcap` (`tests/traffic.rs` reads what they write): never over
/// the scenario or each other, a directory that cannot be made is named with its
/// option, commands that run many scenarios refuse them; a good run leaves both
/// files and no temporary one.
#[test]
fn traffic_exports_never_replace_an_input_and_need_a_writable_place() {
    let d = scratch("traffic");
    let input = "that is the input x.toml";
    let new_name = "give another file name";
    refused(
        &d,
        &["sim", "x.toml", "--candump", "x.toml"],
        input,
        new_name,
    );
    refused(
        &d,
        &["sim", "x.toml", "--pcap", "./x.toml"],
        "that is the input",
        new_name,
    );
    let cosim = [
        "cosim",
        "x.toml",
        "--engines",
        "model,model",
        "--candump",
        "x.toml",
    ];
    refused(&d, &cosim, input, new_name);
    let own = "each output needs a file of its own";
    let both = [
        "sim",
        "x.toml",
        "--candump",
        "t.log",
        "--pcap",
        "sub/../t.log",
    ];
    refused(&d, &both, "--candump and --pcap both name", own);
    let vcd = ["sim", "x.toml", "--vcd", "t.vcd", "--candump", "t.vcd"];
    refused(&d, &vcd, "--vcd and --candump both name", own);
    let dual = [
        "redundancy",
        "cut_a",
        "--candump",
        "t.log",
        "--pcap",
        "t.log",
    ];
    refused(&d, &dual, "--candump and --pcap both name", own);
    // x.toml is a file, so no directory x.toml/ can be made
    let writable = "give a path whose folders can be created";
    for args in [
        &["sim", "x.toml", "--candump", "x.toml/t.log"][..],
        &["redundancy", "paper", "--candump", "x.toml/t.log"],
        &["star", "no_fault", "--candump", "x.toml/t.log"],
    ] {
        refused(
            &d,
            args,
            "--candump x.toml/t.log: cannot create the directory x.toml",
            writable,
        );
    }
    refused(
        &d,
        &["sim", "x.toml", "--pcap", "x.toml/t.pcap"],
        "--pcap x.toml/t.pcap: cannot create the directory x.toml",
        writable,
    );
    let many = "runs many scenarios and exports no traffic";
    for what in ["table", "switchover"] {
        let args = ["redundancy", what, "--candump", "t.log"];
        refused(&d, &args, many, "give `paper` or one fault");
    }
    refused(
        &d,
        &["star", "table", "--pcap", "t.pcap"],
        many,
        "give one fault",
    );
    let o = drcc_in(
        &d,
        &["sim", "x.toml", "--candump", "t.log", "--pcap", "t.pcap"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let names: Vec<String> = files(&d)
        .iter()
        .map(|(p, _)| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        names,
        ["t.log", "t.pcap", "x.toml"],
        "no temporary file left"
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// `wave-diff` names the real cause: a file cut inside a line is not a VCD (exit 2);
/// one cut at a line is a valid but shorter trace, which is not equal to the whole
/// one (exit 1, naming the shorter file), even though every signal agrees over the
/// span both cover; a different timescale alone is no difference, and is said. A
/// file that does not parse is named with where it ends (inside which line).
#[test]
fn wave_diff_names_truncated_files_and_compares_across_timescales() {
    let d = scratch("wave");
    let o = drcc_in(&d, &["sim", "x.toml", "--vcd", "a.vcd"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let full = std::fs::read_to_string(d.join("a.vcd")).unwrap();
    // cut inside a line
    std::fs::write(d.join("cut.vcd"), &full[..full.len() / 2 + 3]).unwrap();
    // cut at a line, half way: before a time stamp, so that every time step
    // it keeps is whole (a cut between a time stamp and its value changes
    // would be a real difference at that time)
    let lines: Vec<&str> = full.lines().collect();
    let half = (lines.len() / 2..lines.len())
        .find(|&k| lines[k].starts_with('#'))
        .expect("a time stamp in the second half");
    std::fs::write(d.join("short.vcd"), lines[..half].join("\n") + "\n").unwrap();
    // the same trace in picoseconds
    let ps: Vec<String> = lines
        .iter()
        .map(|l| match l.strip_prefix('#') {
            Some(t) => format!("#{}", t.parse::<u64>().unwrap() * 1000),
            None => l.replace("$timescale 1 ns $end", "$timescale 1 ps $end"),
        })
        .collect();
    assert!(
        full.contains("$timescale 1 ns $end"),
        "the writer's timescale"
    );
    std::fs::write(d.join("ps.vcd"), ps.join("\n") + "\n").unwrap();

    let o = drcc_in(&d, &["wave-diff", "a.vcd", "cut.vcd"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("cut.vcd: not a valid VCD file"), "{err}");
    assert!(
        err.contains("the file ends inside line"),
        "where it was cut: {err}"
    );

    let o = drcc_in(&d, &["wave-diff", "a.vcd", "short.vcd"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("the files end at different times"), "{err}");
    assert!(err.contains("short.vcd is shorter"), "{err}");

    let o = drcc_in(&d, &["wave-diff", "ps.vcd", "a.vcd"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("timescales differ (1 ps and 1 ns)"), "{out}");
    let o = drcc_in(&d, &["wave-diff", "a.vcd", "a.vcd"]);
    assert!(!String::from_utf8_lossy(&o.stdout).contains("timescales differ"));
    let _ = std::fs::remove_dir_all(&d);
}

/// `drcc campaign`: bad options are refused before any scenario runs, and a
/// results file is never written over.
#[test]
fn campaign_refuses_bad_options_and_never_overwrites_results() {
    let d = scratch("campaign");
    std::fs::write(d.join("r.jsonl"), "earlier results\n").unwrap();
    let cases: [(&[&str], &str, &str); 9] = [
        (
            &["campaign", "--shard", "0/4"],
            "--shard 0/4",
            "1 <= i <= n",
        ),
        (
            &["campaign", "--shard", "5/4"],
            "--shard 5/4",
            "1 <= i <= n",
        ),
        (
            &["campaign", "--shard", "x"],
            "--shard x",
            "e.g. --shard 3/8",
        ),
        (&["campaign", "--count", "0"], "--count 0", "give 1 .."),
        (
            &["campaign", "--topology", "ring"],
            "--topology ring",
            "the topologies are dual",
        ),
        (
            &["campaign", "--faults", "triple"],
            "--faults triple",
            "give single",
        ),
        (&["campaign", "--jobs", "0"], "--jobs 0", "give 1 .. 256"),
        (
            &["campaign", "--out", "r.jsonl"],
            "the file exists",
            "give a new file name",
        ),
        (
            &["campaign", "merge"],
            "campaign merge",
            "give the result files",
        ),
    ];
    for (args, what, fix) in cases {
        refused(&d, args, what, fix);
    }
    refused(
        &d,
        &["campaign", "merge", "x.toml"],
        "x.toml:1: not a campaign result line",
        "drcc campaign --out",
    );
    refused(
        &d,
        &["campaign", "replay", "x.toml"],
        "not a campaign replay file",
        "written by `drcc campaign`",
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// `drcc ring`: a fault, a ring size, an engine, a position or an option that
/// cannot apply is refused before anything runs.
#[test]
fn ring_refuses_bad_faults_sizes_and_positions() {
    let d = scratch("ring");
    refused(
        &d,
        &["ring", "bogus"],
        "unknown ring fault \"bogus\"",
        "give table, no_fault, section_open",
    );
    refused(
        &d,
        &["ring", "table", "--nodes", "3,11"],
        "--nodes \"3,11\"",
        "ring sizes of 3..=10",
    );
    refused(
        &d,
        &["ring", "no_fault", "--engine", "rust-hdl"],
        "model or verilator",
        "use --engine model or verilator",
    );
    refused(
        &d,
        &["ring", "no_fault", "--markdown"],
        "--markdown rewrites the fault table",
        "use it with `drcc ring table`",
    );
    refused(
        &d,
        &["ring", "section_open", "--nodes", "3", "--position", "7"],
        "section 7",
        "sections are 0..3",
    );
    refused(
        &d,
        &["ring", "babbling_idiot", "--nodes", "3", "--position", "5"],
        "ring node 5",
        "ring nodes 0..3",
    );
    refused(
        &d,
        &["ring", "table", "--cosim", "verilator"],
        "--cosim verilator: `table` runs many scenarios",
        "give one fault to compare in lock step",
    );
    refused(
        &d,
        &["ring", "no_fault", "--cosim", "rust-hdl"],
        "model or verilator",
        "use --cosim model or verilator",
    );
    refused(
        &d,
        &["ring", "table", "--candump", "t.log"],
        "--candump t.log: `table` runs many scenarios and exports no traffic",
        "give one fault",
    );
    refused(
        &d,
        &["ring", "table", "--pcap", "t.pcap"],
        "--pcap t.pcap",
        "give one fault",
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// A trace that cannot be written is an error naming the file, not a PASS: the
/// full device (every write fails, ENOSPC) as `--vcd` exits 2 naming it, and
/// stays a device (an output is written in place there, never replaced by a
/// renamed file).
#[cfg(target_os = "linux")]
#[test]
fn a_trace_that_cannot_be_written_is_an_error_and_a_device_stays_a_device() {
    use std::os::unix::fs::FileTypeExt;
    let full = Path::new("/dev/full");
    assert!(
        std::fs::metadata(full).is_ok_and(|m| m.file_type().is_char_device()),
        "/dev/full is a character device on Linux"
    );
    let d = scratch("devfull");
    let o = drcc_in(&d, &["sim", "x.toml", "--vcd", "/dev/full"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("cannot write /dev/full"), "{err}");
    assert!(!String::from_utf8_lossy(&o.stdout).contains("PASS"));
    assert!(
        std::fs::metadata(full).is_ok_and(|m| m.file_type().is_char_device()),
        "/dev/full was replaced by a file"
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// An output that cannot be written is an error naming it (exit 2, one message
/// with the fix), and nothing is left behind: `generate --out` under a file,
/// `campaign --out` under a file, `synth --build-dir` under a file (with yosys,
/// which `synth` probes first), and a generated file on the full device.
#[test]
fn outputs_that_cannot_be_written_are_errors_naming_them() {
    let d = scratch("unwritable");
    std::fs::write(d.join("blocker"), "a file, not a folder").unwrap();
    let fix = "give a path whose folders can be created";
    refused(
        &d,
        &["generate", "--out", "blocker/rtl"],
        "cannot create the directory blocker/rtl",
        fix,
    );
    refused(
        &d,
        &["campaign", "--count", "1", "--out", "blocker/r.jsonl"],
        "cannot create the directory blocker",
        fix,
    );
    if drcc_tools::need(&drcc_tools::YOSYS) {
        // `synth` reads the checkout's rtl-out/, so it runs in the repository.
        let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
        let build = d.join("blocker/b");
        let o = drcc_in(
            repo,
            &[
                "synth",
                "--target",
                "ice40",
                "--build-dir",
                build.to_str().unwrap(),
            ],
        );
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains("blocker/b") && err.contains(fix), "{err}");
    }
    assert_eq!(
        std::fs::read_to_string(d.join("blocker")).unwrap(),
        "a file, not a folder"
    );
    let _ = std::fs::remove_dir_all(&d);
}
