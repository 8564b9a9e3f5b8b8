//! The DRCC's `CTRL` register (DRCC contract §3, §9): the storage of reset
//! mode, the operating mode ([`Mode`], and `dmr`), the switch policy, `dual_tx`,
//! `star`, `k`, the channel modes ([`ChannelMode`]), `single_shot`, `busoff_manual` and `first_copy`. The refusals of §9 are
//! decided by [`CtrlCheck`] (combinational, beside it in the register block, so
//! that no always block both takes the write and flags it):
//!
//! - in reset mode (before the write) the whole word is taken, except that a
//!   write with the illegal policy code, or with redundancy and a listen-only
//!   channel, is refused as a whole (`illegal`); `k = 0` is stored as 1;
//! - outside reset mode only `reset_mode` is taken; a write whose cfg fields
//!   differ from the stored ones sets `illegal`;
//! - a configuration without the DMR function or the replicated-star node
//!   (drcc_contract.md §1.1) stores `dmr` / `star` as a constant 0 (its writes
//!   are refused by [`CtrlCheck`]), so synthesis removes what only those modes use.
//!
//! Field positions and reset values come from the table (`super::registers`).

#[cfg(doc)]
use super::ctrl_check::CtrlCheck;
use super::map::lsb;
#[cfg(doc)]
use super::registers::ChannelMode;
use super::registers::{Mode, MAP};
use crate::channel::sized::Param;
use rust_hdl::prelude::*;

/// `CTRL`.
#[derive(LogicBlock)]
pub struct CtrlReg {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: the table's reset value (reset mode).
    pub rst: Signal<In, Bit>,
    // ---- write (from the register decoder) ----
    /// A write to `CTRL` is taken at this edge.
    pub we: Signal<In, Bit>,
    /// The written word.
    pub wdat: Signal<In, Bits<32>>,
    /// [`CtrlCheck::refused`]: in reset mode the write is not taken.
    pub refused: Signal<In, Bit>,
    /// [`CtrlCheck::k_in`]: the `k` to store.
    pub k_in: Signal<In, Bits<4>>,
    /// The register's value, for reads (a host view's word while `view_on`).
    pub word: Signal<Out, Bits<32>>,
    // ---- host view (PeliCAN contract §14; 0 in the native top) ----
    /// 1 = the fields below are `view_word`'s, not the stored ones (which keep
    /// their values); `reset_mode_d` follows the `reset_mode` in force.
    pub view_on: Signal<In, Bit>,
    /// The `CTRL` word a host view composes (P-CFG-3).
    pub view_word: Signal<In, Bits<32>>,
    // ---- fields ----
    /// `reset_mode`: channels held in reset, queues and FIFO emptied.
    pub reset_mode: Signal<Out, Bit>,
    /// `reset_mode` one edge earlier (1 after `rst`): the channels stay in reset
    /// one clock after reset mode (contract §6).
    pub reset_mode_d: Signal<Out, Bit>,
    /// [`Mode`]: 1 = redundancy mode.
    pub redundancy: Signal<Out, Bit>,
    /// `SwitchPolicy` code.
    pub policy: Signal<Out, Bits<2>>,
    /// Redundancy mode: every message on A, then its copy on B.
    pub dual_tx: Signal<Out, Bit>,
    /// Redundancy mode: replicated star node, the other channel's echo of an own
    /// frame completes it (contract §4.4; stored as written, ignored in the other
    /// modes).
    pub star: Signal<Out, Bit>,
    /// Failed attempts of the k-failed policy (1..15).
    pub k: Signal<Out, Bits<4>>,
    /// [`ChannelMode`] code of channel A.
    pub mode_a: Signal<Out, Bits<2>>,
    /// [`ChannelMode`] code of channel B.
    pub mode_b: Signal<Out, Bits<2>>,
    /// No automatic retransmission (normal mode).
    pub single_shot: Signal<Out, Bit>,
    /// CiA 701 DMR mode (DMR contract §2).
    pub dmr: Signal<Out, Bit>,
    /// A bus-off channel waits for the host's `recover` (contract §11.6).
    pub busoff_manual: Signal<Out, Bit>,
    /// DMR first-copy delivery (DMR contract §8.1); 0 without the DMR function.
    pub first_copy: Signal<Out, Bit>,
    // ---- state ----
    reset_mode_q: DFF<Bit>,
    reset_mode_dq: DFF<Bit>,
    redundancy_q: DFF<Bit>,
    policy_q: DFF<Bits<2>>,
    dual_tx_q: DFF<Bit>,
    star_q: DFF<Bit>,
    k_q: DFF<Bits<4>>,
    mode_a_q: DFF<Bits<2>>,
    mode_b_q: DFF<Bits<2>>,
    single_shot_q: DFF<Bit>,
    dmr_q: DFF<Bit>,
    busoff_manual_q: DFF<Bit>,
    first_copy_q: DFF<Bit>,
    /// The stored word, and the word in force (stored or the view's).
    stored: Signal<Local, Bits<32>>,
    cur: Signal<Local, Bits<32>>,
    // ---- field positions (from the table) ----
    p_reset_mode: Constant<Bits<5>>,
    p_redundancy: Constant<Bits<5>>,
    p_policy: Constant<Bits<5>>,
    p_dual_tx: Constant<Bits<5>>,
    p_star: Constant<Bits<5>>,
    p_k: Constant<Bits<5>>,
    p_mode_a: Constant<Bits<5>>,
    p_mode_b: Constant<Bits<5>>,
    p_single_shot: Constant<Bits<5>>,
    p_dmr: Constant<Bits<5>>,
    p_busoff_manual: Constant<Bits<5>>,
    p_first_copy: Constant<Bits<5>>,
    // ---- codes and reset values ----
    redundancy_reset: Constant<Bit>,
    policy_reset: Constant<Bits<2>>,
    k_reset: Constant<Bits<4>>,
    mode_reset: Constant<Bits<2>>,
    /// The configuration has the CiA 701 DMR function (generation parameter).
    pub(crate) dmr_present: Param<1, 1>,
    /// The configuration has the replicated-star node (generation parameter).
    pub(crate) star_present: Param<1, 1>,
}

impl Default for CtrlReg {
    fn default() -> Self {
        let reset = |field: &str| MAP.field("CTRL", field).reset as u64;
        assert_eq!(reset("reset_mode"), 1, "CTRL resets into reset mode (§3)");
        assert_eq!(
            reset("dual_tx")
                + reset("star")
                + reset("single_shot")
                + reset("dmr")
                + reset("busoff_manual")
                + reset("first_copy"),
            0
        );
        assert_eq!(reset("mode_a"), reset("mode_b"));
        Self {
            clk: Default::default(),
            rst: Default::default(),
            we: Default::default(),
            wdat: Default::default(),
            refused: Default::default(),
            k_in: Default::default(),
            word: Default::default(),
            view_on: Default::default(),
            view_word: Default::default(),
            stored: Default::default(),
            cur: Default::default(),
            reset_mode: Default::default(),
            reset_mode_d: Default::default(),
            redundancy: Default::default(),
            policy: Default::default(),
            dual_tx: Default::default(),
            star: Default::default(),
            k: Default::default(),
            mode_a: Default::default(),
            mode_b: Default::default(),
            single_shot: Default::default(),
            dmr: Default::default(),
            busoff_manual: Default::default(),
            first_copy: Default::default(),
            reset_mode_q: Default::default(),
            reset_mode_dq: Default::default(),
            redundancy_q: Default::default(),
            policy_q: Default::default(),
            dual_tx_q: Default::default(),
            star_q: Default::default(),
            k_q: Default::default(),
            mode_a_q: Default::default(),
            mode_b_q: Default::default(),
            single_shot_q: Default::default(),
            dmr_q: Default::default(),
            busoff_manual_q: Default::default(),
            first_copy_q: Default::default(),
            p_reset_mode: lsb(&MAP, "CTRL", "reset_mode", 1),
            p_redundancy: lsb(&MAP, "CTRL", "redundancy", 1),
            p_policy: lsb(&MAP, "CTRL", "policy", 2),
            p_dual_tx: lsb(&MAP, "CTRL", "dual_tx", 1),
            p_star: lsb(&MAP, "CTRL", "star", 1),
            p_k: lsb(&MAP, "CTRL", "k", 4),
            p_mode_a: lsb(&MAP, "CTRL", "mode_a", 2),
            p_mode_b: lsb(&MAP, "CTRL", "mode_b", 2),
            p_single_shot: lsb(&MAP, "CTRL", "single_shot", 1),
            p_dmr: lsb(&MAP, "CTRL", "dmr", 1),
            p_busoff_manual: lsb(&MAP, "CTRL", "busoff_manual", 1),
            p_first_copy: lsb(&MAP, "CTRL", "first_copy", 1),
            redundancy_reset: Constant::new(reset("redundancy") == Mode::Redundancy.code() as u64),
            policy_reset: Constant::new(reset("policy").into()),
            k_reset: Constant::new(reset("k").into()),
            mode_reset: Constant::new(reset("mode_a").into()),
            dmr_present: Default::default(),
            star_present: Default::default(),
        }
    }
}

impl Logic for CtrlReg {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            reset_mode_q,
            reset_mode_dq,
            redundancy_q,
            policy_q,
            dual_tx_q,
            star_q,
            k_q,
            mode_a_q,
            mode_b_q,
            single_shot_q,
            dmr_q,
            busoff_manual_q,
            first_copy_q
        );
        self.stored.next = (bit_cast::<32, 1>(self.reset_mode_q.q.val().into())
            << self.p_reset_mode.val())
            | (bit_cast::<32, 1>(self.redundancy_q.q.val().into()) << self.p_redundancy.val())
            | (bit_cast::<32, 2>(self.policy_q.q.val()) << self.p_policy.val())
            | (bit_cast::<32, 1>(self.dual_tx_q.q.val().into()) << self.p_dual_tx.val())
            | (bit_cast::<32, 1>(self.star_q.q.val().into()) << self.p_star.val())
            | (bit_cast::<32, 4>(self.k_q.q.val()) << self.p_k.val())
            | (bit_cast::<32, 2>(self.mode_a_q.q.val()) << self.p_mode_a.val())
            | (bit_cast::<32, 2>(self.mode_b_q.q.val()) << self.p_mode_b.val())
            | (bit_cast::<32, 1>(self.single_shot_q.q.val().into()) << self.p_single_shot.val())
            | (bit_cast::<32, 1>(self.dmr_q.q.val().into()) << self.p_dmr.val())
            | (bit_cast::<32, 1>(self.busoff_manual_q.q.val().into())
                << self.p_busoff_manual.val())
            | (bit_cast::<32, 1>(self.first_copy_q.q.val().into()) << self.p_first_copy.val());
        if self.view_on.val() {
            self.cur.next = self.view_word.val();
        } else {
            self.cur.next = self.stored.val();
        }
        // reset_mode one edge earlier, of the word in force (contract §6)
        self.reset_mode_dq.d.next = self.cur.val().get_bit(self.p_reset_mode.val().index());
        if self.we.val() {
            if self.reset_mode_q.q.val() {
                if !self.refused.val() {
                    self.reset_mode_q.d.next =
                        self.wdat.val().get_bit(self.p_reset_mode.val().index());
                    self.redundancy_q.d.next =
                        self.wdat.val().get_bit(self.p_redundancy.val().index());
                    self.policy_q.d.next =
                        self.wdat.val().get_bits::<2>(self.p_policy.val().index());
                    self.dual_tx_q.d.next = self.wdat.val().get_bit(self.p_dual_tx.val().index());
                    self.star_q.d.next = self.wdat.val().get_bit(self.p_star.val().index())
                        & self.star_present.val().any();
                    self.k_q.d.next = self.k_in.val();
                    self.mode_a_q.d.next =
                        self.wdat.val().get_bits::<2>(self.p_mode_a.val().index());
                    self.mode_b_q.d.next =
                        self.wdat.val().get_bits::<2>(self.p_mode_b.val().index());
                    self.single_shot_q.d.next =
                        self.wdat.val().get_bit(self.p_single_shot.val().index());
                    self.dmr_q.d.next = self.wdat.val().get_bit(self.p_dmr.val().index())
                        & self.dmr_present.val().any();
                    self.busoff_manual_q.d.next =
                        self.wdat.val().get_bit(self.p_busoff_manual.val().index());
                    self.first_copy_q.d.next =
                        self.wdat.val().get_bit(self.p_first_copy.val().index())
                            & self.dmr_present.val().any();
                }
            } else {
                // outside reset mode only reset_mode is taken
                self.reset_mode_q.d.next = self.wdat.val().get_bit(self.p_reset_mode.val().index());
            }
        }

        if self.rst.val() {
            self.reset_mode_q.d.next = true;
            self.reset_mode_dq.d.next = true;
            self.redundancy_q.d.next = self.redundancy_reset.val();
            self.policy_q.d.next = self.policy_reset.val();
            self.dual_tx_q.d.next = false;
            self.star_q.d.next = false;
            self.k_q.d.next = self.k_reset.val();
            self.mode_a_q.d.next = self.mode_reset.val();
            self.mode_b_q.d.next = self.mode_reset.val();
            self.single_shot_q.d.next = false;
            self.dmr_q.d.next = false;
            self.busoff_manual_q.d.next = false;
            self.first_copy_q.d.next = false;
        }

        self.word.next = self.cur.val();
        self.reset_mode.next = self.cur.val().get_bit(self.p_reset_mode.val().index());
        self.reset_mode_d.next = self.reset_mode_dq.q.val();
        self.redundancy.next = self.cur.val().get_bit(self.p_redundancy.val().index());
        self.policy.next = self.cur.val().get_bits::<2>(self.p_policy.val().index());
        self.dual_tx.next = self.cur.val().get_bit(self.p_dual_tx.val().index());
        self.star.next = self.cur.val().get_bit(self.p_star.val().index());
        self.k.next = self.cur.val().get_bits::<4>(self.p_k.val().index());
        self.mode_a.next = self.cur.val().get_bits::<2>(self.p_mode_a.val().index());
        self.mode_b.next = self.cur.val().get_bits::<2>(self.p_mode_b.val().index());
        self.single_shot.next = self.cur.val().get_bit(self.p_single_shot.val().index());
        self.dmr.next = self.cur.val().get_bit(self.p_dmr.val().index());
        self.busoff_manual.next = self.cur.val().get_bit(self.p_busoff_manual.val().index());
        self.first_copy.next = self.cur.val().get_bit(self.p_first_copy.val().index());
    }
}
