//! Traffic export (`--candump FILE`, `--pcap FILE`) read back by the tools users
//! read it with: python-can's own `can.LogReader` and tshark. For a bus of channels
//! (the demo scenario), a dual bus (`redundancy a_bus_off`), a replicated star
//! (`star uplink_stuck_dominant`) and a REDCAN ring (`ring section_short`), both
//! files must hold exactly the frames the run delivered, in order, with
//! identifier, format, data, time and interface; the expected list is the run's
//! own delivery record (`RunResult::deliveries`, the hosts' `received` frames,
//! `RingReport::received`) of the same scenario run through the library, and the
//! expected times and interface names follow from the documented rules
//! (`floor(cycle / clock)`, `nodeN`, `nodeNa` / `nodeNb`), not from the writers.
//! Missing python-can or tshark skips that half locally and fails in CI (the ring's
//! log is also read line by line here, without them).

use std::path::{Path, PathBuf};
use std::process::Command;

use drcc_cosim::host::HostRx;
use drcc_cosim::Frame;
use drcc_testbench::dual::{run_dual_observed, DualFault, DualScenario};
use drcc_testbench::ring::{RingFault, RingScenario};
use drcc_testbench::star::{run_star_observed, StarFault, StarScenario};
use drcc_testbench::tools::{python_with_can, tshark};
use drcc_testbench::{EngineKind, Scenario};

/// One delivery as the run recorded it.
#[derive(Clone, Debug)]
struct Delivery {
    cycle: u64,
    iface: String,
    frame: Frame,
}

/// A scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("drcc-traffic-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs the drcc binary with `args` in `dir`; it must succeed.
fn drcc(dir: &Path, args: &[&str]) {
    let o = Command::new(env!("CARGO_BIN_EXE_drcc"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("cannot run the drcc binary");
    assert!(
        o.status.success(),
        "drcc {args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// The frames the hosts popped, collected clock by clock in node order.
fn host_deliveries<'a>(
    seen: &mut Vec<usize>,
    clock: impl Iterator<Item = &'a [HostRx]>,
    out: &mut Vec<Delivery>,
) {
    for (node, received) in clock.enumerate() {
        if seen.len() <= node {
            seen.resize(node + 1, 0);
        }
        for rx in &received[seen[node]..] {
            let line = if rx.channel == 0 { 'a' } else { 'b' };
            out.push(Delivery {
                cycle: rx.cycle,
                iface: format!("node{node}{line}"),
                frame: rx.frame,
            });
        }
        seen[node] = received.len();
    }
}

/// Reads the log with python-can; one JSON object per message, and whether the log
/// line carries the error flag (python-can reads only bus errors as error frames).
const READ_LOG: &str = r#"
import json, sys, can
path = sys.argv[1]
lines = [l for l in open(path) if l.strip()]
msgs = list(can.LogReader(path))
assert len(msgs) == len(lines), (len(msgs), len(lines))
for line, m in zip(lines, msgs):
    raw_id = int(line.split()[2].split('#')[0], 16)
    print(json.dumps({"err_flag": bool(raw_id & 0x20000000), "error": m.is_error_frame,
        "bus_error": bool(raw_id & 0x80),
        "t": m.timestamp, "channel": m.channel, "id": m.arbitration_id,
        "ext": m.is_extended_id, "rtr": m.is_remote_frame, "dlc": m.dlc,
        "data": bytes(m.data).hex()}))
"#;

/// Checks the candump log with python-can: its non-error messages are `want`.
/// Returns the error flags of every message (for the pcap check).
fn check_log(log: &Path, clock_hz: u64, want: &[Delivery]) -> Option<Vec<bool>> {
    let py = python_with_can()?;
    let o = Command::new(py)
        .args(["-c", READ_LOG])
        .arg(log)
        .output()
        .expect("python runs");
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let msgs: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let flags: Vec<bool> = msgs.iter().map(|m| m["err_flag"] == true).collect();
    let frames: Vec<&serde_json::Value> = msgs.iter().filter(|m| m["err_flag"] == false).collect();
    assert_eq!(
        frames.len(),
        want.len(),
        "{log:?}: one message per delivery"
    );
    for (k, (m, d)) in frames.iter().zip(want).enumerate() {
        let f = &d.frame;
        let usec = (d.cycle as u128 * 1_000_000 / clock_hz as u128) as f64;
        let t = m["t"].as_f64().unwrap() * 1e6;
        assert!(
            (t - usec).abs() < 0.01,
            "{k}: time {t} us, want {usec} ({d:?})"
        );
        assert_eq!(m["channel"], d.iface.as_str(), "{k}: {d:?}");
        assert_eq!(m["id"], f.id, "{k}: {d:?}");
        assert_eq!(m["ext"], f.ide, "{k}: {d:?}");
        assert_eq!(m["rtr"], f.rtr, "{k}: {d:?}");
        let dlc = if f.rtr {
            f.dlc.min(8)
        } else {
            f.data_len() as u8
        };
        assert_eq!(m["dlc"], dlc, "{k}: {d:?}");
        let data: String = f.data[..f.data_len()]
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect();
        assert_eq!(m["data"], data.as_str(), "{k}: {d:?}");
        assert_eq!(m["error"], false, "{k}");
    }
    // a bus error (CAN_ERR_BUSERROR, 0x80) is an error frame to python-can
    for m in &msgs {
        let bus_error = m["err_flag"] == true && m["bus_error"] == true;
        assert_eq!(m["error"], bus_error, "{m}");
    }
    Some(flags)
}

/// One pcap record as tshark decodes it.
#[derive(Debug)]
struct Record {
    ns: u128,
    id: u32,
    ext: bool,
    rtr: bool,
    err: bool,
    busoff: bool,
    restarted: bool,
    len: u8,
    data: String,
}

/// Reads the pcap with tshark.
fn tshark_records(pcap: &Path) -> Option<Vec<Record>> {
    let t = tshark()?;
    let fields = [
        "frame.time_epoch",
        "can.id",
        "can.flags.xtd",
        "can.flags.rtr",
        "can.flags.err",
        "can.err.busoff",
        "can.err.restarted",
        "can.len",
        "data.data",
    ];
    let mut cmd = Command::new(t);
    // The payload goes to `data` only: tshark's heuristic CAN payload dissectors
    // would take some frames (AUTOSAR NM takes identifier 0, the King's letters on
    // a ring) and leave `data.data` empty.
    for p in ["autosar-nm", "signal_pdu", "ipdum", "obd-ii"] {
        cmd.args(["--disable-protocol", p]);
    }
    cmd.arg("-r")
        .arg(pcap)
        .args(["-T", "fields", "-E", "separator=/t"]);
    for f in fields {
        cmd.args(["-e", f]);
    }
    let o = cmd.output().expect("tshark runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let flag = |s: &str| s == "1" || s == "True";
    let records = String::from_utf8_lossy(&o.stdout)
        .lines()
        .map(|l| {
            let c: Vec<&str> = l.split('\t').collect();
            let (sec, frac) = c[0].split_once('.').unwrap();
            let err = flag(c[4]);
            Record {
                ns: sec.parse::<u128>().unwrap() * 1_000_000_000
                    + format!("{frac:0<9}")[..9].parse::<u128>().unwrap(),
                // tshark decodes an error frame's identifier as error classes
                id: if err { 0 } else { c[1].parse().unwrap() },
                ext: flag(c[2]),
                rtr: flag(c[3]),
                err,
                busoff: flag(c[5]),
                restarted: flag(c[6]),
                len: c[7].parse().unwrap(),
                data: c.get(8).unwrap_or(&"").to_string(),
            }
        })
        .collect();
    Some(records)
}

/// Checks the pcap with tshark: its non-error records are `want`; the error records
/// sit where the log has its error lines (`log_flags`, when python-can ran).
fn check_pcap(
    pcap: &Path,
    clock_hz: u64,
    want: &[Delivery],
    log_flags: Option<&[bool]>,
) -> Option<Vec<Record>> {
    let records = tshark_records(pcap)?;
    if let Some(flags) = log_flags {
        let errs: Vec<bool> = records.iter().map(|r| r.err).collect();
        assert_eq!(errs, flags, "record n is line n of the candump log");
    }
    let frames: Vec<&Record> = records.iter().filter(|r| !r.err).collect();
    assert_eq!(
        frames.len(),
        want.len(),
        "{pcap:?}: one record per delivery"
    );
    for (k, (r, d)) in frames.iter().zip(want).enumerate() {
        let f = &d.frame;
        let ns = d.cycle as u128 * 1_000_000_000 / clock_hz as u128;
        assert_eq!(r.ns, ns, "{k}: {d:?}");
        assert_eq!((r.id, r.ext, r.rtr), (f.id, f.ide, f.rtr), "{k}: {d:?}");
        let len = if f.rtr {
            f.dlc.min(8)
        } else {
            f.data_len() as u8
        };
        assert_eq!(r.len, len, "{k}: {d:?}");
        if !f.rtr {
            let data: String = f.data[..f.data_len()]
                .iter()
                .map(|b| format!("{b:02x}"))
                .collect();
            assert_eq!(r.data, data, "{k}: {d:?}");
        }
    }
    Some(records)
}

#[test]
fn a_bus_of_channels_exports_every_delivery() {
    let demo = Path::new(env!("CARGO_MANIFEST_DIR")).join("testbench/scenarios/demo.toml");
    let sc = Scenario::load(&demo).unwrap();
    let run = drcc_testbench::run::run(&sc, EngineKind::Model).unwrap();
    let want: Vec<Delivery> = run
        .deliveries
        .iter()
        .map(|e| Delivery {
            cycle: e.cycle,
            iface: format!("node{}", e.node),
            frame: e.frame,
        })
        .collect();
    assert!(want.iter().any(|d| d.frame.ide) && want.iter().any(|d| d.frame.rtr));
    let d = scratch("demo");
    let demo = demo.to_str().unwrap();
    drcc(&d, &["sim", demo, "--candump", "t.log", "--pcap", "t.pcap"]);
    let flags = check_log(&d.join("t.log"), sc.clock_hz, &want);
    if let Some(f) = &flags {
        assert!(f.iter().all(|e| !e), "the demo has no errors");
    }
    check_pcap(&d.join("t.pcap"), sc.clock_hz, &want, flags.as_deref());
    let _ = std::fs::remove_dir_all(&d);
}

/// Node 0's channel A transmitter stuck dominant: besides the deliveries, node 0's
/// line A goes bus-off once and restarts once, and the other nodes see bus errors.
#[test]
fn a_dual_bus_exports_host_deliveries_and_error_frames() {
    let s = DualScenario::standard(DualFault::ABusOff);
    let (mut seen, mut want) = (Vec::new(), Vec::new());
    let mut record = |sys: &drcc_cosim::dual::DualBusSystem| {
        let clock = sys.nodes().iter().map(|n| n.host.received.as_slice());
        host_deliveries(&mut seen, clock, &mut want);
        Ok(())
    };
    run_dual_observed(&s, EngineKind::Model, None, None, &mut record).unwrap();
    let d = scratch("dual");
    drcc(
        &d,
        &[
            "redundancy",
            "a_bus_off",
            "--candump",
            "r.log",
            "--pcap",
            "r.pcap",
        ],
    );
    let hz = drcc_testbench::dual::CLOCK_HZ;
    let flags = check_log(&d.join("r.log"), hz, &want);
    let Some(records) = check_pcap(&d.join("r.pcap"), hz, &want, flags.as_deref()) else {
        return;
    };
    let log = std::fs::read_to_string(d.join("r.log")).unwrap();
    let lines: Vec<&str> = log.lines().collect();
    let at = |pick: fn(&Record) -> bool| -> Vec<&str> {
        records
            .iter()
            .zip(&lines)
            .filter(|(r, _)| pick(r))
            .map(|(_, l)| l.split(' ').nth(1).unwrap())
            .collect()
    };
    assert_eq!(
        at(|r| r.busoff),
        ["node0a"],
        "node 0's line A went bus-off once"
    );
    assert_eq!(at(|r| r.restarted), ["node0a"], "and restarted once");
    assert!(
        at(|r| r.err).contains(&"node1a"),
        "the others saw the errors"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_star_exports_host_deliveries_on_both_lines() {
    let s = StarScenario::standard(StarFault::UplinkStuckDominant);
    let (mut seen, mut want) = (Vec::new(), Vec::new());
    let mut record = |sys: &drcc_cosim::star::StarSystem| {
        let clock = sys.nodes().iter().map(|n| n.host.received.as_slice());
        host_deliveries(&mut seen, clock, &mut want);
        Ok(())
    };
    run_star_observed(&s, EngineKind::Model, None, &mut record).unwrap();
    for line in ['a', 'b'] {
        assert!(
            want.iter().any(|d| d.iface.ends_with(line)),
            "deliveries on {line}"
        );
    }
    let d = scratch("star");
    let args = [
        "star",
        "uplink_stuck_dominant",
        "--candump",
        "s.log",
        "--pcap",
        "s.pcap",
    ];
    drcc(&d, &args);
    let hz = drcc_testbench::star::CLOCK_HZ;
    let flags = check_log(&d.join("s.log"), hz, &want);
    check_pcap(&d.join("s.pcap"), hz, &want, flags.as_deref());
    let _ = std::fs::remove_dir_all(&d);
}

/// The `(seconds.microseconds) IFACE ID#DATA` lines of a candump log that are not
/// error frames (an 8-digit identifier with the error flag 0x20000000), as text.
fn log_frame_lines(log: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(log).unwrap();
    text.lines()
        .filter(|l| {
            let id = l.split(' ').nth(2).unwrap().split('#').next().unwrap();
            id.len() != 8 || u32::from_str_radix(id, 16).unwrap() & 0x2000_0000 == 0
        })
        .map(str::to_string)
        .collect()
}

/// A delivery as the log's documented form writes it, at 1 MHz.
fn ring_line(d: &Delivery) -> String {
    let f = &d.frame;
    let id = match f.ide {
        true => format!("{:08X}", f.id),
        false => format!("{:03X}", f.id),
    };
    let data: String = match f.rtr {
        true => format!(
            "R{}",
            if f.dlc > 0 {
                f.dlc.min(8).to_string()
            } else {
                "".into()
            }
        ),
        false => f.data[..f.data_len()]
            .iter()
            .map(|b| format!("{b:02X}"))
            .collect(),
    };
    let (sec, us) = (d.cycle / 1_000_000, d.cycle % 1_000_000);
    format!("({sec}.{us:06}) {} {id}#{data}", d.iface)
}

/// A 3-node REDCAN ring (a plain node per section) running the distributed
/// algorithm, section 1 shorted: the frames every host popped (the report's
/// `received`, ring and plain nodes) on interface `nodeN` (channel A, a node's only
/// line on the ring), in the order of their clocks, node by node within a clock;
/// the short's error frames besides.
#[test]
fn a_ring_exports_host_deliveries_on_one_line() {
    let s = RingScenario::distributed(3, RingFault::SectionShort { section: 1 });
    let r = drcc_testbench::ring::run(&s, EngineKind::Model).unwrap();
    let mut popped: Vec<(usize, Delivery)> = r
        .received
        .iter()
        .enumerate()
        .flat_map(|(node, rx)| {
            rx.iter().map(move |&(cycle, frame)| {
                let iface = format!("node{node}");
                (
                    node,
                    Delivery {
                        cycle,
                        iface,
                        frame,
                    },
                )
            })
        })
        .collect();
    popped.sort_by_key(|(node, d)| (d.cycle, *node));
    let want: Vec<Delivery> = popped.into_iter().map(|(_, d)| d).collect();
    assert!(
        want.len() > 100,
        "the kingdom's letters and the applications' frames"
    );
    let d = scratch("ring");
    let args = [
        "ring",
        "section_short",
        "--nodes",
        "3",
        "--position",
        "1",
        "--algorithm",
        "distributed",
        "--candump",
        "g.log",
        "--pcap",
        "g.pcap",
    ];
    drcc(&d, &args);
    let lines = log_frame_lines(&d.join("g.log"));
    let expected: Vec<String> = want.iter().map(ring_line).collect();
    assert_eq!(lines.len(), expected.len(), "one line per host pop");
    for (k, (got, exp)) in lines.iter().zip(&expected).enumerate() {
        assert_eq!(got, exp, "line {k} of the frames");
    }
    let hz = drcc_testbench::ring::CLOCK_HZ;
    let flags = check_log(&d.join("g.log"), hz, &want);
    let Some(records) = check_pcap(&d.join("g.pcap"), hz, &want, flags.as_deref()) else {
        return;
    };
    let log = std::fs::read_to_string(d.join("g.log")).unwrap();
    let ifaces: Vec<&str> = log.lines().map(|l| l.split(' ').nth(1).unwrap()).collect();
    let onset_ns = s.onset_us as u128 * 1_000;
    let short: Vec<&str> = (records.iter().zip(&ifaces))
        .filter(|(r, _)| r.err && r.ns >= onset_ns)
        .map(|(_, i)| *i)
        .collect();
    assert!(short.len() > 10, "the short's error frames: {short:?}");
    assert!(
        ifaces.iter().all(|i| i
            .strip_prefix("node")
            .is_some_and(|n| n.parse::<usize>().is_ok())),
        "every interface is nodeN"
    );
    let _ = std::fs::remove_dir_all(&d);
}
