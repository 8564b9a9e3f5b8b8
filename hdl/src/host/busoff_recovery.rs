//! Manual bus-off recovery of one channel (DRCC contract §11.6): the host's
//! permission `recover` and the channel's `boff_hold` input (timing contract
//! §4.5). With `CTRL.busoff_manual` a channel that goes bus-off does not count
//! its 128 runs of 11 recessive bits until the host writes `TX_CMD.recover_x`;
//! the permission lasts while the channel is bus-off and ends at the first edge
//! after it has left bus-off (or has been reset), so the next bus-off waits for
//! the host again. The top instantiates the block once per channel.

use crate::host::registers::ErrState;
use rust_hdl::prelude::*;

/// The permission register and the hold of one channel.
#[derive(LogicBlock)]
pub struct BusoffRecovery {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: no permission.
    pub rst: Signal<In, Bit>,
    // ---- host ----
    /// `CTRL.busoff_manual`: the recovery waits for the host.
    pub busoff_manual: Signal<In, Bit>,
    /// An accepted `TX_CMD` write with this channel's `recover` bit.
    pub recover: Signal<In, Bit>,
    // ---- channel ----
    /// The channel's `err_state` (bus-off = 2).
    pub err_state: Signal<In, Bits<2>>,
    /// The channel's `boff_hold`: `busoff_manual && !permission`.
    pub boff_hold: Signal<Out, Bit>,
    // ---- state ----
    /// The host's permission (contract §11.6, `recover_c`).
    permit: DFF<Bit>,
    bus_off: Signal<Local, Bit>,
    es_bus_off: Constant<Bits<2>>,
}

impl Default for BusoffRecovery {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            busoff_manual: Default::default(),
            recover: Default::default(),
            err_state: Default::default(),
            boff_hold: Default::default(),
            permit: Default::default(),
            bus_off: Default::default(),
            es_bus_off: Constant::new((ErrState::BusOff.code() as u64).into()),
        }
    }
}

impl Logic for BusoffRecovery {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, permit);
        self.bus_off.next = self.err_state.val() == self.es_bus_off.val();
        // recover_c <= bo_c && (recover_c || w_c)
        self.permit.d.next = self.bus_off.val() & (self.permit.q.val() | self.recover.val());
        if self.rst.val() {
            self.permit.d.next = false;
        }
        self.boff_hold.next = self.busoff_manual.val() & !self.permit.q.val();
    }
}
