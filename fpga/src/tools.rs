//! The external programs of the flow (yosys, nextpnr-ice40, icepack): finding
//! them on `PATH` with their Debian package named when one is missing, reading
//! their versions and which yosys families exist, and running one with its
//! output logged in the build directory.

use std::collections::BTreeMap;
use std::io::ErrorKind;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::target::Target;
use crate::Error;

/// An external program the flow runs, and the Debian package that provides it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tool {
    /// Command name on `PATH`.
    pub cmd: &'static str,
    /// Debian / Ubuntu package that installs it.
    pub package: &'static str,
    /// An argument that makes it print something and exit (to see it runs).
    pub probe: &'static str,
}

/// The synthesiser, for every family.
pub const YOSYS: Tool = Tool {
    cmd: "yosys",
    package: "yosys",
    probe: "-V",
};

/// Place and route for iCE40.
pub const NEXTPNR_ICE40: Tool = Tool {
    cmd: "nextpnr-ice40",
    package: "nextpnr-ice40",
    probe: "--version",
};

/// iCE40 bitstream packer.
pub const ICEPACK: Tool = Tool {
    cmd: "icepack",
    package: "fpga-icestorm",
    probe: "-h",
};

/// The tools the flow needs for these targets, in the order they run.
pub fn needed(targets: &[&Target]) -> Vec<Tool> {
    let mut needed = vec![YOSYS];
    if targets.iter().any(|t| t.pnr.is_some()) {
        needed.push(NEXTPNR_ICE40);
        needed.push(ICEPACK);
    }
    needed
}

/// Fails naming every missing tool and its Debian package.
pub fn check(targets: &[&Target]) -> Result<(), Error> {
    let mut missing = Vec::new();
    for tool in needed(targets) {
        match Command::new(tool.cmd)
            .arg(tool.probe)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
        {
            Ok(_) => {}
            Err(e) if e.kind() == ErrorKind::NotFound => missing.push(tool),
            Err(e) => return Err(Error(format!("cannot run {}: {e}", tool.cmd))),
        }
    }
    if missing.is_empty() {
        Ok(())
    } else {
        Err(Error(missing_message(&missing)))
    }
}

/// `yosys (Debian/Ubuntu package yosys), ... not found on PATH; install with: ...`.
pub fn missing_message(missing: &[Tool]) -> String {
    let names: Vec<String> = missing
        .iter()
        .map(|t| format!("{} (Debian/Ubuntu package {})", t.cmd, t.package))
        .collect();
    let mut packages: Vec<&str> = missing.iter().map(|t| t.package).collect();
    packages.dedup();
    format!(
        "{} not found on PATH; install with: sudo apt-get install {}",
        names.join(", "),
        packages.join(" ")
    )
}

/// Versions of the tools, and which yosys families exist.
#[derive(Debug, Clone, Default)]
pub struct ToolEnv {
    /// `0.23` from `Yosys 0.23 (git sha1 ...)`.
    pub yosys_version: String,
    /// nextpnr-ice40's version, if an iCE40 target is in the run.
    pub nextpnr_version: Option<String>,
    /// Per target name: why the family cannot be synthesised (absent: it can).
    pub unsupported: BTreeMap<&'static str, String>,
    /// Per target name: a note (e.g. the family is experimental in yosys).
    pub notes: BTreeMap<&'static str, String>,
}

impl ToolEnv {
    /// Asks the installed tools for their versions and yosys for the synthesis
    /// command and `-family` of every target.
    pub fn probe(targets: &[&Target]) -> Result<Self, Error> {
        let v = capture(YOSYS.cmd, &["-V"])?;
        let yosys_version = parse_yosys_version(&v).unwrap_or_else(|| v.trim().to_string());
        let nextpnr_version = if targets.iter().any(|t| t.pnr.is_some()) {
            let v = capture(NEXTPNR_ICE40.cmd, &["--version"])?;
            Some(parse_nextpnr_version(&v).unwrap_or_else(|| v.trim().to_string()))
        } else {
            None
        };
        let mut env = ToolEnv {
            yosys_version,
            nextpnr_version,
            ..ToolEnv::default()
        };
        let mut help_cache: BTreeMap<&str, String> = BTreeMap::new();
        for t in targets {
            let pass = t.synth_pass();
            if !help_cache.contains_key(pass) {
                help_cache.insert(pass, capture(YOSYS.cmd, &["-h", pass])?);
            }
            env.judge(t, &help_cache[pass]);
        }
        Ok(env)
    }

    /// Records whether `yosys -h <pass>` (its `help` text) supports target `t`.
    fn judge(&mut self, t: &Target, help: &str) {
        let pass = t.synth_pass();
        let version = &self.yosys_version;
        if !help.contains(&format!("{pass} [options]")) {
            self.unsupported
                .insert(t.name, format!("yosys {version} has no `{pass}` command"));
            return;
        }
        let Some(fam) = t.family_option else {
            return;
        };
        let needle = format!("- {fam}:");
        match help.lines().find(|l| l.trim_start().starts_with(&needle)) {
            None => {
                self.unsupported.insert(
                    t.name,
                    format!("yosys {version}: `{pass}` does not support `-family {fam}`"),
                );
            }
            Some(line) if line.contains("EXPERIMENTAL") => {
                self.notes.insert(
                    t.name,
                    format!("yosys {version} marks `-family {fam}` EXPERIMENTAL"),
                );
            }
            Some(_) => {}
        }
    }
}

/// stdout + stderr of a short command.
fn capture(cmd: &str, args: &[&str]) -> Result<String, Error> {
    let out = Command::new(cmd)
        .args(args)
        .stdin(Stdio::null())
        .output()
        .map_err(|e| Error(format!("cannot run {cmd}: {e}")))?;
    let mut s = String::from_utf8_lossy(&out.stdout).into_owned();
    s.push_str(&String::from_utf8_lossy(&out.stderr));
    Ok(s)
}

/// `Yosys 0.23 (git sha1 7ce5011c24b)` -> `0.23`.
pub fn parse_yosys_version(text: &str) -> Option<String> {
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("Yosys "))?;
    line.split_whitespace().nth(1).map(str::to_string)
}

/// `nextpnr-ice40 -- Next Generation Place and Route (Version 0.4-1+b1)` -> `0.4-1+b1`.
pub fn parse_nextpnr_version(text: &str) -> Option<String> {
    let at = text.find("(Version ")?;
    let rest = &text[at + "(Version ".len()..];
    let end = rest.find(')')?;
    Some(rest[..end].trim().to_string())
}

/// Runs a tool in `cwd`, its output to `log` (relative to `cwd`) unless the
/// tool wrote that log itself (then to `<log>.out`); on failure, the error names
/// the tool, the first error line of the log and the log file.
pub fn run_logged(tool: &Tool, args: &[String], cwd: &Path, log: &str) -> Result<(), Error> {
    match run_logged_within(tool, args, cwd, log, None)? {
        Ran::Finished => Ok(()),
        Ran::Stopped(_) => unreachable!("no time limit was set"),
    }
}

/// How a tool run with a time limit ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ran {
    /// It exited successfully.
    Finished,
    /// It was still running at the limit and was killed (its log is kept).
    Stopped(Duration),
}

/// [`run_logged`] with an optional time limit: a tool still running at `limit`
/// is killed and reported as [`Ran::Stopped`], not as an error (nextpnr can
/// route a congested design for hours without converging).
pub fn run_logged_within(
    tool: &Tool,
    args: &[String],
    cwd: &Path,
    log: &str,
    limit: Option<Duration>,
) -> Result<Ran, Error> {
    let log_path = cwd.join(log);
    let out_path = log_path.with_extension("out");
    let out = std::fs::File::create(&out_path)
        .map_err(|e| Error(format!("cannot write {}: {e}", out_path.display())))?;
    let err = out
        .try_clone()
        .map_err(|e| Error(format!("cannot write {}: {e}", out_path.display())))?;
    let mut child = Command::new(tool.cmd)
        .args(args)
        .current_dir(cwd)
        .stdin(Stdio::null())
        .stdout(out)
        .stderr(err)
        .spawn()
        .map_err(|e| {
            if e.kind() == ErrorKind::NotFound {
                Error(missing_message(&[*tool]))
            } else {
                Error(format!("cannot run {}: {e}", tool.cmd))
            }
        })?;
    let started = Instant::now();
    let status = loop {
        let polled = child
            .try_wait()
            .map_err(|e| Error(format!("cannot wait for {}: {e}", tool.cmd)))?;
        if let Some(status) = polled {
            break Some(status);
        }
        if limit.is_some_and(|l| started.elapsed() >= l) {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let text = std::fs::read_to_string(&out_path).unwrap_or_default();
    // The tool's own log is kept; its console output goes beside it only
    // when it has something to say, else it becomes the log.
    if !log_path.exists() || std::fs::metadata(&log_path).is_ok_and(|m| m.len() == 0) {
        std::fs::rename(&out_path, &log_path)
            .map_err(|e| Error(format!("cannot write {}: {e}", log_path.display())))?;
    } else if text.trim().is_empty() {
        let _ = std::fs::remove_file(&out_path);
    }
    let Some(status) = status else {
        return Ok(Ran::Stopped(started.elapsed()));
    };
    if status.success() {
        return Ok(Ran::Finished);
    }
    let logged = std::fs::read_to_string(&log_path).unwrap_or_default();
    let first_error = logged
        .lines()
        .chain(text.lines())
        .find(|l| l.contains("ERROR") || l.contains("Error"))
        .map(|l| l.trim().to_string())
        .unwrap_or_else(|| format!("exit status {status}"));
    Err(Error(format!(
        "{} failed: {first_error} (full log: {})",
        tool.cmd,
        log_path.display()
    )))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::target::TARGETS;

    #[test]
    fn parses_versions() {
        assert_eq!(
            parse_yosys_version("Yosys 0.23 (git sha1 7ce5011c24b)\n").as_deref(),
            Some("0.23")
        );
        assert_eq!(
            parse_nextpnr_version(
                "nextpnr-ice40 -- Next Generation Place and Route (Version 0.4-1+b1)\n"
            )
            .as_deref(),
            Some("0.4-1+b1")
        );
        assert_eq!(parse_yosys_version("command not found\n"), None);
    }

    #[test]
    fn a_tool_past_its_limit_is_stopped_and_its_output_kept() {
        let dir = std::env::temp_dir().join(format!("drcc-fpga-limit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let sh = Tool {
            cmd: "sh",
            package: "dash",
            probe: "-c true",
        };
        let script = |s: &str| vec!["-c".to_string(), s.to_string()];
        let limit = Some(Duration::from_millis(300));
        let ran = run_logged_within(&sh, &script("echo routing; sleep 30"), &dir, "t.log", limit);
        assert!(
            matches!(ran, Ok(Ran::Stopped(d)) if d < Duration::from_secs(10)),
            "{ran:?}"
        );
        let log = std::fs::read_to_string(dir.join("t.log")).unwrap();
        assert_eq!(log, "routing\n");
        // within the limit: finished; a failure names the tool and the log
        let ran = run_logged_within(&sh, &script("echo ok"), &dir, "u.log", limit);
        assert_eq!(ran.unwrap(), Ran::Finished);
        let e = run_logged(&sh, &script("echo 'ERROR: no room'; exit 3"), &dir, "v.log");
        assert!(e.unwrap_err().0.starts_with("sh failed: ERROR: no room"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn missing_tool_names_the_package() {
        let m = missing_message(&[NEXTPNR_ICE40, ICEPACK]);
        assert!(
            m.contains("icepack (Debian/Ubuntu package fpga-icestorm)"),
            "{m}"
        );
        assert!(
            m.contains("sudo apt-get install nextpnr-ice40 fpga-icestorm"),
            "{m}"
        );
    }

    #[test]
    fn place_and_route_tools_only_for_ice40() {
        let xc7 = TARGETS.iter().find(|t| t.name == "xc7").unwrap();
        let ice40 = TARGETS.iter().find(|t| t.name == "ice40").unwrap();
        assert_eq!(needed(&[xc7]), [YOSYS]);
        assert_eq!(needed(&[xc7, ice40]), [YOSYS, NEXTPNR_ICE40, ICEPACK]);
    }

    /// Excerpt of `yosys -h synth_xilinx` (yosys 0.23), with the family list.
    const SYNTH_XILINX_HELP: &str = "\
-- Running command `help synth_xilinx' --\n\
\n\
    synth_xilinx [options]\n\
\n\
This command runs synthesis for Xilinx FPGAs. This command does not operate on\n\
    -family <family>\n\
        run synthesis for the specified Xilinx architecture\n\
        generate the synthesis netlist for the specified family.\n\
        supported values:\n\
        - xcup: Ultrascale Plus\n\
        - xcu: Ultrascale\n\
        - xc7: Series 7 (default)\n\
        - xc6s: Spartan 6\n\
        - xc3se: Spartan 3E (EXPERIMENTAL)\n\
        - xc3s: Spartan 3 (EXPERIMENTAL)\n";

    #[test]
    fn judges_yosys_families_from_the_help() {
        let by = |n: &str| TARGETS.iter().find(|t| t.name == n).unwrap();
        let mut env = ToolEnv {
            yosys_version: "0.23".to_string(),
            ..ToolEnv::default()
        };
        env.judge(by("xc7"), SYNTH_XILINX_HELP);
        env.judge(by("xc3s"), SYNTH_XILINX_HELP);
        assert!(env.unsupported.is_empty(), "{:?}", env.unsupported);
        assert_eq!(
            env.notes["xc3s"],
            "yosys 0.23 marks `-family xc3s` EXPERIMENTAL"
        );
        assert!(!env.notes.contains_key("xc7"));
        env.judge(by("ice40"), "ERROR: No such command: synth_ice40\n");
        assert_eq!(
            env.unsupported["ice40"],
            "yosys 0.23 has no `synth_ice40` command"
        );
        env.judge(
            by("xc7"),
            "    synth_xilinx [options]\n        - xcup: Ultrascale Plus\n",
        );
        assert_eq!(
            env.unsupported["xc7"],
            "yosys 0.23: `synth_xilinx` does not support `-family xc7`"
        );
    }
}
