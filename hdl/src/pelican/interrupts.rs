//! The SJA1000 view's interrupt registers (pelican_contract.md §9; SJA1000 data
//! sheet 6.4.6 IR, 6.4.7 IER): `IER`, `IR`, the comparison registers of the
//! status changes, and the `irq` pin.
//!
//! - `RI = RIE & RBS` is a level (P-IR-2). `TI`, `EI`, `DOI`, `EPI`, `ALI`,
//!   `BEI` are registers, set at the edge of their event if their enable bit is
//!   1 before that edge and the view is in operating mode (P-MOD-6); `WUI` is
//!   never set (no sleep mode, P-MOD-7).
//! - A read of `IR` taken at an edge clears the registers at that edge; an event
//!   at the same edge wins (P-IR-3).
//! - At the edge where `RM` rises every register bit but `EI` clears (P-MOD-5);
//!   `EI` keeps its value and is set by the bus-off that caused the rise.
//! - `EI` marks every change of `ES` or `BS` (P-IR-5). `EPI` marks the logical
//!   controller becoming error passive, and leaving it for error active unless
//!   `ES` falls at the same edge (P-IR-6: a switchover to a healthy channel is
//!   reported by `EI` alone).
//! - `irq` is registered: 1 the clock after any `IR` bit, or an enabled `XIR`
//!   bit, is 1 (P-IRQ-1).

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// `IER`, `IR` and `irq`.
#[derive(LogicBlock, Default)]
pub struct Interrupts {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: `IR`, `IER`, `irq` 0.
    pub rst: Signal<In, Bit>,
    // ---- the host ----
    /// A write of `IER` is taken at this edge (both modes).
    pub ier_write: Signal<In, Bit>,
    /// The byte written.
    pub wdata: Signal<In, Bits<8>>,
    /// A read of `IR` is taken at this edge.
    pub ir_read: Signal<In, Bit>,
    // ---- the mode ----
    /// `MOD.RM` before the edge: no event is raised in reset mode.
    pub rm: Signal<In, Bit>,
    /// `RM` rises at this edge.
    pub rm_rise: Signal<In, Bit>,
    // ---- events and status of the logical controller ----
    /// `SR.RBS`: the RX FIFO holds a frame.
    pub rbs: Signal<In, Bit>,
    /// `TBS` rises by a completion (`TI`).
    pub ti_evt: Signal<In, Bit>,
    /// `DOS` rises (`DOI`).
    pub doi_evt: Signal<In, Bit>,
    /// Channel `u`'s `err_valid` (`BEI`).
    pub bei_evt: Signal<In, Bit>,
    /// Channel `u`'s `arb_lost` (`ALI`).
    pub ali_evt: Signal<In, Bit>,
    /// `SR.ES` of the logical controller.
    pub es: Signal<In, Bit>,
    /// `SR.BS` of the logical controller.
    pub bs: Signal<In, Bit>,
    /// Channel `u`'s error state: 0 error active, 1 error passive, 2 bus-off.
    pub err_state: Signal<In, Bits<2>>,
    /// Some `XIR` bit is set and enabled in `XIER`.
    pub xir_pending: Signal<In, Bit>,
    // ---- outputs ----
    /// `IER` as read.
    pub ier_q: Signal<Out, Bits<8>>,
    /// `IR` as read: [0] `RI`, [1] `TI`, [2] `EI`, [3] `DOI`, [4] `WUI` (0),
    /// [5] `EPI`, [6] `ALI`, [7] `BEI`.
    pub ir_q: Signal<Out, Bits<8>>,
    /// `BS` rises at this edge (the bus-off that sets the hold, P-BO-1).
    pub bs_rise: Signal<Out, Bit>,
    /// Interrupt request, active-high level.
    pub irq: Signal<Out, Bit>,
    // ---- registers ----
    ier: DFF<Bits<8>>,
    ti: DFF<Bit>,
    ei: DFF<Bit>,
    doi: DFF<Bit>,
    epi: DFF<Bit>,
    ali: DFF<Bit>,
    bei: DFF<Bit>,
    es_q: DFF<Bit>,
    bs_q: DFF<Bit>,
    st_q: DFF<Bits<2>>,
    irq_q: DFF<Bit>,
    // ---- events of this edge, before the enables ----
    op: Signal<Local, Bit>,
    ei_evt: Signal<Local, Bit>,
    epi_evt: Signal<Local, Bit>,
    ri: Signal<Local, Bit>,
    ir_all: Signal<Local, Bits<8>>,
    active: Const<2, 0>,
    passive: Const<2, 1>,
    zero8: Const<8, 0>,
}

impl Logic for Interrupts {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, ier, ti, ei, doi, epi, ali, bei, es_q, bs_q, st_q, irq_q);
        self.op.next = !self.rm.val();
        // P-IR-5, P-IR-6: changes against the values one clock earlier
        self.ei_evt.next =
            (self.es.val() != self.es_q.q.val()) | (self.bs.val() != self.bs_q.q.val());
        self.epi_evt.next = ((self.err_state.val() == self.passive.val())
            & (self.st_q.q.val() != self.passive.val()))
            | ((self.err_state.val() == self.active.val())
                & (self.st_q.q.val() == self.passive.val())
                & !(self.es_q.q.val() & !self.es.val()));
        self.es_q.d.next = self.es.val();
        self.bs_q.d.next = self.bs.val();
        self.st_q.d.next = self.err_state.val();
        self.bs_rise.next = self.bs.val() & !self.bs_q.q.val();

        if self.ier_write.val() {
            self.ier.d.next = self.wdata.val();
        }
        // a read clears; an event of the same edge wins (P-IR-3)
        if self.ir_read.val() {
            self.ti.d.next = false;
            self.ei.d.next = false;
            self.doi.d.next = false;
            self.epi.d.next = false;
            self.ali.d.next = false;
            self.bei.d.next = false;
        }
        // entering reset mode clears all but EI (P-MOD-5)
        if self.rm_rise.val() {
            self.ti.d.next = false;
            self.doi.d.next = false;
            self.epi.d.next = false;
            self.ali.d.next = false;
            self.bei.d.next = false;
        }
        if self.op.val() {
            if self.ti_evt.val() && self.ier.q.val().get_bit(1) && !self.rm_rise.val() {
                self.ti.d.next = true;
            }
            if self.ei_evt.val() && self.ier.q.val().get_bit(2) {
                self.ei.d.next = true;
            }
            if self.doi_evt.val() && self.ier.q.val().get_bit(3) && !self.rm_rise.val() {
                self.doi.d.next = true;
            }
            if self.epi_evt.val() && self.ier.q.val().get_bit(5) && !self.rm_rise.val() {
                self.epi.d.next = true;
            }
            if self.ali_evt.val() && self.ier.q.val().get_bit(6) && !self.rm_rise.val() {
                self.ali.d.next = true;
            }
            if self.bei_evt.val() && self.ier.q.val().get_bit(7) && !self.rm_rise.val() {
                self.bei.d.next = true;
            }
        }

        // RI is a level (P-IR-2)
        self.ri.next = self.ier.q.val().get_bit(0) & self.rbs.val();
        self.ir_all.next = (bit_cast::<8, 1>(self.bei.q.val().into()) << 7)
            | (bit_cast::<8, 1>(self.ali.q.val().into()) << 6)
            | (bit_cast::<8, 1>(self.epi.q.val().into()) << 5)
            | (bit_cast::<8, 1>(self.doi.q.val().into()) << 3)
            | (bit_cast::<8, 1>(self.ei.q.val().into()) << 2)
            | (bit_cast::<8, 1>(self.ti.q.val().into()) << 1)
            | bit_cast::<8, 1>(self.ri.val().into());
        self.irq_q.d.next = self.ir_all.val().any() | self.xir_pending.val();

        if self.rst.val() {
            self.ier.d.next = self.zero8.val();
            self.ti.d.next = false;
            self.ei.d.next = false;
            self.doi.d.next = false;
            self.epi.d.next = false;
            self.ali.d.next = false;
            self.bei.d.next = false;
            self.es_q.d.next = false;
            self.bs_q.d.next = false;
            self.st_q.d.next = self.active.val();
            self.irq_q.d.next = false;
        }
        self.ier_q.next = self.ier.q.val();
        self.ir_q.next = self.ir_all.val();
        self.irq.next = self.irq_q.q.val();
    }
}
