//! Receive writer and duplicate removal (DRCC contract §7). Each channel's
//! `rx_valid` pulse sets `rxp_a` / `rxp_b`; the writer FSM (`w_state`: idle 0,
//! scan 1, decide 2, write 3; DMR: rscan 4, fetch 5, release 6) takes A before B, and in redundancy mode with a
//! non-zero window scans the `H`-entry history (a synchronous RAM of H x 116 bits:
//! [115:17] frame, [16] channel, [15:0] timestamp `now`; stored as two RAMs, see
//! below) for an identical frame
//! delivered from the other channel at most `window` bit times earlier that has
//! not already cancelled a copy; such a frame is dropped as a duplicate.
//! Otherwise the frame is written to the RX FIFO (or counted as an overrun when
//! the FIFO is full) and recorded in the history. At the FIFO port, and only
//! there, the acceptance filters judge it (§11.1: a frame no enabled filter
//! matches is dropped silently, after the history has seen it), and the entry
//! is stamped with `now` (§11.2).
//!
//! scan (H + 1 clocks, `scan_i` 0..H): history read address = `scan_i mod H`;
//! at the edge with `scan_i = i >= 1` the read data is entry `i - 1`.
//!
//! Generation parameters (`crate::config`, contract §1.1): the history size `H`
//! (4, 8, 16 or 32; default 32) and the RX FIFO depth (its full count). Entry
//! indices keep their 5 bits, wrapped at `H` (`hmask = H - 1`), and the RAMs
//! their 32 entries, of which the first `H` are used: a smaller history is
//! the same logic with constant-zero upper bits, which synthesis removes.
//!
//! Timing (iCE40 Fmax): the timestamps live in a RAM of their own (`hist_ts`,
//! 32 x 16; the frames and channels in `hist`, 32 x 100: the same 8 block RAMs),
//! read one entry ahead (address `scan_i + 1` in scan, 0 elsewhere, so entry 0 is
//! loaded at the idle -> scan edge). Entry `e`'s expiry `age > window` is thus
//! computed a clock early, for the `now` of the judging edge (`now + tick`:
//! `now` counts `tick`s and only clears with `clear`, which also ends the scan;
//! `window` is cfg, written only in reset mode = `clear`), and registered in
//! `exp_q`. This takes the 16-bit subtraction and compare off the RAM -> `hit` /
//! `free_found` path. A write is always followed by an idle edge, which reloads
//! address 0, so a colliding `hist_ts` read is never observed either. The first free
//! entry (not valid, already used, or expired) seen by the scan is where the new
//! frame is recorded; with all H live, the round-robin `hist_ptr` is the victim.
//!
//! Omissions (§7, outside DMR mode): an entry that expires in `scan` (valid
//! and its age above `window`) without having cancelled a copy (not used) was
//! delivered only by its channel `ch_e`: `omissions[1 - ch_e] += 1`. The
//! statistics (`STATS0`, `OMISSIONS`, `DMR_RX_STATS`) are counted in
//! `super::rx_stats`, cleared by `rst` only; no event counts at a `clear` edge.
//!
//! The history is a block RAM without read-before-write emulation
//! (`super::bram`): it is written only in `write`, and its read data is used only
//! in `scan` edges with `scan_i >= 1`, loaded at the previous `scan` edge, where
//! nothing is written; a colliding read is never observed.
//!
//! The entry flags (valid `v`, used `u`: it cancelled a copy, DMR delivered `d`)
//! live in a third RAM, `flags` (H x 3, one block RAM instead of three H-bit
//! registers with their rotations and a 5-to-32 decoder: about 300 LUT4 and 96
//! flip-flops). It is read at the `hist` address, so the judged entry's flags
//! come with its frame. Each state writes one entry: a judging edge of either
//! scan writes the entry it judges back (its `v` cleared when it expired; the
//! read at that edge is of the next entry), `decide` the hit entry (`u`),
//! `write` the recorded slot, `release` the released entry (`d`). Nothing
//! clears a RAM at once, so `forget` stands for "every `v` is 0" (set by `clear`
//! and by a history idle for 32767 bit times) until a scan has written every
//! entry back invalid and the history is no longer idle (`hist_idle` is
//! cleared only by a frame's scan, so a scan that began with `forget` clears
//! it, and one it was set in the middle of keeps it). An entry's `u` and `d` mean
//! something only while its `v` is 1. A colliding read is never observed: a
//! judging edge writes entry `scan_i - 1` and reads `scan_i`; `decide`, `write`
//! and `release` write while the read address rests at 0, and each is followed
//! by an idle edge, and a scan's first read (of entry 0, at the edge with
//! `scan_i = 0`) is at a scan edge that writes nothing. The RAM's contents
//! after power-up do not matter: `rst` sets `forget`.
//!
//! DMR mode (DMR contract §8, `dmr` = 1): the ACL rule replaces first-copy-wins.
//! `decide` delivers a frame of the ACL (`sel == acl`) and records one of the
//! passive line (PCL) undelivered (`d` = 0); a PCL frame waits for its ACL copy,
//! which then delivers it (no second history entry). At an ACL switch
//! (`release_set`) `release` is set, and every free idle edge runs a release scan
//! (`rscan`, H + 1 clocks as `scan`, with the same expiry and write-back): the oldest waiting frame of the new ACL (`release_scan.rs`)
//! is read back (`fetch`, history address `rel_e`) and written to the FIFO with
//! channel `acl` (`release`). A scan that finds none ends the release. The
//! history read in `release` was loaded at the `fetch` edge, where nothing is
//! written. Outside DMR mode nothing here differs from §7.

use super::bram::Bram;
use super::release_scan::ReleaseScan;
use super::rx_stats::RxStats;
use crate::channel::sized::{Const, Param};
use crate::pelican::acceptance_filter::AcceptanceFilter;
use rust_hdl::prelude::*;

/// Receive writer with the duplicate-removal history.
#[derive(LogicBlock, Default)]
pub struct RxWriter {
    // clock, reset (statistics) and clear (rst or reset mode)
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: clears the statistics.
    pub rst: Signal<In, Bit>,
    /// `rst` or reset mode: the writer goes idle, pending frames are dropped and the history
    /// forgotten.
    pub clear: Signal<In, Bit>,
    // configuration and time
    /// Duplicate removal: redundancy or DMR mode with a non-zero window (the history is used).
    pub dedup_on: Signal<In, Bit>,
    /// `DEDUP_CFG.window`: how far back, in nominal bit times, a copy from the other channel is a
    /// duplicate.
    pub window: Signal<In, Bits<15>>,
    /// Bit-time clock (`BitTick`'s `now`): the history's and the RX timestamp.
    pub now: Signal<In, Bits<16>>,
    /// Nominal bit tick: `now` advances at it.
    pub tick: Signal<In, Bit>,
    // channels: rx_valid pulses and the received frames (valid with the pulse;
    // latched here, since a channel restart clears the channel's rx outputs)
    /// One-clock pulse: channel A delivers `frame_a` (its `rx_valid` less echoes; DMR: the DCL's
    /// delivery).
    pub rxv_a: Signal<In, Bit>,
    /// One-clock pulse: channel B delivers `frame_b` (DMR: the RCL's delivery).
    pub rxv_b: Signal<In, Bit>,
    /// Channel A's frame, valid with `rxv_a`: [98:68] {rtr, ide, id}, [67:64] dlc, [63:0] data.
    pub frame_a: Signal<In, Bits<99>>,
    /// Channel B's frame, valid with `rxv_b` (layout of `frame_a`).
    pub frame_b: Signal<In, Bits<99>>,
    // RX FIFO
    /// RX FIFO count: a frame for a full FIFO is an overrun.
    pub fifo_count: Signal<In, Bits<6>>,
    /// Write `fifo_data` to the RX FIFO at this edge.
    pub fifo_wr: Signal<Out, Bit>,
    /// The FIFO entry: [115:100] `now` (the RX timestamp, contract §11.2), [99]
    /// channel, [98:0] frame.
    pub fifo_data: Signal<Out, Bits<116>>,
    // acceptance filters (contract §11.1; the registers are `crate::host::filters`)
    /// `FILT_ID0[30:0]`: the frame word {rtr, ide, id} to compare.
    pub filt_id0: Signal<In, Bits<31>>,
    /// `FILT_MASK0`: [30:0] the bits compared, [31] `enable`.
    pub filt_mask0: Signal<In, Bits<32>>,
    /// `FILT_ID1[30:0]`.
    pub filt_id1: Signal<In, Bits<31>>,
    /// `FILT_MASK1`.
    pub filt_mask1: Signal<In, Bits<32>>,
    // ---- a host view (PeliCAN contract §14, P-CORE-4); 0 in the native top ----
    /// Source `S`: the view offers this frame at this edge (a self-received
    /// frame, P-TX-5). It is written after A and B, without the scan and
    /// without a history entry, with channel bit 0.
    pub offer_s: Signal<In, Bit>,
    /// The offered frame (the TX RAM's layout).
    pub frame_s: Signal<In, Bits<99>>,
    /// The view's acceptance filter gates the FIFO port too (P-RX-5).
    pub gate_on: Signal<In, Bit>,
    /// Its filter mode `MOD.AFM` (1 = single filter).
    pub gate_afm: Signal<In, Bit>,
    /// `ACR0..3`, `ACR0` in [7:0].
    pub gate_acr: Signal<In, Bits<32>>,
    /// `AMR0..3`, `AMR0` in [7:0].
    pub gate_amr: Signal<In, Bits<32>>,
    /// `STATS_CLR.clear` (contract §11.4): the statistics clear at this edge.
    pub stats_clear: Signal<In, Bit>,
    // events and statistics
    /// A frame was written to the RX FIFO at this edge (`INT_STATUS.rx`).
    pub rx_evt: Signal<Out, Bit>,
    /// A frame was dropped at this edge because the RX FIFO was full (`INT_STATUS.overrun`).
    pub overrun_evt: Signal<Out, Bit>,
    /// `STATS0.duplicates`: duplicates dropped (saturating).
    pub duplicates: Signal<Out, Bits<16>>,
    /// `STATS0.overruns`: frames dropped because the RX FIFO was full (saturating).
    pub overruns: Signal<Out, Bits<16>>,
    /// `OMISSIONS[15:0]`: frames only channel B delivered (omissions of A).
    pub omissions_a: Signal<Out, Bits<16>>,
    /// `OMISSIONS[31:16]`: frames only channel A delivered (omissions of B).
    pub omissions_b: Signal<Out, Bits<16>>,
    // ---- DMR mode (DMR contract §8) ----
    /// DMR mode with the ACL rule instead of first-copy-wins: `CTRL.dmr`, unless
    /// `CTRL.first_copy` with a history (DMR contract §8.1).
    pub acl_rule: Signal<In, Bit>,
    /// `CTRL.dmr`: frames of the passive line count in `pcl_frames` (§8, §8.1).
    pub count_pcl: Signal<In, Bit>,
    /// The ACL register before the edge (0 DCL = channel A, 1 RCL = channel B).
    pub acl: Signal<In, Bit>,
    /// An ACL switch at this edge: the waiting frames of the new ACL are released.
    pub release_set: Signal<In, Bit>,
    /// `DMR_RX_STATS[15:0]`: frames taken from the passive line (saturating).
    pub pcl_frames: Signal<Out, Bits<16>>,
    /// `DMR_RX_STATS[23:16]`: waiting frames released (saturating).
    pub released: Signal<Out, Bits<8>>,
    /// `DMR_RX_STATS[31:24]`: undelivered, unmatched entries expired (saturating).
    pub expired: Signal<Out, Bits<8>>,
    // history
    hist: Bram<Bits<100>, 5>,
    hist_ts: Bram<Bits<16>, 5>,
    /// The entries' flags: [0] valid, [1] used (cancelled a copy), [2] DMR
    /// delivered.
    pub flags: Bram<Bits<3>, 5>,
    rel: ReleaseScan,
    /// The view's acceptance filter on the frame at the FIFO port.
    acf: AcceptanceFilter,
    stats: RxStats,
    // registers (the state and the history flags are public for lock-step probes)
    /// Writer FSM state (idle 0, scan 1, decide 2, write 3, rscan 4, fetch 5, release 6).
    pub w_state: DFF<Bits<3>>,
    rxp_a: DFF<Bit>,
    rxp_b: DFF<Bit>,
    /// The frame of each channel's last `rx_valid` (DRCC contract §7, `rxf`).
    rxf_a: DFF<Bits<99>>,
    rxf_b: DFF<Bits<99>>,
    sel: DFF<Bit>,
    /// The frame in `write` is source `S`'s (P-CORE-4).
    sel_s: DFF<Bit>,
    /// Source `S` has a frame pending, and that frame.
    s_pend: DFF<Bit>,
    s_pend_frame: DFF<Bits<99>>,
    /// The frame of `S` being written.
    s_frame: DFF<Bits<99>>,
    scan_i: DFF<Bits<6>>,
    hit: DFF<Bit>,
    hit_e: DFF<Bits<5>>,
    free_found: DFF<Bit>,
    free_e: DFF<Bits<5>>,
    hist_ptr: DFF<Bits<5>>,
    exp_q: DFF<Bit>,
    hist_idle: DFF<Bits<15>>,
    /// Every entry counts as invalid (`flags` ignored): set by `clear` and by
    /// an idle history, cleared at the end of a scan once neither holds.
    pub forget: DFF<Bit>,
    /// DMR: an ACL switch left frames to release (`release` of §8; a Verilog keyword).
    pub release_q: DFF<Bit>,
    /// DMR: the frame in `decide` came from the passive line.
    w_pcl: DFF<Bit>,
    /// DMR: `d` of the hit entry, taken with `hit`.
    hit_hd: DFF<Bit>,
    // judgement of the history entry being read
    frame_sel: Signal<Local, Bits<99>>,
    scan_e: Signal<Local, Bits<5>>,
    e_ts: Signal<Local, Bits<16>>,
    e_age: Signal<Local, Bits<16>>,
    e_ch: Signal<Local, Bit>,
    e_frame: Signal<Local, Bits<99>>,
    e_hv: Signal<Local, Bit>,
    e_hu: Signal<Local, Bit>,
    e_hd: Signal<Local, Bit>,
    e_expired: Signal<Local, Bit>,
    e_gt: Signal<Local, Bit>,
    e_ge: Signal<Local, Bit>,
    e_keep: Signal<Local, Bit>,
    slot: Signal<Local, Bits<5>>,
    /// A history idle for 32767 bit times, or `clear`: every entry forgotten.
    forget_now: Signal<Local, Bit>,
    fifo_full: Signal<Local, Bit>,
    in_scan: Signal<Local, Bit>,
    judging: Signal<Local, Bit>,
    pcl: Signal<Local, Bit>,
    r_cand: Signal<Local, Bit>,
    w_fifo: Signal<Local, Bit>,
    w_hist: Signal<Local, Bit>,
    omit: Signal<Local, Bit>,
    /// The frame word {rtr, ide, id} at the FIFO port (the filters' input).
    f_word: Signal<Local, Bits<31>>,
    f_match0: Signal<Local, Bit>,
    f_match1: Signal<Local, Bit>,
    /// §11.1: no filter enabled, or an enabled one matches.
    accept: Signal<Local, Bit>,
    // constants
    s_idle: Const<3, 0>,
    s_scan: Const<3, 1>,
    s_decide: Const<3, 2>,
    s_write: Const<3, 3>,
    s_rscan: Const<3, 4>,
    s_fetch: Const<3, 5>,
    s_release: Const<3, 6>,
    zero5: Const<5, 0>,
    one5: Const<5, 1>,
    zero6: Const<6, 0>,
    one6: Const<6, 1>,
    /// `H`: the last `scan_i` of a scan (generation parameter).
    last_scan: Param<6, 32>,
    /// `H - 1`: the entry-index wrap.
    hmask: Param<5, 31>,
    /// The RX FIFO depth: its count when full (generation parameter).
    fifo_depth: Param<6, 32>,
    zero31: Const<31, 0>,
    one3: Const<3, 1>,
    three3: Const<3, 3>,
    five3: Const<3, 5>,
    zero15: Const<15, 0>,
    one15: Const<15, 1>,
    max15: Const<15, 0x7FFF>,
    max16: Const<16, 0xFFFF>,
}

impl RxWriter {
    /// A writer with a history of `history` entries for an RX FIFO of
    /// `fifo_depth` (powers of two, 4..32).
    pub fn new(history: usize, fifo_depth: usize) -> Self {
        for n in [history, fifo_depth] {
            assert!(n.is_power_of_two() && (4..=32).contains(&n));
        }
        Self {
            last_scan: Param::new(history as u64),
            hmask: Param::new(history as u64 - 1),
            fifo_depth: Param::new(fifo_depth as u64),
            ..Default::default()
        }
    }
}

// The update (the scan, the writer FSM, the FIFO port) lives beside this file.
#[path = "dedup_update.rs"]
mod update;
