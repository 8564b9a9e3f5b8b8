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
