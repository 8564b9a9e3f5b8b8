//! The host's side of the hub model ([`super::HubModel`], hub contract §8 and
//! the commands of §7 and §9.2, Wishbone timing as DRCC contract §D.2): the
//! value a read returns (the registers that mirror guard, tracker, ACK unit and
//! NRAP state are assembled here), one Wishbone transaction, and the
//! `CTRL.force_decouple` / `CTRL.recouple` commands. A child module of `super`
//! so that it reaches the hub's state; split from `mod.rs`, which steps the hub.

use super::nrap::phase;
use super::regs::{self, idx, int, WriteEffects};
use super::HubModel;
use crate::engine::hub::HubInputs;
use crate::model::coverage;

impl HubModel {
    /// The value a Wishbone read of word `adr` returns (registers before the edge).
    pub(super) fn read(&self, adr: u8) -> u32 {
        let r = &self.regs;
        match adr {
            idx::ID => regs::id_value(self.hub_id, self.n, self.m),
            idx::CTRL => r.ctrl(),
            idx::BTR => r.btr,
            idx::GUARD_CFG => r.guard,
            idx::BF_CFG => r.bf,
            idx::RESTORE_CFG => r.restore,
            idx::STATUS => {
                r.reset_mode as u32
                    | (self.dec.decoupled as u32) << 1
                    | (self.trk.ack_window() as u32) << 2
                    | (self.trk.state as u32) << 4
                    | (self.enabled as u32) << 16
            }
            idx::INT_STATUS => r.int_status,
            idx::INT_ENABLE => r.int_enable,
            idx::STATS => self.trk.frames as u32 | (self.trk.errors as u32) << 16,
            idx::ACK_UNIT => self.ack.blocks as u32 | (self.ack.window() as u32) << 16,
            idx::NRAP_CFG => r.nrap_cfg,
            idx::NRAP_TIME => r.nrap_time,
            idx::NRAP_DDSP => r.nrap_ddsp,
            idx::NRAP_STATUS => self.nrap.status(),
            a if a >= idx::PORT0 && ((a - idx::PORT0) as usize) < self.n + self.m => {
                self.late[(a - idx::PORT0) as usize].reg()
            }
            _ => 0,
        }
    }

    /// A Wishbone transaction taken at this edge: the read data register, or the
    /// write (decided on the registers before the edge).
    #[cold]
    #[inline(never)]
    pub(super) fn wishbone(&mut self, i: &HubInputs) -> WriteEffects {
        let adr = i.wb_adr & 0x3F;
        let fx = if i.wb_we && i.wb_sel & 0xF != 0xF {
            // bus_contract.md §1: every hub word is written whole.
            coverage::hit("hub register port: a partial write is refused");
            self.regs.wb_dat = 0;
            WriteEffects {
                illegal: true,
                ..WriteEffects::default()
            }
        } else if i.wb_we {
            let before = self.regs;
            self.regs.wb_dat = 0;
            self.regs.write(&before, adr, i.wb_dat_w)
        } else {
            self.regs.wb_dat = self.read(adr);
            WriteEffects::default()
        };
        // A refused access ends with ERR instead of the ack.
        self.regs.wb_ack = !fx.illegal;
        self.regs.wb_err = fx.illegal;
        fx
    }

    /// `CTRL.force_decouple` / `CTRL.recouple` acting at this edge; returns the
    /// `INT_STATUS` events.
    #[cold]
    #[inline(never)]
    pub(super) fn command(&mut self, fx: &WriteEffects) -> u32 {
        let mut ints = 0;
        if fx.force_decouple {
            self.dec.force();
            ints |= int::DECOUPLED;
            if self.regs.nrap_on && self.nrap.command(phase::SPLIT) {
                ints |= int::NRAP;
            }
        }
        if fx.recouple {
            self.dec.recouple();
            if self.nrap.command(phase::RUN) {
                ints |= int::NRAP;
            }
            for g in self.ports[self.n..self.n + self.m].iter_mut() {
                g.enabled = true;
                g.restore_cnt = 0;
                g.silent = 0;
                g.pec = 0;
            }
            self.moved = true;
        }
        ints
    }
}
