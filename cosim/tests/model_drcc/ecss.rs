//! ECSS bus selection (contract §12): the registers `ECSS_CFG`, `ECSS_HB`,
//! `ECSS_PERIOD`, `ECSS_STATUS` (§12.1, refusals of §9), the selection rules of
//! §12.2 (missed heartbeat periods, toggles, the `ntoggle` bound, `no_master`,
//! a heartbeat on either bus) and the main FSM following the selected bus.
//! Heartbeats are frames sent by plain nodes on bus A / B. Expected clocks are
//! worked out from the rules in the comments, with the reset `BTR` (CPB = 8
//! clocks per bit time).
//!
//! Timing used throughout: leaving reset mode is the `CTRL` write's request
//! edge `E` (§2: the write takes effect at that edge). The tick counters are 0
//! after `E` (held in reset mode, §4.3), so with brp = 0 the nominal tick is
//! at the edges `E + 8k` (k >= 1), and the selection is `on` from `E + 1`.
//! Without a heartbeat, `hb_cnt` counts ticks; the edge after the
//! `period`-th tick finds `hb_cnt == period` and misses a period (rule 3, on
//! registered values), so the `ttoggle`-th missed period, a toggle, is at
//! `E + 8 * ttoggle * period + 1`. `irq` (only
//! `bus_toggle` enabled) rises one clock after the edge that sets the bit (§8).

use super::filters::{send, STATS_CLR};
use super::*;

// Word indices (§12.1).
const ECSS_CFG: u8 = 48;
const ECSS_HB: u8 = 49;
const ECSS_PERIOD: u8 = 50;
const ECSS_STATUS: u8 = 51;
/// `INT_STATUS.bus_toggle` (§3, §12.1).
const I_BUS_TOGGLE: u32 = 1 << 17;
/// `INT_STATUS`: every bit (§3: bits 0..17).
const I_ALL: u32 = 0x3_FFFF;

/// `ECSS_CFG`: [7:0] ttoggle, [15:8] ntoggle, [24] bdefault, [31] enable.
fn cfg(ttoggle: u32, ntoggle: u32, bdefault: bool, enable: bool) -> u32 {
    ttoggle | ntoggle << 8 | (bdefault as u32) << 24 | (enable as u32) << 31
}

/// `ECSS_STATUS`: [7:0] ctoggle, [8] bus, [9] no_master, [23:16] missed.
fn st(ctoggle: u32, bus: bool, no_master: bool, missed: u32) -> u32 {
    ctoggle | (bus as u32) << 8 | (no_master as u32) << 9 | missed << 16
}

/// Reset values (§12.1): ttoggle 3, ntoggle 3, bdefault A, disabled; heartbeat
/// base 0x701; period 100000; status 0.
const CFG_RESET: u32 = 3 | 3 << 8;
const HB_RESET: u32 = 0x701;
const PERIOD_RESET: u32 = 100_000;

/// Redundancy mode (error-passive policy, k = 1), running.
const RED: u32 = REDUNDANCY | policy(1) | k(1);

/// The heartbeat 0x701 as a base data frame.
fn hb() -> Frame {
    frame(0x701, false, false, 0, &[])
}

/// Reads INT_STATUS.illegal and clears it (W1C).
fn take_illegal(sys: &mut Sys) -> bool {
    let s = sys.read(0, INT_STATUS) & I_ILLEGAL != 0;
    sys.write(0, INT_STATUS, I_ILLEGAL);
    s
}

/// Configures node 0 in reset mode (`ECSS_HB` too, if given), enables only the
/// `bus_toggle` interrupt, and leaves reset mode with `ctrl`. Returns the edge
/// `E` that left reset mode.
fn setup(sys: &mut Sys, ecss_cfg: u32, hb_word: Option<u32>, period: u32, ctrl: u32) -> u64 {
    sys.write(0, ECSS_CFG, ecss_cfg);
    if let Some(w) = hb_word {
        sys.write(0, ECSS_HB, w);
    }
    sys.write(0, ECSS_PERIOD, period);
    sys.write(0, INT_ENABLE, I_BUS_TOGGLE);
    assert!(!take_illegal(sys), "legal configuration");
    sys.start(0, ctrl);
    // The request edge is the clock before the ack clock.
    sys.clock - 1
}

/// Steps until `irq` rises (at most `limit` clocks); checks and clears
/// `INT_STATUS.bus_toggle`. Returns the edge that set it (one before `irq`).
fn event(sys: &mut Sys, limit: u64) -> u64 {
    assert!(!sys.nodes[0].out.irq, "irq low before waiting");
    let start = sys.clock;
    while !sys.nodes[0].out.irq {
        sys.step();
        assert!(
            sys.clock - start <= limit,
            "no bus_toggle within {limit} clocks"
        );
    }
    let edge = sys.clock - 1;
    assert_ne!(sys.read(0, INT_STATUS) & I_BUS_TOGGLE, 0, "bus_toggle set");
    sys.write(0, INT_STATUS, I_ALL);
    edge
}

/// Steps `clocks` clocks and checks that `irq` stays low (no bus_toggle).
fn quiet(sys: &mut Sys, clocks: u64) {
    for _ in 0..clocks {
        sys.step();
        assert!(
            !sys.nodes[0].out.irq,
            "no bus_toggle at clock {}",
            sys.clock
        );
    }
}

/// Steps up to the edge `clock`.
fn run_to(sys: &mut Sys, clock: u64) {
    assert!(sys.clock <= clock);
    while sys.clock < clock {
        sys.step();
    }
}

/// Plain node `p` sends `f`; returns the clock of its `tx_done` (end of frame),
/// then runs 10 bit times more (as `filters::send`).
fn send_at(sys: &mut Sys, p: usize, f: &Frame) -> u64 {
    let before = sys.plain[p].done;
    sys.plain[p].req = Some(*f);
    while sys.plain[p].done == before {
        sys.step();
        assert!(sys.clock < 1 << 40);
    }
    let done = sys.clock;
    sys.run(10 * CPB);
    done
}

// ---------------------------------------------------------------------------
// (a), (b) registers
// ---------------------------------------------------------------------------

/// §12.1 reset values; `rst` restores them (and clears ctoggle), entering reset
/// mode keeps them.
#[test]
fn ecss_reset_values_and_what_keeps_them() {
    let mut sys = Sys::new(1);
    let reset = [
        (ECSS_CFG, CFG_RESET),
        (ECSS_HB, HB_RESET),
        (ECSS_PERIOD, PERIOD_RESET),
        (ECSS_STATUS, 0),
    ];
    for (adr, v) in reset {
        assert_eq!(sys.read(0, adr), v, "word {adr} at power-up");
    }
    // Configure, toggle once (ttoggle 1, period 4: E + 32), enter reset mode.
    let c = cfg(1, 5, false, true);
    let e = setup(&mut sys, c, Some(0x2000_1234), 4, RED);
    assert_eq!(event(&mut sys, 100), e + 8 * 4 + 1);
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, true, false, 0));
    sys.write(0, CTRL, RESET_MODE | RED);
    sys.run(2);
    // Kept: the cfg registers and ctoggle; the selection is back on bdefault (A).
    assert_eq!(sys.read(0, ECSS_CFG), c);
    assert_eq!(sys.read(0, ECSS_HB), 0x2000_1234);
    assert_eq!(sys.read(0, ECSS_PERIOD), 4);
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, false, false, 0));
    // rst: the reset values, ctoggle 0.
    sys.nodes[0].wb.rst = true;
    sys.step();
    sys.nodes[0].wb.rst = false;
    for (adr, v) in reset {
        assert_eq!(sys.read(0, adr), v, "word {adr} after rst");
    }
}

/// Legal writes in reset mode read back; every refusal of §12.1 / §9 sets
/// `illegal`, ends with ERR (§2) and stores nothing.
#[test]
fn ecss_refused_writes_store_nothing() {
    let mut sys = Sys::new(1);
    // Legal: extremes of every field.
    for (adr, v) in [
        (ECSS_CFG, cfg(1, 255, true, true)),
        (ECSS_CFG, cfg(255, 0, false, false)),
        (ECSS_HB, 0x3FFF_FFFF),
        (ECSS_HB, 0x0000_0123),
        (ECSS_PERIOD, 0x00FF_FFFF),
        (ECSS_PERIOD, 1),
    ] {
        sys.write(0, adr, v);
        assert!(!take_illegal(&mut sys), "legal write {v:#x} to word {adr}");
        assert_eq!(sys.read(0, adr), v, "word {adr} reads back");
    }
    sys.write(0, ECSS_CFG, CFG_RESET);
    sys.write(0, ECSS_HB, HB_RESET);
    sys.write(0, ECSS_PERIOD, PERIOD_RESET);
    assert!(!take_illegal(&mut sys));

    let refused_in_reset_mode = [
        // ttoggle 0 (with everything else legal).
        (ECSS_CFG, cfg(0, 2, true, true)),
        // ntoggle 256 written as a wider number: bit 16, reserved.
        (ECSS_CFG, 3 | 0x100 << 8),
        // Reserved [23:16] and [30:25].
        (ECSS_CFG, CFG_RESET | 1 << 20),
        (ECSS_CFG, CFG_RESET | 1 << 23),
        (ECSS_CFG, CFG_RESET | 1 << 25),
        (ECSS_CFG, CFG_RESET | 1 << 30),
        // ECSS_HB [31:30].
        (ECSS_HB, 0x701 | 1 << 30),
        (ECSS_HB, 0x701 | 1 << 31),
        // period 0, [31:24] set (alone and with a legal period).
        (ECSS_PERIOD, 0),
        (ECSS_PERIOD, 1 << 24),
        (ECSS_PERIOD, 0xFF00_0001),
        // ECSS_STATUS is read-only.
        (ECSS_STATUS, 0x0001_03FF),
    ];
    let check = |sys: &mut Sys, adr: u8, v: u32, what: &str| {
        let before = sys.read(0, adr);
        let (_, err) = sys.access_lanes(0, adr, true, v, 0xF);
        assert!(err, "{what}: write {v:#x} to word {adr} ends with ERR");
        assert!(take_illegal(sys), "{what}: write {v:#x} to word {adr}");
        assert_eq!(sys.read(0, adr), before, "{what}: word {adr} unchanged");
    };
    for (adr, v) in refused_in_reset_mode {
        check(&mut sys, adr, v, "reset mode");
    }
    // A partial write (§2).
    let (_, err) = sys.access_lanes(0, ECSS_PERIOD, true, 0x55, 0x1);
    assert!(err && take_illegal(&mut sys), "partial write refused");
    assert_eq!(sys.read(0, ECSS_PERIOD), PERIOD_RESET);

    // Outside reset mode (normal mode): legal values refused too.
    sys.start(0, policy(1) | k(1));
    assert!(!take_illegal(&mut sys));
    for (adr, v) in [
        (ECSS_CFG, cfg(1, 1, true, true)),
        (ECSS_HB, 0x123),
        (ECSS_PERIOD, 50),
        (ECSS_STATUS, 0),
    ] {
        check(&mut sys, adr, v, "outside reset mode");
    }
    assert_eq!(sys.read(0, ECSS_CFG), CFG_RESET);
    assert_eq!(sys.read(0, ECSS_HB), HB_RESET);
    assert_eq!(sys.read(0, ECSS_PERIOD), PERIOD_RESET);
}

// ---------------------------------------------------------------------------
// (c), (d) leaving reset mode, toggles without a heartbeat
// ---------------------------------------------------------------------------

/// `bus` is `bdefault` while the selection is off, so a node leaves reset mode
/// on `Bdefault`; the main FSM follows (`VA = !bus`, `VB = bus`): with B it
/// goes idle1 -> idle2 at once (tx_channel 1).
#[test]
fn ecss_leaves_reset_mode_on_bdefault() {
    for bdefault in [false, true] {
        let mut sys = Sys::new(1);
        sys.write(0, ECSS_CFG, cfg(3, 3, bdefault, true));
        sys.run(2);
        assert_eq!(
            sys.read(0, ECSS_STATUS),
            st(0, bdefault, false, 0),
            "reset mode: bus = bdefault"
        );
        let e = setup(&mut sys, cfg(3, 3, bdefault, true), None, 1000, RED);
        run_to(&mut sys, e + 10);
        assert_eq!(sys.read(0, ECSS_STATUS), st(0, bdefault, false, 0));
        let s = sys.read(0, STATUS);
        assert_eq!(s >> 4 & 1, bdefault as u32, "tx_channel = bus");
        assert_eq!(status_state(s), if bdefault { IDLE2 } else { IDLE1 });
        // Both aux FSMs valid: the choice is the selection's.
        assert_eq!(s >> 5 & 0xF, 0, "aux A, aux B valid");
    }
}

/// No heartbeat at all, ttoggle 3, ntoggle 2, period 10 bits: missed periods
/// at E + 80, E + 160; toggles at E + 240 and E + 480 (ctoggle 1, 2); the next
/// expiry, E + 720, raises no_master (bus_toggle, no toggle); then nothing.
#[test]
fn ecss_toggles_ntoggle_times_then_gives_up() {
    let mut sys = Sys::new(1);
    let e = setup(&mut sys, cfg(3, 2, false, true), None, 10, RED);
    // One period missed (tick 10 at E + 80), then two.
    run_to(&mut sys, e + 8 * 10 + 2);
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, false, 1));
    run_to(&mut sys, e + 8 * 20 + 2);
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, false, 2));
    assert_eq!(event(&mut sys, 200), e + 8 * 30 + 1, "first toggle");
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, true, false, 0));
    assert_eq!(event(&mut sys, 300), e + 8 * 60 + 1, "second toggle");
    assert_eq!(sys.read(0, ECSS_STATUS), st(2, false, false, 0));
    assert_eq!(event(&mut sys, 300), e + 8 * 90 + 1, "no_master");
    assert_eq!(sys.read(0, ECSS_STATUS), st(2, false, true, 0));
    // Given up: no further toggle, nothing counts.
    quiet(&mut sys, 8 * 200);
    assert_eq!(sys.read(0, ECSS_STATUS), st(2, false, true, 0));
}

/// ntoggle 0 = never toggle: the first expiry (ttoggle 1, period 7: E + 56)
/// raises no_master on bdefault B.
#[test]
fn ecss_ntoggle_zero_never_toggles() {
    let mut sys = Sys::new(1);
    let e = setup(&mut sys, cfg(1, 0, true, true), None, 7, RED);
    assert_eq!(event(&mut sys, 100), e + 8 * 7 + 1);
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, true, true, 0));
    quiet(&mut sys, 8 * 50);
}

/// The policy applies in redundancy mode with `enable` only: in normal mode, or
/// with enable 0, nothing counts or toggles; `bus` stays `bdefault` and with
/// enable 0 the main FSM keeps the aux FSMs' validity (channel A).
#[test]
fn ecss_needs_redundancy_and_enable() {
    for (ctrl, enable) in [(policy(1) | k(1), true), (RED, false)] {
        let mut sys = Sys::new(1);
        setup(&mut sys, cfg(1, 3, true, enable), None, 5, ctrl);
        quiet(&mut sys, 8 * 5 * 6);
        assert_eq!(sys.read(0, ECSS_STATUS), st(0, true, false, 0));
        let s = sys.read(0, STATUS);
        assert_eq!(s >> 4 & 1, 0, "tx_channel 0");
        assert_eq!(status_state(s), IDLE1);
    }
}

// ---------------------------------------------------------------------------
// (e), (f), (g) heartbeats
// ---------------------------------------------------------------------------

/// Heartbeats on the bus in use about every 150 bits (period 100, ttoggle 2:
/// a toggle needs 200 silent bits) keep the node there; after the last one the
/// toggle comes 200 bit times after it (the receiver's EOF, within two bits of
/// the sender's tx_done).
#[test]
fn ecss_heartbeat_on_the_bus_in_use_restarts_the_clock() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let e = setup(&mut sys, cfg(2, 3, false, true), None, 100, RED);
    let mut last = e;
    for _ in 0..6 {
        run_to(&mut sys, last + 8 * 90);
        assert!(!sys.nodes[0].out.irq);
        last = send_at(&mut sys, pa, &hb());
    }
    assert!(last > e + 8 * 600, "heartbeats over 3 toggle times");
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, false, 0));
    let t = event(&mut sys, 8 * 300);
    let d = t as i64 - (last + 8 * 200) as i64;
    assert!(
        (-16..=16).contains(&d),
        "toggle 200 bits after the heartbeat: {d}"
    );
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, true, false, 0));
}

/// ntoggle 1: a toggle to B, a heartbeat on B re-arms the bound (run 0), so
/// the next silence toggles again to A (ctoggle 2, not cleared by the
/// heartbeat); the silence after that gives up (run 1 = ntoggle) on A.
#[test]
fn ecss_heartbeat_rearms_the_bound_and_keeps_ctoggle() {
    let mut sys = Sys::new(1);
    let pb = sys.add_plain(1, true);
    let e = setup(&mut sys, cfg(2, 1, false, true), None, 100, RED);
    assert_eq!(event(&mut sys, 8 * 250), e + 8 * 200 + 1);
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, true, false, 0));
    let h = send_at(&mut sys, pb, &hb());
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, true, false, 0), "kept");
    let t = event(&mut sys, 8 * 250);
    assert!((t as i64 - (h + 8 * 200) as i64).abs() <= 16);
    assert_eq!(
        sys.read(0, ECSS_STATUS),
        st(2, false, false, 0),
        "toggled again: the heartbeat re-armed the bound"
    );
    assert_eq!(event(&mut sys, 8 * 250), t + 8 * 200, "then gives up");
    assert_eq!(sys.read(0, ECSS_STATUS), st(2, false, true, 0));
}

/// Before no_master, a heartbeat on the other bus neither toggles nor restarts
/// the clock: the toggle is at E + 8 * 200 as without it.
#[test]
fn ecss_heartbeat_on_the_other_bus_waits_for_the_missed_periods() {
    let mut sys = Sys::new(1);
    let pb = sys.add_plain(1, true);
    let e = setup(&mut sys, cfg(2, 3, false, true), None, 100, RED);
    run_to(&mut sys, e + 8 * 20);
    send(&mut sys, pb, &hb());
    assert_eq!(
        sys.read(0, ECSS_STATUS),
        st(0, false, false, 0),
        "no toggle"
    );
    // The first period is missed at E + 800 all the same.
    run_to(&mut sys, e + 8 * 100 + 2);
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, false, 1));
    send(&mut sys, pb, &hb());
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, false, 1));
    assert_eq!(event(&mut sys, 8 * 200), e + 8 * 200 + 1);
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, true, false, 0));
}

/// After no_master (ntoggle 0, ttoggle 2, period 100: at E + 1600), a heartbeat
/// on the other bus toggles at once (ctoggle 1, no_master 0) and the main FSM
/// follows; a heartbeat on the bus in use ends no_master without a toggle and
/// the missed periods count again from it.
#[test]
fn ecss_after_no_master_the_other_bus_wins_at_once() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    let e = setup(&mut sys, cfg(2, 0, false, true), None, 100, RED);
    assert_eq!(event(&mut sys, 8 * 250), e + 8 * 200 + 1);
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, true, 0));
    // On the bus in use: no_master ends, no toggle; 200 bits later it gives up
    // again (run 0 = ntoggle).
    let h = send_at(&mut sys, pa, &hb());
    assert!(!sys.nodes[0].out.irq);
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, false, 0));
    let t = event(&mut sys, 8 * 250);
    assert!((t as i64 - (h + 8 * 200) as i64).abs() <= 16);
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, true, 0));
    quiet(&mut sys, 8 * 300);
    // On the other bus: a toggle at the heartbeat's edge, the end of its
    // frame (the receiver's EOF, within two bits of the sender's tx_done).
    let before = sys.plain[pb].done;
    sys.plain[pb].req = Some(hb());
    let (mut irq, mut done) = (None, None);
    while irq.is_none() || done.is_none() {
        sys.step();
        if irq.is_none() && sys.nodes[0].out.irq {
            irq = Some(sys.clock - 1);
        }
        if done.is_none() && sys.plain[pb].done > before {
            done = Some(sys.clock);
        }
        assert!(sys.clock < h + 8 * 1000, "heartbeat sent, bus_toggle");
    }
    let (t, done) = (irq.unwrap(), done.unwrap());
    assert!(
        (t as i64 - done as i64).abs() <= 16,
        "at once: {t} vs {done}"
    );
    assert_ne!(sys.read(0, INT_STATUS) & I_BUS_TOGGLE, 0);
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, true, false, 0));
    let s = sys.read(0, STATUS);
    assert_eq!((s >> 4 & 1, status_state(s)), (1, IDLE2), "the FSM follows");
}

/// Frames sent on the bus in use from E + 10 bits, then silence: the toggle
/// edge and the last frame's tx_done clock.
fn toggle_after(hb_word: u32, frames: &[Frame]) -> (u64, u64, u64) {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    // period 200, ttoggle 2: 400 silent bits.
    let e = setup(&mut sys, cfg(2, 3, false, true), Some(hb_word), 200, RED);
    run_to(&mut sys, e + 8 * 10);
    let mut last = 0;
    for f in frames {
        last = send_at(&mut sys, pa, f);
    }
    assert!(last < e + 8 * 380, "frames sent before the toggle");
    // The node received every frame (RX FIFO count).
    assert_eq!(status_rx_count(sys.read(0, STATUS)), frames.len() as u32);
    let t = event(&mut sys, 8 * 900);
    assert_eq!(sys.read(0, ECSS_STATUS), st(1, true, false, 0));
    (e, last, t)
}

/// Not heartbeats: a remote frame, another identifier, the other format; a
/// base heartbeat compares 11 bits of ECSS_HB.id, an extended one 29.
#[test]
fn ecss_only_matching_data_frames_are_heartbeats() {
    // Base heartbeat 0x701 (ECSS_HB.id = 0x1FFF_F701: only [10:0] compared).
    let base_hb = 0x1FFF_F701;
    let not_hb = [
        frame(0x701, false, true, 0, &[]),
        frame(0x702, false, false, 0, &[]),
        frame(0x701, true, false, 0, &[]),
        frame(0x1FFF_F701, true, false, 0, &[]),
    ];
    let (e, _, t) = toggle_after(base_hb, &not_hb);
    assert_eq!(t, e + 8 * 400 + 1, "none of them restarted the clock");
    let (_, last, t) = toggle_after(base_hb, &[frame(0x701, false, false, 1, &[9])]);
    assert!(
        (t as i64 - (last + 8 * 400) as i64).abs() <= 16,
        "a heartbeat"
    );

    // Extended heartbeat 0x1ABC_D701 (ide).
    let ext_hb = 0x1ABC_D701 | 1 << 29;
    let not_hb = [
        frame(0x0ABC_D701, true, false, 0, &[]),
        frame(0x1ABC_D701, true, true, 0, &[]),
        frame(0x701, false, false, 0, &[]),
    ];
    let (e, _, t) = toggle_after(ext_hb, &not_hb);
    assert_eq!(t, e + 8 * 400 + 1, "none of them restarted the clock");
    let (_, last, t) = toggle_after(ext_hb, &[frame(0x1ABC_D701, true, false, 0, &[])]);
    assert!(
        (t as i64 - (last + 8 * 400) as i64).abs() <= 16,
        "a heartbeat"
    );
}

// ---------------------------------------------------------------------------
// (h) the main FSM follows, (i) STATS_CLR
// ---------------------------------------------------------------------------

/// ttoggle 1, period 200, ntoggle 2: toggles at E + 1600 (to B) and E + 3200
/// (to A). After each, STATUS.tx_channel is the bus, and a pushed message goes
/// on that bus only; the aux FSMs stay valid.
#[test]
fn ecss_main_fsm_sends_on_the_selected_bus() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    let e = setup(&mut sys, cfg(1, 2, false, true), None, 200, RED);
    let f = frame(0x123, false, false, 2, &[1, 2]);
    let g = frame(0x124, false, false, 1, &[3]);

    assert_eq!(event(&mut sys, 8 * 250), e + 8 * 200 + 1);
    let s = sys.read(0, STATUS);
    assert_eq!((s >> 4 & 1, status_state(s)), (1, IDLE2), "on B");
    sys.push(0, &f, 0);
    sys.run(100 * CPB);
    assert_eq!(sys.plain[pb].received, vec![f]);
    assert!(sys.plain[pa].received.is_empty());

    assert_eq!(event(&mut sys, 8 * 250), e + 8 * 400 + 1);
    sys.run(4);
    let s = sys.read(0, STATUS);
    assert_eq!((s >> 4 & 1, status_state(s)), (0, IDLE1), "back on A");
    assert_eq!(s >> 5 & 0xF, 0, "aux A, aux B valid");
    sys.push(0, &g, 0);
    sys.run(100 * CPB);
    assert_eq!(sys.plain[pa].received, vec![g]);
    assert_eq!(sys.plain[pb].received, vec![f]);
    assert_eq!(sys.read(0, ECSS_STATUS), st(2, false, false, 0));
}

/// STATS_CLR clears ctoggle only (bus kept); at the toggle's own edge the clear
/// wins (ctoggle 0 after it, the toggle and its interrupt still happen), one
/// edge earlier the toggle counts after the clear.
#[test]
fn ecss_stats_clr_clears_ctoggle() {
    // ttoggle 1, ntoggle 5, period 10: toggles at E + 80k + 1.
    let mut sys = Sys::new(1);
    let e = setup(&mut sys, cfg(1, 5, false, true), None, 10, RED);
    assert_eq!(event(&mut sys, 100), e + 81);
    assert_eq!(event(&mut sys, 100), e + 161);
    assert_eq!(sys.read(0, ECSS_STATUS), st(2, false, false, 0));
    sys.write(0, STATS_CLR, 1);
    assert_eq!(sys.read(0, ECSS_STATUS), st(0, false, false, 0));

    // A STATS_CLR request at edge `at`; the ctoggle after the toggle at E + 241.
    let clear_at = |at: u64| {
        let mut sys = Sys::new(1);
        let e = setup(&mut sys, cfg(1, 5, false, true), None, 10, RED);
        assert_eq!(event(&mut sys, 100), e + 81);
        assert_eq!(event(&mut sys, 100), e + 161);
        run_to(&mut sys, e + at - 1);
        sys.nodes[0].wb = DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: true,
            wb_adr: STATS_CLR,
            wb_dat_w: 1,
            wb_sel: 0xF,
            ..Default::default()
        };
        sys.step();
        assert!(sys.nodes[0].out.wb_ack);
        sys.nodes[0].wb = DrccInputs::default();
        assert_eq!(event(&mut sys, 100), e + 241, "the toggle happens");
        sys.read(0, ECSS_STATUS)
    };
    assert_eq!(
        clear_at(240),
        st(1, true, false, 0),
        "cleared, then counted"
    );
    assert_eq!(clear_at(241), st(0, true, false, 0), "the clear wins");
}
