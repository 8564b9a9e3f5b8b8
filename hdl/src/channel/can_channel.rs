//! The `can_channel` top: one complete classical CAN 2.0B channel (ISO 11898-1)
//! made of the rx synchronizer, the bit timing logic and the bit stream
//! processor. Ports are grouped by interface: clock/reset, bit-timing
//! configuration, CAN pins, host transmit, host receive, probes.

use super::bsp::field::Field;
use super::bsp::protocol::ProtocolController;
use super::btl::BitTimingLogic;
use super::bus_sampling::synchronizer::RxSynchronizer;
use rust_hdl::prelude::*;

/// One CAN channel: BTL + BSP.
#[derive(LogicBlock, Default)]
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
    pub tx_pending: Signal<Out, Bit>,
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
    // blocks
    rx_sync: RxSynchronizer,
    btl: BitTimingLogic,
    bsp: ProtocolController,
}

impl Logic for CanChannel {
    #[hdl_gen]
    fn update(&mut self) {
        self.rx_sync.clk.next = self.clk.val();
        self.rx_sync.rst.next = self.rst.val();
        self.rx_sync.rx.next = self.rx.val();

        self.btl.clk.next = self.clk.val();
        self.btl.rst.next = self.rst.val();
        self.btl.cfg_brp.next = self.cfg_brp.val();
        self.btl.cfg_tseg1.next = self.cfg_tseg1.val();
        self.btl.cfg_tseg2.next = self.cfg_tseg2.val();
        self.btl.cfg_sjw.next = self.cfg_sjw.val();
        self.btl.cfg_triple.next = self.cfg_triple.val();
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

        self.tx.next = self.bsp.tx.val();
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
    }
}

#[test]
fn can_channel_synthesizes() {
    let mut uut = CanChannel::default();
    uut.connect_all();
    yosys_validate("can_channel", &generate_verilog(&uut)).unwrap();
}
