//! Driver features (contract §10.2; `VERSION` and `SIZES` are in
//! `identification.rs`): the error and arbitration-lost captures `CAP_A` / `CAP_B` with their re-arm, and the
//! `err_warning`, `arb_lost` and `bus_error` interrupts (§10.2, §8). Expected
//! values come from the contract's tables and ISO 11898-1 arithmetic, worked out
//! in the comments.

use super::*;

// CAP_x fields (§3): [2:0] err_kind, [7:3] err_field, [8] err_tx, [9] err_valid,
// [20:16] alc, [21] alc_valid.
const fn cap_err(kind: u32, field: u32, tx: bool, valid: bool) -> u32 {
    kind | field << 3 | (tx as u32) << 8 | (valid as u32) << 9
}
const fn cap_alc(alc: u32, valid: bool) -> u32 {
    alc << 16 | (valid as u32) << 21
}

// Error kinds (timing contract §9) and field codes (timing contract §4.1).
const K_BIT: u32 = 1;
const K_ACK: u32 = 5;
const F_IDLE: u32 = 1;
const F_ACK_SLOT: u32 = 13;
const F_ERROR_FLAG: u32 = 18;

/// BTR with the reset timing (brp 0, tseg1 4, tseg2 1, sjw 0) and warning limit `ewl`.
const fn btr_ewl(ewl: u32) -> u32 {
    4 << 6 | 1 << 10 | ewl << 16
}

/// CHAN_x_ERR fields (§3): [8:0] TEC, [25:24] err_state, [26] err_warning.
fn tec(chan_err: u32) -> u32 {
    chan_err & 0x1FF
}
fn err_state(chan_err: u32) -> u32 {
    chan_err >> 24 & 3
}

/// Stages `f` on node `n` for TX queue `queue` (TX_ID..TX_DATA1, TX_CTRL).
fn stage(sys: &mut Sys, n: usize, f: &Frame, queue: u32) {
    let id = f.id | (f.ide as u32) << 29 | (f.rtr as u32) << 30;
    sys.write(n, TX_ID, id);
    sys.write(n, TX_CTRL, f.dlc as u32 | queue << 8);
    sys.write(
        n,
        TX_DATA0,
        u32::from_le_bytes(f.data[..4].try_into().unwrap()),
    );
    sys.write(
        n,
        TX_DATA1,
        u32::from_le_bytes(f.data[4..].try_into().unwrap()),
    );
}

/// `TX_CMD.push` on every node of `nodes` at the same edge.
fn push_together(sys: &mut Sys, nodes: &[usize]) {
    for &n in nodes {
        sys.nodes[n].wb = DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: true,
            wb_adr: TX_CMD,
            wb_dat_w: 1,
            ..Default::default()
        };
    }
    sys.step();
    for &n in nodes {
        assert!(sys.nodes[n].out.wb_ack, "push taken on node {n}");
        sys.nodes[n].wb = DrccInputs::default();
    }
    sys.step();
}

/// Two DRCC nodes on the dual bus in normal mode, integrated.
fn two_nodes() -> Sys {
    let mut sys = Sys::new(2);
    for n in 0..2 {
        sys.start(n, policy(1) | k(1));
    }
    sys.run(20 * CPB);
    sys
}

/// Node 0 and node 1 push a base data frame (`id0`, `id1`, DLC 1) on queue `ch`
/// (normal mode: queue A on channel A, B on B) at the same edge.
fn start_contest(sys: &mut Sys, ch: u32, id0: u32, id1: u32) {
    stage(sys, 0, &frame(id0, false, false, 1, &[0x5A]), ch);
    stage(sys, 1, &frame(id1, false, false, 1, &[0xA5]), ch);
    push_together(sys, &[0, 1]);
}

/// A whole contest on channel `ch`: both frames are sent (the loser retries after
/// the winner's frame). Checks that the two nodes' first dominant bits on `ch`
/// (their SOFs) fall in the same bit, so that an arbitration took place, and that
/// each node received the other's frame.
fn contest(sys: &mut Sys, ch: u32, id0: u32, id1: u32) {
    start_contest(sys, ch, id0, id1);
    let mut sof = [None, None];
    for _ in 0..300 * CPB {
        sys.step();
        for (n, s) in sof.iter_mut().enumerate() {
            let o = sys.nodes[n].out;
            let tx = if ch == 0 { o.chan_a_tx } else { o.chan_b_tx };
            if !tx && s.is_none() {
                *s = Some(sys.clock);
            }
        }
    }
    let [Some(s0), Some(s1)] = sof else {
        panic!("both nodes send on channel {ch}: {sof:?}")
    };
    assert!(
        s0.abs_diff(s1) < CPB,
        "both SOFs in the same bit (an arbitration): {s0} {s1}"
    );
    // Both frames were delivered, each to the other node (the loser retried).
    for (n, id) in [(0, id1), (1, id0)] {
        let (f, from) = sys.pop(n).expect("a frame received");
        assert_eq!(
            (f.id, from),
            (id, ch),
            "node {n} received the other's frame"
        );
        assert!(sys.pop(n).is_none());
    }
}

// ---------------------------------------------------------------------------
// §10.1 identification
// ---------------------------------------------------------------------------

const ALC_123_133: u32 = 6;
const ALC_120_122: u32 = 9;

/// The first lost arbitration of each channel is captured with its position and
/// raises INT_STATUS.arb_lost (and irq when enabled); a second loss does not
/// overwrite it; writing INT_STATUS.arb_lost re-arms both channels' captures
/// (alc kept, alc_valid 0) and the next loss is captured; reset mode keeps the
/// captures, rst clears them.
#[test]
fn arbitration_loss_is_captured_held_and_rearmed() {
    let mut sys = two_nodes();
    sys.write(1, INT_ENABLE, I_ARB_LOST);
    for n in 0..2 {
        assert_eq!(sys.read(n, CAP_A), 0, "node {n}: CAP_A after reset");
        assert_eq!(sys.read(n, CAP_B), 0, "node {n}: CAP_B after reset");
    }
    assert!(!sys.nodes[1].out.irq);

    // Round 1: A 0x123 vs 0x133, then B 0x120 vs 0x122.
    contest(&mut sys, 0, 0x123, 0x133);
    assert_eq!(sys.read(1, CAP_A), cap_alc(ALC_123_133, true));
    assert_eq!(sys.read(1, CAP_B), 0, "nothing lost on B yet");
    assert_eq!(
        sys.read(1, INT_STATUS) & (I_ARB_LOST | I_BUS_ERROR),
        I_ARB_LOST,
        "arb_lost, and no error"
    );
    assert!(sys.nodes[1].out.irq, "irq with arb_lost enabled");
    // The winner lost nothing.
    assert_eq!(sys.read(0, CAP_A), 0);
    assert_eq!(sys.read(0, INT_STATUS) & I_ARB_LOST, 0);
    contest(&mut sys, 1, 0x120, 0x122);
    assert_eq!(sys.read(1, CAP_B), cap_alc(ALC_120_122, true));
    assert_eq!(sys.read(1, CAP_A), cap_alc(ALC_123_133, true));

    // Round 2, swapped, no re-arm: both captures hold the first loss.
    contest(&mut sys, 0, 0x120, 0x122);
    contest(&mut sys, 1, 0x123, 0x133);
    assert_eq!(sys.read(1, CAP_A), cap_alc(ALC_123_133, true), "A held");
    assert_eq!(sys.read(1, CAP_B), cap_alc(ALC_120_122, true), "B held");

    // Re-arm: one write of INT_STATUS.arb_lost clears both alc_valid, the
    // positions stay readable.
    sys.write(1, INT_STATUS, I_ARB_LOST);
    assert_eq!(sys.read(1, INT_STATUS) & I_ARB_LOST, 0);
    assert_eq!(sys.read(1, CAP_A), cap_alc(ALC_123_133, false));
    assert_eq!(sys.read(1, CAP_B), cap_alc(ALC_120_122, false));
    assert!(!sys.nodes[1].out.irq);

    // Round 3 = round 2, B first: now captured; a loss on B alone raises the
    // interrupt.
    contest(&mut sys, 1, 0x123, 0x133);
    assert_eq!(sys.read(1, CAP_B), cap_alc(ALC_123_133, true), "B re-armed");
    assert_eq!(
        sys.read(1, CAP_A),
        cap_alc(ALC_123_133, false),
        "A untouched"
    );
    assert_eq!(sys.read(1, INT_STATUS) & I_ARB_LOST, I_ARB_LOST, "B's loss");
    assert!(sys.nodes[1].out.irq);
    contest(&mut sys, 0, 0x120, 0x122);
    assert_eq!(sys.read(1, CAP_A), cap_alc(ALC_120_122, true), "A re-armed");

    // Reset mode keeps the captures; rst clears them.
    sys.write(1, CTRL, RESET_MODE | policy(1) | k(1));
    sys.run(10);
    assert_eq!(sys.read(1, CAP_A), cap_alc(ALC_120_122, true));
    assert_eq!(sys.read(1, CAP_B), cap_alc(ALC_123_133, true));
    sys.nodes[1].wb.rst = true;
    sys.step();
    sys.nodes[1].wb.rst = false;
    assert_eq!(sys.read(1, CAP_A), 0, "rst clears CAP_A");
    assert_eq!(sys.read(1, CAP_B), 0, "rst clears CAP_B");
}

/// Node 1 has lost a contest 0x120 vs 0x122 on A and holds alc 9 (not re-armed,
/// INT_STATUS.arb_lost set, enabled); a contest 0x123 vs 0x133 (alc 6) has just
/// been pushed.
fn race_setup() -> Sys {
    let mut sys = two_nodes();
    sys.write(1, INT_ENABLE, I_ARB_LOST);
    contest(&mut sys, 0, 0x120, 0x122);
    assert_eq!(sys.read(1, CAP_A), cap_alc(ALC_120_122, true));
    start_contest(&mut sys, 0, 0x123, 0x133);
    sys
}

/// Writes INT_STATUS = `w` on node 1 so that it is taken at the edge of the
/// `at`-th step from now, then runs to the end of the contest; returns
/// (CAP_A, INT_STATUS.arb_lost) of node 1.
fn race(at: Option<u64>, w: u32) -> (u32, u32) {
    let mut sys = race_setup();
    if let Some(at) = at {
        sys.run(at - 1);
        sys.nodes[1].wb = DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: true,
            wb_adr: INT_STATUS,
            wb_dat_w: w,
            ..Default::default()
        };
        sys.step();
        assert!(sys.nodes[1].out.wb_ack);
        sys.nodes[1].wb = DrccInputs::default();
    }
    sys.run(300 * CPB);
    (sys.read(1, CAP_A), sys.read(1, INT_STATUS) & I_ARB_LOST)
}

/// §10.2: "A capture at the same edge wins" over the re-arm, as an event wins
/// over the W1C clear (§8); one edge later the re-arm only clears.
#[test]
fn capture_at_the_rearm_edge_wins() {
    // Find the edge of the loss: re-armed (and INT_STATUS cleared) right away,
    // node 1's irq (arb_lost enabled) rises one clock after the edge that sets
    // INT_STATUS.arb_lost, which is the edge that sees the channel's arb_lost.
    let mut sys = race_setup();
    sys.write(1, INT_STATUS, I_ARB_LOST);
    assert!(!sys.nodes[1].out.irq);
    let mut steps = 2; // the write's two clocks
    while !sys.nodes[1].out.irq {
        sys.step();
        steps += 1;
        assert!(steps < 200 * CPB, "node 1 loses arbitration");
    }
    let edge = steps - 1;
    sys.run(300 * CPB);
    assert_eq!(
        sys.read(1, CAP_A),
        cap_alc(ALC_123_133, true),
        "re-armed before"
    );

    // Not re-armed: the old loss holds.
    assert_eq!(race(None, 0), (cap_alc(ALC_120_122, true), I_ARB_LOST));
    // Re-armed at the loss's edge: the new loss is captured, the INT bit stays set.
    assert_eq!(
        race(Some(edge), I_ARB_LOST),
        (cap_alc(ALC_123_133, true), I_ARB_LOST)
    );
    // One edge later: the loss was refused (held), the write then re-arms and
    // clears the INT bit set one edge before.
    assert_eq!(
        race(Some(edge + 1), I_ARB_LOST),
        (cap_alc(ALC_120_122, false), 0)
    );
    // A W1C write without bit 11 at that edge re-arms nothing.
    assert_eq!(
        race(Some(edge), I_BUS_ERROR),
        (cap_alc(ALC_120_122, true), I_ARB_LOST)
    );
}

// ---------------------------------------------------------------------------
// §10.2 error capture
// ---------------------------------------------------------------------------

/// A node alone on its buses: every attempt ends with an ACK error as
/// transmitter (ISO 11898-1 10.11.5): err_kind 5, err_field ACK_SLOT (13), err_tx 1.
/// The first error is captured and raises INT_STATUS.bus_error (irq one clock
/// after); later errors, also of another kind, do not overwrite it; reset mode
/// keeps it; writing INT_STATUS.bus_error re-arms both channels; rst clears.
#[test]
fn error_capture_holds_the_first_error_until_rearmed() {
    // 5 | 13 << 3 | 1 << 8 | 1 << 9 = 0x36D.
    let ack = cap_err(K_ACK, F_ACK_SLOT, true, true);
    assert_eq!(ack, 0x36D);
    let mut sys = Sys::new(1);
    sys.write(0, INT_ENABLE, I_BUS_ERROR);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    sys.push(0, &frame(0x155, false, false, 1, &[0xA5]), 0);
    sys.push(0, &frame(0x0AA, false, false, 1, &[0x5A]), 1);
    // The ACK error: TEC + 8 (rule c) at the ACK slot's SAMPLE edge, where the
    // channel also raises err_valid; the DRCC sees it at the next edge
    // (INT_STATUS.bus_error and CAP_A), irq follows one edge later: irq rises 2
    // clocks after the TEC probe. (B's frame starts 10 clocks later.)
    let mut tec8 = None;
    let mut irq = None;
    for _ in 0..200 * CPB {
        sys.step();
        let o = sys.nodes[0].out;
        if o.probes.chan_a_bsp_tx_err_cnt == 8 && tec8.is_none() {
            tec8 = Some(sys.clock);
        }
        if o.irq && irq.is_none() {
            irq = Some(sys.clock);
        }
    }
    let (tec8, irq) = (tec8.expect("an ACK error on A"), irq.expect("irq"));
    assert_eq!(
        irq,
        tec8 + 2,
        "bus_error one edge after err_valid, irq one after"
    );
    sys.run(400 * CPB);
    assert!(
        tec(sys.read(0, CHAN_A_ERR)) >= 24,
        "several ACK errors on A"
    );
    assert!(
        tec(sys.read(0, CHAN_B_ERR)) >= 24,
        "several ACK errors on B"
    );
    assert_eq!(sys.read(0, CAP_A), ack);
    assert_eq!(sys.read(0, CAP_B), ack);
    assert_eq!(
        sys.read(0, INT_STATUS) & (I_BUS_ERROR | I_ARB_LOST),
        I_BUS_ERROR
    );

    // Reset mode: the channels restart (TEC 0), the captures stay.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
    assert_eq!(sys.read(0, CAP_A), ack, "reset mode keeps CAP_A");
    assert_eq!(sys.read(0, CAP_B), ack, "reset mode keeps CAP_B");
    assert_eq!(tec(sys.read(0, CHAN_A_ERR)), 0);

    // Line A cut from the node (its rx reads recessive): its SOF is read back
    // recessive, a bit error in IDLE (timing contract §4.4), then every bit of its
    // active error flag is a bit error (rule d, field ERROR_FLAG) until bus-off.
    // Not re-armed: CAP_A keeps the ACK error.
    sys.nodes[0].on[0] = false;
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    sys.push(0, &frame(0x155, false, false, 1, &[0xA5]), 0);
    // 16 flag bit errors make it error passive (TEC 128); its passive flags are
    // not checked, but every retry's SOF is another bit error: 16 more to TEC 256,
    // bus-off, each retry some 30 bits (flag, delimiter, intermission, suspend).
    sys.run(1000 * CPB);
    assert_eq!(err_state(sys.read(0, CHAN_A_ERR)), 2, "A erred to bus-off");
    assert_eq!(sys.read(0, CAP_A), ack, "held: a later bit error");

    // Re-arm with one write: both err_valid clear, the fields stay.
    sys.write(0, INT_STATUS, I_BUS_ERROR);
    let ack_old = cap_err(K_ACK, F_ACK_SLOT, true, false);
    assert_eq!(sys.read(0, CAP_A), ack_old);
    assert_eq!(sys.read(0, CAP_B), ack_old);
    assert_eq!(
        sys.read(0, INT_STATUS) & I_BUS_ERROR,
        0,
        "bus-off: no error"
    );
    assert!(!sys.nodes[0].out.irq);

    // Restart A (reset mode) and send again on the cut line: the first error
    // after the re-arm is the SOF's bit error, kind 1 in IDLE (1 | 1 << 3 | tx |
    // valid = 0x309); the bit errors in the flag (kind 1 in ERROR_FLAG, 0x391)
    // that follow up to bus-off do not overwrite it.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    sys.push(0, &frame(0x155, false, false, 1, &[0xA5]), 0);
    sys.run(1000 * CPB);
    assert_eq!(err_state(sys.read(0, CHAN_A_ERR)), 2, "A erred to bus-off");
    assert_eq!(sys.read(0, CAP_A), cap_err(K_BIT, F_IDLE, true, true));
    assert_eq!(cap_err(K_BIT, F_IDLE, true, true), 0x309);
    assert_ne!(sys.read(0, CAP_A), cap_err(K_BIT, F_ERROR_FLAG, true, true));
    assert_eq!(sys.read(0, CAP_B), ack_old, "B had no error since");
    assert_eq!(sys.read(0, INT_STATUS) & I_BUS_ERROR, I_BUS_ERROR);
    assert!(sys.nodes[0].out.irq);

    // Re-arm again, line A back, and an ACK error on B alone: it raises
    // bus_error and fills CAP_B; CAP_A keeps its fields, not valid.
    sys.write(0, INT_STATUS, I_BUS_ERROR);
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
    sys.nodes[0].on[0] = true;
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    assert_eq!(sys.read(0, INT_STATUS) & I_BUS_ERROR, 0);
    sys.push(0, &frame(0x0AA, false, false, 1, &[0x5A]), 1);
    sys.run(200 * CPB);
    assert_eq!(
        sys.read(0, INT_STATUS) & I_BUS_ERROR,
        I_BUS_ERROR,
        "B's error"
    );
    assert_eq!(sys.read(0, CAP_B), ack);
    assert_eq!(sys.read(0, CAP_A), cap_err(K_BIT, F_IDLE, true, false));
    assert_eq!(tec(sys.read(0, CHAN_A_ERR)), 0, "no error on A");

    // rst clears both.
    sys.nodes[0].wb.rst = true;
    sys.step();
    sys.nodes[0].wb.rst = false;
    assert_eq!(sys.read(0, CAP_A), 0);
    assert_eq!(sys.read(0, CAP_B), 0);
}

// ---------------------------------------------------------------------------
// §10.2 err_warning
// ---------------------------------------------------------------------------

/// Steps until the TEC probe of channel `ch` of node 0 reaches `tec`; checks that
/// irq (err_warning enabled, INT_STATUS clear) stays 0 until 2 clocks after it
/// and is 1 then: the channel's err_warning follows its TEC, INT_STATUS one edge
/// later (the value differs from the one a clock earlier), irq one edge after.
fn warning_raised_at(sys: &mut Sys, ch: usize, tec: u16) {
    let probe = |s: &Sys| {
        let p = s.nodes[0].out.probes;
        [p.chan_a_bsp_tx_err_cnt, p.chan_b_bsp_tx_err_cnt][ch]
    };
    let mut clocks = 0;
    while probe(sys) < tec {
        assert!(
            !sys.nodes[0].out.irq,
            "no irq below the limit (TEC {})",
            probe(sys)
        );
        sys.step();
        clocks += 1;
        assert!(clocks < 400 * CPB, "channel {ch} reaches TEC {tec}");
    }
    assert_eq!(probe(sys), tec);
    sys.step();
    assert!(!sys.nodes[0].out.irq, "INT_STATUS set at this edge");
    sys.step();
    assert!(sys.nodes[0].out.irq, "irq one edge after INT_STATUS");
}

/// BTR.ewl = 16: a transmitter alone on its bus gets TEC 8 after the first ACK
/// error (8 < 16, no warning) and 16 after the second (16 >= 16: err_warning 1);
/// INT_STATUS.err_warning is set then, not while TEC goes on to 128 (no change),
/// and again when reset mode clears TEC (1 -> 0); the same on channel B alone.
#[test]
fn err_warning_interrupt_follows_each_change_of_either_channel() {
    let mut sys = Sys::new(1);
    sys.write(0, INT_ENABLE, I_ERR_WARNING);
    // EWL 0 in reset mode: the channels (held in reset, TEC = REC = 0) take it
    // and 0 >= 0 raises their err_warning: a change, even in reset mode; back to
    // 96, another one.
    sys.write(0, BTR, btr_ewl(0));
    sys.run(4);
    assert_eq!(sys.read(0, CHAN_A_ERR) >> 26 & 1, 1, "A at the limit 0");
    assert_eq!(sys.read(0, INT_STATUS) & I_ERR_WARNING, I_ERR_WARNING);
    sys.write(0, INT_STATUS, I_ERR_WARNING);
    sys.run(10);
    assert_eq!(
        sys.read(0, INT_STATUS) & I_ERR_WARNING,
        0,
        "no change, no event"
    );
    sys.write(0, BTR, btr_ewl(96));
    sys.run(4);
    assert_eq!(
        sys.read(0, INT_STATUS) & I_ERR_WARNING,
        I_ERR_WARNING,
        "1 -> 0"
    );
    // EWL 16 (TEC 0 below it: no change).
    sys.write(0, BTR, btr_ewl(16));
    sys.write(0, INT_STATUS, I_ERR_WARNING);
    sys.run(4);
    assert_eq!(sys.read(0, INT_STATUS), 0);

    // Channel A: the first ACK error (TEC 8) raises nothing, the second (16) does.
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    sys.push(0, &frame(0x155, false, false, 1, &[0xA5]), 0);
    warning_raised_at(&mut sys, 0, 8 + 8);
    let s = sys.read(0, CHAN_A_ERR);
    assert_eq!((tec(s), s >> 26 & 1), (16, 1), "CHAN_A_ERR.err_warning");
    assert_eq!(sys.read(0, INT_STATUS) & I_ERR_WARNING, I_ERR_WARNING);
    sys.write(0, INT_STATUS, I_ERR_WARNING);
    assert!(!sys.nodes[0].out.irq);
    // On to error passive (TEC 128 after 16 ACK errors; then rule c exception 1
    // keeps it there): err_warning stays 1, no new event.
    sys.run(2000 * CPB);
    let s = sys.read(0, CHAN_A_ERR);
    assert_eq!((tec(s), err_state(s)), (128, 1), "A error passive");
    assert_eq!(
        sys.read(0, INT_STATUS) & I_ERR_WARNING,
        0,
        "a level is no event"
    );

    // Reset mode restarts the channels: TEC 0, err_warning 1 -> 0, an event.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
    assert_eq!(tec(sys.read(0, CHAN_A_ERR)), 0);
    assert_eq!(sys.read(0, INT_STATUS) & I_ERR_WARNING, I_ERR_WARNING);
    sys.write(0, INT_STATUS, I_ERR_WARNING);
    assert_eq!(sys.read(0, INT_STATUS) & I_ERR_WARNING, 0);

    // Channel B alone.
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    sys.push(0, &frame(0x0AA, false, false, 1, &[0x5A]), 1);
    warning_raised_at(&mut sys, 1, 16);
    assert_eq!(sys.read(0, CHAN_B_ERR) >> 26 & 1, 1);
    assert_eq!(tec(sys.read(0, CHAN_A_ERR)), 0, "A had no error");
    assert_eq!(sys.read(0, INT_STATUS) & I_ERR_WARNING, I_ERR_WARNING);
    // Masked: INT_ENABLE without it, no irq.
    sys.write(0, INT_ENABLE, I_ARB_LOST);
    sys.run(2);
    assert!(!sys.nodes[0].out.irq, "irq only for enabled bits");
}
