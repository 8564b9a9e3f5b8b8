//! Receive-pin synchronizer: two flip-flops between the asynchronous `rx` pin and
//! the bit timing logic (timing contract §2). Both stages reset to recessive so a
//! reset never shows a false start-of-frame edge.

use rust_hdl::prelude::*;

/// Two-flip-flop synchronizer for the CAN `rx` pin.
#[derive(LogicBlock, Default)]
pub struct RxSynchronizer {
    // clock and reset
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // pin side
    pub rx: Signal<In, Bit>,
    // core side: the synchronized bus value
    pub rx_s: Signal<Out, Bit>,
    rx_meta: DFF<Bit>,
    rx_sync: DFF<Bit>,
}

impl Logic for RxSynchronizer {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, rx_meta, rx_sync);
        self.rx_meta.d.next = self.rx.val();
        self.rx_sync.d.next = self.rx_meta.q.val();
        if self.rst.val() {
            self.rx_meta.d.next = true;
            self.rx_sync.d.next = true;
        }
        self.rx_s.next = self.rx_sync.q.val();
    }
}

#[test]
fn synchronizer_synthesizes() {
    let mut uut = RxSynchronizer::default();
    uut.connect_all();
    yosys_validate("rx_synchronizer", &generate_verilog(&uut)).unwrap();
}
