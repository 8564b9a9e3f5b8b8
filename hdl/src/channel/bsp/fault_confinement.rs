//! Fault confinement (ISO 11898-1:2015, 12.1.4): the transmit and receive error
//! counters and the error state derived from them.
//!
//! The protocol controller decides which rule applies and raises one event per
//! SAMPLE edge; this block applies it:
//! - rules b, d, e, f for a receiver (+8 to REC) -> `rec_add8`;
//! - rule a (+1 to REC) -> `rec_add1`;
//! - rules c, d, e, f for a transmitter (+8 to TEC) -> `tec_add8`;
//! - rule g (successful transmission, TEC -1) -> `tx_success`;
//! - rule h (successful reception, counted at the ACK slot: REC -1, or from above
//!   127 back to 127, the top of the 119..127 range the standard allows)
//!   -> `rx_success`;
//! - bus-off recovery (128 x 11 recessive bits) -> `recovered` clears both.
//!
//! Error passive at TEC >= 128 or REC >= 128; bus-off at TEC > 255. REC
//! saturates at 255 instead of wrapping.

use rust_hdl::prelude::*;

/// TEC/REC and the error state.
#[derive(LogicBlock)]
pub struct FaultConfinement {
    // clock and reset
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // events from the protocol controller (one clock each)
    pub tec_add8: Signal<In, Bit>,
    pub rec_add1: Signal<In, Bit>,
    pub rec_add8: Signal<In, Bit>,
    pub tx_success: Signal<In, Bit>,
    pub rx_success: Signal<In, Bit>,
    pub recovered: Signal<In, Bit>,
    // counters and state
    pub tec: Signal<Out, Bits<9>>,
    pub rec: Signal<Out, Bits<8>>,
    /// 0 error active, 1 error passive, 2 bus-off.
    pub err_state: Signal<Out, Bits<2>>,
    pub error_passive: Signal<Out, Bit>,
    pub bus_off: Signal<Out, Bit>,
    tec_q: DFF<Bits<9>>,
    rec_q: DFF<Bits<8>>,
    eight9: Constant<Bits<9>>,
    one9: Constant<Bits<9>>,
    zero9: Constant<Bits<9>>,
    limit9: Constant<Bits<9>>,
    busoff9: Constant<Bits<9>>,
    one8: Constant<Bits<8>>,
    eight8: Constant<Bits<8>>,
    zero8: Constant<Bits<8>>,
    limit8: Constant<Bits<8>>,
    max8: Constant<Bits<8>>,
    rec_top8: Constant<Bits<8>>,
    rec_top1: Constant<Bits<8>>,
    state_active: Constant<Bits<2>>,
    state_passive: Constant<Bits<2>>,
    state_bus_off: Constant<Bits<2>>,
}

impl Default for FaultConfinement {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            tec_add8: Default::default(),
            rec_add1: Default::default(),
            rec_add8: Default::default(),
            tx_success: Default::default(),
            rx_success: Default::default(),
            recovered: Default::default(),
            tec: Default::default(),
            rec: Default::default(),
            err_state: Default::default(),
            error_passive: Default::default(),
            bus_off: Default::default(),
            tec_q: Default::default(),
            rec_q: Default::default(),
            eight9: Constant::new(8.into()),
            one9: Constant::new(1.into()),
            zero9: Constant::new(0.into()),
            limit9: Constant::new(128.into()),
            busoff9: Constant::new(255.into()),
            one8: Constant::new(1.into()),
            eight8: Constant::new(8.into()),
            zero8: Constant::new(0.into()),
            limit8: Constant::new(128.into()),
            max8: Constant::new(255.into()),
            rec_top8: Constant::new(247.into()),
            rec_top1: Constant::new(127.into()),
            state_active: Constant::new(0.into()),
            state_passive: Constant::new(1.into()),
            state_bus_off: Constant::new(2.into()),
        }
    }
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
        if self.recovered.val() || self.rst.val() {
            self.tec_q.d.next = self.zero9.val();
            self.rec_q.d.next = self.zero8.val();
        }
        self.tec.next = self.tec_q.q.val();
        self.rec.next = self.rec_q.q.val();
        if self.bus_off.val() {
            self.err_state.next = self.state_bus_off.val();
        } else if self.error_passive.val() {
            self.err_state.next = self.state_passive.val();
        } else {
            self.err_state.next = self.state_active.val();
        }
    }
}

#[test]
fn fault_confinement_synthesizes() {
    let mut uut = FaultConfinement::default();
    uut.connect_all();
    yosys_validate("fault_confinement", &generate_verilog(&uut)).unwrap();
}
