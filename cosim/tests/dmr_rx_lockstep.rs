//! Block-level lock-step of the receive writer (DRCC contract §7, DMR contract
//! §8): `RxWriter` + `RxFifo` + a `now` counter in rust-hdl's simulator against
//! the reference model's `RxPath` (`edge`, `reset` for `rst`), clock by clock,
//! on seeded random traffic of a dual network: the same frame on both lines a few
//! hundred clocks apart in random order, some on one line only, some lost; random
//! pops with stalls (FIFO overruns), ACL switches at random (`release_set` with
//! `acl` toggling at that edge), windows small enough that entries expire, reset
//! mode episodes, runs with first-copy delivery (DMR contract §8.1), and runs
//! with `dmr` = 0 (redundancy dedup, regression).
//!
//! Compared at every clock: the FIFO write (`fifo_wr`, `fifo_data` against the
//! model's RAM slot written), `rx_evt`, `overrun_evt`, FIFO `head`, `count`,
//! `rx_ready` and read data, `duplicates`, `overruns`, the three `DMR_RX_STATS`
//! counts, the two `OMISSIONS` counts, `w_state`, and `hv` / `hu` / `hd` (the
//! block keeps them in its `flags` RAM, read back every clock; `u` and `d` of
//! valid entries).

use drcc_cosim::frame::Frame;
use drcc_cosim::model::drcc::rx_path::{
    RxEvents, RxInputs, RxPath, W_DECIDE, W_FETCH, W_IDLE, W_RELEASE, W_RSCAN, W_SCAN, W_WRITE,
};
use drcc_hdl::memory::dedup::RxWriter;
use rust_hdl::prelude::*;

mod block_support;
use block_support::{settle, Rng};
#[path = "dmr_rx_lockstep/bench.rs"]
mod bench;
use bench::{entry_bits, frame_bits, RxBench};
use std::collections::BTreeSet;

/// One run's configuration.
struct Run {
    seed: u64,
    clocks: usize,
    dmr: bool,
    /// `CTRL.first_copy` (DMR contract §8.1).
    first_copy: bool,
    /// `DEDUP_CFG.window`, bit times.
    window: u16,
    /// Clocks per bit `tick`.
    tick_period: usize,
    /// Largest delay of the second copy, clocks.
    max_delay: u64,
    /// ACL switch probability per clock (1 in `acl_every`), DMR runs.
    acl_every: u64,
    /// A pause of this many clocks between frames now and then (0: none), for
    /// a history left idle long enough to be forgotten (DRCC contract §7).
    pause: u64,
}

/// Paths reached (asserted non-zero so the stimulus keeps reaching them).
#[derive(Default, Debug)]
struct Coverage {
    frames: u64,
    duplicates: u64,
    overruns: u64,
    expired_scan: u64,
    expired_rscan: u64,
    pcl_frames: u64,
    waiting_delivered: u64,
    pcl_copy_of_waiting: u64,
    acl_switches: u64,
    rscans: u64,
    rscan_empty: u64,
    /// A release candidate as old as the one already chosen (the first stays).
    release_ties: u64,
    releases: u64,
    release_overruns: u64,
    hist_recorded_pcl: u64,
    resets: u64,
    /// Entries that expired unmatched and counted as an omission.
    omissions: u64,
    /// Edges where the idle history was forgotten (`hist_idle` reached 32767).
    forgets: u64,
    /// ... of them in a release scan.
    forgets_in_rscan: u64,
    /// ... of them with valid entries left to forget.
    forgets_valid: u64,
    /// ... of them in a release scan that has already judged a valid entry
    /// (forgetting must outlast this scan).
    forgets_valid_in_rscan: u64,
    /// Frames recorded in a history that had been forgotten.
    recorded_after_forget: u64,
}

/// Arrivals per clock and line, at least `GAP` clocks apart on a line.
const GAP: u64 = 40;

fn place(occupied: &mut BTreeSet<u64>, mut t: u64) -> u64 {
    while occupied
        .range(t.saturating_sub(GAP - 1)..t + GAP)
        .next()
        .is_some()
    {
        t += 1;
    }
    occupied.insert(t);
    t
}

fn schedule(run: &Run, rng: &mut Rng) -> Vec<[Option<Frame>; 2]> {
    let n = run.clocks as u64;
    let mut lines: Vec<[Option<Frame>; 2]> = vec![[None; 2]; run.clocks];
    let mut occ: [BTreeSet<u64>; 2] = Default::default();
    // a small pool, so that distinct messages can be identical frames
    let ids = [0x123u32, 0x124, 0x7EA, 0x1ABC_DEF0, 0x10, 0x5A5];
    let datas = [0u64, 0x0102_0304_0506_0708, 0xFFFF_0000_FFFF_0000];
    let mut t = 30u64;
    while t < n {
        let ide = rng.chance(1, 4);
        let id = ids[rng.below(ids.len() as u64) as usize] & if ide { 0x1FFF_FFFF } else { 0x7FF };
        let f = Frame {
            id,
            ide,
            rtr: rng.chance(1, 10),
            dlc: [0u8, 1, 8][rng.below(3) as usize],
            data: datas[rng.below(3) as usize].to_be_bytes(),
        };
        let first = rng.below(2) as usize;
        let d = rng.below(run.max_delay + 1);
        let kind = rng.below(100);
        let mut put = |line: usize, at: u64| {
            let at = place(&mut occ[line], at);
            if at < n {
                lines[at as usize][line] = Some(f);
            }
        };
        if kind < 60 {
            put(first, t);
            put(1 - first, t + d);
        } else if kind < 80 {
            put(first, t);
        } else if kind < 92 {
            put(1 - first, t + d);
        } // else lost on both lines
          // bursts and pauses
        t += if run.pause > 0 && rng.chance(1, 6) {
            run.pause + rng.below(run.pause / 8)
        } else if rng.chance(1, 20) {
            300 + rng.below(1500)
        } else {
            20 + rng.below(120)
        };
    }
    lines
}

/// The writer's flags as the model's three vectors (valid, used, delivered),
/// each read from its flags RAM; `forget` makes every entry invalid, and an
/// entry's used and delivered flags mean something only while it is valid.
fn flags_of(w: &RxWriter) -> (u32, u32, u32) {
    let (mut v, mut u, mut d) = (0u32, 0u32, 0u32);
    for e in 0..32u64 {
        let f = w.flags.peek(e.to_bits()).to_u8();
        if f & 1 == 1 && !w.forget.q.val() {
            v |= 1 << e;
            u |= ((f >> 1) as u32 & 1) << e;
            d |= ((f >> 2) as u32 & 1) << e;
        }
    }
    (v, u, d)
}

/// The block's inputs for one clock (before its edge), from the model's inputs.
fn drive(uut: &mut RxBench, i: &RxInputs, rst: bool, frame: &[Frame; 2]) {
    uut.clk.next = Clock::from(false);
    uut.rst.next = rst;
    uut.reset_mode.next = i.reset_mode;
    uut.dedup_on.next = i.dedup_on;
    uut.dmr.next = i.dmr;
    uut.first_copy.next = i.first_copy;
    uut.acl.next = i.acl != 0;
    uut.release_set.next = i.release_set;
    uut.window.next = (i.window as u64).into();
    uut.tick.next = i.tick;
    uut.pop.next = i.pop;
    uut.rxv_a.next = i.rx_valid[0];
    uut.rxv_b.next = i.rx_valid[1];
    uut.frame_a.next = frame_bits(&frame[0]);
    uut.frame_b.next = frame_bits(&frame[1]);
}

/// The block's outputs and state after the edge against the model's: the
/// events (`fifo`: its pre-edge `fifo_wr`, `fifo_data`, `rx_evt`,
/// `overrun_evt`), the writer's state and flags, the statistics and the FIFO.
fn compare(
    uut: &RxBench,
    m: &RxPath,
    pre: &RxPath,
    ev: &RxEvents,
    fifo: (bool, Bits<116>, bool, bool),
    popped: bool,
    ctx: &dyn Fn() -> String,
) {
    let (fifo_wr, fifo_data, rx_evt, overrun_evt) = fifo;
    assert_eq!(rx_evt, ev.rx, "rx_evt, {}", ctx());
    assert_eq!(fifo_wr, ev.rx, "fifo_wr, {}", ctx());
    assert_eq!(overrun_evt, ev.overrun, "overrun_evt, {}", ctx());
    if ev.rx {
        let slot = ((pre.head + pre.count) & 31) as usize;
        // [115:100], the timestamp (§11.2), is the system lock step's
        assert_eq!(
            fifo_data.get_bits::<100>(0),
            entry_bits(&m.ram[slot]),
            "fifo_data, {}",
            ctx()
        );
    }
    let w = &uut.rxw;
    assert_eq!(w.w_state.q.val().to_u8(), m.w_state, "w_state, {}", ctx());
    let (hv, hu, hd) = flags_of(w);
    assert_eq!(hv, m.hv, "hv, {}", ctx());
    assert_eq!(hu, m.hu & m.hv, "hu of the valid entries, {}", ctx());
    assert_eq!(hd, m.hd & m.hv, "hd of the valid entries, {}", ctx());
    assert_eq!(w.release_q.q.val(), m.release, "release, {}", ctx());
    assert_eq!(
        w.duplicates.val().to_u16(),
        m.duplicates,
        "duplicates, {}",
        ctx()
    );
    assert_eq!(w.overruns.val().to_u16(), m.overruns, "overruns, {}", ctx());
    assert_eq!(
        w.pcl_frames.val().to_u16(),
        m.pcl_frames,
        "pcl_frames, {}",
        ctx()
    );
    assert_eq!(w.released.val().to_u8(), m.released, "released, {}", ctx());
    assert_eq!(w.expired.val().to_u8(), m.expired, "expired, {}", ctx());
    let omissions = [w.omissions_a.val().to_u16(), w.omissions_b.val().to_u16()];
    assert_eq!(omissions, m.omissions, "omissions, {}", ctx());
    let f = &uut.fifo;
    assert_eq!(f.head.q.val().to_u8(), m.head, "head, {}", ctx());
    assert_eq!(f.count.val().to_u8(), m.count, "count, {}", ctx());
    assert_eq!(f.rx_ready.val(), m.rx_ready, "rx_ready, {}", ctx());
    // the block's read data runs one pop ahead at a pop edge (rx_fifo.rs),
    // never observed: the register block blocks the access after a pop
    if m.rx_ready && !popped {
        assert_eq!(
            f.rd_data.val().get_bits::<100>(0),
            entry_bits(&m.rd),
            "FIFO head data, {}",
            ctx()
        );
    }
}

/// What this clock covered, from the model's pre-edge state and what it did.
fn count_coverage(
    cov: &mut Coverage,
    run: &Run,
    pre: &RxPath,
    m: &RxPath,
    ev: &RxEvents,
    inputs: &RxInputs,
) {
    let (rxv, release_set, acl) = (inputs.rx_valid, inputs.release_set, inputs.acl);
    if !inputs.reset_mode {
        cov.frames += rxv.iter().filter(|&&v| v).count() as u64;
        cov.duplicates += (m.duplicates != pre.duplicates) as u64;
        cov.overruns += ev.overrun as u64;
        cov.pcl_frames += (m.pcl_frames != pre.pcl_frames) as u64;
        cov.omissions += (m.omissions != pre.omissions) as u64;
        cov.acl_switches += release_set as u64;
        // an undelivered, unmatched entry left hv in a scan (§8 `expired`)
        let expired_now = run.dmr && pre.hv & !m.hv & !pre.hu & !pre.hd != 0;
        if expired_now && pre.w_state == W_SCAN {
            cov.expired_scan += 1;
        }
        if expired_now && pre.w_state == W_RSCAN {
            cov.expired_rscan += 1;
        }
        if run.dmr && pre.w_state == W_DECIDE && pre.hit {
            let waiting = pre.hd & (1 << pre.hit_e) == 0;
            let pcl = pre.sel != acl;
            if waiting && !pcl {
                assert_eq!(m.w_state, W_WRITE);
                cov.waiting_delivered += 1;
            }
            if waiting && pcl {
                cov.pcl_copy_of_waiting += 1;
            }
        }
        if run.dmr && pre.w_state == W_WRITE && pre.w_hist && pre.w_pcl {
            cov.hist_recorded_pcl += 1;
        }
        if pre.w_state == W_IDLE && m.w_state == W_RSCAN {
            cov.rscans += 1;
        }
        if pre.w_state == W_RSCAN && m.w_state == W_IDLE {
            cov.rscan_empty += 1;
        }
        if pre.w_state == W_RSCAN && pre.scan_i >= 1 && pre.rel_found {
            let e = pre.scan_i as usize - 1;
            let h = pre.hist[e];
            let age = pre.now.wrapping_sub(h.ts);
            let free = (pre.hv & !pre.hu & !pre.hd) >> e & 1 != 0;
            if free && h.ch == acl && age <= run.window && age == pre.rel_age {
                cov.release_ties += 1;
            }
        }
        if pre.w_state == W_RSCAN && m.w_state == W_FETCH {
            assert!(pre.scan_i == 32);
        }
        if pre.w_state == W_RELEASE {
            cov.releases += 1;
            cov.release_overruns += ev.overrun as u64;
        }
        if pre.hist_idle < 32767 && m.hist_idle == 32767 {
            cov.forgets += 1;
            cov.forgets_in_rscan += (pre.w_state == W_RSCAN) as u64;
            cov.forgets_valid += (pre.hv != 0) as u64;
            let judged = (1u64 << pre.scan_i.saturating_sub(1)) - 1;
            cov.forgets_valid_in_rscan +=
                (pre.hv as u64 & judged != 0 && pre.w_state == W_RSCAN) as u64;
        }
        if pre.w_state == W_WRITE && pre.w_hist && pre.hv == 0 && m.hv.count_ones() == 1 {
            cov.recorded_after_forget += 1;
        }
    }
}

fn run_lockstep(run: &Run, cov: &mut Coverage) {
    let mut rng = Rng::new(run.seed);
    let arrivals = schedule(run, &mut rng);
    let mut uut = RxBench::default();
    uut.connect_all();
    uut.clk.next = Clock::from(false);
    settle(&mut uut, "the RX writer bench");
    let mut m = RxPath::default();
    let mut frame = [Frame::default(); 2];
    let mut acl = 0u8;
    let mut pop_num = 1u64;
    let mut prev_pop = false;
    let mut reset_left = 0usize;
    let dedup_on = run.window != 0;
    for (clk, arrived) in arrivals.iter().enumerate() {
        // ---- stimulus for this clock ----
        let rst = clk < 3;
        if clk == 3 || (clk > 100 && rng.chance(1, 15000)) {
            reset_left = 4 + rng.below(8) as usize;
            cov.resets += 1;
        }
        let reset_mode = reset_left > 0;
        reset_left = reset_left.saturating_sub(1);
        if clk % 2000 == 0 {
            // pop phases: a stall (overruns), slow, fast
            pop_num = [0, 1, 1, 20, 60][rng.below(5) as usize];
        }
        let pop = !prev_pop && rng.below(200) < pop_num;
        let tick = clk % run.tick_period == 0;
        let mut rxv = [false; 2];
        for (l, a) in arrived.iter().enumerate() {
            if let Some(f) = a {
                frame[l] = *f;
                rxv[l] = true;
            }
        }
        let release_set =
            run.dmr && !rst && !reset_mode && clk > 50 && rng.chance(1, run.acl_every);
        if rst || reset_mode {
            // the ACL register reads DCL in reset mode (DMR contract §6)
            acl = 0;
        }
        let inputs = RxInputs {
            reset_mode,
            dedup_on,
            dmr: run.dmr,
            first_copy: run.first_copy,
            acl,
            release_set,
            window: run.window,
            tick,
            pop,
            rx_valid: rxv,
        };

        // ---- drive the block, read its pre-edge outputs ----
        drive(&mut uut, &inputs, rst, &frame);
        settle(&mut uut, "the RX writer bench");
        let fifo_wr = uut.rxw.fifo_wr.val();
        let fifo_data = uut.rxw.fifo_data.val();
        let rx_evt = uut.rxw.rx_evt.val();
        let overrun_evt = uut.rxw.overrun_evt.val();

        // ---- the model's edge ----
        let pre = m.clone();
        let ev = if rst {
            m.reset();
            Default::default()
        } else {
            m.edge(&inputs, [&frame[0], &frame[1]])
        };
        uut.clk.next = Clock::from(true);
        settle(&mut uut, "the RX writer bench");

        // ---- compare ----
        let ctx = || {
            format!(
                "seed {} clock {} (pre w_state {} scan_i {} sel {} hit {} hit_e {}; inputs {:?})",
                run.seed, clk, pre.w_state, pre.scan_i, pre.sel, pre.hit, pre.hit_e, inputs
            )
        };
        let popped = pop && pre.count != 0 && !rst && !reset_mode;
        compare(
            &uut,
            &m,
            &pre,
            &ev,
            (fifo_wr, fifo_data, rx_evt, overrun_evt),
            popped,
            &ctx,
        );
        prev_pop = pop;

        // ---- coverage (from the model's pre-edge state and what it did) ----
        if !rst {
            count_coverage(cov, run, &pre, &m, &ev, &inputs);
        }
        if release_set {
            acl ^= 1;
        }
    }
}

fn dmr_run(seed: u64) -> Run {
    let mut r = Rng::new(seed ^ 0xD1B5_4A32_D192_ED03);
    let tick_period = [4usize, 8, 16, 64][r.below(4) as usize];
    // a window of 150..1500 clocks: copies up to 600 clocks apart sometimes expire
    let window = ((150 + r.below(1350)) as usize / tick_period).max(1) as u16;
    Run {
        seed,
        clocks: 60_000,
        dmr: true,
        first_copy: false,
        window,
        tick_period,
        max_delay: 600,
        acl_every: 1200,
        pause: 0,
    }
}

fn assert_dmr_coverage(cov: &Coverage) {
    println!("{cov:#?}");
    let c = cov;
    for (name, v) in [
        ("frames", c.frames),
        ("duplicates", c.duplicates),
        ("overruns", c.overruns),
        ("expired in scan", c.expired_scan),
        ("expired in rscan", c.expired_rscan),
        ("pcl_frames", c.pcl_frames),
        (
            "waiting frame delivered by its ACL copy",
            c.waiting_delivered,
        ),
        ("PCL copy of a waiting frame", c.pcl_copy_of_waiting),
        ("PCL frame recorded undelivered", c.hist_recorded_pcl),
        ("ACL switches", c.acl_switches),
        ("release scans", c.rscans),
        ("release scans without a candidate", c.rscan_empty),
        ("release candidates of equal age", c.release_ties),
        ("releases", c.releases),
        ("release overruns", c.release_overruns),
        ("reset mode episodes", c.resets),
    ] {
        assert!(v > 0, "coverage: {name} never reached");
    }
}

#[test]
fn dmr_rx_lockstep_dmr_seeds() {
    let mut cov = Coverage::default();
    for seed in 1..=8 {
        run_lockstep(&dmr_run(seed), &mut cov);
    }
    assert_dmr_coverage(&cov);
}

/// DMR mode with `window = 0` (no history): ACL frames delivered, PCL dropped.
#[test]
fn dmr_rx_lockstep_dmr_no_history() {
    let mut cov = Coverage::default();
    for seed in 11..=12 {
        let run = Run {
            window: 0,
            ..dmr_run(seed)
        };
        run_lockstep(&run, &mut cov);
    }
    println!("{cov:#?}");
    assert!(cov.pcl_frames > 0 && cov.acl_switches > 0 && cov.frames > 0);
    assert_eq!(cov.rscans, 0, "no release scan without a history");
}

/// Regression: `dmr` = 0, redundancy dedup (first copy wins) and normal mode.
#[test]
fn dmr_rx_lockstep_redundancy_regression() {
    let mut cov = Coverage::default();
    for seed in 21..=23 {
        let run = Run {
            dmr: false,
            ..dmr_run(seed)
        };
        run_lockstep(&run, &mut cov);
    }
    let run = Run {
        dmr: false,
        window: 0,
        ..dmr_run(24)
    };
    run_lockstep(&run, &mut cov);
    println!("{cov:#?}");
    assert!(cov.duplicates > 0 && cov.overruns > 0 && cov.frames > 0);
    assert_eq!(cov.pcl_frames + cov.releases + cov.rscans, 0);
}

/// DMR first-copy delivery (§8.1): the first copy from either line is
/// delivered and the second dropped, as in redundancy mode, while the PCL's
/// frames are still counted; nothing waits, so no release scan ever runs, and
/// entries that expire unmatched count as omissions. With `window = 0` the ACL
/// rule stays.
#[test]
fn dmr_rx_lockstep_first_copy() {
    let mut cov = Coverage::default();
    for seed in 31..=34 {
        let run = Run {
            first_copy: true,
            ..dmr_run(seed)
        };
        run_lockstep(&run, &mut cov);
    }
    println!("{cov:#?}");
    assert!(cov.duplicates > 0 && cov.pcl_frames > 0 && cov.acl_switches > 0);
    assert!(cov.omissions > 0 && cov.overruns > 0);
    assert_eq!(
        cov.rscans + cov.releases + cov.expired_scan + cov.expired_rscan + cov.hist_recorded_pcl,
        0,
        "nothing waits"
    );
    let mut cov = Coverage::default();
    let run = Run {
        first_copy: true,
        window: 0,
        ..dmr_run(35)
    };
    run_lockstep(&run, &mut cov);
    assert!(cov.pcl_frames > 0 && cov.frames > 0);
    assert_eq!(cov.duplicates + cov.rscans, 0, "no history: the ACL rule");
}

/// A history left idle for 32767 bit times is forgotten (§7), also in the
/// middle of a release scan, and the next frames are recorded afresh: a bit
/// tick every clock, pauses past 32767 ticks, and ACL switches every few dozen
/// clocks so that release scans run through the pauses.
#[test]
fn dmr_rx_lockstep_idle_history_forgotten() {
    let mut cov = Coverage::default();
    for seed in 41..=46 {
        let run = Run {
            tick_period: 1,
            // the longest window: entries still valid when the history is forgotten
            window: 32767,
            clocks: 160_000,
            acl_every: 40,
            pause: 34_000,
            ..dmr_run(seed)
        };
        run_lockstep(&run, &mut cov);
    }
    println!("{cov:#?}");
    assert!(cov.forgets > 0, "the history was never forgotten");
    assert!(
        cov.forgets_in_rscan > 0,
        "never forgotten in a release scan"
    );
    assert!(cov.forgets_valid > 0, "never forgot a valid entry");
    assert!(
        cov.forgets_valid_in_rscan > 0,
        "never forgot a valid entry in the middle of a release scan"
    );
    assert!(cov.recorded_after_forget > 0 && cov.rscans > 0 && cov.releases > 0);
}
