//! Manual bus-off recovery (contract §11.6): `CTRL.busoff_manual`, `TX_CMD`
//! [3] `recover_a` and [4] `recover_b`, and the channels' `boff_hold` input
//! (timing contract §4.5). Node 0's line is cut (its receiver reads recessive),
//! so its own SOF and error flags are bit errors and TEC climbs past 255 (as in
//! `driver_features.rs`); with `busoff_manual` the channel then stays bus-off
//! until the host writes `recover_c`, and from the clock after that write it
//! needs the whole ISO 11898-1 recovery, 128 runs of 11 recessive bits. Expected
//! values are worked out from the contracts in the comments.

use super::*;

/// `CTRL.busoff_manual` (§3, §11.6).
const BUSOFF_MANUAL: u32 = 1 << 18;
/// `CTRL.dmr` (DMR contract §2).
const DMR: u32 = 1 << 17;
// TX_CMD fields (§3).
const PUSH: u32 = 1;
const ABORT_A: u32 = 1 << 1;
const ABORT_B: u32 = 1 << 2;
const RECOVER_A: u32 = 1 << 3;
const RECOVER_B: u32 = 1 << 4;
/// `DMR_STATUS` (DMR contract §2.1) and its `dcl_tx_fault` bit [3].
const DMR_STATUS: u8 = 28;
const DCL_TX_FAULT: u32 = 1 << 3;
/// Field code of DATA (timing contract §4.1).
const F_DATA: u8 = 10;
/// ISO 11898-1 12.1.4.2 rule l: 128 occurrences of 11 consecutive recessive
/// bits, counted at the channel's sample points.
const RECOVERY: u32 = 128 * 11;

/// Node 0's channel `c` (0 = A) probes after the last edge: `err_state`,
/// `sample_point`, `tx` pin.
fn chan(o: &DrccOutputs, c: usize) -> (u8, bool, bool) {
    let p = &o.probes;
    if c == 0 {
        (p.chan_a_err_state, p.chan_a_sample_point, o.chan_a_tx)
    } else {
        (p.chan_b_err_state, p.chan_b_sample_point, o.chan_b_tx)
    }
}

/// Node 0 alone on the buses with plain partners on A and B, configured with
/// `ctrl` in reset mode, then running with it and integrated. Returns the
/// system and the plain nodes' indices.
fn setup(ctrl: u32) -> (Sys, [usize; 2]) {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    sys.write(0, CTRL, RESET_MODE | ctrl);
    sys.start(0, ctrl);
    assert_eq!(sys.read(0, CTRL), ctrl, "configuration taken");
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
    sys.run(20 * CPB);
    (sys, [pa, pb])
}

/// Cuts node 0's line `c`, pushes `f` (normal mode: to queue `c`) and steps to
/// the edge where channel `c` becomes bus-off (TEC 256, §C.4.5), then on to the
/// clock its pin is recessive (from the next bit_start). The line stays cut.
/// Returns the channel's sample points after the bus-off edge.
fn cut_to_bus_off(sys: &mut Sys, c: usize, f: &Frame) -> u32 {
    sys.nodes[0].on[c] = false;
    sys.push(0, f, c as u32);
    for _ in 0..2000 * CPB {
        sys.step();
        if chan(&sys.nodes[0].out, c).0 == 2 {
            let mut n = 0;
            while !chan(&sys.nodes[0].out, c).2 {
                sys.step();
                let (es, sp, _) = chan(&sys.nodes[0].out, c);
                assert_eq!(es, 2);
                n += sp as u32;
            }
            return n;
        }
    }
    panic!("channel {c} never became bus-off");
}

/// Puts node 0's line `c` back two bit times after the channel went bus-off
/// (its `tx` is recessive from the bit after that, §C.4.5).
fn reconnect(sys: &mut Sys, c: usize) {
    sys.run(2 * CPB);
    assert!(
        chan(&sys.nodes[0].out, c).2,
        "a bus-off channel is recessive"
    );
    sys.nodes[0].on[c] = true;
}

/// Runs `bits` bit times in which channel `c` must stay bus-off with its pin
/// recessive at every clock.
fn held(sys: &mut Sys, c: usize, bits: u64) {
    for t in 0..bits * CPB {
        sys.step();
        let (es, _, tx) = chan(&sys.nodes[0].out, c);
        assert_eq!(es, 2, "channel {c} still bus-off {t} clocks on");
        assert!(tx, "channel {c} recessive while bus-off");
    }
}

/// A whole-word `TX_CMD` write by node 0: the request clock (the write is taken
/// at its edge) and the ack clock. Returns the outputs after the two edges.
fn tx_cmd(sys: &mut Sys, cmd: u32) -> [DrccOutputs; 2] {
    sys.nodes[0].wb = DrccInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: TX_CMD,
        wb_dat_w: cmd,
        wb_sel: 0xF,
        ..Default::default()
    };
    sys.step();
    let taken = sys.nodes[0].out;
    sys.nodes[0].wb = DrccInputs::default();
    sys.step();
    [taken, sys.nodes[0].out]
}

/// Steps until channel `c` leaves bus-off and returns its sample points from
/// the first step on, the recovering one included (it is a sample point). At
/// every step before it the channel is bus-off and recessive; at it TEC = REC
/// = 0 and error active (§C.4.5). `counted` sample points were already seen.
fn samples_to_recovery(sys: &mut Sys, c: usize, counted: u32) -> u32 {
    let mut n = counted;
    loop {
        sys.step();
        let (es, sp, tx) = chan(&sys.nodes[0].out, c);
        n += sp as u32;
        if es != 2 {
            assert!(sp, "the recovery is a SAMPLE edge");
            assert_eq!(es, 0, "error active after the recovery");
            let e = sys.read(0, [CHAN_A_ERR, CHAN_B_ERR][c]);
            assert_eq!(e & 0x1FF, 0, "TEC 0");
            assert_eq!(e >> 16 & 0xFF, 0, "REC 0");
            return n;
        }
        assert!(tx, "channel {c} recessive while bus-off");
        assert!(n <= 10 * RECOVERY, "channel {c} never recovered");
    }
}

/// The sample points of channel `c` in two outputs (a `tx_cmd`'s edges).
fn sps(o: &[DrccOutputs; 2], c: usize) -> u32 {
    o.iter().map(|o| chan(o, c).1 as u32).sum()
}

/// `busoff_manual` = 1, normal mode: channel `c`, driven bus-off, stays bus-off
/// with its pin recessive for 5 x 128 x 11 bit times of idle bus, keeping its
/// frame (queue `c` count 1, nothing on its bus), though the other channel's
/// `recover` bit (not bus-off: nothing, §11.6) was written at the start.
/// `recover_c` is taken (ack, not illegal) at edge E: `recover_c` is 1 after E,
/// so `boff_hold` is 0 from edge E+1 on and the channel recovers at exactly the
/// 1408th sample point from E+1 on (§11.6, timing contract §4.5: the counts
/// stood still at 0 since the bus-off entry). The held frame is then sent once
/// (tx_done, queue empty). The permission ended with the bus-off (it is 0 from
/// the first edge after the recovery): a second bus-off is held again.
fn manual_recovery(c: usize) {
    let (mut sys, plain) = setup(BUSOFF_MANUAL | policy(1) | k(1));
    let [own, other] = [[RECOVER_A, RECOVER_B][c], [RECOVER_A, RECOVER_B][1 - c]];
    let f = frame(0x0A5, false, false, 2, &[0x12, 0x34]);
    cut_to_bus_off(&mut sys, c, &f);
    reconnect(&mut sys, c);
    let o = tx_cmd(&mut sys, other);
    assert!(o[0].wb_ack, "the other channel's recover is taken");
    held(&mut sys, c, 5 * RECOVERY as u64);
    assert!(sys.plain[plain[c]].received.is_empty(), "nothing sent");
    let s = sys.read(0, STATUS);
    assert_eq!(s >> (9 + 2 * c) & 3, 2, "STATUS: channel {c} bus-off");
    assert_eq!(status_txq(s, c as u32), 1, "the frame stays in queue {c}");
    assert_eq!(sys.read(0, [CHAN_A_ERR, CHAN_B_ERR][c]) >> 24 & 3, 2);
    let o = tx_cmd(&mut sys, own);
    assert!(o[0].wb_ack && !o[0].wb_err, "recover_c is taken");
    // o[0] is edge E (still held); o[1] is E+1, the first edge that counts.
    let n = samples_to_recovery(&mut sys, c, chan(&o[1], c).1 as u32);
    assert_eq!(n, RECOVERY, "128 x 11 recessive bits after the write");
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
    sys.run(200 * CPB);
    assert_eq!(
        sys.plain[plain[c]].received,
        vec![f],
        "the held frame, once"
    );
    assert_eq!(status_txq(sys.read(0, STATUS), c as u32), 0);
    assert_eq!(sys.read(0, INT_STATUS) & I_TX_DONE, I_TX_DONE);

    // The permission is gone: the next bus-off is held again.
    let g = frame(0x0A6, false, false, 1, &[0x56]);
    cut_to_bus_off(&mut sys, c, &g);
    held(&mut sys, c, 3 * RECOVERY as u64);
}

#[test]
fn manual_recovery_of_a_waits_for_recover_a_then_takes_128_x_11_bits() {
    manual_recovery(0);
}

#[test]
fn manual_recovery_of_b_waits_for_recover_b_then_takes_128_x_11_bits() {
    manual_recovery(1);
}

/// `busoff_manual` = 0: the recovery is automatic, the 1408th recessive sample
/// point after the bus-off edge (the line stays cut: every sample is
/// recessive), as with the manual write above but counted from the bus-off
/// itself. A `recover_a` written half way is taken (§11.6: "still taken and
/// has no effect") and changes nothing: the count neither restarts nor stops.
#[test]
fn automatic_recovery_keeps_its_timing_and_ignores_recover() {
    let (mut sys, _) = setup(policy(1) | k(1));
    let mut n = cut_to_bus_off(&mut sys, 0, &frame(0x0A5, false, false, 1, &[1]));
    while n < 700 {
        sys.step();
        let (es, sp, tx) = chan(&sys.nodes[0].out, 0);
        assert!(es == 2 && tx);
        n += sp as u32;
    }
    let o = tx_cmd(&mut sys, RECOVER_A);
    assert!(o[0].wb_ack && !o[0].wb_err, "recover_a is taken");
    let n = samples_to_recovery(&mut sys, 0, n + sps(&o, 0));
    assert_eq!(n, RECOVERY, "ISO recovery from the bus-off edge");
}

/// A `recover` for a channel that is not bus-off does nothing (§11.6): written
/// for both channels while both are error active, it is taken (ack, not
/// illegal), and channel A, driven bus-off afterwards, is held as without it.
#[test]
fn recover_for_a_channel_not_bus_off_does_nothing() {
    let (mut sys, _) = setup(BUSOFF_MANUAL | policy(1) | k(1));
    let o = tx_cmd(&mut sys, RECOVER_A | RECOVER_B);
    assert!(o[0].wb_ack && !o[0].wb_err, "taken");
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0, "not illegal");
    sys.run(20 * CPB);
    cut_to_bus_off(&mut sys, 0, &frame(0x0A5, false, false, 1, &[1]));
    held(&mut sys, 0, 3 * RECOVERY as u64);
}

/// §9 and §11.6: `busoff_manual` is a cfg field. Outside reset mode a CTRL
/// write that changes it is `illegal` and only `reset_mode` is taken; in reset
/// mode it is taken. Checked both ways, and by behaviour: the refused set
/// leaves the recovery automatic (1408 samples from the bus-off), the refused
/// clear leaves the channel held.
#[test]
fn busoff_manual_is_a_cfg_field() {
    let base = policy(1) | k(1);
    for manual in [false, true] {
        let ctrl = if manual { BUSOFF_MANUAL | base } else { base };
        let (mut sys, _) = setup(ctrl);
        // Outside reset mode: change busoff_manual only.
        sys.write(0, CTRL, ctrl ^ BUSOFF_MANUAL);
        assert_eq!(
            sys.read(0, INT_STATUS) & I_ILLEGAL,
            I_ILLEGAL,
            "manual {manual}"
        );
        sys.write(0, INT_STATUS, I_ILLEGAL);
        assert_eq!(sys.read(0, CTRL), ctrl, "manual {manual}: not taken");
        let n = cut_to_bus_off(&mut sys, 0, &frame(0x0A5, false, false, 1, &[1]));
        if manual {
            held(&mut sys, 0, 3 * RECOVERY as u64);
        } else {
            assert_eq!(samples_to_recovery(&mut sys, 0, n), RECOVERY);
        }
        // With reset_mode: reset_mode is taken, the change is not (illegal).
        sys.write(0, CTRL, RESET_MODE | (ctrl ^ BUSOFF_MANUAL));
        assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, I_ILLEGAL);
        sys.write(0, INT_STATUS, I_ILLEGAL);
        assert_eq!(sys.read(0, CTRL), RESET_MODE | ctrl);
        // In reset mode the change is taken.
        sys.write(0, CTRL, RESET_MODE | (ctrl ^ BUSOFF_MANUAL));
        assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
        assert_eq!(sys.read(0, CTRL), RESET_MODE | (ctrl ^ BUSOFF_MANUAL));
    }
}

/// §11.6 refusals: a `recover` in a write refused for another reason is not
/// taken: `push` with an abort (§11.5) and a partial write (§2) end with ERR
/// and leave channel A held. Combined with a legal abort (of the empty queue B,
/// which does nothing) it is taken: the recovery follows, exactly 1408 sample
/// points after the write.
#[test]
fn recover_in_a_refused_write_is_not_taken() {
    let (mut sys, _) = setup(BUSOFF_MANUAL | policy(1) | k(1));
    cut_to_bus_off(&mut sys, 0, &frame(0x0A5, false, false, 1, &[1]));
    for cmd in [
        PUSH | ABORT_A | RECOVER_A,
        PUSH | ABORT_B | RECOVER_A,
        PUSH | ABORT_A | RECOVER_A | RECOVER_B,
    ] {
        let o = tx_cmd(&mut sys, cmd);
        assert!(o[0].wb_err && !o[0].wb_ack, "TX_CMD {cmd:#x} refused");
        assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, I_ILLEGAL);
        sys.write(0, INT_STATUS, I_ILLEGAL);
    }
    // Byte lane 0 holds recover_a (bit 3): a partial write, refused by §2.
    let (_, err) = sys.access_lanes(0, TX_CMD, true, RECOVER_A, 0b0001);
    assert!(err, "a partial TX_CMD write is refused");
    sys.write(0, INT_STATUS, I_ILLEGAL);
    held(&mut sys, 0, 3 * RECOVERY as u64);
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 1, "nothing dropped");
    let o = tx_cmd(&mut sys, ABORT_B | RECOVER_A);
    assert!(
        o[0].wb_ack && !o[0].wb_err,
        "abort_b with recover_a is taken"
    );
    let n = samples_to_recovery(&mut sys, 0, chan(&o[1], 0).1 as u32);
    assert_eq!(n, RECOVERY);
}

/// §11.6 with §6: a write whose push is refused takes no `recover` either (a
/// refused write changes nothing). Queue A holds the frame of the held channel
/// A and 7 more: full (Q = 8 in the default configuration, §1.1). `push |
/// recover_a` to queue A is refused (ERR, illegal, count still 8) and A stays
/// held; the same write with the staged frame for queue B, which has room, is
/// taken: channel B sends that frame and A recovers 1408 sample points later.
#[test]
fn recover_with_a_refused_push_is_not_taken() {
    let (mut sys, [_, pb]) = setup(BUSOFF_MANUAL | policy(1) | k(1));
    cut_to_bus_off(&mut sys, 0, &frame(0x0A5, false, false, 1, &[1]));
    for i in 0..7 {
        sys.push(0, &frame(0x0B0 + i, false, false, 1, &[i as u8]), 0);
    }
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 8, "queue A full");
    // The staged frame is the last one, TX_CTRL.queue 0.
    let o = tx_cmd(&mut sys, PUSH | RECOVER_A);
    assert!(
        o[0].wb_err && !o[0].wb_ack,
        "a push to a full queue is refused"
    );
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, I_ILLEGAL);
    sys.write(0, INT_STATUS, I_ILLEGAL);
    held(&mut sys, 0, 3 * RECOVERY as u64);
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 8);
    let g = frame(0x0C1, false, false, 1, &[0x99]);
    sys.write(0, TX_ID, g.id);
    sys.write(0, TX_CTRL, 1 | 1 << 8);
    sys.write(0, TX_DATA0, 0x99);
    sys.write(0, TX_DATA1, 0);
    let o = tx_cmd(&mut sys, PUSH | RECOVER_A);
    assert!(
        o[0].wb_ack && !o[0].wb_err,
        "push to B with recover_a taken"
    );
    let n = samples_to_recovery(&mut sys, 0, chan(&o[1], 0).1 as u32);
    assert_eq!(n, RECOVERY);
    assert_eq!(sys.plain[pb].received, vec![g], "B sent the pushed frame");
}

/// DMR mode (§11.6 "in every mode"): the DCL channel (A) driven bus-off is held
/// and the line's fault (DMR contract §7, `dcl_tx_fault`) stays; `recover_a`
/// with an abort is refused (§11.5: no abort in DMR mode) and not taken;
/// `recover_a` alone is taken and the recovery follows 1408 sample points
/// later.
#[test]
fn dmr_mode_holds_the_bus_off_line_until_recover() {
    let (mut sys, _) = setup(DMR | BUSOFF_MANUAL | policy(1) | k(1));
    cut_to_bus_off(&mut sys, 0, &frame(0x0A5, false, false, 1, &[1]));
    reconnect(&mut sys, 0);
    held(&mut sys, 0, 2 * RECOVERY as u64);
    assert_ne!(sys.read(0, DMR_STATUS) & DCL_TX_FAULT, 0, "the fault stays");
    let o = tx_cmd(&mut sys, ABORT_A | RECOVER_A);
    assert!(o[0].wb_err, "an abort in DMR mode is refused");
    sys.write(0, INT_STATUS, I_ILLEGAL);
    held(&mut sys, 0, 2 * RECOVERY as u64);
    let o = tx_cmd(&mut sys, RECOVER_A);
    assert!(o[0].wb_ack && !o[0].wb_err, "recover_a is taken");
    let n = samples_to_recovery(&mut sys, 0, chan(&o[1], 0).1 as u32);
    assert_eq!(n, RECOVERY);
}

/// Redundancy mode: bus A stuck dominant in the middle of channel A's DATA field
/// makes its transmitter count +8 per 8 dominant bits (rule f) past 255; the
/// aux FSM fails A on the way (policy 1, error passive) and the main FSM sends
/// the message on B. With `busoff_manual` channel A then stays bus-off (the
/// line is recessive again) and its aux FSM stays `failed` (§5: a bus-off
/// channel is never restarted), while B carries every message, each once.
/// After `recover_a`, A recovers 1408 sample points later, is restarted and,
/// after its probation (`recovery_bits` 1024 bit times), valid again.
#[test]
fn redundancy_mode_keeps_a_held_channel_failed_and_loses_nothing() {
    let (mut sys, [pa, pb]) = setup(REDUNDANCY | BUSOFF_MANUAL | policy(1) | k(1));
    let frames: Vec<Frame> = (0..4)
        .map(|i| frame(0x300 + i, false, false, 8, &[0x55 ^ i as u8; 8]))
        .collect();
    sys.push(0, &frames[0], 0);
    let mut t = 0;
    while sys.nodes[0].out.probes.chan_a_field != F_DATA {
        sys.step();
        t += 1;
        assert!(t < 100 * CPB, "channel A sends the first message");
    }
    sys.stuck[0] = true;
    while chan(&sys.nodes[0].out, 0).0 != 2 {
        sys.step();
        t += 1;
        assert!(t < 1000 * CPB, "channel A never became bus-off");
    }
    sys.stuck[0] = false;
    sys.run(300 * CPB);
    assert_eq!(sys.plain[pb].received, frames[..1], "B carried the message");
    for f in &frames[1..] {
        sys.push(0, f, 0);
    }
    for t in 0..3 * RECOVERY as u64 * CPB {
        sys.step();
        let o = sys.nodes[0].out;
        assert_eq!(chan(&o, 0).0, 2, "A held {t} clocks on");
        assert_eq!(o.probes.aux_a_state, FAILED, "A stays failed");
    }
    assert_eq!(sys.plain[pb].received, frames, "every message, once, on B");
    assert!(
        sys.plain[pa].received.is_empty(),
        "nothing complete on bus A"
    );
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0);
    let o = tx_cmd(&mut sys, RECOVER_A);
    assert!(o[0].wb_ack);
    let n = samples_to_recovery(&mut sys, 0, chan(&o[1], 0).1 as u32);
    assert_eq!(n, RECOVERY);
    sys.run(1200 * CPB);
    assert_eq!(sys.nodes[0].out.probes.aux_a_state, VALID, "A valid again");
    assert_eq!(sys.read(0, STATS1) >> 16, 1, "one recovery");
    // The message A was sending when it failed went on B only: A dropped it.
    assert!(sys.plain[pa].received.is_empty(), "no second copy on A");
    assert_eq!(sys.plain[pb].received, frames);
}

/// Entering reset mode resets the channels, which ends a held bus-off as at
/// power-up without `recover_a` (§11.6, §C.6): after the CTRL write TEC is 0
/// and the channel error active; leaving reset mode, a frame is sent on A.
#[test]
fn reset_mode_ends_a_held_bus_off() {
    let ctrl = BUSOFF_MANUAL | policy(1) | k(1);
    let (mut sys, [pa, _]) = setup(ctrl);
    cut_to_bus_off(&mut sys, 0, &frame(0x0A5, false, false, 1, &[1]));
    reconnect(&mut sys, 0);
    held(&mut sys, 0, 2 * RECOVERY as u64);
    sys.write(0, CTRL, RESET_MODE | ctrl);
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
    let e = sys.read(0, CHAN_A_ERR);
    assert_eq!((e & 0x1FF, e >> 24 & 3), (0, 0), "TEC 0, error active");
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0, "queue emptied");
    sys.start(0, ctrl);
    sys.run(20 * CPB);
    let f = frame(0x0A7, false, false, 1, &[7]);
    sys.push(0, &f, 0);
    sys.run(200 * CPB);
    assert_eq!(sys.plain[pa].received, vec![f]);
}
