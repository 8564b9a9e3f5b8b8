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
#[path = "build/models.rs"]
mod models;
#[path = "build/tables.rs"]
mod tables;

use models::{
    build_runtime, build_stale, copy, fnv1a, prune, shared_cache_dir, stamp_key, verilator_root,
    verilator_version,
};
use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use tables::TopTable;

/// Message when no usable Verilator is found (kept equal to `UNAVAILABLE_MSG` in lib.rs).
const UNAVAILABLE_MSG: &str = "Verilator not found: install it with `apt-get install verilator`";

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
