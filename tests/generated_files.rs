//! Where the commands write generated files, and how (no write to a place the
//! user did not choose): only into the DRCC checkout they run in (the current
//! directory or its nearest ancestor holding `Cargo.toml`, `hdl/src/tops.rs` and
//! `cosim/src/model/drcc_contract.md`), or into `--out DIR`; never into a directory
//! that merely has a `docs/` or `rtl-out/`, never into the checkout the binary was
//! built from; every file through a temporary file and a rename. Outside a checkout
//! a writing command exits 2 with one message naming what to do, and changes no file.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn drcc_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_drcc"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("cannot run the drcc binary")
}

/// A scratch directory that looks like a project with generated files (a `docs/`
/// with a `registers.md` and an `rtl-out/`) but is no DRCC checkout.
fn lookalike(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("drcc-gen-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(d.join("docs")).unwrap();
    std::fs::create_dir_all(d.join("rtl-out")).unwrap();
    std::fs::write(d.join("docs/registers.md"), "the user's own file\n").unwrap();
    std::fs::write(d.join("README.md"), "the user's README\n").unwrap();
    d
}

/// Every file below `d` with its content.
fn snapshot(d: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![d.to_path_buf()];
    while let Some(p) = stack.pop() {
        for e in std::fs::read_dir(&p).unwrap().flatten() {
            let path = e.path();
            if path.is_dir() {
                stack.push(path);
            } else {
                out.push((path.clone(), std::fs::read(&path).unwrap()));
            }
        }
    }
    out.sort();
    out
}

/// Exit 2 and one line naming the cause and the fix.
fn assert_refused(o: &Output, cause: &str, fix: &str) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "stderr: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "one message: {err}");
    assert!(err.contains(cause), "names the cause ({cause}): {err}");
    assert!(err.contains(fix), "names the fix ({fix}): {err}");
}

#[test]
fn outside_a_checkout_no_command_writes_generated_files() {
    let d = lookalike("outside");
    let before = snapshot(&d);
    let cases: [(&[&str], &str); 4] = [
        (&["generate"], "give --out DIR"),
        (&["generate", "--check"], "give --out DIR"),
        (&["dmr", "table", "--markdown"], "leave out --markdown"),
        (&["star", "table", "--markdown"], "leave out --markdown"),
    ];
    for (args, fix) in cases {
        let o = drcc_in(&d, args);
        assert_refused(&o, "is not inside a DRCC checkout", fix);
        assert_eq!(snapshot(&d), before, "{args:?} changed a file");
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn generate_out_writes_every_file_atomically_into_the_given_directory() {
    let d = lookalike("out");
    let out = d.join("gen");
    let o = drcc_in(&d, &["generate", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let names: Vec<String> = snapshot(&out)
        .iter()
        .map(|(p, _)| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    for top in drcc_hdl::tops::names() {
        assert!(names.contains(&format!("{top}.v")), "{top}.v in {names:?}");
    }
    assert!(names.contains(&"registers.md".to_string()), "{names:?}");
    assert!(
        !names.iter().any(|n| n.ends_with(".drcc-tmp")),
        "no temporary file left: {names:?}"
    );
    // the look-alike project's own files are untouched
    assert_eq!(
        std::fs::read_to_string(d.join("docs/registers.md")).unwrap(),
        "the user's own file\n"
    );
    // and `--check` compares the same directory
    let o = drcc_in(&d, &["generate", "--out", out.to_str().unwrap(), "--check"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn inside_the_checkout_any_subdirectory_means_the_checkout() {
    // `generate --check` from `docs/` compares the checkout's rtl-out/ (which CI
    // keeps current), not a `docs/rtl-out/`.
    let repo = Path::new(env!("CARGO_MANIFEST_DIR"));
    let o = drcc_in(&repo.join("docs"), &["generate", "--check"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        out.contains(&format!(
            "up to date {}",
            repo.join("rtl-out/drcc.v").display()
        )),
        "{out}"
    );
}

/// Eight `drcc generate --out DIR` started at once into one directory (a
/// parallel build, CI jobs sharing a workspace) all succeed, and every file is
/// whole: each process writes through a temporary file of its own.
#[test]
fn concurrent_generates_into_one_directory_all_succeed() {
    let d = lookalike("concurrent");
    let out = d.join("gen");
    let children: Vec<_> = (0..8)
        .map(|_| {
            Command::new(env!("CARGO_BIN_EXE_drcc"))
                .current_dir(&d)
                .args(["generate", "--out", out.to_str().unwrap()])
                .stdout(std::process::Stdio::null())
                .stderr(std::process::Stdio::piped())
                .spawn()
                .expect("cannot run the drcc binary")
        })
        .collect();
    for c in children {
        let o = c.wait_with_output().unwrap();
        assert!(
            o.status.success(),
            "a concurrent generate failed: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
    // Whole files: `--check` finds every one current, and no temporary is left.
    let o = drcc_in(&d, &["generate", "--out", out.to_str().unwrap(), "--check"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        !snapshot(&out)
            .iter()
            .any(|(p, _)| p.to_string_lossy().ends_with(".drcc-tmp")),
        "a temporary file was left"
    );
    let _ = std::fs::remove_dir_all(&d);
}
