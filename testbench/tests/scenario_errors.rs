//! Bad scenario files give one clear message naming the file, the line and the
//! field (and, for bit timing, the legal range). The messages are golden
//! snapshots (insta): a change in wording shows up in review.

use drcc_testbench::Scenario;

const HEAD: &str = "name = \"bad\"\nclock_hz = 8_000_000\nnodes = [\"a\", \"b\"]\n";

fn err(body: &str) -> String {
    let text = format!("{HEAD}{body}");
    match Scenario::parse(&text, "bad.toml") {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

const FRAME: &str = "bitrate = 500_000\n[[frame]]\nnode = \"a\"\nid = 0x10\n";

#[test]
fn loader_errors() {
    let cases: Vec<(&str, String)> = vec![
        ("toml syntax", format!("{FRAME}dlc = = 3\n")),
        ("unknown field", format!("{FRAME}dcl = 3\n")),
        ("wrong type", format!("{FRAME}dlc = \"three\"\n")),
        ("dlc out of range", format!("{FRAME}dlc = 16\n")),
        ("byte out of range", format!("{FRAME}data = [1, 256]\n")),
        (
            "negative id",
            "bitrate = 500_000\n[[frame]]\nnode = \"a\"\nid = -1\n".to_string(),
        ),
        ("data vs dlc", format!("{FRAME}dlc = 3\ndata = [1, 2]\n")),
        (
            "remote with data",
            format!("{FRAME}remote = true\ndata = [1]\n"),
        ),
        (
            "base id too large",
            "bitrate = 500_000\n[[frame]]\nnode = \"a\"\nid = 0x800\n".to_string(),
        ),
        (
            "extended id too large",
            "bitrate = 500_000\n[[frame]]\nnode = 1\nid = 0x2000_0000\nextended = true\n"
                .to_string(),
        ),
        (
            "unknown node",
            "bitrate = 500_000\n[[frame]]\nnode = \"c\"\nid = 1\n".to_string(),
        ),
        (
            "node index",
            "bitrate = 500_000\n[[frame]]\nnode = 2\nid = 1\n".to_string(),
        ),
        (
            "two due times",
            format!("{FRAME}at_bit = 1\nat_cycle = 5\n"),
        ),
        (
            "no bit rate",
            "[[frame]]\nnode = \"a\"\nid = 1\n".to_string(),
        ),
        ("impossible bit rate", "bitrate = 300_000\n".to_string()),
        (
            "both rate and timing",
            "bitrate = 500_000\n[timing]\nbrp = 0\ntseg1 = 5\ntseg2 = 2\n".to_string(),
        ),
        (
            "tseg1 range",
            "[timing]\nbrp = 0\ntseg1 = 17\ntseg2 = 2\n".to_string(),
        ),
        (
            "tseg2 range",
            "[timing]\nbrp = 0\ntseg1 = 12\ntseg2 = 9\n".to_string(),
        ),
        (
            "sjw > tseg2",
            "[timing]\nbrp = 0\ntseg1 = 5\ntseg2 = 2\nsjw = 3\n".to_string(),
        ),
        (
            "too few tq",
            "[timing]\nbrp = 0\ntseg1 = 4\ntseg2 = 2\n".to_string(),
        ),
        (
            "brp range",
            "[timing]\nbrp = 64000\ntseg1 = 5\ntseg2 = 2\n".to_string(),
        ),
        (
            "tseg1 too short",
            "[timing]\nbrp = 0\ntseg1 = 2\ntseg2 = 6\nsjw = 1\n".to_string(),
        ),
        (
            "tseg1 too short at brp 1",
            "[timing]\nbrp = 1\ntseg1 = 1\ntseg2 = 8\nsjw = 1\n".to_string(),
        ),
        ("unknown mode", format!("mode = \"silent\"\n{FRAME}")),
        ("mode type", format!("mode = 1\n{FRAME}")),
        ("ewl range", format!("ewl = 256\n{FRAME}")),
        ("negative ewl", format!("ewl = -1\n{FRAME}")),
        ("single_shot type", format!("single_shot = 1\n{FRAME}")),
        (
            "node_config mode",
            format!("{FRAME}[[node_config]]\nnode = \"b\"\nmode = \"loop_back\"\n"),
        ),
        (
            "node_config ewl",
            format!("{FRAME}[[node_config]]\nnode = 0\newl = 1000\n"),
        ),
        (
            "node_config unknown node",
            format!("{FRAME}[[node_config]]\nnode = \"c\"\nsingle_shot = true\n"),
        ),
        (
            "node_config twice",
            format!(
                "{FRAME}[[node_config]]\nnode = \"b\"\newl = 10\n\
                 [[node_config]]\nnode = 1\nmode = \"self_test\"\n"
            ),
        ),
        (
            "node_config unknown key",
            format!("{FRAME}[[node_config]]\nnode = \"b\"\nsilent = true\n"),
        ),
        (
            "abort unknown node",
            format!("{FRAME}[[abort]]\nnode = 5\nat_bit = 30\n"),
        ),
        (
            "abort two due times",
            format!("{FRAME}[[abort]]\nnode = \"a\"\nat_bit = 30\nat_cycle = 9\n"),
        ),
        (
            "expect fails bad frame",
            format!("{FRAME}[[expect]]\nnode = \"a\"\nfails = [3]\n"),
        ),
        (
            "expect bad frame",
            format!("{FRAME}[[expect]]\nnode = \"b\"\nreceives = [0, 1]\n"),
        ),
        (
            "fault kind",
            format!("{FRAME}[[fault]]\nkind = \"melt\"\nat_bit = 3\n"),
        ),
        (
            "fault node missing",
            format!("{FRAME}[[fault]]\nkind = \"flip\"\ntarget = \"rx\"\n"),
        ),
        ("two limits", format!("max_ms = 3\nmax_bits = 4\n{FRAME}")),
    ];
    let mut out = String::new();
    for (what, body) in &cases {
        out.push_str(&format!("{what}:\n  {}\n", err(body)));
    }
    insta::assert_snapshot!("loader_errors", out);
}

#[test]
fn errors_name_file_line_and_field() {
    let e = Scenario::parse(&format!("{HEAD}{FRAME}dlc = 16\n"), "x.toml").unwrap_err();
    assert_eq!(e.file, "x.toml");
    assert_eq!(e.line, Some(8));
    assert_eq!(e.field.as_deref(), Some("frame[0].dlc"));
    let e = Scenario::parse(
        &format!("{HEAD}[timing]\nbrp = 0\ntseg1 = 17\ntseg2 = 2\n"),
        "y.toml",
    )
    .unwrap_err();
    assert_eq!(e.line, Some(6));
    assert_eq!(e.field.as_deref(), Some("timing.tseg1"));
    assert!(e.message.contains("1..=16"), "{}", e.message);
    // Type errors found by the TOML parser also name line and field.
    let e = Scenario::parse(&format!("{HEAD}{FRAME}dlc = \"x\"\n"), "z.toml").unwrap_err();
    assert_eq!(e.line, Some(8));
    assert_eq!(e.field.as_deref(), Some("frame[0].dlc"));
    // Configuration errors too.
    let e = Scenario::parse(
        &format!("{HEAD}{FRAME}[[node_config]]\nnode = \"b\"\nmode = \"x\"\n"),
        "w.toml",
    )
    .unwrap_err();
    assert_eq!(e.line, Some(10));
    assert_eq!(e.field.as_deref(), Some("node_config[0].mode"));
    let e = Scenario::parse(
        &format!("{HEAD}[timing]\nbrp = 0\ntseg1 = 2\ntseg2 = 6\nsjw = 1\n"),
        "v.toml",
    )
    .unwrap_err();
    assert_eq!(e.line, Some(6));
    assert_eq!(e.field.as_deref(), Some("timing.tseg1"));
    assert!(e.message.contains("minimum"), "{}", e.message);
    // A missing file is an error, not a panic.
    assert!(Scenario::load(std::path::Path::new("/nonexistent/s.toml")).is_err());
}

#[test]
fn round_trip_through_toml() {
    let sc = drcc_testbench::random::Traffic::new(9, 30, 24_000_000, 500_000)
        .scenario()
        .unwrap();
    let back = Scenario::parse(&sc.to_toml(), "generated.toml").unwrap();
    assert_eq!(back.frames, sc.frames);
    assert_eq!(back.timing, sc.timing);
    assert_eq!(back.max_cycles, sc.max_cycles);
    assert_eq!(back.nodes, sc.nodes);
    for file in ["faults.toml", "slow_triple.toml", "demo.toml"] {
        let sc = Scenario::load(&drcc_testbench::scenarios_dir().join(file)).unwrap();
        let back = Scenario::parse(&sc.to_toml(), file).unwrap();
        assert_eq!(
            (&back.frames, &back.faults, &back.expect, back.timing),
            (&sc.frames, &sc.faults, &sc.expect, sc.timing),
            "{file}"
        );
        assert_eq!(back.configs, sc.configs, "{file}");
    }
}

#[test]
fn controller_configuration_keys() {
    use drcc_cosim::{ControllerConfig, Mode};
    // Default: every node normal, EWL 96, automatic retransmission.
    let sc = Scenario::parse(&format!("{HEAD}{FRAME}"), "d.toml").unwrap();
    assert_eq!(sc.configs, vec![ControllerConfig::default(); 2]);
    // Scenario keys apply to every node; [[node_config]] overrides per node.
    let text = format!(
        "{HEAD}mode = \"self_test\"\newl = 120\nsingle_shot = true\n{FRAME}\
         [[node_config]]\nnode = \"b\"\nmode = \"listen_only\"\n\
         [[expect]]\nnode = \"a\"\nsends = []\nfails = [0]\n"
    );
    let sc = Scenario::parse(&text, "c.toml").unwrap();
    assert!(sc.aborts.is_empty());
    let a = ControllerConfig {
        mode: Mode::SelfTest,
        ewl: 120,
        single_shot: true,
    };
    let b = ControllerConfig {
        mode: Mode::ListenOnly,
        ..a
    };
    assert_eq!(sc.configs, vec![a, b]);
    let back = Scenario::parse(&sc.to_toml(), "c2.toml").unwrap();
    assert_eq!((&back.configs, &back.expect), (&sc.configs, &sc.expect));
    // Aborts: at_bit or at_cycle, round trip as at_cycle.
    let text = format!(
        "{HEAD}{FRAME}[[abort]]\nnode = \"b\"\nat_bit = 3\n[[abort]]\nnode = 0\nat_cycle = 7\n"
    );
    let sc = Scenario::parse(&text, "a.toml").unwrap();
    let cpb = sc.clocks_per_bit();
    assert_eq!(
        sc.aborts,
        vec![
            drcc_testbench::scenario::ScheduledAbort {
                node: 1,
                at_cycle: 3 * cpb
            },
            drcc_testbench::scenario::ScheduledAbort {
                node: 0,
                at_cycle: 7
            },
        ]
    );
    let back = Scenario::parse(&sc.to_toml(), "a2.toml").unwrap();
    assert_eq!(back.aborts, sc.aborts);
    // Every mode name.
    for (name, mode) in [
        ("normal", Mode::Normal),
        ("listen_only", Mode::ListenOnly),
        ("self_test", Mode::SelfTest),
        ("loopback", Mode::Loopback),
    ] {
        let text = format!("{HEAD}mode = \"{name}\"\nbitrate = 500_000\n");
        let sc = Scenario::parse(&text, "m.toml").unwrap();
        assert!(sc.configs.iter().all(|c| c.mode == mode), "{name}");
        let back = Scenario::parse(&sc.to_toml(), "m2.toml").unwrap();
        assert_eq!(back.configs, sc.configs, "{name}");
    }
    // Same configuration on every node: written as scenario keys.
    let sc = Scenario::parse(&format!("{HEAD}ewl = 7\n{FRAME}"), "e.toml").unwrap();
    assert!(sc.to_toml().contains("\newl = 7\n"));
    assert!(!sc.to_toml().contains("node_config"));
}

/// What cannot finish, or would be silently ignored, is refused with the
/// limit or the fix named (no run for days, no PASS with a fault never applied).
#[test]
fn refused_before_the_run_with_the_limit_named() {
    let contains = |body: &str, line: &str, parts: &[&str]| {
        let e = err(body);
        assert!(e.starts_with(&format!("bad.toml:{line}")), "{e}");
        for p in parts {
            assert!(e.contains(p), "{p:?} in: {e}");
        }
        assert_eq!(e.lines().count(), 1, "{e}");
    };
    // a due time no run reaches (issue: at_bit = 1e12, at_cycle = i64::MAX)
    contains(
        &format!("{FRAME}at_bit = 1_000_000_000_000\n"),
        "8: frame[0].at_bit",
        &[
            "beyond the longest run",
            "1000000000 cycles",
            "give an earlier time",
        ],
    );
    contains(
        &format!("{FRAME}at_cycle = 9223372036854775807\n"),
        "8: frame[0].at_cycle",
        &["beyond the longest run"],
    );
    // a run limit beyond the longest run
    contains(
        &format!("max_bits = 1_000_000_000\n{FRAME}"),
        "4: max_bits",
        &[
            "would last 16000000000 clock cycles",
            "give a shorter limit",
        ],
    );
    // a fault or an abort after the run's end would never be applied
    contains(
        &format!("max_bits = 1000\n{FRAME}[[fault]]\nkind = \"flip\"\nat_bit = 2000\n"),
        "11: fault[0]",
        &[
            "after the run's end (cycle 16000)",
            "never happen",
            "max_cycles / max_bits / max_ms",
        ],
    );
    contains(
        &format!("max_cycles = 500\n{FRAME}[[abort]]\nnode = \"a\"\nat_cycle = 500\n"),
        "11: abort[0]",
        &["after the run's end (cycle 500)"],
    );
    // a frame expected twice is refused, not reported as "not received"
    contains(
        &format!("{FRAME}[[expect]]\nnode = \"b\"\nreceives = [0, 0]\n"),
        "10: expect[0].receives",
        &["frame 0 is listed twice", "list it once"],
    );
}

#[test]
fn names_clocks_and_keys_are_checked_and_messages_stay_short() {
    let text = |head: &str, body: &str| format!("name = \"bad\"\n{head}{body}");
    let parse = |t: &str| Scenario::parse(t, "bad.toml").unwrap_err().to_string();
    // a control character in a node name would reach the terminal raw
    let e = parse(&text(
        "clock_hz = 8_000_000\nnodes = [\"a\", \"b\\u001b[2J\"]\n",
        "bitrate = 500_000\n",
    ));
    assert!(
        e.contains("bad.toml:3: nodes:") && e.contains("without spaces or control characters"),
        "{e}"
    );
    assert!(!e.contains('\u{1b}'), "{e:?}");
    // a clock far above any FPGA's (a trace could not keep its edges apart)
    let e = parse(&text(
        "clock_hz = 2_000_000_000_000\nnodes = 2\n",
        "bitrate = 500_000\n",
    ));
    assert!(
        e.contains("bad.toml:2: clock_hz:") && e.contains("give at most 1000000000 (1 GHz)"),
        "{e}"
    );
    // a missing required key is named where it is missing, not at line 1
    let e = parse(&text("nodes = 2\n", "bitrate = 500_000\n"));
    assert!(
        e.starts_with("bad.toml: clock_hz: missing: `clock_hz` is required at the top level"),
        "{e}"
    );
    let e = parse(&text(
        "clock_hz = 8_000_000\nnodes = 2\n",
        "bitrate = 500_000\n[[frame]]\nnode = 0\n",
    ));
    assert!(
        e.starts_with("bad.toml:5: frame[0].id: missing: `id` is required in frame[0]"),
        "{e}"
    );
    // a pathological key does not make a 200 KB message
    let key = "k".repeat(200_000);
    let e = parse(&text(
        "clock_hz = 8_000_000\nnodes = 2\n",
        &format!("{key} = 1\n"),
    ));
    assert!(e.len() < 1200, "{} characters", e.len());
    assert!(e.contains("more characters)"), "{}", &e[..200]);
}

#[test]
fn an_endless_or_huge_file_is_not_read_to_the_end() {
    let dir = std::env::temp_dir().join(format!("drcc-scenario-big-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let big = dir.join("big.toml");
    std::fs::write(&big, "# x\n".repeat(300_000)).unwrap();
    let e = Scenario::load(&big).unwrap_err().to_string();
    assert!(
        e.contains("larger than 1048576 bytes") && e.contains("a scenario is a small TOML file"),
        "{e}"
    );
    let e = Scenario::load(std::path::Path::new("/dev/zero"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("larger than 1048576 bytes"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}
