//! Every file `drcc generate` writes besides the tops' Verilog: register
//! documentation, C headers, the Verilator shim port table of every top. Each
//! generator lives beside what it describes; this list is the one place `drcc generate` (and `--check`) reads, so
//! a new generated file is one entry here.

/// One generated file.
pub struct GeneratedFile {
    /// Path relative to the repository root (`rtl-out/...`, `docs/...`).
    pub path: &'static str,
    /// Its full text.
    pub text: String,
}

/// The generated files other than `rtl-out/<top>.v`, in the order they are written.
pub fn extras() -> Vec<GeneratedFile> {
    let mut files = vec![
        GeneratedFile {
            path: "rtl-out/drcc_regs.h",
            text: crate::host::registers::c_header(),
        },
        GeneratedFile {
            path: "docs/registers.md",
            text: crate::host::registers::markdown(),
        },
        GeneratedFile {
            path: "rtl-out/hub_regs.h",
            text: crate::host::hub_registers::c_header(),
        },
        GeneratedFile {
            path: "docs/hub_registers.md",
            text: crate::host::hub_registers::markdown(),
        },
    ];
    // verilator-sys's build script finds the tops by these tables (one per top).
    files.extend(crate::tops::TOPS.iter().map(|t| GeneratedFile {
        path: crate::tops::shim_table::path_of(t.name),
        text: t.shim_table(),
    }));
    files
}
