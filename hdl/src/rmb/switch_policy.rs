//! The switch policy of the DRCC (DRCC paper section III, contract §5): when an
//! auxiliary FSM judges its channel failed, so that the main FSM switches to the
//! other channel. Combinational, on registered values; one cause per bit, in the
//! order of `AUX_x[6:2]`:
//!
//! - error passive: policy [`SwitchPolicy::ErrorPassive`] (the paper's) and the
//!   channel is not error active (ISO 11898-1 12.1.4: error passive or bus-off);
//! - bus-off: any policy but [`SwitchPolicy::None`], the channel is bus-off;
//! - k failed: policy [`SwitchPolicy::KFailed`] and at least `k` failed attempts
//!   since the last success;
//! - stall: any policy but none, a stall limit set and a message pending for at
//!   least `stall_limit` bit times;
//! - warning: policy [`SwitchPolicy::Warning`] and the channel's `err_warning`
//!   (TEC or REC at or above `BTR.ewl`; bus-off counts by the bus-off cause).

use crate::host::registers::{ErrState, SwitchPolicy};
use rust_hdl::prelude::*;

/// Failure causes of one channel under the configured switch policy.
#[derive(LogicBlock)]
pub struct FailureJudge {
    // ---- configuration (CTRL, RMB_CFG) ----
    /// [`SwitchPolicy`] code (`CTRL.policy`).
    pub policy: Signal<In, Bits<2>>,
    /// Failed attempts that fail the channel under k-failed (`CTRL.k`).
    pub k: Signal<In, Bits<4>>,
    /// Bit times a message may stay pending (`RMB_CFG.stall_limit`, 0 = off).
    pub stall_limit: Signal<In, Bits<16>>,
    // ---- channel state (registered) ----
    /// [`ErrState`] code of the channel.
    pub err_state: Signal<In, Bits<2>>,
    /// Failed attempts since the last success (saturating).
    pub fail_cnt: Signal<In, Bits<4>>,
    /// Bit times the current message has been pending (saturating).
    pub stall_cnt: Signal<In, Bits<16>>,
    /// The channel's `err_warning`: TEC or REC at or above the warning limit.
    pub err_warning: Signal<In, Bit>,
    // ---- judgement ----
    /// Causes that hold: [0] error passive, [1] bus-off, [2] k failed, [3] stall,
    /// [4] warning.
    pub causes: Signal<Out, Bits<5>>,
    /// Some cause holds: the channel is judged failed.
    pub failed: Signal<Out, Bit>,
    // ---- internals ----
    c_passive: Signal<Local, Bit>,
    c_busoff: Signal<Local, Bit>,
    c_kfail: Signal<Local, Bit>,
    c_stall: Signal<Local, Bit>,
    c_warn: Signal<Local, Bit>,
    p_none: Constant<Bits<2>>,
    p_passive: Constant<Bits<2>>,
    p_kfail: Constant<Bits<2>>,
    p_warning: Constant<Bits<2>>,
    es_active: Constant<Bits<2>>,
    es_busoff: Constant<Bits<2>>,
    zero5: Constant<Bits<5>>,
    zero16: Constant<Bits<16>>,
}

fn code(value: u32) -> Constant<Bits<2>> {
    Constant::new((value as u64).into())
}

impl Default for FailureJudge {
    fn default() -> Self {
        Self {
            policy: Default::default(),
            k: Default::default(),
            stall_limit: Default::default(),
            err_state: Default::default(),
            fail_cnt: Default::default(),
            stall_cnt: Default::default(),
            err_warning: Default::default(),
            causes: Default::default(),
            failed: Default::default(),
            c_passive: Default::default(),
            c_busoff: Default::default(),
            c_kfail: Default::default(),
            c_stall: Default::default(),
            c_warn: Default::default(),
            p_none: code(SwitchPolicy::None.code()),
            p_passive: code(SwitchPolicy::ErrorPassive.code()),
            p_kfail: code(SwitchPolicy::KFailed.code()),
            p_warning: code(SwitchPolicy::Warning.code()),
            es_active: code(ErrState::ErrorActive.code()),
            es_busoff: code(ErrState::BusOff.code()),
            zero5: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
        }
    }
}

impl Logic for FailureJudge {
    #[hdl_gen]
    fn update(&mut self) {
        self.c_passive.next = (self.policy.val() == self.p_passive.val())
            & (self.err_state.val() != self.es_active.val());
        self.c_busoff.next = (self.policy.val() != self.p_none.val())
            & (self.err_state.val() == self.es_busoff.val());
        self.c_kfail.next =
            (self.policy.val() == self.p_kfail.val()) & (self.fail_cnt.val() >= self.k.val());
        self.c_stall.next = (self.policy.val() != self.p_none.val())
            & (self.stall_limit.val() != self.zero16.val())
            & (self.stall_cnt.val() >= self.stall_limit.val());
        self.c_warn.next = (self.policy.val() == self.p_warning.val()) & self.err_warning.val();
        self.causes.next = bit_cast::<5, 1>(self.c_passive.val().into())
            | (bit_cast::<5, 1>(self.c_busoff.val().into()) << 1)
            | (bit_cast::<5, 1>(self.c_kfail.val().into()) << 2)
            | (bit_cast::<5, 1>(self.c_stall.val().into()) << 3)
            | (bit_cast::<5, 1>(self.c_warn.val().into()) << 4);
        self.failed.next = self.causes.val() != self.zero5.val();
    }
}

#[cfg(test)]
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
