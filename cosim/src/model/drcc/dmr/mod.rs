//! DMR mode of the DRCC (`dmr_contract.md`, included below; CiA 701 as described in
//! seed 001): the third DRCC mode, `CTRL.dmr = 1`. This file holds the block's
//! registers (§2), the time base (§3) and the order of one edge; the mailboxes
//! ([`mailboxes`], §4.1-4.2), the engine ([`engine`], §4.3), the transmission
//! ([`tx`], §5) and the state machine with the connection service and recovery
//! ([`recovery`], §6-7) live in their own files. Reception (§8) is the RX path's
//! DMR rule (`super::rx_path`).
//!
//! ## Interpretations (where the contract leaves a choice)
//!
//! 1. Outside DMR mode and in reset mode the block is held in its reset-mode state
//!    (everything §2.1 says clears in reset mode, `cs_due = 1`); clearing
//!    `dmr_state` / `acl` there is not a change (no interrupt, no count).
//! 2. Several faults at one edge: `cause` is written in the order CS failed,
//!    bus-off, evaluation (the last one written stays); `cause_mb` only by an
//!    evaluation.
//! 3. A line's CS request also waits while its restart is pending (`free[L]`
//!    includes `!rec_pending[L]`); otherwise the request of the recovery tick and
//!    the restart pulse leave at the same edge and the channel reset swallows the
//!    request (§7 vs §5).
//! 4. `MB_SEL`, `MB_ID`, `MB_MASK`, `MB_CFG` with `M = 0`: every write is refused
//!    (`illegal`), the window reads 0. `MB_SEL` takes `[3:0]`.
//! 5. A CS fault and a CS success of the same line at one edge: the fault wins.
//! 6. Literal §5: a host request issued at the edge where a tx fault is set
//!    against the same line still leaves (its `abort` is computed from the
//!    pre-edge `busy`), and a restart pulse due at the edge of a fault still fires.
//! 7. §8 (in `super::rx_path`): a PCL copy that hits an entry of the ACL still
//!    waiting for its release does not mark it used (else that frame is never
//!    released); the `RSCAN` decision at `scan_i = 32` includes entry 31 judged
//!    at that edge.
#![doc = include_str!("../../dmr_contract.md")]

pub mod engine;
pub mod mailboxes;
pub mod recovery;
pub mod tx;

use super::regs::dmr::*;
use super::regs::idx;
use crate::frame::Frame;
use engine::{Engine, Raised};
use mailboxes::{Key, Mailboxes};

/// What the DMR block samples at an edge (pre-edge values).
#[derive(Clone, Copy, Debug, Default)]
pub struct DmrInputs {
    /// `CTRL.dmr` and not reset mode.
    pub running: bool,
    /// The nominal bit tick (§D.4.3).
    pub tick: bool,
    /// `reset_mode_q` (part of both channels' `rst`, §D.6).
    pub reset_mode_q: bool,
    // Per line (0 DCL = channel A, 1 RCL = channel B): the channel's registered outputs.
    pub done: [bool; 2],
    pub failed: [bool; 2],
    pub rx_valid: [bool; 2],
    pub rx_frame: [Frame; 2],
    pub err_state: [u8; 2],
    /// TX queue A: count, the RAM read data register, the read-port select.
    pub q_count: u8,
    pub rd: Frame,
    pub rd_sel: u8,
}

/// What the DMR block did at an edge.
#[derive(Clone, Copy, Debug, Default)]
pub struct DmrEvents {
    /// Entries queue A frees behind both lines (§5).
    pub pop: u8,
    /// `INT_STATUS.tx_done`: the first copy of a message (§5).
    pub tx_done: bool,
    /// `INT_STATUS.dmr`: `dmr_state` or `acl` changed (§2.1).
    pub int: bool,
    /// An ACL switch (§6): the RX path starts releasing (§8).
    pub acl_switch: bool,
    /// A received frame that is not a CS frame: it goes to the RX path (§7, §8).
    pub rx_deliver: [bool; 2],
}

/// The DMR block.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DmrBlock {
    // Configuration (§2.1).
    pub cfg: u32,
    pub time: u32,
    pub cs: u32,
    pub mb_sel: u8,
    pub mbx: Mailboxes,
    pub eng: Engine,
    // Time base (§3).
    pub tb_cnt: u16,
    pub dmr_tick: bool,
    // Transmission (§5), per line.
    pub off: [u8; 2],
    pub req: [bool; 2],
    pub busy: [bool; 2],
    pub cs_req: [bool; 2],
    pub cs_busy: [bool; 2],
    pub cs_live: [bool; 2],
    pub cs_due: [bool; 2],
    pub cs_timer: [u16; 2],
    pub abort: [bool; 2],
    pub key_sent: [Key; 2],
    // State machine, connection service, recovery (§6, §7).
    pub tx_fault: [bool; 2],
    pub rx_fault: [bool; 2],
    pub acl: u8,
    pub dmr_state: u8,
    pub cause: u8,
    pub cause_line: u8,
    pub cause_mb: u8,
    pub rec_timer: [u16; 2],
    pub rec_pending: [bool; 2],
    pub restart: [bool; 2],
    pub period_cnt: u16,
    /// The channel was bus-off at the previous edge.
    pub busoff_q: [bool; 2],
    // Statistics, cleared only by `rst`.
    pub state_changes: u8,
    pub acl_switches: u8,
    /// DCL good, DCL bad, RCL good, RCL bad.
    pub cs_count: [u8; 4],
    /// Not a register: the block is in its held state ([`Self::hold`] ran and
    /// neither an edge in DMR mode nor `rst` came since), so holding again
    /// changes only `busoff_q`. Spares a node outside DMR mode the whole hold
    /// at every clock.
    held: bool,
}

impl DmrBlock {
    /// The block after `rst` with `m` mailboxes (generation parameter `M`).
    pub fn new(m: usize) -> Self {
        DmrBlock {
            cfg: CFG_RESET,
            time: TIME_RESET,
            cs: CS_RESET,
            mb_sel: 0,
            mbx: Mailboxes::new(m),
            eng: Engine::default(),
            tb_cnt: 0,
            dmr_tick: false,
            off: [0; 2],
            req: [false; 2],
            busy: [false; 2],
            cs_req: [false; 2],
            cs_busy: [false; 2],
            cs_live: [false; 2],
            cs_due: [true; 2],
            cs_timer: [0; 2],
            abort: [false; 2],
            key_sent: [Key::default(); 2],
            tx_fault: [false; 2],
            rx_fault: [false; 2],
            acl: 0,
            dmr_state: ACTIVE,
            cause: 0,
            cause_line: 0,
            cause_mb: 0,
            rec_timer: [0; 2],
            rec_pending: [false; 2],
            restart: [false; 2],
            period_cnt: 0,
            busoff_q: [false; 2],
            state_changes: 0,
            acl_switches: 0,
            cs_count: [0; 4],
            held: false,
        }
    }

    /// A `rst` edge: every register clears; the mailbox identifier memory stays.
    pub fn rst(&mut self) {
        let mut mbx = self.mbx.clone();
        mbx.rst();
        *self = DmrBlock {
            mbx,
            ..DmrBlock::new(0)
        };
    }

    /// `DMR_CFG.timeout`: mailbox and CS timeout, DMR ticks.
    pub fn timeout(&self) -> u16 {
        self.cfg as u16
    }
    fn cs_period(&self) -> u16 {
        (self.cfg >> 16) as u16
    }
    fn tick_bits(&self) -> u16 {
        self.time as u16
    }
    fn recovery_delay(&self) -> u16 {
        (self.time >> 16) as u16
    }
    /// `cs_id[L]`: the base identifier of the connection service on line L.
    pub fn cs_id(&self, l: usize) -> u32 {
        (self.cs >> (16 * l)) & 0x7FF
    }

    /// The CS frame of line `l` (§7): base format, `cs_id[l]`, DLC 0, data frame.
    pub fn cs_frame(&self, l: usize) -> Frame {
        Frame {
            id: self.cs_id(l),
            ..Frame::default()
        }
    }

    /// The channel `tx_req` of line `l` (§5).
    pub fn tx_req(&self, l: usize) -> bool {
        self.req[l] || self.cs_req[l]
    }

    /// Hold the reset-mode state (reset mode, or a mode other than DMR).
    fn hold(&mut self, i: &DmrInputs) {
        // Idempotent but for `busoff_q`: while held, only `write` changes the
        // block, and only fields the hold keeps (configuration, identifier memory).
        if self.held {
            self.busoff_q = [i.err_state[0] == 2, i.err_state[1] == 2];
            return;
        }
        let keep = DmrBlock {
            cfg: self.cfg,
            time: self.time,
            cs: self.cs,
            mb_sel: self.mb_sel,
            // moved, not cloned: this runs at every clock outside DMR mode
            mbx: std::mem::replace(&mut self.mbx, Mailboxes { mb: Vec::new() }),
            state_changes: self.state_changes,
            acl_switches: self.acl_switches,
            cs_count: self.cs_count,
            busoff_q: [i.err_state[0] == 2, i.err_state[1] == 2],
            ..DmrBlock::new(0)
        };
        *self = keep;
        self.mbx.clear_state();
        self.held = true;
    }

    /// A frame of the connection service (§7): `ide = 0`, `rtr = 0`, `dlc = 0`,
    /// identifier `cs_id_dcl` or `cs_id_rcl`.
    pub fn is_cs_frame(&self, f: &Frame) -> bool {
        !f.ide && !f.rtr && f.dlc == 0 && (f.id == self.cs_id(0) || f.id == self.cs_id(1))
    }

    /// One edge (not `rst`).
    pub fn edge(&mut self, i: &DmrInputs) -> DmrEvents {
        if !i.running {
            self.hold(i);
            return DmrEvents::default();
        }
        self.held = false;
        let c = self.clone();
        let mut ev = DmrEvents::default();
        // §3 time base: `dmr_tick` pulses when `tb_cnt` wraps at a bit tick.
        self.dmr_tick = false;
        if i.tick {
            if c.tb_cnt >= c.tick_bits().wrapping_sub(1) {
                self.tb_cnt = 0;
                self.dmr_tick = true;
            } else {
                self.tb_cnt = c.tb_cnt + 1;
            }
        }
        let mut raised = Raised {
            eval: c.dmr_tick,
            ..Raised::default()
        };
        // §7 reception of CS frames (counted, never an RX event nor host frame);
        // every other frame is an `RX(L)` event (§4.1) and goes to the RX path.
        for l in 0..2 {
            if !i.rx_valid[l] {
                continue;
            }
            let f = &i.rx_frame[l];
            if c.is_cs_frame(f) {
                let bad = (f.id != c.cs_id(l)) as usize;
                let n = &mut self.cs_count[2 * l + bad];
                *n = n.saturating_add(1);
            } else {
                ev.rx_deliver[l] = true;
                raised.rx[l] = Some(Key::of(f));
            }
        }
        // §5 requests and completions (pre-edge values).
        let inc = self.tx_requests(&c, i, &mut raised, &mut ev);
        // §4.3 the engine.
        let timeout = c.timeout();
        let fault = self.eng.edge(&raised, &mut self.mbx, timeout);
        // §6, §7 faults, connection service, recovery.
        let tx_set = self.faults(&c, i, fault, &mut ev);
        // §5 offsets: deletion, return, the queue leaves behind.
        ev.pop = self.tx_offsets(&c, inc, tx_set);
        ev
    }

    /// Wishbone read of a DMR register (`None`: not a DMR register). `rx_stats` is
    /// `DMR_RX_STATS`, kept by the RX path.
    pub fn read(&self, adr: u8, reset_mode: bool, rx_stats: u32) -> Option<u32> {
        let mb = self.mbx.mb.get(self.mb_sel as usize);
        let window = |f: fn(&mailboxes::Mailbox) -> u32| match mb {
            Some(b) if reset_mode => f(b),
            _ => 0,
        };
        Some(match adr {
            idx::DMR_CFG => self.cfg,
            idx::DMR_TIME => self.time,
            idx::DMR_CS => self.cs,
            idx::DMR_STATUS => {
                self.dmr_state as u32
                    | (self.acl as u32) << 2
                    | (self.tx_fault[0] as u32) << 3
                    | (self.rx_fault[0] as u32) << 4
                    | (self.tx_fault[1] as u32) << 5
                    | (self.rx_fault[1] as u32) << 6
                    | (self.cause as u32) << 8
                    | (self.cause_line as u32) << 10
                    | (self.cause_mb as u32 & 0xF) << 12
                    | (self.state_changes as u32) << 16
                    | (self.acl_switches as u32) << 24
            }
            idx::DMR_CS_COUNT => u32::from_le_bytes(self.cs_count),
            idx::DMR_RX_STATS => rx_stats,
            idx::MB_SEL => self.mb_sel as u32,
            // The identifier memory's read port belongs to the engine while it runs.
            idx::MB_ID => window(|b| b.id_reg()),
            idx::MB_MASK => window(|b| b.mask & 0x1FFF_FFFF),
            idx::MB_CFG => window(|b| b.cfg_reg()),
            idx::MB_STATE => mb.map(|b| b.state_reg()).unwrap_or(0),
            _ => return None,
        })
    }

    /// Wishbone write of a DMR register (`None`: not a DMR register); `Some(false)`:
    /// refused, `INT_STATUS.illegal` (§2.2). Applied after this edge's [`Self::edge`]
    /// (the configuration only changes in reset mode, where the block is held).
    pub fn write(&mut self, adr: u8, d: u32, reset_mode: bool) -> Option<bool> {
        let m = self.mbx.m();
        let sel = self.mb_sel as usize;
        let is_cs_id = |s: &Self, ide: bool, id: u32| {
            !ide && (id & 0x7FF == s.cs_id(0) || id & 0x7FF == s.cs_id(1))
        };
        let cfg_ok = reset_mode;
        Some(match adr {
            idx::DMR_CFG => {
                let ok = cfg_ok && d & 0xFFFF != 0;
                if ok {
                    self.cfg = d;
                }
                ok
            }
            idx::DMR_TIME => {
                let ok = cfg_ok && d & 0xFFFF != 0 && d >> 16 != 0;
                if ok {
                    self.time = d;
                }
                ok
            }
            idx::DMR_CS => {
                let w = d & CS_DEFINED;
                let ok = cfg_ok && w & 0x7FF != w >> 16 && !self.mbx.any_enabled();
                if ok {
                    self.cs = w;
                }
                ok
            }
            idx::MB_SEL => {
                let s = (d & 0xF) as usize;
                let ok = s < m;
                if ok {
                    self.mb_sel = s as u8;
                }
                ok
            }
            idx::MB_ID => {
                let w = d & MB_ID_DEFINED;
                let ok = cfg_ok
                    && sel < m
                    && !(self.mbx.mb[sel].enable
                        && is_cs_id(self, w & MB_IDE != 0, w & 0x1FFF_FFFF));
                if ok {
                    let b = &mut self.mbx.mb[sel];
                    b.id = w & 0x1FFF_FFFF;
                    b.ide = w & MB_IDE != 0;
                    b.dir = w & MB_DIR != 0;
                }
                ok
            }
            idx::MB_MASK => {
                let ok = cfg_ok && sel < m;
                if ok {
                    self.mbx.mb[sel].mask = d & 0x1FFF_FFFF;
                }
                ok
            }
            idx::MB_CFG => {
                let en = d & MB_ENABLE != 0;
                let limit = (d & MB_LIMIT_MASK) as u8;
                let ok = cfg_ok
                    && sel < m
                    && !(en && limit == 0)
                    && !(en && is_cs_id(self, self.mbx.mb[sel].ide, self.mbx.mb[sel].id));
                if ok {
                    let b = &mut self.mbx.mb[sel];
                    b.limit = limit;
                    b.enable = en;
                }
                ok
            }
            // DMR_STATUS, DMR_CS_COUNT, DMR_RX_STATS, MB_STATE: read-only.
            idx::DMR_STATUS | idx::DMR_CS_COUNT | idx::DMR_RX_STATS | idx::MB_STATE => false,
            _ => return None,
        })
    }
}
