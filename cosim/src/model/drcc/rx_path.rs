//! RX FIFO and duplicate removal (contract §7): the RX RAM (`rx_fifo_depth` x 100
//! bits, §1.1) with its registered read port, the writer FSM (idle, scan, decide,
//! write), the `H`-entry history of delivered frames and the `now` / `hist_idle` tick counters. In DMR
//! mode (dmr_contract.md §8) the first-copy-wins rule is replaced by the ACL rule:
//! frames of the passive line wait in the history (`hd` = 0) and are released,
//! oldest first, at an ACL switch (states `RSCAN`, `FETCH`, `RELEASE`).

mod writer;

use super::features::Filters;
use crate::frame::Frame;
use crate::model::coverage;

/// Writer FSM states.
pub const W_IDLE: u8 = 0;
pub const W_SCAN: u8 = 1;
pub const W_DECIDE: u8 = 2;
pub const W_WRITE: u8 = 3;
/// DMR mode (dmr_contract.md §8): the release of waiting PCL frames.
pub const W_RSCAN: u8 = 4;
pub const W_FETCH: u8 = 5;
pub const W_RELEASE: u8 = 6;

/// `hist_idle` saturation value: every history entry is dropped there.
const HIST_IDLE_MAX: u16 = 32767;

/// History entries at most (contract §7; a configuration's `H` is 4..32, §1.1).
pub const HIST: usize = 32;

/// The RX path's generation parameters (contract §1.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RxSizes {
    /// RX FIFO entries: a write with this count overruns.
    pub fifo_depth: u8,
    /// History entries `H`: a scan takes `H + 1` clocks.
    pub history: u8,
}

impl Default for RxSizes {
    fn default() -> Self {
        RxSizes {
            fifo_depth: 32,
            history: HIST as u8,
        }
    }
}

/// What the RX path samples at an edge.
#[derive(Clone, Copy, Debug, Default)]
pub struct RxInputs {
    pub reset_mode: bool,
    /// `redundancy && window != 0`; in DMR mode `hist_on = window != 0`.
    pub dedup_on: bool,
    /// DMR mode (dmr_contract.md §8): the ACL rule, unless `first_copy`.
    pub dmr: bool,
    /// `CTRL.first_copy` (dmr_contract.md §8.1): in DMR mode with a history, the
    /// first copy from either line is delivered (§D.7's rule) instead.
    pub first_copy: bool,
    /// The ACL register before the edge (0 DCL = A, 1 RCL = B).
    pub acl: u8,
    /// An ACL switch at this edge: `release <= 1`.
    pub release_set: bool,
    pub window: u16,
    pub tick: bool,
    /// An `RX_CMD.pop` write at this edge.
    pub pop: bool,
    /// Channel `rx_valid` pulses (registered channel outputs).
    pub rx_valid: [bool; 2],
}

/// What the RX path did at an edge.
#[derive(Clone, Copy, Debug, Default)]
pub struct RxEvents {
    /// Pop on an empty FIFO: INT_STATUS.illegal.
    pub pop_refused: bool,
    /// A frame the writer would have written, not accepted by the filters
    /// (DRCC contract §11.1): dropped silently.
    pub rejected: bool,
    pub rx: bool,
    pub overrun: bool,
}

/// One history entry (RAM 32 x 116: frame, channel, timestamp).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HistEntry {
    pub frame: Frame,
    pub ch: u8,
    pub ts: u16,
}

/// The RX FIFO, the writer FSM and the dedup history.
#[derive(Clone, Debug, Default)]
pub struct RxPath {
    /// PeliCAN P-CORE-4: the self-received frame offered by a host view at
    /// this edge (source `S`), set by [`super::DrccModel::step_host`].
    pub offer_s: Option<Frame>,
    /// Source `S` pending (offered, not yet taken by the writer).
    pub s_pend: Option<Frame>,
    /// The frame of source `S` the writer took.
    pub s_frame: Frame,
    /// RX RAM: frame and channel (public for the block-level lock-step test).
    pub ram: [(Frame, u8); 32],
    /// The RX RAM's timestamps (DRCC contract §11.2): `now` at the write edge.
    pub ts: [u16; 32],
    pub head: u8,
    pub count: u8,
    /// RAM read data register (the RX_* registers).
    pub rd: (Frame, u8),
    /// The timestamp of the read data (`RX_TIME.rx_time`).
    pub rd_ts: u16,
    /// `RX_ID[31]`: `count != 0` at the previous edge.
    pub rx_ready: bool,
    pub rxp: [bool; 2],
    /// The frame of each channel's last `rx_valid` (contract §7): the writer reads
    /// it, not the channel, whose outputs a restart clears.
    pub rxf: [Frame; 2],
    pub w_state: u8,
    pub sel: u8,
    pub scan_i: u8,
    pub hit: bool,
    pub hit_e: u8,
    /// History RAM (public for the block-level lock-step test).
    pub hist: [HistEntry; HIST],
    /// History RAM read data register.
    hist_rd: HistEntry,
    pub hv: u32,
    pub hu: u32,
    pub free_found: bool,
    pub free_e: u8,
    pub hist_ptr: u8,
    pub hist_idle: u16,
    pub now: u16,
    // Statistics, cleared only by `rst`.
    pub duplicates: u16,
    pub overruns: u16,
    /// `OMISSIONS`: per channel, frames only the other channel delivered (§7).
    pub omissions: [u16; 2],
    // DMR mode (dmr_contract.md §8).
    /// Delivered: the entry's frame reached the FIFO.
    pub hd: u32,
    pub release: bool,
    pub rel_found: bool,
    pub rel_e: u8,
    pub rel_age: u16,
    pub w_fifo: bool,
    pub w_hist: bool,
    pub w_pcl: bool,
    // DMR statistics (DMR_RX_STATS), cleared only by `rst`.
    pub pcl_frames: u16,
    pub released: u8,
    pub expired: u8,
    /// Generation parameters (not reset).
    pub sizes: RxSizes,
}

impl RxPath {
    /// An RX path with the sizes of one configuration.
    pub fn new(sizes: RxSizes) -> Self {
        RxPath {
            offer_s: None,
            s_pend: None,
            s_frame: Frame::default(),
            sizes,
            ..RxPath::default()
        }
    }

    /// `DMR_RX_STATS`: [15:0] pcl_frames, [23:16] released, [31:24] expired.
    pub fn dmr_stats(&self) -> u32 {
        self.pcl_frames as u32 | (self.released as u32) << 16 | (self.expired as u32) << 24
    }

    /// History read address: `rel_e` in `FETCH`, else `scan_i mod H`.
    fn hist_addr(&self, w_state: u8, scan_i: u8, rel_e: u8) -> usize {
        let last = self.sizes.history - 1;
        if w_state == W_FETCH {
            (rel_e & last) as usize
        } else {
            (scan_i & last) as usize
        }
    }

    /// A `rst` edge: the read ports load as at every edge (RAM contents are not
    /// reset), every register and statistic clears.
    pub fn reset(&mut self) {
        let rd = self.ram[self.head as usize];
        let rd_ts = self.ts[self.head as usize];
        let hist_rd = self.hist[self.hist_addr(self.w_state, self.scan_i, self.rel_e)];
        *self = RxPath {
            ram: self.ram,
            ts: self.ts,
            hist: self.hist,
            sizes: self.sizes,
            rd,
            rd_ts,
            hist_rd,
            ..RxPath::default()
        };
    }

    /// One rising edge without filters (every frame accepted); `rx_frame` are
    /// the channels' `rx_*` outputs (read with `rx_valid` only).
    pub fn edge(&mut self, i: &RxInputs, rx_frame: [&Frame; 2]) -> RxEvents {
        self.edge_filtered(i, rx_frame, &Filters::default())
    }

    /// The FIFO write port (DRCC contract §7 `write`, DMR contract §8 `release`,
    /// §11.1 order): not accepted → dropped silently; else full → overrun; else
    /// written with its channel and the timestamp `now` (§11.2, the value before
    /// the edge, as the history's). Returns whether the frame was written.
    fn fifo_write(
        &mut self,
        c: &RxRegs,
        f: &Frame,
        ch: u8,
        filt: &Filters,
        ev: &mut RxEvents,
    ) -> bool {
        let depth = self.sizes.fifo_depth;
        if !filt.accepts(f) {
            coverage::hit("rx: a frame rejected by the acceptance filters");
            ev.rejected = true;
            false
        } else if c.count >= depth {
            self.overruns = c.overruns.saturating_add(1);
            ev.overrun = true;
            false
        } else {
            let a = ((c.head + c.count) & (depth - 1)) as usize;
            self.ram[a] = (*f, ch);
            self.ts[a] = c.now;
            ev.rx = true;
            true
        }
    }

    /// One rising edge with the acceptance filters `filt` at the FIFO's write
    /// port (DRCC contract §11.1).
    pub fn edge_filtered(
        &mut self,
        i: &RxInputs,
        rx_frame: [&Frame; 2],
        filt: &Filters,
    ) -> RxEvents {
        let mut ev = RxEvents::default();
        let c = self.clone_regs();
        let (s_pend, s_frame, offer) = (self.s_pend, self.s_frame, self.offer_s.take());
        // Registered read ports (read-first: the RAM contents before the edge).
        self.rd = self.ram[c.head as usize];
        self.rd_ts = self.ts[c.head as usize];
        self.hist_rd = self.hist[self.hist_addr(c.w_state, c.scan_i, c.rel_e)];
        let depth = self.sizes.fifo_depth;
        ev.pop_refused = i.pop && c.count == 0;
        self.rx_ready = !i.reset_mode && c.count != 0;
        if i.reset_mode {
            self.clear_in_reset_mode();
            return ev;
        }
        self.count_and_receive(i, &c, rx_frame, s_pend, offer);
        // DMR §8.1: with first-copy delivery and a history the writer follows
        // §D.7; without a history it keeps the ACL rule.
        let acl_rule = i.dmr && !(i.first_copy && i.dedup_on);
        let mut pushed = false;
        match c.w_state {
            W_IDLE => self.writer_idle(i, &c, acl_rule, s_pend, offer),
            W_SCAN => self.writer_scan(i, &c, acl_rule),
            W_DECIDE if acl_rule => self.writer_decide_acl(i, &c),
            W_DECIDE => self.writer_decide(i, &c),
            W_RSCAN => self.writer_rscan(i, &c, acl_rule),
            W_FETCH => self.w_state = W_RELEASE,
            W_RELEASE => pushed = self.writer_release(i, &c, filt, &mut ev),
            _ => pushed = self.writer_write(&c, s_frame, acl_rule, filt, &mut ev),
        }
        if i.release_set {
            self.release = true;
        }
        let popped = i.pop && c.count > 0;
        if popped {
            self.head = (c.head + 1) & (depth - 1);
        }
        self.count = c.count + pushed as u8 - popped as u8;
        ev
    }

    /// Reset mode, a synchronous clear: the FIFO, the writer FSM, the history's
    /// flags and pointer, `rxp`, source S and the `now` / `hist_idle` counters
    /// are held cleared; the RAMs, the last frames and the statistics are kept.
    fn clear_in_reset_mode(&mut self) {
        self.head = 0;
        self.count = 0;
        self.rxp = [false; 2];
        self.w_state = W_IDLE;
        self.sel = 0;
        self.scan_i = 0;
        self.hit = false;
        self.hit_e = 0;
        self.hv = 0;
        self.hu = 0;
        self.free_found = false;
        self.free_e = 0;
        self.hist_ptr = 0;
        self.hist_idle = 0;
        self.now = 0;
        self.hd = 0;
        self.release = false;
        self.rel_found = false;
        self.rel_e = 0;
        self.rel_age = 0;
        self.w_fifo = false;
        self.w_hist = false;
        self.w_pcl = false;
        self.s_pend = None;
    }

    /// The tick counters `now` and `hist_idle` (a `hist_idle` saturated before
    /// the edge drops every history entry), and the receptions of this edge:
    /// the pending flags `rxp`, source S's offer and each channel's last frame.
    fn count_and_receive(
        &mut self,
        i: &RxInputs,
        c: &RxRegs,
        rx_frame: [&Frame; 2],
        s_pend: Option<Frame>,
        offer: Option<Frame>,
    ) {
        if i.tick {
            self.now = c.now.wrapping_add(1);
            self.hist_idle = (c.hist_idle + 1).min(HIST_IDLE_MAX);
        }
        if c.hist_idle == HIST_IDLE_MAX {
            self.hv = 0;
        }
        self.rxp = [c.rxp[0] | i.rx_valid[0], c.rxp[1] | i.rx_valid[1]];
        // An offer at this edge sets the pending source S (set wins).
        self.s_pend = offer.or(s_pend);
        for (s, f) in rx_frame.iter().enumerate() {
            if i.rx_valid[s] {
                self.rxf[s] = **f;
            }
        }
    }

    /// The small registers before the edge (everything but the RAMs).
    fn clone_regs(&self) -> RxRegs {
        RxRegs {
            head: self.head,
            count: self.count,
            rxp: self.rxp,
            rxf: self.rxf,
            w_state: self.w_state,
            sel: self.sel,
            scan_i: self.scan_i,
            hit: self.hit,
            hit_e: self.hit_e,
            hist_rd: self.hist_rd,
            hv: self.hv,
            hu: self.hu,
            free_found: self.free_found,
            free_e: self.free_e,
            hist_ptr: self.hist_ptr,
            hist_idle: self.hist_idle,
            now: self.now,
            duplicates: self.duplicates,
            omissions: self.omissions,
            overruns: self.overruns,
            hd: self.hd,
            release: self.release,
            rel_found: self.rel_found,
            rel_e: self.rel_e,
            rel_age: self.rel_age,
            w_fifo: self.w_fifo,
            w_hist: self.w_hist,
            w_pcl: self.w_pcl,
            pcl_frames: self.pcl_frames,
            released: self.released,
            expired: self.expired,
        }
    }
}

/// Pre-edge copy of the RX path registers.
struct RxRegs {
    head: u8,
    count: u8,
    rxp: [bool; 2],
    rxf: [Frame; 2],
    w_state: u8,
    sel: u8,
    scan_i: u8,
    hit: bool,
    hit_e: u8,
    hist_rd: HistEntry,
    hv: u32,
    hu: u32,
    free_found: bool,
    free_e: u8,
    hist_ptr: u8,
    hist_idle: u16,
    now: u16,
    duplicates: u16,
    omissions: [u16; 2],
    overruns: u16,
    hd: u32,
    release: bool,
    rel_found: bool,
    rel_e: u8,
    rel_age: u16,
    w_fifo: bool,
    w_hist: bool,
    w_pcl: bool,
    pcl_frames: u16,
    released: u8,
    expired: u8,
}
