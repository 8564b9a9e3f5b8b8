//! Build script of verilator-sys: finds the tops by their port tables
//! (`shim/<top>_ports.h`, written by `drcc generate`), generates the Rust port
//! structs and bindings from them (always), and verilates every top from the RTL
//! directory (`<workspace>/rtl-out/<top>.v`, or `$DRCC_RTL_DIR`), builds the
//! Verilator runtime and the C ABI shims (one `<top>_shim.cpp` per top, generated
//! into OUT_DIR around `shim/verilated_top_shim.inc`) and links them all into
//! this crate, then sets `cfg(drcc_verilator)`.
//!
//! Without Verilator, or without the RTL files, the crate is built without the
//! model (a `cargo:warning` says why; `verilator_sys::available()` is false)
//! unless Verilator is required (`drcc_tools::required`: `DRCC_REQUIRE_VERILATOR` or
//! `CI` set to anything but empty, `0`, `false`, `no`, `off`), which turns every
//! such case into a build error.
//!
//! Built models are cached in `<target>/drcc-verilated/` keyed by Verilator
//! version, options and RTL text, so the dev/test/release profiles share one
//! Verilator run; only the small shim is compiled per profile.
//!
//! Ports are never parsed from Verilog or from Verilator's headers: the table and
//! the RTL come from the same rust-hdl block (`drcc generate --check` keeps them
//! current), and the shim checks at compile time that every table port exists on
//! the model and fits its C type.

#[path = "build/eval_step.rs"]
mod eval_step;
#[path = "build/tables.rs"]
mod tables;

use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;
use tables::TopTable;

/// Message when no usable Verilator is found (kept equal to `UNAVAILABLE_MSG` in lib.rs).
const UNAVAILABLE_MSG: &str = "Verilator not found: install it with `apt-get install verilator`";

/// Verilator options. Why each one:
/// - `--cc --build`: C++ model, compiled by Verilator's own makefile into `V<top>__ALL.a`.
/// - `-O3 --x-assign fast --x-initial fast --noassert`: fastest model; X values
///   become constants (the RTL resets every register it relies on).
/// - `--trace`: VCD support compiled in (costs nothing while no trace is open).
/// - `-Wno-fatal`: the RTL is linted separately; warnings must not stop the build.
/// - `--no-timing`: no delay scheduling (synthesizable RTL); also spares the
///   C++20 coroutine runtime.
/// - `-CFLAGS -fPIC`: the archives end up in Rust binaries that may be PIE.
const VERILATOR_FLAGS: &[&str] = &[
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
const MAKE_VARS: &[&str] = &[
    "OPT_FAST=-O3",
    "OPT_SLOW=-O1",
    "OPT_GLOBAL=-O2",
    "VM_PARALLEL_BUILDS=1",
];

/// Why the model could not be built.
enum Missing {
    /// No Verilator or no RTL: an expected situation on a fresh checkout.
    Unavailable { msg: String },
    /// Verilator or the shim compile ran and failed.
    Failed { msg: String, detail: String },
}

fn main() {
    println!("cargo::rustc-check-cfg=cfg(drcc_verilator)");
    for var in ["VERILATOR", "DRCC_RTL_DIR"]
        .into_iter()
        .chain(drcc_tools::REQUIRE_VARS)
    {
        println!("cargo::rerun-if-env-changed={var}");
    }
    let manifest = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let shim_dir = manifest.join("shim");
    println!("cargo::rerun-if-changed={}", shim_dir.display());
    // The script and the files it includes with #[path].
    for own in ["build.rs", "build"] {
        println!("cargo::rerun-if-changed={own}");
    }
    if let Ok(entries) = fs::read_dir(&shim_dir) {
        for e in entries.flatten() {
            println!("cargo::rerun-if-changed={}", e.path().display());
        }
    }

    // The Rust bindings exist in every build, with or without the model.
    let tops = tables::find_tops(&shim_dir).unwrap_or_else(|e| panic!("{e}"));
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("OUT_DIR"));
    write_if_changed(&out.join("tops.rs"), &tables::rust_bindings(&tops));

    let required = drcc_tools::required();
    match build(&manifest, &shim_dir, &tops) {
        Ok(version) => {
            println!("cargo::rustc-cfg=drcc_verilator");
            println!("cargo::rustc-env=DRCC_VERILATOR_VERSION={version}");
            println!("cargo::rustc-env=DRCC_VERILATOR_UNAVAILABLE=");
        }
        Err(Missing::Unavailable { msg }) => {
            if required {
                panic!("{msg} (Verilator is required: DRCC_REQUIRE_VERILATOR or CI is set)");
            }
            println!("cargo::warning={msg}; building verilator-sys without the Verilated model");
            println!("cargo::rustc-env=DRCC_VERILATOR_VERSION=");
            println!("cargo::rustc-env=DRCC_VERILATOR_UNAVAILABLE={msg}");
        }
        Err(Missing::Failed { msg, detail }) => {
            if required {
                panic!("{msg}\n{}", summary(&detail).join("\n"));
            }
            println!("cargo::warning={msg}; building verilator-sys without the Verilated model");
            for line in summary(&detail) {
                println!("cargo::warning=  {line}");
            }
            println!("cargo::rustc-env=DRCC_VERILATOR_VERSION=");
            println!("cargo::rustc-env=DRCC_VERILATOR_UNAVAILABLE={msg}");
        }
    }
}

/// Builds and links every top; returns the Verilator version.
fn build(manifest: &Path, shim_dir: &Path, tops: &[TopTable]) -> Result<String, Missing> {
    let rtl_dir = rtl_dir(manifest);
    for top in tops {
        let file = rtl_dir.join(rtl_file(top));
        // Watch the file; while it is missing, watch the closest existing directory
        // (its appearance changes that directory). A missing watched path would
        // rerun this script, and rebuild every dependent crate, on every build.
        let mut watched = file.clone();
        while !watched.exists() {
            match watched.parent() {
                Some(p) if !p.as_os_str().is_empty() => watched = p.to_path_buf(),
                _ => break,
            }
        }
        println!("cargo::rerun-if-changed={}", watched.display());
    }

    let verilator = find_verilator().ok_or_else(|| Missing::Unavailable {
        msg: UNAVAILABLE_MSG.to_string(),
    })?;
    let version = verilator_version(&verilator)?;
    let root = verilator_root(&verilator)?;

    for top in tops {
        let file = rtl_dir.join(rtl_file(top));
        if !file.is_file() {
            return Err(Missing::Unavailable {
                msg: format!(
                    "rtl-out/{} missing: run `cargo run -- generate` (looked for {})",
                    rtl_file(top),
                    file.display()
                ),
            });
        }
    }

    let out = PathBuf::from(env::var_os("OUT_DIR").expect("OUT_DIR"));
    let lib_dir = out.join("lib");
    fs::create_dir_all(&lib_dir).expect("create OUT_DIR/lib");
    let gen_dir = out.join("shim");
    fs::create_dir_all(&gen_dir).expect("create OUT_DIR/shim");
    let jobs = env::var("NUM_JOBS")
        .ok()
        .and_then(|j| j.parse::<usize>().ok())
        .unwrap_or(2)
        .max(1);

    // Models are cached per (Verilator, options, RTL text) outside OUT_DIR, so the
    // dev, test and release profiles share one build; Verilator rewrites every
    // generated file, so rerunning it would recompile everything. The lock
    // serialises concurrent build-script runs (several profiles in one cargo run).
    let cache = shared_cache_dir(&out);
    fs::create_dir_all(&cache).expect("create the Verilator model cache");
    let lock = fs::File::create(cache.join(".lock")).expect("create the cache lock");
    lock.lock().expect("lock the Verilator model cache");

    let base_key = stamp_key(&verilator, &version, None)?;
    let runtime_dir = cache.join(format!("runtime-{:016x}", fnv1a(&base_key)));
    let runtime = runtime_dir.join("libdrcc_verilated_rt.a");
    // Which models are stale: verilated and compiled below, two at a time.
    let mut stale = Vec::new();
    let mut planned = Vec::new();
    for top in tops {
        let file = rtl_dir.join(rtl_file(top));
        let key = stamp_key(&verilator, &version, Some(&file))?;
        let mdir = cache.join(format!("V{}-{:016x}", top.name, fnv1a(&key)));
        let archive = format!("V{}__ALL.a", top.name);
        let current = fs::read(mdir.join("drcc-stamp")).is_ok_and(|s| s == key)
            && mdir.join(&archive).is_file();
        if !current {
            let size = fs::metadata(&file).map_or(0, |m| m.len());
            stale.push((size, top, file, mdir.clone(), key));
        }
        planned.push((top, mdir, archive));
    }
    build_stale(&verilator, &cache, stale, jobs)?;

    let mut mdirs = Vec::new();
    let mut defines: Vec<(String, String)> = Vec::new();
    for (top, mdir, archive) in planned {
        if let Some(member) = eval_step::clk_prev_member(top, &mdir) {
            let upper = top.name.to_uppercase();
            defines.push((format!("DRCC_{upper}_CLK_PREV"), member));
            // The shim's own copy of the evaluation loop, which skips the
            // input-combinational region when no input changed (drcc::evalStep),
            // only for code it was copied from.
            match eval_step::eval_code_matches(top, &mdir) {
                Ok(()) => defines.push((format!("DRCC_{upper}_EVAL_STEP"), "1".into())),
                Err(why) => println!(
                    "cargo::warning=V{}: {why}: stepping through eval() (same results, slower)",
                    top.name
                ),
            }
        }
        if !runtime.is_file() {
            fs::create_dir_all(&runtime_dir).expect("create the runtime cache");
            build_runtime(top, &mdir, jobs, &runtime)?;
            prune(&cache, "runtime-", &runtime_dir);
        }
        copy(&mdir.join(&archive), &lib_dir.join(format!("lib{archive}")))?;
        mdirs.push(mdir);
    }
    copy(&runtime, &lib_dir.join("libdrcc_verilated_rt.a"))?;

    // The shims: compiled by the cc crate, linked first (they call into the models).
    let include = root.join("include");
    let mut cc = cc::Build::new();
    cc.cpp(true)
        .opt_level(2)
        .warnings(false)
        .cpp_link_stdlib(None)
        .include(shim_dir)
        .include(&include)
        .include(include.join("vltstd"))
        .define("VM_COVERAGE", "0")
        .define("VM_SC", "0")
        .define("VM_TRACE", "1")
        .define("VM_TRACE_FST", "0")
        .define("VM_TRACE_VCD", "1")
        .flag_if_supported("-faligned-new")
        .flag_if_supported("-Wno-unused-parameter");
    for (name, value) in &defines {
        cc.define(name, value.as_str());
    }
    for (top, mdir) in tops.iter().zip(&mdirs) {
        let cpp = gen_dir.join(format!("{}_shim.cpp", top.name));
        write_if_changed(&cpp, &tables::shim_cpp(top));
        cc.include(mdir);
        cc.file(cpp);
    }
    cc.compile("drcc_verilator_shims");

    // Then the models, then the runtime they share, then the C++ runtime.
    println!("cargo::rustc-link-search=native={}", lib_dir.display());
    for top in tops {
        println!("cargo::rustc-link-lib=static=V{}__ALL", top.name);
    }
    println!("cargo::rustc-link-lib=static=drcc_verilated_rt");
    println!("cargo::rustc-link-lib=dylib=stdc++");
    println!("cargo::rustc-link-lib=dylib=pthread");
    Ok(version)
}

/// The RTL file of a top inside the RTL directory (it may hold submodules too).
fn rtl_file(top: &TopTable) -> String {
    format!("{}.v", top.name)
}

/// Writes `text` unless the file already holds it (keeps the shim's mtime, so the
/// cc crate's output stays current).
fn write_if_changed(path: &Path, text: &str) {
    if fs::read_to_string(path).is_ok_and(|old| old == text) {
        return;
    }
    fs::write(path, text).unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
}

/// `$DRCC_RTL_DIR` (relative paths are taken from the workspace root) or `<workspace>/rtl-out`.
fn rtl_dir(manifest: &Path) -> PathBuf {
    let workspace = manifest.join("..").join("..");
    match env::var_os("DRCC_RTL_DIR") {
        Some(d) if !d.is_empty() => {
            let d = PathBuf::from(d);
            if d.is_absolute() {
                d
            } else {
                workspace.join(d)
            }
        }
        _ => workspace.join("rtl-out"),
    }
}

/// `$VERILATOR` if set, else `verilator` on `PATH`.
fn find_verilator() -> Option<PathBuf> {
    if let Some(v) = env::var_os("VERILATOR").filter(|v| !v.is_empty()) {
        let p = PathBuf::from(&v);
        if p.components().count() > 1 {
            return p.is_file().then_some(p);
        }
        return search_path(&v);
    }
    search_path("verilator".as_ref())
}

fn search_path(name: &std::ffi::OsStr) -> Option<PathBuf> {
    let path = env::var_os("PATH")?;
    env::split_paths(&path)
        .map(|dir| dir.join(name))
        .find(|p| is_executable(p))
}

#[cfg(unix)]
fn is_executable(p: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    fs::metadata(p)
        .map(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
        .unwrap_or(false)
}

#[cfg(not(unix))]
fn is_executable(p: &Path) -> bool {
    p.is_file()
}

/// Runs `cmd` and returns its stdout, or a `Missing::Failed` that names `what`.
/// Verilates and compiles the stale models, largest RTL first, on two workers
/// (each runs its own `make -j`): Verilator's front end and each model's last
/// file compile on one core, so two models at a time keep both busy. Each model
/// gets its stamp and build time when it is done.
fn build_stale(
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

fn run(cmd: &mut Command, what: &str) -> Result<String, Missing> {
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

/// The error lines of a failed run (at most 20), else its last 20 lines.
fn summary(detail: &str) -> Vec<&str> {
    let errors: Vec<&str> = detail
        .lines()
        .filter(|l| l.contains("%Error") || l.contains("error:"))
        .take(20)
        .collect();
    if errors.is_empty() {
        let lines: Vec<&str> = detail.lines().collect();
        lines[lines.len().saturating_sub(20)..].to_vec()
    } else {
        errors
    }
}

/// `verilator --version` -> "5.006"; Verilator 4 lacks the options used here.
fn verilator_version(verilator: &Path) -> Result<String, Missing> {
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
fn verilator_root(verilator: &Path) -> Result<PathBuf, Missing> {
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
fn stamp_key(verilator: &Path, version: &str, file: Option<&Path>) -> Result<Vec<u8>, Missing> {
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
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// `<target>/drcc-verilated` (OUT_DIR is `<target>/<profile>/build/<pkg>/out`),
/// or `OUT_DIR/verilated` if the layout is not the usual one.
fn shared_cache_dir(out: &Path) -> PathBuf {
    match out.ancestors().nth(4) {
        Some(t) if out.ancestors().nth(2).and_then(Path::file_name) == Some("build".as_ref()) => {
            t.join("drcc-verilated")
        }
        _ => out.join("verilated"),
    }
}

/// Removes the other `<prefix>*` entries of the cache (older RTL or Verilator).
fn prune(cache: &Path, prefix: &str, keep: &Path) {
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

fn copy(from: &Path, to: &Path) -> Result<(), Missing> {
    fs::copy(from, to).map(|_| ()).map_err(|e| Missing::Failed {
        msg: format!("cannot copy {} to {}", from.display(), to.display()),
        detail: e.to_string(),
    })
}

/// Verilates and compiles one top into `mdir` (incremental: make skips what is current).
fn verilate(
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
fn build_runtime(top: &TopTable, mdir: &Path, jobs: usize, dest: &Path) -> Result<(), Missing> {
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
fn make_list(text: &str, name: &str) -> Vec<String> {
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
