//! Fault confinement (ISO 11898-1:2015, 12.1.4): the transmit and receive error
//! counters and the error state derived from them.
//!
//! The rules block (`fault_confinement_rules`) decides which rule applies and
//! raises one event per SAMPLE edge; this block applies it:
//! - rules b, d, e, f for a receiver (+8 to REC) -> `rec_add8`;
//! - rule a (+1 to REC) -> `rec_add1`;
//! - rules c, d, e, f for a transmitter (+8 to TEC) -> `tec_add8`;
//! - rule g (successful transmission, TEC -1) -> `tx_success`;
//! - rule h (successful reception, counted at the ACK slot: REC -1, or from above
//!   127 back to 127, the top of the 119..127 range the standard allows)
//!   -> `rx_success`;
//! - bus-off recovery (128 x 11 recessive bits) -> `recovered` clears both;
//! - the host's counter reset (contract §4.5) -> `err_reset` clears both, unless
//!   bus-off.
//!
//! Error passive at TEC >= 128 or REC >= 128; bus-off at TEC > 255. REC
//! saturates at 255 instead of wrapping. The error warning (contract §9) is
//! TEC or REC at or above the configured limit.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// TEC/REC and the error state.
#[derive(LogicBlock, Default)]
pub struct FaultConfinement {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: both counters to 0.
    pub rst: Signal<In, Bit>,
    // events from the fault-confinement rules (one clock each)
    /// TEC + 8 (rules c, d, e, f for a transmitter).
    pub tec_add8: Signal<In, Bit>,
    /// REC + 1 (rule a).
    pub rec_add1: Signal<In, Bit>,
    /// REC + 8 (rules b, d, e, f for a receiver).
    pub rec_add8: Signal<In, Bit>,
    /// TEC - 1 (rule g).
    pub tx_success: Signal<In, Bit>,
    /// REC - 1, or back to 127 from above (rule h).
    pub rx_success: Signal<In, Bit>,
    /// Bus-off recovery completed: both counters to 0.
    pub recovered: Signal<In, Bit>,
    /// Error counter reset by the host: both counters to 0 unless bus-off, after
    /// this edge's rules (contract §4.5).
    pub err_reset: Signal<In, Bit>,
    /// Error warning limit (contract §9).
    pub ewl: Signal<In, Bits<8>>,
    // counters and state
    /// Transmit error counter (256 and above: bus-off).
    pub tec: Signal<Out, Bits<9>>,
    /// Receive error counter (saturates at 255).
    pub rec: Signal<Out, Bits<8>>,
    /// 0 error active, 1 error passive, 2 bus-off.
    pub err_state: Signal<Out, Bits<2>>,
    /// TEC >= 128 or REC >= 128.
    pub error_passive: Signal<Out, Bit>,
    /// TEC > 255.
    pub bus_off: Signal<Out, Bit>,
    /// TEC or REC at or above the error warning limit.
    pub warning: Signal<Out, Bit>,
    tec_q: DFF<Bits<9>>,
    rec_q: DFF<Bits<8>>,
    eight9: Const<9, 8>,
    one9: Const<9, 1>,
    zero9: Const<9, 0>,
    limit9: Const<9, 128>,
    busoff9: Const<9, 255>,
    one8: Const<8, 1>,
    eight8: Const<8, 8>,
    zero8: Const<8, 0>,
    limit8: Const<8, 128>,
    max8: Const<8, 255>,
    rec_top8: Const<8, 247>,
    rec_top1: Const<8, 127>,
    state_active: Const<2, 0>,
    state_passive: Const<2, 1>,
    state_bus_off: Const<2, 2>,
}

impl Logic for FaultConfinement {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, tec_q, rec_q);
        // State first: the counter updates below depend on it.
        self.bus_off.next = self.tec_q.q.val() > self.busoff9.val();
        self.error_passive.next =
            (self.tec_q.q.val() >= self.limit9.val()) || (self.rec_q.q.val() >= self.limit8.val());
        // TEC is frozen while bus-off (12.1.4.4: only recovery clears it).
        if self.tec_add8.val() && (self.tec_q.q.val() <= self.busoff9.val()) {
            self.tec_q.d.next = self.tec_q.q.val() + self.eight9.val();
        } else if self.tx_success.val()
            && (self.tec_q.q.val() <= self.busoff9.val())
            && (self.tec_q.q.val() != self.zero9.val())
        {
            self.tec_q.d.next = self.tec_q.q.val() - self.one9.val();
        }
        if self.rec_add8.val() {
            if self.rec_q.q.val() > self.rec_top8.val() {
                self.rec_q.d.next = self.max8.val();
            } else {
                self.rec_q.d.next = self.rec_q.q.val() + self.eight8.val();
            }
        } else if self.rec_add1.val() {
            if self.rec_q.q.val() != self.max8.val() {
                self.rec_q.d.next = self.rec_q.q.val() + self.one8.val();
            }
        } else if self.rx_success.val() {
            if self.rec_q.q.val() >= self.limit8.val() {
                self.rec_q.d.next = self.rec_top1.val();
            } else if self.rec_q.q.val() != self.zero8.val() {
                self.rec_q.d.next = self.rec_q.q.val() - self.one8.val();
            }
        }
        // (not bus-off written out: reading `bus_off` here would be a loop to Verilator)
        if self.recovered.val()
            || self.rst.val()
            || (self.err_reset.val() && (self.tec_q.q.val() <= self.busoff9.val()))
        {
            self.tec_q.d.next = self.zero9.val();
            self.rec_q.d.next = self.zero8.val();
        }
        self.tec.next = self.tec_q.q.val();
        self.rec.next = self.rec_q.q.val();
        self.warning.next = (self.tec_q.q.val() >= bit_cast::<9, 8>(self.ewl.val()))
            || (self.rec_q.q.val() >= self.ewl.val());
        if self.bus_off.val() {
            self.err_state.next = self.state_bus_off.val();
        } else if self.error_passive.val() {
            self.err_state.next = self.state_passive.val();
        } else {
            self.err_state.next = self.state_active.val();
        }
    }
}
