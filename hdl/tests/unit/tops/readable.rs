//! Tests of `drcc_hdl::tops::readable`.

use drcc_hdl::tops::readable::*;

mod tests {
    use super::*;

    #[test]
    fn shared_names() {
        assert_eq!(
            shared_name(&["drcc__chan_a__bsp", "drcc__chan_b__bsp"]),
            "drcc__chan__bsp"
        );
        assert_eq!(shared_name(&["hub__g__0", "hub__g__1"]), "hub__g");
        assert_eq!(shared_name(&["hub__btl", "hub__ack__u_btl"]), "hub__btl");
    }

    #[test]
    fn words() {
        assert!(contains_word("a = tx_q__clock;", "tx_q__clock"));
        assert!(!contains_word("a = tx_q__clock2;", "tx_q__clock"));
    }
}

/// The readable Verilog is the same logic as rust-hdl's: yosys's equivalence
/// checker proves every output and register of `can_channel` and `rcm` equal
/// (rust-hdl's text, renamed and without `initial` blocks, is the gold; the
/// readable text the gate). The DRCC and hub tops are proven by the lock-step
/// suite, which runs on `rtl-out/`.
mod equivalence {
    use super::super::verilog::{rename_modules, strip_initial_blocks};
    use super::readable;
    use std::process::Command;

    fn prove(name: &str, raw: &str) {
        let gold = strip_initial_blocks(&rename_modules(name, raw));
        let gate = readable(&gold);
        assert!(gate.len() < gold.len(), "{name}: nothing was made readable");
        let dir = std::env::temp_dir().join(format!("drcc-equiv-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (g, r) = (dir.join("gold.v"), dir.join("gate.v"));
        std::fs::write(&g, &gold).unwrap();
        std::fs::write(&r, &gate).unwrap();
        let prep = |file: &std::path::Path, as_name: &str| {
            format!(
                "read_verilog {f}; hierarchy -top {name}; proc; flatten; proc; memory; opt_clean; \
                 rename {name} {as_name}; design -stash {as_name};",
                f = file.display()
            )
        };
        let script = format!(
            "{} {} design -copy-from gold -as gold gold; design -copy-from gate -as gate gate; \
             equiv_make gold gate equiv; hierarchy -top equiv; equiv_simple -seq 2; \
             equiv_induct -seq 2; equiv_status -assert",
            prep(&g, "gold"),
            prep(&r, "gate")
        );
        let out = Command::new("yosys")
            .args(["-q", "-p", &script])
            .output()
            .expect("yosys runs");
        let _ = std::fs::remove_dir_all(&dir);
        assert!(
            out.status.success(),
            "{name}: yosys does not prove the readable Verilog equivalent:\n{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }

    #[test]
    fn readable_verilog_is_equivalent_to_rust_hdls() {
        if !drcc_tools::need(&drcc_tools::YOSYS) {
            return;
        }
        prove(
            "can_channel",
            &super::super::raw_verilog_of::<drcc_hdl::channel::can_channel::CanChannel>(),
        );
        prove(
            "rcm",
            &super::super::raw_verilog_of::<drcc_hdl::redcan::rcm::Rcm>(),
        );
    }
}
