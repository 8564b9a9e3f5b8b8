//! Verilating and compiling the models: the options, the stale models built two
//! at a time, the Verilator runtime archive, and the cache they are kept in
//! (`<target>/drcc-verilated/`, keyed by Verilator, options and RTL text).

use super::{Missing, TopTable, UNAVAILABLE_MSG};
use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// Verilator options. Why each one:
/// - `--cc --build`: C++ model, compiled by Verilator's own makefile into `V<top>__ALL.a`.
/// - `-O3 --x-assign fast --x-initial fast --noassert`: fastest model; X values
///   become constants (the RTL resets every register it relies on).
/// - `--trace`: VCD support compiled in (costs nothing while no trace is open).
/// - `-Wno-fatal`: the RTL is linted separately; warnings must not stop the build.
/// - `--no-timing`: no delay scheduling (synthesizable RTL); also spares the
///   C++20 coroutine runtime.
/// - `-CFLAGS -fPIC`: the archives end up in Rust binaries that may be PIE.
pub(crate) const VERILATOR_FLAGS: &[&str] = &[
    "--cc",
    "--build",
    "-O3",
    "--x-assign",
    "fast",
    "--x-initial",
    "fast",
    "--noassert",
    "--trace",
    "-Wno-fatal",
    "--no-timing",
    "-CFLAGS",
    "-fPIC",
];

/// Variables passed to Verilator's make. `OPT_FAST=-O3` for the evaluation code
/// (Verilator's default `-Os` is slower to run; over `-O2`, `-O3` inlines the
/// runtime's wide-word helpers such as `_vl_insert_WW` with their constant
/// arguments, which the DRCC's 100- and 128-bit vectors spent a fifth of their
/// time in, and is as fast on the channel), `-O1` for the construction and
/// trace-declaration code, `-O2` for the runtime library, and
/// `VM_PARALLEL_BUILDS=1` so the generated files compile in parallel with `-j`.
pub(crate) const MAKE_VARS: &[&str] = &[
    "OPT_FAST=-O3",
    "OPT_SLOW=-O1",
    "OPT_GLOBAL=-O2",
    "VM_PARALLEL_BUILDS=1",
];

/// Verilates and compiles the stale models, largest RTL first, on two workers
/// (each runs its own `make -j`): Verilator's front end and each model's last
/// file compile on one core, so two models at a time keep both busy. Each model
/// gets its stamp and build time when it is done.
pub(crate) fn build_stale(
    verilator: &Path,
    cache: &Path,
    mut stale: Vec<(u64, &TopTable, PathBuf, PathBuf, Vec<u8>)>,
    jobs: usize,
) -> Result<(), Missing> {
    stale.sort_by_key(|s| std::cmp::Reverse(s.0));
    let queue = std::sync::Mutex::new(stale.into_iter());
    let worker = || -> Result<(), Missing> {
        loop {
            let next = queue.lock().expect("queue").next();
            let Some((_, top, file, mdir, key)) = next else {
                return Ok(());
            };
            let started = Instant::now();
            let stamp = mdir.join("drcc-stamp");
            let _ = fs::remove_file(&stamp);
            verilate(verilator, top, &file, &mdir, jobs)?;
            fs::write(&stamp, &key).ok();
            fs::write(
                mdir.join("drcc-build-seconds.txt"),
                format!("{:.1}\n", started.elapsed().as_secs_f64()),
            )
            .ok();
            prune(cache, &format!("V{}-", top.name), &mdir);
        }
    };
    std::thread::scope(|s| {
        let other = s.spawn(worker);
        let mine = worker();
        let theirs = other.join().expect("a Verilator worker panicked");
        mine.and(theirs)
    })
}

/// Runs `cmd` and returns its stdout, or a `Missing::Failed` that names `what`.
pub(crate) fn run(cmd: &mut Command, what: &str) -> Result<String, Missing> {
    // An outer make's flags (jobserver, -n, ...) must not leak into Verilator's make.
    for var in ["MAKEFLAGS", "MFLAGS", "MAKELEVEL"] {
        cmd.env_remove(var);
    }
    let out = cmd.output().map_err(|e| Missing::Failed {
        msg: format!("{what}: cannot run {:?}", cmd.get_program()),
        detail: e.to_string(),
    })?;
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    if !out.status.success() {
        let stderr = String::from_utf8_lossy(&out.stderr);
        return Err(Missing::Failed {
            msg: format!("{what} failed ({})", out.status),
            detail: format!("{stdout}\n{stderr}"),
        });
    }
    Ok(stdout)
}

/// `verilator --version` -> "5.006"; Verilator 4 lacks the options used here.
pub(crate) fn verilator_version(verilator: &Path) -> Result<String, Missing> {
    let out = run(
        Command::new(verilator).arg("--version"),
        "verilator --version",
    )
    .map_err(|_| Missing::Unavailable {
        msg: format!("{UNAVAILABLE_MSG} ({} does not run)", verilator.display()),
    })?;
    let version = out.split_whitespace().nth(1).unwrap_or("").to_string();
    let major: u32 = version
        .split('.')
        .next()
        .and_then(|m| m.parse().ok())
        .unwrap_or(0);
    if major < 5 {
        return Err(Missing::Unavailable {
            msg: format!(
                "{UNAVAILABLE_MSG} (found `{}`, version 5 or newer is needed)",
                out.trim()
            ),
        });
    }
    Ok(version)
}

/// The directory holding `include/verilated.h`.
pub(crate) fn verilator_root(verilator: &Path) -> Result<PathBuf, Missing> {
    let out = run(
        Command::new(verilator).args(["--getenv", "VERILATOR_ROOT"]),
        "verilator --getenv VERILATOR_ROOT",
    )?;
    let root = PathBuf::from(out.trim());
    if root.join("include").join("verilated.h").is_file() {
        Ok(root)
    } else {
        Err(Missing::Unavailable {
            msg: format!(
                "{UNAVAILABLE_MSG} (no include/verilated.h under VERILATOR_ROOT={})",
                root.display()
            ),
        })
    }
}

/// What a built model depends on: Verilator (path, version), options, RTL text
/// (without `file`: what the runtime library depends on).
pub(crate) fn stamp_key(
    verilator: &Path,
    version: &str,
    file: Option<&Path>,
) -> Result<Vec<u8>, Missing> {
    let mut key = format!(
        "{}\n{version}\n{}\n{}\n",
        verilator.display(),
        VERILATOR_FLAGS.join(" "),
        MAKE_VARS.join(" ")
    )
    .into_bytes();
    if let Some(file) = file {
        let rtl = fs::read(file).map_err(|e| Missing::Failed {
            msg: format!("cannot read {}", file.display()),
            detail: e.to_string(),
        })?;
        key.extend_from_slice(&rtl);
    }
    Ok(key)
}

/// FNV-1a 64, to name cache directories.
pub(crate) fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// `<target>/drcc-verilated` (OUT_DIR is `<target>/<profile>/build/<pkg>/out`),
/// or `OUT_DIR/verilated` if the layout is not the usual one.
pub(crate) fn shared_cache_dir(out: &Path) -> PathBuf {
    match out.ancestors().nth(4) {
        Some(t) if out.ancestors().nth(2).and_then(Path::file_name) == Some("build".as_ref()) => {
            t.join("drcc-verilated")
        }
        _ => out.join("verilated"),
    }
}

/// Removes the other `<prefix>*` entries of the cache (older RTL or Verilator).
pub(crate) fn prune(cache: &Path, prefix: &str, keep: &Path) {
    let Ok(entries) = fs::read_dir(cache) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p != keep && e.file_name().to_string_lossy().starts_with(prefix) {
            let _ = fs::remove_dir_all(&p);
        }
    }
}

pub(crate) fn copy(from: &Path, to: &Path) -> Result<(), Missing> {
    fs::copy(from, to).map(|_| ()).map_err(|e| Missing::Failed {
        msg: format!("cannot copy {} to {}", from.display(), to.display()),
        detail: e.to_string(),
    })
}

/// Verilates and compiles one top into `mdir` (incremental: make skips what is current).
pub(crate) fn verilate(
    verilator: &Path,
    top: &TopTable,
    file: &Path,
    mdir: &Path,
    jobs: usize,
) -> Result<(), Missing> {
    let mut cmd = Command::new(verilator);
    cmd.args(VERILATOR_FLAGS)
        .arg("--top-module")
        .arg(&top.name)
        .arg("--prefix")
        .arg(format!("V{}", top.name))
        .arg("--Mdir")
        .arg(mdir)
        .arg("-j")
        .arg(jobs.to_string());
    for var in MAKE_VARS {
        cmd.arg("-MAKEFLAGS").arg(var);
    }
    cmd.arg(file);
    let log = mdir.join("verilator-error.log");
    let result = run(
        &mut cmd,
        &format!("verilating {} (log: {})", file.display(), log.display()),
    );
    if let Err(Missing::Failed { detail, .. }) = &result {
        fs::create_dir_all(mdir).ok();
        fs::write(&log, detail).ok();
    }
    result.map(|_| ())
}

/// Builds the Verilator runtime (verilated.cpp, the VCD writer, ...) as one archive.
/// Verilator >= 5.0xx leaves `libverilated.a` in the Mdir; 5.006 does not, so the
/// objects listed as VM_GLOBAL_* in `V<top>_classes.mk` are made with Verilator's
/// own rules and flags and archived here.
pub(crate) fn build_runtime(
    top: &TopTable,
    mdir: &Path,
    jobs: usize,
    dest: &Path,
) -> Result<(), Missing> {
    let existing = mdir.join("libverilated.a");
    if existing.is_file() {
        fs::copy(&existing, dest).map_err(|e| Missing::Failed {
            msg: "cannot copy libverilated.a".into(),
            detail: e.to_string(),
        })?;
        return Ok(());
    }
    let classes = mdir.join(format!("V{}_classes.mk", top.name));
    let text = fs::read_to_string(&classes).map_err(|e| Missing::Failed {
        msg: format!("cannot read {}", classes.display()),
        detail: e.to_string(),
    })?;
    let objs = make_list(&text, "VM_GLOBAL_FAST")
        .into_iter()
        .chain(make_list(&text, "VM_GLOBAL_SLOW"))
        .map(|c| format!("{c}.o"))
        .collect::<Vec<_>>();
    if objs.is_empty() {
        return Err(Missing::Failed {
            msg: format!("no VM_GLOBAL_* runtime classes in {}", classes.display()),
            detail: text,
        });
    }
    let mut make = Command::new("make");
    make.current_dir(mdir)
        .arg("-f")
        .arg(format!("V{}.mk", top.name))
        .arg(format!("-j{jobs}"))
        .args(MAKE_VARS)
        .args(&objs);
    run(&mut make, "building the Verilator runtime")?;
    let _ = fs::remove_file(dest);
    let ar = env::var("AR").unwrap_or_else(|_| "ar".into());
    let mut arc = Command::new(ar);
    arc.current_dir(mdir).arg("rcs").arg(dest).args(&objs);
    run(&mut arc, "archiving the Verilator runtime")?;
    Ok(())
}

/// The words of a `NAME += \` list in a Verilator-generated makefile.
pub(crate) fn make_list(text: &str, name: &str) -> Vec<String> {
    let mut items = Vec::new();
    let mut inside = false;
    for line in text.lines() {
        let t = line.trim();
        if !inside {
            if let Some(rest) = t.strip_prefix(name) {
                let rest = rest.trim_start();
                if rest.starts_with("+=") || rest.starts_with('=') {
                    inside = rest.ends_with('\\');
                }
            }
            continue;
        }
        let word = t.trim_end_matches('\\').trim();
        if !word.is_empty() {
            items.push(word.to_string());
        }
        inside = t.ends_with('\\');
    }
    items
}
