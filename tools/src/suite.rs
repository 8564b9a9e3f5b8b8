//! The rule of a test suite that is one binary (`autotests = false`): every file
//! of `tests/` is one of its modules, or a test target of its own, so a new file
//! cannot build and run nothing.

use std::path::Path;

/// The files of `tests_dir` (`<name>.rs` or `<name>/mod.rs`) that `suite_text`,
/// the suite's own source, does not declare as `mod <name>;`, leaving out the
/// suite itself and the names in `apart` (test targets of their own).
pub fn unbuilt_test_files(tests_dir: &Path, suite_text: &str, apart: &[&str]) -> Vec<String> {
    let entries = std::fs::read_dir(tests_dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", tests_dir.display()));
    let mut unbuilt = Vec::new();
    for entry in entries {
        let path = entry
            .unwrap_or_else(|e| panic!("cannot list {}: {e}", tests_dir.display()))
            .path();
        let Some(name) = path.file_stem().map(|n| n.to_string_lossy().into_owned()) else {
            continue;
        };
        let is_module =
            path.extension().is_some_and(|x| x == "rs") || path.join("mod.rs").is_file();
        if !is_module || name == "suite" || apart.contains(&name.as_str()) {
            continue;
        }
        if !suite_text.contains(&format!("\nmod {name};\n")) {
            unbuilt.push(name);
        }
    }
    unbuilt.sort();
    unbuilt
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file and a folder module the suite names are built; one it does not
    /// name is reported; the suite itself, a target apart and a data folder are
    /// not modules to name.
    #[test]
    fn finds_the_files_no_module_builds() {
        let dir = std::env::temp_dir().join(format!("drcc-tools-suite-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("folder")).unwrap();
        std::fs::create_dir_all(dir.join("snapshots")).unwrap();
        for file in [
            "suite.rs",
            "named.rs",
            "forgotten.rs",
            "apart.rs",
            "folder/mod.rs",
        ] {
            std::fs::write(dir.join(file), "").unwrap();
        }
        let suite = "//! a suite\n\nmod folder;\nmod named;\n";
        let found = unbuilt_test_files(&dir, suite, &["apart"]);
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(found, ["forgotten"]);
    }
}
