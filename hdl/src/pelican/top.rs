//! The `drcc_pelican` top: the DRCC with the SJA1000 (PeliCAN) host view instead
//! of the native register map (`drcc generate --config` with `host = "pelican"`),
//! as fixed clock by clock by `cosim/src/model/pelican_contract.md`. An
//! unmodified SJA1000 driver (Linux `sja1000`, Zephyr `can_sja1000`) runs the
//! dual-redundant controller as one CAN controller; the redundancy sits behind
//! it and in the extension window (§13). User's page: `docs/pelican.md`.
//!
//! The DRCC core ([`DrccCore`]) with its host-view inputs driven by the view's
//! register block ([`PelicanView`]); the core's native register port is the
//! view's window onto the native registers (P-X-3, P-X-4).

use super::view::PelicanView;
use super::PelicanKeys;
use crate::channel::sized::Const;
use crate::config::DrccConfig;
use crate::drcc_core::DrccCore;
use rust_hdl::prelude::*;

/// The SJA1000 view of the DRCC, generated with `M` DMR mailboxes (0..16).
#[derive(LogicBlock, Default)]
pub struct DrccPelican<const M: usize> {
    // clock and reset
    /// Clock: the SJA1000's oscillator `fosc` (a time quantum is `2 x (BRP + 1)`
    /// clocks, P-CFG-2). Every register changes at its rising edge.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high: the registers take their
    /// values of pelican_contract.md §16 (`MOD = 0x01`, reset mode).
    pub rst: Signal<In, Bit>,
    // Wishbone B4 classic slave, 32-bit data (pelican_contract.md §2)
    /// Wishbone cycle, active high. An access is taken at an edge where
    /// `wb_cyc_i & wb_stb_i & !(wb_ack_o | wb_err_o)`.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone strobe, active high.
    pub wb_stb_i: Signal<In, Bit>,
    /// Wishbone write enable: 1 = write.
    pub wb_we_i: Signal<In, Bit>,
    /// Wishbone word address. Stride 4: register `r` is word `r` (`[6:0]`).
    /// Stride 1: register `r` is word `r >> 2`, lane `r & 3` (`[4:0]`, `[6:5]`
    /// ignored).
    pub wb_adr_i: Signal<In, Bits<7>>,
    /// Wishbone write data: the register's byte in `[7:0]` (stride 4) or in its
    /// lane (stride 1).
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Wishbone byte select. Stride 4: a write needs `sel[0]`, a read ignores
    /// it. Stride 1: exactly one lane, read or write. Any other pattern is
    /// refused with `wb_err_o` and `XIR.bus` (P-BUS-3).
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone read data, valid while `wb_ack_o = 1`, else 0: the register's
    /// byte in `[7:0]` (stride 4) or on all four lanes (stride 1).
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone acknowledge, 1 for the clock after the edge that took the access.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Wishbone error, instead of the acknowledge, for a refused access.
    pub wb_err_o: Signal<Out, Bit>,
    /// Interrupt request, active-high level, registered: any `IR` bit, or any
    /// `XIR` bit enabled in `XIER` (P-IRQ-1). Invert it for the SJA1000's `INT#`.
    pub irq: Signal<Out, Bit>,
    // CAN pins (1 = recessive, 0 = dominant); A is the paper's channel 1, B channel 2
    /// Channel A CAN transmit pin, 1 = recessive (a register).
    pub chan_a_tx: Signal<Out, Bit>,
    /// Channel A CAN receive pin, 1 = recessive; synchronized by two flip-flops.
    pub chan_a_rx: Signal<In, Bit>,
    /// Channel B CAN transmit pin, 1 = recessive (a register).
    pub chan_b_tx: Signal<Out, Bit>,
    /// Channel B CAN receive pin, 1 = recessive; synchronized by two flip-flops.
    pub chan_b_rx: Signal<In, Bit>,
    // blocks
    /// The DRCC core (public for block-level probes in tests).
    pub core: DrccCore<M>,
    /// The SJA1000 register block (public for probes in tests).
    pub view: PelicanView,
    all_lanes: Const<4, 0xF>,
}

impl<const M: usize> DrccPelican<M> {
    /// The view with the keys `k` over a core with the sizes of `cfg` (its
    /// `mailboxes` must be `M`; `k.dmr` and `k.star` are taken from it).
    pub fn with_config(cfg: &DrccConfig, k: &PelicanKeys) -> Self {
        let k = PelicanKeys {
            dmr: cfg.dmr,
            star: cfg.star,
            ..*k
        };
        Self {
            core: DrccCore::with_config(cfg),
            view: PelicanView::new(&k),
            ..Default::default()
        }
    }
}

impl<const M: usize> Logic for DrccPelican<M> {
    #[hdl_gen]
    fn update(&mut self) {
        self.core.clk.next = self.clk.val();
        self.core.rst.next = self.rst.val();
        self.view.clk.next = self.clk.val();
        self.view.rst.next = self.rst.val();
        // the bus goes to the view; the core's native port is the view's window
        self.view.wb_cyc_i.next = self.wb_cyc_i.val();
        self.view.wb_stb_i.next = self.wb_stb_i.val();
        self.view.wb_we_i.next = self.wb_we_i.val();
        self.view.wb_adr_i.next = self.wb_adr_i.val();
        self.view.wb_dat_i.next = self.wb_dat_i.val();
        self.view.wb_sel_i.next = self.wb_sel_i.val();
        self.wb_dat_o.next = self.view.wb_dat_o.val();
        self.wb_ack_o.next = self.view.wb_ack_o.val();
        self.wb_err_o.next = self.view.wb_err_o.val();
        self.irq.next = self.view.irq.val();
        self.core.wb_cyc_i.next = self.view.nat_cyc.val();
        self.core.wb_stb_i.next = self.view.nat_cyc.val();
        self.core.wb_we_i.next = self.view.nat_we.val();
        self.core.wb_adr_i.next = self.view.nat_adr.val();
        self.core.wb_dat_i.next = self.view.nat_wdat.val();
        self.core.wb_sel_i.next = self.all_lanes.val();
        self.view.nat_rdat.next = self.core.wb_dat_o.val();
        self.view.nat_err.next = self.core.wb_err_o.val();
        // CAN pins
        self.core.chan_a_rx.next = self.chan_a_rx.val();
        self.core.chan_b_rx.next = self.chan_b_rx.val();
        self.chan_a_tx.next = self.core.chan_a_tx.val();
        self.chan_b_tx.next = self.core.chan_b_tx.val();
        // the core's state, read by the view
        self.view.state.next = self.core.state.val();
        self.view.tx_channel.next = self.core.tx_channel.val();
        self.view.failover.next = self.core.failover.val();
        self.view.tx_success.next = self.core.tx_success.val();
        self.view.aux_a_state.next = self.core.aux_a_state.val();
        self.view.aux_b_state.next = self.core.aux_b_state.val();
        self.view.dmr_state.next = self.core.dmr_state.val();
        self.view.acl.next = self.core.acl.val();
        self.view.dmr_tx_done.next = self.core.dmr_tx_done.val();
        self.view.star_split.next = self.core.star_split.val();
        self.view.rx_overrun.next = self.core.rx_overrun.val();
        self.view.rx_ready.next = self.core.rx_ready.val();
        self.view.rx_count.next = self.core.rx_count.val();
        self.view.rx_head.next = self.core.rx_head.val();
        self.view.ev_switch.next = self.core.ev_switch.val();
        self.view.ev_aux.next = self.core.ev_aux.val();
        self.view.ev_dmr.next = self.core.ev_dmr.val();
        self.view.ev_domain.next = self.core.ev_domain.val();
        self.view.chan_a_err_state.next = self.core.chan_a_err_state.val();
        self.view.chan_a_err_warning.next = self.core.chan_a_err_warning.val();
        self.view.chan_a_tec.next = self.core.chan_a_tec.val();
        self.view.chan_a_rec.next = self.core.chan_a_rec.val();
        self.view.chan_a_boff_runs.next = self.core.chan_a_boff_runs.val();
        self.view.chan_a_field.next = self.core.chan_a_field.val();
        self.view.chan_a_is_tx.next = self.core.chan_a_is_tx.val();
        self.view.chan_a_tx_done.next = self.core.chan_a_tx_done.val();
        self.view.chan_a_tx_failed.next = self.core.chan_a_tx_failed.val();
        self.view.chan_a_tx_pending.next = self.core.chan_a_tx_pending.val();
        self.view.chan_a_err_valid.next = self.core.chan_a_err_valid.val();
        self.view.chan_a_err_kind.next = self.core.chan_a_err_kind.val();
        self.view.chan_a_err_field.next = self.core.chan_a_err_field.val();
        self.view.chan_a_err_tx.next = self.core.chan_a_err_tx.val();
        self.view.chan_a_arb_lost.next = self.core.chan_a_arb_lost.val();
        self.view.chan_a_alc.next = self.core.chan_a_alc.val();
        self.view.chan_b_err_state.next = self.core.chan_b_err_state.val();
        self.view.chan_b_err_warning.next = self.core.chan_b_err_warning.val();
        self.view.chan_b_tec.next = self.core.chan_b_tec.val();
        self.view.chan_b_rec.next = self.core.chan_b_rec.val();
        self.view.chan_b_boff_runs.next = self.core.chan_b_boff_runs.val();
        self.view.chan_b_field.next = self.core.chan_b_field.val();
        self.view.chan_b_is_tx.next = self.core.chan_b_is_tx.val();
        self.view.chan_b_tx_done.next = self.core.chan_b_tx_done.val();
        self.view.chan_b_tx_failed.next = self.core.chan_b_tx_failed.val();
        self.view.chan_b_tx_pending.next = self.core.chan_b_tx_pending.val();
        self.view.chan_b_err_valid.next = self.core.chan_b_err_valid.val();
        self.view.chan_b_err_kind.next = self.core.chan_b_err_kind.val();
        self.view.chan_b_err_field.next = self.core.chan_b_err_field.val();
        self.view.chan_b_err_tx.next = self.core.chan_b_err_tx.val();
        self.view.chan_b_arb_lost.next = self.core.chan_b_arb_lost.val();
        self.view.chan_b_alc.next = self.core.chan_b_alc.val();
        // the view's drive of the core (§14)
        self.core.view_on.next = true;
        self.core.view_ctrl.next = self.view.view_ctrl.val();
        self.core.view_btr.next = self.view.view_btr.val();
        self.core.view_chan_reset.next = self.view.view_chan_reset.val();
        self.core.view_push.next = self.view.view_push.val();
        self.core.view_push_q.next = self.view.view_push_q.val();
        self.core.view_push_frame.next = self.view.view_push_frame.val();
        self.core.view_pop.next = self.view.view_pop.val();
        self.core.view_tx_single.next = self.view.view_tx_single.val();
        self.core.view_tx_abort.next = self.view.view_tx_abort.val();
        self.core.view_boff_hold.next = self.view.view_boff_hold.val();
        self.core.view_offer_s.next = self.view.view_offer_s.val();
        self.core.view_frame_s.next = self.view.view_frame_s.val();
        self.core.view_gate_on.next = self.view.view_gate_on.val();
        self.core.view_afm.next = self.view.view_afm.val();
        self.core.view_acr.next = self.view.view_acr.val();
        self.core.view_amr.next = self.view.view_amr.val();
        self.core.view_cap_rearm.next = self.view.view_cap_rearm.val();
    }
}
