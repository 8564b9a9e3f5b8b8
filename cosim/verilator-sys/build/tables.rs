//! The port tables `shim/<top>_ports.h` (written by `drcc generate` from the
//! rust-hdl blocks) and what the build script makes of them: the list of tops,
//! the per-top C++ shim and the Rust port structs and bindings. Nothing here
//! knows a port by name; a new table is a new top.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

/// One port of a table: `X(c_type, name, width)  /* doc */`.
pub struct Field {
    /// C type of the struct field (`uint8_t` .. `uint64_t`).
    pub c_type: String,
    /// Port name, also the field name on both sides.
    pub name: String,
    /// Port width in bits.
    pub width: u32,
    /// The port's doc (from the block's `///` comment), may be empty.
    pub doc: String,
}

/// The table of one top.
pub struct TopTable {
    /// Module name (`can_channel`): model `V<name>`, RTL `<name>.v`.
    pub name: String,
    /// Inputs except `clk`, in struct order.
    pub inputs: Vec<Field>,
    /// Outputs, in struct order.
    pub outputs: Vec<Field>,
}

impl TopTable {
    /// `CanChannel`: the prefix of the port structs and the wrapper's name.
    pub fn camel(&self) -> String {
        self.name
            .split('_')
            .map(|w| {
                let mut c = w.chars();
                c.next()
                    .map(|f| f.to_ascii_uppercase().to_string() + c.as_str())
                    .unwrap_or_default()
            })
            .collect()
    }
}

/// Every `<name>_ports.h` in `shim_dir`, parsed, sorted by name.
pub fn find_tops(shim_dir: &Path) -> Result<Vec<TopTable>, String> {
    let entries =
        fs::read_dir(shim_dir).map_err(|e| format!("cannot list {}: {e}", shim_dir.display()))?;
    let mut tops = Vec::new();
    for e in entries.flatten() {
        let file = e.file_name().to_string_lossy().into_owned();
        let Some(name) = file.strip_suffix("_ports.h") else {
            continue;
        };
        let text = fs::read_to_string(e.path())
            .map_err(|err| format!("cannot read {}: {err}", e.path().display()))?;
        tops.push(parse(name, &text).map_err(|err| format!("{}: {err}", e.path().display()))?);
    }
    if tops.is_empty() {
        return Err(format!(
            "no <top>_ports.h in {}: run `cargo run -- generate`",
            shim_dir.display()
        ));
    }
    tops.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(tops)
}

/// The `X(...)` lines under `#define DRCC_<NAME>_INPUTS(X)` and `_OUTPUTS(X)`.
pub fn parse(name: &str, text: &str) -> Result<TopTable, String> {
    let upper = name.to_uppercase();
    let inputs_def = format!("#define DRCC_{upper}_INPUTS(X)");
    let outputs_def = format!("#define DRCC_{upper}_OUTPUTS(X)");
    let mut table = TopTable {
        name: name.to_string(),
        inputs: Vec::new(),
        outputs: Vec::new(),
    };
    let mut into: Option<bool> = None; // Some(true): inputs
    for line in text.lines() {
        let t = line.trim();
        if t.starts_with(&inputs_def) {
            into = Some(true);
            continue;
        }
        if t.starts_with(&outputs_def) {
            into = Some(false);
            continue;
        }
        let Some(is_input) = into else { continue };
        let Some(args) = t.strip_prefix("X(") else {
            into = None;
            continue;
        };
        let (args, rest) = args
            .split_once(')')
            .ok_or_else(|| format!("unclosed X( in `{t}`"))?;
        let f: Vec<&str> = args.split(',').map(str::trim).collect();
        let [c_type, port, width] = f[..] else {
            return Err(format!("expected X(c_type, name, width) in `{t}`"));
        };
        let width: u32 = width
            .parse()
            .map_err(|_| format!("bad width `{width}` in `{t}`"))?;
        let doc = rest
            .split_once("/*")
            .and_then(|(_, d)| d.split_once("*/"))
            .map(|(d, _)| d.trim().to_string())
            .unwrap_or_default();
        rust_type(c_type)?;
        let field = Field {
            c_type: c_type.to_string(),
            name: port.to_string(),
            width,
            doc,
        };
        if is_input {
            table.inputs.push(field);
        } else {
            table.outputs.push(field);
        }
        if !t.ends_with('\\') {
            into = None;
        }
    }
    if table.inputs.is_empty() || table.outputs.is_empty() {
        return Err(format!("no {inputs_def} / {outputs_def} table"));
    }
    Ok(table)
}

/// The Rust type mirroring a table's C type.
fn rust_type(c_type: &str) -> Result<&'static str, String> {
    Ok(match c_type {
        "uint8_t" => "u8",
        "uint16_t" => "u16",
        "uint32_t" => "u32",
        "uint64_t" => "u64",
        other => return Err(format!("unsupported port type `{other}`")),
    })
}

/// `<name>_shim.cpp`: the C ABI of one top, all of it in `verilated_top_shim.inc`.
pub fn shim_cpp(t: &TopTable) -> String {
    let (name, upper, camel) = (&t.name, t.name.to_uppercase(), t.camel());
    format!(
        "// {name}_shim.cpp: generated by verilator-sys/build.rs from shim/{name}_ports.h.\n\
         // The C ABI around the Verilated `{name}` top (V{name}); the code is in\n\
         // verilated_top_shim.inc, the port table in {name}_ports.h.\n\
         \n\
         #include <cstddef>\n\
         #include <cstdint>\n\
         #include <type_traits>\n\
         \n\
         #include \"V{name}.h\"\n\
         #include \"{name}_ports.h\"\n\
         #include \"drcc_shim_common.h\"\n\
         \n\
         // build.rs defines DRCC_{upper}_CLK_PREV when it finds the model's \"previous clk\" member.\n\
         #ifdef DRCC_{upper}_CLK_PREV\n\
         #include \"V{name}___024root.h\"\n\
         #define DRCC_SHIM_CLK_PREV DRCC_{upper}_CLK_PREV\n\
         #endif\n\
         \n\
         // build.rs defines DRCC_{upper}_EVAL_STEP when the model's evaluation code is the\n\
         // one drcc::evalStep copies.\n\
         #ifdef DRCC_{upper}_EVAL_STEP\n\
         #include \"V{name}__Syms.h\"\n\
         #define DRCC_SHIM_EVAL_STEP 1\n\
         #define DRCC_SHIM_ROOT V{name}___024root\n\
         #define DRCC_SHIM_SYMS V{name}__Syms\n\
         #define DRCC_SHIM_ROOT_FN(f) V{name}___024root___##f\n\
         #endif\n\
         \n\
         #define DRCC_SHIM_MODEL V{name}\n\
         #define DRCC_SHIM_NAME \"{name}\"\n\
         #define DRCC_SHIM_IN {camel}In\n\
         #define DRCC_SHIM_OUT {camel}Out\n\
         #define DRCC_SHIM_INPUTS DRCC_{upper}_INPUTS\n\
         #define DRCC_SHIM_OUTPUTS DRCC_{upper}_OUTPUTS\n\
         #define DRCC_SHIM_FN(f) drcc_{name}_##f\n\
         \n\
         #include \"verilated_top_shim.inc\"\n"
    )
}

/// The Rust side of every top, `include!`d by `src/lib.rs`: the port structs
/// (`port_struct!`), the layout fingerprint and the wrapper (`verilated_top!`).
pub fn rust_bindings(tops: &[TopTable]) -> String {
    let mut r = String::from("// Generated by verilator-sys/build.rs from shim/*_ports.h.\n");
    for t in tops {
        let (name, camel) = (&t.name, t.camel());
        for (fields, dir, what) in [
            (&t.inputs, "In", "Every input of `{name}` except `clk`. Single-bit ports hold 0 or 1; the shim masks every value to its port width."),
            (&t.outputs, "Out", "Every output of `{name}` right after a rising edge."),
        ] {
            let doc = format!("{} (From `shim/{name}_ports.h`.)", what.replace("{name}", name));
            writeln!(r, "port_struct! {{\n    #[doc = {doc:?}]\n    pub struct {camel}{dir} {{").unwrap();
            for f in fields {
                let ty = rust_type(&f.c_type).expect("checked by parse");
                writeln!(r, "        #[doc = {:?}]\n        {}: {ty} = {},", f.doc, f.name, f.width).unwrap();
            }
            r.push_str("    }\n}\n\n");
        }
        writeln!(
            r,
            "/// The layout fingerprint the C side must report (`drcc_{name}_abi`).\n\
             pub fn {name}_abi() -> u64 {{\n    \
                 let mut h = LayoutHash::new();\n    \
                 {camel}In::layout_hash(&mut h);\n    \
                 {camel}Out::layout_hash(&mut h);\n    \
                 h.0\n\
             }}\n"
        )
        .unwrap();
        let doc = format!("The Verilated `{name}` top (ports: `rtl-out/{name}.v`).");
        let f = |s: &str| format!("drcc_{name}_{s}");
        writeln!(
            r,
            "verilated_top! {{\n    #[doc = {doc:?}]\n    \
             wrapper {camel}, ports {camel}In / {camel}Out, abi {name}_abi, ffi {name}_ffi {{\n        \
             {}, {}, {}, {}, {}, {}, {}, {}, {},\n    }}\n}}\n",
            f("abi"),
            f("new"),
            f("free"),
            f("step"),
            f("fast_edge"),
            f("set_exact"),
            f("trace_open"),
            f("trace_dump"),
            f("trace_close"),
        )
        .unwrap();
    }
    r
}
