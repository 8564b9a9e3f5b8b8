//! The checks of a `CTRL` write (DRCC contract §9), combinational on the written
//! word and the stored fields:
//!
//! - in reset mode a write with redundancy or DMR and a listen-only channel, or
//!   with both redundancy and DMR (DMR contract §2), is refused as a whole (every
//!   policy code is legal: 3 is the warning-limit policy of §5);
//! - outside reset mode only `reset_mode` is taken, and a write whose cfg fields
//!   differ from the stored ones is flagged;
//! - `k = 0` is stored as 1 (not illegal);
//! - in a configuration without the DMR function or without the replicated-star
//!   node (drcc_contract.md §1.1), a write with `dmr` or `star` set is refused as
//!   a whole in reset mode (outside it the cfg fields cannot change anyway).
//!
//! Field positions and codes come from the table (`super::registers`).

use super::map::lsb;
use super::registers::{ChannelMode, MAP};
use crate::channel::sized::Param;
use rust_hdl::prelude::*;

/// The §9 checks of a `CTRL` write.
#[derive(LogicBlock)]
pub struct CtrlCheck {
    // ---- the write ----
    /// The written word.
    pub wdat: Signal<In, Bits<32>>,
    // ---- the stored fields (super::ctrl_reg::CtrlReg) ----
    /// Reset mode before the write.
    pub reset_mode: Signal<In, Bit>,
    /// Stored `redundancy`.
    pub redundancy: Signal<In, Bit>,
    /// Stored `policy`.
    pub policy: Signal<In, Bits<2>>,
    /// Stored `dual_tx`.
    pub dual_tx: Signal<In, Bit>,
    /// Stored `star`.
    pub star: Signal<In, Bit>,
    /// Stored `k`.
    pub k: Signal<In, Bits<4>>,
    /// Stored `mode_a`.
    pub mode_a: Signal<In, Bits<2>>,
    /// Stored `mode_b`.
    pub mode_b: Signal<In, Bits<2>>,
    /// Stored `single_shot`.
    pub single_shot: Signal<In, Bit>,
    /// Stored `dmr`.
    pub dmr: Signal<In, Bit>,
    /// Stored `busoff_manual`.
    pub busoff_manual: Signal<In, Bit>,
    /// Stored `first_copy`.
    pub first_copy: Signal<In, Bit>,
    // ---- verdict ----
    /// The `k` to store: the written one, 0 read as 1.
    pub k_in: Signal<Out, Bits<4>>,
    /// The word is refused in reset mode (redundancy or DMR with a listen-only
    /// channel, redundancy with DMR).
    pub refused: Signal<Out, Bit>,
    /// A write of this word now sets `INT_STATUS.illegal`.
    pub illegal: Signal<Out, Bit>,
    // ---- internals ----
    cfg_differs: Signal<Local, Bit>,
    listen: Signal<Local, Bit>,
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
    mode_listen: Constant<Bits<2>>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    /// The configuration has the CiA 701 DMR function (generation parameter).
    pub(crate) dmr_present: Param<1, 1>,
    /// The configuration has the replicated-star node (generation parameter).
    pub(crate) star_present: Param<1, 1>,
}

impl Default for CtrlCheck {
    fn default() -> Self {
        Self {
            wdat: Default::default(),
            reset_mode: Default::default(),
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
            k_in: Default::default(),
            refused: Default::default(),
            illegal: Default::default(),
            cfg_differs: Default::default(),
            listen: Default::default(),
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
            mode_listen: Constant::new((ChannelMode::ListenOnly.code() as u64).into()),
            zero4: Constant::new(0.into()),
            one4: Constant::new(1.into()),
            dmr_present: Default::default(),
            star_present: Default::default(),
        }
    }
}

impl Logic for CtrlCheck {
    #[hdl_gen]
    fn update(&mut self) {
        // k = 0 is stored as 1
        if self.wdat.val().get_bits::<4>(self.p_k.val().index()) == self.zero4.val() {
            self.k_in.next = self.one4.val();
        } else {
            self.k_in.next = self.wdat.val().get_bits::<4>(self.p_k.val().index());
        }
        // redundancy or DMR (both need two transmitting channels) with a
        // listen-only channel; redundancy and DMR together
        self.listen.next = (self.wdat.val().get_bits::<2>(self.p_mode_a.val().index())
            == self.mode_listen.val())
            | (self.wdat.val().get_bits::<2>(self.p_mode_b.val().index())
                == self.mode_listen.val());
        self.refused.next = ((self.wdat.val().get_bit(self.p_redundancy.val().index())
            | self.wdat.val().get_bit(self.p_dmr.val().index()))
            & self.listen.val())
            | (self.wdat.val().get_bit(self.p_redundancy.val().index())
                & self.wdat.val().get_bit(self.p_dmr.val().index()))
            | (self.wdat.val().get_bit(self.p_dmr.val().index()) & !self.dmr_present.val().any())
            | (self.wdat.val().get_bit(self.p_star.val().index()) & !self.star_present.val().any());
        self.cfg_differs.next = (self.wdat.val().get_bit(self.p_redundancy.val().index())
            != self.redundancy.val())
            | (self.wdat.val().get_bits::<2>(self.p_policy.val().index()) != self.policy.val())
            | (self.wdat.val().get_bit(self.p_dual_tx.val().index()) != self.dual_tx.val())
            | (self.wdat.val().get_bit(self.p_star.val().index()) != self.star.val())
            | (self.k_in.val() != self.k.val())
            | (self.wdat.val().get_bits::<2>(self.p_mode_a.val().index()) != self.mode_a.val())
            | (self.wdat.val().get_bits::<2>(self.p_mode_b.val().index()) != self.mode_b.val())
            | (self.wdat.val().get_bit(self.p_single_shot.val().index()) != self.single_shot.val())
            | (self.wdat.val().get_bit(self.p_dmr.val().index()) != self.dmr.val())
            | (self.wdat.val().get_bit(self.p_busoff_manual.val().index())
                != self.busoff_manual.val())
            | (self.wdat.val().get_bit(self.p_first_copy.val().index()) != self.first_copy.val());
        if self.reset_mode.val() {
            self.illegal.next = self.refused.val();
        } else {
            self.illegal.next = self.cfg_differs.val();
        }
    }
}
