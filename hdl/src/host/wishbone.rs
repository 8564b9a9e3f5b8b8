//! The DRCC's register block (DRCC contract §2, §3, §8, §9): the Wishbone slave
//! front end (`super::wb_slave`), the write side of the map (configuration,
//! the staged TX frame, commands), and the interrupt events (`STATS1` is counted by `crate::rmb::stats`). Word
//! indices and field positions come from the table (`super::registers`); the
//! read-only words are assembled beside it by `super::status_words` and come in
//! as `ro_word`.
//!
//! - Byte lanes (bus_contract.md §1): `TX_ID`, `TX_CTRL`, `TX_DATA0/1` take the
//!   selected bytes and keep the others; a partial write to any other word is
//!   refused. A refused access ends with `wb_err_o` instead of `wb_ack_o`.
//! - cfg fields (CTRL except `reset_mode`, BTR, RMB_CFG, DEDUP_CFG) are writable
//!   only in reset mode; CTRL with redundancy and a listen-only channel is
//!   refused; k = 0 is stored as 1; refused writes,
//!   writes to RO/unmapped registers, a refused push or pop set
//!   `INT_STATUS.illegal` (§9).
//! - The `err_state` event is raised here when either channel's error state
//!   differs from its value one clock earlier (§8).

use super::ctrl_check::CtrlCheck;
use super::ctrl_reg::CtrlReg;
use super::map::lsb;
use super::registers::{self as map, MAP};
use super::wb_slave::WbSlave;
use crate::channel::sized::Param;
use crate::channel::BRP_BITS;
use crate::config::DrccConfig;
use rust_hdl::prelude::*;

/// The DRCC's Wishbone register block.
#[derive(LogicBlock)]
pub struct WbRegs {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: every register to its table reset value.
    pub rst: Signal<In, Bit>,
    // ---- Wishbone B4 classic slave ----
    /// Cycle in progress.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Strobe.
    pub wb_stb_i: Signal<In, Bit>,
    /// Write enable.
    pub wb_we_i: Signal<In, Bit>,
    /// Word index.
    pub wb_adr_i: Signal<In, Bits<6>>,
    /// Write data.
    pub wb_dat_i: Signal<In, Bits<32>>,
    /// Byte lanes of a write (lane i = `wb_dat_i[8i+7:8i]`).
    pub wb_sel_i: Signal<In, Bits<4>>,
    /// Read data (registered, with the ack).
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Acknowledge (registered).
    pub wb_ack_o: Signal<Out, Bit>,
    /// Error: the access was refused (registered, instead of the ack).
    pub wb_err_o: Signal<Out, Bit>,
    /// Interrupt request (registered).
    pub irq: Signal<Out, Bit>,
    // ---- host view (PeliCAN contract §14; 0 in the native top) ----
    /// 1 = `view_ctrl` and `view_btr` replace the stored `CTRL` and `BTR`
    /// (fields, reads); the registers keep their values.
    pub view_on: Signal<In, Bit>,
    /// The `CTRL` word of a host view.
    pub view_ctrl: Signal<In, Bits<32>>,
    /// The `BTR` word of a host view.
    pub view_btr: Signal<In, Bits<28>>,
    // ---- status in ----
    /// The addressed read-only register (`super::status_words`), 0 otherwise.
    pub ro_word: Signal<In, Bits<32>>,
    /// Channel A error state (the `err_state` event).
    pub es_a: Signal<In, Bits<2>>,
    /// Channel B error state.
    pub es_b: Signal<In, Bits<2>>,
    /// TX queue A count (a push to a full queue is refused).
    pub txq_a: Signal<In, Bits<4>>,
    /// TX queue B count.
    pub txq_b: Signal<In, Bits<4>>,
    /// RX FIFO count (a pop of an empty FIFO is refused).
    pub rx_count: Signal<In, Bits<6>>,
    // ---- events in (INT_STATUS, STATS1) ----
    /// A frame was written to the RX FIFO.
    pub ev_rx: Signal<In, Bit>,
    /// A message was sent.
    pub ev_tx_done: Signal<In, Bit>,
    /// The main FSM switched channel.
    pub ev_switch: Signal<In, Bit>,
    /// A received frame was dropped (RX FIFO full).
    pub ev_overrun: Signal<In, Bit>,
    /// A message failed.
    pub ev_tx_failure: Signal<In, Bit>,
    /// An aux FSM judged a channel failed or recovered it.
    pub ev_aux: Signal<In, Bit>,
    // ---- the DMR registers (super::dmr_regs) ----
    /// `wb_adr_i` is a DMR register: `ext_word` is its value.
    pub ext_hit: Signal<In, Bit>,
    /// The addressed DMR register's value.
    pub ext_word: Signal<In, Bits<32>>,
    /// `wb_adr_i` is a writable DMR register: its block decides the refusal.
    pub ext_writable: Signal<In, Bit>,
    /// The DMR block refuses the write at this edge.
    pub ext_illegal: Signal<In, Bit>,
    /// The DMR state or the active line changed (`INT_STATUS.dmr`).
    pub ev_dmr: Signal<In, Bit>,
    /// A star node's `STAR_STATUS.split` changed (`INT_STATUS.domain`, §4.5).
    pub ev_domain: Signal<In, Bit>,
    /// A channel's warning flag changed (`INT_STATUS.err_warning`, §10.2).
    pub ev_err_warning: Signal<In, Bit>,
    /// A channel lost arbitration (`INT_STATUS.arb_lost`).
    pub ev_arb_lost: Signal<In, Bit>,
    /// A channel detected a bus error (`INT_STATUS.bus_error`).
    pub ev_bus_error: Signal<In, Bit>,
    /// Channel A's `tx_done` (`INT_STATUS.tx_done_a`, §11.3).
    pub ev_tx_done_a: Signal<In, Bit>,
    /// Channel B's `tx_done`.
    pub ev_tx_done_b: Signal<In, Bit>,
    /// Channel A's `tx_failed` (`INT_STATUS.tx_failure_a`).
    pub ev_tx_failure_a: Signal<In, Bit>,
    /// Channel B's `tx_failed`.
    pub ev_tx_failure_b: Signal<In, Bit>,
    /// The ECSS bus selection toggled or gave up (`INT_STATUS.bus_toggle`, §12).
    pub ev_bus_toggle: Signal<In, Bit>,
    /// A whole-word write is taken at this edge (the DMR registers take no other).
    pub wr_o: Signal<Out, Bit>,
    // ---- configuration out ----
    /// `CTRL.reset_mode`.
    pub reset_mode: Signal<Out, Bit>,
    /// `reset_mode` one edge earlier (1 after `rst`): the channels stay in reset
    /// one clock after reset mode (contract §6).
    pub reset_mode_d: Signal<Out, Bit>,
    /// `CTRL.redundancy` ([`map::Mode`]).
    pub redundancy: Signal<Out, Bit>,
    /// `CTRL.policy` ([`map::SwitchPolicy`]).
    pub policy: Signal<Out, Bits<2>>,
    /// `CTRL.dual_tx`.
    pub dual_tx: Signal<Out, Bit>,
    /// `CTRL.star`: replicated star node (contract §4.4).
    pub star: Signal<Out, Bit>,
    /// `CTRL.k` (1..15).
    pub k: Signal<Out, Bits<4>>,
    /// `CTRL.mode_a` ([`ChannelMode`]).
    pub mode_a: Signal<Out, Bits<2>>,
    /// `CTRL.mode_b` ([`ChannelMode`]).
    pub mode_b: Signal<Out, Bits<2>>,
    /// `CTRL.single_shot`.
    pub single_shot: Signal<Out, Bit>,
    /// `CTRL.dmr`: CiA 701 DMR mode.
    pub dmr: Signal<Out, Bit>,
    /// `CTRL.busoff_manual`: bus-off recovery at the host's request (§11.6).
    pub busoff_manual: Signal<Out, Bit>,
    /// `CTRL.first_copy`: DMR first-copy delivery (DMR contract §8.1).
    pub first_copy: Signal<Out, Bit>,
    /// The prescaler BRP, `{BTR.brp_ext, BTR.brp}` (0..1023).
    pub brp: Signal<Out, Bits<BRP_BITS>>,
    /// `BTR.tseg1`.
    pub tseg1: Signal<Out, Bits<4>>,
    /// `BTR.tseg2`.
    pub tseg2: Signal<Out, Bits<3>>,
    /// `BTR.sjw`.
    pub sjw: Signal<Out, Bits<2>>,
    /// `BTR.triple`.
    pub triple: Signal<Out, Bit>,
    /// `BTR.ewl`.
    pub ewl: Signal<Out, Bits<8>>,
    /// `RMB_CFG.recovery_bits`.
    pub recovery_bits: Signal<Out, Bits<16>>,
    /// `RMB_CFG.stall_limit`.
    pub stall_limit: Signal<Out, Bits<16>>,
    /// `DEDUP_CFG.window`.
    pub window: Signal<Out, Bits<15>>,
    // ---- commands out ----
    /// `TX_CMD.push` accepted: append `tx_frame` to a TX queue.
    pub push: Signal<Out, Bit>,
    /// Queue of the push: 1 = B (normal mode with `TX_CTRL.queue`).
    pub push_q: Signal<Out, Bit>,
    /// The staged frame: [98:68] {rtr, ide, id}, [67:64] dlc, [63:0] data.
    pub tx_frame: Signal<Out, Bits<99>>,
    /// `TX_CMD.abort_a` accepted (§11.5): queue A keeps only what a channel holds.
    pub abort_a: Signal<Out, Bit>,
    /// `TX_CMD.abort_b` accepted.
    pub abort_b: Signal<Out, Bit>,
    /// `TX_CMD.recover_a` accepted (§11.6): bus-off channel A may recover.
    pub recover_a: Signal<Out, Bit>,
    /// `TX_CMD.recover_b` accepted.
    pub recover_b: Signal<Out, Bit>,
    /// `RX_CMD.pop` accepted.
    pub pop: Signal<Out, Bit>,
    /// `INT_STATUS.bus_error` written 1: the error captures re-arm (§10.2).
    pub rearm_err: Signal<Out, Bit>,
    /// `INT_STATUS.arb_lost` written 1: the arbitration-lost captures re-arm.
    pub rearm_alc: Signal<Out, Bit>,
    /// `STATS_CLR.clear` written 1: the statistics clear at this edge (§11.4).
    pub stats_clear: Signal<Out, Bit>,
    // ---- blocks ----
    bus: WbSlave<18>,
    ctrl: CtrlReg,
    ctrl_check: CtrlCheck,
    // ---- registers ----
    btr_q: DFF<Bits<28>>,
    /// The BTR in force: the stored one or a host view's.
    btr_word: Signal<Local, Bits<28>>,
    rmb_cfg_q: DFF<Bits<32>>,
    window_q: DFF<Bits<15>>,
    tx_id_q: DFF<Bits<31>>,
    tx_dlc_q: DFF<Bits<4>>,
    tx_queue_q: DFF<Bit>,
    tx_data0_q: DFF<Bits<32>>,
    tx_data1_q: DFF<Bits<32>>,
    es_a_prev: DFF<Bits<2>>,
    es_b_prev: DFF<Bits<2>>,
    /// The access answered now was refused: its ack is `ERR` (bus_contract.md §1).
    err_q: DFF<Bit>,
    // ---- decode ----
    wr: Signal<Local, Bit>,
    /// All four byte lanes are selected.
    full: Signal<Local, Bit>,
    /// The addressed word honours byte lanes (the staged TX frame).
    laned: Signal<Local, Bit>,
    /// `wb_sel_i` widened to bits.
    lane_mask: Signal<Local, Bits<32>>,
    /// The addressed laned word's value (0 for the others).
    lane_old: Signal<Local, Bits<32>>,
    /// `TX_CTRL` as it reads.
    tx_ctrl_word: Signal<Local, Bits<32>>,
    rdata: Signal<Local, Bits<32>>,
    wdat: Signal<Local, Bits<32>>,
    illegal: Signal<Local, Bit>,
    w1c: Signal<Local, Bits<18>>,
    target_count: Signal<Local, Bits<4>>,
    es_evt: Signal<Local, Bit>,
    tx_data64: Signal<Local, Bits<64>>,
    // ---- word indices (from the table) ----
    a_ctrl: Constant<Bits<6>>,
    a_btr: Constant<Bits<6>>,
    a_rmb_cfg: Constant<Bits<6>>,
    a_dedup_cfg: Constant<Bits<6>>,
    a_int_status: Constant<Bits<6>>,
    a_int_enable: Constant<Bits<6>>,
    a_tx_id: Constant<Bits<6>>,
    a_tx_ctrl: Constant<Bits<6>>,
    a_tx_data0: Constant<Bits<6>>,
    a_tx_data1: Constant<Bits<6>>,
    a_tx_cmd: Constant<Bits<6>>,
    a_rx_cmd: Constant<Bits<6>>,
    a_stats_clr: Constant<Bits<6>>,
    // ---- field positions (from the table) ----
    b_brp: Constant<Bits<5>>,
    b_brp_ext: Constant<Bits<5>>,
    brp_ext_shift: Constant<Bits<4>>,
    b_tseg1: Constant<Bits<5>>,
    b_tseg2: Constant<Bits<5>>,
    b_sjw: Constant<Bits<5>>,
    b_triple: Constant<Bits<5>>,
    b_ewl: Constant<Bits<5>>,
    r_recovery: Constant<Bits<5>>,
    r_stall: Constant<Bits<5>>,
    d_window: Constant<Bits<5>>,
    t_dlc: Constant<Bits<5>>,
    t_queue: Constant<Bits<5>>,
    t_push: Constant<Bits<5>>,
    t_abort_a: Constant<Bits<5>>,
    t_abort_b: Constant<Bits<5>>,
    t_recover_a: Constant<Bits<5>>,
    t_recover_b: Constant<Bits<5>>,
    r_pop: Constant<Bits<5>>,
    c_clear: Constant<Bits<5>>,
    i_rx: Constant<Bits<5>>,
    i_tx_done: Constant<Bits<5>>,
    i_switch: Constant<Bits<5>>,
    i_err_state: Constant<Bits<5>>,
    i_overrun: Constant<Bits<5>>,
    i_tx_failure: Constant<Bits<5>>,
    i_illegal: Constant<Bits<5>>,
    i_aux: Constant<Bits<5>>,
    i_dmr: Constant<Bits<5>>,
    i_domain: Constant<Bits<5>>,
    i_err_warning: Constant<Bits<5>>,
    i_arb_lost: Constant<Bits<5>>,
    i_bus_error: Constant<Bits<5>>,
    i_tx_done_a: Constant<Bits<5>>,
    i_tx_done_b: Constant<Bits<5>>,
    i_tx_failure_a: Constant<Bits<5>>,
    i_tx_failure_b: Constant<Bits<5>>,
    i_bus_toggle: Constant<Bits<5>>,
    /// `INT_STATUS.bus_error` as a mask (the re-arm of §10.2).
    m_bus_error: Constant<Bits<18>>,
    /// `INT_STATUS.arb_lost` as a mask.
    m_arb_lost: Constant<Bits<18>>,
    // ---- reset values and codes ----
    btr_reset: Constant<Bits<28>>,
    rmb_cfg_reset: Constant<Bits<32>>,
    window_reset: Constant<Bits<15>>,
    queue_full: Constant<Bits<4>>,
    zero2: Constant<Bits<2>>,
    zero4: Constant<Bits<4>>,
    zero6: Constant<Bits<6>>,
    zero18: Constant<Bits<18>>,
    zero15: Constant<Bits<15>>,
    zero16: Constant<Bits<16>>,
    zero31: Constant<Bits<31>>,
    zero32: Constant<Bits<32>>,
    all_lanes: Constant<Bits<4>>,
    lane0: Constant<Bits<32>>,
    lane1: Constant<Bits<32>>,
    lane2: Constant<Bits<32>>,
    lane3: Constant<Bits<32>>,
}

fn adr(index: u32) -> Constant<Bits<6>> {
    Constant::new((index as u64).into())
}

/// Reset value of `reg` (or of one of its fields) as an RTL constant.
fn reset<const B: usize>(value: u32) -> Constant<Bits<B>> {
    Constant::new((value as u64).into())
}

/// Checks that `reg`'s fields fit in the `bits` low bits the RTL stores.
fn stored_in(reg: &str, bits: u32) {
    let r = map::register(reg).expect("register in the map");
    assert!(
        (r.defined() as u64) >> bits == 0,
        "register map DRCC: {reg} has fields above bit {}, the RTL stores {bits} bits",
        bits - 1
    );
}

impl Default for WbRegs {
    fn default() -> Self {
        stored_in("BTR", 28);
        stored_in("RMB_CFG", 32);
        stored_in("INT_STATUS", 18);
        stored_in("INT_ENABLE", 18);
        let field_reset = |reg: &str, field: &str| MAP.field(reg, field).reset;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_sel_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            wb_err_o: Default::default(),
            irq: Default::default(),
            ro_word: Default::default(),
            es_a: Default::default(),
            es_b: Default::default(),
            txq_a: Default::default(),
            txq_b: Default::default(),
            rx_count: Default::default(),
            ev_rx: Default::default(),
            ev_tx_done: Default::default(),
            ev_switch: Default::default(),
            ev_overrun: Default::default(),
            ev_tx_failure: Default::default(),
            ev_aux: Default::default(),
            reset_mode: Default::default(),
            reset_mode_d: Default::default(),
            redundancy: Default::default(),
            policy: Default::default(),
            dual_tx: Default::default(),
            star: Default::default(),
            k: Default::default(),
            mode_a: Default::default(),
            mode_b: Default::default(),
            single_shot: Default::default(),
            dmr: Default::default(),
            busoff_manual: Default::default(),
            first_copy: Default::default(),
            ext_hit: Default::default(),
            ext_word: Default::default(),
            ext_writable: Default::default(),
            ext_illegal: Default::default(),
            ev_dmr: Default::default(),
            ev_domain: Default::default(),
            ev_err_warning: Default::default(),
            ev_arb_lost: Default::default(),
            ev_bus_error: Default::default(),
            ev_tx_done_a: Default::default(),
            ev_tx_done_b: Default::default(),
            ev_tx_failure_a: Default::default(),
            ev_tx_failure_b: Default::default(),
            ev_bus_toggle: Default::default(),
            wr_o: Default::default(),
            brp: Default::default(),
            view_on: Default::default(),
            view_ctrl: Default::default(),
            view_btr: Default::default(),
            tseg1: Default::default(),
            tseg2: Default::default(),
            sjw: Default::default(),
            triple: Default::default(),
            ewl: Default::default(),
            recovery_bits: Default::default(),
            stall_limit: Default::default(),
            window: Default::default(),
            push: Default::default(),
            push_q: Default::default(),
            tx_frame: Default::default(),
            pop: Default::default(),
            rearm_err: Default::default(),
            rearm_alc: Default::default(),
            stats_clear: Default::default(),
            abort_a: Default::default(),
            abort_b: Default::default(),
            recover_a: Default::default(),
            recover_b: Default::default(),
            bus: Default::default(),
            ctrl: Default::default(),
            ctrl_check: Default::default(),
            btr_q: Default::default(),
            btr_word: Default::default(),
            rmb_cfg_q: Default::default(),
            window_q: Default::default(),
            tx_id_q: Default::default(),
            tx_dlc_q: Default::default(),
            tx_queue_q: Default::default(),
            tx_data0_q: Default::default(),
            tx_data1_q: Default::default(),
            es_a_prev: Default::default(),
            es_b_prev: Default::default(),
            err_q: Default::default(),
            wr: Default::default(),
            full: Default::default(),
            laned: Default::default(),
            lane_mask: Default::default(),
            lane_old: Default::default(),
            tx_ctrl_word: Default::default(),
            rdata: Default::default(),
            wdat: Default::default(),
            illegal: Default::default(),
            w1c: Default::default(),
            target_count: Default::default(),
            es_evt: Default::default(),
            tx_data64: Default::default(),
            a_ctrl: adr(map::CTRL),
            a_btr: adr(map::BTR),
            a_rmb_cfg: adr(map::RMB_CFG),
            a_dedup_cfg: adr(map::DEDUP_CFG),
            a_int_status: adr(map::INT_STATUS),
            a_int_enable: adr(map::INT_ENABLE),
            a_tx_id: adr(map::TX_ID),
            a_tx_ctrl: adr(map::TX_CTRL),
            a_tx_data0: adr(map::TX_DATA0),
            a_tx_data1: adr(map::TX_DATA1),
            a_tx_cmd: adr(map::TX_CMD),
            a_rx_cmd: adr(map::RX_CMD),
            a_stats_clr: adr(map::STATS_CLR),
            b_brp: lsb(&MAP, "BTR", "brp", 6),
            b_brp_ext: lsb(&MAP, "BTR", "brp_ext", 4),
            brp_ext_shift: Constant::new(6.into()),
            b_tseg1: lsb(&MAP, "BTR", "tseg1", 4),
            b_tseg2: lsb(&MAP, "BTR", "tseg2", 3),
            b_sjw: lsb(&MAP, "BTR", "sjw", 2),
            b_triple: lsb(&MAP, "BTR", "triple", 1),
            b_ewl: lsb(&MAP, "BTR", "ewl", 8),
            r_recovery: lsb(&MAP, "RMB_CFG", "recovery_bits", 16),
            r_stall: lsb(&MAP, "RMB_CFG", "stall_limit", 16),
            d_window: lsb(&MAP, "DEDUP_CFG", "window", 15),
            t_dlc: lsb(&MAP, "TX_CTRL", "dlc", 4),
            t_queue: lsb(&MAP, "TX_CTRL", "queue", 1),
            t_push: lsb(&MAP, "TX_CMD", "push", 1),
            t_abort_a: lsb(&MAP, "TX_CMD", "abort_a", 1),
            t_abort_b: lsb(&MAP, "TX_CMD", "abort_b", 1),
            t_recover_a: lsb(&MAP, "TX_CMD", "recover_a", 1),
            t_recover_b: lsb(&MAP, "TX_CMD", "recover_b", 1),
            r_pop: lsb(&MAP, "RX_CMD", "pop", 1),
            c_clear: lsb(&MAP, "STATS_CLR", "clear", 1),
            i_rx: lsb(&MAP, "INT_STATUS", "rx", 1),
            i_tx_done: lsb(&MAP, "INT_STATUS", "tx_done", 1),
            i_switch: lsb(&MAP, "INT_STATUS", "switch", 1),
            i_err_state: lsb(&MAP, "INT_STATUS", "err_state", 1),
            i_overrun: lsb(&MAP, "INT_STATUS", "overrun", 1),
            i_tx_failure: lsb(&MAP, "INT_STATUS", "tx_failure", 1),
            i_illegal: lsb(&MAP, "INT_STATUS", "illegal", 1),
            i_aux: lsb(&MAP, "INT_STATUS", "aux", 1),
            i_dmr: lsb(&MAP, "INT_STATUS", "dmr", 1),
            i_domain: lsb(&MAP, "INT_STATUS", "domain", 1),
            i_err_warning: lsb(&MAP, "INT_STATUS", "err_warning", 1),
            i_arb_lost: lsb(&MAP, "INT_STATUS", "arb_lost", 1),
            i_bus_error: lsb(&MAP, "INT_STATUS", "bus_error", 1),
            i_tx_done_a: lsb(&MAP, "INT_STATUS", "tx_done_a", 1),
            i_tx_done_b: lsb(&MAP, "INT_STATUS", "tx_done_b", 1),
            i_tx_failure_a: lsb(&MAP, "INT_STATUS", "tx_failure_a", 1),
            i_tx_failure_b: lsb(&MAP, "INT_STATUS", "tx_failure_b", 1),
            i_bus_toggle: lsb(&MAP, "INT_STATUS", "bus_toggle", 1),
            m_bus_error: Constant::new((MAP.field("INT_STATUS", "bus_error").mask() as u64).into()),
            m_arb_lost: Constant::new((MAP.field("INT_STATUS", "arb_lost").mask() as u64).into()),
            btr_reset: reset(map::register("BTR").unwrap().reset_value()),
            rmb_cfg_reset: reset(map::register("RMB_CFG").unwrap().reset_value()),
            window_reset: reset(field_reset("DEDUP_CFG", "window")),
            queue_full: reset(8),
            zero2: Constant::new(0.into()),
            zero4: Constant::new(0.into()),
            zero6: Constant::new(0.into()),
            zero18: Constant::new(0.into()),
            zero15: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
            zero31: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
            all_lanes: Constant::new(0xF.into()),
            lane0: Constant::new(0xFF.into()),
            lane1: Constant::new(0xFF00.into()),
            lane2: Constant::new(0xFF_0000.into()),
            lane3: Constant::new(0xFF00_0000u64.into()),
        }
    }
}

impl WbRegs {
    /// The register block of a DRCC generated with `cfg` (contract §1.1): a push
    /// to a TX queue holding `tx_queue_depth` frames is refused (§6), and so is
    /// a `CTRL` with `dmr` / `star` when the configuration lacks that mode.
    pub fn with_config(cfg: &DrccConfig) -> Self {
        let mut r = Self {
            queue_full: reset(cfg.tx_queue_depth as u32),
            ..Default::default()
        };
        r.ctrl.dmr_present = Param::new(cfg.dmr as u64);
        r.ctrl.star_present = Param::new(cfg.star as u64);
        r.ctrl_check.dmr_present = Param::new(cfg.dmr as u64);
        r.ctrl_check.star_present = Param::new(cfg.star as u64);
        r
    }
}

// The update (the access decode, the writes, the events) lives beside this file.
#[path = "wishbone_update.rs"]
mod update;
