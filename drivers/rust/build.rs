//! Generates the register constants of `drcc-driver` from the C header
//! `rtl-out/drcc_regs.h` (the one generated register table; nothing is copied
//! by hand): every `#define DRCC_<NAME> <value>u` becomes `pub const <NAME>: u32`
//! in `$OUT_DIR/regs.rs`. `DRCC_REGS_H` overrides the header's path.
//!
//! [`PENDING`] lists fields of the contract the header may not carry yet
//! (written from `cosim/src/model/drcc_contract.md`); each is emitted only
//! when the header lacks it, so the header's own definition always wins.

use std::env;
use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;

/// Contract §11.6 (map 1.3): `CTRL[18]` `busoff_manual`, `TX_CMD[3]`
/// `recover_a`, `TX_CMD[4]` `recover_b`, for a header generated before them.
const PENDING: &[(&str, u32)] = &[
    ("CTRL_BUSOFF_MANUAL_SHIFT", 18),
    ("CTRL_BUSOFF_MANUAL_MASK", 1 << 18),
    ("TX_CMD_RECOVER_A_SHIFT", 3),
    ("TX_CMD_RECOVER_A_MASK", 1 << 3),
    ("TX_CMD_RECOVER_B_SHIFT", 4),
    ("TX_CMD_RECOVER_B_MASK", 1 << 4),
];

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
    let mut names = Vec::new();
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
        names.push(name.to_string());
        count += 1;
    }
    for (name, value) in PENDING {
        if !names.iter().any(|n| n == name) {
            writeln!(
                out,
                "/// `DRCC_{name}` of the contract (not yet in `drcc_regs.h`)."
            )
            .unwrap();
            writeln!(out, "pub const {name}: u32 = {value:#010X};").unwrap();
        }
    }
    assert!(
        count > 100,
        "{}: only {count} definitions",
        header.display()
    );
    let dest = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets it")).join("regs.rs");
    fs::write(&dest, out).expect("write regs.rs");
}
