//! `drcc generate [--out DIR] [--check]`: writes `<top>.v` for every top of
//! `drcc_hdl::tops::emit_all()`, the DRCC register header `drcc_regs.h` beside
//! them and the register documentation `docs/registers.md` (into DIR too when
//! `--out` is given), both generated from `drcc_hdl::host::registers`; or checks
//! that the files on disk are current.
//!
//! Without `--out` the files go into the DRCC checkout the command runs in (the
//! current directory or its nearest ancestor with the checkout's marker files,
//! `super::project_root`), and `--check` compares that checkout; outside a checkout
//! it refuses. Every file is written through a temporary file and a rename.

use std::path::{Path, PathBuf};

use super::{project_root, write_atomic, CliError, CliResult};

/// Where a generated file goes, from its repository-relative path.
type Placer = Box<dyn Fn(&Path) -> PathBuf>;

/// Runs the command.
pub fn run(out: Option<PathBuf>, check: bool) -> CliResult {
    // Where the files go: flat into `--out DIR`, or each at its place in the
    // checkout the command runs in.
    let (dir, place): (PathBuf, Placer) = match out {
        Some(d) => (
            d.clone(),
            Box::new(move |rel: &Path| {
                d.join(rel.file_name().expect("generated path has a file name"))
            }),
        ),
        None => {
            let root = project_root(", or give --out DIR to write the files there")?;
            (
                root.join("rtl-out"),
                Box::new(move |rel: &Path| root.join(rel)),
            )
        }
    };
    let tops = drcc_hdl::tops::emit_all();
    let extras: Vec<(PathBuf, String)> = drcc_hdl::generated::extras()
        .into_iter()
        .map(|f| (place(Path::new(f.path)), f.text))
        .collect();
    if check {
        let verilog = check_dir(&dir, &tops);
        let others = check_files(&extras);
        match (verilog, others) {
            (Ok(()), Ok(())) => Ok(()),
            (Err(CliError::Failed(a)), Err(CliError::Failed(b))) => {
                Err(CliError::Failed(format!("{a}; {b}")))
            }
            (Err(e), _) | (_, Err(e)) => Err(e),
        }
    } else {
        write_dir(&dir, &tops)?;
        write_files(&extras)
    }
}

fn write_files(files: &[(PathBuf, String)]) -> CliResult {
    for (path, text) in files {
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent)
                .map_err(|e| CliError::Error(format!("cannot create {}: {e}", parent.display())))?;
        }
        if std::fs::read_to_string(path).is_ok_and(|old| old == *text) {
            println!("unchanged {}", path.display());
            continue;
        }
        write_atomic(path, text)?;
        println!("wrote {} ({} lines)", path.display(), text.lines().count());
    }
    Ok(())
}

fn check_files(files: &[(PathBuf, String)]) -> CliResult {
    let mut stale = Vec::new();
    for (path, text) in files {
        match std::fs::read_to_string(path) {
            Ok(old) if old == *text => println!("up to date {}", path.display()),
            Ok(_) => stale.push(format!("{} is stale", path.display())),
            Err(_) => stale.push(format!("{} is missing", path.display())),
        }
    }
    if stale.is_empty() {
        Ok(())
    } else {
        Err(CliError::Failed(format!(
            "{}; run `drcc generate` and commit the result",
            stale.join("; ")
        )))
    }
}

fn write_dir(dir: &Path, tops: &[(&'static str, String)]) -> CliResult {
    std::fs::create_dir_all(dir)
        .map_err(|e| CliError::Error(format!("cannot create {}: {e}", dir.display())))?;
    for (name, text) in tops {
        let path = dir.join(format!("{name}.v"));
        let same = std::fs::read_to_string(&path).is_ok_and(|old| old == *text);
        if same {
            println!("unchanged {}", path.display());
            continue;
        }
        write_atomic(&path, text)?;
        println!("wrote {} ({} lines)", path.display(), text.lines().count());
    }
    Ok(())
}

fn check_dir(dir: &Path, tops: &[(&'static str, String)]) -> CliResult {
    let mut stale = Vec::new();
    for (name, text) in tops {
        let path = dir.join(format!("{name}.v"));
        match std::fs::read_to_string(&path) {
            Ok(old) if old == *text => println!("up to date {}", path.display()),
            Ok(old) => {
                let line = old
                    .lines()
                    .zip(text.lines())
                    .position(|(a, b)| a != b)
                    .unwrap_or_else(|| old.lines().count().min(text.lines().count()))
                    + 1;
                stale.push(format!(
                    "{} is stale (first difference at line {line})",
                    path.display()
                ));
            }
            Err(_) => stale.push(format!("{} is missing", path.display())),
        }
    }
    if let Ok(entries) = std::fs::read_dir(dir) {
        for e in entries.flatten() {
            let p = e.path();
            let stem = p.file_stem().and_then(|s| s.to_str()).unwrap_or("");
            if p.extension().is_some_and(|x| x == "v") && !tops.iter().any(|(n, _)| *n == stem) {
                stale.push(format!(
                    "{} is not emitted by any top (remove it)",
                    p.display()
                ));
            }
        }
    }
    if stale.is_empty() {
        Ok(())
    } else {
        Err(CliError::Failed(format!(
            "{}; run `drcc generate` and commit the result",
            stale.join("; ")
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_names_stale_and_extra_files() {
        let dir = std::env::temp_dir().join(format!("drcc-generate-test-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let tops = vec![("top_a", "module top_a;\nendmodule\n".to_string())];
        write_dir(&dir, &tops).unwrap();
        check_dir(&dir, &tops).unwrap();
        std::fs::write(dir.join("top_a.v"), "module top_a;\n// edited\nendmodule\n").unwrap();
        std::fs::write(dir.join("old.v"), "").unwrap();
        match check_dir(&dir, &tops) {
            Err(CliError::Failed(m)) => {
                assert!(
                    m.contains("top_a.v is stale (first difference at line 2)"),
                    "{m}"
                );
                assert!(m.contains("old.v is not emitted"), "{m}");
            }
            other => panic!("{other:?}"),
        }
        std::fs::remove_file(dir.join("top_a.v")).unwrap();
        match check_dir(&dir, &tops) {
            Err(CliError::Failed(m)) => assert!(m.contains("top_a.v is missing"), "{m}"),
            other => panic!("{other:?}"),
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
