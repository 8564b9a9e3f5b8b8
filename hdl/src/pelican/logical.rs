//! The SJA1000 view's logical controller (pelican_contract.md §5, P-LOG-1..4;
//! the status and counter reads of P-SR-1 and P-ERR-1): the one CAN controller
//! an SJA1000 driver sees, made from the DRCC's two channels. It picks the
//! channel in use `u`, and gives that channel's error state, counters, bus
//! activity and error and arbitration events to the registers.
//!
//! - `u` (P-LOG-1): `SINGLE_A` A, `SINGLE_B` B, `REDUNDANCY` the main FSM's
//!   `tx_channel` (§D4), `DMR` the active CAN line `acl` (§M6). While the
//!   bus-off hold `boh` lasts, `u` stays the channel it was when the hold began
//!   (the hold keeps the main FSM in IDLE1, on A).
//! - `BS` = logical bus-off (P-LOG-3): single modes `bo_u`; `REDUNDANCY`
//!   `bo_u` while no switch will carry the message away (policy `none`, or the
//!   other channel's auxiliary FSM not valid, §D4.2); `DMR` both lines bus-off;
//!   `bo_u` in every mode while `boh`.
//! - The reporting channel `r` (P-LOG-5): `u`; with `XMODE.rep` in
//!   `REDUNDANCY` and `DMR`, outside the hold, the other channel when it could
//!   carry the traffic and ranks better (error state, then warning).
//! - `ES` = `ew_r`, `EP` = `ep_r` (P-LOG-4, P-LOG-5).
//! - `TXERR` = `TEC` of `r`, or `127 - boff_runs` while `r` is bus-off (the
//!   SJA1000 loads 127 and counts the recovery down, data sheet 6.4.12);
//!   `RXERR` = `REC` of `r`; both 0 in host reset mode (P-ERR-1).
//! - `RS`, `TS` (P-SR-1): 1 in reset mode; in operating mode `TS` is `u`'s
//!   transmitter role and `RS` its activity on the bus as a receiver (its field
//!   is none of integrating, idle, intermission, suspend, bus-off).
//!
//! Combinational but for the register that keeps `u` through the hold: every
//! output is a function of registers (the view's mode bits, `u_q` and the
//! core's registered probes).

use crate::channel::bsp::field::Field;
use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The logical controller of the SJA1000 view.
#[derive(LogicBlock, Default)]
pub struct LogicalController {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: the kept channel is A.
    pub rst: Signal<In, Bit>,
    // ---- the view's configuration ----
    /// `XMODE.mode`: 0 `SINGLE_A`, 1 `REDUNDANCY`, 2 `DMR`, 3 `SINGLE_B`.
    pub mode: Signal<In, Bits<2>>,
    /// `XMODE.policy`, the switch policy code (§D5; 0 = none).
    pub policy: Signal<In, Bits<2>>,
    /// `MOD.RM` as read (`hrm | boh`).
    pub rm: Signal<In, Bit>,
    /// Host reset mode `hrm` (the channels are in reset).
    pub hrm: Signal<In, Bit>,
    /// The bus-off hold `boh` (P-BO-1): `u` and `BS` are kept through it.
    pub boh: Signal<In, Bit>,
    /// `XMODE.rep`: report the better channel that could carry the traffic.
    pub rep: Signal<In, Bit>,
    // ---- the core's choice of channel ----
    /// The main FSM's `tx_channel` (0 = A).
    pub tx_channel: Signal<In, Bit>,
    /// The DMR active CAN line (0 = DCL = A).
    pub acl: Signal<In, Bit>,
    /// Auxiliary FSM A's state (valid 0).
    pub aux_a_state: Signal<In, Bits<2>>,
    /// Auxiliary FSM B's state (valid 0).
    pub aux_b_state: Signal<In, Bits<2>>,
    // ---- channel A's probes ----
    /// Channel A `err_state`: 0 active, 1 passive, 2 bus-off.
    pub err_state_a: Signal<In, Bits<2>>,
    /// Channel A error warning.
    pub ew_a: Signal<In, Bit>,
    /// Channel A transmit error counter.
    pub tec_a: Signal<In, Bits<9>>,
    /// Channel A receive error counter.
    pub rec_a: Signal<In, Bits<8>>,
    /// Channel A completed runs of its bus-off recovery.
    pub boff_runs_a: Signal<In, Bits<7>>,
    /// Channel A's field.
    pub field_a: Signal<In, Field>,
    /// Channel A is transmitter.
    pub is_tx_a: Signal<In, Bit>,
    // ---- channel B's probes ----
    /// Channel B `err_state`.
    pub err_state_b: Signal<In, Bits<2>>,
    /// Channel B error warning.
    pub ew_b: Signal<In, Bit>,
    /// Channel B transmit error counter.
    pub tec_b: Signal<In, Bits<9>>,
    /// Channel B receive error counter.
    pub rec_b: Signal<In, Bits<8>>,
    /// Channel B completed runs of its bus-off recovery.
    pub boff_runs_b: Signal<In, Bits<7>>,
    /// Channel B's field.
    pub field_b: Signal<In, Field>,
    /// Channel B is transmitter.
    pub is_tx_b: Signal<In, Bit>,
    // ---- the logical controller ----
    /// The channel in use `u` (0 = A).
    pub u: Signal<Out, Bit>,
    /// `SR.BS`: logical bus-off.
    pub bs: Signal<Out, Bit>,
    /// `SR.ES`: error warning of `u`.
    pub es: Signal<Out, Bit>,
    /// Logical error passive: `r` is error passive.
    pub ep: Signal<Out, Bit>,
    /// The error state of `r` (for `EPI`, P-IR-6).
    pub err_state_r: Signal<Out, Bits<2>>,
    /// `SR.RS`: receiving.
    pub rs: Signal<Out, Bit>,
    /// `SR.TS`: transmitting.
    pub ts: Signal<Out, Bit>,
    /// `TXERR`.
    pub txerr: Signal<Out, Bits<8>>,
    /// `RXERR`.
    pub rxerr: Signal<Out, Bits<8>>,
    // ---- the channel in use through the hold ----
    /// `u` as the mode gives it.
    u_live: Signal<Local, Bit>,
    /// `u` of the last clock: kept while `boh`.
    u_q: DFF<Bit>,
    // ---- channel u's probes ----
    err_state_u: Signal<Local, Bits<2>>,
    field_u: Signal<Local, Field>,
    is_tx_u: Signal<Local, Bit>,
    bo_a: Signal<Local, Bit>,
    bo_b: Signal<Local, Bit>,
    bo_u: Signal<Local, Bit>,
    aux_other: Signal<Local, Bits<2>>,
    // ---- the reporting channel r (P-LOG-5) ----
    rank_a: Signal<Local, Bits<3>>,
    rank_b: Signal<Local, Bits<3>>,
    other_competes: Signal<Local, Bit>,
    r: Signal<Local, Bit>,
    tec_r: Signal<Local, Bits<9>>,
    boff_runs_r: Signal<Local, Bits<7>>,
    // ---- codes ----
    single_a: Const<2, 0>,
    redundancy: Const<2, 1>,
    dmr: Const<2, 2>,
    bus_off: Const<2, 2>,
    passive: Const<2, 1>,
    valid: Const<2, 0>,
    policy_none: Const<2, 0>,
    counter_max: Const<9, 255>,
    recovery_start: Const<8, 127>,
    zero8: Const<8, 0>,
}

impl Logic for LogicalController {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, u_q);
        // P-LOG-1: the channel in use, kept through the bus-off hold
        if self.mode.val() == self.single_a.val() {
            self.u_live.next = false;
        } else if self.mode.val() == self.redundancy.val() {
            self.u_live.next = self.tx_channel.val();
        } else if self.mode.val() == self.dmr.val() {
            self.u_live.next = self.acl.val();
        } else {
            self.u_live.next = true;
        }
        if self.boh.val() {
            self.u.next = self.u_q.q.val();
        } else {
            self.u.next = self.u_live.val();
        }
        self.u_q.d.next = self.u.val() & !self.rst.val();
        if self.u.val() {
            self.err_state_u.next = self.err_state_b.val();
            self.field_u.next = self.field_b.val();
            self.is_tx_u.next = self.is_tx_b.val();
            self.aux_other.next = self.aux_a_state.val();
        } else {
            self.err_state_u.next = self.err_state_a.val();
            self.field_u.next = self.field_a.val();
            self.is_tx_u.next = self.is_tx_a.val();
            self.aux_other.next = self.aux_b_state.val();
        }
        // P-LOG-5: the reporting channel; rank = error state, then warning
        self.rank_a.next = (bit_cast::<3, 2>(self.err_state_a.val()) << 1)
            | bit_cast::<3, 1>(self.ew_a.val().into());
        self.rank_b.next = (bit_cast::<3, 2>(self.err_state_b.val()) << 1)
            | bit_cast::<3, 1>(self.ew_b.val().into());
        self.other_competes.next = false;
        if self.rep.val() & !self.boh.val() {
            if self.mode.val() == self.redundancy.val() {
                self.other_competes.next = (self.policy.val() != self.policy_none.val())
                    & (self.aux_other.val() == self.valid.val());
            } else if self.mode.val() == self.dmr.val() {
                self.other_competes.next = true;
            }
        }
        self.r.next = self.u.val();
        if self.other_competes.val() {
            if self.u.val() {
                self.r.next = self.rank_a.val() >= self.rank_b.val();
            } else {
                self.r.next = self.rank_b.val() < self.rank_a.val();
            }
        }
        if self.r.val() {
            self.err_state_r.next = self.err_state_b.val();
            self.tec_r.next = self.tec_b.val();
            self.boff_runs_r.next = self.boff_runs_b.val();
            self.es.next = self.ew_b.val();
            self.rxerr.next = self.rec_b.val();
        } else {
            self.err_state_r.next = self.err_state_a.val();
            self.tec_r.next = self.tec_a.val();
            self.boff_runs_r.next = self.boff_runs_a.val();
            self.es.next = self.ew_a.val();
            self.rxerr.next = self.rec_a.val();
        }
        // P-LOG-2, P-LOG-3: logical bus-off
        self.bo_a.next = self.err_state_a.val() == self.bus_off.val();
        self.bo_b.next = self.err_state_b.val() == self.bus_off.val();
        self.bo_u.next = self.err_state_u.val() == self.bus_off.val();
        self.ep.next = self.err_state_r.val() == self.passive.val();
        if self.boh.val() {
            // the held channel stays bus-off until the host clears RM (P-BO-3)
            self.bs.next = self.bo_u.val();
        } else if self.mode.val() == self.redundancy.val() {
            // only a switch to a valid channel carries the message away (§D4.2)
            self.bs.next = self.bo_u.val()
                & ((self.policy.val() == self.policy_none.val())
                    | (self.aux_other.val() != self.valid.val()));
        } else if self.mode.val() == self.dmr.val() {
            self.bs.next = self.bo_a.val() & self.bo_b.val();
        } else {
            self.bs.next = self.bo_u.val();
        }
        // P-ERR-1: TXERR counts the recovery down from 127 while bus-off
        if self.err_state_r.val() == self.bus_off.val() {
            self.txerr.next = self.recovery_start.val() - bit_cast::<8, 7>(self.boff_runs_r.val());
        } else if self.tec_r.val() > self.counter_max.val() {
            self.txerr.next = self.counter_max.val().get_bits::<8>(0);
        } else {
            self.txerr.next = self.tec_r.val().get_bits::<8>(0);
        }
        if self.hrm.val() {
            self.txerr.next = self.zero8.val();
            self.rxerr.next = self.zero8.val();
        }
        // P-SR-1: the bus activity of u; both 1 in reset mode and while u waits
        // for the bus to become idle (integrating, bus-off; DS Table 14 note 3)
        self.ts.next = self.rm.val()
            | self.is_tx_u.val()
            | (self.field_u.val() == Field::Integrating)
            | (self.field_u.val() == Field::BusOff);
        self.rs.next = self.rm.val()
            | (self.field_u.val() == Field::Integrating)
            | (self.field_u.val() == Field::BusOff)
            | (!self.is_tx_u.val()
                & (self.field_u.val() != Field::Idle)
                & (self.field_u.val() != Field::Intermission)
                & (self.field_u.val() != Field::Suspend));
    }
}
