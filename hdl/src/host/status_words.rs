//! The read-only registers of the DRCC map (contract §3): `ID`, `STATUS`,
//! `CHAN_x_ERR`, `AUX_x`, the head of the RX FIFO (`RX_ID`, `RX_CTRL`,
//! `RX_DATAx`), `STATS0`, `STATS1`, `TIMES`, `STAR_STATUS` (§4.5, assembled by
//! `crate::rmb::star`), `OMISSIONS` (§7), `VERSION`, `SIZES` and `CAP_x` (§10,
//! the captures assembled by `super::captures`), `RX_TIME` (§11.2), from the status of the
//! blocks that own it, with every field at its position in the table
//! (`super::registers`). Combinational: `word` is the addressed register's value
//! (0 when the address is not one of them); the register block registers it
//! through its Wishbone slave.

use super::map::{lsb, placed};
use super::registers::{self as map, MAP};
use crate::channel::sized::Param;
use crate::config::DrccConfig;
use rust_hdl::prelude::*;

/// The read-only words of the DRCC register map, for a DRCC with `M` DMR
/// mailboxes (`SIZES.mailboxes`).
#[derive(LogicBlock)]
pub struct StatusWords<const M: usize> {
    /// Word index on the bus (`wb_adr_i`).
    pub adr: Signal<In, Bits<6>>,
    /// The addressed read-only register, 0 for any other address.
    pub word: Signal<Out, Bits<32>>,
    // ---- main FSM (STATUS, TIMES) ----
    /// Main FSM state (paper Table 1).
    pub state: Signal<In, Bits<4>>,
    /// Channel in use: 0 A, 1 B.
    pub tx_channel: Signal<In, Bit>,
    /// A transmission is in progress.
    pub tx_going_on: Signal<In, Bit>,
    /// Bit times from the first request to the delivery of the last message.
    pub last_tx_time: Signal<In, Bits<16>>,
    /// Bit times from the first request to the failover of the last switch.
    pub switch_time: Signal<In, Bits<16>>,
    /// `CTRL.reset_mode` (mirrored in STATUS).
    pub reset_mode: Signal<In, Bit>,
    // ---- queues (STATUS) ----
    /// TX queue A count (0..8).
    pub txq_a: Signal<In, Bits<4>>,
    /// TX queue B count (0..8).
    pub txq_b: Signal<In, Bits<4>>,
    /// RX FIFO count (0..32).
    pub rx_count: Signal<In, Bits<6>>,
    // ---- channel A fault confinement (CHAN_A_ERR) ----
    /// Error state of channel A (ISO 11898-1 12.1.4).
    pub es_a: Signal<In, Bits<2>>,
    /// Transmit error counter of channel A.
    pub tec_a: Signal<In, Bits<9>>,
    /// Receive error counter of channel A.
    pub rec_a: Signal<In, Bits<8>>,
    /// Error warning of channel A.
    pub ew_a: Signal<In, Bit>,
    // ---- channel B fault confinement (CHAN_B_ERR) ----
    /// Error state of channel B.
    pub es_b: Signal<In, Bits<2>>,
    /// Transmit error counter of channel B.
    pub tec_b: Signal<In, Bits<9>>,
    /// Receive error counter of channel B.
    pub rec_b: Signal<In, Bits<8>>,
    /// Error warning of channel B.
    pub ew_b: Signal<In, Bit>,
    // ---- auxiliary FSM A (AUX_A) ----
    /// State of aux FSM A.
    pub aux_a_state: Signal<In, Bits<2>>,
    /// Latched causes (passive, bus-off, k-failed, stall, warning) of aux FSM A.
    pub causes_a: Signal<In, Bits<5>>,
    /// Failed attempts since the last success on A.
    pub fail_cnt_a: Signal<In, Bits<4>>,
    /// Times A was judged failed.
    pub failures_a: Signal<In, Bits<8>>,
    /// Times A recovered.
    pub recoveries_a: Signal<In, Bits<8>>,
    // ---- auxiliary FSM B (AUX_B) ----
    /// State of aux FSM B.
    pub aux_b_state: Signal<In, Bits<2>>,
    /// Latched causes of aux FSM B.
    pub causes_b: Signal<In, Bits<5>>,
    /// Failed attempts since the last success on B.
    pub fail_cnt_b: Signal<In, Bits<4>>,
    /// Times B was judged failed.
    pub failures_b: Signal<In, Bits<8>>,
    /// Times B recovered.
    pub recoveries_b: Signal<In, Bits<8>>,
    // ---- RX FIFO head (RX_ID, RX_CTRL, RX_DATAx) ----
    /// Head entry: [115:100] timestamp (§11.2), [99] channel, [98:68] {rtr, ide,
    /// id}, [67:64] dlc, [63:0] data (byte 0 in [63:56]).
    pub rx_head: Signal<In, Bits<116>>,
    /// `now` (§7), for `RX_TIME.now`.
    pub now: Signal<In, Bits<16>>,
    /// The head is valid.
    pub rx_ready: Signal<In, Bit>,
    // ---- statistics (STATS0, STATS1) ----
    /// Duplicates dropped.
    pub duplicates: Signal<In, Bits<16>>,
    /// Frames dropped because the RX FIFO was full.
    pub overruns: Signal<In, Bits<16>>,
    /// Channel switches.
    pub switches: Signal<In, Bits<16>>,
    /// Channel recoveries.
    pub recoveries: Signal<In, Bits<16>>,
    // ---- replicated star node, omissions (STAR_STATUS, OMISSIONS) ----
    /// `STAR_STATUS`, assembled by the star node's block.
    pub star_word: Signal<In, Bits<32>>,
    /// Frames only channel B delivered (omissions of A).
    pub omissions_a: Signal<In, Bits<16>>,
    /// Frames only channel A delivered (omissions of B).
    pub omissions_b: Signal<In, Bits<16>>,
    // ---- captures (CAP_A, CAP_B) ----
    /// `CAP_A`, assembled by `super::captures`.
    pub cap_a: Signal<In, Bits<32>>,
    /// `CAP_B`.
    pub cap_b: Signal<In, Bits<32>>,
    // ---- the sizes (SIZES, §1.1): Verilog parameters of the top but M ----
    sz_rx_fifo: Param<6, 32>,
    sz_tx_queue: Param<4, 8>,
    sz_history: Param<6, 32>,
    sz_mailboxes: Param<5, 16>,
    sz_dmr: Param<1, 1>,
    sz_star: Param<1, 1>,
    // ---- decode ----
    rx_data64: Signal<Local, Bits<64>>,
    a_id: Constant<Bits<6>>,
    a_status: Constant<Bits<6>>,
    a_chan_a_err: Constant<Bits<6>>,
    a_chan_b_err: Constant<Bits<6>>,
    a_aux_a: Constant<Bits<6>>,
    a_aux_b: Constant<Bits<6>>,
    a_rx_id: Constant<Bits<6>>,
    a_rx_ctrl: Constant<Bits<6>>,
    a_rx_data0: Constant<Bits<6>>,
    a_rx_data1: Constant<Bits<6>>,
    a_stats0: Constant<Bits<6>>,
    a_stats1: Constant<Bits<6>>,
    a_times: Constant<Bits<6>>,
    a_star_status: Constant<Bits<6>>,
    a_omissions: Constant<Bits<6>>,
    a_version: Constant<Bits<6>>,
    a_sizes: Constant<Bits<6>>,
    a_cap_a: Constant<Bits<6>>,
    a_cap_b: Constant<Bits<6>>,
    a_rx_time: Constant<Bits<6>>,
    id_value: Constant<Bits<32>>,
    version_value: Constant<Bits<32>>,
    zero32: Constant<Bits<32>>,
    // ---- field positions (from the table) ----
    st_state: Constant<Bits<5>>,
    st_tx_channel: Constant<Bits<5>>,
    st_aux_a: Constant<Bits<5>>,
    st_aux_b: Constant<Bits<5>>,
    st_es_a: Constant<Bits<5>>,
    st_es_b: Constant<Bits<5>>,
    st_reset_mode: Constant<Bits<5>>,
    st_tx_going_on: Constant<Bits<5>>,
    st_txq_a: Constant<Bits<5>>,
    st_txq_b: Constant<Bits<5>>,
    st_rx_count: Constant<Bits<5>>,
    err_tec: Constant<Bits<5>>,
    err_rec: Constant<Bits<5>>,
    err_state: Constant<Bits<5>>,
    err_warning: Constant<Bits<5>>,
    aux_state: Constant<Bits<5>>,
    aux_causes: Constant<Bits<5>>,
    aux_fail_cnt: Constant<Bits<5>>,
    aux_failures: Constant<Bits<5>>,
    aux_recoveries: Constant<Bits<5>>,
    rx_ready_at: Constant<Bits<5>>,
    rx_dlc_at: Constant<Bits<5>>,
    rx_channel_at: Constant<Bits<5>>,
    s0_duplicates: Constant<Bits<5>>,
    s0_overruns: Constant<Bits<5>>,
    s1_switches: Constant<Bits<5>>,
    s1_recoveries: Constant<Bits<5>>,
    t_last_tx: Constant<Bits<5>>,
    t_switch: Constant<Bits<5>>,
    o_a: Constant<Bits<5>>,
    o_b: Constant<Bits<5>>,
    rt_rx_time: Constant<Bits<5>>,
    rt_now: Constant<Bits<5>>,
    z_rx_fifo: Constant<Bits<5>>,
    z_tx_queue: Constant<Bits<5>>,
    z_history: Constant<Bits<5>>,
    z_mailboxes: Constant<Bits<5>>,
    z_dmr: Constant<Bits<5>>,
    z_star: Constant<Bits<5>>,
}

fn adr(index: u32) -> Constant<Bits<6>> {
    Constant::new((index as u64).into())
}

/// Checks the fields the RTL fixes by structure: the frame layout of the TX
/// queues and the RX FIFO (id, ide, rtr adjacent from bit 0), whole-word data
/// registers, the five latched causes in the aux FSM's order.
fn check_structural_fields() {
    for reg in ["TX_ID", "RX_ID"] {
        placed(&MAP, reg, "id", 0, 29);
        placed(&MAP, reg, "ide", 29, 1);
        placed(&MAP, reg, "rtr", 30, 1);
    }
    for reg in ["TX_DATA0", "TX_DATA1", "RX_DATA0", "RX_DATA1"] {
        placed(&MAP, reg, "data", 0, 32);
    }
    placed(&MAP, "ID", "id", 0, 32);
    for aux in ["AUX_A", "AUX_B"] {
        let first = MAP.field(aux, "cause_passive").lsb;
        for (i, cause) in [
            "cause_passive",
            "cause_busoff",
            "cause_kfail",
            "cause_stall",
            "cause_warning",
        ]
        .into_iter()
        .enumerate()
        {
            placed(&MAP, aux, cause, first + i as u32, 1);
        }
    }
}

impl<const M: usize> Default for StatusWords<M> {
    fn default() -> Self {
        check_structural_fields();
        // the table's SIZES reset values are the default top's sizes
        let d = DrccConfig::DEFAULT;
        for (field, size) in [
            ("rx_fifo_depth", d.rx_fifo_depth),
            ("tx_queue_depth", d.tx_queue_depth),
            ("history", d.history),
            ("mailboxes", d.mailboxes),
            ("dmr", d.dmr as usize),
            ("star", d.star as usize),
        ] {
            assert_eq!(
                MAP.field("SIZES", field).reset as usize,
                size,
                "register map DRCC: SIZES.{field} resets to the default top's size"
            );
        }
        // CHAN_B_ERR and AUX_B share the field list of CHAN_A_ERR and AUX_A
        for (a, b) in [("CHAN_A_ERR", "CHAN_B_ERR"), ("AUX_A", "AUX_B")] {
            let (a, b) = (map::register(a).unwrap(), map::register(b).unwrap());
            assert!(
                a.fields
                    .iter()
                    .zip(b.fields)
                    .all(|(x, y)| x.lsb == y.lsb && x.width == y.width)
                    && a.fields.len() == b.fields.len(),
                "register map DRCC: {} and {} must have the same layout",
                a.name,
                b.name
            );
        }
        Self {
            adr: Default::default(),
            word: Default::default(),
            state: Default::default(),
            tx_channel: Default::default(),
            tx_going_on: Default::default(),
            last_tx_time: Default::default(),
            switch_time: Default::default(),
            reset_mode: Default::default(),
            txq_a: Default::default(),
            txq_b: Default::default(),
            rx_count: Default::default(),
            es_a: Default::default(),
            tec_a: Default::default(),
            rec_a: Default::default(),
            ew_a: Default::default(),
            es_b: Default::default(),
            tec_b: Default::default(),
            rec_b: Default::default(),
            ew_b: Default::default(),
            aux_a_state: Default::default(),
            causes_a: Default::default(),
            fail_cnt_a: Default::default(),
            failures_a: Default::default(),
            recoveries_a: Default::default(),
            aux_b_state: Default::default(),
            causes_b: Default::default(),
            fail_cnt_b: Default::default(),
            failures_b: Default::default(),
            recoveries_b: Default::default(),
            rx_head: Default::default(),
            now: Default::default(),
            rx_ready: Default::default(),
            duplicates: Default::default(),
            overruns: Default::default(),
            switches: Default::default(),
            recoveries: Default::default(),
            star_word: Default::default(),
            omissions_a: Default::default(),
            omissions_b: Default::default(),
            cap_a: Default::default(),
            cap_b: Default::default(),
            sz_rx_fifo: Default::default(),
            sz_tx_queue: Default::default(),
            sz_history: Default::default(),
            sz_mailboxes: Param::new(M as u64),
            sz_dmr: Default::default(),
            sz_star: Default::default(),
            rx_data64: Default::default(),
            a_id: adr(map::ID),
            a_status: adr(map::STATUS),
            a_chan_a_err: adr(map::CHAN_A_ERR),
            a_chan_b_err: adr(map::CHAN_B_ERR),
            a_aux_a: adr(map::AUX_A),
            a_aux_b: adr(map::AUX_B),
            a_rx_id: adr(map::RX_ID),
            a_rx_ctrl: adr(map::RX_CTRL),
            a_rx_data0: adr(map::RX_DATA0),
            a_rx_data1: adr(map::RX_DATA1),
            a_stats0: adr(map::STATS0),
            a_stats1: adr(map::STATS1),
            a_times: adr(map::TIMES),
            a_star_status: adr(map::STAR_STATUS),
            a_omissions: adr(map::OMISSIONS),
            a_version: adr(map::VERSION),
            a_sizes: adr(map::SIZES),
            a_cap_a: adr(map::CAP_A),
            a_cap_b: adr(map::CAP_B),
            a_rx_time: adr(map::RX_TIME),
            id_value: Constant::new((map::ID_VALUE as u64).into()),
            version_value: Constant::new(
                (map::register("VERSION").unwrap().reset_value() as u64).into(),
            ),
            zero32: Constant::new(0.into()),
            st_state: lsb(&MAP, "STATUS", "state", 4),
            st_tx_channel: lsb(&MAP, "STATUS", "tx_channel", 1),
            st_aux_a: lsb(&MAP, "STATUS", "aux_a_state", 2),
            st_aux_b: lsb(&MAP, "STATUS", "aux_b_state", 2),
            st_es_a: lsb(&MAP, "STATUS", "err_state_a", 2),
            st_es_b: lsb(&MAP, "STATUS", "err_state_b", 2),
            st_reset_mode: lsb(&MAP, "STATUS", "reset_mode", 1),
            st_tx_going_on: lsb(&MAP, "STATUS", "tx_going_on", 1),
            st_txq_a: lsb(&MAP, "STATUS", "txq_a_count", 4),
            st_txq_b: lsb(&MAP, "STATUS", "txq_b_count", 4),
            st_rx_count: lsb(&MAP, "STATUS", "rx_count", 6),
            err_tec: lsb(&MAP, "CHAN_A_ERR", "tec", 9),
            err_rec: lsb(&MAP, "CHAN_A_ERR", "rec", 8),
            err_state: lsb(&MAP, "CHAN_A_ERR", "err_state", 2),
            err_warning: lsb(&MAP, "CHAN_A_ERR", "err_warning", 1),
            aux_state: lsb(&MAP, "AUX_A", "state", 2),
            aux_causes: lsb(&MAP, "AUX_A", "cause_passive", 1),
            aux_fail_cnt: lsb(&MAP, "AUX_A", "fail_cnt", 4),
            aux_failures: lsb(&MAP, "AUX_A", "failures", 8),
            aux_recoveries: lsb(&MAP, "AUX_A", "recoveries", 8),
            rx_ready_at: lsb(&MAP, "RX_ID", "rx_ready", 1),
            rx_dlc_at: lsb(&MAP, "RX_CTRL", "dlc", 4),
            rx_channel_at: lsb(&MAP, "RX_CTRL", "channel", 1),
            s0_duplicates: lsb(&MAP, "STATS0", "duplicates", 16),
            s0_overruns: lsb(&MAP, "STATS0", "overruns", 16),
            s1_switches: lsb(&MAP, "STATS1", "switches", 16),
            s1_recoveries: lsb(&MAP, "STATS1", "recoveries", 16),
            t_last_tx: lsb(&MAP, "TIMES", "last_tx_time", 16),
            t_switch: lsb(&MAP, "TIMES", "switch_time", 16),
            o_a: lsb(&MAP, "OMISSIONS", "omissions_a", 16),
            o_b: lsb(&MAP, "OMISSIONS", "omissions_b", 16),
            rt_rx_time: lsb(&MAP, "RX_TIME", "rx_time", 16),
            rt_now: lsb(&MAP, "RX_TIME", "now", 16),
            z_rx_fifo: lsb(&MAP, "SIZES", "rx_fifo_depth", 6),
            z_tx_queue: lsb(&MAP, "SIZES", "tx_queue_depth", 4),
            z_history: lsb(&MAP, "SIZES", "history", 6),
            z_mailboxes: lsb(&MAP, "SIZES", "mailboxes", 5),
            z_dmr: lsb(&MAP, "SIZES", "dmr", 1),
            z_star: lsb(&MAP, "SIZES", "star", 1),
        }
    }
}

impl<const M: usize> StatusWords<M> {
    /// The words of a DRCC built with `cfg`: `SIZES` reads its sizes (each a
    /// `localparam` that the top's Verilog parameters set, `crate::tops::params`).
    pub fn with_config(cfg: &DrccConfig) -> Self {
        assert_eq!(
            cfg.mailboxes, M,
            "StatusWords<{M}> is for {M} DMR mailboxes"
        );
        Self {
            sz_rx_fifo: Param::new(cfg.rx_fifo_depth as u64),
            sz_tx_queue: Param::new(cfg.tx_queue_depth as u64),
            sz_history: Param::new(cfg.history as u64),
            sz_dmr: Param::new(cfg.dmr as u64),
            sz_star: Param::new(cfg.star as u64),
            ..Default::default()
        }
    }
}

impl<const M: usize> Logic for StatusWords<M> {
    #[hdl_gen]
    fn update(&mut self) {
        // register byte order: byte 0 in [7:0]; channel order: byte 0 in [63:56]
        self.rx_data64.next = self.rx_head.val().get_bits::<64>(0);
        self.word.next = self.zero32.val();
        if self.adr.val() == self.a_id.val() {
            self.word.next = self.id_value.val();
        } else if self.adr.val() == self.a_status.val() {
            self.word.next = (bit_cast::<32, 4>(self.state.val()) << self.st_state.val())
                | (bit_cast::<32, 1>(self.tx_channel.val().into()) << self.st_tx_channel.val())
                | (bit_cast::<32, 2>(self.aux_a_state.val()) << self.st_aux_a.val())
                | (bit_cast::<32, 2>(self.aux_b_state.val()) << self.st_aux_b.val())
                | (bit_cast::<32, 2>(self.es_a.val()) << self.st_es_a.val())
                | (bit_cast::<32, 2>(self.es_b.val()) << self.st_es_b.val())
                | (bit_cast::<32, 1>(self.reset_mode.val().into()) << self.st_reset_mode.val())
                | (bit_cast::<32, 1>(self.tx_going_on.val().into()) << self.st_tx_going_on.val())
                | (bit_cast::<32, 4>(self.txq_a.val()) << self.st_txq_a.val())
                | (bit_cast::<32, 4>(self.txq_b.val()) << self.st_txq_b.val())
                | (bit_cast::<32, 6>(self.rx_count.val()) << self.st_rx_count.val());
        } else if self.adr.val() == self.a_chan_a_err.val() {
            self.word.next = (bit_cast::<32, 9>(self.tec_a.val()) << self.err_tec.val())
                | (bit_cast::<32, 8>(self.rec_a.val()) << self.err_rec.val())
                | (bit_cast::<32, 2>(self.es_a.val()) << self.err_state.val())
                | (bit_cast::<32, 1>(self.ew_a.val().into()) << self.err_warning.val());
        } else if self.adr.val() == self.a_chan_b_err.val() {
            self.word.next = (bit_cast::<32, 9>(self.tec_b.val()) << self.err_tec.val())
                | (bit_cast::<32, 8>(self.rec_b.val()) << self.err_rec.val())
                | (bit_cast::<32, 2>(self.es_b.val()) << self.err_state.val())
                | (bit_cast::<32, 1>(self.ew_b.val().into()) << self.err_warning.val());
        } else if self.adr.val() == self.a_aux_a.val() {
            self.word.next = (bit_cast::<32, 2>(self.aux_a_state.val()) << self.aux_state.val())
                | (bit_cast::<32, 5>(self.causes_a.val()) << self.aux_causes.val())
                | (bit_cast::<32, 4>(self.fail_cnt_a.val()) << self.aux_fail_cnt.val())
                | (bit_cast::<32, 8>(self.failures_a.val()) << self.aux_failures.val())
                | (bit_cast::<32, 8>(self.recoveries_a.val()) << self.aux_recoveries.val());
        } else if self.adr.val() == self.a_aux_b.val() {
            self.word.next = (bit_cast::<32, 2>(self.aux_b_state.val()) << self.aux_state.val())
                | (bit_cast::<32, 5>(self.causes_b.val()) << self.aux_causes.val())
                | (bit_cast::<32, 4>(self.fail_cnt_b.val()) << self.aux_fail_cnt.val())
                | (bit_cast::<32, 8>(self.failures_b.val()) << self.aux_failures.val())
                | (bit_cast::<32, 8>(self.recoveries_b.val()) << self.aux_recoveries.val());
        } else if self.adr.val() == self.a_rx_id.val() {
            self.word.next = bit_cast::<32, 31>(self.rx_head.val().get_bits::<31>(68))
                | (bit_cast::<32, 1>(self.rx_ready.val().into()) << self.rx_ready_at.val());
        } else if self.adr.val() == self.a_rx_ctrl.val() {
            self.word.next = (bit_cast::<32, 4>(self.rx_head.val().get_bits::<4>(64))
                << self.rx_dlc_at.val())
                | (bit_cast::<32, 1>(self.rx_head.val().get_bit(99).into())
                    << self.rx_channel_at.val());
        } else if self.adr.val() == self.a_rx_data0.val() {
            self.word.next = bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(56))
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(48)) << 8)
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(40)) << 16)
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(32)) << 24);
        } else if self.adr.val() == self.a_rx_data1.val() {
            self.word.next = bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(24))
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(16)) << 8)
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(8)) << 16)
                | (bit_cast::<32, 8>(self.rx_data64.val().get_bits::<8>(0)) << 24);
        } else if self.adr.val() == self.a_stats0.val() {
            self.word.next = (bit_cast::<32, 16>(self.duplicates.val())
                << self.s0_duplicates.val())
                | (bit_cast::<32, 16>(self.overruns.val()) << self.s0_overruns.val());
        } else if self.adr.val() == self.a_stats1.val() {
            self.word.next = (bit_cast::<32, 16>(self.switches.val()) << self.s1_switches.val())
                | (bit_cast::<32, 16>(self.recoveries.val()) << self.s1_recoveries.val());
        } else if self.adr.val() == self.a_times.val() {
            self.word.next = (bit_cast::<32, 16>(self.last_tx_time.val()) << self.t_last_tx.val())
                | (bit_cast::<32, 16>(self.switch_time.val()) << self.t_switch.val());
        } else if self.adr.val() == self.a_star_status.val() {
            self.word.next = self.star_word.val();
        } else if self.adr.val() == self.a_omissions.val() {
            self.word.next = (bit_cast::<32, 16>(self.omissions_a.val()) << self.o_a.val())
                | (bit_cast::<32, 16>(self.omissions_b.val()) << self.o_b.val());
        } else if self.adr.val() == self.a_version.val() {
            self.word.next = self.version_value.val();
        } else if self.adr.val() == self.a_sizes.val() {
            self.word.next = (bit_cast::<32, 6>(self.sz_rx_fifo.val()) << self.z_rx_fifo.val())
                | (bit_cast::<32, 4>(self.sz_tx_queue.val()) << self.z_tx_queue.val())
                | (bit_cast::<32, 6>(self.sz_history.val()) << self.z_history.val())
                | (bit_cast::<32, 5>(self.sz_mailboxes.val()) << self.z_mailboxes.val())
                | (bit_cast::<32, 1>(self.sz_dmr.val()) << self.z_dmr.val())
                | (bit_cast::<32, 1>(self.sz_star.val()) << self.z_star.val());
        } else if self.adr.val() == self.a_cap_a.val() {
            self.word.next = self.cap_a.val();
        } else if self.adr.val() == self.a_cap_b.val() {
            self.word.next = self.cap_b.val();
        } else if self.adr.val() == self.a_rx_time.val() {
            self.word.next = (bit_cast::<32, 16>(self.rx_head.val().get_bits::<16>(100))
                << self.rt_rx_time.val())
                | (bit_cast::<32, 16>(self.now.val()) << self.rt_now.val());
        }
    }
}
