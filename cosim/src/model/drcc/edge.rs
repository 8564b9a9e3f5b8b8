//! The DRCC model's clock edge (every DRCC register at a non-reset edge), phase
//! by phase in the order the edge runs them: the nominal bit tick, the Wishbone
//! access, the star node's echo and the hubs' frames, the ECSS bus selection, the
//! main FSM, the aux FSMs, the DMR block, the TX queues, the RX path, and last the
//! interrupts and the commit of the registers. Every phase reads the registers
//! before the edge and the channel outputs of the previous step; where a phase
//! reads what an earlier one wrote (the registers after the edge, a block's
//! events), the order here is the one that counts.

use super::aux_fsm::AuxInputs;
use super::dmr::{DmrEvents, DmrInputs};
use super::features;
use super::main_fsm::{FsmEvents, FsmInputs};
use super::register_file::{Access, Regs};
use super::regs::*;
use super::rx_path::{RxEvents, RxInputs};
use super::star;
use super::tx_queues::TxqInputs;
use super::{DrccModel, HostEvents};
use crate::engine::drcc::DrccInputs;
use crate::model::{coverage, field};

/// One edge in progress: the registers before it (`r`, what every phase reads),
/// the registers after it (`n`, what the phases write), the `INT_STATUS` events
/// raised so far, and the mode bits and bit tick every phase reads.
struct Edge {
    r: Regs,
    n: Regs,
    ints: u32,
    reset_mode: bool,
    redundancy: bool,
    dmr_mode: bool,
    running: bool,
    tick: bool,
}

impl DrccModel {
    /// Every DRCC register at a non-reset edge (the channels are stepped after).
    pub(super) fn edge(&mut self, i: &DrccInputs) {
        let mut e = self.bit_tick();
        let acc = self.host_access(i, &mut e);
        let (echo, hubf) = self.star_frames(&mut e);
        self.ecss_selection(&mut e);
        let (fev, in_use) = self.main_fsm_edge(&mut e, echo);
        self.aux_fsms(&mut e, in_use);
        let (dev, dmr_off, acl_q) = self.dmr_edge(&mut e, acc.dmr_write);
        self.tx_queues_edge(&mut e, &acc, fev.pop, dev.pop, dmr_off);
        let rev = self.rx_path_edge(&mut e, acc.pop, echo, hubf, acl_q, &dev);
        self.channel_events(&mut e, acc.w1c);
        self.commit(e, &acc, &fev, &rev, &dev);
    }

    /// Nominal bit tick (§4.3): whether this edge ticks, and its counters, the
    /// first registers written after the edge. Opens the edge with the mode bits
    /// before it.
    fn bit_tick(&self) -> Edge {
        let r = self.r;
        let reset_mode = r.reset_mode();
        let redundancy = r.redundancy();
        let dmr_mode = r.dmr();
        let running = redundancy && !reset_mode;

        // Nominal bit tick (§4.3).
        let tpb1 = r.tq_per_bit() - 1;
        let tq_wrap = r.tq_cnt == r.brp();
        let tick = tq_wrap && r.bit_cnt == tpb1;
        let mut n = r;
        n.reset_mode_q = reset_mode;
        if reset_mode {
            n.tq_cnt = 0;
            n.bit_cnt = 0;
        } else if tq_wrap {
            n.tq_cnt = 0;
            n.bit_cnt = if r.bit_cnt == tpb1 { 0 } else { r.bit_cnt + 1 };
        } else {
            n.tq_cnt = r.tq_cnt + 1;
        }
        Edge {
            r,
            n,
            ints: 0,
            reset_mode,
            redundancy,
            dmr_mode,
            running,
            tick,
        }
    }

    /// The host's access (§2, §3, §9, §11): the Wishbone access taken at this
    /// edge, its writes into the registers after the edge, with a host view's
    /// push and pop in place of the native ones. Its refusal is the first event.
    fn host_access(&self, i: &DrccInputs, e: &mut Edge) -> Access {
        // Wishbone (§2, §3, §9, §11).
        let mut acc = self.access(i, &mut e.n);
        if let Some(h) = &self.host {
            acc.push = h.push;
            acc.pop = h.pop;
        }
        e.ints = acc.ints;
        acc
    }

    /// The star node's receptions (§4.4, §4.5): per channel, whether it is the
    /// node's own frame heard back (echo) and whether it is a hub's
    /// identification frame; the hubs' decision follows the latter.
    fn star_frames(&mut self, e: &mut Edge) -> ([bool; 2], [bool; 2]) {
        let (r, running) = (&e.r, e.running);
        let [pa, pb] = &self.out;
        // Echo (§4.4): in a star node, a channel's reception of the attempted head
        // message (the TX RAM read data) is the node's own frame heard through the
        // other hub.
        let star_on = running && r.star() && self.fsm.attempted;
        let echo = [pa, pb].map(|o| star_on && o.rx_valid && o.rx_frame == self.txq.rd);
        // The hubs' identification frames (§4.5).
        let (hubf, domain) = self.star.edge(
            running && r.star(),
            [pa.rx_valid, pb.rx_valid],
            [&pa.rx_frame, &pb.rx_frame],
        );
        if domain {
            coverage::hit("drcc star: the hubs' decision changes the domain");
            e.ints |= int::DOMAIN;
        }
        if e.reset_mode {
            self.star = star::StarFollow::default();
        }
        (echo, hubf)
    }

    /// ECSS bus selection (§12.2), on pre-edge values.
    fn ecss_selection(&self, e: &mut Edge) {
        let [pa, pb] = &self.out;
        let ecss_on = e.redundancy && e.r.ecss.cfg.enable() && !e.reset_mode;
        let toggle = e.n.ecss.sel.edge(
            &e.r.ecss.cfg,
            ecss_on,
            e.tick,
            [pa.rx_valid, pb.rx_valid],
            [&pa.rx_frame, &pb.rx_frame],
        );
        if toggle {
            coverage::hit("drcc ecss: the bus selection toggles or gives up");
            e.ints |= int::BUS_TOGGLE;
        }
    }

    /// Main FSM (§4), on pre-edge values of the aux FSMs (or the ECSS
    /// selection, §12.2) and TX queue A. Returns its events and which channels
    /// it used before the edge (for the aux FSMs).
    fn main_fsm_edge(&mut self, e: &mut Edge, echo: [bool; 2]) -> (FsmEvents, [bool; 2]) {
        let r = &e.r;
        let [pa, pb] = &self.out;
        let (va, vb) = r.ecss.validity(e.redundancy).unwrap_or((
            self.aux[0].state == aux::VALID,
            self.aux[1].state == aux::VALID,
        ));
        let fsm_in = FsmInputs {
            running: e.running,
            q: self.txq.count[0] > 0,
            va,
            vb,
            // §4.4/§4.5: a star node sends the copy only after the hubs split.
            dual_tx: r.dual_tx() && (!r.star() || self.star.split),
            tick: e.tick,
            pending_a: pa.tx_pending,
            done_a: pa.tx_done,
            failed_a: pa.tx_failed,
            pending_b: pb.tx_pending,
            done_b: pb.tx_done,
            failed_b: pb.tx_failed,
            echo_a: echo[0],
            echo_b: echo[1],
        };
        let in_use = [self.fsm.uses_a(), self.fsm.uses_b()];
        let fev = self.fsm.edge(&fsm_in);
        if fev.tx_success {
            e.ints |= int::TX_DONE;
        }
        if fev.tx_failure {
            e.ints |= int::TX_FAILURE;
        }
        if fev.switch {
            e.ints |= int::SWITCH;
        }
        (fev, in_use)
    }

    /// Aux FSMs (§5). A channel is restarted only at bus idle, B only while A is
    /// valid (pre-edge state).
    fn aux_fsms(&mut self, e: &mut Edge, in_use: [bool; 2]) {
        let (r, reset_mode) = (&e.r, e.reset_mode);
        let [pa, pb] = &self.out;
        let a_valid = self.aux[0].state == aux::VALID;
        for (c, o) in [pa, pb].into_iter().enumerate() {
            let aev = self.aux[c].edge(&AuxInputs {
                // P-CORE-3: behind a host view only the channel's reset holds
                // its aux FSM, which so keeps judging through a bus-off hold
                running: e.redundancy
                    && self.host.as_ref().map_or(!reset_mode, |h| !h.chan_reset[c]),
                policy: r.policy(),
                k: r.k(),
                stall_limit: (r.rmb >> 16) as u16,
                recovery_bits: r.rmb as u16,
                tick: e.tick,
                in_use: in_use[c],
                restart_ok: o.probes.field == field::IDLE && (c == 0 || a_valid),
                tx_pending: o.tx_pending,
                tx_done: o.tx_done,
                rx_valid: o.rx_valid,
                err_valid: o.diag.err_valid,
                err_tx: o.diag.err_tx,
                err_state: o.probes.err_state,
                err_warning: o.diag.err_warning,
                sample_point: o.probes.sample_point,
            });
            if aev.int {
                e.ints |= int::AUX;
            }
            if aev.recovered {
                e.n.recoveries = e.n.recoveries.saturating_add(1);
            }
        }
    }

    /// DMR block (dmr_contract.md §3-§7), on pre-edge channel outputs and queue,
    /// then the access's write to its registers. Returns its events, and the
    /// read offset and `acl` before the edge (for the TX queues and the RX path).
    fn dmr_edge(&mut self, e: &mut Edge, dmr_write: Option<(u8, u32)>) -> (DmrEvents, u8, u8) {
        let [pa, pb] = &self.out;
        let dmr_off = self.dmr.off[self.txq.rd_sel as usize & 1];
        let acl_q = self.dmr.acl;
        let dev = self.dmr.edge(&DmrInputs {
            running: e.dmr_mode && !e.reset_mode,
            tick: e.tick,
            reset_mode_q: e.r.reset_mode_q,
            done: [pa.tx_done, pb.tx_done],
            failed: [pa.tx_failed, pb.tx_failed],
            rx_valid: [pa.rx_valid, pb.rx_valid],
            rx_frame: [pa.rx_frame, pb.rx_frame],
            err_state: [pa.probes.err_state, pb.probes.err_state],
            q_count: self.txq.count[0],
            rd: self.txq.rd,
            rd_sel: self.txq.rd_sel,
        });
        if let Some((adr, d)) = dmr_write {
            // §1.1: without the DMR function its registers take no write.
            if !self.params.dmr || self.dmr.write(adr, d, e.reset_mode) != Some(true) {
                e.ints |= int::ILLEGAL;
            }
        }
        if dev.tx_done {
            e.ints |= int::TX_DONE;
        }
        if dev.int {
            e.ints |= int::DMR;
        }
        (dev, dmr_off, acl_q)
    }

    /// TX queues (§6): the host's push and aborts, the main FSM's or the DMR
    /// block's pop, then the host's recovery permission (§11.6), which a push
    /// the queues refuse cancels.
    fn tx_queues_edge(
        &mut self,
        e: &mut Edge,
        acc: &Access,
        fsm_pop: bool,
        dmr_pop: u8,
        dmr_off: u8,
    ) {
        let [pa, pb] = &self.out;
        let tev = self.txq.edge(&TxqInputs {
            reset_mode: e.reset_mode,
            redundancy: e.redundancy,
            dmr: e.dmr_mode.then_some((dmr_off, dmr_pop)),
            push: acc.push,
            abort: acc.abort,
            fsm_pop,
            done: [pa.tx_done, pb.tx_done],
            failed: [pa.tx_failed, pb.tx_failed],
        });
        if tev.push_refused {
            e.ints |= int::ILLEGAL;
        }
        // §11.6: the host's permission, taken and kept only while bus-off; a
        // write refused for any reason (here: its push, §6) takes none.
        for (c, o) in [pa, pb].into_iter().enumerate() {
            let w = acc.recover[c] && !tev.push_refused;
            e.n.recover[c] = o.probes.err_state == 2 && (e.r.recover[c] || w);
        }
        if tev.tx_done {
            e.ints |= int::TX_DONE;
        }
        if tev.tx_failure {
            e.ints |= int::TX_FAILURE;
        }
    }

    /// RX FIFO and duplicate removal (§7), the filters at its write port (§11.1).
    fn rx_path_edge(
        &mut self,
        e: &mut Edge,
        pop: bool,
        echo: [bool; 2],
        hubf: [bool; 2],
        acl_q: u8,
        dev: &DmrEvents,
    ) -> RxEvents {
        let (r, reset_mode, dmr_mode) = (&e.r, e.reset_mode, e.dmr_mode);
        let [pa, pb] = &self.out;
        let rev = self.rx.edge_filtered(
            &RxInputs {
                reset_mode,
                dedup_on: (e.redundancy || dmr_mode) && r.window() != 0,
                dmr: dmr_mode,
                first_copy: r.first_copy(),
                acl: acl_q,
                release_set: dev.acl_switch,
                window: r.window(),
                tick: e.tick,
                pop,
                // DMR §7: CS frames never reach the RX path.
                rx_valid: if dmr_mode && !reset_mode {
                    dev.rx_deliver
                } else {
                    // An echo is the node's own frame, not a reception (§4.4); an
                    // identification frame is the hubs' (§4.5).
                    [
                        pa.rx_valid && !echo[0] && !hubf[0],
                        pb.rx_valid && !echo[1] && !hubf[1],
                    ]
                },
            },
            [&pa.rx_frame, &pb.rx_frame],
            &r.filt,
        );
        if rev.pop_refused {
            e.ints |= int::ILLEGAL;
        }
        if rev.rx {
            e.ints |= int::RX;
        }
        if rev.overrun {
            e.ints |= int::OVERRUN;
        }
        rev
    }

    /// Interrupts (§8) from the channels' outputs, the driver's events and the
    /// captures (§10.2), and which channel completed or dropped its frame
    /// (§11.3); `w1c` is the acknowledgement that re-arms the captures.
    fn channel_events(&self, e: &mut Edge, w1c: u32) {
        let r = &e.r;
        let [pa, pb] = &self.out;
        // Interrupts (§8).
        let es = [pa.probes.err_state, pb.probes.err_state];
        if es != r.err_q {
            e.ints |= int::ERR_STATE;
        }
        e.n.err_q = es;
        // §10.2: the driver's events and the captures, the same in every mode.
        let warn = [pa.diag.err_warning, pb.diag.err_warning];
        if warn != r.warn_q {
            e.ints |= int::ERR_WARNING;
        }
        e.n.warn_q = warn;
        if pa.arb_lost || pb.arb_lost {
            e.ints |= int::ARB_LOST;
        }
        if pa.diag.err_valid || pb.diag.err_valid {
            e.ints |= int::BUS_ERROR;
        }
        // §11.3: which channel completed or dropped its frame, in every mode.
        e.ints |= features::tx_channel_events(pa, pb);
        // Re-arm: the acknowledgement of the interrupt (an INT_STATUS write that
        // took effect) clears both channels' valid bits; a capture at this edge wins.
        // A host view's window re-arms one channel's (PeliCAN P-X-3).
        let (rearm_err, rearm_alc) = (w1c & int::BUS_ERROR != 0, w1c & int::ARB_LOST != 0);
        let view = self.host.map_or([false; 2], |h| h.cap_rearm);
        e.n.cap = [
            r.cap[0].edge(pa, rearm_err || view[0], rearm_alc || view[0]),
            r.cap[1].edge(pb, rearm_err || view[1], rearm_alc || view[1]),
        ];
    }

    /// The edge's end: the access's answer (§9), the events reported to a host
    /// view, `INT_STATUS` and `irq`, the registers committed, and last the
    /// statistics clear (§11.4).
    fn commit(&mut self, e: Edge, acc: &Access, fev: &FsmEvents, rev: &RxEvents, dev: &DmrEvents) {
        let (r, mut n, ints) = (e.r, e.n, e.ints);
        let take = acc.take;
        // Every `illegal` comes from the access taken at this edge (§9).
        let refused = take && ints & int::ILLEGAL != 0;
        n.wb_ack = take && !refused;
        n.wb_err = refused;
        if refused {
            n.wb_dat = 0;
        }
        self.host_ev = HostEvents {
            ints,
            tx_success: fev.tx_success,
            stored: rev.rx,
            overrun: rev.overrun,
            dmr_tx_done: dev.tx_done,
        };
        n.int_status = (r.int_status & !acc.w1c) | ints;
        n.irq = r.int_status & r.int_enable != 0;
        self.r = n;
        // §11.4: the clear wins over every count's event at this edge.
        if acc.stats_clr {
            self.clear_statistics();
        }
    }
}
