//! The update of the receive writer ([`super::RxWriter`], DRCC contract §7, §11;
//! DMR contract §8): the history scan, the writer FSM, the FIFO port with the
//! acceptance filters' verdict and the timestamp, and the statistics strobes. A
//! child module of `super` so that it reaches the block's private registers;
//! split from `dedup.rs`, which declares the ports, the registers and the
//! generation parameters.

use super::*;

impl Logic for RxWriter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            w_state,
            rxp_a,
            rxp_b,
            rxf_a,
            rxf_b,
            sel,
            scan_i,
            hit,
            hit_e,
            free_found,
            free_e,
            hist_ptr,
            exp_q,
            hist_idle,
            forget,
            release_q,
            w_pcl,
            hit_hd,
            sel_s,
            s_pend,
            s_pend_frame,
            s_frame
        );
        self.hist.clk.next = self.clk.val();
        self.hist.read_enable.next = true;
        self.hist_ts.clk.next = self.clk.val();
        self.hist_ts.read_enable.next = true;
        self.flags.clk.next = self.clk.val();
        self.flags.read_enable.next = true;
        self.rel.clk.next = self.clk.val();
        self.rel.clear.next = self.clear.val();
        self.stats.clk.next = self.clk.val();
        self.stats.rst.next = self.rst.val() | self.stats_clear.val();

        // the frame being processed (latched at its rx_valid), and the history
        // entry being read
        if self.sel_s.q.val() {
            self.frame_sel.next = self.s_frame.q.val();
        } else if self.sel.q.val() {
            self.frame_sel.next = self.rxf_b.q.val();
        } else {
            self.frame_sel.next = self.rxf_a.q.val();
        }
        // masked to H entries, so every index register (free_e, hit_e, rel_e, the
        // slot) and the decoder below have constant upper bits with H < 32
        self.scan_e.next =
            (self.scan_i.q.val().get_bits::<5>(0) - self.one5.val()) & self.hmask.val();
        // where a new frame is recorded: the first free entry, else hist_ptr
        if self.free_found.q.val() {
            self.slot.next = self.free_e.q.val();
        } else {
            self.slot.next = self.hist_ptr.q.val();
        }
        // the one entry whose flags each state writes: the judged entry in a
        // scan, the hit entry in decide, the released entry in release, the
        // recorded slot in write
        if self.w_state.q.val() == self.s_decide.val() {
            self.flags.write_address.next = self.hit_e.q.val();
        } else if self.w_state.q.val() == self.s_release.val() {
            self.flags.write_address.next = self.rel.rel_e.val();
        } else if self.w_state.q.val() == self.s_write.val() {
            self.flags.write_address.next = self.slot.val();
        } else {
            self.flags.write_address.next = self.scan_e.val();
        }
        self.flags.write_enable.next = false;
        self.flags.write_data.next = self.flags.read_data.val();
        self.e_ch.next = self.hist.read_data.val().get_bit(0);
        self.e_frame.next = self.hist.read_data.val().get_bits::<99>(1);
        // timing: expiry one clock ahead (module doc). In scan, e_ts is the entry
        // judged at the next edge, when now will be now + tick:
        // (age + 1) mod 2^16 > window <=> age >= window && age != 0xFFFF.
        self.e_ts.next = self.hist_ts.read_data.val();
        self.e_age.next = self.now.val() - self.e_ts.val();
        self.e_gt.next = self.e_age.val() > bit_cast::<16, 15>(self.window.val());
        self.e_ge.next = self.e_age.val() >= bit_cast::<16, 15>(self.window.val());
        if self.tick.val() {
            self.exp_q.d.next = self.e_ge.val() & (self.e_age.val() != self.max16.val());
        } else {
            self.exp_q.d.next = self.e_gt.val();
        }
        // in scan, the flags of entry scan_e, read with its frame
        self.e_hv.next = self.flags.read_data.val().get_bit(0) & !self.forget.q.val();
        self.e_hu.next = self.flags.read_data.val().get_bit(1);
        self.e_hd.next = self.flags.read_data.val().get_bit(2);
        self.e_expired.next = self.exp_q.q.val();
        self.fifo_full.next = self.fifo_count.val() == self.fifo_depth.val();
        // both scans judge one entry per edge with scan_i >= 1
        self.in_scan.next = (self.w_state.q.val() == self.s_scan.val())
            | (self.w_state.q.val() == self.s_rscan.val());
        self.judging.next = self.in_scan.val() & (self.scan_i.q.val() != self.zero6.val());
        // §8: the frame in decide came from the passive line
        self.pcl.next = self.sel.q.val() != self.acl.val();
        // write: to the FIFO unless a PCL frame (it waits); to the history unless
        // it was the ACL copy of a waiting frame (hit)
        self.w_fifo.next = self.sel_s.q.val() | !(self.acl_rule.val() & self.w_pcl.q.val());
        self.w_hist.next = self.dedup_on.val() & !self.hit.q.val() & !self.sel_s.q.val();

        if self.w_state.q.val() == self.s_fetch.val() {
            self.hist.read_address.next = self.rel.rel_e.val();
        } else {
            self.hist.read_address.next = self.scan_i.q.val().get_bits::<5>(0) & self.hmask.val();
        }
        self.flags.read_address.next = self.scan_i.q.val().get_bits::<5>(0) & self.hmask.val();
        self.hist.write_enable.next = false;
        self.hist.write_address.next = self.slot.val();
        self.hist.write_data.next = (bit_cast::<100, 99>(self.frame_sel.val()) << 1)
            | bit_cast::<100, 1>(self.sel.q.val().into());
        // one entry ahead of `hist` (module doc)
        if self.in_scan.val() {
            self.hist_ts.read_address.next =
                (self.scan_i.q.val().get_bits::<5>(0) + self.one5.val()) & self.hmask.val();
        } else {
            self.hist_ts.read_address.next = self.zero5.val();
        }
        self.hist_ts.write_enable.next = false;
        self.hist_ts.write_address.next = self.slot.val();
        self.hist_ts.write_data.next = self.now.val();
        self.fifo_wr.next = false;
        if self.w_state.q.val() == self.s_release.val() {
            // §8: a released frame goes to the FIFO with channel acl
            self.fifo_data.next = (bit_cast::<116, 1>(self.acl.val().into()) << 99)
                | bit_cast::<116, 99>(self.e_frame.val());
        } else {
            self.fifo_data.next = (bit_cast::<116, 1>(self.sel.q.val().into()) << 99)
                | bit_cast::<116, 99>(self.frame_sel.val());
        }
        // §11.2: stamped with now at the write edge
        self.fifo_data.next = self.fifo_data.val() | (bit_cast::<116, 16>(self.now.val()) << 100);
        // §11.1: the filters judge the frame at the FIFO port, nothing before it
        self.f_word.next = self.fifo_data.val().get_bits::<31>(68);
        self.f_match0.next = self.filt_mask0.val().get_bit(31)
            & (((self.f_word.val() ^ self.filt_id0.val())
                & self.filt_mask0.val().get_bits::<31>(0))
                == self.zero31.val());
        self.f_match1.next = self.filt_mask1.val().get_bit(31)
            & (((self.f_word.val() ^ self.filt_id1.val())
                & self.filt_mask1.val().get_bits::<31>(0))
                == self.zero31.val());
        // P-RX-5: a host view's acceptance filter on the same frame
        self.acf.afm.next = self.gate_afm.val();
        self.acf.acr0.next = self.gate_acr.val().get_bits::<8>(0);
        self.acf.acr1.next = self.gate_acr.val().get_bits::<8>(8);
        self.acf.acr2.next = self.gate_acr.val().get_bits::<8>(16);
        self.acf.acr3.next = self.gate_acr.val().get_bits::<8>(24);
        self.acf.amr0.next = self.gate_amr.val().get_bits::<8>(0);
        self.acf.amr1.next = self.gate_amr.val().get_bits::<8>(8);
        self.acf.amr2.next = self.gate_amr.val().get_bits::<8>(16);
        self.acf.amr3.next = self.gate_amr.val().get_bits::<8>(24);
        self.acf.rtr.next = self.fifo_data.val().get_bit(98);
        self.acf.ide.next = self.fifo_data.val().get_bit(97);
        self.acf.id.next = self.fifo_data.val().get_bits::<29>(68);
        self.acf.dlc.next = self.fifo_data.val().get_bits::<4>(64);
        self.acf.data1.next = self.fifo_data.val().get_bits::<8>(56);
        self.acf.data2.next = self.fifo_data.val().get_bits::<8>(48);
        self.accept.next = (!(self.filt_mask0.val().get_bit(31)
            | self.filt_mask1.val().get_bit(31))
            | self.f_match0.val()
            | self.f_match1.val())
            & (!self.gate_on.val() | self.acf.accept.val());
        self.rx_evt.next = false;
        self.overrun_evt.next = false;
        // release scan: a candidate is a waiting frame of the ACL (§8)
        self.rel.start.next = false;
        self.r_cand.next = (self.w_state.q.val() == self.s_rscan.val())
            & self.judging.val()
            & self.e_hv.val()
            & !self.e_expired.val()
            & !self.e_hu.val()
            & !self.e_hd.val()
            & (self.e_ch.val() == self.acl.val());
        self.rel.cand.next = self.r_cand.val();
        self.rel.scan_e.next = self.scan_e.val();
        self.rel.next_age.next = self.e_age.val();
        self.rel.tick.next = self.tick.val();
        self.stats.pcl_inc.next = false;
        self.stats.released_inc.next = false;
        // §8: an undelivered, unmatched entry that expires in either scan
        self.stats.expired_inc.next = self.acl_rule.val()
            & self.judging.val()
            & self.e_hv.val()
            & self.e_expired.val()
            & !self.e_hu.val()
            & !self.e_hd.val();
        // §7 omissions: an entry only its channel delivered expires in scan
        self.omit.next = !self.acl_rule.val()
            & self.judging.val()
            & (self.w_state.q.val() == self.s_scan.val())
            & self.e_hv.val()
            & self.e_expired.val()
            & !self.e_hu.val();
        self.stats.omit_a.next = self.omit.val() & self.e_ch.val();
        self.stats.omit_b.next = self.omit.val() & !self.e_ch.val();
        self.stats.dup_inc.next = false;
        self.stats.overrun_inc.next = false;

        // defaults
        self.w_state.d.next = self.w_state.q.val();
        self.rxp_a.d.next = self.rxp_a.q.val();
        self.rxp_b.d.next = self.rxp_b.q.val();
        self.sel.d.next = self.sel.q.val();
        self.sel_s.d.next = self.sel_s.q.val();
        self.s_pend.d.next = self.s_pend.q.val();
        self.s_pend_frame.d.next = self.s_pend_frame.q.val();
        self.s_frame.d.next = self.s_frame.q.val();
        self.scan_i.d.next = self.scan_i.q.val();
        self.hit.d.next = self.hit.q.val();
        self.hit_e.d.next = self.hit_e.q.val();
        self.hit_hd.d.next = self.hit_hd.q.val();
        self.free_found.d.next = self.free_found.q.val();
        self.free_e.d.next = self.free_e.q.val();
        self.hist_ptr.d.next = self.hist_ptr.q.val();
        self.release_q.d.next = self.release_q.q.val();
        self.w_pcl.d.next = self.w_pcl.q.val();
        self.hist_idle.d.next = self.hist_idle.q.val();
        if self.tick.val() & (self.hist_idle.q.val() != self.max15.val()) {
            self.hist_idle.d.next = self.hist_idle.q.val() + self.one15.val();
        }
        // a history left idle for 32767 bit times is forgotten, so an entry is
        // never judged by a wrapped age
        self.forget_now.next = self.clear.val() | (self.hist_idle.q.val() == self.max15.val());
        self.forget.d.next = self.forget.q.val() | self.forget_now.val();
        // in scan: entry scan_e stays valid unless it expired
        self.e_keep.next = self.e_hv.val() & !self.e_expired.val();

        if self.judging.val() {
            // the judged entry written back: expired entries (all of them while
            // forgetting) leave the history
            self.flags.write_enable.next = true;
            // (u and d of an invalid entry are never read)
            self.flags.write_data.next = (bit_cast::<3, 1>(self.e_keep.val().into()))
                | (bit_cast::<3, 1>(self.e_hu.val().into()) << 1)
                | (bit_cast::<3, 1>(self.e_hd.val().into()) << 2);
            if self.scan_i.q.val() == self.last_scan.val() {
                // every entry is now written back, invalid if forgotten; a
                // history still idle (`hist_idle` stays 32767 until the next
                // frame's scan) stays forgotten
                self.forget.d.next = self.forget_now.val();
            }
        }
        if self.w_state.q.val() == self.s_idle.val() {
            if self.rxp_a.q.val() | self.rxp_b.q.val() {
                if self.rxp_a.q.val() {
                    self.sel.d.next = false;
                    self.rxp_a.d.next = false;
                } else {
                    self.sel.d.next = true;
                    self.rxp_b.d.next = false;
                }
                self.sel_s.d.next = false;
                self.hist_idle.d.next = self.zero15.val();
                self.scan_i.d.next = self.zero6.val();
                self.hit.d.next = false;
                self.free_found.d.next = false;
                if self.dedup_on.val() {
                    self.w_state.d.next = self.s_scan.val();
                } else if self.acl_rule.val() {
                    self.w_state.d.next = self.s_decide.val();
                } else {
                    self.w_state.d.next = self.s_write.val();
                }
            } else if self.s_pend.q.val() {
                // P-CORE-4: source S after A and B, no scan, no history entry
                self.sel.d.next = false;
                self.sel_s.d.next = true;
                self.s_frame.d.next = self.s_pend_frame.q.val();
                self.s_pend.d.next = false;
                self.w_state.d.next = self.s_write.val();
            } else if self.acl_rule.val() & self.release_q.q.val() & self.dedup_on.val() {
                // §8: a free idle edge looks for the next frame to release
                self.w_state.d.next = self.s_rscan.val();
                self.scan_i.d.next = self.zero6.val();
                self.rel.start.next = true;
            }
        } else if self.in_scan.val() {
            if self.judging.val()
                & (self.w_state.q.val() == self.s_scan.val())
                & (!self.e_hv.val() | self.e_hu.val() | self.e_expired.val())
                & !self.free_found.q.val()
            {
                self.free_found.d.next = true;
                self.free_e.d.next = self.scan_e.val();
            }
            if self.judging.val()
                & (self.w_state.q.val() == self.s_scan.val())
                & self.e_hv.val()
                & !self.e_expired.val()
                & !self.e_hu.val()
                & (self.e_ch.val() != self.sel.q.val())
                & (self.e_frame.val() == self.frame_sel.val())
                & !self.hit.q.val()
            {
                self.hit.d.next = true;
                self.hit_e.d.next = self.scan_e.val();
                self.hit_hd.d.next = self.e_hd.val();
            }
            self.scan_i.d.next = self.scan_i.q.val() + self.one6.val();
            if self.scan_i.q.val() == self.last_scan.val() {
                if self.w_state.q.val() == self.s_scan.val() {
                    self.w_state.d.next = self.s_decide.val();
                } else if self.rel.found.val() | self.r_cand.val() {
                    // entry H - 1, judged at this edge, counts
                    self.w_state.d.next = self.s_fetch.val();
                } else {
                    self.release_q.d.next = false;
                    self.w_state.d.next = self.s_idle.val();
                }
            }
        } else if self.w_state.q.val() == self.s_decide.val() {
            if self.acl_rule.val() {
                self.w_pcl.d.next = self.pcl.val();
            }
            self.stats.pcl_inc.next = self.count_pcl.val() & self.pcl.val();
            if self.hit.q.val() {
                // duplicate: it cancels the history entry and is dropped. DMR:
                // a PCL copy of a frame still waiting on the ACL leaves the entry
                // for the release
                if !self.acl_rule.val() | !self.pcl.val() | self.hit_hd.q.val() {
                    // the hit entry is used: {v, u, d} = {1, 1, hit_hd}
                    self.flags.write_enable.next = true;
                    self.flags.write_data.next =
                        self.three3.val() | (bit_cast::<3, 1>(self.hit_hd.q.val().into()) << 2);
                }
                if self.acl_rule.val() & !self.hit_hd.q.val() & !self.pcl.val() {
                    // DMR: the PCL copy came first and waited: delivered now
                    self.w_state.d.next = self.s_write.val();
                } else {
                    self.stats.dup_inc.next = true;
                    self.w_state.d.next = self.s_idle.val();
                }
            } else {
                self.w_state.d.next = self.s_write.val();
            }
        } else if self.w_state.q.val() == self.s_write.val() {
            if !self.w_fifo.val() {
                // DMR: a PCL frame waits in the history
            } else if !self.accept.val() {
                // §11.1: filtered out, dropped silently (still recorded below)
            } else if self.fifo_full.val() {
                self.stats.overrun_inc.next = true;
                self.overrun_evt.next = true;
            } else {
                self.fifo_wr.next = true;
                self.rx_evt.next = true;
            }
            if self.w_hist.val() {
                self.hist.write_enable.next = true;
                self.hist_ts.write_enable.next = true;
                // the recorded slot: {v, u, d} = {1, 0, delivered}
                self.flags.write_enable.next = true;
                self.flags.write_data.next =
                    self.one3.val() | (bit_cast::<3, 1>(self.w_fifo.val().into()) << 2);
                if !self.free_found.q.val() {
                    self.hist_ptr.d.next =
                        (self.hist_ptr.q.val() + self.one5.val()) & self.hmask.val();
                }
            }
            self.w_state.d.next = self.s_idle.val();
        } else if self.w_state.q.val() == self.s_fetch.val() {
            // the history read address is rel_e at this edge
            self.w_state.d.next = self.s_release.val();
        } else {
            // release (§8): the waiting frame is delivered on the ACL
            if !self.accept.val() {
                // §11.1: filtered out, dropped silently
            } else if self.fifo_full.val() {
                self.stats.overrun_inc.next = true;
                self.overrun_evt.next = true;
            } else {
                self.fifo_wr.next = true;
                self.rx_evt.next = true;
            }
            // the released entry is delivered: {v, u, d} = {1, 0, 1}
            self.flags.write_enable.next = true;
            self.flags.write_data.next = self.five3.val();
            self.stats.released_inc.next = true;
            self.w_state.d.next = self.s_idle.val();
        }
        // rx_valid pulses (with their frames) and ACL switches (a new event wins
        // over the clear above)
        if self.rxv_a.val() {
            self.rxp_a.d.next = true;
            self.rxf_a.d.next = self.frame_a.val();
        }
        if self.rxv_b.val() {
            self.rxp_b.d.next = true;
            self.rxf_b.d.next = self.frame_b.val();
        }
        if self.release_set.val() {
            self.release_q.d.next = true;
        }
        if self.offer_s.val() {
            self.s_pend.d.next = true;
            self.s_pend_frame.d.next = self.frame_s.val();
        }

        if self.clear.val() {
            self.w_state.d.next = self.s_idle.val();
            self.rxp_a.d.next = false;
            self.rxp_b.d.next = false;
            self.sel.d.next = false;
            self.sel_s.d.next = false;
            self.s_pend.d.next = false;
            self.scan_i.d.next = self.zero6.val();
            self.hit.d.next = false;
            self.hit_e.d.next = self.zero5.val();
            self.hit_hd.d.next = false;
            self.free_found.d.next = false;
            self.free_e.d.next = self.zero5.val();
            self.hist_ptr.d.next = self.zero5.val();
            self.hist_idle.d.next = self.zero15.val();
            self.forget.d.next = true;
            self.flags.write_enable.next = false;
            self.release_q.d.next = false;
            self.w_pcl.d.next = false;
            self.fifo_wr.next = false;
            self.rx_evt.next = false;
            self.overrun_evt.next = false;
            self.hist.write_enable.next = false;
            self.hist_ts.write_enable.next = false;
            self.stats.dup_inc.next = false;
            self.stats.overrun_inc.next = false;
            self.stats.omit_a.next = false;
            self.stats.omit_b.next = false;
            self.stats.pcl_inc.next = false;
            self.stats.released_inc.next = false;
            self.stats.expired_inc.next = false;
        }
        self.duplicates.next = self.stats.duplicates.val();
        self.overruns.next = self.stats.overruns.val();
        self.omissions_a.next = self.stats.omissions_a.val();
        self.omissions_b.next = self.stats.omissions_b.val();
        self.pcl_frames.next = self.stats.pcl_frames.val();
        self.released.next = self.stats.released.val();
        self.expired.next = self.stats.expired.val();
    }
}
