//! The SJA1000 view's mode and command unit (pelican_contract.md §3, §6, §7,
//! §8; SJA1000 data sheet 6.4.3 MOD, 6.4.4 CMR, 6.4.5 SR): the two reset-mode
//! registers behind `MOD.RM`, the mode bits, the transmit buffer's status and the
//! command strobes the core takes.
//!
//! - `RM = hrm | boh`: `hrm` is host reset mode (P-MOD-3), `boh` the bus-off hold
//!   (P-BO-1..6). A `MOD` write with `RM = 1` sets `hrm` unless `boh` (P-MOD-4);
//!   with `RM = 0` it clears whichever is set. A rise of `BS` in operating mode
//!   with `XMODE.bom` sets `boh`. A write while `boh` that changes a channel
//!   configuration value turns the hold into host reset mode (P-BO-6); `MOD`'s
//!   own `LOM`/`STM` are judged here, the other registers by the caller
//!   (`reconfig`).
//! - At the edge where `RM` rises (P-MOD-5): `TBS <= 1`, `DOS <= 0`, the
//!   message's one-shot, self-reception and abort latches clear.
//! - `CMR` (§6) in operating mode: `TR`/`SRR` with `TBS = 1` start a
//!   transmission (`push`, or the listen-only completion of P-TX-6); `AT` alone
//!   with `TBS = 0` is the abort of P-TX-3. `RRB` pops a non-empty FIFO, `CDO`
//!   clears `DOS`, in either mode.
//! - A completion (P-TX-7, chosen by the caller per mode): `TBS <= 1`,
//!   `TCS <= tx_ok`, the latches clear.
//!
//! Decisions where two rules meet at one edge (written in docs/pelican.md):
//! a host `RM = 1` write wins over a bus-off at the same edge (the hold is not
//! set; the host reset is the larger one), and a start at the edge where `RM`
//! rises pushes nothing (the flush of that edge would drop it anyway).

use rust_hdl::prelude::*;

/// `MOD`, `hrm`/`boh`, `TBS`/`TCS`/`DOS` and the command strobes.
#[derive(LogicBlock, Default)]
pub struct ModeControl {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: `MOD = 0x01` (host reset mode), `TBS = TCS = 1`,
    /// `DOS = 0` (data sheet 6.4.2).
    pub rst: Signal<In, Bit>,
    // ---- host writes, decoded by the register port ----
    /// A write of `MOD` is taken at this edge.
    pub mod_write: Signal<In, Bit>,
    /// A write of `CMR` is taken at this edge.
    pub cmr_write: Signal<In, Bit>,
    /// Bits [4:0] of the byte written (the `MOD` and `CMR` bits; [7:5] are
    /// unused in both).
    pub wdata: Signal<In, Bits<5>>,
    /// A write taken at this edge changes a channel configuration value other
    /// than `MOD`'s (`BTR0`, `BTR1`, `EWLR`, `XMODE`, `XK`): P-BO-6.
    pub reconfig: Signal<In, Bit>,
    // ---- configuration ----
    /// `XMODE.mode` is `SINGLE_A` or `SINGLE_B`: one-shot and abort act there
    /// only (P-TX-3, P-TX-4).
    pub single: Signal<In, Bit>,
    /// `XMODE.bom`: a bus-off enters reset mode, as the SJA1000's (P-BO-1).
    pub bom: Signal<In, Bit>,
    // ---- the logical controller and the core ----
    /// `BS` rises at this edge (`BS & !bs_q`, P-IR-5's comparison register).
    pub bs_rise: Signal<In, Bit>,
    /// The message in the core completes at this edge (P-TX-7).
    pub tx_complete: Signal<In, Bit>,
    /// With `tx_complete`: it was delivered (else a one-shot failure or abort).
    pub tx_ok: Signal<In, Bit>,
    /// The RX writer loses an accepted frame at this edge, the FIFO full (P-RX-6).
    pub overrun: Signal<In, Bit>,
    /// The RX FIFO holds a frame (`RBS`).
    pub rx_ready: Signal<In, Bit>,
    // ---- registers as read ----
    /// `MOD` as read: [0] `RM`, [1] `LOM`, [2] `STM`, [3] `AFM`, [4] `SM` (0).
    pub mod_q: Signal<Out, Bits<8>>,
    /// `MOD.RM` (`hrm | boh`).
    pub rm: Signal<Out, Bit>,
    /// Host reset mode.
    pub hrm: Signal<Out, Bit>,
    /// Bus-off hold.
    pub boh: Signal<Out, Bit>,
    /// The channels' reset: `hrm` and one clock after it falls, so the channels
    /// take the configuration written by the write that clears it (P-MOD-3).
    pub chan_reset: Signal<Out, Bit>,
    /// Listen-only mode (`MOD.LOM`).
    pub lom: Signal<Out, Bit>,
    /// Self-test mode (`MOD.STM`).
    pub stm: Signal<Out, Bit>,
    /// Acceptance filter mode (`MOD.AFM`: 1 = single filter).
    pub afm: Signal<Out, Bit>,
    /// `SR.TBS`: the transmit buffer is free.
    pub tbs: Signal<Out, Bit>,
    /// `SR.TCS`: the last message was delivered.
    pub tcs: Signal<Out, Bit>,
    /// `SR.DOS`: a frame was lost, the FIFO full.
    pub dos: Signal<Out, Bit>,
    // ---- strobes and latches for the core ----
    /// `RM` rises at this edge (P-MOD-5: the interrupt register clears).
    pub rm_rise: Signal<Out, Bit>,
    /// Push the transmit buffer's frame into the TX queue at this edge (P-TX-2).
    pub push: Signal<Out, Bit>,
    /// Pop the RX FIFO's head at this edge (`CMR.RRB`, P-CMR-4).
    pub pop: Signal<Out, Bit>,
    /// The message in the core is one-shot (`CMR.AT` with `TR`, P-TX-4).
    pub one_shot: Signal<Out, Bit>,
    /// The message in the core is self-received (`CMR.SRR`, P-TX-5).
    pub self_rx: Signal<Out, Bit>,
    /// The host aborts the message in the core (`CMR.AT` alone, P-TX-3).
    pub abort_req: Signal<Out, Bit>,
    /// Offer the completed frame to the RX writer at this edge (P-TX-5).
    pub self_offer: Signal<Out, Bit>,
    /// `TBS` rises by a completion at this edge (the `TI` event, P-IR-4).
    pub ti_evt: Signal<Out, Bit>,
    /// `DOS` rises at this edge (the `DOI` event).
    pub doi_evt: Signal<Out, Bit>,
    /// A write the SJA1000 would carry out and this view does not (`XIR.ign`):
    /// one-shot or abort outside the single modes, `MOD.SM = 1` (P-MOD-7).
    pub ign_evt: Signal<Out, Bit>,
    // ---- registers ----
    hrm_q: DFF<Bit>,
    hrm_d: DFF<Bit>,
    boh_q: DFF<Bit>,
    lom_q: DFF<Bit>,
    stm_q: DFF<Bit>,
    afm_q: DFF<Bit>,
    tbs_q: DFF<Bit>,
    tcs_q: DFF<Bit>,
    dos_q: DFF<Bit>,
    one_shot_q: DFF<Bit>,
    self_q: DFF<Bit>,
    abort_q: DFF<Bit>,
    /// A start in listen-only mode completes at the next edge (P-TX-6).
    lom_done: DFF<Bit>,
    // ---- next state ----
    hrm_n: Signal<Local, Bit>,
    boh_n: Signal<Local, Bit>,
    rm_now: Signal<Local, Bit>,
    start: Signal<Local, Bit>,
    abort: Signal<Local, Bit>,
}

impl Logic for ModeControl {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, hrm_q, hrm_d, boh_q, lom_q, stm_q, afm_q, tbs_q, tcs_q, dos_q, one_shot_q,
            self_q, abort_q, lom_done
        );
        self.rm_now.next = self.hrm_q.q.val() | self.boh_q.q.val();

        // ---- MOD: the two reset-mode registers (P-MOD-2..4, P-BO-1, P-BO-6) ----
        self.hrm_n.next = self.hrm_q.q.val();
        self.boh_n.next = self.boh_q.q.val();
        if self.mod_write.val() {
            if self.wdata.val().get_bit(0) {
                // RM = 1 while the hold is on changes nothing (P-MOD-4)
                if !self.boh_q.q.val() {
                    self.hrm_n.next = true;
                }
            } else {
                self.hrm_n.next = false;
                self.boh_n.next = false;
            }
        }
        // a reconfiguration while the hold is on is a restart (P-BO-6)
        if self.boh_q.q.val()
            && (self.reconfig.val()
                | (self.mod_write.val()
                    & ((self.wdata.val().get_bit(1) != self.lom_q.q.val())
                        | (self.wdata.val().get_bit(2) != self.stm_q.q.val()))))
        {
            self.boh_n.next = false;
            self.hrm_n.next = true;
        }
        if self.bs_rise.val() && self.bom.val() && !self.rm_now.val() && !self.hrm_n.val() {
            self.boh_n.next = true;
        }
        self.hrm_q.d.next = self.hrm_n.val();
        self.boh_q.d.next = self.boh_n.val();
        self.hrm_d.d.next = self.hrm_q.q.val();
        self.rm_rise.next = (self.hrm_n.val() | self.boh_n.val()) & !self.rm_now.val();
        // mode bits: written in reset mode only, also by the write leaving it
        if self.mod_write.val() && self.rm_now.val() {
            self.lom_q.d.next = self.wdata.val().get_bit(1);
            self.stm_q.d.next = self.wdata.val().get_bit(2);
            self.afm_q.d.next = self.wdata.val().get_bit(3);
        }

        // ---- CMR: transmit commands in operating mode (P-CMR-1..3) ----
        self.start.next = self.cmr_write.val()
            & !self.rm_now.val()
            & self.tbs_q.q.val()
            & (self.wdata.val().get_bit(0) | self.wdata.val().get_bit(4));
        self.abort.next = self.cmr_write.val()
            & !self.rm_now.val()
            & !self.tbs_q.q.val()
            & self.wdata.val().get_bit(1)
            & !self.wdata.val().get_bit(0)
            & !self.wdata.val().get_bit(4);
        // a push at the edge where RM rises reaches the core, which the hold
        // empties at the next edge (P-MOD-5)
        self.push.next = self.start.val() & !self.lom_q.q.val();
        self.lom_done.d.next = self.start.val() & self.lom_q.q.val();
        if self.start.val() {
            self.tbs_q.d.next = false;
            self.tcs_q.d.next = false;
            // P-TX-6: a listen-only start latches no one-shot and no self-reception
            if !self.lom_q.q.val() {
                self.one_shot_q.d.next = self.wdata.val().get_bit(1) & self.single.val();
                self.self_q.d.next = self.wdata.val().get_bit(4);
            }
        }
        if self.abort.val() && self.single.val() {
            self.abort_q.d.next = true;
        }
        self.ign_evt.next = (self.start.val()
            & !self.lom_q.q.val()
            & self.wdata.val().get_bit(1)
            & !self.single.val())
            | (self.abort.val() & !self.single.val())
            | (self.mod_write.val() & self.wdata.val().get_bit(4));

        // ---- completion (P-TX-6, P-TX-7) ----
        self.self_offer.next = self.tx_complete.val() & self.tx_ok.val() & self.self_q.q.val();
        self.ti_evt.next = self.tx_complete.val() | self.lom_done.q.val();
        if self.lom_done.q.val() {
            self.tbs_q.d.next = true;
        }
        if self.tx_complete.val() {
            self.tbs_q.d.next = true;
            self.tcs_q.d.next = self.tx_ok.val();
            self.one_shot_q.d.next = false;
            self.self_q.d.next = false;
            self.abort_q.d.next = false;
        }

        // ---- receive buffer: RRB, CDO, overrun (P-CMR-4, P-CMR-5, P-RX-6) ----
        self.pop.next = self.cmr_write.val() & self.wdata.val().get_bit(2) & self.rx_ready.val();
        if self.cmr_write.val() && self.wdata.val().get_bit(3) {
            self.dos_q.d.next = false;
        }
        if self.overrun.val() {
            self.dos_q.d.next = true;
        }
        self.doi_evt.next = self.overrun.val() & !self.dos_q.q.val();

        // ---- entering reset mode (P-MOD-5) ----
        if self.rm_rise.val() {
            self.tbs_q.d.next = true;
            self.dos_q.d.next = false;
            self.one_shot_q.d.next = false;
            self.self_q.d.next = false;
            self.abort_q.d.next = false;
            self.lom_done.d.next = false;
        }

        if self.rst.val() {
            self.hrm_q.d.next = true;
            self.hrm_d.d.next = true;
            self.boh_q.d.next = false;
            self.lom_q.d.next = false;
            self.stm_q.d.next = false;
            self.afm_q.d.next = false;
            self.tbs_q.d.next = true;
            self.tcs_q.d.next = true;
            self.dos_q.d.next = false;
            self.one_shot_q.d.next = false;
            self.self_q.d.next = false;
            self.abort_q.d.next = false;
            self.lom_done.d.next = false;
        }

        // ---- outputs ----
        self.rm.next = self.rm_now.val();
        self.hrm.next = self.hrm_q.q.val();
        self.boh.next = self.boh_q.q.val();
        self.chan_reset.next = self.hrm_q.q.val() | self.hrm_d.q.val();
        self.lom.next = self.lom_q.q.val();
        self.stm.next = self.stm_q.q.val();
        self.afm.next = self.afm_q.q.val();
        self.tbs.next = self.tbs_q.q.val();
        self.tcs.next = self.tcs_q.q.val();
        self.dos.next = self.dos_q.q.val();
        self.one_shot.next = self.one_shot_q.q.val();
        self.self_rx.next = self.self_q.q.val();
        self.abort_req.next = self.abort_q.q.val();
        self.mod_q.next = (bit_cast::<8, 1>(self.afm_q.q.val().into()) << 3)
            | (bit_cast::<8, 1>(self.stm_q.q.val().into()) << 2)
            | (bit_cast::<8, 1>(self.lom_q.q.val().into()) << 1)
            | bit_cast::<8, 1>(self.rm_now.val().into());
    }
}
