//! Tests of `drcc_hdl::host::ctrl_check`.

use drcc_hdl::host::ctrl_check::*;
use drcc_hdl::host::registers::{ChannelMode, MAP};
use rust_hdl::prelude::*;

mod tests {
    use super::*;
    use drcc_hdl::host::registers::{Mode, SwitchPolicy};

    fn ctrl(fields: &[(&str, u32)]) -> u32 {
        fields
            .iter()
            .fold(0, |w, (n, v)| w | MAP.field("CTRL", n).put(*v))
    }

    /// (k_in, refused, illegal) for `word` against the reset-value fields.
    fn check(reset_mode: bool, word: u32) -> (u64, bool, bool) {
        let mut uut = CtrlCheck::default();
        uut.connect_all();
        let reset = |f: &str| MAP.field("CTRL", f).reset as u64;
        uut.reset_mode.next = reset_mode;
        uut.policy.next = reset("policy").into();
        uut.k.next = reset("k").into();
        uut.wdat.next = (word as u64).into();
        assert!(simulate(&mut uut, 10));
        (
            uut.k_in.val().to_u64(),
            uut.refused.val(),
            uut.illegal.val(),
        )
    }

    #[test]
    fn ctrl_check_synthesizes() {
        let mut uut = CtrlCheck::default();
        uut.connect_all();
        crate::synth_check::yosys_check("ctrl_check", &generate_verilog(&uut));
    }

    /// Contract §9, with the words built from the table and the named codes.
    #[test]
    fn refusals_of_section_9() {
        let ep = SwitchPolicy::ErrorPassive.code();
        let base = [("reset_mode", 1), ("policy", ep), ("k", 1)];
        assert_eq!(check(true, ctrl(&base)), (1, false, false));
        // every policy code is taken (3: the warning-limit policy, §5)
        let w = ctrl(&[
            ("reset_mode", 1),
            ("policy", SwitchPolicy::Warning.code()),
            ("k", 1),
        ]);
        assert_eq!(check(true, w), (1, false, false));
        // outside reset mode a policy change is flagged
        assert!(check(false, w).2);
        // redundancy with a listen-only channel: refused
        let listen = ChannelMode::ListenOnly.code();
        let w = ctrl(&[
            ("redundancy", Mode::Redundancy.code()),
            ("mode_b", listen),
            ("policy", ep),
        ]);
        assert!(check(true, w).2);
        // DMR with a listen-only channel, and DMR with redundancy: refused (DMR §2)
        let w = ctrl(&[("dmr", 1), ("mode_a", listen), ("policy", ep)]);
        assert!(check(true, w).2);
        let w = ctrl(&[
            ("dmr", 1),
            ("redundancy", Mode::Redundancy.code()),
            ("policy", ep),
        ]);
        assert!(check(true, w).2);
        assert!(!check(true, ctrl(&[("dmr", 1), ("policy", ep), ("k", 1)])).2);
        // listen-only in normal mode is legal
        let w = ctrl(&[("mode_b", listen), ("policy", ep)]);
        assert!(!check(true, w).2);
        // k = 0 is stored as 1, not refused
        assert_eq!(check(true, ctrl(&[("policy", ep)])), (1, false, false));
        // outside reset mode: a cfg change is flagged, the same cfg is not
        let w = ctrl(&[("policy", ep), ("k", 1), ("dual_tx", 1)]);
        assert!(check(false, w).2);
        let w = ctrl(&[("policy", ep), ("k", 1), ("star", 1)]);
        assert!(check(false, w).2);
        // star is not refused, in either mode (ignored outside redundancy mode)
        assert_eq!(
            check(true, ctrl(&[("policy", ep), ("k", 1), ("star", 1)])),
            (1, false, false)
        );
        let w = ctrl(&[
            ("redundancy", Mode::Redundancy.code()),
            ("policy", ep),
            ("k", 1),
            ("star", 1),
        ]);
        assert!(!check(true, w).2);
        assert!(!check(false, ctrl(&[("policy", ep), ("k", 1)])).2);
    }
}
