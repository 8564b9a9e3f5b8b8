//! ECSS bus selection (DRCC contract §12, ECSS-E-ST-50-15C / CANopen object
//! 2000h): the registers `ECSS_CFG`, `ECSS_HB`, `ECSS_PERIOD` (cfg, §12.1) and
//! `ECSS_STATUS`, and the selection of §12.2. A node uses the bus on which it
//! hears the redundancy master's heartbeat; after `ttoggle` heartbeat periods
//! without one it toggles to the other bus, at most `ntoggle` times in a row,
//! then gives up (`no_master`) until a heartbeat comes back. In redundancy mode
//! with `enable` the selected bus is the main FSM's channel validity
//! (`VA = !bus`, `VB = bus`).

use super::regs::{ecss as f, frame_id, idx};
use crate::frame::Frame;

/// The three cfg registers (§12.1), as stored: always legal values (a write that
/// would store an illegal one is refused as a whole).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EcssCfg {
    /// `ECSS_CFG`: ttoggle, ntoggle, bdefault, enable.
    pub cfg: u32,
    /// `ECSS_HB`: the heartbeat's id and ide.
    pub hb: u32,
    /// `ECSS_PERIOD`: the heartbeat period in nominal bit times.
    pub period: u32,
}

impl Default for EcssCfg {
    /// The reset values: ttoggle 3, ntoggle 3, bdefault A, disabled; heartbeat
    /// 0x701 base; period 100000.
    fn default() -> Self {
        EcssCfg {
            cfg: f::CFG_RESET,
            hb: f::HB_RESET,
            period: f::PERIOD_RESET,
        }
    }
}

impl EcssCfg {
    pub fn enable(&self) -> bool {
        self.cfg & f::ENABLE != 0
    }
    fn ttoggle(&self) -> u32 {
        self.cfg & f::TTOGGLE_MASK
    }
    fn ntoggle(&self) -> u32 {
        (self.cfg >> f::NTOGGLE_SHIFT) & 0xFF
    }
    fn bdefault(&self) -> bool {
        self.cfg & f::BDEFAULT != 0
    }

    /// A write of `d` to cfg word `adr` (one of `ECSS_CFG`..`ECSS_PERIOD`):
    /// stored iff in reset mode and the value is legal (§12.1, §9). Returns
    /// whether it was taken (false: `INT_STATUS.illegal`).
    pub fn write(&mut self, adr: u8, d: u32, reset_mode: bool) -> bool {
        let legal = match adr {
            idx::ECSS_CFG => d & f::TTOGGLE_MASK != 0 && d & f::CFG_RESERVED == 0,
            idx::ECSS_HB => d & f::HB_RESERVED == 0,
            idx::ECSS_PERIOD => d & f::PERIOD_MASK != 0 && d & !f::PERIOD_MASK == 0,
            _ => false,
        };
        if !(reset_mode && legal) {
            return false;
        }
        match adr {
            idx::ECSS_CFG => self.cfg = d,
            idx::ECSS_HB => self.hb = d,
            _ => self.period = d,
        }
        true
    }

    /// A heartbeat: a received data frame with `ide` = `ECSS_HB.ide` and the
    /// identifier `ECSS_HB.id` (11 bits compared for a base frame, 29 for an
    /// extended one).
    fn heartbeat(&self, rx_valid: bool, fr: &Frame) -> bool {
        let ide = self.hb & f::HB_IDE != 0;
        let id_mask = if ide { frame_id::ID_MASK } else { 0x7FF };
        rx_valid && !fr.rtr && fr.ide == ide && (fr.id ^ self.hb) & id_mask == 0
    }
}

/// The selection's registers (§12.2).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Selection {
    /// The bus in use: false = A, true = B.
    pub bus: bool,
    /// Nominal bit times in the current heartbeat period (24 bits).
    pub hb_cnt: u32,
    /// Heartbeat periods missed since the last heartbeat or toggle.
    pub missed: u8,
    /// Toggles since the last heartbeat on the bus in use.
    pub run: u8,
    /// Every toggle (saturating 255); cleared by `rst` and `STATS_CLR` only.
    pub ctoggle: u8,
    /// The node gave up toggling (`run` reached `ntoggle`).
    pub no_master: bool,
}

impl Selection {
    /// `ECSS_STATUS`.
    pub fn status(&self) -> u32 {
        self.ctoggle as u32
            | if self.bus { f::BUS } else { 0 }
            | if self.no_master { f::NO_MASTER } else { 0 }
            | (self.missed as u32) << f::MISSED_SHIFT
    }

    /// A toggle: the other bus, counted; a new heartbeat period.
    fn toggle(&mut self) {
        self.bus = !self.bus;
        self.ctoggle = self.ctoggle.saturating_add(1);
        self.hb_cnt = 0;
        self.missed = 0;
    }

    /// One edge, on the values before it: `on` = `CTRL.redundancy &&
    /// ECSS_CFG.enable && !reset_mode`, `tick` the nominal bit tick (§4.3), the
    /// channels' `rx_valid` / `rx_frame`. Returns whether `INT_STATUS.bus_toggle`
    /// is set at this edge (a toggle, or `no_master` rising).
    pub fn edge(
        &mut self,
        c: &EcssCfg,
        on: bool,
        tick: bool,
        rx_valid: [bool; 2],
        frames: [&Frame; 2],
    ) -> bool {
        if !on {
            *self = Selection {
                bus: c.bdefault(),
                ctoggle: self.ctoggle,
                ..Selection::default()
            };
            return false;
        }
        let hb = [0, 1].map(|x| c.heartbeat(rx_valid[x], frames[x]));
        let (here, other) = (hb[self.bus as usize], hb[!self.bus as usize]);
        if here {
            // 1. The master heard on the bus in use: a new period, the bound re-armed.
            self.hb_cnt = 0;
            self.missed = 0;
            self.run = 0;
            self.no_master = false;
            false
        } else if self.no_master && other {
            // 2. Given up, and the master is heard on the other bus: go there.
            self.toggle();
            self.run = 0;
            self.no_master = false;
            true
        } else if self.no_master {
            false
        } else if self.hb_cnt >= c.period {
            // 3. A heartbeat period missed (on registered values: the edge
            // after the tick that completed it).
            self.hb_cnt = 0;
            if (self.missed as u32) + 1 < c.ttoggle() {
                self.missed += 1;
                return false;
            }
            self.missed = 0;
            if (self.run as u32) < c.ntoggle() {
                self.toggle();
                self.run += 1;
            } else {
                self.no_master = true;
            }
            true
        } else {
            // 4. One more bit time of the period, at each tick.
            if tick {
                self.hb_cnt += 1;
            }
            false
        }
    }
}

/// The ECSS block: its cfg registers and the selection.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Ecss {
    pub cfg: EcssCfg,
    pub sel: Selection,
}

impl Ecss {
    /// The value a read of word `adr` returns, if it is an ECSS word.
    pub fn read(&self, adr: u8) -> Option<u32> {
        match adr {
            idx::ECSS_CFG => Some(self.cfg.cfg),
            idx::ECSS_HB => Some(self.cfg.hb),
            idx::ECSS_PERIOD => Some(self.cfg.period),
            idx::ECSS_STATUS => Some(self.sel.status()),
            _ => None,
        }
    }

    /// The main FSM's channel validity `(VA, VB)` from the selection while it
    /// replaces the auxiliary FSMs' (`CTRL.redundancy && ECSS_CFG.enable`).
    pub fn validity(&self, redundancy: bool) -> Option<(bool, bool)> {
        (redundancy && self.cfg.enable()).then_some((!self.sel.bus, self.sel.bus))
    }
}
