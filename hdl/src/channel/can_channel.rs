//! The `can_channel` top: one complete classical CAN 2.0B channel (ISO 11898-1)
//! made of the rx synchronizer, the bit timing logic and the bit stream
//! processor. Ports are grouped by interface: clock/reset, bit-timing
//! configuration, CAN pins, host transmit, host receive, probes.

use super::bsp::field::Field;
use super::bsp::protocol::ProtocolController;
use super::btl::BitTimingLogic;
use super::bus_sampling::synchronizer::RxSynchronizer;
use super::config::ChannelConfig;
use rust_hdl::prelude::*;

/// One CAN channel: BTL + BSP.
#[derive(LogicBlock)]
pub struct CanChannel {
    // clock and reset
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // bit-timing configuration: tq = (cfg_brp+1) clocks, TSEG1 = cfg_tseg1+1,
    // TSEG2 = cfg_tseg2+1, SJW = min(cfg_sjw+1, TSEG2)
    pub cfg_brp: Signal<In, Bits<6>>,
    pub cfg_tseg1: Signal<In, Bits<4>>,
    pub cfg_tseg2: Signal<In, Bits<3>>,
    pub cfg_sjw: Signal<In, Bits<2>>,
    pub cfg_triple: Signal<In, Bit>,
    // controller configuration: mode (0 normal, 1 listen-only, 2 self-test,
    // 3 loop-back), error warning limit, no automatic retransmission
    pub cfg_mode: Signal<In, Bits<2>>,
    pub cfg_ewl: Signal<In, Bits<8>>,
    pub cfg_single_shot: Signal<In, Bit>,
    // CAN pins (1 = recessive)
    pub rx: Signal<In, Bit>,
    pub tx: Signal<Out, Bit>,
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
    pub sample_point: Signal<Out, Bit>,
    pub sampled_bit: Signal<Out, Bit>,
    pub field: Signal<Out, Field>,
    pub tec: Signal<Out, Bits<9>>,
    pub rec: Signal<Out, Bits<8>>,
    pub err_state: Signal<Out, Bits<2>>,
    // diagnostics
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
    // blocks
    cfg_regs: ChannelConfig,
    rx_sync: RxSynchronizer,
    btl: BitTimingLogic,
    bsp: ProtocolController,
    loopback_mode: Constant<Bits<2>>,
}

impl Default for CanChannel {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            cfg_brp: Default::default(),
            cfg_tseg1: Default::default(),
            cfg_tseg2: Default::default(),
            cfg_sjw: Default::default(),
            cfg_triple: Default::default(),
            cfg_mode: Default::default(),
            cfg_ewl: Default::default(),
            cfg_single_shot: Default::default(),
            rx: Default::default(),
            tx: Default::default(),
            tx_req: Default::default(),
            tx_id: Default::default(),
            tx_ide: Default::default(),
            tx_rtr: Default::default(),
            tx_dlc: Default::default(),
            tx_data: Default::default(),
            tx_abort: Default::default(),
            tx_pending: Default::default(),
            tx_failed: Default::default(),
            tx_done: Default::default(),
            arb_lost: Default::default(),
            rx_valid: Default::default(),
            rx_id: Default::default(),
            rx_ide: Default::default(),
            rx_rtr: Default::default(),
            rx_dlc: Default::default(),
            rx_data: Default::default(),
            sample_point: Default::default(),
            sampled_bit: Default::default(),
            field: Default::default(),
            tec: Default::default(),
            rec: Default::default(),
            err_state: Default::default(),
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
            cfg_regs: Default::default(),
            rx_sync: Default::default(),
            btl: Default::default(),
            bsp: Default::default(),
            loopback_mode: Constant::new(3.into()),
        }
    }
}

impl Logic for CanChannel {
    #[hdl_gen]
    fn update(&mut self) {
        self.cfg_regs.clk.next = self.clk.val();
        self.cfg_regs.rst.next = self.rst.val();
        self.cfg_regs.cfg_brp.next = self.cfg_brp.val();
        self.cfg_regs.cfg_tseg1.next = self.cfg_tseg1.val();
        self.cfg_regs.cfg_tseg2.next = self.cfg_tseg2.val();
        self.cfg_regs.cfg_sjw.next = self.cfg_sjw.val();
        self.cfg_regs.cfg_triple.next = self.cfg_triple.val();
        self.cfg_regs.cfg_mode.next = self.cfg_mode.val();
        self.cfg_regs.cfg_ewl.next = self.cfg_ewl.val();
        self.cfg_regs.cfg_single_shot.next = self.cfg_single_shot.val();

        // Loop-back mode (contract §7): the receiver hears the node's own tx
        // register and the pin stays recessive.
        self.rx_sync.clk.next = self.clk.val();
        self.rx_sync.rst.next = self.rst.val();
        if self.cfg_regs.mode.val() == self.loopback_mode.val() {
            self.rx_sync.rx.next = self.bsp.tx.val();
            self.tx.next = true;
        } else {
            self.rx_sync.rx.next = self.rx.val();
            self.tx.next = self.bsp.tx.val();
        }

        self.btl.clk.next = self.clk.val();
        self.btl.rst.next = self.rst.val();
        self.btl.cfg_brp_next.next = self.cfg_regs.brp_next.val();
        self.btl.cfg_tseg1_len.next = self.cfg_regs.tseg1_len.val();
        self.btl.cfg_tseg2_len.next = self.cfg_regs.tseg2_len.val();
        self.btl.cfg_sjw_len.next = self.cfg_regs.sjw_len.val();
        self.btl.cfg_triple.next = self.cfg_regs.triple.val();
        self.btl.rx_s.next = self.rx_sync.rx_s.val();
        self.btl.tx.next = self.bsp.tx.val();
        self.btl.hard_sync_enable.next = self.bsp.hard_sync_enable.val();

        self.bsp.clk.next = self.clk.val();
        self.bsp.rst.next = self.rst.val();
        self.bsp.sample.next = self.btl.sample.val();
        self.bsp.sampled.next = self.btl.sampled.val();
        self.bsp.bit_start.next = self.btl.bit_start.val();
        self.bsp.hard_sync.next = self.btl.hard_sync.val();
        self.bsp.tx_req.next = self.tx_req.val();
        self.bsp.tx_id.next = self.tx_id.val();
        self.bsp.tx_ide.next = self.tx_ide.val();
        self.bsp.tx_rtr.next = self.tx_rtr.val();
        self.bsp.tx_dlc.next = self.tx_dlc.val();
        self.bsp.tx_data.next = self.tx_data.val();
        self.bsp.tx_abort.next = self.tx_abort.val();
        self.bsp.mode.next = self.cfg_regs.mode.val();
        self.bsp.ewl.next = self.cfg_regs.ewl.val();
        self.bsp.single_shot.next = self.cfg_regs.single_shot.val();

        self.tx_pending.next = self.bsp.tx_pending.val();
        self.tx_done.next = self.bsp.tx_done.val();
        self.arb_lost.next = self.bsp.arb_lost.val();
        self.rx_valid.next = self.bsp.rx_valid.val();
        self.rx_id.next = self.bsp.rx_id.val();
        self.rx_ide.next = self.bsp.rx_ide.val();
        self.rx_rtr.next = self.bsp.rx_rtr.val();
        self.rx_dlc.next = self.bsp.rx_dlc.val();
        self.rx_data.next = self.bsp.rx_data.val();
        self.sample_point.next = self.btl.sample_point.val();
        self.sampled_bit.next = self.btl.last_sample.val();
        self.field.next = self.bsp.field.val();
        self.tec.next = self.bsp.tec.val();
        self.rec.next = self.bsp.rec.val();
        self.err_state.next = self.bsp.err_state.val();
        self.tx_failed.next = self.bsp.tx_failed.val();
        self.err_warning.next = self.bsp.err_warning.val();
        self.err_valid.next = self.bsp.err_valid.val();
        self.err_kind.next = self.bsp.err_kind.val();
        self.err_field.next = self.bsp.err_field.val();
        self.err_tx.next = self.bsp.err_tx.val();
        self.alc.next = self.bsp.alc.val();
        self.cnt_bit.next = self.bsp.cnt_bit.val();
        self.cnt_stuff.next = self.bsp.cnt_stuff.val();
        self.cnt_crc.next = self.bsp.cnt_crc.val();
        self.cnt_form.next = self.bsp.cnt_form.val();
        self.cnt_ack.next = self.bsp.cnt_ack.val();
    }
}

#[test]
fn can_channel_synthesizes() {
    let mut uut = CanChannel::default();
    uut.connect_all();
    yosys_validate("can_channel", &generate_verilog(&uut)).unwrap();
}
