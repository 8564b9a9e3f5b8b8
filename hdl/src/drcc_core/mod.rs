//! The DRCC core: everything of the DRCC but its ports, so that more than one
//! host view can sit on it (PeliCAN contract §14). Two `can_channel`s (A = the
//! DRCC paper's channel 1, B = channel 2) share one bit timing; the redundancy
//! management (main FSM of Table 1, one auxiliary FSM per channel, bit tick), the
//! TX buffer, the RX FIFO with duplicate removal, the replicated-star node (§4.4,
//! §4.5), the CiA 701 DMR function (`dmr_contract.md`) and the native register
//! block (`crate::host`) complete it, as fixed by `drcc_contract.md`.
//!
//! The native top (`crate::drcc`, `rtl-out/drcc.v`) is this core with its
//! host-view inputs tied off (`view_on = 0`); the native register port is then
//! the host. A host view (the SJA1000 view, `pelican_contract.md`) drives the
//! view inputs instead: with `view_on = 1` the configuration is the view's
//! (`view_ctrl`, `view_btr` replace the stored `CTRL` and `BTR`: their
//! `reset_mode` is the hold of P-CORE-3), the channels' reset is `view_chan_reset`
//! (P-CORE-3), pushes and pops are the view's, and the per-request single shot,
//! abort and bus-off hold of P-CORE-1, P-TX-3 and P-CORE-2 are added to the
//! core's own. The native register port stays usable, for the view's window onto
//! the native registers (P-X-3, P-X-4). The view outputs report what a view
//! reads: the channels' transmit and error events, the RX path's events and
//! head, and the core's states.
//!
//! Generation parameter `M`, the DMR mailboxes (0..16, DMR contract §2); the
//! other sizes (TX queue and RX FIFO depths, the history) are set by
//! [`DrccCore::with_config`] (`crate::config`).

use crate::channel::bsp::field::Field;
use crate::channel::can_channel::CanChannel;
use crate::channel::sized::{Const, Param};
use crate::config::DrccConfig;
use crate::dmr::control::DmrControl;
use crate::dmr::engine::DmrEngine;
use crate::dmr::if_mailboxes::IfMailboxes;
use crate::dmr::mailbox_cfg::MailboxCfg;
use crate::host::busoff_recovery::BusoffRecovery;
use crate::host::captures::Captures;
use crate::host::dmr_check::DmrCheck;
use crate::host::dmr_regs::DmrRegs;
use crate::host::ecss_regs::EcssRegs;
use crate::host::filters::FilterRegs;
use crate::host::status_words::StatusWords;
use crate::host::wishbone::WbRegs;
use crate::memory::dedup::RxWriter;
use crate::memory::rx_fifo::RxFifo;
use crate::memory::tx_buffer::TxBuffer;
use crate::rmb::aux_fsm::AuxFsm;
use crate::rmb::bit_tick::BitTick;
use crate::rmb::echo::Echo;
use crate::rmb::ecss::{BusSelect, HbClock, ToggleCount};
use crate::rmb::main_fsm::MainFsm;
use crate::rmb::stats::RedundancyStats;
use rust_hdl::prelude::*;

/// The DRCC core, generated with `M` DMR mailboxes (0..16). Its ports named as
/// the native top's are that top's (`crate::drcc`, where they are described).
#[derive(LogicBlock, Default)]
pub struct DrccCore<const M: usize> {
    // clock and reset
    /// Clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high.
    pub rst: Signal<In, Bit>,
    // Wishbone B4 classic slave (drcc_contract.md §2); register map:
    // docs/registers.md, rtl-out/drcc_regs.h
    /// Wishbone cycle, active high.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone strobe, active high.
    pub wb_stb_i: Signal<In, Bit>,
    /// Wishbone write enable.
    pub wb_we_i: Signal<In, Bit>,
    /// Wishbone word address.
    pub wb_adr_i: Signal<In, Bits<6>>,
    /// Wishbone write data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Wishbone byte select of a write.
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone read data, valid while `wb_ack_o = 1`, else 0.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone acknowledge.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Wishbone error, instead of the acknowledge, for a refused access.
    pub wb_err_o: Signal<Out, Bit>,
    /// Interrupt request, active-high level, registered.
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
    // paper probes (DRCC paper Table 1, drcc_contract.md §4)
    /// Main FSM state (Table 1 codes).
    pub state: Signal<Out, Bits<4>>,
    /// Channel the main FSM transmits on.
    pub tx_channel: Signal<Out, Bit>,
    /// One-clock pulse: a channel delivered the message in flight.
    pub transmission_ack: Signal<Out, Bit>,
    /// Channel A transmit request (its `tx_req`), a one-clock pulse.
    pub chan_a_transmission_req: Signal<Out, Bit>,
    /// Channel B transmit request (its `tx_req`), a one-clock pulse.
    pub chan_b_transmission_req: Signal<Out, Bit>,
    /// One-clock pulse, the clock after `transmission_ack`.
    pub tx_success: Signal<Out, Bit>,
    /// Channel(s) that delivered the last message, bit 0 = A, bit 1 = B.
    pub tx_ok_channel: Signal<Out, Bits<2>>,
    /// One-clock pulse: the main FSM judged a channel failed for the message.
    pub tx_failure: Signal<Out, Bit>,
    /// Latched failed channel(s), bit 0 = A, bit 1 = B.
    pub tx_failure_channel: Signal<Out, Bits<2>>,
    /// A transmission is in progress.
    pub tx_going_on: Signal<Out, Bit>,
    /// Channel A transmit error counter (its `tec`).
    pub chan_a_bsp_tx_err_cnt: Signal<Out, Bits<9>>,
    /// Channel A is not error active.
    pub chan_a_bsp_node_error_passive: Signal<Out, Bit>,
    /// Channel B transmit error counter (its `tec`).
    pub chan_b_bsp_tx_err_cnt: Signal<Out, Bits<9>>,
    /// Channel B is not error active.
    pub chan_b_bsp_node_error_passive: Signal<Out, Bit>,
    // other probes (drcc_contract.md §5; the channel probes of timing_contract.md)
    /// Aux FSM A, the validity of channel A.
    pub aux_a_state: Signal<Out, Bits<2>>,
    /// Aux FSM B, the validity of channel B.
    pub aux_b_state: Signal<Out, Bits<2>>,
    /// Channel A `sample_point`.
    pub chan_a_sample_point: Signal<Out, Bit>,
    /// Channel B `sample_point`.
    pub chan_b_sample_point: Signal<Out, Bit>,
    /// Channel A `field`.
    pub chan_a_field: Signal<Out, Field>,
    /// Channel B `field`.
    pub chan_b_field: Signal<Out, Field>,
    /// Channel A receive error counter (its `rec`).
    pub chan_a_rec: Signal<Out, Bits<8>>,
    /// Channel B receive error counter (its `rec`).
    pub chan_b_rec: Signal<Out, Bits<8>>,
    /// Channel A `err_state`.
    pub chan_a_err_state: Signal<Out, Bits<2>>,
    /// Channel B `err_state`.
    pub chan_b_err_state: Signal<Out, Bits<2>>,
    // DMR probes (dmr_contract.md §9; CiA 701 names), all 0 outside DMR mode
    /// DMR state.
    pub dmr_state: Signal<Out, Bits<2>>,
    /// Active CAN line.
    pub acl: Signal<Out, Bit>,
    /// The DCL cannot transmit (a transmit fault was found on it).
    pub dcl_tx_fault: Signal<Out, Bit>,
    /// A fault on reception was found on the DCL.
    pub dcl_rx_fault: Signal<Out, Bit>,
    /// The RCL cannot transmit.
    pub rcl_tx_fault: Signal<Out, Bit>,
    /// A fault on reception was found on the RCL.
    pub rcl_rx_fault: Signal<Out, Bit>,
    /// One-clock pulse every `DMR_TIME.tick_bits` nominal bit times (the DMR tick).
    pub dmr_tick: Signal<Out, Bit>,
    // ---- host view inputs (PeliCAN contract §14); the native top ties them to 0 ----
    /// 1 = a host view drives the core: the configuration, the channels' reset,
    /// pushes and pops below replace the native register block's.
    pub view_on: Signal<In, Bit>,
    /// The native `CTRL` word the view composes (P-CFG-3); its `reset_mode` is
    /// the hold of P-CORE-3 (queues, FIFO, history emptied, main FSM held).
    pub view_ctrl: Signal<In, Bits<32>>,
    /// The native `BTR` word the view composes (P-CFG-2).
    pub view_btr: Signal<In, Bits<28>>,
    /// The channels' reset (P-CORE-3), bit 0 = A, bit 1 = B.
    pub view_chan_reset: Signal<In, Bits<2>>,
    /// Push the frame `view_push_frame` into TX queue `view_push_q` (P-TX-2).
    pub view_push: Signal<In, Bit>,
    /// The queue of a push: 0 = A (the logical queue), 1 = B.
    pub view_push_q: Signal<In, Bit>,
    /// The pushed frame, laid out as the TX RAM (`crate::memory::tx_buffer`).
    pub view_push_frame: Signal<In, Bits<99>>,
    /// Pop the RX FIFO's head (P-CMR-4).
    pub view_pop: Signal<In, Bit>,
    /// The next transmit request is single shot (P-CORE-1, P-TX-4).
    pub view_tx_single: Signal<In, Bit>,
    /// Per-channel transmit abort, added to the core's own (P-TX-3, P-BO-3).
    pub view_tx_abort: Signal<In, Bits<2>>,
    /// Per-channel bus-off hold, added to the core's own (P-CORE-2, P-BO-3).
    pub view_boff_hold: Signal<In, Bits<2>>,
    /// Offer `view_frame_s` to the RX writer as source `S` (P-CORE-4, P-TX-5).
    pub view_offer_s: Signal<In, Bit>,
    /// The offered frame (the TX RAM's layout): the message transmitted.
    pub view_frame_s: Signal<In, Bits<99>>,
    /// The view's acceptance filter gates the RX FIFO's write port (P-RX-5).
    pub view_gate_on: Signal<In, Bit>,
    /// Its filter mode (`MOD.AFM`, 1 = single filter).
    pub view_afm: Signal<In, Bit>,
    /// `ACR0..3`, `ACR0` in [7:0].
    pub view_acr: Signal<In, Bits<32>>,
    /// `AMR0..3`, `AMR0` in [7:0].
    pub view_amr: Signal<In, Bits<32>>,
    /// The view's native window loaded `CAP_A` (bit 0) or `CAP_B` (bit 1): that
    /// channel's captures re-arm at this edge (P-X-3).
    pub view_cap_rearm: Signal<In, Bits<2>>,
    // ---- host view outputs: what a view reads (unused by the native top) ----
    /// The RX writer stored a frame in the FIFO (one-clock pulse).
    pub rx_stored: Signal<Out, Bit>,
    /// The RX writer dropped a frame on a full FIFO (one-clock pulse).
    pub rx_overrun: Signal<Out, Bit>,
    /// The RX FIFO is not empty (registered, §D7).
    pub rx_ready: Signal<Out, Bit>,
    /// The RX FIFO's count.
    pub rx_count: Signal<Out, Bits<6>>,
    /// The RX FIFO's head: [115:100] time, [99] channel, [98:0] frame as the TX RAM.
    pub rx_head: Signal<Out, Bits<116>>,
    /// DMR mode: the host's `tx_done` of a message (first copy, §M5).
    pub dmr_tx_done: Signal<Out, Bit>,
    /// `INT_STATUS.switch` event: the main FSM changed channel (§D8).
    pub ev_switch: Signal<Out, Bit>,
    /// `INT_STATUS.aux` event: an auxiliary FSM failed or recovered a channel.
    pub ev_aux: Signal<Out, Bit>,
    /// `INT_STATUS.dmr` event of the DMR function (§M9).
    pub ev_dmr: Signal<Out, Bit>,
    /// `INT_STATUS.domain` event: the hubs' decision changed the domain (§4.5).
    pub ev_domain: Signal<Out, Bit>,
    /// Replicated star: the hubs have split (§4.5).
    pub star_split: Signal<Out, Bit>,
    /// The main FSM's `failover` (§D4): it works on channel B since its last switch.
    pub failover: Signal<Out, Bit>,
    /// Channel A `tx_done`: its frame was transmitted (§C8).
    pub chan_a_tx_done: Signal<Out, Bit>,
    /// Channel A `tx_failed`: its frame was dropped (single shot, abort; §C8).
    pub chan_a_tx_failed: Signal<Out, Bit>,
    /// Channel A `tx_pending`: a frame is latched for transmission.
    pub chan_a_tx_pending: Signal<Out, Bit>,
    /// Channel A `is_tx`: the transmitter role (P-CORE-5).
    pub chan_a_is_tx: Signal<Out, Bit>,
    /// Channel A `boff_runs`: completed runs of the bus-off recovery (P-CORE-5).
    pub chan_a_boff_runs: Signal<Out, Bits<7>>,
    /// Channel A error warning (§C9).
    pub chan_a_err_warning: Signal<Out, Bit>,
    /// Channel A transmit error counter.
    pub chan_a_tec: Signal<Out, Bits<9>>,
    /// Channel A `err_valid`: an error was detected (§C4.6).
    pub chan_a_err_valid: Signal<Out, Bit>,
    /// Channel A `err_kind` of the error.
    pub chan_a_err_kind: Signal<Out, Bits<3>>,
    /// Channel A `err_field`: the field of the error.
    pub chan_a_err_field: Signal<Out, Field>,
    /// Channel A `err_tx`: the error was found as transmitter.
    pub chan_a_err_tx: Signal<Out, Bit>,
    /// Channel A `arb_lost`: arbitration lost.
    pub chan_a_arb_lost: Signal<Out, Bit>,
    /// Channel A `alc`: the bit where arbitration was lost.
    pub chan_a_alc: Signal<Out, Bits<5>>,
    /// Channel B `tx_done`: its frame was transmitted (§C8).
    pub chan_b_tx_done: Signal<Out, Bit>,
    /// Channel B `tx_failed`: its frame was dropped (single shot, abort; §C8).
    pub chan_b_tx_failed: Signal<Out, Bit>,
    /// Channel B `tx_pending`: a frame is latched for transmission.
    pub chan_b_tx_pending: Signal<Out, Bit>,
    /// Channel B `is_tx`: the transmitter role (P-CORE-5).
    pub chan_b_is_tx: Signal<Out, Bit>,
    /// Channel B `boff_runs`: completed runs of the bus-off recovery (P-CORE-5).
    pub chan_b_boff_runs: Signal<Out, Bits<7>>,
    /// Channel B error warning (§C9).
    pub chan_b_err_warning: Signal<Out, Bit>,
    /// Channel B transmit error counter.
    pub chan_b_tec: Signal<Out, Bits<9>>,
    /// Channel B `err_valid`: an error was detected (§C4.6).
    pub chan_b_err_valid: Signal<Out, Bit>,
    /// Channel B `err_kind` of the error.
    pub chan_b_err_kind: Signal<Out, Bits<3>>,
    /// Channel B `err_field`: the field of the error.
    pub chan_b_err_field: Signal<Out, Field>,
    /// Channel B `err_tx`: the error was found as transmitter.
    pub chan_b_err_tx: Signal<Out, Bit>,
    /// Channel B `arb_lost`: arbitration lost.
    pub chan_b_arb_lost: Signal<Out, Bit>,
    /// Channel B `alc`: the bit where arbitration was lost.
    pub chan_b_alc: Signal<Out, Bits<5>>,
    // blocks
    regs: WbRegs,
    dmr_check: DmrCheck<M>,
    dmr_regs: DmrRegs<M>,
    filters: FilterRegs,
    // ECSS bus selection (§12)
    ecss_regs: EcssRegs,
    ecss: BusSelect,
    ecss_count: ToggleCount,
    ecss_clock: HbClock,
    mailbox_cfg: IfMailboxes<MailboxCfg, M>,
    dmr_ctl: DmrControl,
    dmr_eng: IfMailboxes<DmrEngine<M>, M>,
    status: StatusWords<M>,
    caps: Captures,
    ticker: BitTick,
    stats: RedundancyStats,
    /// The main FSM (paper Table 1); public so the unit tests can watch its pulses.
    pub main: MainFsm,
    echo: Echo,
    aux_a: AuxFsm,
    aux_b: AuxFsm,
    txbuf: TxBuffer,
    rxfifo: RxFifo,
    rxw: RxWriter,
    // every reader takes a frame at rx_valid: the channels' rx outputs are
    // valid with it only (RX_HOLD = 0, `crate::channel::bsp::rx_frame`)
    chan_a: CanChannel<0>,
    chan_b: CanChannel<0>,
    // manual bus-off recovery of each channel (§11.6)
    busoff_a: BusoffRecovery,
    busoff_b: BusoffRecovery,
    // glue
    clear: Signal<Local, Bit>,
    rmb_hold: Signal<Local, Bit>,
    /// Each channel's reset before the restarts (rst, reset mode, the view's).
    chan_reset_a: Signal<Local, Bit>,
    chan_reset_b: Signal<Local, Bit>,
    // the channels' received frames, laid out as the TX RAM (id, ide, rtr, dlc, data)
    rx_frame_a: Signal<Local, Bits<99>>,
    rx_frame_b: Signal<Local, Bits<99>>,
    // the mailbox blocks' outputs (0 with M = 0)
    mb_id_word: Signal<Local, Bits<31>>,
    mb_mask: Signal<Local, Bits<29>>,
    mb_state_word: Signal<Local, Bits<32>>,
    eval_fault: Signal<Local, Bit>,
    eval_line: Signal<Local, Bit>,
    eval_tx: Signal<Local, Bit>,
    eval_deviation: Signal<Local, Bit>,
    eval_mb: Signal<Local, Bits<4>>,
    zero4: Const<4, 0>,
    zero29: Const<29, 0>,
    zero31: Const<31, 0>,
    zero32: Const<32, 0>,
}

impl<const M: usize> DrccCore<M> {
    /// The DRCC with the sizes of `cfg` (its `mailboxes` must be `M`): the TX
    /// queues, the RX FIFO and the duplicate-removal history (`crate::config`).
    pub fn with_config(cfg: &DrccConfig) -> Self {
        assert_eq!(cfg.mailboxes, M, "DrccCore<{M}> has {M} DMR mailboxes");
        cfg.check().unwrap_or_else(|e| panic!("{e}"));
        let mut dmr_check = DmrCheck::<M>::new();
        dmr_check.dmr_present = Param::new(cfg.dmr as u64);
        Self {
            regs: WbRegs::with_config(cfg),
            status: StatusWords::with_config(cfg),
            dmr_check,
            txbuf: TxBuffer::new(cfg.tx_queue_depth),
            rxfifo: RxFifo::new(cfg.rx_fifo_depth),
            rxw: RxWriter::new(cfg.history, cfg.rx_fifo_depth),
            ..Default::default()
        }
    }
}

// The update (every block's wiring) lives beside this file.
mod wiring;
