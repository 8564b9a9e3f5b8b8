//! The NRAP phase machine at a SAMPLE edge (hub contract §9.2), one method per
//! phase: `RUN` and its triggers, the end of `SRP_FORCE`, `SRP_EXCHANGE` (silent
//! sublinks restored, pairs of identification frames), `NRP`, the end of
//! `DDSP_FORCE` and `DDSP_SEND`. Each returns whether the phase was left, in
//! which case [`Nrap::sample`] keeps the timer and the counter `goto` cleared.

use super::{phase, Nrap, NrapCfg, SampleEffects, SampleInputs, SILENT_SUBLINK};
use crate::model::coverage;
use crate::model::hub::guard::PortGuard;

/// One SAMPLE edge in progress, as the phase rules see it.
pub(super) struct SampleEdge {
    /// The frame on the bus matched a ROM up to the bit before this one.
    pub(super) id_frame: bool,
    /// This bit is the ACK slot of the own / the twin's identification frame.
    pub(super) own_frame: bool,
    pub(super) twin_frame: bool,
    /// The phase timer and counter after the edge, if the phase stays.
    pub(super) nt: u16,
    pub(super) ncnt: u8,
    /// The enabled sublinks before the edge (the guards' late copy).
    pub(super) sub_enabled: u16,
    pub(super) fx: SampleEffects,
}

impl Nrap {
    /// `RUN`: NRAP starts when no sublink is left or the network is blocked
    /// (`SRP_FORCE`), or joins the twin's exchange on its identification frame
    /// (`SRP_EXCHANGE`).
    pub(super) fn run(&mut self, i: &SampleInputs, e: &mut SampleEdge, cfg: &NrapCfg) -> bool {
        let blocked = cfg.block_frames != 0 && self.unacked >= cfg.block_frames;
        if i.nrap_on && !i.decoupled && blocked {
            coverage::hit("hub nrap: triggered (network blocked)");
        }
        if i.nrap_on && !i.decoupled && (e.sub_enabled == 0 || blocked) {
            coverage::hit("hub nrap: triggered (no sublink left)");
            self.goto(phase::SRP_FORCE, &mut e.fx);
            self.last = 0;
            self.runs = (self.runs + 1).min(15);
            return true;
        }
        if i.nrap_on && !i.decoupled && e.twin_frame {
            coverage::hit("hub nrap: joins the twin's exchange");
            self.goto(phase::SRP_EXCHANGE, &mut e.fx);
            self.runs = (self.runs + 1).min(15);
            self.rrun = [0; 16];
            // The joining frame counts for the pairs as in SRP_EXCHANGE.
            self.pairs(false, true, i.b);
            return true;
        }
        false
    }

    /// The end of `SRP_FORCE` (its time is up): every sublink disabled, on to
    /// `SRP_EXCHANGE`.
    pub(super) fn end_srp_force(
        &mut self,
        e: &mut SampleEdge,
        ports: &mut [PortGuard],
        n: usize,
    ) -> bool {
        self.goto(phase::SRP_EXCHANGE, &mut e.fx);
        for g in ports[n..].iter_mut() {
            g.enabled = false;
        }
        self.rrun = [0; 16];
        true
    }

    /// `SRP_EXCHANGE`: silent sublinks restored, pairs of identification frames
    /// counted (the own frame acknowledged through an interlink); enough pairs
    /// lead to `NRP`, the end of its time to `DDSP_FORCE`.
    pub(super) fn srp_exchange(
        &mut self,
        i: &SampleInputs,
        e: &mut SampleEdge,
        ports: &mut [PortGuard],
        n: usize,
        cfg: &NrapCfg,
    ) -> bool {
        self.restore_silent_sublinks(i, ports, n);
        // The ACK of the own frame must come through an interlink: the
        // AND of the enabled sublinks (1 when none is enabled).
        let twin_b = i.pq | !e.sub_enabled | ((1u16 << n) - 1) == u16::MAX;
        let acked = if e.own_frame { twin_b } else { i.b };
        if self.pairs(e.own_frame, e.twin_frame, acked) {
            e.ncnt = (e.ncnt + 1).min(15);
        }
        if e.ncnt >= cfg.srp_pairs {
            coverage::hit("hub nrap: sublinks agreed (to node restoration)");
            self.goto(phase::NRP, &mut e.fx);
            self.restore_nodes(ports, n);
            return true;
        }
        if e.nt >= cfg.srp_bits {
            self.enter_ddsp(ports, n, &mut e.fx);
            return true;
        }
        false
    }

    /// A disabled sublink recessive for `SILENT_SUBLINK` samples in a row is
    /// restored with clean counters (`SRP_EXCHANGE`).
    fn restore_silent_sublinks(&mut self, i: &SampleInputs, ports: &mut [PortGuard], n: usize) {
        for (p, g) in ports.iter_mut().enumerate().skip(n) {
            // the guard's own `enabled` (§6.1), not the late copy
            if !g.enabled {
                let r = if (i.pq >> p) & 1 == 1 {
                    (self.rrun[p] + 1).min(15)
                } else {
                    0
                };
                self.rrun[p] = r;
                if r >= SILENT_SUBLINK {
                    coverage::hit("hub nrap: silent sublink restored");
                    g.enabled = true;
                    g.pec = 0;
                    g.silent = 0;
                    g.restore_cnt = 0;
                }
            }
        }
    }

    /// `NRP`: erring node ports dropped, pairs counted; enough pairs recouple
    /// (`RUN`), the end of its time leads to `DDSP_FORCE`.
    pub(super) fn nrp(
        &mut self,
        i: &SampleInputs,
        e: &mut SampleEdge,
        ports: &mut [PortGuard],
        n: usize,
        cfg: &NrapCfg,
    ) -> bool {
        self.drop_erring(ports, n, i, e.id_frame);
        if self.pairs(e.own_frame, e.twin_frame, i.b) {
            e.ncnt = (e.ncnt + 1).min(15);
        }
        if e.ncnt >= cfg.nrp_pairs {
            coverage::hit("hub nrap: recoupled");
            self.goto(phase::RUN, &mut e.fx);
            self.outcome = true;
            return true;
        }
        if e.nt >= cfg.nrp_bits {
            self.enter_ddsp(ports, n, &mut e.fx);
            return true;
        }
        false
    }

    /// The end of `DDSP_FORCE` (its time is up): the node ports restored, on to
    /// `DDSP_SEND`.
    pub(super) fn end_ddsp_force(
        &mut self,
        e: &mut SampleEdge,
        ports: &mut [PortGuard],
        n: usize,
    ) -> bool {
        self.goto(phase::DDSP_SEND, &mut e.fx);
        self.restore_nodes(ports, n);
        true
    }

    /// `DDSP_SEND`: erring node ports dropped, own frames acknowledged counted;
    /// enough of them or the end of its time split the stars (`SPLIT`).
    pub(super) fn ddsp_send(
        &mut self,
        i: &SampleInputs,
        e: &mut SampleEdge,
        ports: &mut [PortGuard],
        n: usize,
        cfg: &NrapCfg,
    ) -> bool {
        self.drop_erring(ports, n, i, e.id_frame);
        if e.own_frame && !i.b {
            e.ncnt = (e.ncnt + 1).min(15);
        }
        if e.ncnt >= cfg.ddsp_frames || e.nt >= cfg.ddsp_bits {
            coverage::hit("hub nrap: split (each star on its own)");
            self.goto(phase::SPLIT, &mut e.fx);
            self.outcome = false;
            return true;
        }
        false
    }
}
