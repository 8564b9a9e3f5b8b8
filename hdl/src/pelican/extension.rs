//! The SJA1000 view's extension window, 112..127 (pelican_contract.md §13,
//! P-X-1..4): the DRCC's identification, its redundancy configuration
//! (`XMODE`, `XK`) and status (`XSTAT`, `XERR`, `XFSM`), its interrupt bits
//! (`XIR`, `XIER`) and the window onto the native registers (`XWIN_*`). An
//! SJA1000 reads 0 at these addresses and stores nothing, so SJA1000 software
//! never writes them.
//!
//! - `XMODE` (115), `XK` (116) reset to the generation keys and are written only
//!   in reset mode; a write in operating mode, of `mode = DMR` without the DMR
//!   function or of `star` without the star node, is ignored with `XIR.ign`
//!   (P-X-1). `XK = 0` is stored as 1. A write that changes either is a
//!   reconfiguration (P-BO-6).
//! - `XIR` (120) bits are set by their events in every mode and cleared by a read
//!   taken at the same edge, an event winning (P-X-2); `XIER` (121) gates only
//!   the interrupt request.
//! - The native window, 122..127, is its own block
//!   ([`super::native_window::NativeWindow`]); its refused commits come in as
//!   the `XIR.win` event.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// `XID0/1`, `XVER`, `XMODE`, `XK`, `XSTAT`, `XERR`, `XFSM`, `XIR`, `XIER`.
#[derive(LogicBlock)]
pub struct ExtensionRegs {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: `XMODE`, `XK` the generation keys, the rest 0.
    pub rst: Signal<In, Bit>,
    // ---- the host's register access ----
    /// A register write is taken at this edge.
    pub wr: Signal<In, Bit>,
    /// A register read is taken at this edge (`XIR` clears on read).
    pub rd: Signal<In, Bit>,
    /// The register number 0..127.
    pub addr: Signal<In, Bits<7>>,
    /// The byte written.
    pub wdata: Signal<In, Bits<8>>,
    /// `MOD.RM` before the edge.
    pub rm: Signal<In, Bit>,
    /// The byte at `addr` for a read (0 outside 112..121).
    pub rdata: Signal<Out, Bits<8>>,
    // ---- events of this edge for XIR ----
    /// Native `INT_STATUS.switch` event.
    pub ev_switch: Signal<In, Bit>,
    /// Native `INT_STATUS.aux` event.
    pub ev_aux: Signal<In, Bit>,
    /// Native `INT_STATUS.dmr` event.
    pub ev_dmr: Signal<In, Bit>,
    /// Native `INT_STATUS.domain` event.
    pub ev_domain: Signal<In, Bit>,
    /// Native `INT_STATUS.err_state` event (either channel's error state changed).
    pub ev_err_state: Signal<In, Bit>,
    /// A bus access was refused (P-BUS-3).
    pub ev_bus: Signal<In, Bit>,
    /// The native window refused a commit (P-X-4).
    pub ev_win: Signal<In, Bit>,
    /// A write the view ignores, from outside this block (`MOD.SM`, `CMR.AT`
    /// outside the single modes, counter writes, the RX RAM).
    pub ev_ign: Signal<In, Bit>,
    // ---- status read through XSTAT, XERR, XFSM ----
    /// The channel in use `u`.
    pub u: Signal<In, Bit>,
    /// The main FSM's `failover`.
    pub failover: Signal<In, Bit>,
    /// Auxiliary FSM A's state.
    pub aux_a_state: Signal<In, Bits<2>>,
    /// Auxiliary FSM B's state.
    pub aux_b_state: Signal<In, Bits<2>>,
    /// Bus-off hold.
    pub boh: Signal<In, Bit>,
    /// `RBS`: the RX FIFO holds a frame.
    pub rbs: Signal<In, Bit>,
    /// The channel of the FIFO head (1 = B).
    pub head_ch: Signal<In, Bit>,
    /// Channel A `err_state`.
    pub err_state_a: Signal<In, Bits<2>>,
    /// Channel B `err_state`.
    pub err_state_b: Signal<In, Bits<2>>,
    /// Channel A error warning.
    pub ew_a: Signal<In, Bit>,
    /// Channel B error warning.
    pub ew_b: Signal<In, Bit>,
    /// Main FSM state.
    pub fsm_state: Signal<In, Bits<4>>,
    /// DMR state.
    pub dmr_state: Signal<In, Bits<2>>,
    /// DMR active CAN line.
    pub acl: Signal<In, Bit>,
    /// Replicated star: the hubs have split.
    pub split: Signal<In, Bit>,
    // ---- to the view ----
    /// `XMODE`: [1:0] mode, [3:2] policy, [4] dual_tx, [5] star, [6] bom,
    /// [7] rep.
    pub xmode: Signal<Out, Bits<8>>,
    /// `XK` (1..15).
    pub xk: Signal<Out, Bits<4>>,
    /// A write at this edge changes `XMODE` or `XK` (P-BO-6).
    pub reconfig: Signal<Out, Bit>,
    /// Some `XIR` bit is set and enabled in `XIER`.
    pub xir_pending: Signal<Out, Bit>,
    // ---- generation parameters ----
    /// `XMODE` after reset (the `pelican_*` keys).
    pub xmode_reset: Constant<Bits<8>>,
    /// `XK` after reset (`pelican_k`).
    pub xk_reset: Constant<Bits<4>>,
    /// The top has the DMR function.
    pub dmr_present: Constant<Bit>,
    /// The top has the replicated-star node.
    pub star_present: Constant<Bit>,
    // ---- registers ----
    xmode_q: DFF<Bits<8>>,
    xk_q: DFF<Bits<4>>,
    xir: DFF<Bits<8>>,
    xier: DFF<Bits<8>>,
    // ---- decode ----
    ign: Signal<Local, Bit>,
    xir_set: Signal<Local, Bits<8>>,
    xk_new: Signal<Local, Bits<4>>,
    /// `ign` from here or outside; `RBS` with a head from channel B.
    ign_any: Signal<Local, Bit>,
    head_b: Signal<Local, Bit>,
    a_xmode: Const<7, 115>,
    a_xk: Const<7, 116>,
    a_xstat: Const<7, 117>,
    a_xerr: Const<7, 118>,
    a_xfsm: Const<7, 119>,
    a_xir: Const<7, 120>,
    a_xier: Const<7, 121>,
    a_xid0: Const<7, 112>,
    a_xid1: Const<7, 113>,
    a_xver: Const<7, 114>,
    xid0: Const<8, 0x44>,
    xid1: Const<8, 0x52>,
    xver: Const<8, 0x10>,
    mode_dmr: Const<2, 2>,
    k_one: Const<4, 1>,
    zero4: Const<4, 0>,
    zero8: Const<8, 0>,
}

impl ExtensionRegs {
    /// The window of a top generated with `XMODE`/`XK` reset values `xmode`, `xk`
    /// and with (`dmr`) or without the DMR function, (`star`) the star node.
    pub fn new(xmode: u8, xk: u8, dmr: bool, star: bool) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr: Default::default(),
            rd: Default::default(),
            addr: Default::default(),
            wdata: Default::default(),
            rm: Default::default(),
            rdata: Default::default(),
            ev_switch: Default::default(),
            ev_aux: Default::default(),
            ev_dmr: Default::default(),
            ev_domain: Default::default(),
            ev_err_state: Default::default(),
            ev_bus: Default::default(),
            ev_win: Default::default(),
            ev_ign: Default::default(),
            u: Default::default(),
            failover: Default::default(),
            aux_a_state: Default::default(),
            aux_b_state: Default::default(),
            boh: Default::default(),
            rbs: Default::default(),
            head_ch: Default::default(),
            err_state_a: Default::default(),
            err_state_b: Default::default(),
            ew_a: Default::default(),
            ew_b: Default::default(),
            fsm_state: Default::default(),
            dmr_state: Default::default(),
            acl: Default::default(),
            split: Default::default(),
            xmode: Default::default(),
            xk: Default::default(),
            reconfig: Default::default(),
            xir_pending: Default::default(),
            xmode_reset: Constant::new((xmode as u64).into()),
            xk_reset: Constant::new((xk.clamp(1, 15) as u64).into()),
            dmr_present: Constant::new(dmr),
            star_present: Constant::new(star),
            xmode_q: Default::default(),
            xk_q: Default::default(),
            xir: Default::default(),
            xier: Default::default(),
            ign: Default::default(),
            xir_set: Default::default(),
            xk_new: Default::default(),
            ign_any: Default::default(),
            head_b: Default::default(),
            a_xmode: Default::default(),
            a_xk: Default::default(),
            a_xstat: Default::default(),
            a_xerr: Default::default(),
            a_xfsm: Default::default(),
            a_xir: Default::default(),
            a_xier: Default::default(),
            a_xid0: Default::default(),
            a_xid1: Default::default(),
            a_xver: Default::default(),
            xid0: Default::default(),
            xid1: Default::default(),
            xver: Default::default(),
            mode_dmr: Default::default(),
            k_one: Default::default(),
            zero4: Default::default(),
            zero8: Default::default(),
        }
    }
}

impl Default for ExtensionRegs {
    /// The generator's defaults ([`super::PelicanKeys::default`]).
    fn default() -> Self {
        let k = super::PelicanKeys::default();
        Self::new(k.xmode(), k.k, k.dmr, k.star)
    }
}

impl Logic for ExtensionRegs {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, xmode_q, xk_q, xir, xier);
        self.head_b.next = self.rbs.val() & self.head_ch.val();
        self.xk_new.next = self.wdata.val().get_bits::<4>(0);
        if self.xk_new.val() == self.zero4.val() {
            self.xk_new.next = self.k_one.val();
        }
        // ---- writes (P-X-1) ----
        self.ign.next = false;
        self.reconfig.next = false;
        if self.wr.val() {
            if self.addr.val() == self.a_xmode.val() {
                if !self.rm.val()
                    | ((self.wdata.val().get_bits::<2>(0) == self.mode_dmr.val())
                        & !self.dmr_present.val())
                    | (self.wdata.val().get_bit(5) & !self.star_present.val())
                {
                    self.ign.next = true;
                } else {
                    self.xmode_q.d.next = self.wdata.val();
                    self.reconfig.next = (self.wdata.val()) != self.xmode_q.q.val();
                }
            }
            if self.addr.val() == self.a_xk.val() {
                if !self.rm.val() {
                    self.ign.next = true;
                } else {
                    self.xk_q.d.next = self.xk_new.val();
                    self.reconfig.next = self.xk_new.val() != self.xk_q.q.val();
                }
            }
            if self.addr.val() == self.a_xier.val() {
                self.xier.d.next = self.wdata.val();
            }
        }
        // ---- XIR: a read clears, an event of the same edge wins (P-X-2) ----
        self.ign_any.next = self.ign.val() | self.ev_ign.val();
        self.xir_set.next = (bit_cast::<8, 1>(self.ign_any.val().into()) << 7)
            | (bit_cast::<8, 1>(self.ev_win.val().into()) << 6)
            | (bit_cast::<8, 1>(self.ev_bus.val().into()) << 5)
            | (bit_cast::<8, 1>(self.ev_err_state.val().into()) << 4)
            | (bit_cast::<8, 1>(self.ev_domain.val().into()) << 3)
            | (bit_cast::<8, 1>(self.ev_dmr.val().into()) << 2)
            | (bit_cast::<8, 1>(self.ev_aux.val().into()) << 1)
            | bit_cast::<8, 1>(self.ev_switch.val().into());
        if self.rd.val() && (self.addr.val() == self.a_xir.val()) {
            self.xir.d.next = self.xir_set.val();
        } else {
            self.xir.d.next = self.xir.q.val() | self.xir_set.val();
        }
        if self.rst.val() {
            self.xmode_q.d.next = self.xmode_reset.val();
            self.xk_q.d.next = self.xk_reset.val();
            self.xir.d.next = self.zero8.val();
            self.xier.d.next = self.zero8.val();
        }
        // ---- reads ----
        self.rdata.next = self.zero8.val();
        if self.addr.val() == self.a_xid0.val() {
            self.rdata.next = self.xid0.val();
        }
        if self.addr.val() == self.a_xid1.val() {
            self.rdata.next = self.xid1.val();
        }
        if self.addr.val() == self.a_xver.val() {
            self.rdata.next = self.xver.val();
        }
        if self.addr.val() == self.a_xmode.val() {
            self.rdata.next = self.xmode_q.q.val();
        }
        if self.addr.val() == self.a_xk.val() {
            self.rdata.next = bit_cast::<8, 4>(self.xk_q.q.val());
        }
        if self.addr.val() == self.a_xstat.val() {
            self.rdata.next = (bit_cast::<8, 1>(self.head_b.val().into()) << 7)
                | (bit_cast::<8, 1>(self.boh.val().into()) << 6)
                | (bit_cast::<8, 2>(self.aux_b_state.val()) << 4)
                | (bit_cast::<8, 2>(self.aux_a_state.val()) << 2)
                | (bit_cast::<8, 1>(self.failover.val().into()) << 1)
                | bit_cast::<8, 1>(self.u.val().into());
        }
        if self.addr.val() == self.a_xerr.val() {
            self.rdata.next = (bit_cast::<8, 1>(self.ew_b.val().into()) << 5)
                | (bit_cast::<8, 1>(self.ew_a.val().into()) << 4)
                | (bit_cast::<8, 2>(self.err_state_b.val()) << 2)
                | bit_cast::<8, 2>(self.err_state_a.val());
        }
        if self.addr.val() == self.a_xfsm.val() {
            self.rdata.next = (bit_cast::<8, 1>(self.split.val().into()) << 7)
                | (bit_cast::<8, 1>(self.acl.val().into()) << 6)
                | (bit_cast::<8, 2>(self.dmr_state.val()) << 4)
                | bit_cast::<8, 4>(self.fsm_state.val());
        }
        if self.addr.val() == self.a_xir.val() {
            self.rdata.next = self.xir.q.val();
        }
        if self.addr.val() == self.a_xier.val() {
            self.rdata.next = self.xier.q.val();
        }
        self.xmode.next = self.xmode_q.q.val();
        self.xk.next = self.xk_q.q.val();
        self.xir_pending.next = (self.xir.q.val() & self.xier.q.val()).any();
    }
}
