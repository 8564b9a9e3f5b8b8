//! Reference model of the DRCC top (dual-redundancy CAN controller), written from
//! its clock-level contract (`drcc_contract.md`, included below) and the DRCC paper
//! (seed 003, Table 1 and section IV). Two [`ChannelModel`]s (the channel oracle) are
//! paired under the redundancy manager: main FSM ([`main_fsm`]), one auxiliary FSM
//! per channel ([`aux_fsm`]), the TX queues ([`tx_queues`]), the RX FIFO with
//! duplicate removal ([`rx_path`]) and the Wishbone register file
//! (`register_file.rs`, map in [`regs`]); one clock edge, phase by phase, is
//! `edge.rs`. The third mode, CiA 701 dual-modular redundancy (`CTRL.dmr`), is the
//! DMR block ([`dmr`], `dmr_contract.md`).
//!
//! Step order (a registered design): every next-state value is computed from the
//! values before the edge. The channel outputs the DRCC logic sees at an edge are
//! the channel output registers of the previous step; the channel inputs of this
//! edge are derived from the DRCC registers before the edge; then everything is
//! committed and the outputs are read from the registers after the edge.
//!
//! ## Interpretations (where the contract leaves a choice)
//!
//! 1. `tx_failure` is a one-clock pulse register like `transmission_ack` and
//!    `tx_success`; `tx_ok_channel` / `tx_failure_channel` are the latched values.
//! 2. wait4 row 2: `tx_failure` and `tx_failure_channel` are both set only with
//!    `failed_b`. The copy "finish" there (dual_tx copy aborted on B) raises no
//!    `transmission_ack`, hence no `tx_success` and no `INT_STATUS.tx_done` (finish_q
//!    = `transmission_ack` set and popped at the same edge, literally §4.1).
//! 3. Reset mode (and normal mode for the FSMs) is a synchronous clear judged on the
//!    `reset_mode` register before the edge: queues, RX FIFO, writer FSM, history,
//!    `rxp`, `now`, `hist_idle`, `tx_time`, tick counters are held cleared while it
//!    is 1 (the clear takes effect at the first edge after `reset_mode` rises).
//!    `INT_STATUS`, `INT_ENABLE`, `irq`, the staged TX registers and (contract
//!    §10.2) `CAP_A`, `CAP_B` are not cleared by reset mode. Clearing `failover`
//!    in reset mode is not a switch event.
//! 4. RAMs are read-first: a read port loaded at an edge where the same address is
//!    written gets the old contents. RAM contents are never reset (power-up 0); the
//!    read data registers keep loading at `rst` and reset-mode edges, and `RX_ID`,
//!    `RX_CTRL`, `RX_DATA*` show the RX read data register even when the FIFO is
//!    empty (only `RX_ID[31]`, the `rx_ready` register, tells).
//! 5. All full/empty decisions use the counts before the edge: a push to a full
//!    queue is refused even if the same edge pops it; an RX write with `count == 32`
//!    overruns even if the same edge pops; a pop is refused (illegal) iff the count
//!    before the edge is 0 (also in reset mode, where the clear wins anyway).
//! 6. `CTRL` outside reset mode: the written cfg fields are compared with the
//!    current ones after the `k = 0 -> 1` clamp (writing k = 0 while k = 1 is not
//!    illegal); reserved bits are ignored. `policy = 3` outside reset mode is such a
//!    difference (illegal, `reset_mode` still taken).
//! 7. A write to `TX_CMD` with bits 0..4 clear, or to `RX_CMD` with bit 0 clear,
//!    does nothing (not illegal; `TX_CMD`'s abort bits: §11.5, recover bits:
//!    §11.6).
//!    `TX_CMD` and `RX_CMD` read 0. Writes to `INT_STATUS` (W1C) and every RW
//!    register are legal in any mode.
//! 8. `rxp` set (a new `rx_valid`) and clear (the writer takes it) at the same edge:
//!    set wins. `probe_cnt` clear (`err_valid`) and increment (`sample_point`) at the
//!    same edge: clear wins. `fail_cnt`: entering restart clears, else `tx_done`
//!    clears, else a failed attempt increments.
//! 9. STATS1 recoveries add one per aux FSM recovering (two if both recover at the
//!    same edge). `hist_idle` clears `hv` at every edge where it is 32767 before the
//!    edge.
//! 10. The TEC probe `chan_?_bsp_tx_err_cnt` and `CHAN_?_ERR[8:0]` are the channel
//!     TEC masked to 9 bits. Unused main FSM encodings (10..15) go to idle1.
//! 11. `tick` is not gated by reset mode (the counters are cleared there, so it
//!     cannot fire after the first reset-mode edge; everything it drives is held
//!     cleared in reset mode anyway).
//! 12. §10.2 re-arm: "a write to `INT_STATUS` (taken)" is read as a write that
//!     takes effect, i.e. the same write whose W1C clears bits: a partial
//!     (byte-lane) write to `INT_STATUS` is refused (§2, `illegal`), clears
//!     nothing and re-arms nothing. The `err_warning` comparison register and the
//!     captures are updated at every non-`rst` edge, reset mode included (the
//!     channels held in reset raise no `err_valid`/`arb_lost` there, and leaving
//!     the warning limit by the counters' reset is an event).
//! 13. §11.1 filters: `FILT_IDk` stores [30:0] (bit 31 reads 0), `FILT_MASKk` all
//!     32 bits. A frame released by the DMR ACL rule and then rejected still
//!     counts as `released` and is marked delivered (`hd`): the DMR rules see it
//!     as before, only the FIFO write is skipped.
//! 14. §11.2 the timestamp is `now` before the write edge (the value every rule
//!     reads, as the history's `ts`); a tick at that edge is not in it.
//! 15. §11.4 `STATS_CLR` keeps the byte-lane rule of §2: a partial write is
//!     refused like that of every whole word ("never refused" is read as "in
//!     any mode"). The counts of `DMR_STATUS` (`state_changes`, `acl_switches`)
//!     are not in the contract's list and are kept, as `DMR_CS_COUNT`.
//! 16. §11.6: a `TX_CMD` write refused for any reason takes no `recover`: a
//!     partial write (§2), an abort with `push` or in DMR mode (§11.5), both
//!     decoded at the register port, and a `push` the queue refuses (§6: reset
//!     mode, queue full), judged by the TX queues at the same edge.
//! 17. §12.2 a heartbeat is judged on the channel's raw `rx_valid` / `rx_frame`:
//!     the acceptance filters, duplicate removal and the star node's echo and
//!     identification rules do not hide it. `bus` follows `bdefault` in reset
//!     mode too (rule `!on`), so `ECSS_STATUS.bus` reads `bdefault` there.
#![doc = include_str!("../drcc_contract.md")]

pub mod aux_fsm;
pub mod dmr;
pub mod ecss;
mod edge;
pub mod features;
mod host;
pub mod main_fsm;
mod params;
mod register_file;
pub mod regs;
pub mod rx_path;
pub mod star;
pub mod tx_queues;

use crate::engine::drcc::{DrccInputs, DrccOutputs, DrccProbes};
use crate::engine::{BitTiming, ChannelInputs, ChannelOutputs, ControllerConfig, Mode};
use crate::model::ChannelModel;
use aux_fsm::AuxFsm;
use dmr::DmrBlock;
pub use host::{HostDrive, HostEvents, NativeAccess};
use main_fsm::MainFsm;
pub use params::DrccParams;
use register_file::Regs;
use regs::dmr as dmr_regs;
use regs::*;
use rx_path::{RxPath, RxSizes};
use tx_queues::TxQueues;

/// The DRCC top, simulated clock by clock.
#[derive(Clone, Debug)]
pub struct DrccModel {
    chan: [ChannelModel; 2],
    /// The channels' output registers after the last edge.
    out: [ChannelOutputs; 2],
    r: Regs,
    fsm: MainFsm,
    aux: [AuxFsm; 2],
    txq: TxQueues,
    rx: RxPath,
    dmr: DmrBlock,
    /// The hubs' decision as this star node sees it (§4.5).
    star: star::StarFollow,
    /// Generation parameters (§1.1).
    params: DrccParams,
    /// A non-native host view's drive of this edge (PeliCAN contract §14);
    /// `None` for the native register file.
    host: Option<HostDrive>,
    /// What the core reported to the host view at the last edge.
    host_ev: HostEvents,
}

impl Default for DrccModel {
    fn default() -> Self {
        Self::new()
    }
}

impl DrccModel {
    /// A DRCC in its reset state (reset mode, both channels held in reset), with
    /// the default 16 DMR mailboxes.
    pub fn new() -> Self {
        Self::with_mailboxes(dmr_regs::M_DEFAULT)
    }

    /// A DRCC with `m` DMR mailboxes (generation parameter `M`, 0..16) and the
    /// default sizes otherwise.
    pub fn with_mailboxes(m: usize) -> Self {
        Self::with_params(&DrccParams::with_mailboxes(m))
    }

    /// A DRCC generated with the sizes of `p` (contract §1.1).
    pub fn with_params(p: &DrccParams) -> Self {
        let chan = [ChannelModel::new(), ChannelModel::new()];
        let out = [chan[0].outputs(), chan[1].outputs()];
        DrccModel {
            chan,
            out,
            r: Regs::reset(),
            fsm: MainFsm::default(),
            aux: [AuxFsm::default(); 2],
            txq: TxQueues::new(p.tx_queue_depth),
            rx: RxPath::new(RxSizes {
                fifo_depth: p.rx_fifo_depth,
                history: p.history,
            }),
            dmr: DmrBlock::new(p.mailboxes),
            star: star::StarFollow::default(),
            params: *p,
            host: None,
            host_ev: HostEvents::default(),
        }
    }

    /// The inputs of channel `c` (0 = A) for this edge, from the registers before it.
    fn chan_inputs(&self, c: usize, rst: bool, rx: bool) -> ChannelInputs {
        let r = &self.r;
        let b = r.btr;
        let h = self.host.as_ref();
        // P-CORE-3: a host view splits the hold (`reset_mode`) from the
        // channels' reset.
        let chan_reset = h.map_or(r.reset_mode() || r.reset_mode_q, |h| h.chan_reset[c]);
        ChannelInputs {
            rst: rst
                || chan_reset
                || (self.aux[c].restarting() && !r.star())
                || self.dmr.restart[c],
            // §5: a star node's restart is soft (counters only, no re-integration).
            err_reset: self.aux[c].restarting() && r.star(),
            // §11.6: a bus-off channel counts its recovery only with the host's
            // permission when `busoff_manual` is set (in every mode).
            boff_hold: r.boff_hold(c) || h.is_some_and(|h| h.boff_hold[c]),
            // The native map has no per-frame single shot (P-CORE-1).
            tx_single: h.is_some_and(|h| h.tx_single),
            rx,
            timing: BitTiming {
                brp: r.brp(),
                tseg1: ((b >> btr::TSEG1_SHIFT) & 0xF) as u8 + 1,
                tseg2: ((b >> btr::TSEG2_SHIFT) & 0x7) as u8 + 1,
                sjw: ((b >> btr::SJW_SHIFT) & 0x3) as u8 + 1,
                triple_sampling: b & btr::TRIPLE != 0,
            },
            config: ControllerConfig {
                mode: Mode::from_code(
                    (r.ctrl
                        >> if c == 0 {
                            ctrl::MODE_A_SHIFT
                        } else {
                            ctrl::MODE_B_SHIFT
                        }) as u8,
                ),
                ewl: (b >> btr::EWL_SHIFT) as u8,
                single_shot: r.ctrl & ctrl::SINGLE_SHOT != 0 && !r.redundancy() && !r.dmr(),
            },
            tx_req: self.txq.req[c]
                || self.dmr.tx_req(c)
                || if c == 0 {
                    self.fsm.req_a
                } else {
                    self.fsm.req_b
                },
            // DMR §5: the CS frame of the line while its `cs_req` is 1.
            tx_frame: if self.dmr.cs_req[c] {
                self.dmr.cs_frame(c)
            } else {
                self.txq.rd
            },
            tx_abort: h.is_some_and(|h| h.tx_abort[c])
                || self.dmr.abort[c]
                || self.txq.abort[c]
                || if c == 0 {
                    self.fsm.abort_a
                } else {
                    self.fsm.abort_b
                },
        }
    }

    /// Apply `inputs` for one clock period, make one rising edge, return the outputs
    /// right after it.
    pub fn step(&mut self, i: &DrccInputs) -> DrccOutputs {
        let ca = self.chan_inputs(0, i.rst, i.chan_a_rx);
        let cb = self.chan_inputs(1, i.rst, i.chan_b_rx);
        if i.rst {
            let redundancy = self.r.redundancy();
            let dmr_off = self
                .r
                .dmr()
                .then(|| self.dmr.off[self.txq.rd_sel as usize & 1]);
            self.r = Regs::reset();
            self.fsm = MainFsm::default();
            self.aux = [AuxFsm::default(); 2];
            self.txq.reset(redundancy, dmr_off);
            self.rx.reset();
            self.dmr.rst();
            self.star = star::StarFollow::default();
        } else {
            self.edge(i);
        }
        self.chan[0].clock(&ca);
        self.chan[1].clock(&cb);
        self.out = [self.chan[0].outputs(), self.chan[1].outputs()];
        self.outputs()
    }

    /// The outputs after the last edge.
    pub fn outputs(&self) -> DrccOutputs {
        let [a, b] = &self.out;
        let f = &self.fsm;
        DrccOutputs {
            wb_ack: self.r.wb_ack,
            wb_err: self.r.wb_err,
            wb_dat_r: self.r.wb_dat,
            irq: self.r.irq,
            chan_a_tx: a.tx,
            chan_b_tx: b.tx,
            probes: DrccProbes {
                state: f.state,
                tx_channel: f.tx_channel(),
                transmission_ack: f.transmission_ack,
                chan_a_transmission_req: f.req_a || self.txq.req[0],
                chan_b_transmission_req: f.req_b || self.txq.req[1],
                tx_success: f.tx_success,
                tx_ok_channel: f.tx_ok_channel,
                tx_failure: f.tx_failure,
                tx_failure_channel: f.tx_failure_channel,
                tx_going_on: f.tx_going_on(),
                chan_a_bsp_tx_err_cnt: a.probes.tec & 0x1FF,
                chan_a_bsp_node_error_passive: a.probes.err_state != 0,
                chan_b_bsp_tx_err_cnt: b.probes.tec & 0x1FF,
                chan_b_bsp_node_error_passive: b.probes.err_state != 0,
                aux_a_state: self.aux[0].state,
                aux_b_state: self.aux[1].state,
                chan_a_sample_point: a.probes.sample_point,
                chan_b_sample_point: b.probes.sample_point,
                chan_a_field: a.probes.field,
                chan_b_field: b.probes.field,
                chan_a_rec: a.probes.rec,
                chan_b_rec: b.probes.rec,
                chan_a_err_state: a.probes.err_state,
                chan_b_err_state: b.probes.err_state,
                dmr_state: self.dmr.dmr_state,
                acl: self.dmr.acl != 0,
                dcl_tx_fault: self.dmr.tx_fault[0],
                dcl_rx_fault: self.dmr.rx_fault[0],
                rcl_tx_fault: self.dmr.tx_fault[1],
                rcl_rx_fault: self.dmr.rx_fault[1],
                dmr_tick: self.dmr.dmr_tick,
            },
        }
    }
}
