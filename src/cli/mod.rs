//! The `drcc` subcommands, the error type shared by them (check failure: exit 1;
//! error: exit 2) and the panic hook that turns an internal error into one line.

pub mod campaign;
pub mod dmr;
pub mod gen_config;
pub mod generate;
pub mod redundancy;
pub mod ring;
pub mod run;
pub mod serve;
pub mod star;
pub mod synth;
pub mod traffic;
pub mod wave;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use drcc_tools::atomic::{is_special, tmp_path};

/// Why a command failed.
#[derive(Debug)]
pub enum CliError {
    /// A check failed (exit 1): the message says what.
    Failed(String),
    /// An error (exit 2): bad input, missing tool, I/O.
    Error(String),
}

impl CliError {
    /// Prints the message and gives the exit code.
    pub fn report(self) -> ExitCode {
        match self {
            CliError::Failed(m) => {
                eprintln!("drcc: FAILED: {m}");
                ExitCode::from(1)
            }
            CliError::Error(m) => {
                eprintln!("drcc: error: {m}");
                ExitCode::from(2)
            }
        }
    }
}

impl From<String> for CliError {
    fn from(s: String) -> Self {
        CliError::Error(s)
    }
}

/// Result of a command.
pub type CliResult = Result<(), CliError>;

/// Prints an internal error (a panic) as one message and exits with code 2,
/// without a backtrace.
pub fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_string());
        let at = info
            .location()
            .map(|l| format!(" (at {}:{})", l.file(), l.line()))
            .unwrap_or_default();
        eprintln!("drcc: error: internal error: {msg}{at}");
        std::process::exit(2);
    }));
}

/// The files that mark a DRCC checkout: the project whose generated files
/// (`rtl-out/`, `docs/registers.md`, the tables in README.md and `docs/`) the
/// commands write.
pub const PROJECT_MARKERS: [&str; 3] = [
    "Cargo.toml",
    "hdl/src/tops.rs",
    "cosim/src/model/drcc_contract.md",
];

/// The DRCC checkout a command writes generated files into: the current directory
/// or its nearest ancestor that holds every file of [`PROJECT_MARKERS`]. Never the
/// checkout the binary was built from, and never a directory that merely has a
/// `docs/` or `rtl-out/`. `instead` says what the user can do outside a checkout.
pub fn project_root(instead: &str) -> Result<PathBuf, CliError> {
    let cwd = std::env::current_dir()
        .map_err(|e| CliError::Error(format!("cannot read the current directory: {e}")))?;
    cwd.ancestors()
        .find(|d| PROJECT_MARKERS.iter().all(|m| d.join(m).is_file()))
        .map(Path::to_path_buf)
        .ok_or_else(|| {
            CliError::Error(format!(
                "{} is not inside a DRCC checkout (no directory from here up holds {}): run \
                 this from the checkout whose files it regenerates{instead}",
                cwd.display(),
                PROJECT_MARKERS[1]
            ))
        })
}

/// Writes `text` to `path` through a temporary file beside it and a rename, so an
/// interrupted write leaves the old file or the new one, never a truncated one.
/// A device or a pipe is written in place ([`drcc_tools::atomic`]).
pub fn write_atomic(path: &Path, text: impl AsRef<[u8]>) -> Result<(), CliError> {
    drcc_tools::atomic::write(path, text).map_err(CliError::Error)
}

/// Whether two paths name the same file: the same file on disk if both exist,
/// else the same path once made absolute, `.` and `..` resolved and the longest
/// existing ancestor canonicalized (symbolic links).
pub fn same_file(a: &Path, b: &Path) -> bool {
    fn canon(p: &Path) -> Option<PathBuf> {
        if let Ok(c) = p.canonicalize() {
            return Some(c);
        }
        let mut abs = PathBuf::new();
        for c in std::env::current_dir().ok()?.join(p).components() {
            match c {
                std::path::Component::ParentDir => {
                    abs.pop();
                }
                std::path::Component::CurDir => {}
                other => abs.push(other),
            }
        }
        let base = abs.ancestors().find(|d| d.exists())?.to_path_buf();
        let rest = abs.strip_prefix(&base).ok()?.to_path_buf();
        Some(base.canonicalize().ok()?.join(rest))
    }
    match (canon(a), canon(b)) {
        (Some(x), Some(y)) => x == y,
        _ => a == b,
    }
}

/// Refuses output files that would destroy an input or each other: each output
/// (`(option, path)`) must differ from every input and from every other output.
pub fn check_outputs(inputs: &[&Path], outputs: &[(&str, &Path)]) -> CliResult {
    for (i, (opt, out)) in outputs.iter().enumerate() {
        if let Some(inp) = inputs.iter().find(|inp| same_file(inp, out)) {
            return Err(CliError::Error(format!(
                "{opt} {}: that is the input {}, which the output would replace; give \
                 another file name",
                out.display(),
                inp.display()
            )));
        }
        if let Some((other, _)) = outputs[..i].iter().find(|(_, o)| same_file(o, out)) {
            return Err(CliError::Error(format!(
                "{other} and {opt} both name {}: each output needs a file of its own",
                out.display()
            )));
        }
    }
    Ok(())
}

/// An output file written under a temporary name beside it and renamed into place
/// by [`AtomicFile::commit`]; dropped uncommitted (an error, an interrupt), it
/// removes the temporary file and leaves the old file, if any, as it was. A device
/// or a pipe (`/dev/null`, a FIFO) is written in place: renaming a file over it
/// would replace the device with a file.
pub struct AtomicFile {
    path: PathBuf,
    /// The temporary file, or none for a device or a pipe.
    tmp: Option<PathBuf>,
    writer: Option<std::io::BufWriter<std::fs::File>>,
}

impl AtomicFile {
    /// Creates the temporary file (and the missing directories of `path`).
    pub fn create(path: &Path) -> Result<Self, CliError> {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            drcc_tools::atomic::create_dir(dir).map_err(CliError::Error)?;
        }
        let tmp = (!is_special(path)).then(|| tmp_path(path));
        let f = std::fs::File::create(tmp.as_deref().unwrap_or(path)).map_err(|e| {
            CliError::Error(format!(
                "cannot create {} ({e}): give a file in a writable directory",
                path.display()
            ))
        })?;
        Ok(AtomicFile {
            path: path.to_path_buf(),
            tmp,
            writer: Some(std::io::BufWriter::new(f)),
        })
    }

    /// The writer of the temporary file.
    pub fn writer(&mut self) -> &mut std::io::BufWriter<std::fs::File> {
        self.writer.as_mut().expect("not committed")
    }

    /// Flushes the temporary file and renames it over `path`.
    pub fn commit(mut self) -> CliResult {
        use std::io::Write;
        let mut w = self.writer.take().expect("not committed");
        w.flush()
            .map_err(|e| CliError::Error(format!("cannot write {}: {e}", self.path.display())))?;
        drop(w);
        match &self.tmp {
            Some(tmp) => std::fs::rename(tmp, &self.path).map_err(|e| {
                CliError::Error(format!("cannot replace {}: {e}", self.path.display()))
            }),
            None => Ok(()),
        }
    }
}

/// Writes go to the temporary file, so writers that own their output (the traffic
/// export's) can own the file and give it back for [`AtomicFile::commit`].
impl std::io::Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.writer().write(buf)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.writer().flush()
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if let (Some(_), Some(tmp)) = (self.writer.take(), &self.tmp) {
            let _ = std::fs::remove_file(tmp);
        }
    }
}

/// A path to *read* from the workspace: as given if it exists relative to the
/// current directory, else relative to the workspace this binary was built from.
/// Commands never write through it (see [`project_root`]).
pub fn workspace_path(rel: &str) -> PathBuf {
    let here = Path::new(rel);
    if here.exists() {
        return here.to_path_buf();
    }
    let built = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    if built.exists() {
        built
    } else {
        here.to_path_buf()
    }
}

/// `drcc bench`.
pub fn bench(seconds: f64) -> CliResult {
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= 600.0) {
        return Err(CliError::Error(format!(
            "--seconds {seconds}: give a duration between 0 and 600 seconds"
        )));
    }
    let mut out = std::io::stdout().lock();
    drcc_testbench::bench::run(&mut out, Duration::from_secs_f64(seconds))
        .map_err(|e| CliError::Error(format!("cannot write the report: {e}")))?;
    Ok(())
}

/// Replaces the text between the marker lines `begin` and `end` (generated tables in
/// README.md and docs/) with `body`; names a missing marker.
pub fn replace_between(text: &str, begin: &str, end: &str, body: &str) -> Result<String, String> {
    let b = text
        .find(begin)
        .ok_or_else(|| format!("no `{begin}` marker"))?
        + begin.len();
    let e = text[b..]
        .find(end)
        .map(|i| b + i)
        .ok_or_else(|| format!("no `{end}` marker after the begin marker"))?;
    Ok(format!("{}\n{}{}", &text[..b], body, &text[e..]))
}

/// Rewrites the generated block between `begin` and `end` in every file of `paths`,
/// all or none: every new text is computed and written to a temporary file beside its
/// target first, and only when all of them are written are they renamed over the
/// targets (a rename within a directory is atomic). A missing marker, an unreadable
/// file or an unwritable directory leaves every file as it was.
pub fn rewrite_between_atomic(paths: &[PathBuf], begin: &str, end: &str, body: &str) -> CliResult {
    let mut staged: Vec<(PathBuf, PathBuf)> = Vec::new();
    let cleanup = |staged: &[(PathBuf, PathBuf)]| {
        for (tmp, _) in staged {
            let _ = std::fs::remove_file(tmp);
        }
    };
    for path in paths {
        let step = || -> Result<PathBuf, String> {
            let text = std::fs::read_to_string(path)
                .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
            let new = replace_between(&text, begin, end, body)
                .map_err(|m| format!("{}: {m}", path.display()))?;
            let tmp = tmp_path(path);
            std::fs::write(&tmp, new).map_err(|e| {
                format!(
                    "cannot write {} ({e}): make its directory writable",
                    tmp.display()
                )
            })?;
            Ok(tmp)
        };
        match step() {
            Ok(tmp) => staged.push((tmp, path.clone())),
            Err(m) => {
                cleanup(&staged);
                return Err(CliError::Error(format!("{m}; no file was changed")));
            }
        }
    }
    for (i, (tmp, path)) in staged.iter().enumerate() {
        if let Err(e) = std::fs::rename(tmp, path) {
            cleanup(&staged[i..]);
            return Err(CliError::Error(format!(
                "cannot replace {}: {e}",
                path.display()
            )));
        }
    }
    Ok(())
}

/// `drcc coverage`: the functional coverage of the model over the test suite's
/// workloads (`drcc_testbench::coverage`); exit 1 if a bin is never hit or a name
/// that is not a bin was counted.
pub fn coverage() -> CliResult {
    let t = std::time::Instant::now();
    let r = drcc_testbench::coverage::collect(|w| eprintln!("drcc coverage: {w} ..."))
        .map_err(CliError::Error)?;
    println!("{}", r.table());
    for (name, took) in &r.times {
        eprintln!("drcc coverage: {:7.1} s  {name}", took.as_secs_f64());
    }
    eprintln!(
        "drcc coverage: {} workloads in {:.0} s (on every core)",
        r.times.len(),
        t.elapsed().as_secs_f64()
    );
    let (missed, unlisted) = (r.missed().len(), r.unlisted().len());
    if missed + unlisted > 0 {
        return Err(CliError::Failed(format!(
            "{missed} bin(s) never hit, {unlisted} name(s) counted that are not bins (listed above)"
        )));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const B: &str = "<!-- t:begin -->";
    const E: &str = "<!-- t:end -->";

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("drcc-cli-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn atomic_rewrite_changes_every_file() {
        let d = dir("atomic-ok");
        let (a, b) = (d.join("a.md"), d.join("b.md"));
        std::fs::write(&a, format!("x\n{B}\nold\n{E}\n")).unwrap();
        std::fs::write(&b, format!("{B}\n{E}\ny\n")).unwrap();
        rewrite_between_atomic(&[a.clone(), b.clone()], B, E, "new\n").unwrap();
        assert_eq!(
            std::fs::read_to_string(&a).unwrap(),
            format!("x\n{B}\nnew\n{E}\n")
        );
        assert_eq!(
            std::fs::read_to_string(&b).unwrap(),
            format!("{B}\nnew\n{E}\ny\n")
        );
        assert_eq!(
            std::fs::read_dir(&d).unwrap().count(),
            2,
            "no temporary file left"
        );
    }

    #[test]
    fn atomic_rewrite_changes_nothing_when_one_file_is_bad() {
        let d = dir("atomic-bad");
        let (a, b) = (d.join("a.md"), d.join("b.md"));
        let before = format!("{B}\nold\n{E}\n");
        std::fs::write(&a, &before).unwrap();
        std::fs::write(&b, "no markers\n").unwrap();
        let m = match rewrite_between_atomic(&[a.clone(), b.clone()], B, E, "new\n") {
            Err(CliError::Error(m)) => m,
            other => panic!("expected an error, got {other:?}"),
        };
        assert!(
            m.contains("no file was changed") && m.contains("b.md"),
            "{m}"
        );
        assert_eq!(std::fs::read_to_string(&a).unwrap(), before);
        assert_eq!(
            std::fs::read_dir(&d).unwrap().count(),
            2,
            "no temporary file left"
        );
        let missing = d.join("missing.md");
        assert!(rewrite_between_atomic(&[a.clone(), missing], B, E, "x").is_err());
        assert_eq!(std::fs::read_to_string(&a).unwrap(), before);
    }
}
