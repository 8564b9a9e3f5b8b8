//! Auxiliary FSM of one channel ("channel validity", DRCC contract §5; the
//! paper's auxiliary FSMs of section III). States (`aux_state[1:0]`): valid 0,
//! failed 1, restart 2, probation 3.
//!
//! - valid -> failed when a cause of the switch policy holds
//!   (`super::switch_policy`: error passive, bus-off, k failed attempts, stall,
//!   warning limit);
//!   the cause bits are latched, `failures` counts.
//! - failed -> restart when the channel is idle, not bus-off, not in use by
//!   the main FSM and `restart_ok` (at bus idle, and B only while A is valid:
//!   the other channel receives while this one re-integrates).
//! - restart -> probation after one clock, during which the channel is reset
//!   (`chan_rst`: it re-integrates with the bus as after power-up).
//! - probation -> valid after `recovery_bits` error-free sample points.
//!
//! Timing (iCE40 Fmax): the contract's `probe_cnt >= recovery_bits` (0 treated
//! as 1) is implemented as a down counter `left_q` = `rb_eff - probe_cnt` with a
//! registered `left_q == 0` flag (`done_q`), so no 16-bit compare against the
//! configuration sits in front of the recovery event and the STATS1 counter.
//! Identical at every clock: `recovery_bits` is cfg (writable only in reset
//! mode, when `hold` keeps this FSM in valid), so it is constant from `restart`
//! to the end of probation; there `probe_cnt` starts at 0, grows by at most 1
//! per clock and the FSM leaves as soon as it reaches `rb_eff` >= 1, so
//! `probe_cnt <= rb_eff` and `probe_cnt >= rb_eff` <=> `left_q == 0`.
//!
//! While `hold` (normal or reset mode) it sits in valid with the working counters
//! and cause bits cleared; `failures` and `recoveries` clear with `rst` only (the top ORs in `STATS_CLR`,
//! DRCC contract §11.4).

use super::switch_policy::FailureJudge;
use crate::host::registers::{AuxState, ErrState};
use rust_hdl::prelude::*;

/// Auxiliary FSM of one channel.
#[derive(LogicBlock)]
pub struct AuxFsm {
    // clock, reset, hold (rst, normal or reset mode)
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset (the top ORs in `STATS_CLR`): clears the `failures` and `recoveries`
    /// counts.
    pub rst: Signal<In, Bit>,
    /// Normal or reset mode: the FSM sits in valid with its working counters and cause bits
    /// cleared.
    pub hold: Signal<In, Bit>,
    // configuration
    /// `CTRL.policy`: the switch policy code (`SwitchPolicy`: which causes fail the channel,
    /// contract §5).
    pub policy: Signal<In, Bits<2>>,
    /// `CTRL.k`: failed attempts that fail the channel under the k-failed policy.
    pub k: Signal<In, Bits<4>>,
    /// `RMB_CFG.stall_limit`: bit times a message may stay pending before the channel is judged
    /// failed (0 = off).
    pub stall_limit: Signal<In, Bits<16>>,
    /// `RMB_CFG.recovery_bits`: error-free sample points in probation before the channel is valid
    /// again (0 counts as 1).
    pub recovery_bits: Signal<In, Bits<16>>,
    // bit tick and main FSM
    /// Nominal bit tick: the stall count advances at it while a message is pending.
    pub tick: Signal<In, Bit>,
    /// The main FSM uses this channel (its `in_use_a` / `in_use_b`): a failed channel is not
    /// restarted.
    pub in_use: Signal<In, Bit>,
    /// A restart cannot cost a frame: the channel at bus idle, and for B, A valid.
    pub restart_ok: Signal<In, Bit>,
    // channel
    /// The channel's `err_valid` pulse: an error was detected (with `err_tx` a failed attempt; it
    /// restarts probation).
    pub err_valid: Signal<In, Bit>,
    /// The channel's `err_tx`: the node was transmitter at that error.
    pub err_tx: Signal<In, Bit>,
    /// The channel's `tx_done` pulse: a frame was sent, the failed-attempt count clears.
    pub tx_done: Signal<In, Bit>,
    /// The channel's `tx_pending`: the stall count runs while it is set; a failed channel restarts
    /// only without it.
    pub tx_pending: Signal<In, Bit>,
    /// A frame received without error: the line works (clears the stall count).
    pub rx_valid: Signal<In, Bit>,
    /// The channel's fault confinement state (`ErrState`: 0 error active, 1 error passive, 2
    /// bus-off).
    pub err_state: Signal<In, Bits<2>>,
    /// The channel's `err_warning` (TEC or REC at or above `ewl`): the cause of
    /// the warning policy.
    pub err_warning: Signal<In, Bit>,
    /// The channel's `sample_point` pulse: probation counts these.
    pub sample_point: Signal<In, Bit>,
    // outputs
    /// FSM state `aux_state[1:0]` (`AUX_x.state`): valid 0, failed 1, restart 2, probation 3.
    pub aux_state: Signal<Out, Bits<2>>,
    /// The channel is valid (state valid): the main FSM's `VA` / `VB`.
    pub valid: Signal<Out, Bit>,
    /// State restart: the channel is reset for this clock and re-integrates with the bus.
    pub chan_rst: Signal<Out, Bit>,
    /// Latched failure causes `AUX_x[6:2]`: [0] error passive, [1] bus-off, [2] k failed, [3]
    /// stall, [4] warning.
    pub causes: Signal<Out, Bits<5>>,
    /// `AUX_x.fail_cnt`: failed attempts since the last success (saturating at 15).
    pub fail_cnt: Signal<Out, Bits<4>>,
    /// `AUX_x.failures`: times the channel was judged failed (saturating).
    pub failures: Signal<Out, Bits<8>>,
    /// `AUX_x.recoveries`: times the channel became valid again after probation (saturating).
    pub recoveries: Signal<Out, Bits<8>>,
    /// Valid -> failed at this edge (`INT_STATUS.aux`; combinational).
    pub fail_evt: Signal<Out, Bit>,
    /// Probation -> valid at this edge (`INT_STATUS.aux`, `STATS1.recoveries`; combinational).
    pub recover_evt: Signal<Out, Bit>,
    // registers
    st: DFF<Bits<2>>,
    fail_q: DFF<Bits<4>>,
    stall_q: DFF<Bits<16>>,
    left_q: DFF<Bits<16>>,
    done_q: DFF<Bit>,
    causes_q: DFF<Bits<5>>,
    failures_q: DFF<Bits<8>>,
    recoveries_q: DFF<Bits<8>>,
    // judgement
    judge: FailureJudge,
    now_causes: Signal<Local, Bits<5>>,
    rb_eff: Signal<Local, Bits<16>>,
    // constants
    s_valid: Constant<Bits<2>>,
    s_failed: Constant<Bits<2>>,
    s_restart: Constant<Bits<2>>,
    s_probation: Constant<Bits<2>>,
    es_busoff: Constant<Bits<2>>,
    one4: Constant<Bits<4>>,
    zero4: Constant<Bits<4>>,
    zero5: Constant<Bits<5>>,
    max4: Constant<Bits<4>>,
    one8: Constant<Bits<8>>,
    zero8: Constant<Bits<8>>,
    max8: Constant<Bits<8>>,
    one16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
}

impl Default for AuxFsm {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            hold: Default::default(),
            policy: Default::default(),
            k: Default::default(),
            stall_limit: Default::default(),
            recovery_bits: Default::default(),
            tick: Default::default(),
            in_use: Default::default(),
            restart_ok: Default::default(),
            err_valid: Default::default(),
            err_tx: Default::default(),
            tx_done: Default::default(),
            tx_pending: Default::default(),
            rx_valid: Default::default(),
            err_state: Default::default(),
            err_warning: Default::default(),
            sample_point: Default::default(),
            aux_state: Default::default(),
            valid: Default::default(),
            chan_rst: Default::default(),
            causes: Default::default(),
            fail_cnt: Default::default(),
            failures: Default::default(),
            recoveries: Default::default(),
            fail_evt: Default::default(),
            recover_evt: Default::default(),
            st: Default::default(),
            fail_q: Default::default(),
            stall_q: Default::default(),
            left_q: Default::default(),
            done_q: Default::default(),
            causes_q: Default::default(),
            failures_q: Default::default(),
            recoveries_q: Default::default(),
            judge: Default::default(),
            now_causes: Default::default(),
            rb_eff: Default::default(),
            s_valid: Constant::new((AuxState::Valid.code() as u64).into()),
            s_failed: Constant::new((AuxState::Failed.code() as u64).into()),
            s_restart: Constant::new((AuxState::Restart.code() as u64).into()),
            s_probation: Constant::new((AuxState::Probation.code() as u64).into()),
            es_busoff: Constant::new((ErrState::BusOff.code() as u64).into()),
            one4: Constant::new(1.into()),
            zero4: Constant::new(0.into()),
            zero5: Constant::new(0.into()),
            max4: Constant::new(15.into()),
            one8: Constant::new(1.into()),
            zero8: Constant::new(0.into()),
            max8: Constant::new(255.into()),
            one16: Constant::new(1.into()),
            zero16: Constant::new(0.into()),
            max16: Constant::new(0xFFFF.into()),
        }
    }
}

impl Logic for AuxFsm {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            st,
            fail_q,
            stall_q,
            left_q,
            done_q,
            causes_q,
            failures_q,
            recoveries_q
        );
        self.st.d.next = self.st.q.val();
        self.left_q.d.next = self.left_q.q.val();
        self.done_q.d.next = self.done_q.q.val();
        self.causes_q.d.next = self.causes_q.q.val();
        self.failures_q.d.next = self.failures_q.q.val();
        self.recoveries_q.d.next = self.recoveries_q.q.val();
        self.fail_evt.next = false;
        self.recover_evt.next = false;

        // fail_cnt: +1 per failed attempt (saturating), 0 at tx_done
        self.fail_q.d.next = self.fail_q.q.val();
        if self.err_valid.val() & self.err_tx.val() & (self.fail_q.q.val() != self.max4.val()) {
            self.fail_q.d.next = self.fail_q.q.val() + self.one4.val();
        }
        if self.tx_done.val() {
            self.fail_q.d.next = self.zero4.val();
        }
        // stall_cnt: ticks while pending (saturating), 0 while not pending and at
        // each frame received (the line carries frames: losing arbitration on it
        // is not a stall, contract §5)
        self.stall_q.d.next = self.stall_q.q.val();
        if self.tick.val() & (self.stall_q.q.val() != self.max16.val()) {
            self.stall_q.d.next = self.stall_q.q.val() + self.one16.val();
        }
        if !self.tx_pending.val() | self.rx_valid.val() {
            self.stall_q.d.next = self.zero16.val();
        }

        // failure causes under the switch policy, on registered values
        self.judge.policy.next = self.policy.val();
        self.judge.k.next = self.k.val();
        self.judge.stall_limit.next = self.stall_limit.val();
        self.judge.err_state.next = self.err_state.val();
        self.judge.fail_cnt.next = self.fail_q.q.val();
        self.judge.stall_cnt.next = self.stall_q.q.val();
        self.judge.err_warning.next = self.err_warning.val();
        self.now_causes.next = self.judge.causes.val();
        if self.recovery_bits.val() == self.zero16.val() {
            self.rb_eff.next = self.one16.val();
        } else {
            self.rb_eff.next = self.recovery_bits.val();
        }

        if self.st.q.val() == self.s_valid.val() {
            if self.judge.failed.val() {
                self.st.d.next = self.s_failed.val();
                self.causes_q.d.next = self.causes_q.q.val() | self.now_causes.val();
                if self.failures_q.q.val() != self.max8.val() {
                    self.failures_q.d.next = self.failures_q.q.val() + self.one8.val();
                }
                self.fail_evt.next = true;
            }
        } else if self.st.q.val() == self.s_failed.val() {
            // a bus-off channel recovers by itself first (ISO 11898-1 12.1.4.2)
            if !self.tx_pending.val()
                & !self.in_use.val()
                & self.restart_ok.val()
                & (self.err_state.val() != self.es_busoff.val())
            {
                self.st.d.next = self.s_restart.val();
                self.fail_q.d.next = self.zero4.val();
            }
        } else if self.st.q.val() == self.s_restart.val() {
            self.st.d.next = self.s_probation.val();
            // probe_cnt <= 0 (see the module doc: left = rb_eff - probe_cnt)
            self.left_q.d.next = self.rb_eff.val();
            self.done_q.d.next = false;
        } else {
            // probation
            if self.err_valid.val() {
                self.left_q.d.next = self.rb_eff.val();
                self.done_q.d.next = false;
            } else if self.sample_point.val() {
                // timing: the flag is precomputed one clock ahead
                self.left_q.d.next = self.left_q.q.val() - self.one16.val();
                self.done_q.d.next = self.left_q.q.val() == self.one16.val();
            }
            // probe_cnt >= rb_eff (registered: off the critical path)
            if self.done_q.q.val() {
                self.st.d.next = self.s_valid.val();
                if self.recoveries_q.q.val() != self.max8.val() {
                    self.recoveries_q.d.next = self.recoveries_q.q.val() + self.one8.val();
                }
                self.recover_evt.next = true;
            }
        }

        if self.hold.val() {
            self.st.d.next = self.s_valid.val();
            self.fail_q.d.next = self.zero4.val();
            self.stall_q.d.next = self.zero16.val();
            self.left_q.d.next = self.rb_eff.val();
            self.done_q.d.next = false;
            self.causes_q.d.next = self.zero5.val();
            // held, the FSM judges nothing: no failure or recovery is counted
            // (contract §5; found by reading AUX_* in the bus tops' lock step)
            self.failures_q.d.next = self.failures_q.q.val();
            self.recoveries_q.d.next = self.recoveries_q.q.val();
            self.fail_evt.next = false;
            self.recover_evt.next = false;
        }
        if self.rst.val() {
            self.failures_q.d.next = self.zero8.val();
            self.recoveries_q.d.next = self.zero8.val();
        }

        self.aux_state.next = self.st.q.val();
        self.valid.next = self.st.q.val() == self.s_valid.val();
        self.chan_rst.next = self.st.q.val() == self.s_restart.val();
        self.causes.next = self.causes_q.q.val();
        self.fail_cnt.next = self.fail_q.q.val();
        self.failures.next = self.failures_q.q.val();
        self.recoveries.next = self.recoveries_q.q.val();
    }
}
