//! Compiles the C driver (`drivers/c/drcc.c`) and the small glue the tests call
//! it through (`c/glue.c`), with the flags the C driver promises to pass:
//! `-std=c99 -Wall -Wextra -Werror -pedantic`, header from `rtl-out/`.

use std::path::PathBuf;

fn main() {
    let dir = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"));
    let driver = dir.join("../c");
    let rtl = dir.join("../../rtl-out");
    for f in [
        driver.join("drcc.c"),
        driver.join("drcc.h"),
        dir.join("c/glue.c"),
        rtl.join("drcc_regs.h"),
    ] {
        println!("cargo:rerun-if-changed={}", f.display());
    }
    cc::Build::new()
        .file(driver.join("drcc.c"))
        .file(dir.join("c/glue.c"))
        .include(&driver)
        .include(&rtl)
        .flag("-std=c99")
        .flag("-pedantic")
        .warnings(true)
        .extra_warnings(true)
        .warnings_into_errors(true)
        .compile("drcc_c_driver");
}
