//! Tests of `drcc_hdl::rmb::switch_policy`.

use drcc_hdl::host::registers::{ErrState, SwitchPolicy};
use drcc_hdl::rmb::switch_policy::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    /// Causes for one input combination (no error warning).
    fn judge(
        policy: SwitchPolicy,
        es: ErrState,
        fail_cnt: u64,
        k: u64,
        stall: u64,
        limit: u64,
    ) -> u64 {
        judge_w(policy, es, false, fail_cnt, k, stall, limit)
    }

    /// Causes for one input combination.
    fn judge_w(
        policy: SwitchPolicy,
        es: ErrState,
        warning: bool,
        fail_cnt: u64,
        k: u64,
        stall: u64,
        limit: u64,
    ) -> u64 {
        let mut uut = FailureJudge::default();
        uut.connect_all();
        uut.err_warning.next = warning;
        uut.policy.next = (policy.code() as u64).into();
        uut.err_state.next = (es.code() as u64).into();
        uut.fail_cnt.next = fail_cnt.into();
        uut.k.next = k.into();
        uut.stall_cnt.next = stall.into();
        uut.stall_limit.next = limit.into();
        assert!(simulate(&mut uut, 10));
        assert_eq!(uut.failed.val(), uut.causes.val().any());
        uut.causes.val().to_u64()
    }

    #[test]
    fn failure_judge_synthesizes() {
        let mut uut = FailureJudge::default();
        uut.connect_all();
        crate::synth_check::yosys_check("failure_judge", &generate_verilog(&uut));
    }

    /// The DRCC paper's policy: switch when the channel is error passive (or
    /// worse); bus-off counts under every policy but none.
    #[test]
    fn error_passive_policy_fails_a_passive_channel() {
        use ErrState::{BusOff, ErrorActive};
        use SwitchPolicy::{KFailed, None};
        const PASSIVE: SwitchPolicy = SwitchPolicy::ErrorPassive;
        const EP: ErrState = ErrState::ErrorPassive;
        assert_eq!(judge(PASSIVE, ErrorActive, 15, 1, 0, 0), 0);
        assert_eq!(judge(PASSIVE, EP, 0, 1, 0, 0), 0b0001);
        assert_eq!(judge(PASSIVE, BusOff, 0, 1, 0, 0), 0b0011);
        assert_eq!(
            judge(None, BusOff, 15, 1, 100, 1),
            0,
            "policy none never fails"
        );
        assert_eq!(
            judge(KFailed, EP, 0, 1, 0, 0),
            0,
            "k-failed ignores passive"
        );
        assert_eq!(judge(KFailed, BusOff, 0, 1, 0, 0), 0b0010);
    }

    #[test]
    fn k_failed_and_stall_causes() {
        use ErrState::ErrorActive;
        use SwitchPolicy::KFailed;
        const PASSIVE: SwitchPolicy = SwitchPolicy::ErrorPassive;
        assert_eq!(judge(KFailed, ErrorActive, 2, 3, 0, 0), 0);
        assert_eq!(judge(KFailed, ErrorActive, 3, 3, 0, 0), 0b0100);
        assert_eq!(
            judge(PASSIVE, ErrorActive, 3, 3, 0, 0),
            0,
            "k only under k-failed"
        );
        assert_eq!(judge(PASSIVE, ErrorActive, 0, 1, 9, 10), 0);
        assert_eq!(judge(PASSIVE, ErrorActive, 0, 1, 10, 10), 0b1000);
        assert_eq!(
            judge(KFailed, ErrorActive, 0, 1, 0xFFFF, 0),
            0,
            "stall limit 0 is off"
        );
    }

    /// §5 policy 3: a channel at or above the warning limit fails (cause [4]);
    /// the other policies ignore the warning; bus-off still counts as bus-off.
    #[test]
    fn warning_policy_fails_a_channel_at_the_warning_limit() {
        use ErrState::{BusOff, ErrorActive, ErrorPassive};
        use SwitchPolicy::{KFailed, Warning};
        const PASSIVE: SwitchPolicy = SwitchPolicy::ErrorPassive;
        assert_eq!(judge_w(Warning, ErrorActive, false, 15, 1, 0, 0), 0);
        assert_eq!(judge_w(Warning, ErrorActive, true, 0, 1, 0, 0), 0b1_0000);
        assert_eq!(
            judge_w(Warning, ErrorPassive, false, 0, 1, 0, 0),
            0,
            "error passive alone is not a cause under the warning policy"
        );
        assert_eq!(judge_w(Warning, BusOff, true, 0, 1, 0, 0), 0b1_0010);
        assert_eq!(judge_w(Warning, ErrorActive, false, 0, 1, 10, 10), 0b0_1000);
        assert_eq!(judge_w(PASSIVE, ErrorActive, true, 0, 1, 0, 0), 0);
        assert_eq!(judge_w(KFailed, ErrorActive, true, 0, 1, 0, 0), 0);
    }
}
