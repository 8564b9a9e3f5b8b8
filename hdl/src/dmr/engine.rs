//! The DMR engine (DMR contract §4.1-§4.4, the seed's "DMR process action"):
//! seven event flags with their latched keys, served one job at a time by the
//! FSM `IDLE / SCAN / UPDATE / EVAL`, and the mailboxes' counters and timers
//! (`super::mailbox_state`).
//!
//! - An event job (`TX`, `RX`, `REQ` of a line) scans the mailboxes one per clock
//!   for the lowest match of its key (§4.1) and updates that mailbox: `M + 2`
//!   clocks (§4.3).
//! - An evaluation (`pend_eval`, set at `dmr_tick`) judges every enabled mailbox
//!   once (§4.2, seed Figure 4): `M + 1` clocks. Its verdict (`fault*`) is
//!   combinational on the registers before the edge; the control block sets the
//!   fault flag at that edge.
//!
//! The identifier memory (`super::mailbox_cfg`) is outside: the engine asks for
//! mailbox `e_i + 1` during `SCAN` and `EVAL` and for 0 in `IDLE`, so the read
//! data is always mailbox `e_i` (registered read, the address one edge ahead).
//! The state copy the engine reads (`super::mailbox_state`, block RAM) follows
//! the same addresses, except at the last `SCAN` edge, where it loads `e_hit`
//! for `UPDATE`.
//!
//! The evaluation's settling bits (§4.2: a receive mailbox's first timeout after
//! a recovery re-balances it) live with the state (`super::mailbox_state`).
//!
//! `hold` resets the flags and the FSM and zeroes the state; the latched keys and
//! `e_kind`, `e_line`, `e_key`, `e_hit` are not reset: each is written before it
//! is read (a flag with its key, a job's fields when the job is taken).

use super::mailbox_state::MailboxState;
use crate::channel::sized::{Const, LastIndex};
use rust_hdl::prelude::*;

/// Mailboxes `M` of the default DRCC (generation parameter, contract §2).
pub const MAILBOXES: usize = 16;

/// Engine states (§4.3), the `e_state` probe.
pub const E_IDLE: u64 = 0;
pub const E_SCAN: u64 = 1;
pub const E_UPDATE: u64 = 2;
pub const E_EVAL: u64 = 3;

/// Job kinds (`e_kind`).
const K_TX: u64 = 0;
const K_RX: u64 = 1;
const K_REQ: u64 = 2;

/// The DMR engine with the state of `M` mailboxes (1..16).
#[derive(LogicBlock, Default)]
pub struct DmrEngine<const M: usize> {
    /// System clock.
    pub clk: Signal<In, Clock>,
    // ---- control ----
    /// Not running (not DMR mode, or reset mode): flags cleared, FSM in `IDLE`,
    /// every counter and timer 0.
    pub hold: Signal<In, Bit>,
    /// A recovery (§7): every counter and timer becomes 0 at this edge, over any
    /// engine update; the flags and the FSM go on.
    pub clear_state: Signal<In, Bit>,
    /// `DMR_CFG.timeout`: DMR ticks loaded into a mailbox timer.
    pub timeout: Signal<In, Bits<16>>,
    // ---- events raised at this edge (§4.1) and their keys {ide, id[28:0]} ----
    /// `TX(DCL)`: a host message sent on the DCL.
    pub tx_dcl: Signal<In, Bit>,
    /// `TX(RCL)`: a host message sent on the RCL.
    pub tx_rcl: Signal<In, Bit>,
    /// `RX(DCL)`: a frame (not CS) received on the DCL.
    pub rx_dcl: Signal<In, Bit>,
    /// `RX(RCL)`: a frame (not CS) received on the RCL.
    pub rx_rcl: Signal<In, Bit>,
    /// `REQ(DCL)`: a host message requested on the DCL.
    pub req_dcl: Signal<In, Bit>,
    /// `REQ(RCL)`: a host message requested on the RCL.
    pub req_rcl: Signal<In, Bit>,
    /// Key of `TX(DCL)`.
    pub key_tx_dcl: Signal<In, Bits<30>>,
    /// Key of `TX(RCL)`.
    pub key_tx_rcl: Signal<In, Bits<30>>,
    /// Key of `RX(DCL)`.
    pub key_rx_dcl: Signal<In, Bits<30>>,
    /// Key of `RX(RCL)`.
    pub key_rx_rcl: Signal<In, Bits<30>>,
    /// Key of `REQ(DCL)`.
    pub key_req_dcl: Signal<In, Bits<30>>,
    /// Key of `REQ(RCL)`.
    pub key_req_rcl: Signal<In, Bits<30>>,
    /// `dmr_tick` (§3): an evaluation is due (`pend_eval` set at this edge).
    pub eval: Signal<In, Bit>,
    // ---- mailbox configuration ----
    /// `MB_CFG.enable`, bit i = mailbox i.
    pub mb_enable: Signal<In, Bits<16>>,
    /// `MB_CFG.limit`, mailbox i in `[8i+6:8i]`.
    pub mb_limits: Signal<In, Bits<128>>,
    /// Identifier memory read address to load at this edge.
    pub cfg_addr: Signal<Out, Bits<4>>,
    /// `MB_ID` of the address of the previous edge: [30] dir, [29] ide, [28:0] id.
    pub cfg_id_word: Signal<In, Bits<31>>,
    /// `MB_MASK` of the address of the previous edge.
    pub cfg_mask: Signal<In, Bits<29>>,
    // ---- host window ----
    /// `MB_SEL`.
    pub mb_sel: Signal<In, Bits<4>>,
    /// `MB_STATE` of mailbox `mb_sel`: [7:0] counter, [31:16] timer; after an
    /// edge, the state after it of the mailbox `mb_sel` named at it.
    pub mb_state_word: Signal<Out, Bits<32>>,
    // ---- the evaluation's verdict at this edge (§4.2) ----
    /// A fault is found.
    pub fault: Signal<Out, Bit>,
    /// The faulty line: 0 DCL, 1 RCL (`counter > 0 ? RCL : DCL`).
    pub fault_line: Signal<Out, Bit>,
    /// The mailbox is a transmit mailbox (else receive).
    pub fault_tx: Signal<Out, Bit>,
    /// `DEVIATION` (else `TIMEOUT`).
    pub fault_deviation: Signal<Out, Bit>,
    /// The mailbox judged.
    pub fault_mb: Signal<Out, Bits<4>>,
    // ---- probe ----
    /// `e_state`: 0 IDLE, 1 SCAN, 2 UPDATE, 3 EVAL.
    pub e_state: Signal<Out, Bits<2>>,
    // ---- event registers (§4.3) ----
    pend_tx_dcl: DFF<Bit>,
    pend_tx_rcl: DFF<Bit>,
    pend_rx_dcl: DFF<Bit>,
    pend_rx_rcl: DFF<Bit>,
    pend_req_dcl: DFF<Bit>,
    pend_req_rcl: DFF<Bit>,
    pend_eval: DFF<Bit>,
    k_tx_dcl: DFF<Bits<30>>,
    k_tx_rcl: DFF<Bits<30>>,
    k_rx_dcl: DFF<Bits<30>>,
    k_rx_rcl: DFF<Bits<30>>,
    k_req_dcl: DFF<Bits<30>>,
    k_req_rcl: DFF<Bits<30>>,
    // ---- engine registers (§4.3) ----
    state: DFF<Bits<2>>,
    e_i: DFF<Bits<4>>,
    e_kind: DFF<Bits<2>>,
    e_line: DFF<Bit>,
    e_key: DFF<Bits<30>>,
    e_found: DFF<Bit>,
    e_hit: DFF<Bits<4>>,
    // ---- mailbox state ----
    mbx: MailboxState<M>,
    // ---- internals ----
    mb: Signal<Local, Bits<4>>,
    mb_c: Signal<Local, Bits<7>>,
    en: Signal<Local, Bit>,
    limit: Signal<Local, Bits<8>>,
    c: Signal<Local, Bits<8>>,
    t: Signal<Local, Bits<16>>,
    hit: Signal<Local, Bit>,
    c_step: Signal<Local, Bits<8>>,
    toward: Signal<Local, Bit>,
    t_step: Signal<Local, Bits<16>>,
    c_abs: Signal<Local, Bits<8>>,
    t_dec: Signal<Local, Bits<16>>,
    deviation: Signal<Local, Bit>,
    expired: Signal<Local, Bit>,
    rebalance: Signal<Local, Bit>,
    /// §4.2 debt of the mailbox worked on: a timeout judged it, the counter kept.
    owed: Signal<Local, Bit>,
    s_idle: Const<2, E_IDLE>,
    s_scan: Const<2, E_SCAN>,
    s_update: Const<2, E_UPDATE>,
    s_eval: Const<2, E_EVAL>,
    k_tx: Const<2, K_TX>,
    k_rx: Const<2, K_RX>,
    k_req: Const<2, K_REQ>,
    last: LastIndex<4, M>,
    one4: Const<4, 1>,
    zero4: Const<4, 0>,
    zero8: Const<8, 0>,
    one8: Const<8, 1>,
    max8: Const<8, 0x7F>,
    min8: Const<8, 0x80>,
    zero16: Const<16, 0>,
    one16: Const<16, 1>,
    zero29: Const<29, 0>,
}

impl<const M: usize> Logic for DmrEngine<M> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            pend_tx_dcl,
            pend_tx_rcl,
            pend_rx_dcl,
            pend_rx_rcl,
            pend_req_dcl,
            pend_req_rcl,
            pend_eval,
            k_tx_dcl,
            k_tx_rcl,
            k_rx_dcl,
            k_rx_rcl,
            k_req_dcl,
            k_req_rcl,
            state,
            e_i,
            e_kind,
            e_line,
            e_key,
            e_found,
            e_hit
        );
        self.mbx.clk.next = self.clk.val();
        // The mailbox the engine works on: `e_hit` in UPDATE, `e_i` otherwise.
        if self.state.q.val() == self.s_update.val() {
            self.mb.next = self.e_hit.q.val();
        } else {
            self.mb.next = self.e_i.q.val();
        }
        self.mbx.sel.next = self.mb.val();
        self.owed.next = self.mbx.oweds.val().get_bit(self.mb.val().index());
        self.mb_c.next = bit_cast::<7, 4>(self.mb.val()) << 3;
        // Its state, from the block RAM copy read at the previous edge.
        self.c.next = self.mbx.rd_counter.val();
        self.t.next = self.mbx.rd_timer.val();
        // The host window (`MB_STATE`): the state after the previous edge of
        // the mailbox `MB_SEL` named there (`super::mailbox_state`).
        self.mbx.win_addr.next = self.mb_sel.val();
        self.mb_state_word.next = bit_cast::<32, 8>(self.mbx.win_counter.val())
            | (bit_cast::<32, 16>(self.mbx.win_timer.val()) << 16);
        self.en.next = self.mb_enable.val().get_bit(self.mb.val().index());
        self.limit.next =
            bit_cast::<8, 7>(self.mb_limits.val().get_bits::<7>(self.mb_c.val().index()));
        // The identifier memory: mailbox e_i + 1 is read while scanning or
        // evaluating (the data of e_i is there now), mailbox 0 in IDLE.
        if (self.state.q.val() == self.s_scan.val()) | (self.state.q.val() == self.s_eval.val()) {
            self.cfg_addr.next = self.e_i.q.val() + self.one4.val();
        } else {
            self.cfg_addr.next = self.zero4.val();
        }
        // §4.1 match of e_key: enable, direction (transmit for TX and REQ), ide,
        // the masked identifier.
        self.hit.next = self.en.val()
            & (self.cfg_id_word.val().get_bit(30) == (self.e_kind.q.val() != self.k_rx.val()))
            & (self.cfg_id_word.val().get_bit(29) == self.e_key.q.val().get_bit(29))
            & (((self.e_key.q.val().get_bits::<29>(0) ^ self.cfg_id_word.val().get_bits::<29>(0))
                & self.cfg_mask.val())
                == self.zero29.val());
        // The state read for the next clock: `e_hit` (found at this edge or
        // before) for UPDATE, otherwise the mailbox of the identifier memory.
        if (self.state.q.val() == self.s_scan.val()) & (self.e_i.q.val() == self.last.val()) {
            if !self.e_found.q.val() & self.hit.val() {
                self.mbx.rd_addr.next = self.e_i.q.val();
            } else {
                self.mbx.rd_addr.next = self.e_hit.q.val();
            }
        } else {
            self.mbx.rd_addr.next = self.cfg_addr.val();
        }
        // §4.1 counter step: DCL +1, RCL -1, saturating; `toward` = the copy of
        // the lagging line (|c'| < |c|).
        if !self.e_line.q.val() {
            if self.c.val() == self.max8.val() {
                self.c_step.next = self.c.val();
            } else {
                self.c_step.next = self.c.val() + self.one8.val();
            }
            self.toward.next = self.c.val().get_bit(7);
        } else {
            if self.c.val() == self.min8.val() {
                self.c_step.next = self.c.val();
            } else {
                self.c_step.next = self.c.val() - self.one8.val();
            }
            self.toward.next = !self.c.val().get_bit(7) & (self.c.val() != self.zero8.val());
        }
        // balanced stops the timer; the first copy or a lagging one (re)starts
        // it, unless a debt is owed (§4.2)
        if self.c_step.val() == self.zero8.val() {
            self.t_step.next = self.zero16.val();
        } else if !self.owed.val() & ((self.c.val() == self.zero8.val()) | self.toward.val()) {
            self.t_step.next = self.timeout.val();
        } else {
            self.t_step.next = self.t.val();
        }
        // §4.2 evaluation: t' = timer - 1 (stopped at 0); |counter| > limit is a
        // deviation, else an unbalanced counter whose t' is 0 a timeout.
        if self.c.val().get_bit(7) {
            self.c_abs.next = self.zero8.val() - self.c.val();
        } else {
            self.c_abs.next = self.c.val();
        }
        if self.t.val() == self.zero16.val() {
            self.t_dec.next = self.zero16.val();
        } else {
            self.t_dec.next = self.t.val() - self.one16.val();
        }
        self.deviation.next = self.c_abs.val() > self.limit.val();
        // while a debt is owed only a deviation judges (§4.2)
        self.expired.next = (self.c.val() != self.zero8.val())
            & (self.t_dec.val() == self.zero16.val())
            & !self.owed.val();
        // §4.2 settling: a mailbox's first timeout after its counters were
        // cleared re-balances it instead of judging a line.
        self.rebalance.next = self.expired.val()
            & !self.deviation.val()
            & self.mbx.settles.val().get_bit(self.e_i.q.val().index());
        // The verdict, on the values before the edge. A fault's counter is not 0:
        // its sign names the line ("a positive value ... hence the RCL is faulty").
        self.fault.next = !self.hold.val()
            & (self.state.q.val() == self.s_eval.val())
            & self.en.val()
            & (self.deviation.val() | self.expired.val())
            & !self.rebalance.val();
        self.fault_line.next = !self.c.val().get_bit(7);
        self.fault_tx.next = self.cfg_id_word.val().get_bit(30);
        self.fault_deviation.next = self.deviation.val();
        self.fault_mb.next = self.e_i.q.val();
        self.e_state.next = self.state.q.val();
        // The mailbox write of UPDATE and EVAL.
        self.mbx.we.next = false;
        self.mbx.counter_d.next = self.c.val();
        self.mbx.timer_d.next = self.t.val();
        self.mbx.clear.next = self.hold.val() | self.clear_state.val();
        // §4.2 settling: a recovery's clearing settles every mailbox, `hold` none
        self.mbx.settle_all.next = self.clear_state.val();
        self.mbx.settle_none.next = self.hold.val();
        self.mbx.settle_drop.next = false;
        self.mbx.owe_set.next = false;
        self.mbx.owe_drop.next = false;
        // §4.3: the sources set their flags (the newer key wins).
        if self.tx_dcl.val() {
            self.pend_tx_dcl.d.next = true;
            self.k_tx_dcl.d.next = self.key_tx_dcl.val();
        }
        if self.tx_rcl.val() {
            self.pend_tx_rcl.d.next = true;
            self.k_tx_rcl.d.next = self.key_tx_rcl.val();
        }
        if self.rx_dcl.val() {
            self.pend_rx_dcl.d.next = true;
            self.k_rx_dcl.d.next = self.key_rx_dcl.val();
        }
        if self.rx_rcl.val() {
            self.pend_rx_rcl.d.next = true;
            self.k_rx_rcl.d.next = self.key_rx_rcl.val();
        }
        if self.req_dcl.val() {
            self.pend_req_dcl.d.next = true;
            self.k_req_dcl.d.next = self.key_req_dcl.val();
        }
        if self.req_rcl.val() {
            self.pend_req_rcl.d.next = true;
            self.k_req_rcl.d.next = self.key_req_rcl.val();
        }
        if self.eval.val() {
            self.pend_eval.d.next = true;
        }
        // §4.3 the FSM.
        if self.state.q.val() == self.s_idle.val() {
            // The first set flag is taken (it clears unless set again at this
            // edge): tx DCL, tx RCL, rx DCL, rx RCL, req DCL, req RCL, eval.
            self.e_i.d.next = self.zero4.val();
            self.e_found.d.next = false;
            if self.pend_tx_dcl.q.val() {
                self.pend_tx_dcl.d.next = self.tx_dcl.val();
                self.e_kind.d.next = self.k_tx.val();
                self.e_line.d.next = false;
                self.e_key.d.next = self.k_tx_dcl.q.val();
                self.state.d.next = self.s_scan.val();
            } else if self.pend_tx_rcl.q.val() {
                self.pend_tx_rcl.d.next = self.tx_rcl.val();
                self.e_kind.d.next = self.k_tx.val();
                self.e_line.d.next = true;
                self.e_key.d.next = self.k_tx_rcl.q.val();
                self.state.d.next = self.s_scan.val();
            } else if self.pend_rx_dcl.q.val() {
                self.pend_rx_dcl.d.next = self.rx_dcl.val();
                self.e_kind.d.next = self.k_rx.val();
                self.e_line.d.next = false;
                self.e_key.d.next = self.k_rx_dcl.q.val();
                self.state.d.next = self.s_scan.val();
            } else if self.pend_rx_rcl.q.val() {
                self.pend_rx_rcl.d.next = self.rx_rcl.val();
                self.e_kind.d.next = self.k_rx.val();
                self.e_line.d.next = true;
                self.e_key.d.next = self.k_rx_rcl.q.val();
                self.state.d.next = self.s_scan.val();
            } else if self.pend_req_dcl.q.val() {
                self.pend_req_dcl.d.next = self.req_dcl.val();
                self.e_kind.d.next = self.k_req.val();
                self.e_line.d.next = false;
                self.e_key.d.next = self.k_req_dcl.q.val();
                self.state.d.next = self.s_scan.val();
            } else if self.pend_req_rcl.q.val() {
                self.pend_req_rcl.d.next = self.req_rcl.val();
                self.e_kind.d.next = self.k_req.val();
                self.e_line.d.next = true;
                self.e_key.d.next = self.k_req_rcl.q.val();
                self.state.d.next = self.s_scan.val();
            } else if self.pend_eval.q.val() {
                self.pend_eval.d.next = self.eval.val();
                self.state.d.next = self.s_eval.val();
            }
        } else if self.state.q.val() == self.s_scan.val() {
            // one mailbox per clock; the lowest match wins
            if !self.e_found.q.val() & self.hit.val() {
                self.e_found.d.next = true;
                self.e_hit.d.next = self.e_i.q.val();
            }
            if self.e_i.q.val() == self.last.val() {
                self.state.d.next = self.s_update.val();
            } else {
                self.e_i.d.next = self.e_i.q.val() + self.one4.val();
            }
        } else if self.state.q.val() == self.s_update.val() {
            // §4.1 effect on the matched mailbox: REQ loads the timer, TX/RX step
            if self.e_found.q.val() {
                self.mbx.we.next = true;
                if self.e_kind.q.val() == self.k_req.val() {
                    self.mbx.timer_d.next = self.timeout.val();
                } else {
                    self.mbx.counter_d.next = self.c_step.val();
                    self.mbx.timer_d.next = self.t_step.val();
                    // a counter back at 0 has paid its debt
                    self.mbx.owe_drop.next = self.c_step.val() == self.zero8.val();
                }
            }
            self.state.d.next = self.s_idle.val();
        } else {
            // EVAL: §4.2 for mailbox e_i (nothing if disabled)
            if self.en.val() {
                self.mbx.we.next = true;
                if self.deviation.val() | self.expired.val() {
                    // a timeout keeps the counter as the judged line's debt; a
                    // deviation or a re-balance clears it
                    if self.deviation.val() | self.rebalance.val() {
                        self.mbx.counter_d.next = self.zero8.val();
                        self.mbx.owe_drop.next = true;
                    } else {
                        self.mbx.owe_set.next = true;
                    }
                    self.mbx.timer_d.next = self.zero16.val();
                    self.mbx.settle_drop.next = true;
                } else {
                    self.mbx.timer_d.next = self.t_dec.val();
                }
            }
            if self.e_i.q.val() == self.last.val() {
                self.state.d.next = self.s_idle.val();
            } else {
                self.e_i.d.next = self.e_i.q.val() + self.one4.val();
            }
        }
        if self.hold.val() {
            self.pend_tx_dcl.d.next = false;
            self.pend_tx_rcl.d.next = false;
            self.pend_rx_dcl.d.next = false;
            self.pend_rx_rcl.d.next = false;
            self.pend_req_dcl.d.next = false;
            self.pend_req_rcl.d.next = false;
            self.pend_eval.d.next = false;
            self.state.d.next = self.s_idle.val();
            self.e_i.d.next = self.zero4.val();
            self.e_found.d.next = false;
        }
    }
}
