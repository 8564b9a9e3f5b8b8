//! The `drcc` top: the dual-redundancy CAN controller of the DRCC paper
//! (sections II-IV, Table 1), as fixed clock by clock by
//! `cosim/src/model/drcc_contract.md`. Two `can_channel`s (A = the paper's
//! channel 1, B = channel 2) share one bit timing; the redundancy management
//! block (main FSM of Table 1, one auxiliary FSM per channel, bit tick), the TX
//! buffer, the RX FIFO with duplicate removal and the Wishbone register block
//! complete it; a replicated star node (`CTRL.star`, contract §4.4, §4.5) adds the
//! echo of the node's own frames and follows the hubs' identification frames
//! (`crate::rmb::echo`, `crate::rmb::star`: `STAR_STATUS`, `INT_STATUS.domain`;
//! neither frame reaches the RX path). The third mode, CiA 701
//! dual-modular redundancy (`dmr_contract.md`), adds the DMR control and
//! mailbox engine (`crate::dmr`) and the DMR paths of the TX buffer and the RX
//! writer. Ports (contract §1): clock/reset, Wishbone slave, irq, CAN pins, the
//! paper's probes, the channel probes, the DMR probes (DMR contract §9).
//!
//! Generation parameter `M`, the DMR mailboxes (0..16, DMR contract §2): `drcc` is
//! [`Drcc`] (`M = 16`), `drcc_m0` is [`DrccM0`] (`M = 0`: no mailbox engine, no
//! identifier memory; DMR faults are then found by bus-off and the connection
//! service only). The other sizes (TX queue and RX FIFO depths, the history) are
//! set by [`DrccCore::with_config`] (`crate::config`; `drcc_small`).

use crate::channel::bsp::field::Field;
use crate::channel::can_channel::CanChannel;
use crate::channel::sized::{Const, Param};
use crate::config::DrccConfig;
use crate::dmr::control::DmrControl;
use crate::dmr::engine::{DmrEngine, MAILBOXES};
use crate::dmr::if_mailboxes::IfMailboxes;
use crate::dmr::mailbox_cfg::MailboxCfg;
use crate::host::busoff_recovery::BusoffRecovery;
use crate::host::captures::Captures;
use crate::host::dmr_check::DmrCheck;
use crate::host::dmr_regs::DmrRegs;
use crate::host::filters::FilterRegs;
use crate::host::status_words::StatusWords;
use crate::host::wishbone::WbRegs;
use crate::memory::dedup::RxWriter;
use crate::memory::rx_fifo::RxFifo;
use crate::memory::tx_buffer::TxBuffer;
use crate::rmb::aux_fsm::AuxFsm;
use crate::rmb::bit_tick::BitTick;
use crate::rmb::echo::Echo;
use crate::rmb::main_fsm::MainFsm;
use crate::rmb::stats::RedundancyStats;
use rust_hdl::prelude::*;

/// The DRCC with the default 16 DMR mailboxes (`rtl-out/drcc.v`).
pub type Drcc = DrccCore<MAILBOXES>;

/// The DRCC without DMR mailboxes (`rtl-out/drcc_m0.v`).
pub type DrccM0 = DrccCore<0>;

/// The DRCC top, generated with `M` DMR mailboxes (0..16).
#[derive(LogicBlock, Default)]
pub struct DrccCore<const M: usize> {
    // clock and reset
    /// Clock. Every register changes at its rising edge; the channels' bit timing
    /// (register `BTR`) is counted in its periods.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset of everything, active high: registers, queues, FIFO and
    /// both channels take their reset values at an edge with `rst = 1`, and the DRCC
    /// leaves it in reset mode (`CTRL.reset_mode = 1`), where the host writes the
    /// channel configuration (`CTRL`, `BTR`).
    pub rst: Signal<In, Bit>,
    // Wishbone B4 classic slave (drcc_contract.md §2); register map:
    // docs/registers.md, rtl-out/drcc_regs.h
    /// Wishbone cycle, active high. A transaction is taken at an edge where
    /// `wb_cyc_i & wb_stb_i & !(wb_ack_o | wb_err_o)`.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Wishbone strobe, active high.
    pub wb_stb_i: Signal<In, Bit>,
    /// Wishbone write enable: 1 = write, 0 = read.
    pub wb_we_i: Signal<In, Bit>,
    /// Wishbone word address: register index 0..63, byte offset = 4 x `wb_adr_i`.
    pub wb_adr_i: Signal<In, Bits<6>>,
    /// Wishbone write data. Data bytes in `TX_DATA0/1`: byte 0 (first on the
    /// bus) in `[7:0]`, unlike the channel ports.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Wishbone byte select of a write: `TX_ID`, `TX_CTRL`, `TX_DATA0/1` take
    /// the selected bytes; a partial write to another word is refused
    /// (`wb_err_o`). Ignored on reads. Tie to `4'b1111` without byte lanes.
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Wishbone read data, valid while `wb_ack_o = 1`, else 0. Reads have no side
    /// effects; unmapped addresses read 0.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Wishbone acknowledge, 1 for the clock after the edge that took the
    /// transaction: every access takes 2 clocks.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Wishbone error, instead of the acknowledge, for a refused access (it
    /// also sets `INT_STATUS.illegal`): bus_contract.md §1.
    pub wb_err_o: Signal<Out, Bit>,
    /// Interrupt request, active-high level, registered: `|(INT_STATUS & INT_ENABLE)`.
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
    /// Main FSM state: idle1 0, wait1 1, ch1 2, abort1 3, wait2 4, idle2 5, wait3 6,
    /// ch2 7, abort2 8, wait4 9.
    pub state: Signal<Out, Bits<4>>,
    /// Channel the main FSM transmits on: 0 = A, 1 = B (`state >= idle2`).
    pub tx_channel: Signal<Out, Bit>,
    /// One-clock pulse: a channel delivered the message in flight.
    pub transmission_ack: Signal<Out, Bit>,
    /// Channel A transmit request (its `tx_req`), a one-clock pulse.
    pub chan_a_transmission_req: Signal<Out, Bit>,
    /// Channel B transmit request (its `tx_req`), a one-clock pulse.
    pub chan_b_transmission_req: Signal<Out, Bit>,
    /// One-clock pulse, the clock after `transmission_ack`: the message is done and
    /// left its queue (not for the first copy of a `dual_tx` message).
    pub tx_success: Signal<Out, Bit>,
    /// Channel(s) that delivered the last message, bit 0 = A, bit 1 = B (`11`: both,
    /// `dual_tx`). Held until the next delivery; cleared in reset mode.
    pub tx_ok_channel: Signal<Out, Bits<2>>,
    /// One-clock pulse: the main FSM judged a channel failed for the message.
    pub tx_failure: Signal<Out, Bit>,
    /// Latched failed channel(s), bit 0 = A, bit 1 = B. Held until the next failure;
    /// cleared in reset mode.
    pub tx_failure_channel: Signal<Out, Bits<2>>,
    /// A transmission is in progress: `state` is neither idle1 nor idle2.
    pub tx_going_on: Signal<Out, Bit>,
    /// Channel A transmit error counter (its `tec`).
    pub chan_a_bsp_tx_err_cnt: Signal<Out, Bits<9>>,
    /// Channel A is not error active (error passive or bus-off: `err_state != 0`).
    pub chan_a_bsp_node_error_passive: Signal<Out, Bit>,
    /// Channel B transmit error counter (its `tec`).
    pub chan_b_bsp_tx_err_cnt: Signal<Out, Bits<9>>,
    /// Channel B is not error active (error passive or bus-off: `err_state != 0`).
    pub chan_b_bsp_node_error_passive: Signal<Out, Bit>,
    // other probes (drcc_contract.md §5; the channel probes of timing_contract.md)
    /// Aux FSM A, the validity of channel A: valid 0, failed 1, restart 2,
    /// probation 3.
    pub aux_a_state: Signal<Out, Bits<2>>,
    /// Aux FSM B, the validity of channel B: valid 0, failed 1, restart 2,
    /// probation 3.
    pub aux_b_state: Signal<Out, Bits<2>>,
    /// Channel A `sample_point`: one-clock pulse after each of its sample points.
    pub chan_a_sample_point: Signal<Out, Bit>,
    /// Channel B `sample_point`: one-clock pulse after each of its sample points.
    pub chan_b_sample_point: Signal<Out, Bit>,
    /// Channel A `field`: field of its next non-stuff bit (timing contract §4.1 codes).
    pub chan_a_field: Signal<Out, Field>,
    /// Channel B `field`: field of its next non-stuff bit (timing contract §4.1 codes).
    pub chan_b_field: Signal<Out, Field>,
    /// Channel A receive error counter (its `rec`).
    pub chan_a_rec: Signal<Out, Bits<8>>,
    /// Channel B receive error counter (its `rec`).
    pub chan_b_rec: Signal<Out, Bits<8>>,
    /// Channel A `err_state`: 0 error active, 1 error passive, 2 bus-off.
    pub chan_a_err_state: Signal<Out, Bits<2>>,
    /// Channel B `err_state`: 0 error active, 1 error passive, 2 bus-off.
    pub chan_b_err_state: Signal<Out, Bits<2>>,
    // DMR probes (dmr_contract.md §9; CiA 701 names), all 0 outside DMR mode
    /// DMR state: 0 redundancy active, 1 redundancy passive, 2 redundancy disabled,
    /// 3 network disconnected.
    pub dmr_state: Signal<Out, Bits<2>>,
    /// Active CAN line: 0 = DCL (channel A), 1 = RCL (channel B).
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
    // blocks
    regs: WbRegs,
    dmr_check: DmrCheck<M>,
    dmr_regs: DmrRegs<M>,
    filters: FilterRegs,
    mailbox_cfg: IfMailboxes<MailboxCfg, M>,
    dmr_ctl: DmrControl,
    dmr_eng: IfMailboxes<DmrEngine<M>, M>,
    status: StatusWords<M>,
    caps: Captures,
    ticker: BitTick,
    stats: RedundancyStats,
    pub main: MainFsm,
    echo: Echo,
    aux_a: AuxFsm,
    aux_b: AuxFsm,
    txbuf: TxBuffer,
    rxfifo: RxFifo,
    rxw: RxWriter,
    chan_a: CanChannel,
    chan_b: CanChannel,
    // manual bus-off recovery of each channel (§11.6)
    busoff_a: BusoffRecovery,
    busoff_b: BusoffRecovery,
    // glue
    clear: Signal<Local, Bit>,
    rmb_hold: Signal<Local, Bit>,
    dmr_hold: Signal<Local, Bit>,
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
#[path = "drcc_wiring.rs"]
mod wiring;
