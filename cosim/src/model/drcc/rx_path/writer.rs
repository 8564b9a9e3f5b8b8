//! The RX path's writer FSM (contract §7, dmr_contract.md §8), one method per
//! state: `IDLE` takes a pending reception, `SCAN` reads the history for a copy
//! and a free entry, `DECIDE` judges the frame (first-copy rule, or the ACL rule
//! in DMR mode), `RSCAN`, `FETCH` and `RELEASE` release the oldest waiting frame
//! of the new ACL, and `WRITE` writes the FIFO and the history. Every state reads
//! the registers before the edge (`RxRegs`) and writes those after it.

use super::{
    HistEntry, RxEvents, RxInputs, RxPath, RxRegs, W_DECIDE, W_FETCH, W_IDLE, W_RSCAN, W_SCAN,
    W_WRITE,
};
use crate::frame::Frame;
use crate::model::coverage;
use crate::model::drcc::features::Filters;

impl RxPath {
    /// Expiry of a history entry; under the ACL rule an undelivered, unmatched
    /// one counts in `expired` (§8).
    fn expire(&mut self, c: &RxRegs, acl_rule: bool, bit: u32) {
        self.hv &= !bit;
        if acl_rule && c.hu & bit == 0 && c.hd & bit == 0 {
            self.expired = c.expired.saturating_add(1);
        }
    }

    /// `IDLE`: take a pending reception (A before B), else a pending frame of
    /// source S, else start a release scan.
    pub(super) fn writer_idle(
        &mut self,
        i: &RxInputs,
        c: &RxRegs,
        acl_rule: bool,
        s_pend: Option<Frame>,
        offer: Option<Frame>,
    ) {
        if c.rxp[0] || c.rxp[1] {
            let s = if c.rxp[0] { 0 } else { 1 };
            self.sel = s as u8;
            // A new rx_valid at this edge sets it again (set wins).
            self.rxp[s] = i.rx_valid[s];
            self.hist_idle = 0;
            self.w_state = if i.dedup_on {
                W_SCAN
            } else if acl_rule {
                W_DECIDE
            } else {
                W_WRITE
            };
            // Outside DMR mode every frame goes to the FIFO (§D.7).
            self.w_fifo = true;
            self.w_hist = i.dedup_on;
            self.scan_i = 0;
            self.hit = false;
            self.free_found = false;
        } else if let Some(f) = s_pend {
            // P-CORE-4: source S after A and B, written without the
            // scan and without a history entry.
            self.sel = 2;
            self.s_frame = f;
            self.s_pend = offer;
            self.w_state = W_WRITE;
            self.w_fifo = true;
            self.w_hist = false;
        } else if acl_rule && c.release && i.dedup_on {
            self.w_state = W_RSCAN;
            self.scan_i = 0;
            self.rel_found = false;
        }
    }

    /// `SCAN`: judge the history entry read at the previous edge: the first
    /// free one, an expiry (an omission of the other channel if unmatched), or
    /// the first copy of the frame from the other channel.
    pub(super) fn writer_scan(&mut self, i: &RxInputs, c: &RxRegs, acl_rule: bool) {
        if c.scan_i >= 1 {
            let e = c.scan_i - 1;
            let bit = 1u32 << e;
            let entry = c.hist_rd;
            let age = c.now.wrapping_sub(entry.ts);
            let live = c.hv & bit != 0;
            if (!live || c.hu & bit != 0 || age > i.window) && !c.free_found {
                self.free_found = true;
                self.free_e = e;
            }
            if c.hv & bit != 0 && age > i.window {
                if !acl_rule && c.hu & bit == 0 {
                    // Only channel ch delivered it: an omission of the other.
                    let miss = 1 - (entry.ch as usize & 1);
                    self.omissions[miss] = c.omissions[miss].saturating_add(1);
                    coverage::hit("rx: an omission (history entry expired unmatched)");
                }
                self.expire(c, acl_rule, bit);
            } else if c.hv & bit != 0
                && c.hu & bit == 0
                && entry.ch != c.sel
                && entry.frame == c.rxf[c.sel as usize]
                && !c.hit
            {
                self.hit = true;
                self.hit_e = e;
            }
        }
        self.scan_i = c.scan_i + 1;
        if c.scan_i == self.sizes.history {
            self.w_state = W_DECIDE;
        }
    }

    /// `DECIDE` under the ACL rule (§8): a PCL frame waits in the history, a
    /// copy of a frame already delivered is a duplicate.
    pub(super) fn writer_decide_acl(&mut self, i: &RxInputs, c: &RxRegs) {
        // §8 the ACL rule.
        let pcl = c.sel != i.acl;
        if pcl {
            self.pcl_frames = c.pcl_frames.saturating_add(1);
        }
        self.w_pcl = pcl;
        if c.hit {
            let bit = 1u32 << c.hit_e;
            // Interpretation: a PCL copy of a frame still waiting on the
            // ACL (recorded before the switch, not yet released) leaves the
            // entry for the release, or that frame would be lost.
            if !(pcl && c.hd & bit == 0) {
                self.hu |= bit;
            }
            if c.hd & bit == 0 && !pcl {
                // The PCL copy came first and waited: delivered now.
                self.w_fifo = true;
                self.w_hist = false;
                self.w_state = W_WRITE;
            } else {
                self.duplicates = c.duplicates.saturating_add(1);
                self.w_state = W_IDLE;
            }
        } else {
            self.w_fifo = !pcl;
            self.w_hist = i.dedup_on;
            self.w_state = W_WRITE;
        }
    }

    /// `DECIDE` under the first-copy rule (§7): a copy found in the history is
    /// a duplicate, dropped; any other frame is written.
    pub(super) fn writer_decide(&mut self, i: &RxInputs, c: &RxRegs) {
        // §8.1: the frames of the passive line are still counted.
        if i.dmr && c.sel != i.acl {
            self.pcl_frames = c.pcl_frames.saturating_add(1);
        }
        if c.hit {
            self.hu |= 1 << c.hit_e;
            self.duplicates = c.duplicates.saturating_add(1);
            self.w_state = W_IDLE;
        } else {
            self.w_state = W_WRITE;
        }
    }

    /// `RSCAN` (§8): scan the history for the oldest frame of the new ACL still
    /// waiting, expiring old entries on the way.
    pub(super) fn writer_rscan(&mut self, i: &RxInputs, c: &RxRegs, acl_rule: bool) {
        if c.scan_i >= 1 {
            let e = c.scan_i - 1;
            let bit = 1u32 << e;
            let entry = c.hist_rd;
            let age = c.now.wrapping_sub(entry.ts);
            if c.hv & bit != 0 && age > i.window {
                self.expire(c, acl_rule, bit);
            } else if c.hv & bit != 0
                && c.hu & bit == 0
                && c.hd & bit == 0
                && entry.ch == i.acl
                && (!c.rel_found || age > c.rel_age)
            {
                // The oldest waiting frame of the new ACL.
                self.rel_found = true;
                self.rel_e = e;
                self.rel_age = age;
            }
        }
        self.scan_i = c.scan_i + 1;
        if c.scan_i == self.sizes.history {
            // Interpretation: entry H - 1, judged at this edge, counts.
            if self.rel_found {
                self.w_state = W_FETCH;
            } else {
                self.release = false;
                self.w_state = W_IDLE;
            }
        }
    }

    /// `RELEASE` (§8): the fetched waiting frame goes to the FIFO and is marked
    /// delivered. Returns whether the FIFO was written.
    pub(super) fn writer_release(
        &mut self,
        i: &RxInputs,
        c: &RxRegs,
        filt: &Filters,
        ev: &mut RxEvents,
    ) -> bool {
        let frame = c.hist_rd.frame;
        let pushed = self.fifo_write(c, &frame, i.acl, filt, ev);
        self.hd |= 1 << c.rel_e;
        self.released = c.released.saturating_add(1);
        self.w_state = W_IDLE;
        pushed
    }

    /// `WRITE`: the selected frame to the FIFO (unless it waits, §8) and to the
    /// history (a free entry, else the next by `hist_ptr`). Returns whether the
    /// FIFO was written.
    pub(super) fn writer_write(
        &mut self,
        c: &RxRegs,
        s_frame: Frame,
        acl_rule: bool,
        filt: &Filters,
        ev: &mut RxEvents,
    ) -> bool {
        let hist_size = self.sizes.history;
        let mut pushed = false;
        let frame = if c.sel == 2 {
            s_frame
        } else {
            c.rxf[c.sel as usize]
        };
        // A PCL frame (!w_fifo) waits in the history (§8).
        if c.w_fifo {
            pushed = self.fifo_write(c, &frame, c.sel, filt, ev);
        }
        if c.w_hist {
            let p = if c.free_found {
                c.free_e
            } else {
                c.hist_ptr & (hist_size - 1)
            };
            self.hist[p as usize] = HistEntry {
                frame,
                ch: c.sel,
                ts: c.now,
            };
            self.hv |= 1 << p;
            self.hu &= !(1 << p);
            if c.w_pcl && acl_rule {
                self.hd &= !(1 << p);
            } else {
                self.hd |= 1 << p;
            }
            if !c.free_found {
                self.hist_ptr = (p + 1) & (hist_size - 1);
            }
        }
        self.w_state = W_IDLE;
        pushed
    }
}
