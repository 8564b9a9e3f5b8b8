//! The SJA1000 view's window onto the DRCC's native registers, 122..127
//! (pelican_contract.md §13, P-X-3, P-X-4): `XWIN_IDX` names a native word,
//! `XWIN_D0..3` hold it, `XWIN_CMD` commits or reloads it. The window drives the
//! core's own native register port (DRCC contract §D2), so the word is read and
//! written by the native rules; the view adds its own substitutions and limits.
//!
//! - A write of `XWIN_IDX`, or `XWIN_CMD = 0x02` (reload), taken at E is a
//!   native read of that index at E; its data loads `XWIN_D0..3` at E+1 (the
//!   native port's answer clock). The view's next access is taken at E+2 at the
//!   earliest on every bus, so it always sees the loaded word. The indices the
//!   view owns (`INT_STATUS`, `INT_ENABLE`, `TX_*`, `RX_*`) are not read: the
//!   port stays idle and the word loads 0. A load of `CAP_A` or `CAP_B`
//!   re-arms that channel's native captures at E (the SJA1000's ECC and ALC
//!   re-arm on their read the same way; the view's own are separate, §10).
//! - `XWIN_CMD = 0x01` (commit) at E is a native full-word write of
//!   `XWIN_D0..3` to the index at E, only for the configuration words of
//!   P-X-4 while the host holds reset mode (`hrm`). Otherwise it is refused
//!   at E (`XWIN_CMD[0] <= 1`, `XIR.win`); a write the native rules refuse
//!   (its error answer at E+1) is refused at E+1 the same way. An accepted
//!   commit sets `XWIN_CMD[0] <= 0`.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// `XWIN_IDX`, `XWIN_CMD`, `XWIN_D0..3` and the native port's drive.
#[derive(LogicBlock, Default)]
pub struct NativeWindow {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register 0, the native port idle.
    pub rst: Signal<In, Bit>,
    // ---- the host's register access ----
    /// A register write is taken at this edge.
    pub wr: Signal<In, Bit>,
    /// The register number 0..127.
    pub addr: Signal<In, Bits<7>>,
    /// The byte written.
    pub wdata: Signal<In, Bits<8>>,
    /// Host reset mode before the edge (`hrm`): commits are taken only then.
    pub hrm: Signal<In, Bit>,
    /// The byte at `addr` for a read (0 outside 122..127).
    pub rdata: Signal<Out, Bits<8>>,
    /// A commit was refused at this edge (the `XIR.win` event).
    pub refused: Signal<Out, Bit>,
    // ---- the core's native register port (one full-word access, §D2) ----
    /// Native access at this edge (the port's `cyc` and `stb`).
    pub nat_cyc: Signal<Out, Bit>,
    /// The native access is a write.
    pub nat_we: Signal<Out, Bit>,
    /// Native word index.
    pub nat_adr: Signal<Out, Bits<6>>,
    /// Native write data: `XWIN_D0..3`.
    pub nat_wdat: Signal<Out, Bits<32>>,
    /// The port's read data, valid in the answer clock (else 0).
    pub nat_rdat: Signal<In, Bits<32>>,
    /// The port's error answer: the native rules refused the write.
    pub nat_err: Signal<In, Bit>,
    /// Re-arm channel A's (bit 0) or B's (bit 1) native captures at this edge.
    pub cap_rearm: Signal<Out, Bits<2>>,
    // ---- registers ----
    xwin_idx: DFF<Bits<6>>,
    xwin_d: DFF<Bits<32>>,
    xwin_refused: DFF<Bit>,
    /// A native read was made at the last edge: load its answer.
    load_q: DFF<Bit>,
    /// A native write was made at the last edge: its error answer refuses it.
    commit_q: DFF<Bit>,
    // ---- decode ----
    load: Signal<Local, Bit>,
    commit: Signal<Local, Bit>,
    accept: Signal<Local, Bit>,
    load_idx: Signal<Local, Bits<6>>,
    /// The index is one the view owns: it loads 0 (P-X-3).
    owned: Signal<Local, Bit>,
    /// `XWIN_IDX` names a word a commit may write (P-X-4).
    idx_ok: Signal<Local, Bit>,
    d_shift: Signal<Local, Bits<5>>,
    a_xwin_idx: Const<7, 122>,
    a_xwin_cmd: Const<7, 123>,
    page_xwin_d: Const<5, 31>,
    cmd_commit: Const<8, 1>,
    cmd_reload: Const<8, 2>,
    byte_mask: Const<32, 0xFF>,
    zero2: Const<2, 0>,
    zero6: Const<6, 0>,
    zero8: Const<8, 0>,
    zero32: Const<32, 0>,
    bit_a: Const<2, 1>,
    bit_b: Const<2, 2>,
    // native word indices (DRCC contract §D3)
    i_rmb_cfg: Const<6, 3>,
    i_dedup_cfg: Const<6, 4>,
    i_int_status: Const<6, 6>,
    i_int_enable: Const<6, 7>,
    i_tx_id: Const<6, 12>,
    i_rx_cmd: Const<6, 21>,
    i_dmr_cfg: Const<6, 25>,
    i_dmr_time: Const<6, 26>,
    i_dmr_cs: Const<6, 27>,
    i_mb_sel: Const<6, 31>,
    i_mb_id: Const<6, 32>,
    i_mb_mask: Const<6, 33>,
    i_mb_cfg: Const<6, 34>,
    i_cap_a: Const<6, 40>,
    i_cap_b: Const<6, 41>,
}

impl Logic for NativeWindow {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, xwin_idx, xwin_d, xwin_refused, load_q, commit_q);
        self.d_shift.next = bit_cast::<5, 2>(self.addr.val().get_bits::<2>(0)) << 3;
        self.idx_ok.next = (self.xwin_idx.q.val() == self.i_rmb_cfg.val())
            | (self.xwin_idx.q.val() == self.i_dedup_cfg.val())
            | (self.xwin_idx.q.val() == self.i_dmr_cfg.val())
            | (self.xwin_idx.q.val() == self.i_dmr_time.val())
            | (self.xwin_idx.q.val() == self.i_dmr_cs.val())
            | (self.xwin_idx.q.val() == self.i_mb_sel.val())
            | (self.xwin_idx.q.val() == self.i_mb_id.val())
            | (self.xwin_idx.q.val() == self.i_mb_mask.val())
            | (self.xwin_idx.q.val() == self.i_mb_cfg.val());
        // ---- the command of this edge ----
        self.load.next = self.wr.val()
            & ((self.addr.val() == self.a_xwin_idx.val())
                | ((self.addr.val() == self.a_xwin_cmd.val())
                    & (self.wdata.val() == self.cmd_reload.val())));
        self.commit.next = self.wr.val()
            & (self.addr.val() == self.a_xwin_cmd.val())
            & (self.wdata.val() == self.cmd_commit.val());
        self.accept.next = self.commit.val() & self.hrm.val() & self.idx_ok.val();
        if self.addr.val() == self.a_xwin_idx.val() {
            self.load_idx.next = self.wdata.val().get_bits::<6>(0);
        } else {
            self.load_idx.next = self.xwin_idx.q.val();
        }
        self.owned.next = (self.load_idx.val() == self.i_int_status.val())
            | (self.load_idx.val() == self.i_int_enable.val())
            | ((self.load_idx.val() >= self.i_tx_id.val())
                & (self.load_idx.val() <= self.i_rx_cmd.val()));
        // ---- the native port (P-X-3, P-X-4) ----
        self.nat_cyc.next = (self.load.val() & !self.owned.val()) | self.accept.val();
        self.nat_we.next = self.accept.val();
        self.nat_adr.next = self.load_idx.val();
        self.nat_wdat.next = self.xwin_d.q.val();
        self.cap_rearm.next = self.zero2.val();
        if self.load.val() & (self.load_idx.val() == self.i_cap_a.val()) {
            self.cap_rearm.next = self.bit_a.val();
        }
        if self.load.val() & (self.load_idx.val() == self.i_cap_b.val()) {
            self.cap_rearm.next = self.bit_b.val();
        }
        // ---- registers ----
        self.refused.next =
            (self.commit.val() & !self.accept.val()) | (self.commit_q.q.val() & self.nat_err.val());
        self.load_q.d.next = self.load.val();
        self.commit_q.d.next = self.accept.val();
        if self.load_q.q.val() {
            // the answer of the last edge's read (0 when the port stayed idle)
            self.xwin_d.d.next = self.nat_rdat.val();
        }
        if self.wr.val() & (self.addr.val() == self.a_xwin_idx.val()) {
            self.xwin_idx.d.next = self.wdata.val().get_bits::<6>(0);
        }
        if self.commit.val() {
            self.xwin_refused.d.next = !self.accept.val();
        }
        if self.commit_q.q.val() & self.nat_err.val() {
            self.xwin_refused.d.next = true;
        }
        if self.wr.val() & (self.addr.val().get_bits::<5>(2) == self.page_xwin_d.val()) {
            self.xwin_d.d.next = (self.xwin_d.q.val()
                & !(self.byte_mask.val() << self.d_shift.val()))
                | (bit_cast::<32, 8>(self.wdata.val()) << self.d_shift.val());
        }
        if self.rst.val() {
            self.xwin_idx.d.next = self.zero6.val();
            self.xwin_d.d.next = self.zero32.val();
            self.xwin_refused.d.next = false;
            self.load_q.d.next = false;
            self.commit_q.d.next = false;
        }
        // ---- reads ----
        self.rdata.next = self.zero8.val();
        if self.addr.val() == self.a_xwin_idx.val() {
            self.rdata.next = bit_cast::<8, 6>(self.xwin_idx.q.val());
        }
        if self.addr.val() == self.a_xwin_cmd.val() {
            self.rdata.next = bit_cast::<8, 1>(self.xwin_refused.q.val().into());
        }
        if self.addr.val().get_bits::<5>(2) == self.page_xwin_d.val() {
            match self.addr.val().get_bits::<2>(0).index() {
                0 => self.rdata.next = self.xwin_d.q.val().get_bits::<8>(0),
                1 => self.rdata.next = self.xwin_d.q.val().get_bits::<8>(8),
                2 => self.rdata.next = self.xwin_d.q.val().get_bits::<8>(16),
                _ => self.rdata.next = self.xwin_d.q.val().get_bits::<8>(24),
            }
        }
    }
}
