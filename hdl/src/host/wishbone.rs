//! Wishbone B4 classic slave and register block of the DRCC top (DRCC contract
//! §2, §3, §8, §9). Decodes with the word indices of `super::registers` (the one
//! source of truth of the map).
//!
//! - A transaction is taken at an edge where `cyc & stb & !ack`: `ack <= 1` and,
//!   for a read, `dat_o <=` the register value before the edge; a write takes
//!   effect at that edge. At every other edge `ack <= 0`, `dat_o <= 0`.
//! - cfg fields (CTRL except `reset_mode`, BTR, RMB_CFG, DEDUP_CFG) are writable
//!   only in reset mode; CTRL with policy 3, or with redundancy and a
//!   LISTEN_ONLY channel, is refused; k = 0 is stored as 1;
//!   refused writes, writes to RO/unmapped registers, a refused push or pop set
//!   `INT_STATUS.illegal` (§9).
//! - `INT_STATUS` is W1C, an event at the same edge wins; `irq <=
//!   |(INT_STATUS & INT_ENABLE)` (§8). The `err_state` event is raised here when
//!   either channel's error state differs from its value one clock earlier.
//! - STATS1 (switches, recoveries) count here; the other statistics come in.

use super::registers as map;
use rust_hdl::prelude::*;

/// Wishbone register block.
#[derive(LogicBlock)]
pub struct WbRegs {
    // clock and reset
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Wishbone B4 classic slave
    pub wb_cyc_i: Signal<In, Bit>,
    pub wb_stb_i: Signal<In, Bit>,
    pub wb_we_i: Signal<In, Bit>,
    pub wb_adr_i: Signal<In, Bits<6>>,
    pub wb_dat_i: Signal<In, Bits<32>>,
    pub wb_dat_o: Signal<Out, Bits<32>>,
    pub wb_ack_o: Signal<Out, Bit>,
    pub irq: Signal<Out, Bit>,
    // status inputs (all registered in their blocks)
    pub state: Signal<In, Bits<4>>,
    pub tx_channel: Signal<In, Bit>,
    pub tx_going_on: Signal<In, Bit>,
    pub aux_a_state: Signal<In, Bits<2>>,
    pub aux_b_state: Signal<In, Bits<2>>,
    pub es_a: Signal<In, Bits<2>>,
    pub es_b: Signal<In, Bits<2>>,
    pub txq_a: Signal<In, Bits<4>>,
    pub txq_b: Signal<In, Bits<4>>,
    pub rx_count: Signal<In, Bits<6>>,
    pub tec_a: Signal<In, Bits<9>>,
    pub rec_a: Signal<In, Bits<8>>,
    pub ew_a: Signal<In, Bit>,
    pub tec_b: Signal<In, Bits<9>>,
    pub rec_b: Signal<In, Bits<8>>,
    pub ew_b: Signal<In, Bit>,
    pub causes_a: Signal<In, Bits<4>>,
    pub fail_cnt_a: Signal<In, Bits<4>>,
    pub failures_a: Signal<In, Bits<8>>,
    pub recoveries_a: Signal<In, Bits<8>>,
    pub causes_b: Signal<In, Bits<4>>,
    pub fail_cnt_b: Signal<In, Bits<4>>,
    pub failures_b: Signal<In, Bits<8>>,
    pub recoveries_b: Signal<In, Bits<8>>,
    pub rx_head: Signal<In, Bits<100>>,
    pub rx_ready: Signal<In, Bit>,
    pub duplicates: Signal<In, Bits<16>>,
    pub overruns: Signal<In, Bits<16>>,
    pub last_tx_time: Signal<In, Bits<16>>,
    pub switch_time: Signal<In, Bits<16>>,
    // events (INT_STATUS, STATS1)
    pub ev_rx: Signal<In, Bit>,
    pub ev_tx_done: Signal<In, Bit>,
    pub ev_switch: Signal<In, Bit>,
    pub ev_overrun: Signal<In, Bit>,
    pub ev_tx_failure: Signal<In, Bit>,
    pub ev_aux: Signal<In, Bit>,
    pub ev_recover_a: Signal<In, Bit>,
    pub ev_recover_b: Signal<In, Bit>,
    // configuration outputs
    pub reset_mode: Signal<Out, Bit>,
    /// `reset_mode` one edge earlier (1 after `rst`): the channels stay in reset
    /// one clock after reset mode (contract §6).
    pub reset_mode_d: Signal<Out, Bit>,
    pub redundancy: Signal<Out, Bit>,
    pub policy: Signal<Out, Bits<2>>,
    pub dual_tx: Signal<Out, Bit>,
    pub k: Signal<Out, Bits<4>>,
    pub mode_a: Signal<Out, Bits<2>>,
    pub mode_b: Signal<Out, Bits<2>>,
    pub single_shot: Signal<Out, Bit>,
    pub brp: Signal<Out, Bits<6>>,
    pub tseg1: Signal<Out, Bits<4>>,
    pub tseg2: Signal<Out, Bits<3>>,
    pub sjw: Signal<Out, Bits<2>>,
    pub triple: Signal<Out, Bit>,
    pub ewl: Signal<Out, Bits<8>>,
    pub recovery_bits: Signal<Out, Bits<16>>,
    pub stall_limit: Signal<Out, Bits<16>>,
    pub window: Signal<Out, Bits<15>>,
    // commands
    pub push: Signal<Out, Bit>,
    pub push_q: Signal<Out, Bit>,
    pub tx_frame: Signal<Out, Bits<99>>,
    pub pop: Signal<Out, Bit>,
    // registers
    ack_q: DFF<Bit>,
    dat_q: DFF<Bits<32>>,
    irq_q: DFF<Bit>,
    reset_mode_q: DFF<Bit>,
    reset_mode_dq: DFF<Bit>,
    redundancy_q: DFF<Bit>,
    policy_q: DFF<Bits<2>>,
    dual_tx_q: DFF<Bit>,
    k_q: DFF<Bits<4>>,
    mode_a_q: DFF<Bits<2>>,
    mode_b_q: DFF<Bits<2>>,
    single_shot_q: DFF<Bit>,
    btr_q: DFF<Bits<24>>,
    rmb_cfg_q: DFF<Bits<32>>,
    window_q: DFF<Bits<15>>,
    int_status: DFF<Bits<8>>,
    int_enable: DFF<Bits<8>>,
    tx_id_q: DFF<Bits<31>>,
    tx_dlc_q: DFF<Bits<4>>,
    tx_queue_q: DFF<Bit>,
    tx_data0_q: DFF<Bits<32>>,
    tx_data1_q: DFF<Bits<32>>,
    switches_q: DFF<Bits<16>>,
    recov_q: DFF<Bits<16>>,
    es_a_prev: DFF<Bits<2>>,
    es_b_prev: DFF<Bits<2>>,
    // decode
    taken: Signal<Local, Bit>,
    wr: Signal<Local, Bit>,
    rdata: Signal<Local, Bits<32>>,
    wdat: Signal<Local, Bits<32>>,
    illegal: Signal<Local, Bit>,
    w1c: Signal<Local, Bits<8>>,
    k_w: Signal<Local, Bits<4>>,
    cfg_differs: Signal<Local, Bit>,
    target_count: Signal<Local, Bits<4>>,
    events: Signal<Local, Bits<8>>,
    es_evt: Signal<Local, Bit>,
    ctrl_val: Signal<Local, Bits<32>>,
    status_val: Signal<Local, Bits<32>>,
    tx_data64: Signal<Local, Bits<64>>,
    rx_data64: Signal<Local, Bits<64>>,
    // register indices (from the register map)
    a_id: Constant<Bits<6>>,
    a_ctrl: Constant<Bits<6>>,
    a_btr: Constant<Bits<6>>,
    a_rmb_cfg: Constant<Bits<6>>,
    a_dedup_cfg: Constant<Bits<6>>,
    a_status: Constant<Bits<6>>,
    a_int_status: Constant<Bits<6>>,
    a_int_enable: Constant<Bits<6>>,
    a_chan_a_err: Constant<Bits<6>>,
    a_chan_b_err: Constant<Bits<6>>,
    a_aux_a: Constant<Bits<6>>,
    a_aux_b: Constant<Bits<6>>,
    a_tx_id: Constant<Bits<6>>,
    a_tx_ctrl: Constant<Bits<6>>,
    a_tx_data0: Constant<Bits<6>>,
    a_tx_data1: Constant<Bits<6>>,
    a_tx_cmd: Constant<Bits<6>>,
    a_rx_id: Constant<Bits<6>>,
    a_rx_ctrl: Constant<Bits<6>>,
    a_rx_data0: Constant<Bits<6>>,
    a_rx_data1: Constant<Bits<6>>,
    a_rx_cmd: Constant<Bits<6>>,
    a_stats0: Constant<Bits<6>>,
    a_stats1: Constant<Bits<6>>,
    a_times: Constant<Bits<6>>,
    // constants
    id_value: Constant<Bits<32>>,
    ctrl_reset_btr: Constant<Bits<24>>,
    rmb_cfg_reset: Constant<Bits<32>>,
    window_reset: Constant<Bits<15>>,
    policy_illegal: Constant<Bits<2>>,
    mode_listen: Constant<Bits<2>>,
    policy_reset: Constant<Bits<2>>,
    zero2: Constant<Bits<2>>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    full4: Constant<Bits<4>>,
    zero6: Constant<Bits<6>>,
    zero8: Constant<Bits<8>>,
    zero15: Constant<Bits<15>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    two16: Constant<Bits<16>>,
    max16: Constant<Bits<16>>,
    max16m1: Constant<Bits<16>>,
    zero24: Constant<Bits<24>>,
    zero31: Constant<Bits<31>>,
    zero32: Constant<Bits<32>>,
}

fn adr(index: u32) -> Constant<Bits<6>> {
    Constant::new((index as u64).into())
}

fn field_reset(reg: &str, field: &str) -> u64 {
    let r = map::register(reg).expect("register in the map");
    let f = r
        .fields
        .iter()
        .find(|f| f.name == field)
        .expect("field in the map");
    f.reset as u64
}

impl Default for WbRegs {
    fn default() -> Self {
        let btr = map::register("BTR").unwrap().reset_value() as u64;
        let rmb = map::register("RMB_CFG").unwrap().reset_value() as u64;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_adr_i: Default::default(),
            wb_dat_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            irq: Default::default(),
            state: Default::default(),
            tx_channel: Default::default(),
            tx_going_on: Default::default(),
            aux_a_state: Default::default(),
            aux_b_state: Default::default(),
            es_a: Default::default(),
            es_b: Default::default(),
            txq_a: Default::default(),
            txq_b: Default::default(),
            rx_count: Default::default(),
            tec_a: Default::default(),
            rec_a: Default::default(),
            ew_a: Default::default(),
            tec_b: Default::default(),
            rec_b: Default::default(),
            ew_b: Default::default(),
            causes_a: Default::default(),
            fail_cnt_a: Default::default(),
            failures_a: Default::default(),
            recoveries_a: Default::default(),
            causes_b: Default::default(),
            fail_cnt_b: Default::default(),
            failures_b: Default::default(),
            recoveries_b: Default::default(),
            rx_head: Default::default(),
            rx_ready: Default::default(),
            duplicates: Default::default(),
            overruns: Default::default(),
            last_tx_time: Default::default(),
            switch_time: Default::default(),
            ev_rx: Default::default(),
            ev_tx_done: Default::default(),
            ev_switch: Default::default(),
            ev_overrun: Default::default(),
            ev_tx_failure: Default::default(),
            ev_aux: Default::default(),
            ev_recover_a: Default::default(),
            ev_recover_b: Default::default(),
            reset_mode: Default::default(),
            reset_mode_d: Default::default(),
            redundancy: Default::default(),
            policy: Default::default(),
            dual_tx: Default::default(),
            k: Default::default(),
            mode_a: Default::default(),
            mode_b: Default::default(),
            single_shot: Default::default(),
            brp: Default::default(),
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
            ack_q: Default::default(),
            dat_q: Default::default(),
            irq_q: Default::default(),
            reset_mode_q: Default::default(),
            reset_mode_dq: Default::default(),
            redundancy_q: Default::default(),
            policy_q: Default::default(),
            dual_tx_q: Default::default(),
            k_q: Default::default(),
            mode_a_q: Default::default(),
            mode_b_q: Default::default(),
            single_shot_q: Default::default(),
            btr_q: Default::default(),
            rmb_cfg_q: Default::default(),
            window_q: Default::default(),
            int_status: Default::default(),
            int_enable: Default::default(),
            tx_id_q: Default::default(),
            tx_dlc_q: Default::default(),
            tx_queue_q: Default::default(),
            tx_data0_q: Default::default(),
            tx_data1_q: Default::default(),
            switches_q: Default::default(),
            recov_q: Default::default(),
            es_a_prev: Default::default(),
            es_b_prev: Default::default(),
            taken: Default::default(),
            wr: Default::default(),
            rdata: Default::default(),
            wdat: Default::default(),
            illegal: Default::default(),
            w1c: Default::default(),
            k_w: Default::default(),
            cfg_differs: Default::default(),
            target_count: Default::default(),
            events: Default::default(),
            es_evt: Default::default(),
            ctrl_val: Default::default(),
            status_val: Default::default(),
            tx_data64: Default::default(),
            rx_data64: Default::default(),
            a_id: adr(map::ID),
            a_ctrl: adr(map::CTRL),
            a_btr: adr(map::BTR),
            a_rmb_cfg: adr(map::RMB_CFG),
            a_dedup_cfg: adr(map::DEDUP_CFG),
            a_status: adr(map::STATUS),
            a_int_status: adr(map::INT_STATUS),
            a_int_enable: adr(map::INT_ENABLE),
            a_chan_a_err: adr(map::CHAN_A_ERR),
            a_chan_b_err: adr(map::CHAN_B_ERR),
            a_aux_a: adr(map::AUX_A),
            a_aux_b: adr(map::AUX_B),
            a_tx_id: adr(map::TX_ID),
            a_tx_ctrl: adr(map::TX_CTRL),
            a_tx_data0: adr(map::TX_DATA0),
            a_tx_data1: adr(map::TX_DATA1),
            a_tx_cmd: adr(map::TX_CMD),
            a_rx_id: adr(map::RX_ID),
            a_rx_ctrl: adr(map::RX_CTRL),
            a_rx_data0: adr(map::RX_DATA0),
            a_rx_data1: adr(map::RX_DATA1),
            a_rx_cmd: adr(map::RX_CMD),
            a_stats0: adr(map::STATS0),
            a_stats1: adr(map::STATS1),
            a_times: adr(map::TIMES),
            id_value: Constant::new((map::ID_VALUE as u64).into()),
            ctrl_reset_btr: Constant::new(btr.into()),
            rmb_cfg_reset: Constant::new(rmb.into()),
            window_reset: Constant::new(field_reset("DEDUP_CFG", "window").into()),
            policy_illegal: Constant::new(3.into()),
            mode_listen: Constant::new(1.into()),
            policy_reset: Constant::new(field_reset("CTRL", "policy").into()),
            zero2: Constant::new(0.into()),
            zero4: Constant::new(0.into()),
            one4: Constant::new(1.into()),
            full4: Constant::new(8.into()),
            zero6: Constant::new(0.into()),
            zero8: Constant::new(0.into()),
            zero15: Constant::new(0.into()),
            zero16: Constant::new(0.into()),
            one16: Constant::new(1.into()),
            two16: Constant::new(2.into()),
            max16: Constant::new(0xFFFF.into()),
            max16m1: Constant::new(0xFFFE.into()),
            zero24: Constant::new(0.into()),
            zero31: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl Logic for WbRegs {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            ack_q,
            dat_q,
            irq_q,
            reset_mode_q,
            reset_mode_dq,
            redundancy_q,
            policy_q,
            dual_tx_q,
            k_q,
            mode_a_q,
            mode_b_q,
            single_shot_q,
            btr_q,
            rmb_cfg_q,
            window_q,
            int_status,
            int_enable,
            tx_id_q,
            tx_dlc_q,
            tx_queue_q,
            tx_data0_q,
            tx_data1_q,
            switches_q,
            recov_q,
            es_a_prev,
            es_b_prev
        );
        self.taken.next = self.wb_cyc_i.val() & self.wb_stb_i.val() & !self.ack_q.q.val();
        self.wr.next = self.taken.val() & self.wb_we_i.val();
        self.wdat.next = self.wb_dat_i.val();
        self.es_evt.next = (self.es_a.val() != self.es_a_prev.q.val())
            | (self.es_b.val() != self.es_b_prev.q.val());

        // ---- read values ----
        self.ctrl_val.next = bit_cast::<32, 1>(self.reset_mode_q.q.val().into())
            | (bit_cast::<32, 1>(self.redundancy_q.q.val().into()) << 1)
            | (bit_cast::<32, 2>(self.policy_q.q.val()) << 2)
            | (bit_cast::<32, 1>(self.dual_tx_q.q.val().into()) << 4)
            | (bit_cast::<32, 4>(self.k_q.q.val()) << 8)
            | (bit_cast::<32, 2>(self.mode_a_q.q.val()) << 12)
            | (bit_cast::<32, 2>(self.mode_b_q.q.val()) << 14)
            | (bit_cast::<32, 1>(self.single_shot_q.q.val().into()) << 16);
        self.status_val.next = bit_cast::<32, 4>(self.state.val())
            | (bit_cast::<32, 1>(self.tx_channel.val().into()) << 4)
            | (bit_cast::<32, 2>(self.aux_a_state.val()) << 5)
            | (bit_cast::<32, 2>(self.aux_b_state.val()) << 7)
            | (bit_cast::<32, 2>(self.es_a.val()) << 9)
            | (bit_cast::<32, 2>(self.es_b.val()) << 11)
            | (bit_cast::<32, 1>(self.reset_mode_q.q.val().into()) << 13)
            | (bit_cast::<32, 1>(self.tx_going_on.val().into()) << 14)
            | (bit_cast::<32, 4>(self.txq_a.val()) << 16)
            | (bit_cast::<32, 4>(self.txq_b.val()) << 20)
            | (bit_cast::<32, 6>(self.rx_count.val()) << 24);
        // register byte order: byte 0 in [7:0]; channel order: byte 0 in [63:56]
        self.rx_data64.next = self.rx_head.val().get_bits::<64>(0);
        self.tx_data64.next = (bit_cast::<64, 8>(self.tx_data0_q.q.val().get_bits::<8>(0)) << 56)
            | (bit_cast::<64, 8>(self.tx_data0_q.q.val().get_bits::<8>(8)) << 48)
            | (bit_cast::<64, 8>(self.tx_data0_q.q.val().get_bits::<8>(16)) << 40)
            | (bit_cast::<64, 8>(self.tx_data0_q.q.val().get_bits::<8>(24)) << 32)
            | (bit_cast::<64, 8>(self.tx_data1_q.q.val().get_bits::<8>(0)) << 24)
            | (bit_cast::<64, 8>(self.tx_data1_q.q.val().get_bits::<8>(8)) << 16)
            | (bit_cast::<64, 8>(self.tx_data1_q.q.val().get_bits::<8>(16)) << 8)
            | bit_cast::<64, 8>(self.tx_data1_q.q.val().get_bits::<8>(24));

        self.rdata.next = self.zero32.val();
        if self.wb_adr_i.val() == self.a_id.val() {
            self.rdata.next = self.id_value.val();
        } else if self.wb_adr_i.val() == self.a_ctrl.val() {
            self.rdata.next = self.ctrl_val.val();
        } else if self.wb_adr_i.val() == self.a_btr.val() {
            self.rdata.next = bit_cast::<32, 24>(self.btr_q.q.val());
        } else if self.wb_adr_i.val() == self.a_rmb_cfg.val() {
            self.rdata.next = self.rmb_cfg_q.q.val();
        } else if self.wb_adr_i.val() == self.a_dedup_cfg.val() {
            self.rdata.next = bit_cast::<32, 15>(self.window_q.q.val());
        } else if self.wb_adr_i.val() == self.a_status.val() {
            self.rdata.next = self.status_val.val();
        } else if self.wb_adr_i.val() == self.a_int_status.val() {
            self.rdata.next = bit_cast::<32, 8>(self.int_status.q.val());
        } else if self.wb_adr_i.val() == self.a_int_enable.val() {
            self.rdata.next = bit_cast::<32, 8>(self.int_enable.q.val());
        } else if self.wb_adr_i.val() == self.a_chan_a_err.val() {
            self.rdata.next = bit_cast::<32, 9>(self.tec_a.val())
                | (bit_cast::<32, 8>(self.rec_a.val()) << 16)
                | (bit_cast::<32, 2>(self.es_a.val()) << 24)
                | (bit_cast::<32, 1>(self.ew_a.val().into()) << 26);
        } else if self.wb_adr_i.val() == self.a_chan_b_err.val() {
            self.rdata.next = bit_cast::<32, 9>(self.tec_b.val())
                | (bit_cast::<32, 8>(self.rec_b.val()) << 16)
                | (bit_cast::<32, 2>(self.es_b.val()) << 24)
                | (bit_cast::<32, 1>(self.ew_b.val().into()) << 26);
        } else if self.wb_adr_i.val() == self.a_aux_a.val() {
            self.rdata.next = bit_cast::<32, 2>(self.aux_a_state.val())
                | (bit_cast::<32, 4>(self.causes_a.val()) << 2)
                | (bit_cast::<32, 4>(self.fail_cnt_a.val()) << 8)
                | (bit_cast::<32, 8>(self.failures_a.val()) << 16)
                | (bit_cast::<32, 8>(self.recoveries_a.val()) << 24);
        } else if self.wb_adr_i.val() == self.a_aux_b.val() {
            self.rdata.next = bit_cast::<32, 2>(self.aux_b_state.val())
                | (bit_cast::<32, 4>(self.causes_b.val()) << 2)
                | (bit_cast::<32, 4>(self.fail_cnt_b.val()) << 8)
                | (bit_cast::<32, 8>(self.failures_b.val()) << 16)
                | (bit_cast::<32, 8>(self.recoveries_b.val()) << 24);
        } else if self.wb_adr_i.val() == self.a_tx_id.val() {
            self.rdata.next = bit_cast::<32, 31>(self.tx_id_q.q.val());
        } else if self.wb_adr_i.val() == self.a_tx_ctrl.val() {
            self.rdata.next = bit_cast::<32, 4>(self.tx_dlc_q.q.val())
                | (bit_cast::<32, 1>(self.tx_queue_q.q.val().into()) << 8);
        } else if self.wb_adr_i.val() == self.a_tx_data0.val() {
            self.rdata.next = self.tx_data0_q.q.val();
        } else if self.wb_adr_i.val() == self.a_tx_data1.val() {
            self.rdata.next = self.tx_data1_q.q.val();
        } else if self.wb_adr_i.val() == self.a_rx_id.val() {
            self.rdata.next = bit_cast::<32, 31>(self.rx_head.val().get_bits::<31>(68))
                | (bit_cast::<32, 1>(self.rx_ready.val().into()) << 31);
        } else if self.wb_adr_i.val() == self.a_rx_ctrl.val() {
            self.rdata.next = bit_cast::<32, 4>(self.rx_head.val().get_bits::<4>(64))
                | (bit_cast::<32, 1>(self.rx_head.val().get_bit(99).into()) << 8);
        } else if self.wb_adr_i.val() == self.a_rx_data0.val() {
            self.rdata.next = bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(56))
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(48)) << 8)
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(40)) << 16)
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(32)) << 24);
        } else if self.wb_adr_i.val() == self.a_rx_data1.val() {
            self.rdata.next = bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(24))
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(16)) << 8)
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(8)) << 16)
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(0)) << 24);
        } else if self.wb_adr_i.val() == self.a_stats0.val() {
            self.rdata.next = bit_cast::<32, 16>(self.duplicates.val())
                | (bit_cast::<32, 16>(self.overruns.val()) << 16);
        } else if self.wb_adr_i.val() == self.a_stats1.val() {
            self.rdata.next = bit_cast::<32, 16>(self.switches_q.q.val())
                | (bit_cast::<32, 16>(self.recov_q.q.val()) << 16);
        } else if self.wb_adr_i.val() == self.a_times.val() {
            self.rdata.next = bit_cast::<32, 16>(self.last_tx_time.val())
                | (bit_cast::<32, 16>(self.switch_time.val()) << 16);
        }

        // ---- Wishbone handshake ----
        self.ack_q.d.next = self.taken.val();
        self.dat_q.d.next = self.zero32.val();
        if self.taken.val() & !self.wb_we_i.val() {
            self.dat_q.d.next = self.rdata.val();
        }

        // ---- writes ----
        self.reset_mode_q.d.next = self.reset_mode_q.q.val();
        self.reset_mode_dq.d.next = self.reset_mode_q.q.val();
        self.redundancy_q.d.next = self.redundancy_q.q.val();
        self.policy_q.d.next = self.policy_q.q.val();
        self.dual_tx_q.d.next = self.dual_tx_q.q.val();
        self.k_q.d.next = self.k_q.q.val();
        self.mode_a_q.d.next = self.mode_a_q.q.val();
        self.mode_b_q.d.next = self.mode_b_q.q.val();
        self.single_shot_q.d.next = self.single_shot_q.q.val();
        self.btr_q.d.next = self.btr_q.q.val();
        self.rmb_cfg_q.d.next = self.rmb_cfg_q.q.val();
        self.window_q.d.next = self.window_q.q.val();
        self.int_enable.d.next = self.int_enable.q.val();
        self.tx_id_q.d.next = self.tx_id_q.q.val();
        self.tx_dlc_q.d.next = self.tx_dlc_q.q.val();
        self.tx_queue_q.d.next = self.tx_queue_q.q.val();
        self.tx_data0_q.d.next = self.tx_data0_q.q.val();
        self.tx_data1_q.d.next = self.tx_data1_q.q.val();
        self.illegal.next = false;
        self.w1c.next = self.zero8.val();
        self.push.next = false;
        self.pop.next = false;

        // CTRL.k: 0 is stored as 1
        if self.wdat.val().get_bits::<4>(8) == self.zero4.val() {
            self.k_w.next = self.one4.val();
        } else {
            self.k_w.next = self.wdat.val().get_bits::<4>(8);
        }
        self.cfg_differs.next = (self.wdat.val().get_bit(1) != self.redundancy_q.q.val())
            | (self.wdat.val().get_bits::<2>(2) != self.policy_q.q.val())
            | (self.wdat.val().get_bit(4) != self.dual_tx_q.q.val())
            | (self.k_w.val() != self.k_q.q.val())
            | (self.wdat.val().get_bits::<2>(12) != self.mode_a_q.q.val())
            | (self.wdat.val().get_bits::<2>(14) != self.mode_b_q.q.val())
            | (self.wdat.val().get_bit(16) != self.single_shot_q.q.val());
        // target queue of a push: A in redundancy mode, else TX_CTRL.queue
        if self.tx_queue_q.q.val() & !self.redundancy_q.q.val() {
            self.target_count.next = self.txq_b.val();
        } else {
            self.target_count.next = self.txq_a.val();
        }

        if self.wr.val() {
            if self.wb_adr_i.val() == self.a_ctrl.val() {
                if self.reset_mode_q.q.val() {
                    // policy 3, or redundancy with a LISTEN_ONLY channel (§9)
                    if (self.wdat.val().get_bits::<2>(2) == self.policy_illegal.val())
                        | (self.wdat.val().get_bit(1)
                            & ((self.wdat.val().get_bits::<2>(12) == self.mode_listen.val())
                                | (self.wdat.val().get_bits::<2>(14) == self.mode_listen.val())))
                    {
                        self.illegal.next = true;
                    } else {
                        self.reset_mode_q.d.next = self.wdat.val().get_bit(0);
                        self.redundancy_q.d.next = self.wdat.val().get_bit(1);
                        self.policy_q.d.next = self.wdat.val().get_bits::<2>(2);
                        self.dual_tx_q.d.next = self.wdat.val().get_bit(4);
                        self.k_q.d.next = self.k_w.val();
                        self.mode_a_q.d.next = self.wdat.val().get_bits::<2>(12);
                        self.mode_b_q.d.next = self.wdat.val().get_bits::<2>(14);
                        self.single_shot_q.d.next = self.wdat.val().get_bit(16);
                    }
                } else {
                    self.reset_mode_q.d.next = self.wdat.val().get_bit(0);
                    self.illegal.next = self.cfg_differs.val();
                }
            } else if self.wb_adr_i.val() == self.a_btr.val() {
                if self.reset_mode_q.q.val() {
                    self.btr_q.d.next = self.wdat.val().get_bits::<24>(0);
                } else {
                    self.illegal.next = true;
                }
            } else if self.wb_adr_i.val() == self.a_rmb_cfg.val() {
                if self.reset_mode_q.q.val() {
                    self.rmb_cfg_q.d.next = self.wdat.val();
                } else {
                    self.illegal.next = true;
                }
            } else if self.wb_adr_i.val() == self.a_dedup_cfg.val() {
                if self.reset_mode_q.q.val() {
                    self.window_q.d.next = self.wdat.val().get_bits::<15>(0);
                } else {
                    self.illegal.next = true;
                }
            } else if self.wb_adr_i.val() == self.a_int_status.val() {
                self.w1c.next = self.wdat.val().get_bits::<8>(0);
            } else if self.wb_adr_i.val() == self.a_int_enable.val() {
                self.int_enable.d.next = self.wdat.val().get_bits::<8>(0);
            } else if self.wb_adr_i.val() == self.a_tx_id.val() {
                self.tx_id_q.d.next = self.wdat.val().get_bits::<31>(0);
            } else if self.wb_adr_i.val() == self.a_tx_ctrl.val() {
                self.tx_dlc_q.d.next = self.wdat.val().get_bits::<4>(0);
                self.tx_queue_q.d.next = self.wdat.val().get_bit(8);
            } else if self.wb_adr_i.val() == self.a_tx_data0.val() {
                self.tx_data0_q.d.next = self.wdat.val();
            } else if self.wb_adr_i.val() == self.a_tx_data1.val() {
                self.tx_data1_q.d.next = self.wdat.val();
            } else if self.wb_adr_i.val() == self.a_tx_cmd.val() {
                if self.wdat.val().get_bit(0) {
                    if self.reset_mode_q.q.val() | (self.target_count.val() == self.full4.val()) {
                        self.illegal.next = true;
                    } else {
                        self.push.next = true;
                    }
                }
            } else if self.wb_adr_i.val() == self.a_rx_cmd.val() {
                if self.wdat.val().get_bit(0) {
                    if self.rx_count.val() == self.zero6.val() {
                        self.illegal.next = true;
                    } else {
                        self.pop.next = true;
                    }
                }
            } else {
                // read-only or unmapped
                self.illegal.next = true;
            }
        }

        // ---- interrupts and statistics ----
        self.events.next = bit_cast::<8, 1>(self.ev_rx.val().into())
            | (bit_cast::<8, 1>(self.ev_tx_done.val().into()) << 1)
            | (bit_cast::<8, 1>(self.ev_switch.val().into()) << 2)
            | (bit_cast::<8, 1>(self.es_evt.val().into()) << 3)
            | (bit_cast::<8, 1>(self.ev_overrun.val().into()) << 4)
            | (bit_cast::<8, 1>(self.ev_tx_failure.val().into()) << 5)
            | (bit_cast::<8, 1>(self.illegal.val().into()) << 6)
            | (bit_cast::<8, 1>(self.ev_aux.val().into()) << 7);
        self.int_status.d.next = (self.int_status.q.val() & !self.w1c.val()) | self.events.val();
        self.irq_q.d.next = (self.int_status.q.val() & self.int_enable.q.val()) != self.zero8.val();
        self.es_a_prev.d.next = self.es_a.val();
        self.es_b_prev.d.next = self.es_b.val();
        self.switches_q.d.next = self.switches_q.q.val();
        if self.ev_switch.val() & (self.switches_q.q.val() != self.max16.val()) {
            self.switches_q.d.next = self.switches_q.q.val() + self.one16.val();
        }
        self.recov_q.d.next = self.recov_q.q.val();
        if self.ev_recover_a.val() & self.ev_recover_b.val() {
            if self.recov_q.q.val() >= self.max16m1.val() {
                self.recov_q.d.next = self.max16.val();
            } else {
                self.recov_q.d.next = self.recov_q.q.val() + self.two16.val();
            }
        } else if (self.ev_recover_a.val() | self.ev_recover_b.val())
            & (self.recov_q.q.val() != self.max16.val())
        {
            self.recov_q.d.next = self.recov_q.q.val() + self.one16.val();
        }

        if self.rst.val() {
            self.ack_q.d.next = false;
            self.dat_q.d.next = self.zero32.val();
            self.irq_q.d.next = false;
            self.reset_mode_q.d.next = true;
            self.reset_mode_dq.d.next = true;
            self.redundancy_q.d.next = false;
            self.policy_q.d.next = self.policy_reset.val();
            self.dual_tx_q.d.next = false;
            self.k_q.d.next = self.one4.val();
            self.mode_a_q.d.next = self.zero2.val();
            self.mode_b_q.d.next = self.zero2.val();
            self.single_shot_q.d.next = false;
            self.btr_q.d.next = self.ctrl_reset_btr.val();
            self.rmb_cfg_q.d.next = self.rmb_cfg_reset.val();
            self.window_q.d.next = self.window_reset.val();
            self.int_status.d.next = self.zero8.val();
            self.int_enable.d.next = self.zero8.val();
            self.tx_id_q.d.next = self.zero31.val();
            self.tx_dlc_q.d.next = self.zero4.val();
            self.tx_queue_q.d.next = false;
            self.tx_data0_q.d.next = self.zero32.val();
            self.tx_data1_q.d.next = self.zero32.val();
            self.switches_q.d.next = self.zero16.val();
            self.recov_q.d.next = self.zero16.val();
            self.es_a_prev.d.next = self.zero2.val();
            self.es_b_prev.d.next = self.zero2.val();
            self.push.next = false;
            self.pop.next = false;
        }

        // ---- outputs ----
        self.wb_ack_o.next = self.ack_q.q.val();
        self.wb_dat_o.next = self.dat_q.q.val();
        self.irq.next = self.irq_q.q.val();
        self.reset_mode.next = self.reset_mode_q.q.val();
        self.reset_mode_d.next = self.reset_mode_dq.q.val();
        self.redundancy.next = self.redundancy_q.q.val();
        self.policy.next = self.policy_q.q.val();
        self.dual_tx.next = self.dual_tx_q.q.val();
        self.k.next = self.k_q.q.val();
        self.mode_a.next = self.mode_a_q.q.val();
        self.mode_b.next = self.mode_b_q.q.val();
        self.single_shot.next = self.single_shot_q.q.val();
        self.brp.next = self.btr_q.q.val().get_bits::<6>(0);
        self.tseg1.next = self.btr_q.q.val().get_bits::<4>(6);
        self.tseg2.next = self.btr_q.q.val().get_bits::<3>(10);
        self.sjw.next = self.btr_q.q.val().get_bits::<2>(13);
        self.triple.next = self.btr_q.q.val().get_bit(15);
        self.ewl.next = self.btr_q.q.val().get_bits::<8>(16);
        self.recovery_bits.next = self.rmb_cfg_q.q.val().get_bits::<16>(0);
        self.stall_limit.next = self.rmb_cfg_q.q.val().get_bits::<16>(16);
        self.window.next = self.window_q.q.val();
        self.push_q.next = self.tx_queue_q.q.val() & !self.redundancy_q.q.val();
        self.tx_frame.next = (bit_cast::<99, 31>(self.tx_id_q.q.val()) << 68)
            | (bit_cast::<99, 4>(self.tx_dlc_q.q.val()) << 64)
            | bit_cast::<99, 64>(self.tx_data64.val());
    }
}

#[test]
fn wb_regs_synthesizes() {
    let mut uut = WbRegs::default();
    uut.connect_all();
    yosys_validate("wb_regs", &generate_verilog(&uut)).unwrap();
}
