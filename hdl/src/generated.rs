//! Every file `drcc generate` writes besides the tops' Verilog: register
//! documentation, C headers, the Verilator shim port table of every top. Each
//! generator lives beside what it describes; this list is the one place `drcc generate` (and `--check`) reads, so
//! a new generated file is one entry here.

/// The license of every generated file, as its first line says (SPDX).
pub const SPDX_LICENSE: &str = "Apache-2.0";

/// The SPDX line that opens a generated file at `path`, in its comment syntax
/// (`//` for Verilog and C, an HTML comment for Markdown).
pub fn spdx_line(path: &str) -> String {
    if path.ends_with(".md") {
        format!("<!-- SPDX-License-Identifier: {SPDX_LICENSE} -->\n")
    } else if path.ends_with(".core") {
        format!("# SPDX-License-Identifier: {SPDX_LICENSE}\n")
    } else {
        format!("// SPDX-License-Identifier: {SPDX_LICENSE}\n")
    }
}

/// One generated file.
pub struct GeneratedFile {
    /// Path relative to the repository root (`rtl-out/...`, `docs/...`).
    pub path: String,
    /// Its full text.
    pub text: String,
}

/// The generated files other than `rtl-out/<top>.v`, in the order they are written.
pub fn extras() -> Vec<GeneratedFile> {
    let mut files = vec![
        GeneratedFile {
            path: "rtl-out/drcc_regs.h".into(),
            text: crate::host::registers::c_header(),
        },
        GeneratedFile {
            path: "docs/registers.md".into(),
            text: crate::host::registers::markdown(),
        },
        GeneratedFile {
            path: "rtl-out/hub_regs.h".into(),
            text: crate::host::hub_registers::c_header(),
        },
        GeneratedFile {
            path: "docs/hub_registers.md".into(),
            text: crate::host::hub_registers::markdown(),
        },
    ];
    // verilator-sys's build script finds the tops by these tables (one per top).
    files.extend(crate::tops::TOPS.iter().map(|t| GeneratedFile {
        path: crate::tops::shim_table::path_of(t.name).into(),
        text: t.shim_table(),
    }));
    // FuseSoC: a core file and a smoke testbench per top, and the lint waivers
    // the core's lint target reads.
    for t in crate::tops::TOPS {
        files.push(GeneratedFile {
            path: format!("rtl-out/{}.core", t.name),
            text: crate::tops::fusesoc::core_file(t),
        });
        files.push(GeneratedFile {
            path: format!("rtl-out/tb/{}_tb.v", t.name),
            text: crate::tops::fusesoc::smoke_tb(t),
        });
    }
    files.push(GeneratedFile {
        path: "rtl-out/verilator_waivers.vlt".into(),
        text: include_str!("../lint/verilator_waivers.vlt").to_string(),
    });
    // The SPDX line opens every file but the core files, whose first line must
    // be `CAPI=2:` (they carry it on their second).
    for f in files.iter_mut().filter(|f| !f.path.ends_with(".core")) {
        f.text.insert_str(0, &spdx_line(&f.path));
    }
    files
}
