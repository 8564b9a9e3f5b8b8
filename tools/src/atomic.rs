//! Files written whole or not at all: every file the project writes for a user
//! (generated Verilog and headers, traces, reports, build scripts) goes through a
//! temporary file beside it and a rename, so an interrupted or failed write leaves
//! the old file or the new one, never a truncated one, and every write error is
//! an error naming the file.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// The temporary file beside `path` that an atomic write goes through.
pub fn tmp_path(path: &Path) -> PathBuf {
    // Unique per process and per call: several processes writing one directory
    // at once (a parallel build, CI jobs sharing a workspace) must not rename
    // one another's temporary files away.
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("file");
    path.with_file_name(format!(".{name}.{}-{n}.drcc-tmp", std::process::id()))
}

/// Whether `path` is a device, a pipe or a socket (`/dev/null`, `/dev/stdout`, a
/// FIFO): written in place, never replaced by a renamed file.
pub fn is_special(path: &Path) -> bool {
    std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir())
}

/// Creates the directory `dir` and its missing parents; the error names the
/// directory, the cause and the fix.
pub fn create_dir(dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| {
        format!(
            "cannot create the directory {} ({e}): give a path whose folders can be created",
            dir.display()
        )
    })
}

/// Writes `bytes` to `path` atomically (a device or a pipe in place). The error
/// names the file and the cause.
pub fn write(path: &Path, bytes: impl AsRef<[u8]>) -> Result<(), String> {
    write_with(path, |w| w.write_all(bytes.as_ref()))
}

/// Writes `path` atomically with `fill`, which streams into a buffered writer (a
/// device or a pipe is written in place). On any error of `fill`, of the flush
/// or of the rename, the temporary file is removed, `path` is left as it was,
/// and the error names `path`.
pub fn write_with(
    path: &Path,
    fill: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> Result<(), String> {
    let cannot = |e: io::Error| format!("cannot write {}: {e}", path.display());
    if is_special(path) {
        let mut w = BufWriter::new(File::create(path).map_err(cannot)?);
        return fill(&mut w).and_then(|_| w.flush()).map_err(cannot);
    }
    let tmp = tmp_path(path);
    let written = File::create(&tmp).and_then(|f| {
        let mut w = BufWriter::new(f);
        fill(&mut w)?;
        w.into_inner().map_err(|e| e.into_error())?.sync_all()
    });
    if let Err(e) = written {
        let _ = std::fs::remove_file(&tmp);
        return Err(format!(
            "cannot write {} ({e}): make its directory writable and leave room on its disk",
            path.display()
        ));
    }
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        format!("cannot replace {}: {e}", path.display())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("drcc-atomic-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn a_write_replaces_the_file_whole_and_leaves_no_temporary() {
        let d = dir("whole");
        let f = d.join("out.txt");
        std::fs::write(&f, "old").unwrap();
        write(&f, "new text").unwrap();
        assert_eq!(std::fs::read_to_string(&f).unwrap(), "new text");
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1);
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_failed_fill_leaves_the_old_file_and_names_it() {
        let d = dir("fail");
        let f = d.join("trace.vcd");
        std::fs::write(&f, "old").unwrap();
        let e = write_with(&f, |w| {
            w.write_all(b"half")?;
            Err(io::Error::other("disk full"))
        })
        .unwrap_err();
        assert!(e.contains("trace.vcd") && e.contains("disk full"), "{e}");
        assert_eq!(std::fs::read_to_string(&f).unwrap(), "old");
        assert_eq!(std::fs::read_dir(&d).unwrap().count(), 1, "temporary left");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_missing_directory_is_an_error_naming_the_file() {
        let d = dir("missing");
        let f = d.join("no/such/dir/out.v");
        let e = write(&f, "x").unwrap_err();
        assert!(e.contains("out.v"), "{e}");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_directory_blocked_by_a_file_is_an_error_naming_it() {
        let d = dir("blocked");
        std::fs::write(d.join("blocker"), "x").unwrap();
        let e = create_dir(&d.join("blocker/sub")).unwrap_err();
        assert!(
            e.contains("blocker/sub") && e.contains("give a path"),
            "{e}"
        );
        assert!(d.join("blocker").is_file());
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_device_is_written_in_place() {
        assert!(is_special(Path::new("/dev/null")));
        write(Path::new("/dev/null"), "x").unwrap();
        // still the device: a rename over it would have left a regular file
        assert!(is_special(Path::new("/dev/null")), "/dev/null was replaced");
    }

    #[test]
    #[cfg(target_os = "linux")]
    fn a_full_device_is_an_error() {
        let e = write(Path::new("/dev/full"), vec![0u8; 1 << 16]).unwrap_err();
        assert!(e.contains("/dev/full"), "{e}");
    }
}
