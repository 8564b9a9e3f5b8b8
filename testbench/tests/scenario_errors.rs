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
    }
}
