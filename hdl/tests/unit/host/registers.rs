//! Tests of `drcc_hdl::host::registers`.

pub use drcc_hdl::host::codes::{ChannelMode, Mode, StarLast, SwitchPolicy};
use drcc_hdl::host::registers::*;

mod tests {
    use super::*;

    #[test]
    fn table_is_consistent() {
        MAP.check().unwrap();
        for (i, r) in REGISTERS.iter().enumerate() {
            assert_eq!(r.index as usize, i, "{} is out of order", r.name);
        }
        // reset values from the contract (§3)
        assert_eq!(register("CTRL").unwrap().reset_value(), 0x0000_0105);
        assert_eq!(register("BTR").unwrap().reset_value(), 0x0060_0500);
        let h = c_header();
        assert!(h.contains("#define DRCC_BTR_EWL_MASK 0x00FF0000u"));
        assert!(h.contains("#define DRCC_CTRL_POLICY_ERROR_PASSIVE 1u"));
        assert!(h.contains("#define DRCC_STATE_WAIT4 9u"));
        assert!(markdown().contains("| 24 | 0x60 | [`TIMES`]"));
        assert!(markdown().contains("| 36 | 0x90 | [`STAR_STATUS`]"));
        assert!(markdown().contains("| 37 | 0x94 | [`OMISSIONS`]"));
        assert!(h.contains("#define DRCC_CTRL_POLICY_WARNING 3u"));
    }

    #[test]
    fn codes_are_the_contracts() {
        // contract §3: policy 0 none, 1 error-passive, 2 k-failed, 3 warning; §C.7
        // modes
        assert_eq!(SwitchPolicy::ErrorPassive.code(), 1);
        assert_eq!(SwitchPolicy::KFailed.code(), 2);
        assert_eq!(SwitchPolicy::Warning.code(), 3);
        assert_eq!(StarLast::HubB.code(), 2);
        assert_eq!(ChannelMode::ListenOnly.code(), 1);
        assert_eq!(ChannelMode::Loopback.code(), 3);
        assert_eq!(Mode::Redundancy.code(), 1);
        assert!(markdown().contains("1 `ERROR_PASSIVE`"));
    }
}
