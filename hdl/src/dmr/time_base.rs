//! The DMR time base (DMR contract §3) and the period of the connection service
//! (§7): `tb_cnt` counts nominal bit `tick`s and wraps at `tick_bits - 1`, the
//! register `dmr_tick` pulses at the wrap; `period_cnt` counts `dmr_tick`s and
//! wraps at `cs_period - 1` (0 = no periodic CS). Both clear while held (reset
//! mode). The wrap tests `cnt + 1 == limit` with the incrementer already there:
//! the same as the contract's `cnt == limit - 1` (the limits change only in
//! reset mode, where the counters are 0), and the same at `limit = 0`.

use rust_hdl::prelude::*;

/// DMR tick and CS period.
#[derive(LogicBlock)]
pub struct DmrTimeBase {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst` or held (reset mode, or not DMR mode): both counters and `dmr_tick` to 0.
    pub clear: Signal<In, Bit>,
    // ---- configuration ----
    /// `DMR_TIME.tick_bits`: nominal bit times per DMR tick.
    pub tick_bits: Signal<In, Bits<16>>,
    /// `DMR_CFG.cs_period`: DMR ticks between periodic CS frames, 0 = none.
    pub cs_period: Signal<In, Bits<16>>,
    // ---- time ----
    /// The nominal bit tick (DRCC contract §4.3).
    pub tick: Signal<In, Bit>,
    /// `dmr_tick`: one clock per `tick_bits` bit ticks (a register).
    pub dmr_tick: Signal<Out, Bit>,
    /// A periodic CS is due at this edge (combinational, §7).
    pub period_due: Signal<Out, Bit>,
    /// `tb_cnt`.
    pub tb_cnt: DFF<Bits<16>>,
    /// `dmr_tick`.
    pub tick_q: DFF<Bit>,
    /// `period_cnt`.
    pub period_cnt: DFF<Bits<16>>,
    tb_next: Signal<Local, Bits<16>>,
    period_next: Signal<Local, Bits<16>>,
    period_on: Signal<Local, Bit>,
    one16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
}

impl Default for DmrTimeBase {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            clear: Default::default(),
            tick_bits: Default::default(),
            cs_period: Default::default(),
            tick: Default::default(),
            dmr_tick: Default::default(),
            period_due: Default::default(),
            tb_cnt: Default::default(),
            tick_q: Default::default(),
            period_cnt: Default::default(),
            tb_next: Default::default(),
            period_next: Default::default(),
            period_on: Default::default(),
            one16: Constant::new(1.into()),
            zero16: Constant::new(0.into()),
        }
    }
}

impl Logic for DmrTimeBase {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, tb_cnt, tick_q, period_cnt);
        // §3: at a bit tick, wrap at tick_bits - 1 and pulse dmr_tick.
        self.tb_next.next = self.tb_cnt.q.val() + self.one16.val();
        self.tick_q.d.next = false;
        if self.tick.val() {
            if self.tb_next.val() == self.tick_bits.val() {
                self.tb_cnt.d.next = self.zero16.val();
                self.tick_q.d.next = true;
            } else {
                self.tb_cnt.d.next = self.tb_next.val();
            }
        }
        // §7: every cs_period DMR ticks (cs_period = 0: none).
        self.period_next.next = self.period_cnt.q.val() + self.one16.val();
        self.period_on.next = self.tick_q.q.val() & (self.cs_period.val() != self.zero16.val());
        self.period_due.next =
            self.period_on.val() & (self.period_next.val() == self.cs_period.val());
        if self.period_on.val() {
            if self.period_next.val() == self.cs_period.val() {
                self.period_cnt.d.next = self.zero16.val();
            } else {
                self.period_cnt.d.next = self.period_next.val();
            }
        }
        if self.clear.val() {
            self.tb_cnt.d.next = self.zero16.val();
            self.tick_q.d.next = false;
            self.period_cnt.d.next = self.zero16.val();
            self.period_due.next = false;
        }
        self.dmr_tick.next = self.tick_q.q.val();
    }
}
