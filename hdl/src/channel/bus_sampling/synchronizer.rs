//! Receive-pin synchronizer: two flip-flops between the asynchronous `rx` pin and
//! the bit timing logic (timing contract §2), in a [`SyncCell`] that carries the
//! vendors' synchronizer attributes. Both stages reset to recessive so a reset
//! never shows a false start-of-frame edge.

use crate::pins::SyncCell;
use rust_hdl::prelude::*;

/// Two-flip-flop synchronizer for the CAN `rx` pin.
#[derive(LogicBlock, Default)]
pub struct RxSynchronizer {
    // clock and reset
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: both stages recessive.
    pub rst: Signal<In, Bit>,
    // pin side
    /// The asynchronous CAN `rx` pin, 1 = recessive.
    pub rx: Signal<In, Bit>,
    // core side
    /// The synchronized bus value, two clocks after the pin.
    pub rx_s: Signal<Out, Bit>,
    rx_sync: SyncCell,
}

impl Logic for RxSynchronizer {
    #[hdl_gen]
    fn update(&mut self) {
        self.rx_sync.clock.next = self.clk.val();
        self.rx_sync.rst.next = self.rst.val();
        self.rx_sync.d.next = self.rx.val();
        self.rx_s.next = self.rx_sync.q.val();
    }
}
