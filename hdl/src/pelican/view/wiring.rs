//! The wiring of the SJA1000 register block ([`super::PelicanView`]): the bus
//! access and its decode, every block's inputs, the read multiplexer and the
//! core's drive (pelican_contract.md §2-§14). A child module of `super` so
//! that it reaches the view's private blocks.

use super::*;

impl Logic for PelicanView {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, ack_q, err_q, dat_q, dmr_done_q, err_state_q);
        self.mc.clk.next = self.clk.val();
        self.ints.clk.next = self.clk.val();
        self.cfg.clk.next = self.clk.val();
        self.ext.clk.next = self.clk.val();
        self.win.clk.next = self.clk.val();
        self.txb.clk.next = self.clk.val();
        self.rx_start.clk.next = self.clk.val();
        self.alc.clk.next = self.clk.val();
        self.ecc.clk.next = self.clk.val();
        // ---- the bus access (P-BUS-1..4) ----
        self.take.next =
            self.wb_cyc_i.val() & self.wb_stb_i.val() & !(self.ack_q.q.val() | self.err_q.q.val());
        self.lanes.adr.next = self.wb_adr_i.val();
        self.lanes.sel.next = self.wb_sel_i.val();
        self.lanes.we.next = self.wb_we_i.val();
        self.lanes.wdat.next = self.wb_dat_i.val();
        self.wr.next = self.take.val() & self.wb_we_i.val() & !self.lanes.refused.val();
        self.rd.next = self.take.val() & !self.wb_we_i.val() & !self.lanes.refused.val();
        self.single_b.next = self.ext.xmode.val().get_bits::<2>(0) == self.mode_single_b.val();
        self.single.next = self.single_b.val()
            | (self.ext.xmode.val().get_bits::<2>(0) == self.mode_single_a.val());
        // ---- the logical controller (§5) ----
        self.logical.clk.next = self.clk.val();
        self.logical.rst.next = self.rst.val();
        self.logical.boh.next = self.mc.boh.val();
        self.logical.rep.next = self.ext.xmode.val().get_bit(7);
        self.logical.mode.next = self.ext.xmode.val().get_bits::<2>(0);
        self.logical.policy.next = self.ext.xmode.val().get_bits::<2>(2);
        self.logical.rm.next = self.mc.rm.val();
        self.logical.hrm.next = self.mc.hrm.val();
        self.logical.tx_channel.next = self.tx_channel.val();
        self.logical.acl.next = self.acl.val();
        self.logical.aux_a_state.next = self.aux_a_state.val();
        self.logical.aux_b_state.next = self.aux_b_state.val();
        self.logical.err_state_a.next = self.chan_a_err_state.val();
        self.logical.ew_a.next = self.chan_a_err_warning.val();
        self.logical.tec_a.next = self.chan_a_tec.val();
        self.logical.rec_a.next = self.chan_a_rec.val();
        self.logical.boff_runs_a.next = self.chan_a_boff_runs.val();
        self.logical.field_a.next = self.chan_a_field.val();
        self.logical.is_tx_a.next = self.chan_a_is_tx.val();
        self.logical.err_state_b.next = self.chan_b_err_state.val();
        self.logical.ew_b.next = self.chan_b_err_warning.val();
        self.logical.tec_b.next = self.chan_b_tec.val();
        self.logical.rec_b.next = self.chan_b_rec.val();
        self.logical.boff_runs_b.next = self.chan_b_boff_runs.val();
        self.logical.field_b.next = self.chan_b_field.val();
        self.logical.is_tx_b.next = self.chan_b_is_tx.val();
        // channel u's events and captures (P-IR-4, P-CAP-1, P-CAP-2)
        if self.logical.u.val() {
            self.err_state_u.next = self.chan_b_err_state.val();
            self.ecc_code.err_kind.next = self.chan_b_err_kind.val();
            self.ecc_code.err_field.next = self.chan_b_err_field.val();
            self.ecc_code.err_tx.next = self.chan_b_err_tx.val();
            self.ecc.pulse.next = self.chan_b_err_valid.val();
            self.alc.pulse.next = self.chan_b_arb_lost.val();
            self.alc.value.next = bit_cast::<8, 5>(self.chan_b_alc.val());
        } else {
            self.err_state_u.next = self.chan_a_err_state.val();
            self.ecc_code.err_kind.next = self.chan_a_err_kind.val();
            self.ecc_code.err_field.next = self.chan_a_err_field.val();
            self.ecc_code.err_tx.next = self.chan_a_err_tx.val();
            self.ecc.pulse.next = self.chan_a_err_valid.val();
            self.alc.pulse.next = self.chan_a_arb_lost.val();
            self.alc.value.next = bit_cast::<8, 5>(self.chan_a_alc.val());
        }
        self.ecc_code.passive.next = self.err_state_u.val() == self.passive.val();
        self.ecc.value.next = self.ecc_code.ecc.val();
        self.alc.read.next = self.rd.val() & (self.lanes.reg_num.val() == self.a_alc.val());
        self.ecc.read.next = self.rd.val() & (self.lanes.reg_num.val() == self.a_ecc.val());
        self.alc.rst.next = self.rst.val();
        self.ecc.rst.next = self.rst.val();
        // ---- MOD, CMR and the message's completion (§4, §6, §7) ----
        self.mc.rst.next = self.rst.val();
        self.mc.mod_write.next = self.wr.val() & (self.lanes.reg_num.val() == self.a_mod.val());
        self.mc.cmr_write.next = self.wr.val() & (self.lanes.reg_num.val() == self.a_cmr.val());
        self.mc.wdata.next = self.lanes.wbyte.val().get_bits::<5>(0);
        self.mc.reconfig.next = self.cfg.reconfig.val() | self.ext.reconfig.val();
        self.mc.single.next = self.single.val();
        self.mc.bom.next = self.ext.xmode.val().get_bit(6);
        self.mc.bs_rise.next = self.ints.bs_rise.val();
        self.mc.overrun.next = self.rx_overrun.val() & !self.mc.rm.val();
        // RRB pops while the FIFO holds a frame and the view is operating
        self.mc.rx_ready.next = self.rx_count.val().any() & !self.mc.rm.val();
        // P-TX-7: the completion of the message in the core
        self.mc.tx_ok.next = true;
        if self.single.val() {
            if self.single_b.val() {
                self.mc.tx_complete.next = self.chan_b_tx_done.val() | self.chan_b_tx_failed.val();
                self.mc.tx_ok.next = self.chan_b_tx_done.val();
            } else {
                self.mc.tx_complete.next = self.chan_a_tx_done.val() | self.chan_a_tx_failed.val();
                self.mc.tx_ok.next = self.chan_a_tx_done.val();
            }
        } else if self.ext.xmode.val().get_bits::<2>(0) == self.mode_dmr.val() {
            self.mc.tx_complete.next = self.dmr_done_q.q.val();
        } else {
            self.mc.tx_complete.next = self.tx_success.val();
        }
        if self.mc.tbs.val() {
            self.mc.tx_complete.next = false;
        }
        self.dmr_done_q.d.next = self.dmr_tx_done.val();
        // ---- interrupts (§9) ----
        self.ints.rst.next = self.rst.val();
        self.ints.ier_write.next = self.wr.val() & (self.lanes.reg_num.val() == self.a_ier.val());
        self.ints.wdata.next = self.lanes.wbyte.val();
        self.ints.ir_read.next = self.rd.val() & (self.lanes.reg_num.val() == self.a_ir.val());
        self.ints.rm.next = self.mc.rm.val();
        self.ints.rm_rise.next = self.mc.rm_rise.val();
        self.ints.rbs.next = self.rx_ready.val();
        self.ints.ti_evt.next = self.mc.ti_evt.val();
        self.ints.doi_evt.next = self.mc.doi_evt.val();
        self.ints.bei_evt.next = self.ecc.pulse.val();
        self.ints.ali_evt.next = self.alc.pulse.val();
        self.ints.es.next = self.logical.es.val();
        self.ints.bs.next = self.logical.bs.val();
        self.ints.err_state.next = self.logical.err_state_r.val();
        self.ints.xir_pending.next = self.ext.xir_pending.val();
        // ---- configuration, buffers, extension ----
        self.cfg.rst.next = self.rst.val();
        self.cfg.wr.next = self.wr.val();
        self.cfg.addr.next = self.lanes.reg_num.val();
        self.cfg.wdata.next = self.lanes.wbyte.val();
        self.cfg.rm.next = self.mc.rm.val();
        self.txb.rst.next = self.rst.val();
        self.txb.wr.next = self.wr.val();
        self.txb.addr.next = self.lanes.reg_num.val();
        self.txb.wdata.next = self.lanes.wbyte.val();
        self.txb.rm.next = self.mc.rm.val();
        self.txb.tbs.next = self.mc.tbs.val();
        self.rxwin.frame.next = self.rx_head.val().get_bits::<99>(0);
        self.rxwin.addr.next = self.lanes.reg_num.val();
        self.rx_start.rst.next = self.rst.val();
        self.rx_start.pop.next = self.mc.pop.val();
        self.rx_start.rtr.next = self.rx_head.val().get_bit(98);
        self.rx_start.ide.next = self.rx_head.val().get_bit(97);
        self.rx_start.dlc.next = self.rx_head.val().get_bits::<4>(64);
        self.rx_start.write.next =
            self.wr.val() & (self.lanes.reg_num.val() == self.a_rbsa.val()) & self.mc.rm.val();
        self.rx_start.wdata.next = self.lanes.wbyte.val().get_bits::<6>(0);
        // writes the view ignores with XIR.ign: counters (P-BO-5), the RX RAM (P-MAP-3)
        self.ign.next = self.mc.ign_evt.val();
        if self.wr.val() & self.mc.rm.val() {
            if ((self.lanes.reg_num.val() == self.a_rxerr.val())
                | (self.lanes.reg_num.val() == self.a_txerr.val()))
                & (self.mc.boh.val() | self.lanes.wbyte.val().any())
            {
                self.ign.next = true;
            }
            if (self.lanes.reg_num.val().get_bits::<2>(5) == self.page_ram_lo.val())
                | (self.lanes.reg_num.val().get_bits::<2>(5) == self.page_ram_hi.val())
            {
                self.ign.next = true;
            }
        }
        self.ext.rst.next = self.rst.val();
        self.ext.wr.next = self.wr.val();
        self.ext.rd.next = self.rd.val();
        self.ext.addr.next = self.lanes.reg_num.val();
        self.ext.wdata.next = self.lanes.wbyte.val();
        self.ext.rm.next = self.mc.rm.val();
        self.ext.ev_switch.next = self.ev_switch.val();
        self.ext.ev_aux.next = self.ev_aux.val();
        self.ext.ev_dmr.next = self.ev_dmr.val();
        self.ext.ev_domain.next = self.ev_domain.val();
        self.ext.ev_err_state.next = self.err_state_q.q.val()
            != ((bit_cast::<4, 2>(self.chan_b_err_state.val()) << 2)
                | bit_cast::<4, 2>(self.chan_a_err_state.val()));
        self.err_state_q.d.next = (bit_cast::<4, 2>(self.chan_b_err_state.val()) << 2)
            | bit_cast::<4, 2>(self.chan_a_err_state.val());
        self.ext.ev_bus.next = self.take.val() & self.lanes.refused.val();
        self.ext.ev_ign.next = self.ign.val();
        self.ext.ev_win.next = self.win.refused.val();
        self.ext.u.next = self.logical.u.val();
        self.ext.failover.next = self.failover.val();
        self.ext.aux_a_state.next = self.aux_a_state.val();
        self.ext.aux_b_state.next = self.aux_b_state.val();
        self.ext.boh.next = self.mc.boh.val();
        self.ext.rbs.next = self.rx_ready.val();
        self.ext.head_ch.next = self.rx_head.val().get_bit(99);
        self.ext.err_state_a.next = self.chan_a_err_state.val();
        self.ext.err_state_b.next = self.chan_b_err_state.val();
        self.ext.ew_a.next = self.chan_a_err_warning.val();
        self.ext.ew_b.next = self.chan_b_err_warning.val();
        self.ext.fsm_state.next = self.state.val();
        self.ext.dmr_state.next = self.dmr_state.val();
        self.ext.acl.next = self.acl.val();
        self.ext.split.next = self.star_split.val();
        // ---- the native window (P-X-3, P-X-4) ----
        self.win.rst.next = self.rst.val();
        self.win.wr.next = self.wr.val();
        self.win.addr.next = self.lanes.reg_num.val();
        self.win.wdata.next = self.lanes.wbyte.val();
        self.win.hrm.next = self.mc.hrm.val();
        self.win.nat_rdat.next = self.nat_rdat.val();
        self.win.nat_err.next = self.nat_err.val();
        self.nat_cyc.next = self.win.nat_cyc.val();
        self.nat_we.next = self.win.nat_we.val();
        self.nat_adr.next = self.win.nat_adr.val();
        self.nat_wdat.next = self.win.nat_wdat.val();
        self.view_cap_rearm.next = self.win.cap_rearm.val();
        // ---- the read multiplexer (P-MAP-1) ----
        self.sr.next = (bit_cast::<8, 1>(self.logical.bs.val().into()) << 7)
            | (bit_cast::<8, 1>(self.logical.es.val().into()) << 6)
            | (bit_cast::<8, 1>(self.logical.ts.val().into()) << 5)
            | (bit_cast::<8, 1>(self.logical.rs.val().into()) << 4)
            | (bit_cast::<8, 1>(self.mc.tcs.val().into()) << 3)
            | (bit_cast::<8, 1>(self.mc.tbs.val().into()) << 2)
            | (bit_cast::<8, 1>(self.mc.dos.val().into()) << 1)
            | bit_cast::<8, 1>(self.rx_ready.val().into());
        self.rbyte.next = self.cfg.rdata.val()
            | self.ext.rdata.val()
            | self.win.rdata.val()
            | self.txb.rdata.val();
        if !self.mc.rm.val() {
            self.rbyte.next = self.rbyte.val() | self.rxwin.rdata.val();
        }
        match self.lanes.reg_num.val().index() {
            0 => self.rbyte.next = self.mc.mod_q.val(),
            2 => self.rbyte.next = self.sr.val(),
            3 => self.rbyte.next = self.ints.ir_q.val(),
            4 => self.rbyte.next = self.ints.ier_q.val(),
            11 => self.rbyte.next = self.alc.q.val(),
            12 => self.rbyte.next = self.ecc.q.val(),
            14 => self.rbyte.next = self.logical.rxerr.val(),
            15 => self.rbyte.next = self.logical.txerr.val(),
            29 => self.rbyte.next = bit_cast::<8, 6>(self.rx_count.val()),
            30 => self.rbyte.next = self.rx_start.rbsa.val(),
            _ => {}
        }
        self.lanes.rbyte.next = self.rbyte.val();
        // ---- the bus response, one clock after the access ----
        self.ack_q.d.next = self.take.val() & !self.lanes.refused.val();
        self.err_q.d.next = self.take.val() & self.lanes.refused.val();
        self.dat_q.d.next = self.zero32.val();
        if self.rd.val() {
            self.dat_q.d.next = self.lanes.rdat.val();
        }
        if self.rst.val() {
            self.ack_q.d.next = false;
            self.err_q.d.next = false;
            self.dmr_done_q.d.next = false;
            self.err_state_q.d.next = self.zero4.val();
        }
        self.wb_ack_o.next = self.ack_q.q.val();
        self.wb_err_o.next = self.err_q.q.val();
        self.wb_dat_o.next = self.dat_q.q.val();
        self.irq.next = self.ints.irq.val();
        // ---- the core's drive (P-CFG-2, P-CFG-3, §14) ----
        if self.mc.lom.val() {
            self.chan_mode.next = self.m_listen_only.val();
        } else if self.mc.stm.val() {
            self.chan_mode.next = self.m_self_test.val();
        } else {
            self.chan_mode.next = self.m_normal.val();
        }
        self.ctrl.next = bit_cast::<32, 1>(self.mc.rm.val().into())
            | (bit_cast::<32, 4>(self.ext.xk.val()) << 8);
        self.view_chan_reset.next = self.zero2.val();
        if self.single_b.val() {
            self.ctrl.next = self.ctrl.val() | (bit_cast::<32, 2>(self.chan_mode.val()) << 14);
            self.view_chan_reset.next = self.bit_a.val();
        } else if self.single.val() {
            self.ctrl.next = self.ctrl.val() | (bit_cast::<32, 2>(self.chan_mode.val()) << 12);
            self.view_chan_reset.next = self.bit_b.val();
        } else {
            // REDUNDANCY, DMR: both channels in mode M, policy, dual_tx, star
            self.ctrl.next = self.ctrl.val()
                | self.ctrl_redundancy.val()
                | (bit_cast::<32, 2>(self.chan_mode.val()) << 12)
                | (bit_cast::<32, 2>(self.chan_mode.val()) << 14)
                | (bit_cast::<32, 4>(self.ext.xmode.val().get_bits::<4>(2)) << 2);
            if (self.ext.xmode.val().get_bits::<2>(0) == self.mode_dmr.val()) & !self.mc.lom.val() {
                self.ctrl.next =
                    (self.ctrl.val() & !self.ctrl_redundancy.val()) | self.ctrl_dmr.val();
            }
        }
        if self.mc.chan_reset.val() {
            self.view_chan_reset.next = self.both.val();
        }
        self.view_ctrl.next = self.ctrl.val();
        self.view_btr.next = self.cfg.view_btr.val();
        self.view_push.next = self.mc.push.val();
        self.view_push_q.next = self.single_b.val();
        self.view_push_frame.next = self.txb.frame.val();
        self.view_pop.next = self.mc.pop.val();
        self.view_tx_single.next = self.mc.one_shot.val() & self.single.val();
        // P-BO-3: a held bus-off channel neither counts nor keeps a frame;
        // P-TX-3: the host's abort in the single modes
        self.tx_abort.next = self.zero2.val();
        self.boff_hold.next = self.zero2.val();
        if self.mc.boh.val() {
            if self.chan_a_tx_pending.val() {
                self.tx_abort.next = self.tx_abort.val() | self.bit_a.val();
            }
            if self.chan_b_tx_pending.val() {
                self.tx_abort.next = self.tx_abort.val() | self.bit_b.val();
            }
            if self.chan_a_err_state.val() == self.bus_off.val() {
                self.boff_hold.next = self.boff_hold.val() | self.bit_a.val();
            }
            if self.chan_b_err_state.val() == self.bus_off.val() {
                self.boff_hold.next = self.boff_hold.val() | self.bit_b.val();
            }
        }
        if self.mc.abort_req.val() & self.single.val() {
            if self.single_b.val() {
                self.tx_abort.next = self.tx_abort.val() | self.bit_b.val();
            } else {
                self.tx_abort.next = self.tx_abort.val() | self.bit_a.val();
            }
        }
        self.view_tx_abort.next = self.tx_abort.val();
        self.view_boff_hold.next = self.boff_hold.val();
        self.self_norm.frame.next = self.txb.frame.val();
        self.view_offer_s.next = self.mc.self_offer.val();
        self.view_frame_s.next = self.self_norm.normalized.val();
        self.view_gate_on.next = true;
        self.view_afm.next = self.mc.afm.val();
        self.view_acr.next = self.cfg.acr.val();
        self.view_amr.next = self.cfg.amr.val();
    }
}
