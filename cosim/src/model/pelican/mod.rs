//! Reference model of the DRCC top generated with `host = "pelican"`: the
//! SJA1000-compatible (PeliCAN) host view of `pelican_contract.md` (included
//! below) over the DRCC core of [`crate::model::drcc`]. The view replaces only
//! the native register file: it composes the core's configuration, pushes and
//! pops through the core's host interface ([`HostDrive`]) and reads the core's
//! state back ([`crate::model::drcc::host::CoreView`]).
//!
//! Step order (a registered design): the bus access, the view's registers and
//! the core's drive of an edge are computed from the values before it (the
//! core's channel outputs of the last step); then the core makes its edge, and
//! its write-port events of that edge (overrun, `XIR` causes) are added.
//!
//! ## Interpretations (where the contract leaves a choice)
//!
//! 1. P-TX-5 self-reception: the frame of `TXB` (unchanged while `TBS = 0`) is
//!    offered to the RX writer's source `S` at the completion edge of a
//!    successful message started with `SRR`; `S` is taken after A and B when
//!    the writer is idle, and its FIFO entry's channel reads 2 (`XSTAT[7]` 0).
//! 2. P-CORE-3: an auxiliary FSM is held (in `valid`) by its channel's reset
//!    and outside redundancy mode only, so through a bus-off hold it keeps
//!    judging (a bus-off channel reads failed in `XFSM`) and raises its events.
//! 3. P-X-3/P-X-4 native window: the load and the commit are one access of the
//!    core's native register port at the edge that takes the `XWIN_*` write
//!    ([`HostDrive::native`]); the port's answer of the next edge loads the word
//!    or refuses the commit (`XIR.win` then, too).
//! 4. An `RRB` pops only while the FIFO count before the edge is not 0 and the
//!    view is in operating mode (in reset mode the core's hold empties it).
//! 5. Events that coincide with the `RM` 0 -> 1 edge lose to P-MOD-5's clearing,
//!    except `EI` (P-BO-2); an overrun there sets neither `DOS` nor `DOI`.
//! 6. In `DMR` the completion (P-TX-7) is the DMR function's `tx_done` of the
//!    previous edge (the pulse as registered by the core's `INT_STATUS`).
//! 7. A stride-1 Wishbone write with one lane selects register
//!    `{adr, l}`; a read returns the byte on all four lanes (P-BUS-2); a
//!    stride-4 read returns the byte in lane 0 only.
#![doc = include_str!("../pelican_contract.md")]

pub mod acf;
mod params;
pub mod regs;

use crate::model::drcc::{DrccModel, HostDrive, HostEvents};
use crate::model::field;
use acf::Acf;
pub use params::{mode, PelicanParams};

/// The top's inputs of one clock (P-GEN-2, Wishbone).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PelicanInputs {
    pub rst: bool,
    pub cyc: bool,
    pub stb: bool,
    pub we: bool,
    /// `wb_adr_i`: word address (7 bits at stride 4, 5 bits at stride 1).
    pub adr: u8,
    pub dat: u32,
    pub sel: u8,
    pub chan_a_rx: bool,
    pub chan_b_rx: bool,
}

impl Default for PelicanInputs {
    fn default() -> Self {
        PelicanInputs {
            rst: false,
            cyc: false,
            stb: false,
            we: false,
            adr: 0,
            dat: 0,
            sel: 0,
            chan_a_rx: true,
            chan_b_rx: true,
        }
    }
}

/// The top's outputs after an edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PelicanOutputs {
    pub dat: u32,
    pub ack: bool,
    pub err: bool,
    pub irq: bool,
    pub chan_a_tx: bool,
    pub chan_b_tx: bool,
}

/// The view's registers (§3-§13).
#[derive(Clone, Copy, Debug)]
pub(crate) struct View {
    pub hrm: bool,
    pub boh: bool,
    /// `hrm` one edge earlier: the channels' last reset edge (P-MOD-3).
    pub hrm_q: bool,
    pub lom: bool,
    pub stm: bool,
    pub afm: bool,
    pub btr0: u8,
    pub btr1: u8,
    pub ocr: u8,
    pub ewlr: u8,
    pub cdr: u8,
    pub ier: u8,
    /// `IR` register bits (RI is a level, P-IR-2).
    pub ir: u8,
    pub tbs: bool,
    pub tcs: bool,
    pub dos: bool,
    pub one_shot: bool,
    pub self_rx: bool,
    pub abort_req: bool,
    /// A listen-only start waits one edge for its completion (P-TX-6).
    pub lo_start: bool,
    pub acr: [u8; 4],
    pub amr: [u8; 4],
    pub txb: [u8; 13],
    pub scr: [u8; 3],
    pub alc: u8,
    pub ecc: u8,
    pub alc_armed: bool,
    pub ecc_armed: bool,
    pub rbsa: u8,
    pub es_q: bool,
    pub bs_q: bool,
    pub st_q: u8,
    pub xmode: u8,
    pub xk: u8,
    pub xir: u8,
    pub xier: u8,
    pub xwin_idx: u8,
    pub xwin_d: [u8; 4],
    pub xwin_refused: bool,
    /// `u` of the last clock, kept while `boh` (P-LOG-1).
    pub u_q: bool,
    /// The window made a native read (load) or write (commit) at the last edge.
    pub xwin_load_q: bool,
    pub xwin_commit_q: bool,
    pub ack: bool,
    pub err: bool,
    pub dat: u32,
    pub irq: bool,
}

impl View {
    fn reset(p: &PelicanParams, txb: [u8; 13]) -> Self {
        View {
            hrm: true,
            boh: false,
            hrm_q: true,
            lom: false,
            stm: false,
            afm: false,
            btr0: 0,
            btr1: 0x14,
            ocr: 0,
            ewlr: 96,
            cdr: 0,
            ier: 0,
            ir: 0,
            tbs: true,
            tcs: true,
            dos: false,
            one_shot: false,
            self_rx: false,
            abort_req: false,
            lo_start: false,
            acr: [0; 4],
            amr: [0xFF; 4],
            txb,
            scr: [0; 3],
            alc: 0,
            ecc: 0,
            alc_armed: true,
            ecc_armed: true,
            rbsa: 0,
            es_q: false,
            bs_q: false,
            st_q: 0,
            xmode: p.xmode(),
            xk: p.k.max(1),
            xir: 0,
            xier: 0,
            xwin_idx: 0,
            xwin_d: [0; 4],
            xwin_refused: false,
            u_q: false,
            xwin_load_q: false,
            xwin_commit_q: false,
            ack: false,
            err: false,
            dat: 0,
            irq: false,
        }
    }

    /// `RM` as read (P-GEN-3).
    pub fn rm(&self) -> bool {
        self.hrm || self.boh
    }
    pub fn mode(&self) -> u8 {
        self.xmode & 3
    }
    pub fn single(&self) -> bool {
        matches!(self.mode(), mode::SINGLE_A | mode::SINGLE_B)
    }
}

/// What the view gave the core at one edge: the core's own inputs (PeliCAN
/// contract §14), for a test that runs another core beside the model's.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CoreEdge {
    /// The edge was a reset edge.
    pub rst: bool,
    /// The CAN receive pins, A and B.
    pub rx: [bool; 2],
    /// The view's drive of the core.
    pub drive: HostDrive,
}

/// The `host = "pelican"` top, clock by clock.
#[derive(Clone, Debug)]
pub struct PelicanModel {
    pub(crate) v: View,
    core: DrccModel,
    params: PelicanParams,
    /// The core's events at the last edge.
    ev: HostEvents,
    /// The core's inputs at the last edge.
    last: CoreEdge,
}

impl PelicanModel {
    /// A top generated with `p`, in its reset state.
    pub fn new(p: PelicanParams) -> Self {
        PelicanModel {
            v: View::reset(&p, [0; 13]),
            core: DrccModel::with_params(&p.core),
            params: p,
            ev: HostEvents::default(),
            last: CoreEdge::default(),
        }
    }

    /// The generation keys.
    pub fn params(&self) -> &PelicanParams {
        &self.params
    }

    /// The core underneath (probes).
    pub fn core(&self) -> &DrccModel {
        &self.core
    }

    /// The core's inputs at the last edge.
    pub fn last_core_edge(&self) -> &CoreEdge {
        &self.last
    }

    /// The core's events at the last edge.
    pub fn core_events(&self) -> &HostEvents {
        &self.ev
    }

    /// Channel in use `u` (P-LOG-1): kept through the bus-off hold.
    pub fn u(&self) -> usize {
        if self.v.boh {
            return self.v.u_q as usize;
        }
        let c = self.core.core_view();
        match self.v.mode() {
            mode::SINGLE_A => 0,
            mode::SINGLE_B => 1,
            mode::REDUNDANCY => c.tx_channel as usize,
            _ => c.acl as usize & 1,
        }
    }

    /// Logical bus-off `lbo` (P-LOG-3).
    pub fn lbo(&self) -> bool {
        let c = self.core.core_view();
        let bo = |x: usize| c.chan[x].probes.err_state == 2;
        let u = self.u();
        if self.v.boh {
            // P-LOG-3: the held channel stays bus-off until RM is cleared
            return bo(u);
        }
        match self.v.mode() {
            mode::REDUNDANCY => {
                let policy = (self.v.xmode >> 2) & 3;
                bo(u) && (policy == 0 || c.aux[1 - u] != crate::model::drcc::regs::aux::VALID)
            }
            mode::DMR => bo(0) && bo(1),
            _ => bo(u),
        }
    }

    /// The reporting channel `r` (P-LOG-5): `u`, or with `XMODE.rep` in
    /// `REDUNDANCY` and `DMR` the other channel when it could carry the
    /// traffic and ranks better (error state, then warning), outside the hold.
    pub fn r(&self) -> usize {
        let u = self.u();
        let v = &self.v;
        let c = self.core.core_view();
        let o = 1 - u;
        let competes = v.xmode & 0x80 != 0
            && !v.boh
            && match v.mode() {
                mode::REDUNDANCY => {
                    (v.xmode >> 2) & 3 != 0 && c.aux[o] == crate::model::drcc::regs::aux::VALID
                }
                mode::DMR => true,
                _ => false,
            };
        let rank =
            |x: usize| 2 * (c.chan[x].probes.err_state & 3) + c.chan[x].diag.err_warning as u8;
        if competes && rank(o) < rank(u) {
            o
        } else {
            u
        }
    }

    /// `ES` (P-LOG-4): the reporting channel's warning.
    pub fn es(&self) -> bool {
        self.core.core_view().chan[self.r()].diag.err_warning
    }

    /// The core's drive for this edge from the view's registers before it.
    fn drive(&self, v: &View) -> HostDrive {
        let c = self.core.core_view();
        let m = if v.lom {
            1
        } else if v.stm {
            2
        } else {
            0
        };
        let mut ctrl = (v.rm() as u32) | ((v.xk & 0xF).max(1) as u32) << 8;
        let (mut reset_a, mut reset_b) = (false, false);
        match v.mode() {
            mode::SINGLE_A => {
                ctrl |= m << 12;
                reset_b = true;
            }
            mode::SINGLE_B => {
                ctrl |= m << 14;
                reset_a = true;
            }
            md => {
                ctrl |= 2 | (m << 12) | (m << 14) | ((v.xmode as u32 >> 2) & 3) << 2;
                ctrl |= ((v.xmode as u32 >> 4) & 1) << 4 | ((v.xmode as u32 >> 5) & 1) << 5;
                if md == mode::DMR && !v.lom {
                    ctrl = (ctrl & !2) | 1 << 17;
                }
            }
        }
        let brp = 2 * (v.btr0 as u32 & 0x3F) + 1;
        let btr = (brp & 0x3F)
            | (brp >> 6) << 24
            | (v.btr1 as u32 & 0xF) << 6
            | (v.btr1 as u32 >> 4 & 7) << 10
            | (v.btr0 as u32 >> 6) << 13
            | (v.btr1 as u32 >> 7) << 15
            | (v.ewlr as u32) << 16;
        let chan_reset = v.hrm || v.hrm_q;
        let qc = if v.mode() == mode::SINGLE_B { 1 } else { 0 };
        let mut tx_abort = [false; 2];
        let mut boff_hold = [false; 2];
        for x in 0..2 {
            // P-BO-3: a held bus-off channel neither counts nor keeps a frame.
            if v.boh {
                boff_hold[x] = c.chan[x].probes.err_state == 2;
                tx_abort[x] = c.chan[x].tx_pending;
            }
        }
        if v.abort_req && v.single() {
            tx_abort[qc] = true;
        }
        HostDrive {
            ctrl,
            btr,
            chan_reset: [chan_reset || reset_a, chan_reset || reset_b],
            push: None,
            pop: false,
            tx_single: v.one_shot && v.single(),
            tx_abort,
            boff_hold,
            self_frame: None,
            gate: Some(Acf {
                acr: v.acr,
                amr: v.amr,
                single: v.afm,
            }),
            native: None,
            cap_rearm: [false; 2],
        }
    }

    /// Apply `i` for one clock period, make one rising edge, return the outputs.
    pub fn step(&mut self, i: &PelicanInputs) -> PelicanOutputs {
        if i.rst {
            self.v = View::reset(&self.params, self.v.txb);
            let d = self.drive(&self.v);
            self.last = CoreEdge {
                rst: true,
                rx: [i.chan_a_rx, i.chan_b_rx],
                drive: d,
            };
            self.ev = self.core.step_host(true, [i.chan_a_rx, i.chan_b_rx], d);
            return self.outputs();
        }
        let v = self.v;
        let mut n = v;
        let mut drive = self.drive(&v);
        self.window_answer(&v, &mut n);
        self.access(i, &mut n, &mut drive);
        drive.self_frame = self.events(&mut n);
        // P-MOD-5: the edge where RM rises.
        if !v.rm() && n.rm() {
            n.tbs = true;
            n.dos = false;
            n.lo_start = false;
            n.abort_req = false;
            n.one_shot = false;
            n.self_rx = false;
            n.ir &= regs::ir::EI;
            // P-BO-2: EI of the bus-off survives.
        }
        n.hrm_q = v.hrm;
        n.u_q = self.u() == 1;
        // P-IRQ-1: the register takes IR as it is before the edge (RI with the
        // core's rx_ready before the edge).
        n.irq = (v.ir | self.ri(&v)) != 0 || v.xir & v.xier != 0;
        self.last = CoreEdge {
            rst: false,
            rx: [i.chan_a_rx, i.chan_b_rx],
            drive,
        };
        let ev = self
            .core
            .step_host(false, [i.chan_a_rx, i.chan_b_rx], drive);
        // P-RX-6: the writer drops an accepted frame on a full FIFO.
        if ev.overrun && !v.rm() && !n.rm() {
            // DOI marks the DOS 0 -> 1 edge: none while DOS was 1, a CDO of
            // the same edge notwithstanding (P-IR-4).
            if !v.dos && v.ier & regs::ier::DOIE != 0 {
                n.ir |= regs::ir::DOI;
            }
            n.dos = true;
        }
        n.xir |= regs::xir_events(ev.ints);
        self.ev = ev;
        self.v = n;
        self.outputs()
    }

    /// P-X-3, P-X-4: the native port's answer to the window's access of the
    /// last edge: a load takes the read data (0 when the port stayed idle), a
    /// commit the native rules refused sets the flag and `XIR.win`.
    fn window_answer(&self, v: &View, n: &mut View) {
        let o = self.core.outputs();
        n.xwin_load_q = false;
        n.xwin_commit_q = false;
        if v.xwin_load_q {
            n.xwin_d = o.wb_dat_r.to_le_bytes();
        }
        if v.xwin_commit_q && o.wb_err {
            n.xwin_refused = true;
            n.xir |= regs::xir::WIN;
        }
    }

    /// `RI` as a level (P-IR-2) on the registers `v`.
    fn ri(&self, v: &View) -> u8 {
        let rbs = self.core.core_view().rx_ready;
        if rbs && v.ier & regs::ier::RIE != 0 {
            regs::ir::RI
        } else {
            0
        }
    }

    /// The outputs after the last edge.
    pub fn outputs(&self) -> PelicanOutputs {
        let o = self.core.outputs();
        PelicanOutputs {
            dat: self.v.dat,
            ack: self.v.ack,
            err: self.v.err,
            irq: self.v.irq,
            chan_a_tx: o.chan_a_tx,
            chan_b_tx: o.chan_b_tx,
        }
    }

    /// `SR` (P-SR-1).
    pub fn sr(&self) -> u8 {
        let v = &self.v;
        let c = self.core.core_view();
        let u = self.u();
        let f = c.chan[u].probes.field;
        let is_tx = c.chan[u].probes.is_tx;
        let active = !matches!(
            f,
            field::INTEGRATING
                | field::IDLE
                | field::INTERMISSION
                | field::SUSPEND
                | field::BUS_OFF
        );
        // DS 6.4.5 Table 14 note 3: both set while waiting for the bus to
        // become idle (11 recessive bits after reset mode, 128 x 11 after bus-off)
        let waiting = matches!(f, field::INTEGRATING | field::BUS_OFF);
        let (rs, ts) = if v.rm() || waiting {
            (true, true)
        } else {
            (active && !is_tx, is_tx)
        };
        (c.rx_ready as u8)
            | (v.dos as u8) << 1
            | (v.tbs as u8) << 2
            | (v.tcs as u8) << 3
            | (rs as u8) << 4
            | (ts as u8) << 5
            | (self.es() as u8) << 6
            | (self.lbo() as u8) << 7
    }
}
