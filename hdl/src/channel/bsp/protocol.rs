//! Protocol controller of the bit stream processor (ISO 11898-1:2015, clauses 10
//! and 12; timing contract §4): frame coding and decoding field by field,
//! bit stuffing (10.5), CRC-15 (10.4.2.6), bitwise arbitration (10.4.2.1 /
//! 12.1.2), acknowledgement (10.4.2.7), error detection (12.1.3), error and
//! overload frames (10.4.3, 10.4.4), intermission and suspend transmission
//! (10.4.5), bus integration and bus-off recovery (12.1.4.4).
//!
//! State changes only at the sample point (`sample`); the `tx` pin is loaded only
//! at `bit_start`. Decisions where the standard leaves room (written in the
//! timing contract too):
//! - The type of error flag (active or passive) is the error state after the
//!   counters have been updated for the error that starts it (contract §4.5).
//! - The counting rules follow contract §4.5 rule by rule (rule letters of
//!   ISO 11898-1 12.1.4.2); REC is decremented at the ACK slot (rule h).
//! - A transmitter's frame is latched by a one-clock `tx_req` and stays pending
//!   through lost arbitration and errors until sent (automatic retransmission).

use super::crc::Crc15Step;
use super::fault_confinement::FaultConfinement;
use super::field::Field;
use rust_hdl::prelude::*;

/// The protocol controller of one channel.
#[derive(LogicBlock)]
pub struct ProtocolController {
    // clock and reset
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // from the bit timing logic
    pub sample: Signal<In, Bit>,
    pub sampled: Signal<In, Bit>,
    pub bit_start: Signal<In, Bit>,
    pub hard_sync: Signal<In, Bit>,
    // to the bit timing logic and the pin
    pub hard_sync_enable: Signal<Out, Bit>,
    pub tx: Signal<Out, Bit>,
    // configuration (held, from the configuration registers)
    pub mode: Signal<In, Bits<2>>,
    pub ewl: Signal<In, Bits<8>>,
    pub single_shot: Signal<In, Bit>,
    // host transmit interface
    pub tx_req: Signal<In, Bit>,
    pub tx_id: Signal<In, Bits<29>>,
    pub tx_ide: Signal<In, Bit>,
    pub tx_rtr: Signal<In, Bit>,
    pub tx_dlc: Signal<In, Bits<4>>,
    pub tx_data: Signal<In, Bits<64>>,
    pub tx_abort: Signal<In, Bit>,
    pub tx_pending: Signal<Out, Bit>,
    pub tx_failed: Signal<Out, Bit>,
    pub tx_done: Signal<Out, Bit>,
    pub arb_lost: Signal<Out, Bit>,
    // host receive interface
    pub rx_valid: Signal<Out, Bit>,
    pub rx_id: Signal<Out, Bits<29>>,
    pub rx_ide: Signal<Out, Bit>,
    pub rx_rtr: Signal<Out, Bit>,
    pub rx_dlc: Signal<Out, Bits<4>>,
    pub rx_data: Signal<Out, Bits<64>>,
    // probes
    pub field: Signal<Out, Field>,
    pub tec: Signal<Out, Bits<9>>,
    pub rec: Signal<Out, Bits<8>>,
    pub err_state: Signal<Out, Bits<2>>,
    // diagnostics (contract §9)
    pub err_warning: Signal<Out, Bit>,
    pub err_valid: Signal<Out, Bit>,
    pub err_kind: Signal<Out, Bits<3>>,
    pub err_field: Signal<Out, Field>,
    pub err_tx: Signal<Out, Bit>,
    pub alc: Signal<Out, Bits<5>>,
    pub cnt_bit: Signal<Out, Bits<8>>,
    pub cnt_stuff: Signal<Out, Bits<8>>,
    pub cnt_crc: Signal<Out, Bits<8>>,
    pub cnt_form: Signal<Out, Bits<8>>,
    pub cnt_ack: Signal<Out, Bits<8>>,
    // transmit control and diagnostics state
    abort_pending: DFF<Bit>,
    attempt: DFF<Bit>,
    starts: Signal<Local, Bit>,
    join_starts: Signal<Local, Bit>,
    tx_failed_q: DFF<Bit>,
    err_valid_q: DFF<Bit>,
    err_kind_q: DFF<Bits<3>>,
    err_field_q: DFF<Field>,
    err_tx_q: DFF<Bit>,
    alc_q: DFF<Bits<5>>,
    cnt_bit_q: DFF<Bits<8>>,
    cnt_stuff_q: DFF<Bits<8>>,
    cnt_crc_q: DFF<Bits<8>>,
    cnt_form_q: DFF<Bits<8>>,
    cnt_ack_q: DFF<Bits<8>>,
    listen_only: Signal<Local, Bit>,
    ack_check_off: Signal<Local, Bit>,
    loopback: Signal<Local, Bit>,
    stuff_err: Signal<Local, Bit>,
    stuff_as_bit: Signal<Local, Bit>,
    bit_err: Signal<Local, Bit>,
    form_err: Signal<Local, Bit>,
    crc_err: Signal<Local, Bit>,
    lost: Signal<Local, Bit>,
    sof_error: Signal<Local, Bit>,
    err_kind_n: Signal<Local, Bits<3>>,
    alc_n: Signal<Local, Bits<5>>,
    k3_bit: Constant<Bits<3>>,
    k3_stuff: Constant<Bits<3>>,
    k3_crc: Constant<Bits<3>>,
    k3_form: Constant<Bits<3>>,
    k3_ack: Constant<Bits<3>>,
    n2_1: Constant<Bits<2>>,
    n2_3m: Constant<Bits<2>>,
    n5_11: Constant<Bits<5>>,
    n5_12: Constant<Bits<5>>,
    n5_13: Constant<Bits<5>>,
    n5_31: Constant<Bits<5>>,
    n8_1: Constant<Bits<8>>,
    n8_255: Constant<Bits<8>>,
    zero5: Constant<Bits<5>>,
    zero8: Constant<Bits<8>>,
    // sub-blocks
    crc_step: Crc15Step,
    fc: FaultConfinement,
    // protocol state
    field_q: DFF<Field>,
    bit_cnt: DFF<Bits<7>>,
    is_tx: DFF<Bit>,
    pending: DFF<Bit>,
    stuff_cnt: DFF<Bits<3>>,
    stuff_last: DFF<Bit>,
    stuff_en: DFF<Bit>,
    crc: DFF<Bits<15>>,
    crc_ok: DFF<Bit>,
    flag_passive: DFF<Bit>,
    recovery_cnt: DFF<Bits<7>>,
    tx_q: DFF<Bit>,
    tx_bit: Signal<Local, Bit>,
    last_bit_arb: DFF<Bit>,
    dom_cnt: DFF<Bits<3>>,
    delim_first: DFF<Bit>,
    ack_passive_pending: DFF<Bit>,
    // registered pre-decodes of the state the next SAMPLE edge sees
    p_in_arbitration: DFF<Bit>,
    p_ide: DFF<Bit>,
    p_in_frame: DFF<Bit>,
    p_crc_covered: DFF<Bit>,
    p_in_delim: DFF<Bit>,
    p_after_error_flag: DFF<Bit>,
    p_ack_slot: DFF<Bit>,
    p_stuff_bit: DFF<Bit>,
    p_bc0: DFF<Bit>,
    p_bc2: DFF<Bit>,
    p_bc3: DFF<Bit>,
    p_bc5: DFF<Bit>,
    p_bc6: DFF<Bit>,
    p_bc7: DFF<Bit>,
    p_bc10: DFF<Bit>,
    p_bc14: DFF<Bit>,
    p_bc17: DFF<Bit>,
    p_data_end: DFF<Bit>,
    p_recovery_end: DFF<Bit>,
    p_dom7: DFF<Bit>,
    p_crc_bit: DFF<Bit>,
    p_passive: DFF<Bit>,
    p_bus_off: DFF<Bit>,
    p_suspend_due: DFF<Bit>,
    p_tec_ge120: DFF<Bit>,
    p_tec_ge248: DFF<Bit>,
    p_rec_ge127: DFF<Bit>,
    p_rec_ge120: DFF<Bit>,
    p_cnt_bit_max: DFF<Bit>,
    p_cnt_stuff_max: DFF<Bit>,
    p_cnt_crc_max: DFF<Bit>,
    p_cnt_form_max: DFF<Bit>,
    p_cnt_ack_max: DFF<Bit>,
    p_alc: DFF<Bits<5>>,
    // latched transmit frame
    // identifier, aligned so the bit counter indexes it without an adder:
    // ID_A (ID[28:18] extended, ID[10:0] base) in bits 15..5 (bit 15 - n is ID_A
    // bit n), ID[17:0] in bits 31..14 (bit 31 - n is ID_B bit n)
    txf_ida: DFF<Bits<16>>,
    txf_idb: DFF<Bits<32>>,
    txf_ide: DFF<Bit>,
    txf_rtr: DFF<Bit>,
    txf_dlc: DFF<Bits<4>>,
    txf_data: DFF<Bits<64>>,
    // receive shift registers
    rxs_id: DFF<Bits<29>>,
    rxs_srr_rtr: DFF<Bit>,
    rxs_ide: DFF<Bit>,
    rxs_rtr: DFF<Bit>,
    rxs_dlc: DFF<Bits<4>>,
    rxs_data: DFF<Bits<64>>,
    data_len: DFF<Bits<7>>,
    // host-visible receive registers and pulses
    rx_valid_q: DFF<Bit>,
    tx_done_q: DFF<Bit>,
    arb_lost_q: DFF<Bit>,
    rx_id_q: DFF<Bits<29>>,
    rx_ide_q: DFF<Bit>,
    rx_rtr_q: DFF<Bit>,
    rx_dlc_q: DFF<Bits<4>>,
    rx_data_q: DFF<Bits<64>>,
    // next-state values of the sample-point update
    field_n: Signal<Local, Field>,
    bit_cnt_n: Signal<Local, Bits<7>>,
    bit_cnt_inc: Signal<Local, Bits<7>>,
    is_tx_n: Signal<Local, Bit>,
    stuff_cnt_n: Signal<Local, Bits<3>>,
    stuff_last_n: Signal<Local, Bit>,
    stuff_en_n: Signal<Local, Bit>,
    crc_n: Signal<Local, Bits<15>>,
    crc_ok_n: Signal<Local, Bit>,
    flag_passive_n: Signal<Local, Bit>,
    tx_bit_n: Signal<Local, Bit>,
    // classification of the sampled bit
    bus_bit: Signal<Local, Bits<1>>,
    start_ok: Signal<Local, Bit>,
    in_arbitration: Signal<Local, Bit>,
    in_frame: Signal<Local, Bit>,
    in_delim: Signal<Local, Bit>,
    after_error_flag: Signal<Local, Bit>,
    sof: Signal<Local, Bit>,
    sof_as_tx: Signal<Local, Bit>,
    crc_covered: Signal<Local, Bit>,
    dlc_n: Signal<Local, Bits<4>>,
    data_bits: Signal<Local, Bits<7>>,
    // errors and fault-confinement events
    error: Signal<Local, Bit>,
    flag_error: Signal<Local, Bit>,
    suspend_due: Signal<Local, Bit>,
    passive_after: Signal<Local, Bit>,
    ev_recovered: Signal<Local, Bit>,
    ev_rx_success: Signal<Local, Bit>,
    ev_tx_success: Signal<Local, Bit>,
    ev_rec_add8: Signal<Local, Bit>,
    ev_rec_add1: Signal<Local, Bit>,
    ev_tec_add8: Signal<Local, Bit>,
    bus_off_after: Signal<Local, Bit>,
    join_ok: Signal<Local, Bit>,
    tec_exempt: Signal<Local, Bit>,
    ack_error: Signal<Local, Bit>,
    // bit selectors of the transmitted frame
    id_a_idx: Signal<Local, Bits<4>>,
    id_b_idx: Signal<Local, Bits<5>>,
    dlc_idx: Signal<Local, Bits<2>>,
    data_idx: Signal<Local, Bits<6>>,
    // CRC aligned one bit up: bit 15 - n is CRC bit 14 - n
    crc_idx: Signal<Local, Bits<4>>,
    crc_tx: Signal<Local, Bits<16>>,
    crc_rx_idx: Signal<Local, Bits<4>>,
    data_wr_idx: Signal<Local, Bits<6>>,
    // sized constants (rust-hdl would emit unsized literals otherwise)
    n7_0: Constant<Bits<7>>,
    n7_1: Constant<Bits<7>>,
    n7_2: Constant<Bits<7>>,
    n7_3: Constant<Bits<7>>,
    n7_5: Constant<Bits<7>>,
    n7_6: Constant<Bits<7>>,
    n7_7: Constant<Bits<7>>,
    n7_10: Constant<Bits<7>>,
    n7_14: Constant<Bits<7>>,
    n7_17: Constant<Bits<7>>,
    n7_64: Constant<Bits<7>>,
    n7_127: Constant<Bits<7>>,
    n3_1: Constant<Bits<3>>,
    n3_5: Constant<Bits<3>>,
    n3_7: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    n9_120: Constant<Bits<9>>,
    n9_248: Constant<Bits<9>>,
    n8_120: Constant<Bits<8>>,
    n8_127: Constant<Bits<8>>,
    n6_63: Constant<Bits<6>>,
    n4_14: Constant<Bits<4>>,
    zero4: Constant<Bits<4>>,
    zero15: Constant<Bits<15>>,
    zero29: Constant<Bits<29>>,
    zero64: Constant<Bits<64>>,
}

impl Default for ProtocolController {
    fn default() -> Self {
        let c7 = |v: u64| Constant::new(Bits::<7>::from(v));
        Self {
            clk: Default::default(),
            rst: Default::default(),
            sample: Default::default(),
            sampled: Default::default(),
            bit_start: Default::default(),
            hard_sync: Default::default(),
            hard_sync_enable: Default::default(),
            tx: Default::default(),
            tx_req: Default::default(),
            tx_id: Default::default(),
            tx_ide: Default::default(),
            tx_rtr: Default::default(),
            tx_dlc: Default::default(),
            tx_data: Default::default(),
            tx_pending: Default::default(),
            tx_abort: Default::default(),
            tx_failed: Default::default(),
            mode: Default::default(),
            ewl: Default::default(),
            single_shot: Default::default(),
            err_warning: Default::default(),
            err_valid: Default::default(),
            err_kind: Default::default(),
            err_field: Default::default(),
            err_tx: Default::default(),
            alc: Default::default(),
            cnt_bit: Default::default(),
            cnt_stuff: Default::default(),
            cnt_crc: Default::default(),
            cnt_form: Default::default(),
            cnt_ack: Default::default(),
            tx_done: Default::default(),
            arb_lost: Default::default(),
            rx_valid: Default::default(),
            rx_id: Default::default(),
            rx_ide: Default::default(),
            rx_rtr: Default::default(),
            rx_dlc: Default::default(),
            rx_data: Default::default(),
            field: Default::default(),
            tec: Default::default(),
            rec: Default::default(),
            err_state: Default::default(),
            abort_pending: Default::default(),
            attempt: Default::default(),
            starts: Default::default(),
            join_starts: Default::default(),
            tx_failed_q: Default::default(),
            err_valid_q: Default::default(),
            err_kind_q: Default::default(),
            err_field_q: Default::default(),
            err_tx_q: Default::default(),
            alc_q: Default::default(),
            cnt_bit_q: Default::default(),
            cnt_stuff_q: Default::default(),
            cnt_crc_q: Default::default(),
            cnt_form_q: Default::default(),
            cnt_ack_q: Default::default(),
            listen_only: Default::default(),
            ack_check_off: Default::default(),
            loopback: Default::default(),
            stuff_err: Default::default(),
            stuff_as_bit: Default::default(),
            bit_err: Default::default(),
            form_err: Default::default(),
            crc_err: Default::default(),
            lost: Default::default(),
            sof_error: Default::default(),
            err_kind_n: Default::default(),
            alc_n: Default::default(),
            k3_bit: Constant::new(1.into()),
            k3_stuff: Constant::new(2.into()),
            k3_crc: Constant::new(3.into()),
            k3_form: Constant::new(4.into()),
            k3_ack: Constant::new(5.into()),
            n2_1: Constant::new(1.into()),
            n2_3m: Constant::new(3.into()),
            n5_11: Constant::new(11.into()),
            n5_12: Constant::new(12.into()),
            n5_13: Constant::new(13.into()),
            n5_31: Constant::new(31.into()),
            n8_1: Constant::new(1.into()),
            n8_255: Constant::new(255.into()),
            zero5: Constant::new(0.into()),
            zero8: Constant::new(0.into()),
            crc_step: Default::default(),
            fc: Default::default(),
            field_q: Default::default(),
            bit_cnt: Default::default(),
            is_tx: Default::default(),
            pending: Default::default(),
            stuff_cnt: Default::default(),
            stuff_last: Default::default(),
            stuff_en: Default::default(),
            crc: Default::default(),
            crc_ok: Default::default(),
            flag_passive: Default::default(),
            recovery_cnt: Default::default(),
            tx_q: Default::default(),
            tx_bit: Default::default(),
            last_bit_arb: Default::default(),
            dom_cnt: Default::default(),
            delim_first: Default::default(),
            ack_passive_pending: Default::default(),
            p_in_arbitration: Default::default(),
            p_ide: Default::default(),
            p_in_frame: Default::default(),
            p_crc_covered: Default::default(),
            p_in_delim: Default::default(),
            p_after_error_flag: Default::default(),
            p_ack_slot: Default::default(),
            p_stuff_bit: Default::default(),
            p_bc0: Default::default(),
            p_bc2: Default::default(),
            p_bc3: Default::default(),
            p_bc5: Default::default(),
            p_bc6: Default::default(),
            p_bc7: Default::default(),
            p_bc10: Default::default(),
            p_bc14: Default::default(),
            p_bc17: Default::default(),
            p_data_end: Default::default(),
            p_recovery_end: Default::default(),
            p_dom7: Default::default(),
            p_crc_bit: Default::default(),
            p_passive: Default::default(),
            p_bus_off: Default::default(),
            p_suspend_due: Default::default(),
            p_tec_ge120: Default::default(),
            p_tec_ge248: Default::default(),
            p_rec_ge127: Default::default(),
            p_rec_ge120: Default::default(),
            p_cnt_bit_max: Default::default(),
            p_cnt_stuff_max: Default::default(),
            p_cnt_crc_max: Default::default(),
            p_cnt_form_max: Default::default(),
            p_cnt_ack_max: Default::default(),
            p_alc: Default::default(),
            txf_ida: Default::default(),
            txf_idb: Default::default(),
            txf_ide: Default::default(),
            txf_rtr: Default::default(),
            txf_dlc: Default::default(),
            txf_data: Default::default(),
            rxs_id: Default::default(),
            rxs_srr_rtr: Default::default(),
            rxs_ide: Default::default(),
            rxs_rtr: Default::default(),
            rxs_dlc: Default::default(),
            rxs_data: Default::default(),
            data_len: Default::default(),
            rx_valid_q: Default::default(),
            tx_done_q: Default::default(),
            arb_lost_q: Default::default(),
            rx_id_q: Default::default(),
            rx_ide_q: Default::default(),
            rx_rtr_q: Default::default(),
            rx_dlc_q: Default::default(),
            rx_data_q: Default::default(),
            field_n: Default::default(),
            bit_cnt_n: Default::default(),
            bit_cnt_inc: Default::default(),
            is_tx_n: Default::default(),
            stuff_cnt_n: Default::default(),
            stuff_last_n: Default::default(),
            stuff_en_n: Default::default(),
            crc_n: Default::default(),
            crc_ok_n: Default::default(),
            flag_passive_n: Default::default(),
            tx_bit_n: Default::default(),
            bus_bit: Default::default(),
            start_ok: Default::default(),
            in_arbitration: Default::default(),
            in_frame: Default::default(),
            in_delim: Default::default(),
            after_error_flag: Default::default(),
            sof: Default::default(),
            sof_as_tx: Default::default(),
            crc_covered: Default::default(),
            dlc_n: Default::default(),
            data_bits: Default::default(),
            error: Default::default(),
            flag_error: Default::default(),
            suspend_due: Default::default(),
            passive_after: Default::default(),
            ev_recovered: Default::default(),
            ev_rx_success: Default::default(),
            ev_tx_success: Default::default(),
            ev_rec_add8: Default::default(),
            ev_rec_add1: Default::default(),
            ev_tec_add8: Default::default(),
            bus_off_after: Default::default(),
            join_ok: Default::default(),
            tec_exempt: Default::default(),
            ack_error: Default::default(),
            id_a_idx: Default::default(),
            id_b_idx: Default::default(),
            dlc_idx: Default::default(),
            data_idx: Default::default(),
            crc_idx: Default::default(),
            crc_tx: Default::default(),
            crc_rx_idx: Default::default(),
            data_wr_idx: Default::default(),
            n7_0: c7(0),
            n7_1: c7(1),
            n7_2: c7(2),
            n7_3: c7(3),
            n7_5: c7(5),
            n7_6: c7(6),
            n7_7: c7(7),
            n7_10: c7(10),
            n7_14: c7(14),
            n7_17: c7(17),
            n7_64: c7(64),
            n7_127: c7(127),
            n3_1: Constant::new(1.into()),
            n3_5: Constant::new(5.into()),
            n3_7: Constant::new(7.into()),
            zero3: Constant::new(0.into()),
            n9_120: Constant::new(120.into()),
            n9_248: Constant::new(248.into()),
            n8_120: Constant::new(120.into()),
            n8_127: Constant::new(127.into()),
            n6_63: Constant::new(63.into()),
            n4_14: Constant::new(14.into()),
            zero4: Constant::new(0.into()),
            zero15: Constant::new(0.into()),
            zero29: Constant::new(0.into()),
            zero64: Constant::new(0.into()),
        }
    }
}

impl Logic for ProtocolController {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            field_q,
            bit_cnt,
            is_tx,
            pending,
            stuff_cnt,
            stuff_last,
            stuff_en,
            crc,
            crc_ok,
            flag_passive,
            recovery_cnt,
            tx_q,
            last_bit_arb,
            dom_cnt,
            delim_first,
            ack_passive_pending,
            abort_pending,
            attempt,
            tx_failed_q,
            err_valid_q,
            err_kind_q,
            err_field_q,
            err_tx_q,
            alc_q,
            cnt_bit_q,
            cnt_stuff_q,
            cnt_crc_q,
            cnt_form_q,
            cnt_ack_q,
            p_in_arbitration,
            p_ide,
            p_in_frame,
            p_crc_covered,
            p_in_delim,
            p_after_error_flag,
            p_ack_slot,
            p_stuff_bit,
            p_bc0,
            p_bc2,
            p_bc3,
            p_bc5,
            p_bc6,
            p_bc7,
            p_bc10,
            p_bc14,
            p_bc17,
            p_data_end,
            p_recovery_end,
            p_dom7,
            p_crc_bit,
            p_passive,
            p_bus_off,
            p_suspend_due,
            p_tec_ge120,
            p_tec_ge248,
            p_rec_ge127,
            p_rec_ge120,
            p_cnt_bit_max,
            p_cnt_stuff_max,
            p_cnt_crc_max,
            p_cnt_form_max,
            p_cnt_ack_max,
            p_alc,
            txf_ida,
            txf_idb,
            txf_ide,
            txf_rtr,
            txf_dlc,
            txf_data,
            rxs_id,
            rxs_srr_rtr,
            rxs_ide,
            rxs_rtr,
            rxs_dlc,
            rxs_data,
            data_len,
            rx_valid_q,
            tx_done_q,
            arb_lost_q,
            rx_id_q,
            rx_ide_q,
            rx_rtr_q,
            rx_dlc_q,
            rx_data_q
        );
        self.fc.clk.next = self.clk.val();
        self.fc.rst.next = self.rst.val();
        self.crc_step.crc.next = self.crc.q.val();
        self.crc_step.data_bit.next = self.sampled.val();

        // ---- defaults: nothing changes unless the sample point says so
        self.field_n.next = self.field_q.q.val();
        self.bit_cnt_n.next = self.bit_cnt.q.val();
        self.bit_cnt_inc.next = self.bit_cnt.q.val() + self.n7_1.val();
        self.is_tx_n.next = self.is_tx.q.val();
        self.stuff_cnt_n.next = self.stuff_cnt.q.val();
        self.stuff_last_n.next = self.stuff_last.q.val();
        self.stuff_en_n.next = self.stuff_en.q.val();
        self.crc_n.next = self.crc.q.val();
        self.crc_ok_n.next = self.crc_ok.q.val();
        self.flag_passive_n.next = self.flag_passive.q.val();
        self.bus_bit.next = self.sampled.val().into();
        // Operating mode (contract §7).
        self.listen_only.next = self.mode.val() == self.n2_1.val();
        self.ack_check_off.next = self.mode.val().get_bit(1);
        self.loopback.next = self.mode.val() == self.n2_3m.val();
        // Contract §8: nothing starts in listen-only mode or while an abort is due.
        self.start_ok.next = self.pending.q.val()
            && !self.fc.bus_off.val()
            && !self.listen_only.val()
            && !self.tx_abort.val()
            && !self.abort_pending.q.val();
        self.stuff_err.next = false;
        self.stuff_as_bit.next = false;
        self.bit_err.next = false;
        self.form_err.next = false;
        self.crc_err.next = false;
        self.lost.next = false;
        self.sof_error.next = false;
        self.tx_failed_q.d.next = false;
        self.err_valid_q.d.next = false;
        if !self.pending.q.val() {
            self.abort_pending.d.next = false;
        }
        // Transmit abort (contract §8), new or remembered: carried out at the first
        // edge where the frame is not on the bus.
        if (self.tx_abort.val() || self.abort_pending.q.val()) && self.pending.q.val() {
            if !self.is_tx.q.val() && self.tx_q.q.val() {
                self.pending.d.next = false;
                self.tx_failed_q.d.next = true;
                self.abort_pending.d.next = false;
            } else {
                self.abort_pending.d.next = true;
            }
        }
        self.sof.next = false;
        self.sof_as_tx.next = false;
        self.error.next = false;
        self.flag_error.next = false;
        self.passive_after.next = false;
        self.bus_off_after.next = false;
        // 10.4.5: an error-passive transmitter suspends after its frame and does
        // not join a SOF at intermission bit 3.
        self.suspend_due.next = self.p_suspend_due.q.val();
        self.join_ok.next = self.start_ok.val() && !self.suspend_due.val();
        // A node whose own SOF is already on `tx` keeps its attempt (contract §8).
        self.starts.next = (!self.tx_q.q.val() && self.pending.q.val()) || self.start_ok.val();
        self.join_starts.next = (!self.tx_q.q.val() && self.pending.q.val()) || self.join_ok.val();
        self.tec_exempt.next = false;
        self.ack_error.next = false;
        self.ev_tec_add8.next = false;
        self.ev_rec_add1.next = false;
        self.ev_rec_add8.next = false;
        self.ev_tx_success.next = false;
        self.ev_rx_success.next = false;
        self.ev_recovered.next = false;
        self.rx_valid_q.d.next = false;
        self.tx_done_q.d.next = false;
        self.arb_lost_q.d.next = false;
        self.dlc_n.next = (self.rxs_dlc.q.val() << 1) | bit_cast::<4, 1>(self.bus_bit.val());
        if self.rxs_rtr.q.val() {
            self.data_bits.next = self.n7_0.val();
        } else if self.dlc_n.val().get_bit(3) {
            self.data_bits.next = self.n7_64.val();
        } else {
            self.data_bits.next = bit_cast::<7, 3>(self.dlc_n.val().get_bits::<3>(0)) << 3;
        }
        // Arbitration-lost position (contract §9).
        match self.field_q.q.val() {
            Field::IdA => {
                self.alc_n.next = self.bit_cnt.q.val().get_bits::<5>(0);
            }
            Field::SrrRtr => {
                self.alc_n.next = self.n5_11.val();
            }
            Field::Ide => {
                self.alc_n.next = self.n5_12.val();
            }
            Field::IdB => {
                self.alc_n.next = self.n5_13.val() + self.bit_cnt.q.val().get_bits::<5>(0);
            }
            _ => {
                self.alc_n.next = self.n5_31.val();
            }
        }
        self.err_kind_n.next = self.k3_crc.val();
        self.crc_rx_idx.next = self.n4_14.val() - self.bit_cnt.q.val().get_bits::<4>(0);
        self.data_wr_idx.next = self.n6_63.val() - self.bit_cnt.q.val().get_bits::<6>(0);

        // ---- registered pre-decodes: everything below is a function of state that
        // changes only at SAMPLE edges, bit_start or reset, registered every clock.
        // The next SAMPLE edge comes at least 3 clocks after any of these (8 tq after
        // a sample, TSEG1 >= 3 clocks after a bit_start, 2 ticks after reset), so at
        // a SAMPLE edge each equals its combinational value and the sample-point
        // logic starts from flip-flops instead of decoders and comparators.
        // Field classification (10.4.2: the arbitration field is ID and RTR, plus
        // SRR and IDE in extended frames).
        self.p_in_arbitration.d.next = false;
        self.p_ide.d.next = false;
        self.p_in_frame.d.next = false;
        self.p_crc_covered.d.next = false;
        self.p_in_delim.d.next = false;
        self.p_after_error_flag.d.next = false;
        match self.field_q.q.val() {
            Field::ErrorDelim => {
                self.p_in_delim.d.next = true;
                self.p_after_error_flag.d.next = true;
            }
            Field::OverloadDelim => {
                self.p_in_delim.d.next = true;
            }
            Field::IdA => {
                self.p_in_arbitration.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::SrrRtr => {
                self.p_in_arbitration.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::Ide => {
                // IDE belongs to the arbitration field of extended frames only
                // (10.4.2.2); a base frame's IDE is control field.
                self.p_in_arbitration.d.next = false;
                self.p_ide.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::IdB => {
                self.p_in_arbitration.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::RtrExt => {
                self.p_in_arbitration.d.next = true;
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::R1 => {
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::R0 => {
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::Dlc => {
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::Data => {
                self.p_in_frame.d.next = true;
                self.p_crc_covered.d.next = true;
            }
            Field::Crc => {
                self.p_in_frame.d.next = true;
            }
            Field::CrcDelim => {
                self.p_in_frame.d.next = true;
            }
            Field::AckSlot => {
                self.p_in_frame.d.next = true;
            }
            Field::AckDelim => {
                self.p_in_frame.d.next = true;
            }
            Field::Eof => {
                self.p_in_frame.d.next = true;
            }
            _ => {}
        }

        self.p_ack_slot.d.next = self.field_q.q.val() == Field::AckSlot;
        self.p_stuff_bit.d.next =
            self.stuff_en.q.val() && (self.stuff_cnt.q.val() == self.n3_5.val());
        self.p_bc0.d.next = self.bit_cnt.q.val() == self.n7_0.val();
        self.p_bc2.d.next = self.bit_cnt.q.val() == self.n7_2.val();
        self.p_bc3.d.next = self.bit_cnt.q.val() == self.n7_3.val();
        self.p_bc5.d.next = self.bit_cnt.q.val() == self.n7_5.val();
        self.p_bc6.d.next = self.bit_cnt.q.val() == self.n7_6.val();
        self.p_bc7.d.next = self.bit_cnt.q.val() == self.n7_7.val();
        self.p_bc10.d.next = self.bit_cnt.q.val() == self.n7_10.val();
        self.p_bc14.d.next = self.bit_cnt.q.val() == self.n7_14.val();
        self.p_bc17.d.next = self.bit_cnt.q.val() == self.n7_17.val();
        self.p_data_end.d.next = self.bit_cnt_inc.val() == self.data_len.q.val();
        self.p_recovery_end.d.next = self.recovery_cnt.q.val() == self.n7_127.val();
        self.p_dom7.d.next = self.dom_cnt.q.val() == self.n3_7.val();
        // (indexed only in the CRC field, where the index is in range)
        self.p_crc_bit.d.next = false;
        if self.field_q.q.val() == Field::Crc {
            self.p_crc_bit.d.next = self.crc.q.val().get_bit(self.crc_rx_idx.val().index());
        }
        self.p_alc.d.next = self.alc_n.val();
        self.p_passive.d.next = self.fc.error_passive.val();
        self.p_bus_off.d.next = self.fc.bus_off.val();
        self.p_suspend_due.d.next = self.is_tx.q.val() && self.fc.error_passive.val();
        self.p_tec_ge120.d.next = self.fc.tec.val() >= self.n9_120.val();
        self.p_tec_ge248.d.next = self.fc.tec.val() >= self.n9_248.val();
        self.p_rec_ge127.d.next = self.fc.rec.val() >= self.n8_127.val();
        self.p_rec_ge120.d.next = self.fc.rec.val() >= self.n8_120.val();
        self.p_cnt_bit_max.d.next = self.cnt_bit_q.q.val() == self.n8_255.val();
        self.p_cnt_stuff_max.d.next = self.cnt_stuff_q.q.val() == self.n8_255.val();
        self.p_cnt_crc_max.d.next = self.cnt_crc_q.q.val() == self.n8_255.val();
        self.p_cnt_form_max.d.next = self.cnt_form_q.q.val() == self.n8_255.val();
        self.p_cnt_ack_max.d.next = self.cnt_ack_q.q.val() == self.n8_255.val();
        self.in_arbitration.next =
            self.p_in_arbitration.q.val() || (self.p_ide.q.val() && self.txf_ide.q.val());
        self.in_frame.next = self.p_in_frame.q.val();
        self.crc_covered.next = self.p_crc_covered.q.val();
        self.in_delim.next = self.p_in_delim.q.val();
        self.after_error_flag.next = self.p_after_error_flag.q.val();

        // ---- the sample point
        if self.sample.val() {
            if self.p_stuff_bit.q.val() {
                // 10.5: a stuff bit must be the complement of the five before it.
                if self.sampled.val() == self.stuff_last.q.val() {
                    self.error.next = true;
                    self.stuff_err.next = true;
                    // A transmitter reads back its own stuff bit: a bit error, except
                    // the recessive stuff bit in arbitration (rule c exception 2).
                    if self.is_tx.q.val() && !(self.last_bit_arb.q.val() && self.tx_q.q.val()) {
                        self.stuff_as_bit.next = true;
                    }
                    // 12.1.4.2 exception: recessive stuff bit read dominant in arbitration.
                    if self.is_tx.q.val() && self.last_bit_arb.q.val() && self.tx_q.q.val() {
                        self.tec_exempt.next = true;
                    }
                } else {
                    self.stuff_cnt_n.next = self.n3_1.val();
                    self.stuff_last_n.next = self.sampled.val();
                }
            } else {
                self.last_bit_arb.d.next = self.in_arbitration.val();
                if self.stuff_en.q.val() {
                    if self.sampled.val() == self.stuff_last.q.val() {
                        self.stuff_cnt_n.next = self.stuff_cnt.q.val() + self.n3_1.val();
                    } else {
                        self.stuff_cnt_n.next = self.n3_1.val();
                        self.stuff_last_n.next = self.sampled.val();
                    }
                }
                if self.crc_covered.val() {
                    self.crc_n.next = self.crc_step.crc_next.val();
                }
                // 12.1.3.1 bit monitoring by the transmitter, with 12.1.2 arbitration.
                if self.is_tx.q.val()
                    && self.in_frame.val()
                    && (self.sampled.val() != self.tx_q.q.val())
                {
                    if self.in_arbitration.val() && self.tx_q.q.val() {
                        self.is_tx_n.next = false;
                        self.arb_lost_q.d.next = true;
                        self.lost.next = true;
                        self.alc_q.d.next = self.p_alc.q.val();
                    } else if self.p_ack_slot.q.val() && self.tx_q.q.val() {
                        // Dominant ACK slot: acknowledged.
                    } else {
                        self.error.next = true;
                        self.bit_err.next = true;
                    }
                }
                // 7.2.1: a receiver's own dominant ACK read back recessive.
                if !self.is_tx.q.val()
                    && self.p_ack_slot.q.val()
                    && !self.tx_q.q.val()
                    && self.sampled.val()
                {
                    self.error.next = true;
                    self.bit_err.next = true;
                }
                match self.field_q.q.val() {
                    Field::Integrating => {
                        // 12.1.4.4: 11 consecutive recessive bits before taking part.
                        if self.sampled.val() {
                            if self.p_bc10.q.val() {
                                self.field_n.next = Field::Idle;
                                self.bit_cnt_n.next = self.n7_0.val();
                            } else {
                                self.bit_cnt_n.next = self.bit_cnt_inc.val();
                            }
                        } else {
                            self.bit_cnt_n.next = self.n7_0.val();
                        }
                    }
                    Field::Idle => {
                        if !self.sampled.val() {
                            self.sof.next = true;
                            self.sof_as_tx.next = self.starts.val();
                        } else if !self.tx_q.q.val() {
                            // 12.1.3.1: its own SOF read back recessive is a bit
                            // error; having sent a frame bit, it is transmitter.
                            self.is_tx_n.next = true;
                            self.sof_error.next = true;
                            self.error.next = true;
                            self.bit_err.next = true;
                        }
                    }
                    Field::Suspend => {
                        // 10.4.5: a passive transmitter waits 8 bits; it may receive meanwhile.
                        if !self.sampled.val() {
                            self.sof.next = true;
                        } else if self.p_bc7.q.val() {
                            self.field_n.next = Field::Idle;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::Intermission => {
                        if !self.sampled.val() {
                            if self.p_bc2.q.val() {
                                // 10.4.5: dominant third intermission bit is a SOF.
                                self.sof.next = true;
                                self.sof_as_tx.next = self.join_starts.val();
                            } else {
                                // 10.4.4: dominant intermission bit 1 or 2: overload.
                                self.field_n.next = Field::OverloadFlag;
                                self.bit_cnt_n.next = self.n7_0.val();
                            }
                        } else if self.p_bc2.q.val() {
                            if self.suspend_due.val() {
                                self.field_n.next = Field::Suspend;
                            } else {
                                self.field_n.next = Field::Idle;
                            }
                            // The transmitter role ends with the intermission.
                            self.is_tx_n.next = false;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::IdA => {
                        self.rxs_id.d.next =
                            (self.rxs_id.q.val() << 1) | bit_cast::<29, 1>(self.bus_bit.val());
                        if self.p_bc10.q.val() {
                            self.field_n.next = Field::SrrRtr;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::SrrRtr => {
                        self.rxs_srr_rtr.d.next = self.sampled.val();
                        self.field_n.next = Field::Ide;
                    }
                    Field::Ide => {
                        self.rxs_ide.d.next = self.sampled.val();
                        if self.sampled.val() {
                            self.field_n.next = Field::IdB;
                        } else {
                            self.rxs_rtr.d.next = self.rxs_srr_rtr.q.val();
                            self.field_n.next = Field::R0;
                        }
                        self.bit_cnt_n.next = self.n7_0.val();
                    }
                    Field::IdB => {
                        self.rxs_id.d.next =
                            (self.rxs_id.q.val() << 1) | bit_cast::<29, 1>(self.bus_bit.val());
                        if self.p_bc17.q.val() {
                            self.field_n.next = Field::RtrExt;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::RtrExt => {
                        self.rxs_rtr.d.next = self.sampled.val();
                        self.field_n.next = Field::R1;
                    }
                    Field::R1 => {
                        self.field_n.next = Field::R0;
                    }
                    Field::R0 => {
                        self.field_n.next = Field::Dlc;
                        self.bit_cnt_n.next = self.n7_0.val();
                    }
                    Field::Dlc => {
                        self.rxs_dlc.d.next = self.dlc_n.val();
                        if self.p_bc3.q.val() {
                            self.data_len.d.next = self.data_bits.val();
                            if self.data_bits.val() == self.n7_0.val() {
                                self.field_n.next = Field::Crc;
                            } else {
                                self.field_n.next = Field::Data;
                            }
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::Data => {
                        self.rxs_data.d.next = self
                            .rxs_data
                            .q
                            .val()
                            .replace_bit(self.data_wr_idx.val().index(), self.sampled.val());
                        if self.p_data_end.q.val() {
                            self.field_n.next = Field::Crc;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::Crc => {
                        if self.sampled.val() != self.p_crc_bit.q.val() {
                            self.crc_ok_n.next = false;
                        }
                        if self.p_bc14.q.val() {
                            self.field_n.next = Field::CrcDelim;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::CrcDelim => {
                        // 10.5: the stuffed region ends with the CRC sequence.
                        self.stuff_en_n.next = false;
                        if !self.sampled.val() {
                            self.error.next = true; // 12.1.3.4 form error
                            self.form_err.next = true;
                        }
                        self.field_n.next = Field::AckSlot;
                    }
                    Field::AckSlot => {
                        if self.is_tx.q.val() && self.sampled.val() && !self.ack_check_off.val() {
                            // 12.1.3.5 ACK error (not checked in self-test and loop-back)
                            self.error.next = true;
                            self.ack_error.next = true;
                        }
                        if !self.is_tx.q.val() && !self.tx_q.q.val() && !self.sampled.val() {
                            // Rule h: received up to the ACK slot and acknowledged.
                            self.ev_rx_success.next = true;
                        }
                        self.field_n.next = Field::AckDelim;
                    }
                    Field::AckDelim => {
                        if !self.sampled.val() {
                            self.error.next = true; // form error
                            self.form_err.next = true;
                        } else if !self.crc_ok.q.val() && !self.is_tx.q.val() {
                            // 12.1.3.3: CRC error flag starts after the ACK delimiter.
                            self.error.next = true;
                            self.crc_err.next = true;
                        }
                        self.field_n.next = Field::Eof;
                        self.bit_cnt_n.next = self.n7_0.val();
                    }
                    Field::Eof => {
                        if !self.sampled.val() {
                            if (self.p_bc6.q.val()) && !self.is_tx.q.val() {
                                // 10.4.4: a receiver's dominant last EOF bit is an overload.
                                self.field_n.next = Field::OverloadFlag;
                                self.bit_cnt_n.next = self.n7_0.val();
                            } else {
                                self.error.next = true; // form error
                                self.form_err.next = true;
                            }
                        } else {
                            if (self.p_bc5.q.val()) && (!self.is_tx.q.val() || self.loopback.val())
                            {
                                // 10.7: valid for receivers at the last but one EOF bit.
                                self.rx_valid_q.d.next = true;
                                self.rx_id_q.d.next = self.rxs_id.q.val();
                                self.rx_ide_q.d.next = self.rxs_ide.q.val();
                                self.rx_rtr_q.d.next = self.rxs_rtr.q.val();
                                self.rx_dlc_q.d.next = self.rxs_dlc.q.val();
                                self.rx_data_q.d.next = self.rxs_data.q.val();
                            }
                            if self.p_bc6.q.val() {
                                if self.is_tx.q.val() {
                                    // 10.7: valid for the transmitter at the end of EOF.
                                    self.tx_done_q.d.next = true;
                                    self.pending.d.next = false;
                                    self.attempt.d.next = false;
                                    self.abort_pending.d.next = false;
                                    self.ev_tx_success.next = true;
                                }
                                self.field_n.next = Field::Intermission;
                                self.bit_cnt_n.next = self.n7_0.val();
                            } else {
                                self.bit_cnt_n.next = self.bit_cnt_inc.val();
                            }
                        }
                    }
                    Field::ErrorFlag => {
                        if self.flag_passive.q.val() {
                            // Rule c exception 1: a dominant bit during the passive flag
                            // that follows a passive ACK error costs TEC + 8 once.
                            if self.ack_passive_pending.q.val() && !self.sampled.val() {
                                self.ev_tec_add8.next = true;
                                self.ack_passive_pending.d.next = false;
                            }
                            // 10.4.3: a passive flag ends after 6 equal consecutive bits.
                            if (self.p_bc0.q.val())
                                || (self.sampled.val() != self.stuff_last.q.val())
                            {
                                self.bit_cnt_n.next = self.n7_1.val();
                                self.stuff_last_n.next = self.sampled.val();
                            } else if self.p_bc5.q.val() {
                                self.field_n.next = Field::ErrorDelim;
                                self.bit_cnt_n.next = self.n7_0.val();
                                self.delim_first.d.next = true;
                                self.dom_cnt.d.next = self.zero3.val();
                                self.ack_passive_pending.d.next = false;
                            } else {
                                self.bit_cnt_n.next = self.bit_cnt_inc.val();
                            }
                        } else if self.sampled.val() {
                            // Rules d/e: bit error in its own active error flag.
                            self.flag_error.next = true;
                        } else if self.p_bc5.q.val() {
                            self.field_n.next = Field::ErrorDelim;
                            self.bit_cnt_n.next = self.n7_0.val();
                            self.delim_first.d.next = true;
                            self.dom_cnt.d.next = self.zero3.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::OverloadFlag => {
                        if self.sampled.val() && !self.listen_only.val() {
                            // Rules d/e: bit error in its own overload flag.
                            self.flag_error.next = true;
                        } else if self.p_bc5.q.val() {
                            self.field_n.next = Field::OverloadDelim;
                            self.bit_cnt_n.next = self.n7_0.val();
                            self.delim_first.d.next = true;
                            self.dom_cnt.d.next = self.zero3.val();
                        } else {
                            self.bit_cnt_n.next = self.bit_cnt_inc.val();
                        }
                    }
                    Field::BusOff => {
                        // 12.1.4.4: 128 occurrences of 11 consecutive recessive bits.
                        if self.sampled.val() {
                            if self.p_bc10.q.val() {
                                self.bit_cnt_n.next = self.n7_0.val();
                                if self.p_recovery_end.q.val() {
                                    self.field_n.next = Field::Idle;
                                    self.ev_recovered.next = true;
                                    self.recovery_cnt.d.next = self.n7_0.val();
                                } else {
                                    self.recovery_cnt.d.next =
                                        self.recovery_cnt.q.val() + self.n7_1.val();
                                }
                            } else {
                                self.bit_cnt_n.next = self.bit_cnt_inc.val();
                            }
                        } else {
                            self.bit_cnt_n.next = self.n7_0.val();
                        }
                    }
                    _ => {}
                }
                // Error and overload delimiters share one rule set; rule b only
                // follows an error flag.
                if self.in_delim.val() {
                    // 10.4.3/10.4.4: wait for recessive, then 8 recessive bits in all.
                    if self.p_bc0.q.val() {
                        self.delim_first.d.next = false;
                        if self.sampled.val() {
                            self.bit_cnt_n.next = self.n7_1.val();
                        } else {
                            if self.delim_first.q.val()
                                && self.after_error_flag.val()
                                && !self.is_tx.q.val()
                            {
                                // Rule b: dominant first bit after its error flag.
                                self.ev_rec_add8.next = true;
                            }
                            // Rule f: every 8th consecutive dominant bit after the flag.
                            self.dom_cnt.d.next = self.dom_cnt.q.val() + self.n3_1.val();
                            if self.p_dom7.q.val() {
                                if self.is_tx.q.val() {
                                    self.ev_tec_add8.next = true;
                                } else {
                                    self.ev_rec_add8.next = true;
                                }
                            }
                        }
                    } else if !self.sampled.val() {
                        if self.p_bc7.q.val() {
                            self.field_n.next = Field::OverloadFlag;
                            self.bit_cnt_n.next = self.n7_0.val();
                        } else {
                            self.error.next = true; // form error in the delimiter
                            self.form_err.next = true;
                        }
                    } else if self.p_bc7.q.val() {
                        self.field_n.next = Field::Intermission;
                        self.bit_cnt_n.next = self.n7_0.val();
                    } else {
                        self.bit_cnt_n.next = self.bit_cnt_inc.val();
                    }
                }
            }

            // Start of frame: a new frame begins, as transmitter if one is pending.
            if self.sof.val() {
                self.field_n.next = Field::IdA;
                self.bit_cnt_n.next = self.n7_0.val();
                self.is_tx_n.next = self.sof_as_tx.val();
                self.attempt.d.next = self.sof_as_tx.val();
                self.stuff_en_n.next = true;
                self.stuff_cnt_n.next = self.n3_1.val();
                self.stuff_last_n.next = false;
                self.crc_n.next = self.zero15.val();
                self.crc_ok_n.next = true;
                self.rxs_id.d.next = self.zero29.val();
                self.rxs_data.d.next = self.zero64.val();
                self.rxs_rtr.d.next = false;
            }

            // One kind per error, by the precedence of contract §9.
            if self.stuff_as_bit.val() || self.bit_err.val() || self.flag_error.val() {
                self.err_kind_n.next = self.k3_bit.val();
            } else if self.stuff_err.val() {
                self.err_kind_n.next = self.k3_stuff.val();
            } else if self.form_err.val() {
                self.err_kind_n.next = self.k3_form.val();
            } else if self.ack_error.val() {
                self.err_kind_n.next = self.k3_ack.val();
            } else if self.crc_err.val() {
                self.err_kind_n.next = self.k3_crc.val();
            }
            // Any error: error flag from the next bit on (12.1.4.2 counter rules).
            if self.error.val() {
                if self.is_tx_n.val() {
                    if self.ack_error.val() && self.p_passive.q.val() {
                        // Rule c exception 1: decided during the passive flag.
                        self.ack_passive_pending.d.next = true;
                    } else if !self.tec_exempt.val() {
                        self.ev_tec_add8.next = true; // rule c
                    }
                } else {
                    self.ev_rec_add1.next = true; // rule a
                }
            }
            if self.flag_error.val() {
                if self.is_tx.q.val() {
                    self.ev_tec_add8.next = true; // rule d
                } else {
                    self.ev_rec_add8.next = true; // rule e
                }
            }
            // The error state after this sample's counter events (12.1.4.2 rules
            // i/j): computed here from the counters so no combinational path runs
            // back from the fault-confinement block.
            self.passive_after.next = self.p_passive.q.val()
                || (self.ev_tec_add8.val() && self.p_tec_ge120.q.val())
                || (self.ev_rec_add1.val() && self.p_rec_ge127.q.val())
                || (self.ev_rec_add8.val() && self.p_rec_ge120.q.val());
            self.bus_off_after.next = !self.listen_only.val()
                && self.ev_tec_add8.val()
                && self.p_tec_ge248.q.val()
                && !self.p_bus_off.q.val();
            if self.error.val() || self.flag_error.val() {
                self.field_n.next = Field::ErrorFlag;
                self.bit_cnt_n.next = self.n7_0.val();
                self.stuff_en_n.next = false;
                // The flag type follows the state after this error's increment.
                self.flag_passive_n.next = self.passive_after.val() || self.listen_only.val();
                // Error code capture (contract §9).
                self.err_valid_q.d.next = true;
                self.err_kind_q.d.next = self.err_kind_n.val();
                self.err_field_q.d.next = self.field_q.q.val();
                self.err_tx_q.d.next = self.is_tx.q.val() || self.sof_error.val();
                if (self.err_kind_n.val() == self.k3_bit.val()) && !self.p_cnt_bit_max.q.val() {
                    self.cnt_bit_q.d.next = self.cnt_bit_q.q.val() + self.n8_1.val();
                }
                if (self.err_kind_n.val() == self.k3_stuff.val()) && !self.p_cnt_stuff_max.q.val() {
                    self.cnt_stuff_q.d.next = self.cnt_stuff_q.q.val() + self.n8_1.val();
                }
                if (self.err_kind_n.val() == self.k3_crc.val()) && !self.p_cnt_crc_max.q.val() {
                    self.cnt_crc_q.d.next = self.cnt_crc_q.q.val() + self.n8_1.val();
                }
                if (self.err_kind_n.val() == self.k3_form.val()) && !self.p_cnt_form_max.q.val() {
                    self.cnt_form_q.d.next = self.cnt_form_q.q.val() + self.n8_1.val();
                }
                if (self.err_kind_n.val() == self.k3_ack.val()) && !self.p_cnt_ack_max.q.val() {
                    self.cnt_ack_q.d.next = self.cnt_ack_q.q.val() + self.n8_1.val();
                }
            }
            // Single shot or a due abort: a failed attempt drops the frame (§8).
            // An attempt runs from its SOF to tx_done, lost arbitration or the
            // first error it detects as transmitter (contract §8).
            if (self.attempt.q.val()
                && self.is_tx.q.val()
                && (self.lost.val() || self.error.val() || self.flag_error.val()))
                || self.sof_error.val()
            {
                self.attempt.d.next = false;
                if self.single_shot.val() || self.abort_pending.q.val() {
                    self.pending.d.next = false;
                    self.tx_failed_q.d.next = true;
                    self.abort_pending.d.next = false;
                }
            }
            // 12.1.4.4: TEC > 255 makes the node bus-off at once.
            if self.bus_off_after.val() {
                self.field_n.next = Field::BusOff;
                self.is_tx_n.next = false;
                self.attempt.d.next = false;
                self.bit_cnt_n.next = self.n7_0.val();
                self.recovery_cnt.d.next = self.n7_0.val();
            }
            self.field_q.d.next = self.field_n.val();
            self.bit_cnt.d.next = self.bit_cnt_n.val();
            self.is_tx.d.next = self.is_tx_n.val();
            self.stuff_cnt.d.next = self.stuff_cnt_n.val();
            self.stuff_last.d.next = self.stuff_last_n.val();
            self.stuff_en.d.next = self.stuff_en_n.val();
            self.crc.d.next = self.crc_n.val();
            self.crc_ok.d.next = self.crc_ok_n.val();
            self.flag_passive.d.next = self.flag_passive_n.val();
        }

        // ---- fault-confinement events of this clock
        self.fc.tec_add8.next = self.ev_tec_add8.val() && !self.listen_only.val();
        self.fc.rec_add1.next = self.ev_rec_add1.val() && !self.listen_only.val();
        self.fc.rec_add8.next = self.ev_rec_add8.val() && !self.listen_only.val();
        self.fc.tx_success.next = self.ev_tx_success.val() && !self.listen_only.val();
        self.fc.rx_success.next = self.ev_rx_success.val() && !self.listen_only.val();
        self.fc.recovered.next = self.ev_recovered.val();

        // ---- the bit this node sends next (contract §4.2), prepared from the state
        // the last SAMPLE edge left: the state changes only at SAMPLE edges and no
        // bit_start falls on one, so it is the bit of that edge, and the sample
        // decision stays off this path. (The latched frame can change only while
        // nothing is pending, and then the node sends no frame bit.)
        // 15 - n, 31 - n, 3 - n, 63 - n: the complement of the bit counter.
        self.id_a_idx.next = !self.bit_cnt.q.val().get_bits::<4>(0);
        self.id_b_idx.next = !self.bit_cnt.q.val().get_bits::<5>(0);
        self.dlc_idx.next = !self.bit_cnt.q.val().get_bits::<2>(0);
        self.data_idx.next = !self.bit_cnt.q.val().get_bits::<6>(0);
        self.crc_idx.next = !self.bit_cnt.q.val().get_bits::<4>(0);
        self.crc_tx.next = bit_cast::<16, 15>(self.crc.q.val()) << 1;
        self.tx_bit_n.next = true;
        match self.field_q.q.val() {
            Field::ErrorFlag => {
                self.tx_bit_n.next = self.flag_passive.q.val();
            }
            Field::OverloadFlag => {
                self.tx_bit_n.next = false;
            }
            Field::AckSlot => {
                // 10.4.2.7: receivers that found the CRC correct send ACK.
                self.tx_bit_n.next = self.is_tx.q.val() || !self.crc_ok.q.val();
            }
            _ => {
                if self.is_tx.q.val() {
                    if self.stuff_en.q.val() && (self.stuff_cnt.q.val() == self.n3_5.val()) {
                        self.tx_bit_n.next = !self.stuff_last.q.val();
                    } else {
                        match self.field_q.q.val() {
                            Field::IdA => {
                                self.tx_bit_n.next =
                                    self.txf_ida.q.val().get_bit(self.id_a_idx.val().index());
                            }
                            Field::SrrRtr => {
                                self.tx_bit_n.next = self.txf_ide.q.val() || self.txf_rtr.q.val();
                            }
                            Field::Ide => {
                                self.tx_bit_n.next = self.txf_ide.q.val();
                            }
                            Field::IdB => {
                                self.tx_bit_n.next =
                                    self.txf_idb.q.val().get_bit(self.id_b_idx.val().index());
                            }
                            Field::RtrExt => {
                                self.tx_bit_n.next = self.txf_rtr.q.val();
                            }
                            Field::R1 => {
                                self.tx_bit_n.next = false;
                            }
                            Field::R0 => {
                                self.tx_bit_n.next = false;
                            }
                            Field::Dlc => {
                                self.tx_bit_n.next =
                                    self.txf_dlc.q.val().get_bit(self.dlc_idx.val().index());
                            }
                            Field::Data => {
                                self.tx_bit_n.next =
                                    self.txf_data.q.val().get_bit(self.data_idx.val().index());
                            }
                            Field::Crc => {
                                self.tx_bit_n.next =
                                    self.crc_tx.val().get_bit(self.crc_idx.val().index());
                            }
                            _ => {}
                        }
                    }
                }
            }
        }

        // Listen-only: the node never drives a dominant bit (contract §7).
        self.tx_bit.next = self.tx_bit_n.val() || self.listen_only.val();

        // ---- the tx pin changes only at the start of a bit
        if self.bit_start.val() {
            if self.hard_sync.val() && (self.field_q.q.val() == Field::Idle) {
                self.tx_q.d.next = !self.starts.val();
            } else if self.hard_sync.val() && (self.field_q.q.val() == Field::Intermission) {
                // 10.4.6: a node joining at intermission bit 3 sends no SOF bit;
                // its first identifier bit follows.
                self.tx_q.d.next = true;
            } else if self.hard_sync.val() && (self.field_q.q.val() == Field::Suspend) {
                self.tx_q.d.next = true;
            } else if self.field_q.q.val() == Field::Idle {
                self.tx_q.d.next = !self.starts.val();
            } else {
                self.tx_q.d.next = self.tx_bit.val();
            }
        }

        // ---- host transmit request: latched while nothing is pending
        if self.tx_req.val() && !self.pending.q.val() && self.listen_only.val() {
            // Contract §7: listen-only refuses transmit requests.
            self.tx_failed_q.d.next = true;
        } else if self.tx_req.val() && !self.pending.q.val() {
            self.pending.d.next = true;
            if self.tx_ide.val() {
                self.txf_ida.d.next = bit_cast::<16, 11>(self.tx_id.val().get_bits::<11>(18)) << 5;
            } else {
                self.txf_ida.d.next = bit_cast::<16, 11>(self.tx_id.val().get_bits::<11>(0)) << 5;
            }
            self.txf_idb.d.next = bit_cast::<32, 18>(self.tx_id.val().get_bits::<18>(0)) << 14;
            self.txf_ide.d.next = self.tx_ide.val();
            self.txf_rtr.d.next = self.tx_rtr.val();
            self.txf_dlc.d.next = self.tx_dlc.val();
            self.txf_data.d.next = self.tx_data.val();
        }

        // ---- hard synchronisation is allowed between frames (11.3.2.1)
        match self.field_q.q.val() {
            Field::Integrating => {
                self.hard_sync_enable.next = true;
            }
            Field::Idle => {
                self.hard_sync_enable.next = true;
            }
            Field::Suspend => {
                self.hard_sync_enable.next = true;
            }
            Field::BusOff => {
                self.hard_sync_enable.next = true;
            }
            Field::Intermission => {
                // Third intermission bit: bit_cnt == 2. Intermission is entered with
                // bit_cnt = 0 (EOF, overload/error delimiter) and counts up only
                // while bit_cnt != 2, so bit_cnt is 0, 1 or 2 here and bit 1 alone
                // decides; the BTL's next state sees no 7-bit comparator.
                self.hard_sync_enable.next = self.bit_cnt.q.val().get_bit(1);
            }
            _ => {
                self.hard_sync_enable.next = false;
            }
        }

        // ---- outputs
        self.tx.next = self.tx_q.q.val();
        self.tx_pending.next = self.pending.q.val();
        self.tx_done.next = self.tx_done_q.q.val();
        self.arb_lost.next = self.arb_lost_q.q.val();
        self.rx_valid.next = self.rx_valid_q.q.val();
        self.rx_id.next = self.rx_id_q.q.val();
        self.rx_ide.next = self.rx_ide_q.q.val();
        self.rx_rtr.next = self.rx_rtr_q.q.val();
        self.rx_dlc.next = self.rx_dlc_q.q.val();
        self.rx_data.next = self.rx_data_q.q.val();
        self.field.next = self.field_q.q.val();
        self.tec.next = self.fc.tec.val();
        self.rec.next = self.fc.rec.val();
        self.err_state.next = self.fc.err_state.val();
        self.tx_failed.next = self.tx_failed_q.q.val();
        self.err_warning.next = (self.fc.tec.val() >= bit_cast::<9, 8>(self.ewl.val()))
            || (self.fc.rec.val() >= self.ewl.val());
        self.err_valid.next = self.err_valid_q.q.val();
        self.err_kind.next = self.err_kind_q.q.val();
        self.err_field.next = self.err_field_q.q.val();
        self.err_tx.next = self.err_tx_q.q.val();
        self.alc.next = self.alc_q.q.val();
        self.cnt_bit.next = self.cnt_bit_q.q.val();
        self.cnt_stuff.next = self.cnt_stuff_q.q.val();
        self.cnt_crc.next = self.cnt_crc_q.q.val();
        self.cnt_form.next = self.cnt_form_q.q.val();
        self.cnt_ack.next = self.cnt_ack_q.q.val();

        // ---- synchronous reset
        if self.rst.val() {
            self.field_q.d.next = Field::Integrating;
            self.bit_cnt.d.next = self.n7_0.val();
            self.is_tx.d.next = false;
            self.pending.d.next = false;
            self.stuff_cnt.d.next = self.n3_1.val();
            self.stuff_last.d.next = false;
            self.stuff_en.d.next = false;
            self.crc.d.next = self.zero15.val();
            self.crc_ok.d.next = true;
            self.flag_passive.d.next = false;
            self.recovery_cnt.d.next = self.n7_0.val();
            self.tx_q.d.next = true;
            self.last_bit_arb.d.next = false;
            self.dom_cnt.d.next = self.zero3.val();
            self.delim_first.d.next = false;
            self.ack_passive_pending.d.next = false;
            self.abort_pending.d.next = false;
            self.attempt.d.next = false;
            self.tx_failed_q.d.next = false;
            self.err_valid_q.d.next = false;
            self.err_kind_q.d.next = self.zero3.val();
            self.err_field_q.d.next = Field::Integrating;
            self.err_tx_q.d.next = false;
            self.alc_q.d.next = self.zero5.val();
            self.cnt_bit_q.d.next = self.zero8.val();
            self.cnt_stuff_q.d.next = self.zero8.val();
            self.cnt_crc_q.d.next = self.zero8.val();
            self.cnt_form_q.d.next = self.zero8.val();
            self.cnt_ack_q.d.next = self.zero8.val();
            self.rx_valid_q.d.next = false;
            self.tx_done_q.d.next = false;
            self.arb_lost_q.d.next = false;
            self.rx_id_q.d.next = self.zero29.val();
            self.rx_ide_q.d.next = false;
            self.rx_rtr_q.d.next = false;
            self.rx_dlc_q.d.next = self.zero4.val();
            self.rx_data_q.d.next = self.zero64.val();
        }
    }
}

#[test]
fn protocol_controller_synthesizes() {
    let mut uut = ProtocolController::default();
    uut.connect_all();
    yosys_validate("protocol_controller", &generate_verilog(&uut)).unwrap();
}
