//! The LiteX integration (`integrations/litex/drcc_litex.py`): a LiteX SoC with
//! the DRCC on its main bus elaborates, its Verilog instantiates the core at the
//! region asked for, and Icarus compiles the SoC's top with `rtl-out/drcc.v`
//! (`integrations/litex/elaborate_test.py`, which an integrator can run as is).
//!
//! Without LiteX (or Icarus) the test is skipped with one line, except in CI
//! (`drcc_tools`), where it fails.

use std::path::PathBuf;
use std::process::Command;

#[test]
fn a_litex_soc_with_the_drcc_elaborates() {
    if !drcc_tools::need(&drcc_tools::IVERILOG) {
        return;
    }
    let Some(python) = drcc_tools::python_with(
        &["litex", "migen"],
        "pip install litex migen (.ci/run installs them into target/py-venv)",
    ) else {
        return;
    };
    let script =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("integrations/litex/elaborate_test.py");
    let out_dir = std::env::temp_dir().join(format!("drcc-litex-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out_dir);
    let out = Command::new(python)
        .arg(&script)
        .arg(&out_dir)
        .output()
        .expect("python runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.status.success(),
        "the LiteX elaboration failed:\n{text}"
    );
    assert!(
        text.contains("PASS: LiteX SoC with the DRCC elaborated"),
        "{text}"
    );
    let _ = std::fs::remove_dir_all(&out_dir);
}
