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
//! set by [`DrccTop::with_config`] (`crate::config`; `drcc_small`).
//!
//! The logic is the core's ([`DrccCore`], `crate::drcc_core`); this top gives it its
//! ports and ties its host-view inputs off, so the native register block is the
//! host.

use crate::channel::bsp::field::Field;
use crate::channel::sized::Const;
use crate::config::DrccConfig;
use crate::dmr::engine::MAILBOXES;
use crate::drcc_core::DrccCore;
use rust_hdl::prelude::*;

/// The DRCC with the default 16 DMR mailboxes (`rtl-out/drcc.v`).
pub type Drcc = DrccTop<MAILBOXES>;

/// The DRCC without DMR mailboxes (`rtl-out/drcc_m0.v`).
pub type DrccM0 = DrccTop<0>;

/// The DRCC top, generated with `M` DMR mailboxes (0..16).
#[derive(LogicBlock, Default)]
pub struct DrccTop<const M: usize> {
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
    // the DRCC core, its host-view inputs tied off
    /// The core (public for block-level probes in tests).
    pub core: DrccCore<M>,
    zero2: Const<2, 0>,
    zero28: Const<28, 0>,
    zero32: Const<32, 0>,
    zero99: Const<99, 0>,
}

impl<const M: usize> DrccTop<M> {
    /// The DRCC with the sizes of `cfg` (its `mailboxes` must be `M`): the TX
    /// queues, the RX FIFO and the duplicate-removal history (`crate::config`).
    pub fn with_config(cfg: &DrccConfig) -> Self {
        Self {
            core: DrccCore::with_config(cfg),
            ..Default::default()
        }
    }
}

impl<const M: usize> Logic for DrccTop<M> {
    #[hdl_gen]
    fn update(&mut self) {
        self.core.clk.next = self.clk.val();
        self.core.rst.next = self.rst.val();
        self.core.wb_cyc_i.next = self.wb_cyc_i.val();
        self.core.wb_stb_i.next = self.wb_stb_i.val();
        self.core.wb_we_i.next = self.wb_we_i.val();
        self.core.wb_adr_i.next = self.wb_adr_i.val();
        self.core.wb_dat_i.next = self.wb_dat_i.val();
        self.core.wb_sel_i.next = self.wb_sel_i.val();
        self.core.chan_a_rx.next = self.chan_a_rx.val();
        self.core.chan_b_rx.next = self.chan_b_rx.val();
        self.wb_dat_o.next = self.core.wb_dat_o.val();
        self.wb_ack_o.next = self.core.wb_ack_o.val();
        self.wb_err_o.next = self.core.wb_err_o.val();
        self.irq.next = self.core.irq.val();
        self.chan_a_tx.next = self.core.chan_a_tx.val();
        self.chan_b_tx.next = self.core.chan_b_tx.val();
        self.state.next = self.core.state.val();
        self.tx_channel.next = self.core.tx_channel.val();
        self.transmission_ack.next = self.core.transmission_ack.val();
        self.chan_a_transmission_req.next = self.core.chan_a_transmission_req.val();
        self.chan_b_transmission_req.next = self.core.chan_b_transmission_req.val();
        self.tx_success.next = self.core.tx_success.val();
        self.tx_ok_channel.next = self.core.tx_ok_channel.val();
        self.tx_failure.next = self.core.tx_failure.val();
        self.tx_failure_channel.next = self.core.tx_failure_channel.val();
        self.tx_going_on.next = self.core.tx_going_on.val();
        self.chan_a_bsp_tx_err_cnt.next = self.core.chan_a_bsp_tx_err_cnt.val();
        self.chan_a_bsp_node_error_passive.next = self.core.chan_a_bsp_node_error_passive.val();
        self.chan_b_bsp_tx_err_cnt.next = self.core.chan_b_bsp_tx_err_cnt.val();
        self.chan_b_bsp_node_error_passive.next = self.core.chan_b_bsp_node_error_passive.val();
        self.aux_a_state.next = self.core.aux_a_state.val();
        self.aux_b_state.next = self.core.aux_b_state.val();
        self.chan_a_sample_point.next = self.core.chan_a_sample_point.val();
        self.chan_b_sample_point.next = self.core.chan_b_sample_point.val();
        self.chan_a_field.next = self.core.chan_a_field.val();
        self.chan_b_field.next = self.core.chan_b_field.val();
        self.chan_a_rec.next = self.core.chan_a_rec.val();
        self.chan_b_rec.next = self.core.chan_b_rec.val();
        self.chan_a_err_state.next = self.core.chan_a_err_state.val();
        self.chan_b_err_state.next = self.core.chan_b_err_state.val();
        self.dmr_state.next = self.core.dmr_state.val();
        self.acl.next = self.core.acl.val();
        self.dcl_tx_fault.next = self.core.dcl_tx_fault.val();
        self.dcl_rx_fault.next = self.core.dcl_rx_fault.val();
        self.rcl_tx_fault.next = self.core.rcl_tx_fault.val();
        self.rcl_rx_fault.next = self.core.rcl_rx_fault.val();
        self.dmr_tick.next = self.core.dmr_tick.val();
        // no host view: the native register block is the host
        self.core.view_on.next = false;
        self.core.view_ctrl.next = self.zero32.val();
        self.core.view_btr.next = self.zero28.val();
        self.core.view_chan_reset.next = self.zero2.val();
        self.core.view_push.next = false;
        self.core.view_push_q.next = false;
        self.core.view_push_frame.next = self.zero99.val();
        self.core.view_pop.next = false;
        self.core.view_tx_single.next = false;
        self.core.view_tx_abort.next = self.zero2.val();
        self.core.view_boff_hold.next = self.zero2.val();
        self.core.view_offer_s.next = false;
        self.core.view_frame_s.next = self.zero99.val();
        self.core.view_gate_on.next = false;
        self.core.view_afm.next = false;
        self.core.view_acr.next = self.zero32.val();
        self.core.view_amr.next = self.zero32.val();
        self.core.view_cap_rearm.next = self.zero2.val();
    }
}
