//! The wiring of the DRCC core ([`super::DrccCore`], DRCC contract §1-§9; DMR
//! contract §2-§9; the host view of PeliCAN contract §14): every block's
//! inputs, the channels' configuration and TX frame, the register block's events
//! and read-only words, the probes and the view outputs. A child module of
//! `super` so that it reaches the core's private blocks; split from `mod.rs`,
//! which declares the ports and the blocks.

use super::*;

impl<const M: usize> Logic for DrccCore<M> {
    #[hdl_gen]
    fn update(&mut self) {
        // reset mode empties the queues and the FIFO; the RMB runs in redundancy
        // mode only
        self.clear.next = self.rst.val() | self.regs.reset_mode.val();
        self.rmb_hold.next =
            self.rst.val() | self.regs.reset_mode.val() | !self.regs.redundancy.val();
        // the channels' reset: rst, and reset mode with one more clock (§6) or,
        // behind a host view, the view's (P-CORE-3)
        if self.view_on.val() {
            self.chan_reset_a.next = self.rst.val() | self.view_chan_reset.val().get_bit(0);
            self.chan_reset_b.next = self.rst.val() | self.view_chan_reset.val().get_bit(1);
        } else {
            self.chan_reset_a.next = self.clear.val() | self.regs.reset_mode_d.val();
            self.chan_reset_b.next = self.clear.val() | self.regs.reset_mode_d.val();
        }
        self.rx_frame_a.next = (bit_cast::<99, 1>(self.chan_a.rx_rtr.val().into()) << 98)
            | (bit_cast::<99, 1>(self.chan_a.rx_ide.val().into()) << 97)
            | (bit_cast::<99, 29>(self.chan_a.rx_id.val()) << 68)
            | (bit_cast::<99, 4>(self.chan_a.rx_dlc.val()) << 64)
            | bit_cast::<99, 64>(self.chan_a.rx_data.val());
        self.rx_frame_b.next = (bit_cast::<99, 1>(self.chan_b.rx_rtr.val().into()) << 98)
            | (bit_cast::<99, 1>(self.chan_b.rx_ide.val().into()) << 97)
            | (bit_cast::<99, 29>(self.chan_b.rx_id.val()) << 68)
            | (bit_cast::<99, 4>(self.chan_b.rx_dlc.val()) << 64)
            | bit_cast::<99, 64>(self.chan_b.rx_data.val());

        // ---- register block ----
        self.regs.clk.next = self.clk.val();
        self.regs.rst.next = self.rst.val();
        self.regs.wb_cyc_i.next = self.wb_cyc_i.val();
        self.regs.wb_stb_i.next = self.wb_stb_i.val();
        self.regs.wb_we_i.next = self.wb_we_i.val();
        self.regs.wb_adr_i.next = self.wb_adr_i.val();
        self.regs.wb_dat_i.next = self.wb_dat_i.val();
        self.regs.wb_sel_i.next = self.wb_sel_i.val();
        self.regs.view_on.next = self.view_on.val();
        self.regs.view_ctrl.next = self.view_ctrl.val();
        self.regs.view_btr.next = self.view_btr.val();
        self.regs.ro_word.next = self.status.word.val();
        self.regs.es_a.next = self.chan_a.err_state.val();
        self.regs.es_b.next = self.chan_b.err_state.val();
        self.regs.txq_a.next = self.txbuf.count_a.val();
        self.regs.txq_b.next = self.txbuf.count_b.val();
        self.regs.rx_count.next = self.rxfifo.count.val();
        self.regs.ev_rx.next = self.rxw.rx_evt.val();
        self.regs.ev_tx_done.next = self.txbuf.done_evt.val()
            | self.main.success_evt.val()
            | self.dmr_ctl.tx_done_evt.val();
        self.regs.ev_switch.next = self.main.switch_evt.val();
        self.regs.ev_overrun.next = self.rxw.overrun_evt.val();
        self.regs.ev_tx_failure.next = self.txbuf.failed_evt.val() | self.main.fail_evt.val();
        self.regs.ev_aux.next = self.aux_a.fail_evt.val()
            | self.aux_a.recover_evt.val()
            | self.aux_b.fail_evt.val()
            | self.aux_b.recover_evt.val();
        self.wb_dat_o.next = self.regs.wb_dat_o.val();
        self.wb_ack_o.next = self.regs.wb_ack_o.val();
        self.wb_err_o.next = self.regs.wb_err_o.val();
        self.irq.next = self.regs.irq.val();
        // the registers kept outside the block: DMR (25..35) and filters (§11.1)
        self.regs.ext_hit.next =
            self.dmr_check.hit.val() | self.filters.hit.val() | self.ecss_regs.hit.val();
        self.regs.ext_word.next =
            self.dmr_check.word.val() | self.filters.word.val() | self.ecss_regs.word.val();
        self.regs.ext_writable.next =
            self.dmr_check.writable.val() | self.filters.hit.val() | self.ecss_regs.writable.val();
        self.regs.ext_illegal.next = self.dmr_check.illegal.val()
            | self.filters.illegal.val()
            | self.ecss_regs.illegal.val();
        self.regs.ev_bus_toggle.next = self.ecss.ev_toggle.val();
        // ---- ECSS bus selection (§12) ----
        self.ecss_regs.clk.next = self.clk.val();
        self.ecss_regs.rst.next = self.rst.val();
        self.ecss_regs.wr.next = self.regs.wr_o.val();
        self.ecss_regs.adr.next = self.wb_adr_i.val();
        self.ecss_regs.wdat.next = self.wb_dat_i.val();
        self.ecss_regs.reset_mode.next = self.regs.reset_mode.val();
        // ECSS_STATUS: the selection's fields and Ctoggle in [7:0]
        self.ecss_regs.status_word.next =
            self.ecss.word.val() | bit_cast::<32, 8>(self.ecss_count.count.val());
        self.ecss_count.clk.next = self.clk.val();
        self.ecss_count.clear.next = self.rst.val() | self.regs.stats_clear.val();
        self.ecss_count.toggled.next = self.ecss.toggled.val();
        self.ecss.clk.next = self.clk.val();
        self.ecss.rst.next = self.rst.val();
        self.ecss.on.next =
            self.regs.redundancy.val() & self.ecss_regs.enable.val() & !self.regs.reset_mode.val();
        self.ecss.hb_cnt.next = self.ecss_clock.count.val();
        self.ecss_clock.clk.next = self.clk.val();
        self.ecss_clock.tick.next = self.ticker.tick.val();
        self.ecss_clock.restart.next = self.ecss.clock_restart.val();
        self.ecss_clock.run.next = self.ecss.clock_run.val();
        self.ecss.bdefault.next = self.ecss_regs.bdefault.val();
        self.ecss.ttoggle.next = self.ecss_regs.ttoggle.val();
        self.ecss.ntoggle.next = self.ecss_regs.ntoggle.val();
        self.ecss.period.next = self.ecss_regs.period.val();
        self.ecss.hb.next = self.ecss_regs.hb.val();
        self.ecss.rx_valid_a.next = self.chan_a.rx_valid.val();
        self.ecss.key_a.next = self.rx_frame_a.val().get_bits::<31>(68);
        self.ecss.rx_valid_b.next = self.chan_b.rx_valid.val();
        self.ecss.key_b.next = self.rx_frame_b.val().get_bits::<31>(68);
        self.filters.clk.next = self.clk.val();
        self.filters.rst.next = self.rst.val();
        self.filters.wr.next = self.regs.wr_o.val();
        self.filters.adr.next = self.wb_adr_i.val();
        self.filters.wdat.next = self.wb_dat_i.val();
        self.filters.reset_mode.next = self.regs.reset_mode.val();
        self.regs.ev_dmr.next = self.dmr_ctl.int_evt.val();
        self.regs.ev_domain.next = self.echo.ev_domain.val();
        self.regs.ev_err_warning.next = self.caps.ev_err_warning.val();
        self.regs.ev_arb_lost.next = self.caps.ev_arb_lost.val();
        self.regs.ev_bus_error.next = self.caps.ev_bus_error.val();
        // §11.3: which channel finished or dropped its frame
        self.regs.ev_tx_done_a.next = self.chan_a.tx_done.val();
        self.regs.ev_tx_done_b.next = self.chan_b.tx_done.val();
        self.regs.ev_tx_failure_a.next = self.chan_a.tx_failed.val();
        self.regs.ev_tx_failure_b.next = self.chan_b.tx_failed.val();

        // ---- the channels' captures (§10.2) ----
        self.caps.clk.next = self.clk.val();
        self.caps.rst.next = self.rst.val();
        self.caps.err_valid_a.next = self.chan_a.err_valid.val();
        self.caps.err_kind_a.next = self.chan_a.err_kind.val();
        self.caps.err_field_a.next = self.chan_a.err_field.val();
        self.caps.err_tx_a.next = self.chan_a.err_tx.val();
        self.caps.arb_lost_a.next = self.chan_a.arb_lost.val();
        self.caps.alc_a.next = self.chan_a.alc.val();
        self.caps.ew_a.next = self.chan_a.err_warning.val();
        self.caps.err_valid_b.next = self.chan_b.err_valid.val();
        self.caps.err_kind_b.next = self.chan_b.err_kind.val();
        self.caps.err_field_b.next = self.chan_b.err_field.val();
        self.caps.err_tx_b.next = self.chan_b.err_tx.val();
        self.caps.arb_lost_b.next = self.chan_b.arb_lost.val();
        self.caps.alc_b.next = self.chan_b.alc.val();
        self.caps.ew_b.next = self.chan_b.err_warning.val();
        self.caps.rearm_err.next = self.regs.rearm_err.val();
        self.caps.rearm_alc.next = self.regs.rearm_alc.val();
        self.caps.rearm_chan.next = self.view_cap_rearm.val();

        // ---- the mailboxes (DMR contract §4), generated with M > 0 ----
        self.mb_id_word.next = self.zero31.val();
        self.mb_mask.next = self.zero29.val();
        self.mb_state_word.next = self.zero32.val();
        self.eval_fault.next = false;
        self.eval_line.next = false;
        self.eval_tx.next = false;
        self.eval_deviation.next = false;
        self.eval_mb.next = self.zero4.val();
        for i in 0..M.min(1) {
            self.mailbox_cfg[i].clk.next = self.clk.val();
            // the memory's read port is the host's in reset mode, the engine's
            // while DMR runs (DMR contract §2.1)
            if self.regs.reset_mode.val() | !self.regs.dmr.val() {
                self.mailbox_cfg[i].read_address.next = self.dmr_regs.mb_sel.val();
            } else {
                self.mailbox_cfg[i].read_address.next = self.dmr_eng[i].cfg_addr.val();
            }
            self.mailbox_cfg[i].write_address.next = self.dmr_regs.mb_sel.val();
            self.mailbox_cfg[i].we_id.next = self.dmr_regs.mb_we_id.val();
            self.mailbox_cfg[i].we_mask.next = self.dmr_regs.mb_we_mask.val();
            self.mailbox_cfg[i].wdat.next = self.wb_dat_i.val().get_bits::<31>(0);
            self.mb_id_word.next = self.mailbox_cfg[i].id_word.val();
            self.mb_mask.next = self.mailbox_cfg[i].mask.val();
            self.dmr_eng[i].clk.next = self.clk.val();
            self.dmr_eng[i].hold.next = self.regs.reset_mode.val() | !self.regs.dmr.val();
            self.dmr_eng[i].clear_state.next = self.dmr_ctl.clear_mailboxes.val();
            self.dmr_eng[i].timeout.next = self.dmr_regs.timeout.val();
            self.dmr_eng[i].tx_dcl.next = self.dmr_ctl.raise_tx_dcl.val();
            self.dmr_eng[i].tx_rcl.next = self.dmr_ctl.raise_tx_rcl.val();
            self.dmr_eng[i].rx_dcl.next = self.dmr_ctl.raise_rx_dcl.val();
            self.dmr_eng[i].rx_rcl.next = self.dmr_ctl.raise_rx_rcl.val();
            self.dmr_eng[i].req_dcl.next = self.dmr_ctl.raise_req_dcl.val();
            self.dmr_eng[i].req_rcl.next = self.dmr_ctl.raise_req_rcl.val();
            self.dmr_eng[i].key_tx_dcl.next = self.dmr_ctl.key_tx_dcl.val();
            self.dmr_eng[i].key_tx_rcl.next = self.dmr_ctl.key_tx_rcl.val();
            self.dmr_eng[i].key_rx_dcl.next = self.dmr_ctl.key_rx_dcl.val();
            self.dmr_eng[i].key_rx_rcl.next = self.dmr_ctl.key_rx_rcl.val();
            self.dmr_eng[i].key_req_dcl.next = self.dmr_ctl.key_req_dcl.val();
            self.dmr_eng[i].key_req_rcl.next = self.dmr_ctl.key_req_rcl.val();
            self.dmr_eng[i].eval.next = self.dmr_ctl.raise_eval.val();
            self.dmr_eng[i].mb_enable.next = self.dmr_regs.mb_enable.val();
            self.dmr_eng[i].mb_limits.next = self.dmr_regs.mb_limits.val();
            self.dmr_eng[i].cfg_id_word.next = self.mailbox_cfg[i].id_word.val();
            self.dmr_eng[i].cfg_mask.next = self.mailbox_cfg[i].mask.val();
            self.dmr_eng[i].mb_sel.next = self.dmr_regs.mb_sel.val();
            self.mb_state_word.next = self.dmr_eng[i].mb_state_word.val();
            self.eval_fault.next = self.dmr_eng[i].fault.val();
            self.eval_line.next = self.dmr_eng[i].fault_line.val();
            self.eval_tx.next = self.dmr_eng[i].fault_tx.val();
            self.eval_deviation.next = self.dmr_eng[i].fault_deviation.val();
            self.eval_mb.next = self.dmr_eng[i].fault_mb.val();
        }

        // ---- DMR registers and mailbox memory (DMR contract §2) ----
        self.dmr_check.adr.next = self.wb_adr_i.val();
        self.dmr_check.wdat.next = self.wb_dat_i.val();
        self.dmr_check.reset_mode.next = self.regs.reset_mode.val();
        self.dmr_check.cfg_word.next = self.dmr_regs.cfg_word.val();
        self.dmr_check.time_word.next = self.dmr_regs.time_word.val();
        self.dmr_check.cs_id_dcl.next = self.dmr_regs.cs_id_dcl.val();
        self.dmr_check.cs_id_rcl.next = self.dmr_regs.cs_id_rcl.val();
        self.dmr_check.mb_sel.next = self.dmr_regs.mb_sel.val();
        self.dmr_check.mb_enable.next = self.dmr_regs.mb_enable.val();
        self.dmr_check.mb_limits.next = self.dmr_regs.mb_limits.val();
        self.dmr_check.mb_id_word.next = self.mb_id_word.val();
        self.dmr_check.mb_mask.next = self.mb_mask.val();
        self.dmr_check.status_word.next = self.dmr_ctl.status_word.val();
        self.dmr_check.cs_count_word.next = self.dmr_ctl.cs_count_word.val();
        self.dmr_check.rx_stats_word.next = (bit_cast::<32, 8>(self.rxw.expired.val()) << 24)
            | (bit_cast::<32, 8>(self.rxw.released.val()) << 16)
            | bit_cast::<32, 16>(self.rxw.pcl_frames.val());
        self.dmr_check.mb_state_word.next = self.mb_state_word.val();
        self.dmr_regs.clk.next = self.clk.val();
        self.dmr_regs.rst.next = self.rst.val();
        self.dmr_regs.wr.next = self.regs.wr_o.val();
        self.dmr_regs.adr.next = self.wb_adr_i.val();
        self.dmr_regs.wdat.next = self.wb_dat_i.val();
        self.dmr_regs.writable.next = self.dmr_check.writable.val();
        self.dmr_regs.refused.next = self.dmr_check.illegal.val();
        // ---- DMR function (DMR contract §3-§7): control and mailbox engine ----
        self.dmr_ctl.clk.next = self.clk.val();
        self.dmr_ctl.rst.next = self.rst.val();
        // DMR held outside DMR mode and in reset mode (DMR contract §2), written out
        // at each use: a local would close a false loop for Verilator (design.md)
        self.dmr_ctl.hold.next = self.regs.reset_mode.val() | !self.regs.dmr.val();
        self.dmr_ctl.timeout.next = self.dmr_regs.timeout.val();
        self.dmr_ctl.cs_period.next = self.dmr_regs.cs_period.val();
        self.dmr_ctl.tick_bits.next = self.dmr_regs.tick_bits.val();
        self.dmr_ctl.recovery_delay.next = self.dmr_regs.recovery_delay.val();
        self.dmr_ctl.cs_id_dcl.next = self.dmr_regs.cs_id_dcl.val();
        self.dmr_ctl.cs_id_rcl.next = self.dmr_regs.cs_id_rcl.val();
        self.dmr_ctl.tick.next = self.ticker.tick.val();
        self.dmr_ctl.reset_mode_q.next = self.regs.reset_mode_d.val();
        self.dmr_ctl.done_dcl.next = self.chan_a.tx_done.val();
        self.dmr_ctl.failed_dcl.next = self.chan_a.tx_failed.val();
        self.dmr_ctl.rx_valid_dcl.next = self.chan_a.rx_valid.val();
        self.dmr_ctl.rx_ide_dcl.next = self.chan_a.rx_ide.val();
        self.dmr_ctl.rx_rtr_dcl.next = self.chan_a.rx_rtr.val();
        self.dmr_ctl.rx_dlc_dcl.next = self.chan_a.rx_dlc.val();
        self.dmr_ctl.rx_id_dcl.next = self.chan_a.rx_id.val();
        self.dmr_ctl.err_state_dcl.next = self.chan_a.err_state.val();
        self.dmr_ctl.done_rcl.next = self.chan_b.tx_done.val();
        self.dmr_ctl.failed_rcl.next = self.chan_b.tx_failed.val();
        self.dmr_ctl.rx_valid_rcl.next = self.chan_b.rx_valid.val();
        self.dmr_ctl.rx_ide_rcl.next = self.chan_b.rx_ide.val();
        self.dmr_ctl.rx_rtr_rcl.next = self.chan_b.rx_rtr.val();
        self.dmr_ctl.rx_dlc_rcl.next = self.chan_b.rx_dlc.val();
        self.dmr_ctl.rx_id_rcl.next = self.chan_b.rx_id.val();
        self.dmr_ctl.err_state_rcl.next = self.chan_b.err_state.val();
        self.dmr_ctl.q_count.next = self.txbuf.count_a.val();
        self.dmr_ctl.rd_ide.next = self.txbuf.rd_frame.val().get_bit(97);
        self.dmr_ctl.rd_id.next = self.txbuf.rd_frame.val().get_bits::<29>(68);
        self.dmr_ctl.rd_sel.next = self.txbuf.rd_sel_o.val();
        self.dmr_ctl.eval_fault.next = self.eval_fault.val();
        self.dmr_ctl.eval_line.next = self.eval_line.val();
        self.dmr_ctl.eval_tx.next = self.eval_tx.val();
        self.dmr_ctl.eval_deviation.next = self.eval_deviation.val();
        self.dmr_ctl.eval_mb.next = self.eval_mb.val();

        // ---- read-only registers ----
        self.status.adr.next = self.wb_adr_i.val();
        self.status.reset_mode.next = self.regs.reset_mode.val();
        self.status.state.next = self.main.state.val();
        self.status.tx_channel.next = self.main.tx_channel.val();
        self.status.tx_going_on.next = self.main.tx_going_on.val();
        self.status.last_tx_time.next = self.main.last_tx_time.val();
        self.status.switch_time.next = self.main.switch_time.val();
        self.status.txq_a.next = self.txbuf.count_a.val();
        self.status.txq_b.next = self.txbuf.count_b.val();
        self.status.rx_count.next = self.rxfifo.count.val();
        self.status.es_a.next = self.chan_a.err_state.val();
        self.status.tec_a.next = self.chan_a.tec.val();
        self.status.rec_a.next = self.chan_a.rec.val();
        self.status.ew_a.next = self.chan_a.err_warning.val();
        self.status.es_b.next = self.chan_b.err_state.val();
        self.status.tec_b.next = self.chan_b.tec.val();
        self.status.rec_b.next = self.chan_b.rec.val();
        self.status.ew_b.next = self.chan_b.err_warning.val();
        self.status.aux_a_state.next = self.aux_a.aux_state.val();
        self.status.causes_a.next = self.aux_a.causes.val();
        self.status.fail_cnt_a.next = self.aux_a.fail_cnt.val();
        self.status.failures_a.next = self.aux_a.failures.val();
        self.status.recoveries_a.next = self.aux_a.recoveries.val();
        self.status.aux_b_state.next = self.aux_b.aux_state.val();
        self.status.causes_b.next = self.aux_b.causes.val();
        self.status.fail_cnt_b.next = self.aux_b.fail_cnt.val();
        self.status.failures_b.next = self.aux_b.failures.val();
        self.status.recoveries_b.next = self.aux_b.recoveries.val();
        self.status.rx_head.next = self.rxfifo.rd_data.val();
        self.status.now.next = self.ticker.now.val();
        self.status.rx_ready.next = self.rxfifo.rx_ready.val();
        self.status.duplicates.next = self.rxw.duplicates.val();
        self.status.overruns.next = self.rxw.overruns.val();
        self.status.switches.next = self.stats.switches.val();
        self.status.star_word.next = self.echo.star_word.val();
        self.status.omissions_a.next = self.rxw.omissions_a.val();
        self.status.omissions_b.next = self.rxw.omissions_b.val();
        self.status.recoveries.next = self.stats.recoveries.val();
        self.status.cap_a.next = self.caps.cap_a.val();
        self.status.cap_b.next = self.caps.cap_b.val();
        self.stats.clk.next = self.clk.val();
        // §11.4: STATS_CLR clears the counts as rst does
        self.stats.rst.next = self.rst.val() | self.regs.stats_clear.val();
        self.stats.switch_evt.next = self.main.switch_evt.val();
        self.stats.recover_a.next = self.aux_a.recover_evt.val();
        self.stats.recover_b.next = self.aux_b.recover_evt.val();

        // ---- bit tick ----
        self.ticker.clk.next = self.clk.val();
        self.ticker.hold.next = self.clear.val();
        self.ticker.brp.next = self.regs.brp.val();
        self.ticker.tseg1.next = self.regs.tseg1.val();
        self.ticker.tseg2.next = self.regs.tseg2.val();

        // ---- main FSM (Table 1) ----
        self.main.clk.next = self.clk.val();
        self.main.rst.next = self.rst.val();
        self.main.hold.next = self.rmb_hold.val();
        // §4.4: a star node sends the dual_tx copy only after the hubs split (§4.5).
        self.main.dual_tx.next =
            self.regs.dual_tx.val() & (!self.regs.star.val() | self.echo.star_split.val());
        self.main.queued.next = self.txbuf.count_a.val().any();
        // §12.2: under the ECSS policy the bus in use is the only valid channel
        if self.regs.redundancy.val() & self.ecss_regs.enable.val() {
            self.main.valid_a.next = !self.ecss.bus.val();
            self.main.valid_b.next = self.ecss.bus.val();
        } else {
            self.main.valid_a.next = self.aux_a.valid.val();
            self.main.valid_b.next = self.aux_b.valid.val();
        }
        self.main.pending_a.next = self.chan_a.tx_pending.val();
        self.main.pending_b.next = self.chan_b.tx_pending.val();
        self.main.done_a.next = self.chan_a.tx_done.val();
        self.main.done_b.next = self.chan_b.tx_done.val();
        self.main.failed_a.next = self.chan_a.tx_failed.val();
        self.main.failed_b.next = self.chan_b.tx_failed.val();
        self.main.tick.next = self.ticker.tick.val();
        self.main.echo_a.next = self.echo.echo_a.val();
        self.main.echo_b.next = self.echo.echo_b.val();

        // ---- star node: the echo of the attempted head message (§4.4), the
        // hubs' identification frames (§4.5) ----
        self.echo.clk.next = self.clk.val();
        self.echo.star.next = self.regs.star.val();
        self.echo.clear.next = self.rmb_hold.val();
        self.echo.attempted.next = self.main.attempted.val();
        self.echo.head.next = self.txbuf.rd_frame.val();
        self.echo.rx_valid_a.next = self.chan_a.rx_valid.val();
        self.echo.frame_a.next = self.rx_frame_a.val();
        self.echo.rx_valid_b.next = self.chan_b.rx_valid.val();
        self.echo.frame_b.next = self.rx_frame_b.val();

        // ---- auxiliary FSMs ----
        self.aux_a.clk.next = self.clk.val();
        self.aux_a.rst.next = self.rst.val() | self.regs.stats_clear.val();
        // P-CORE-3: behind a host view only the channel's reset holds it
        self.aux_a.hold.next = self.rmb_hold.val();
        if self.view_on.val() {
            self.aux_a.hold.next = self.rst.val()
                | self.view_chan_reset.val().get_bit(0)
                | !self.regs.redundancy.val();
        }
        self.aux_a.policy.next = self.regs.policy.val();
        self.aux_a.k.next = self.regs.k.val();
        self.aux_a.stall_limit.next = self.regs.stall_limit.val();
        self.aux_a.recovery_bits.next = self.regs.recovery_bits.val();
        self.aux_a.tick.next = self.ticker.tick.val();
        self.aux_a.in_use.next = self.main.in_use_a.val();
        // restart only at bus idle, B only while A is valid (contract §5)
        self.aux_a.restart_ok.next = self.chan_a.field.val() == Field::Idle;
        self.aux_a.err_valid.next = self.chan_a.err_valid.val();
        self.aux_a.err_tx.next = self.chan_a.err_tx.val();
        self.aux_a.tx_done.next = self.chan_a.tx_done.val();
        self.aux_a.tx_pending.next = self.chan_a.tx_pending.val();
        self.aux_a.rx_valid.next = self.chan_a.rx_valid.val();
        self.aux_a.err_state.next = self.chan_a.err_state.val();
        self.aux_a.err_warning.next = self.chan_a.err_warning.val();
        self.aux_a.sample_point.next = self.chan_a.sample_point.val();
        self.aux_b.clk.next = self.clk.val();
        self.aux_b.rst.next = self.rst.val() | self.regs.stats_clear.val();
        self.aux_b.hold.next = self.rmb_hold.val();
        if self.view_on.val() {
            self.aux_b.hold.next = self.rst.val()
                | self.view_chan_reset.val().get_bit(1)
                | !self.regs.redundancy.val();
        }
        self.aux_b.policy.next = self.regs.policy.val();
        self.aux_b.k.next = self.regs.k.val();
        self.aux_b.stall_limit.next = self.regs.stall_limit.val();
        self.aux_b.recovery_bits.next = self.regs.recovery_bits.val();
        self.aux_b.tick.next = self.ticker.tick.val();
        self.aux_b.in_use.next = self.main.in_use_b.val();
        self.aux_b.restart_ok.next =
            (self.chan_b.field.val() == Field::Idle) & self.aux_a.valid.val();
        self.aux_b.err_valid.next = self.chan_b.err_valid.val();
        self.aux_b.err_tx.next = self.chan_b.err_tx.val();
        self.aux_b.tx_done.next = self.chan_b.tx_done.val();
        self.aux_b.tx_pending.next = self.chan_b.tx_pending.val();
        self.aux_b.rx_valid.next = self.chan_b.rx_valid.val();
        self.aux_b.err_state.next = self.chan_b.err_state.val();
        self.aux_b.err_warning.next = self.chan_b.err_warning.val();
        self.aux_b.sample_point.next = self.chan_b.sample_point.val();

        // ---- TX buffer ----
        self.txbuf.clk.next = self.clk.val();
        self.txbuf.clear.next = self.clear.val();
        self.txbuf.redundancy.next = self.regs.redundancy.val();
        self.txbuf.dmr.next = self.regs.dmr.val();
        self.txbuf.off_dcl.next = self.dmr_ctl.off_dcl.val().get_bits::<3>(0);
        self.txbuf.off_rcl.next = self.dmr_ctl.off_rcl.val().get_bits::<3>(0);
        self.txbuf.dmr_pop.next = self.dmr_ctl.pop.val();
        if self.view_on.val() {
            self.txbuf.push.next = self.view_push.val();
            self.txbuf.push_q.next = self.view_push_q.val();
            self.txbuf.push_frame.next = self.view_push_frame.val();
        } else {
            self.txbuf.push.next = self.regs.push.val();
            self.txbuf.push_q.next = self.regs.push_q.val();
            self.txbuf.push_frame.next = self.regs.tx_frame.val();
        }
        self.txbuf.pop_red.next = self.main.pop.val();
        self.txbuf.abort_a.next = self.regs.abort_a.val();
        self.txbuf.abort_b.next = self.regs.abort_b.val();
        self.txbuf.done_a.next = self.chan_a.tx_done.val();
        self.txbuf.failed_a.next = self.chan_a.tx_failed.val();
        self.txbuf.done_b.next = self.chan_b.tx_done.val();
        self.txbuf.failed_b.next = self.chan_b.tx_failed.val();

        // ---- RX path ----
        self.rxfifo.clk.next = self.clk.val();
        self.rxfifo.clear.next = self.clear.val();
        self.rxfifo.wr.next = self.rxw.fifo_wr.val();
        self.rxfifo.wr_data.next = self.rxw.fifo_data.val();
        self.rxfifo.pop.next = (self.regs.pop.val() & !self.view_on.val())
            | (self.view_pop.val() & self.view_on.val());
        self.rxw.clk.next = self.clk.val();
        self.rxw.rst.next = self.rst.val();
        self.rxw.clear.next = self.clear.val();
        self.rxw.dedup_on.next =
            (self.regs.redundancy.val() | self.regs.dmr.val()) & self.regs.window.val().any();
        // DMR: the ACL rule (DMR contract §8), or first copy with a history
        // (§8.1); CS frames never reach the RX path
        self.rxw.acl_rule.next =
            self.regs.dmr.val() & !(self.regs.first_copy.val() & self.regs.window.val().any());
        self.rxw.count_pcl.next = self.regs.dmr.val();
        self.rxw.acl.next = self.dmr_ctl.acl.val();
        self.rxw.release_set.next = self.dmr_ctl.acl_switch.val();
        self.rxw.window.next = self.regs.window.val();
        self.rxw.now.next = self.ticker.now.val();
        self.rxw.stats_clear.next = self.regs.stats_clear.val();
        self.rxw.filt_id0.next = self.filters.id0.val();
        self.rxw.filt_mask0.next = self.filters.mask0.val();
        self.rxw.filt_id1.next = self.filters.id1.val();
        self.rxw.filt_mask1.next = self.filters.mask1.val();
        self.rxw.tick.next = self.ticker.tick.val();
        // a host view's source S and acceptance gate (P-CORE-4)
        self.rxw.offer_s.next = self.view_offer_s.val();
        self.rxw.frame_s.next = self.view_frame_s.val();
        self.rxw.gate_on.next = self.view_gate_on.val();
        self.rxw.gate_afm.next = self.view_afm.val();
        self.rxw.gate_acr.next = self.view_acr.val();
        self.rxw.gate_amr.next = self.view_amr.val();
        if self.regs.reset_mode.val() | !self.regs.dmr.val() {
            // neither an echo (the node's own frame, §4.4) nor a hub's
            // identification frame (§4.5) is a reception
            self.rxw.rxv_a.next = self.echo.rxv_a.val();
            self.rxw.rxv_b.next = self.echo.rxv_b.val();
        } else {
            self.rxw.rxv_a.next = self.dmr_ctl.rx_deliver_dcl.val();
            self.rxw.rxv_b.next = self.dmr_ctl.rx_deliver_rcl.val();
        }
        self.rxw.frame_a.next = self.rx_frame_a.val();
        self.rxw.frame_b.next = self.rx_frame_b.val();
        self.rxw.fifo_count.next = self.rxfifo.count.val();

        // ---- channels: shared bit timing, own mode, TX RAM read data ----
        // channel rst = rst | reset_mode | reset_mode one edge earlier | dual-bus
        // restart | DMR restart (contract §6): the channels capture their
        // configuration while in reset
        self.chan_a.clk.next = self.clk.val();
        self.chan_a.rst.next = self.chan_reset_a.val()
            | (self.aux_a.chan_rst.val() & !self.regs.star.val())
            | self.dmr_ctl.restart_dcl.val();
        // §5: a star node's restart is soft (counters only, no re-integration)
        self.chan_a.err_reset.next = self.aux_a.chan_rst.val() & self.regs.star.val();
        // §11.6: with CTRL.busoff_manual the recovery waits for TX_CMD.recover_a
        self.busoff_a.clk.next = self.clk.val();
        self.busoff_a.rst.next = self.rst.val();
        self.busoff_a.busoff_manual.next = self.regs.busoff_manual.val();
        self.busoff_a.recover.next = self.regs.recover_a.val();
        self.busoff_a.err_state.next = self.chan_a.err_state.val();
        self.chan_a.boff_hold.next =
            self.busoff_a.boff_hold.val() | self.view_boff_hold.val().get_bit(0);
        // the native map has no per-frame single shot (CTRL.single_shot is per
        // channel); a view's is per request (P-CORE-1)
        self.chan_a.tx_single.next = self.view_tx_single.val();
        self.chan_a.cfg_brp.next = self.regs.brp.val();
        self.chan_a.cfg_tseg1.next = self.regs.tseg1.val();
        self.chan_a.cfg_tseg2.next = self.regs.tseg2.val();
        self.chan_a.cfg_sjw.next = self.regs.sjw.val();
        self.chan_a.cfg_triple.next = self.regs.triple.val();
        self.chan_a.cfg_mode.next = self.regs.mode_a.val();
        self.chan_a.cfg_ewl.next = self.regs.ewl.val();
        self.chan_a.cfg_single_shot.next =
            self.regs.single_shot.val() & !self.regs.redundancy.val() & !self.regs.dmr.val();
        self.chan_a.rx.next = self.chan_a_rx.val();
        self.chan_a.tx_req.next =
            self.main.req_a.val() | self.txbuf.req_a.val() | self.dmr_ctl.tx_req_dcl.val();
        self.chan_a.tx_abort.next = self.main.abort_a.val()
            | self.dmr_ctl.tx_abort_dcl.val()
            | self.txbuf.chan_abort_a.val()
            | self.view_tx_abort.val().get_bit(0);
        if self.dmr_ctl.cs_req_dcl.val() {
            // the CS frame of the line: base format, DLC 0, data frame (§7)
            self.chan_a.tx_rtr.next = false;
            self.chan_a.tx_ide.next = false;
            self.chan_a.tx_id.next = bit_cast::<29, 11>(self.dmr_regs.cs_id_dcl.val());
            self.chan_a.tx_dlc.next = bit_cast::<4, 1>(false.into());
            self.chan_a.tx_data.next = bit_cast::<64, 1>(false.into());
        } else {
            self.chan_a.tx_rtr.next = self.txbuf.rd_frame.val().get_bit(98);
            self.chan_a.tx_ide.next = self.txbuf.rd_frame.val().get_bit(97);
            self.chan_a.tx_id.next = self.txbuf.rd_frame.val().get_bits::<29>(68);
            self.chan_a.tx_dlc.next = self.txbuf.rd_frame.val().get_bits::<4>(64);
            self.chan_a.tx_data.next = self.txbuf.rd_frame.val().get_bits::<64>(0);
        }
        self.chan_b.clk.next = self.clk.val();
        self.chan_b.rst.next = self.chan_reset_b.val()
            | (self.aux_b.chan_rst.val() & !self.regs.star.val())
            | self.dmr_ctl.restart_rcl.val();
        // §5: a star node's restart is soft (counters only, no re-integration)
        self.chan_b.err_reset.next = self.aux_b.chan_rst.val() & self.regs.star.val();
        self.busoff_b.clk.next = self.clk.val();
        self.busoff_b.rst.next = self.rst.val();
        self.busoff_b.busoff_manual.next = self.regs.busoff_manual.val();
        self.busoff_b.recover.next = self.regs.recover_b.val();
        self.busoff_b.err_state.next = self.chan_b.err_state.val();
        self.chan_b.boff_hold.next =
            self.busoff_b.boff_hold.val() | self.view_boff_hold.val().get_bit(1);
        self.chan_b.tx_single.next = self.view_tx_single.val();
        self.chan_b.cfg_brp.next = self.regs.brp.val();
        self.chan_b.cfg_tseg1.next = self.regs.tseg1.val();
        self.chan_b.cfg_tseg2.next = self.regs.tseg2.val();
        self.chan_b.cfg_sjw.next = self.regs.sjw.val();
        self.chan_b.cfg_triple.next = self.regs.triple.val();
        self.chan_b.cfg_mode.next = self.regs.mode_b.val();
        self.chan_b.cfg_ewl.next = self.regs.ewl.val();
        self.chan_b.cfg_single_shot.next =
            self.regs.single_shot.val() & !self.regs.redundancy.val() & !self.regs.dmr.val();
        self.chan_b.rx.next = self.chan_b_rx.val();
        self.chan_b.tx_req.next =
            self.main.req_b.val() | self.txbuf.req_b.val() | self.dmr_ctl.tx_req_rcl.val();
        self.chan_b.tx_abort.next = self.main.abort_b.val()
            | self.dmr_ctl.tx_abort_rcl.val()
            | self.txbuf.chan_abort_b.val()
            | self.view_tx_abort.val().get_bit(1);
        if self.dmr_ctl.cs_req_rcl.val() {
            // the CS frame of the line: base format, DLC 0, data frame (§7)
            self.chan_b.tx_rtr.next = false;
            self.chan_b.tx_ide.next = false;
            self.chan_b.tx_id.next = bit_cast::<29, 11>(self.dmr_regs.cs_id_rcl.val());
            self.chan_b.tx_dlc.next = bit_cast::<4, 1>(false.into());
            self.chan_b.tx_data.next = bit_cast::<64, 1>(false.into());
        } else {
            self.chan_b.tx_rtr.next = self.txbuf.rd_frame.val().get_bit(98);
            self.chan_b.tx_ide.next = self.txbuf.rd_frame.val().get_bit(97);
            self.chan_b.tx_id.next = self.txbuf.rd_frame.val().get_bits::<29>(68);
            self.chan_b.tx_dlc.next = self.txbuf.rd_frame.val().get_bits::<4>(64);
            self.chan_b.tx_data.next = self.txbuf.rd_frame.val().get_bits::<64>(0);
        }
        self.chan_a_tx.next = self.chan_a.tx.val();
        self.chan_b_tx.next = self.chan_b.tx.val();

        // ---- probes ----
        self.state.next = self.main.state.val();
        self.tx_channel.next = self.main.tx_channel.val();
        self.transmission_ack.next = self.main.transmission_ack.val();
        self.chan_a_transmission_req.next = self.main.req_a.val() | self.txbuf.req_a.val();
        self.chan_b_transmission_req.next = self.main.req_b.val() | self.txbuf.req_b.val();
        self.tx_success.next = self.main.tx_success.val();
        self.tx_ok_channel.next = self.main.tx_ok_channel.val();
        self.tx_failure.next = self.main.tx_failure.val();
        self.tx_failure_channel.next = self.main.tx_failure_channel.val();
        self.tx_going_on.next = self.main.tx_going_on.val();
        self.chan_a_bsp_tx_err_cnt.next = self.chan_a.tec.val();
        self.chan_a_bsp_node_error_passive.next = self.chan_a.err_state.val().any();
        self.chan_b_bsp_tx_err_cnt.next = self.chan_b.tec.val();
        self.chan_b_bsp_node_error_passive.next = self.chan_b.err_state.val().any();
        self.aux_a_state.next = self.aux_a.aux_state.val();
        self.aux_b_state.next = self.aux_b.aux_state.val();
        self.chan_a_sample_point.next = self.chan_a.sample_point.val();
        self.chan_b_sample_point.next = self.chan_b.sample_point.val();
        self.chan_a_field.next = self.chan_a.field.val();
        self.chan_b_field.next = self.chan_b.field.val();
        self.chan_a_rec.next = self.chan_a.rec.val();
        self.chan_b_rec.next = self.chan_b.rec.val();
        self.chan_a_err_state.next = self.chan_a.err_state.val();
        self.chan_b_err_state.next = self.chan_b.err_state.val();
        self.dmr_state.next = self.dmr_ctl.dmr_state.val();
        self.acl.next = self.dmr_ctl.acl.val();
        self.dcl_tx_fault.next = self.dmr_ctl.dcl_tx_fault.val();
        self.dcl_rx_fault.next = self.dmr_ctl.dcl_rx_fault.val();
        self.rcl_tx_fault.next = self.dmr_ctl.rcl_tx_fault.val();
        self.rcl_rx_fault.next = self.dmr_ctl.rcl_rx_fault.val();
        self.dmr_tick.next = self.dmr_ctl.dmr_tick.val();

        // ---- view outputs (PeliCAN contract §14) ----
        self.rx_stored.next = self.rxw.rx_evt.val();
        self.rx_overrun.next = self.rxw.overrun_evt.val();
        self.rx_ready.next = self.rxfifo.rx_ready.val();
        self.rx_count.next = self.rxfifo.count.val();
        self.rx_head.next = self.rxfifo.rd_data.val();
        self.dmr_tx_done.next = self.dmr_ctl.tx_done_evt.val();
        self.ev_switch.next = self.main.switch_evt.val();
        self.ev_aux.next = self.regs.ev_aux.val();
        self.ev_dmr.next = self.dmr_ctl.int_evt.val();
        self.ev_domain.next = self.echo.ev_domain.val();
        self.star_split.next = self.echo.star_split.val();
        self.failover.next = self.main.failover.val();
        self.chan_a_tx_done.next = self.chan_a.tx_done.val();
        self.chan_a_tx_failed.next = self.chan_a.tx_failed.val();
        self.chan_a_tx_pending.next = self.chan_a.tx_pending.val();
        self.chan_a_is_tx.next = self.chan_a.is_tx.val();
        self.chan_a_boff_runs.next = self.chan_a.boff_runs.val();
        self.chan_a_err_warning.next = self.chan_a.err_warning.val();
        self.chan_a_tec.next = self.chan_a.tec.val();
        self.chan_a_err_valid.next = self.chan_a.err_valid.val();
        self.chan_a_err_kind.next = self.chan_a.err_kind.val();
        self.chan_a_err_field.next = self.chan_a.err_field.val();
        self.chan_a_err_tx.next = self.chan_a.err_tx.val();
        self.chan_a_arb_lost.next = self.chan_a.arb_lost.val();
        self.chan_a_alc.next = self.chan_a.alc.val();
        self.chan_b_tx_done.next = self.chan_b.tx_done.val();
        self.chan_b_tx_failed.next = self.chan_b.tx_failed.val();
        self.chan_b_tx_pending.next = self.chan_b.tx_pending.val();
        self.chan_b_is_tx.next = self.chan_b.is_tx.val();
        self.chan_b_boff_runs.next = self.chan_b.boff_runs.val();
        self.chan_b_err_warning.next = self.chan_b.err_warning.val();
        self.chan_b_tec.next = self.chan_b.tec.val();
        self.chan_b_err_valid.next = self.chan_b.err_valid.val();
        self.chan_b_err_kind.next = self.chan_b.err_kind.val();
        self.chan_b_err_field.next = self.chan_b.err_field.val();
        self.chan_b_err_tx.next = self.chan_b.err_tx.val();
        self.chan_b_arb_lost.next = self.chan_b.arb_lost.val();
        self.chan_b_alc.next = self.chan_b.alc.val();
    }
}
