//! The update of the NRAP phase machine ([`super::Nrap`], hub contract §9.2,
//! §9.5): phase decode, the rules of each phase at the SAMPLE edge, the
//! commands, the port strobes and the `NRAP_STATUS` word. A child module of
//! `super` so that it reaches the block's private fields; split from `nrap.rs`,
//! which describes the rules and declares the ports, the registers and the
//! constants.

use super::*;

impl<const H: usize> Logic for Nrap<H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, nrap_q, nt, ncnt, half, last, unacked, runs, outcome);
        self.st_run.next = self.nrap_q.q.val() == self.ph_run.val();
        self.st_srp_force.next = self.nrap_q.q.val() == self.ph_srp_force.val();
        self.st_exchange.next = self.nrap_q.q.val() == self.ph_exchange.val();
        self.st_nrp.next = self.nrap_q.q.val() == self.ph_nrp.val();
        self.st_ddsp_force.next = self.nrap_q.q.val() == self.ph_ddsp_force.val();
        self.st_send.next = self.nrap_q.q.val() == self.ph_send.val();
        self.is_active.next = self.st_srp_force.val()
            | self.st_exchange.val()
            | self.st_nrp.val()
            | self.st_ddsp_force.val()
            | self.st_send.val();
        // NRAP may start from RUN
        self.go.next = self.st_run.val() & self.nrap_on.val() & !self.decoupled.val();

        // the counters' increments and comparisons, registered in the clock before
        // (`super::nrap_ahead`); a command that changes the phase clears nt, ncnt
        self.ahead.clk.next = self.clk.val();
        self.ahead.nt.next = self.nt.q.val();
        self.ahead.ncnt.next = self.ncnt.q.val();
        self.ahead.unacked.next = self.unacked.q.val();
        if self.cmd_run.val() {
            self.ahead.clear.next = !self.st_run.val();
        } else {
            self.ahead.clear.next = self.cmd_split.val()
                & self.nrap_on.val()
                & (self.nrap_q.q.val() != self.ph_split.val());
        }
        self.ahead.force_bits.next = self.force_bits.val();
        self.ahead.srp_bits.next = self.srp_bits.val();
        self.ahead.nrp_bits.next = self.nrp_bits.val();
        self.ahead.ddsp_bits.next = self.ddsp_bits.val();
        self.ahead.srp_pairs.next = self.srp_pairs.val();
        self.ahead.nrp_pairs.next = self.nrp_pairs.val();
        self.ahead.ddsp_frames.next = self.ddsp_frames.val();
        self.ahead.block_frames.next = self.block_frames.val();
        // new nt: every SAMPLE edge counts (saturating)
        self.nt_new.next = self.ahead.nt_inc.val();
        // new unacked: frames in a row with an error flag at their ACK delimiter;
        // `blocked`: the new unacked >= block_frames != 0
        self.unacked_new.next = self.unacked.q.val();
        self.blocked.next = self.ahead.blk0.val();
        if self.at_delim.val() {
            if self.b.val() {
                self.unacked_new.next = self.zero5.val();
                self.blocked.next = false;
            } else {
                self.unacked_new.next = self.ahead.un_inc.val();
                self.blocked.next = self.ahead.blk1.val();
            }
        }
        // the ACK slot of an identification frame; hub A's and hub B's by HUB_ID
        self.ack_own.next = self.at_ack.val() & self.own_frame.val();
        self.ack_twin.next = self.at_ack.val() & self.twin_frame.val();
        if self.is_b.val() {
            self.ack_a.next = self.ack_twin.val();
            self.ack_b.next = self.ack_own.val();
        } else {
            self.ack_a.next = self.ack_own.val();
            self.ack_b.next = self.ack_twin.val();
        }
        // pairs (SRP_EXCHANGE, NRP): A's frame acknowledged, then B's; in
        // SRP_EXCHANGE the own frame's ACK must come through an interlink
        self.pairs.next = self.st_exchange.val() | self.st_nrp.val();
        if self.st_exchange.val() & self.own_frame.val() {
            self.ackd.next = !self.twin_b.val();
        } else {
            self.ackd.next = !self.b.val();
        }
        self.half_new.next = self.half.q.val();
        if self.pairs.val() & (self.ack_a.val() | self.ack_b.val()) {
            if !self.ackd.val() {
                self.half_new.next = false;
            } else if self.ack_a.val() {
                self.half_new.next = true;
            } else if self.half.q.val() {
                self.half_new.next = false;
            }
        }
        // new ncnt: the pairs, or in DDSP_SEND the own frames, the phase counts
        self.inc.next = (self.pairs.val() & self.ack_b.val() & self.ackd.val() & self.half.q.val())
            | (self.st_send.val() & self.ack_own.val() & !self.b.val());
        if self.inc.val() {
            self.ncnt_new.next = self.ahead.ncnt_inc.val();
        } else {
            self.ncnt_new.next = self.ncnt.q.val();
        }

        // ---- the phase rules (§9.2), at SAMPLE edges ----
        self.next.next = self.nrap_q.q.val();
        // `chg`: the phase changes (every rule below moves to another phase), kept
        // beside `next` so that the clears need no comparison of the two
        self.chg.next = false;
        self.last_new.next = self.last.q.val();
        self.set_decoupled.next = false;
        self.p_exchange.next = false;
        self.p_watch.next = false;
        self.p_off_sub.next = false;
        self.p_join.next = false;
        self.p_enable.next = false;
        self.half_join.next = false;
        if self.pairs.val() {
            if self.ack_twin.val() {
                self.last_new.next = self.last_twin.val();
            }
            if self.ack_own.val() & self.ackd.val() {
                self.last_new.next = self.last_own.val();
            }
        }
        if self.sample.val() {
            if self.st_run.val() {
                if self.go.val() & (!self.any_sub_en.val() | self.blocked.val()) {
                    // Trigger (no sublink enabled) or Blocked network
                    self.next.next = self.ph_srp_force.val();
                    self.chg.next = true;
                    self.last_new.next = self.last_none.val();
                } else if self.go.val() & self.ack_twin.val() {
                    // Joining: the twin's identification frame came through; its
                    // ACK slot counts for the pairs as in SRP_EXCHANGE (the twin's
                    // frame is hub A's when this hub is B)
                    self.next.next = self.ph_exchange.val();
                    self.chg.next = true;
                    self.last_new.next = self.last_twin.val();
                    self.half_join.next = self.is_b.val() & !self.b.val();
                    self.p_join.next = true;
                }
            } else if self.st_srp_force.val() {
                if self.ahead.nt_force.val() {
                    self.next.next = self.ph_exchange.val();
                    self.chg.next = true;
                    self.p_off_sub.next = true;
                }
            } else if self.st_exchange.val() {
                self.p_exchange.next = true;
                // new ncnt >= srp_pairs, new nt >= srp_bits
                if (self.inc.val() & self.ahead.srp1.val())
                    | (!self.inc.val() & self.ahead.srp0.val())
                {
                    self.next.next = self.ph_nrp.val();
                    self.chg.next = true;
                    self.p_enable.next = true;
                } else if self.ahead.nt_srp.val() {
                    self.next.next = self.ph_ddsp_force.val();
                    self.chg.next = true;
                    self.set_decoupled.next = true;
                    self.p_off_sub.next = true;
                }
            } else if self.st_nrp.val() {
                self.p_watch.next = self.in_id.val();
                if (self.inc.val() & self.ahead.nrp1.val())
                    | (!self.inc.val() & self.ahead.nrp0.val())
                {
                    self.next.next = self.ph_run.val();
                    self.chg.next = true;
                } else if self.ahead.nt_nrp.val() {
                    self.next.next = self.ph_ddsp_force.val();
                    self.chg.next = true;
                    self.set_decoupled.next = true;
                    self.p_off_sub.next = true;
                }
            } else if self.st_ddsp_force.val() {
                if self.ahead.nt_force.val() {
                    self.next.next = self.ph_send.val();
                    self.chg.next = true;
                    self.p_enable.next = true;
                }
            } else if self.st_send.val() {
                self.p_watch.next = self.in_id.val();
                if (self.inc.val() & self.ahead.ddsp1.val())
                    | (!self.inc.val() & self.ahead.ddsp0.val())
                    | self.ahead.nt_ddsp.val()
                {
                    self.next.next = self.ph_split.val();
                    self.chg.next = true;
                }
            }
        }
        // ---- host commands decide the phase of their edge (§8) ----
        if self.cmd_run.val() {
            self.next.next = self.ph_run.val();
            self.chg.next = !self.st_run.val();
        } else if self.cmd_split.val() & self.nrap_on.val() {
            self.next.next = self.ph_split.val();
            self.chg.next = self.nrap_q.q.val() != self.ph_split.val();
        }
        self.next_active.next =
            (self.next.val() != self.ph_run.val()) & (self.next.val() != self.ph_split.val());

        // ---- registers ----
        self.nrap_q.d.next = self.next.val();
        if self.sample.val() {
            self.last.d.next = self.last_new.val();
            self.unacked.d.next = self.unacked_new.val();
        }
        self.ev_phase.next = self.chg.val();
        if self.ev_phase.val() {
            // every phase change clears the phase's timer, counter and half pair;
            // the joining frame's ACK slot then counts as in SRP_EXCHANGE
            self.nt.d.next = self.zero16.val();
            self.ncnt.d.next = self.zero4.val();
            self.half.d.next = self.half_join.val() & (self.next.val() == self.ph_exchange.val());
        } else {
            if self.sample.val() {
                self.nt.d.next = self.nt_new.val();
                self.ncnt.d.next = self.ncnt_new.val();
                self.half.d.next = self.half_new.val();
            }
        }
        if !self.hold.val() {
            if self.st_run.val() & self.next_active.val() & (self.runs.q.val() != self.max4.val()) {
                self.runs.d.next = self.runs.q.val() + self.one4.val();
            }
            if self.is_active.val() & !self.next_active.val() {
                self.outcome.d.next = self.next.val() == self.ph_run.val();
            }
        }
        // reset mode holds the phase, its counters and `last`; no event, no strobe
        if self.hold.val() {
            self.nrap_q.d.next = self.ph_run.val();
            self.nt.d.next = self.zero16.val();
            self.ncnt.d.next = self.zero4.val();
            self.half.d.next = false;
            self.last.d.next = self.last_none.val();
            self.unacked.d.next = self.zero5.val();
            self.ev_phase.next = false;
            self.set_decoupled.next = false;
            self.p_exchange.next = false;
            self.p_watch.next = false;
            self.p_off_sub.next = false;
            self.p_join.next = false;
            self.p_enable.next = false;
        }
        if self.rst.val() {
            self.runs.d.next = self.zero4.val();
            self.outcome.d.next = false;
        }

        // ---- outputs (registers) ----
        self.phase.next = self.nrap_q.q.val();
        self.active.next = self.is_active.val();
        self.forcing.next = self.st_srp_force.val() | self.st_ddsp_force.val();
        self.send.next = (((self.st_exchange.val() & self.any_sub_en.val()) | self.st_nrp.val())
            & (self.last.q.val() != self.last_own.val()))
            | self.st_send.val();
        self.ack_en.next = self.st_exchange.val() | self.st_nrp.val() | self.st_send.val();
        self.hush.next = !self.is_active.val() | self.st_srp_force.val() | self.st_ddsp_force.val();
        self.quiet_twin.next = self.st_send.val() | (self.nrap_q.q.val() == self.ph_split.val());
        self.status.next = (bit_cast::<32, 3>(self.nrap_q.q.val()) << self.s_nrap.val())
            | (bit_cast::<32, 1>(self.outcome.q.val().into()) << self.s_outcome.val())
            | (bit_cast::<32, 4>(self.runs.q.val()) << self.s_runs.val())
            | (bit_cast::<32, 4>(self.ncnt.q.val()) << self.s_ncnt.val())
            | (bit_cast::<32, 2>(self.last.q.val()) << self.s_last.val())
            | (bit_cast::<32, 1>(self.half.q.val().into()) << self.s_half.val())
            | (bit_cast::<32, 16>(self.nt.q.val()) << self.s_nt.val());
    }
}
