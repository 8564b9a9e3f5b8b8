//! Generates the register constants of `drcc-driver` from the C header
//! `rtl-out/drcc_regs.h` (the one generated register table; nothing is copied
//! by hand): every `#define DRCC_<NAME> <value>u` becomes `pub const <NAME>: u32`
//! in `$OUT_DIR/regs.rs`. `DRCC_REGS_H` overrides the header's path.

use std::env;
use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;

fn main() {
    let header = match env::var_os("DRCC_REGS_H") {
        Some(p) => PathBuf::from(p),
        None => PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets it"))
            .join("../../rtl-out/drcc_regs.h"),
    };
    println!("cargo:rerun-if-env-changed=DRCC_REGS_H");
    println!("cargo:rerun-if-changed={}", header.display());
    let text = fs::read_to_string(&header)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", header.display()));
    let mut out = String::new();
    let mut count = 0;
    for line in text.lines() {
        let mut words = line.split_whitespace();
        if words.next() != Some("#define") {
            continue;
        }
        let (Some(name), Some(value)) = (words.next(), words.next()) else {
            continue; // the include guard has no value
        };
        let Some(name) = name.strip_prefix("DRCC_") else {
            continue;
        };
        let digits = value.trim_end_matches(['u', 'U']);
        let parsed = match digits
            .strip_prefix("0x")
            .or_else(|| digits.strip_prefix("0X"))
        {
            Some(hex) => u32::from_str_radix(hex, 16),
            None => digits.parse::<u32>(),
        };
        let value =
            parsed.unwrap_or_else(|_| panic!("{}: cannot parse `{line}`", header.display()));
        writeln!(out, "/// `DRCC_{name}` of `drcc_regs.h`.").unwrap();
        writeln!(out, "pub const {name}: u32 = {value:#010X};").unwrap();
        count += 1;
    }
    assert!(
        count > 100,
        "{}: only {count} definitions",
        header.display()
    );
    let dest = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets it")).join("regs.rs");
    fs::write(&dest, out).expect("write regs.rs");
}
