//! Compiles the C driver (`drivers/c/drcc.c`), the small glue the tests call
//! it through (`c/glue.c`) and the example of `drivers/c/README.md` (the first
//! C block after its example marker, extracted verbatim), with the flags the
//! C driver promises to pass: `-std=c99 -Wall -Wextra -Werror -pedantic`,
//! header from `rtl-out/`.

use std::path::{Path, PathBuf};

/// The line of `drivers/c/README.md` that the example's C block follows.
const MARKER: &str = "<!-- example: compiled and run by drivers/rust/tests/readme_example.rs -->";

/// The first fenced C block after [`MARKER`] in `readme`.
fn readme_example(readme: &Path) -> String {
    let text = std::fs::read_to_string(readme)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", readme.display()));
    let after = text
        .split_once(MARKER)
        .unwrap_or_else(|| panic!("{}: no example marker", readme.display()))
        .1;
    let body = after
        .split_once("```c\n")
        .expect("a ```c block after the marker")
        .1;
    let code = body.split_once("```").expect("the block is closed").0;
    code.to_string()
}

fn main() {
    let dir = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let driver = dir.join("../c");
    let rtl = dir.join("../../rtl-out");
    for f in [
        driver.join("drcc.c"),
        driver.join("drcc.h"),
        dir.join("c/glue.c"),
        driver.join("README.md"),
        rtl.join("drcc_regs.h"),
    ] {
        println!("cargo:rerun-if-changed={}", f.display());
    }
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets it"));
    let example = out.join("readme_example.c");
    std::fs::write(&example, readme_example(&driver.join("README.md"))).expect("write example");
    cc::Build::new()
        .file(driver.join("drcc.c"))
        .file(dir.join("c/glue.c"))
        .file(&example)
        .include(&driver)
        .include(&rtl)
        .flag("-std=c99")
        .flag("-pedantic")
        .warnings(true)
        .extra_warnings(true)
        .warnings_into_errors(true)
        .compile("drcc_c_driver");
}
