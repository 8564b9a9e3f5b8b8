//! Acceptance filters (contract §11.1): the identifier / mask pairs `FILT_ID0`,
//! `FILT_MASK0`, `FILT_ID1`, `FILT_MASK1` at the RX FIFO's write port. Expected
//! values come from the contract's match rule `((word ^ FILT_IDk) & FILT_MASKk)
//! == 0` on the word `{rtr, ide, id}`, worked out by hand in the comments.

use super::*;

// Word indices (§11).
pub(crate) const FILT_ID0: u8 = 42;
pub(crate) const FILT_MASK0: u8 = 43;
pub(crate) const FILT_ID1: u8 = 44;
pub(crate) const FILT_MASK1: u8 = 45;
pub(crate) const RX_TIME: u8 = 46;
pub(crate) const STATS_CLR: u8 = 47;
/// OMISSIONS (§3, §7).
pub(crate) const OMISSIONS: u8 = 37;

// FILT_* fields (§11): [28:0] id, [29] ide, [30] rtr, [31] enable (mask only).
pub(crate) const F_IDE: u32 = 1 << 29;
pub(crate) const F_RTR: u32 = 1 << 30;
pub(crate) const F_EN: u32 = 1 << 31;

/// Plain node `p` sends `f`; runs until it reports `tx_done`, then 10 bits more
/// (the DRCC's writer needs at most `H + 3` clocks after the frame's `rx_valid`,
/// §11.2).
pub(crate) fn send(sys: &mut Sys, p: usize, f: &Frame) {
    send_all(sys, &[(p, *f)]);
}

/// Several plain nodes start sending at the same edge (on their own buses).
pub(crate) fn send_all(sys: &mut Sys, frames: &[(usize, Frame)]) {
    let before: Vec<usize> = frames.iter().map(|&(p, _)| sys.plain[p].done).collect();
    for &(p, f) in frames {
        sys.plain[p].req = Some(f);
    }
    let mut clocks = 0;
    while frames
        .iter()
        .zip(&before)
        .any(|(&(p, _), &b)| sys.plain[p].done == b)
    {
        sys.step();
        clocks += 1;
        assert!(clocks < 300 * CPB, "plain nodes send {frames:?}");
    }
    sys.run(10 * CPB);
}

/// Writes the two filters of node `n` in reset mode, then leaves it with `ctrl`.
pub(crate) fn set_filters(sys: &mut Sys, n: usize, ctrl: u32, f: [(u32, u32); 2]) {
    sys.write(n, CTRL, ctrl | RESET_MODE);
    for (k, (id, mask)) in f.into_iter().enumerate() {
        sys.write(n, FILT_ID0 + 2 * k as u8, id);
        sys.write(n, FILT_MASK0 + 2 * k as u8, mask);
    }
    assert_eq!(sys.read(n, INT_STATUS) & I_ILLEGAL, 0, "filters written");
    sys.start(n, ctrl);
    sys.run(20 * CPB);
}

/// Node 0 receives `f` from plain node `p`: whether it was accepted (written into
/// the FIFO, INT_STATUS.rx), checking the FIFO's contents either way.
fn accepted(sys: &mut Sys, p: usize, f: &Frame) -> bool {
    sys.write(0, INT_STATUS, I_RX | I_OVERRUN);
    send(sys, p, f);
    let rx = sys.read(0, INT_STATUS) & (I_RX | I_OVERRUN);
    match sys.pop(0) {
        Some((got, _)) => {
            assert_eq!(got, *f, "the frame as received");
            assert_eq!(rx, I_RX, "written: INT_STATUS.rx");
            assert!(sys.pop(0).is_none());
            true
        }
        None => {
            assert_eq!(rx, 0, "dropped silently: no rx, no overrun");
            false
        }
    }
}

/// A base frame `id` with one data byte.
fn base(id: u32) -> Frame {
    frame(id, false, false, 1, &[id as u8])
}
/// An extended frame `id` with two data bytes.
fn ext(id: u32) -> Frame {
    frame(id, true, false, 2, &[0xE0, id as u8])
}

/// One filter, then two OR-ed, then none enabled, against base, extended and
/// remote frames received on channel A in normal mode.
#[test]
fn filters_match_identifier_ide_and_rtr_under_their_masks() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let ctrl = policy(1) | k(1);
    // No filter enabled (reset state): everything is accepted.
    sys.start(0, ctrl);
    sys.run(20 * CPB);
    assert!(accepted(&mut sys, pa, &base(0x124)));
    assert!(accepted(&mut sys, pa, &ext(0x1555_5123)));

    // Filter 0, a base filter as §11.1 recommends: id 0x123, mask id[10:0] and
    // the ide bit (ide 0). Base 0x123: word 0x123, xor 0 -> match, also as a
    // remote frame (rtr not in the mask: word 0x4000_0123 ^ 0x123 = 0x4000_0000,
    // & mask 0x2000_07FF = 0). Base 0x124: xor 0x007 -> no match. Extended
    // 0x1555_5123: word 0x3555_5123, xor 0x3555_5000, & mask = 0x2000_0000 (ide)
    // -> no match, though its low 11 bits are 0x123.
    let f0 = (0x123, 0x7FF | F_IDE | F_EN);
    set_filters(&mut sys, 0, ctrl, [f0, (0, 0)]);
    assert!(accepted(&mut sys, pa, &base(0x123)));
    assert!(accepted(&mut sys, pa, &frame(0x123, false, true, 2, &[])));
    assert!(!accepted(&mut sys, pa, &base(0x124)));
    assert!(!accepted(&mut sys, pa, &ext(0x1555_5123)));
    assert!(!accepted(&mut sys, pa, &ext(0x123)));

    // The same filter without the ide mask bit matches that extended frame:
    // xor 0x3555_5000 & 0x7FF = 0.
    set_filters(&mut sys, 0, ctrl, [(0x123, 0x7FF | F_EN), (0, 0)]);
    assert!(accepted(&mut sys, pa, &ext(0x1555_5123)));
    assert!(accepted(&mut sys, pa, &base(0x123)));
    assert!(!accepted(&mut sys, pa, &base(0x323)));

    // Filter 1 alone, an extended group of data frames: id 0x1ABC_DE00 with ide,
    // mask id[28:8], ide and rtr. 0x1ABC_DE42: xor 0x42 & mask 0x7FFF_FF00 = 0 ->
    // match. 0x1ABC_DF42: xor 0x100 -> no match. Its remote frame: xor
    // 0x4000_0042 -> rtr differs -> no match. Base 0x042: ide differs.
    let f1 = (0x1ABC_DE00 | F_IDE, 0x1FFF_FF00 | F_IDE | F_RTR | F_EN);
    set_filters(&mut sys, 0, ctrl, [(0, 0), f1]);
    assert!(accepted(&mut sys, pa, &ext(0x1ABC_DE42)));
    assert!(!accepted(&mut sys, pa, &ext(0x1ABC_DF42)));
    assert!(!accepted(
        &mut sys,
        pa,
        &frame(0x1ABC_DE42, true, true, 0, &[])
    ));
    assert!(!accepted(&mut sys, pa, &base(0x042)));
    assert!(!accepted(&mut sys, pa, &base(0x123)), "filter 0 disabled");

    // Both enabled: a frame either one matches is accepted (OR).
    set_filters(&mut sys, 0, ctrl, [f0, f1]);
    assert!(accepted(&mut sys, pa, &base(0x123)), "filter 0 matches");
    assert!(
        accepted(&mut sys, pa, &ext(0x1ABC_DEFF)),
        "filter 1 matches"
    );
    assert!(!accepted(&mut sys, pa, &base(0x124)), "neither");
    assert!(!accepted(&mut sys, pa, &ext(0x1555_5123)), "neither");

    // Identifiers and masks written but no enable bit: no filter is enabled,
    // every frame is accepted.
    set_filters(
        &mut sys,
        0,
        ctrl,
        [(0x123, 0x7FFF_FFFF), (0x3FF, 0x7FFF_FFFF)],
    );
    assert!(accepted(&mut sys, pa, &base(0x124)));
    assert!(accepted(&mut sys, pa, &ext(0x1ABC_DF42)));
    // One enabled filter that matches nothing present: the other's disabled
    // identifier does not help.
    set_filters(
        &mut sys,
        0,
        ctrl,
        [(0x3FF, 0x7FF | F_IDE | F_EN), (0x124, 0x7FF)],
    );
    assert!(!accepted(&mut sys, pa, &base(0x124)));
    assert!(accepted(&mut sys, pa, &base(0x3FF)));
}

/// §11.1 order at the write: not accepted -> dropped; else FIFO full -> overrun;
/// else written. With F = 4 (§1.1) and four accepted frames waiting, a rejected
/// frame raises nothing and counts nothing; an accepted one overruns.
#[test]
fn a_rejected_frame_is_no_overrun_when_the_fifo_is_full() {
    let p = DrccParams {
        rx_fifo_depth: 4,
        ..DrccParams::DEFAULT
    };
    let mut sys = Sys::with_params(1, &p);
    let pa = sys.add_plain(0, true);
    // Accept base 0x100..0x10F: mask id[10:4] and ide.
    set_filters(
        &mut sys,
        0,
        policy(1) | k(1),
        [(0x100, 0x7F0 | F_IDE | F_EN), (0, 0)],
    );
    for id in 0x100..0x104 {
        send(&mut sys, pa, &base(id));
    }
    assert_eq!(status_rx_count(sys.read(0, STATUS)), 4, "full");
    assert_eq!(sys.read(0, INT_STATUS) & (I_RX | I_OVERRUN), I_RX);
    sys.write(0, INT_STATUS, I_RX | I_OVERRUN);
    send(&mut sys, pa, &base(0x200));
    assert_eq!(
        sys.read(0, INT_STATUS) & (I_RX | I_OVERRUN),
        0,
        "dropped silently"
    );
    assert_eq!(sys.read(0, STATS0) >> 16, 0, "no overrun counted");
    // An accepted frame now overruns.
    send(&mut sys, pa, &base(0x104));
    assert_eq!(sys.read(0, INT_STATUS) & (I_RX | I_OVERRUN), I_OVERRUN);
    assert_eq!(sys.read(0, STATS0) >> 16, 1, "one overrun");
    for id in 0x100..0x104 {
        assert_eq!(sys.pop(0).map(|(f, ch)| (f.id, ch)), Some((id, 0)));
    }
    assert!(sys.pop(0).is_none());
}

/// Redundancy mode with duplicate removal: the filters act after it (§11.1), so
/// a rejected frame is still recorded in the history: its copy on the other
/// channel is cancelled (a duplicate), and a rejected frame only one channel
/// carried is still judged an omission when its entry expires (§7).
#[test]
fn rejected_frames_still_feed_duplicate_removal_and_omissions() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    // window 200 bit times; accept base 0x100 only.
    sys.write(0, DEDUP_CFG, 200);
    let ctrl = REDUNDANCY | policy(1) | k(1);
    set_filters(&mut sys, 0, ctrl, [(0x100, 0x7FF | F_IDE | F_EN), (0, 0)]);
    sys.write(0, INT_STATUS, 0x1_FFFF);

    // A rejected pair: the second copy is cancelled by the first's entry.
    let r = base(0x200);
    send_all(&mut sys, &[(pa, r), (pb, r)]);
    assert_eq!(sys.read(0, STATS0), 1, "duplicates 1, overruns 0");
    assert_eq!(status_rx_count(sys.read(0, STATUS)), 0);
    assert_eq!(sys.read(0, INT_STATUS) & (I_RX | I_OVERRUN), 0);
    // A copy arriving later (on B, some 70 bit times after A's: within the
    // window) is cancelled too.
    let r2 = base(0x201);
    send(&mut sys, pa, &r2);
    send(&mut sys, pb, &r2);
    assert_eq!(sys.read(0, STATS0), 2, "duplicates 2");
    assert_eq!(status_rx_count(sys.read(0, STATUS)), 0);

    // A rejected frame on A only; 300 bit times later (> window 200) an accepted
    // pair arrives: its scan expires the unmatched entry, an omission of B
    // (OMISSIONS[31:16], "only A delivered").
    send(&mut sys, pa, &base(0x202));
    sys.run(300 * CPB);
    let a = base(0x100);
    send_all(&mut sys, &[(pa, a), (pb, a)]);
    assert_eq!(sys.read(0, OMISSIONS), 1 << 16);
    assert_eq!(
        sys.read(0, STATS0),
        3,
        "the accepted pair: one more duplicate"
    );
    assert_eq!(sys.pop(0), Some((a, 0)), "delivered once, from A");
    assert!(sys.pop(0).is_none());
    assert_eq!(sys.read(0, INT_STATUS) & (I_RX | I_OVERRUN), I_RX);
}

/// The filters are cfg registers (§11.1, §3, §9): 0 after `rst`, written in reset
/// mode (FILT_ID [30:0], FILT_MASK [31:0]), refused outside it (ERR, illegal,
/// unchanged), kept over reset mode, cleared by `rst`. RX_TIME is read-only;
/// STATS_CLR is never refused and reads 0.
#[test]
fn filter_registers_are_cfg_registers() {
    let mut sys = Sys::new(1);
    for adr in [
        FILT_ID0, FILT_MASK0, FILT_ID1, FILT_MASK1, RX_TIME, STATS_CLR,
    ] {
        assert_eq!(sys.read(0, adr), 0, "word {adr} after rst");
    }
    let values = [
        (FILT_ID0, 0xFFFF_FFFF, 0x7FFF_FFFF),
        (FILT_MASK0, 0xFFFF_FFFF, 0xFFFF_FFFF),
        (FILT_ID1, 0x2000_0123, 0x2000_0123),
        (FILT_MASK1, 0x8000_07FF, 0x8000_07FF),
    ];
    for (adr, w, v) in values {
        let (_, err) = sys.access_lanes(0, adr, true, w, 0xF);
        assert!(!err, "word {adr} taken in reset mode");
        assert_eq!(sys.read(0, adr), v, "word {adr} as written");
    }
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
    sys.start(0, policy(1) | k(1));
    for (adr, _, v) in values {
        let (_, err) = sys.access_lanes(0, adr, true, 0x0000_0456, 0xF);
        assert!(err, "word {adr} refused outside reset mode");
        assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, I_ILLEGAL);
        sys.write(0, INT_STATUS, I_ILLEGAL);
        assert_eq!(sys.read(0, adr), v, "word {adr} unchanged");
    }
    // RX_TIME read-only, STATS_CLR never refused, both modes.
    for running in [true, false] {
        if !running {
            sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
        }
        assert!(
            sys.access_lanes(0, RX_TIME, true, 1, 0xF).1,
            "RX_TIME is RO"
        );
        assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, I_ILLEGAL);
        sys.write(0, INT_STATUS, I_ILLEGAL);
        for w in [0, 1, 0xFFFF_FFFF] {
            assert!(!sys.access_lanes(0, STATS_CLR, true, w, 0xF).1);
            assert_eq!(sys.read(0, STATS_CLR), 0, "write-only, reads 0");
        }
        assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0, "running {running}");
    }
    // Reset mode kept them; rst clears them.
    for (adr, _, v) in values {
        assert_eq!(sys.read(0, adr), v, "word {adr} kept over reset mode");
    }
    sys.nodes[0].wb.rst = true;
    sys.step();
    sys.nodes[0].wb.rst = false;
    for (adr, _, _) in values {
        assert_eq!(sys.read(0, adr), 0, "word {adr} cleared by rst");
    }
}
