//! Host transmit abort (contract §11.5): `TX_CMD` [1] `abort_a`, [2] `abort_b`.
//! Normal mode keeps only the frame the channel holds and passes the abort to
//! the channel, which drops it at the end of its attempt (timing contract §8);
//! redundancy mode keeps only the head; a write with `push` and an abort, or an
//! abort in DMR mode, is refused; reset mode ignores it. Expected values are
//! worked out from the contract in the comments.

use super::*;

// TX_CMD fields (§3, §11.5).
const PUSH: u32 = 1;
const ABORT_A: u32 = 1 << 1;
const ABORT_B: u32 = 1 << 2;
/// `CTRL.dmr` (DMR contract §2).
const DMR: u32 = 1 << 17;
// INT_STATUS per-channel transmit events (§11.3).
const I_TX_DONE_A: u32 = 1 << 13;
const I_TX_FAILURE_A: u32 = 1 << 15;
const I_TX_FAILURE_B: u32 = 1 << 16;
/// The transmit-related INT_STATUS bits these tests judge.
const I_TX: u32 = I_TX_DONE | I_TX_FAILURE | I_ILLEGAL;

/// A base data frame of 8 bytes: with no acknowledging node, every attempt
/// runs about 100 bit times to the ACK slot and is retried after an error frame.
fn long_frame(id: u32) -> Frame {
    frame(id, false, false, 8, &[id as u8; 8])
}

/// One Wishbone write by node `n` (as `Sys::access`), returning the outputs
/// after its request edge (where it is taken) and after its ack edge.
fn write_watch(sys: &mut Sys, n: usize, adr: u8, dat: u32) -> [DrccOutputs; 2] {
    sys.nodes[n].wb = DrccInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: adr,
        wb_dat_w: dat,
        wb_sel: 0xF,
        ..Default::default()
    };
    sys.step();
    let taken = sys.nodes[n].out;
    sys.nodes[n].wb = DrccInputs::default();
    sys.step();
    [taken, sys.nodes[n].out]
}

/// What node 0 did on each channel during a stretch of clocks.
#[derive(Debug, Default)]
struct Activity {
    /// The channel's tx pin was dominant at some clock.
    tx: [bool; 2],
    /// The channel's transmission request (`chan_?_transmission_req`) pulsed.
    req: [bool; 2],
}

impl Activity {
    fn add(&mut self, o: &DrccOutputs) {
        self.tx[0] |= !o.chan_a_tx;
        self.tx[1] |= !o.chan_b_tx;
        self.req[0] |= o.probes.chan_a_transmission_req;
        self.req[1] |= o.probes.chan_b_transmission_req;
    }
}

/// Runs `bits` nominal bit times, recording node 0's activity.
fn watch(sys: &mut Sys, bits: u64) -> Activity {
    let mut a = Activity::default();
    for _ in 0..bits * CPB {
        sys.step();
        a.add(&sys.nodes[0].out);
    }
    a
}

/// STATUS TX queue counts [A, B] of node 0.
fn counts(sys: &mut Sys) -> [u32; 2] {
    let s = sys.read(0, STATUS);
    [status_txq(s, 0), status_txq(s, 1)]
}

/// One DRCC node alone on both buses in normal mode, integrated (11 recessive
/// bits after its channels leave reset).
fn lone_normal() -> Sys {
    let mut sys = Sys::new(1);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    sys
}

/// Normal mode, nobody acknowledges: queue A holds 3 frames and queue B 2, the
/// head of each in its channel, retried forever. `abort_c` of queue `c` while
/// channel c's first attempt is on the bus: queue c keeps the frame in the
/// channel (count 1: `busy_c`, and no `tx_done`/`tx_failed` at that edge), the
/// channel ends that attempt (ACK error) and drops it (timing contract §8: the
/// remembered abort turns the failed attempt into a drop), the queue pops it
/// (count 0, `tx_failure`), and channel c sends nothing more. The other queue
/// and channel are untouched. Returns INT_STATUS after the drop.
fn abort_in_flight(c: usize) -> u32 {
    let mut sys = lone_normal();
    for id in [0x101, 0x102, 0x103] {
        sys.push(0, &long_frame(id), 0);
    }
    for id in [0x201, 0x202] {
        sys.push(0, &long_frame(id), 1);
    }
    // The pushes took 50 clocks (6 bits); 10 more bits: both first attempts
    // started and are at about bit 16 of ~100 before the ACK slot.
    let a = watch(&mut sys, 10);
    assert_eq!(a.tx, [true, true], "both channels are sending");
    assert_eq!(counts(&mut sys), [3, 2]);
    let abort = [ABORT_A, ABORT_B][c];
    let o = write_watch(&mut sys, 0, TX_CMD, abort);
    assert!(o[0].wb_ack && !o[0].wb_err, "an abort is taken");
    // The frame in channel c stays counted until the channel gives it back.
    let mut expect = [3, 2];
    expect[c] = 1;
    assert_eq!(
        counts(&mut sys),
        expect,
        "queue {c} keeps the frame in flight"
    );
    assert_eq!(
        sys.read(0, INT_STATUS) & I_TX,
        0,
        "the attempt in progress runs on"
    );
    // ACK error about 85 bits after the abort, error flag 6, delimiter 8,
    // intermission 3: everything is over within 150 bits.
    watch(&mut sys, 150);
    expect[c] = 0;
    assert_eq!(
        counts(&mut sys),
        expect,
        "queue {c} popped the dropped frame"
    );
    let int = sys.read(0, INT_STATUS);
    assert_eq!(int & I_TX, I_TX_FAILURE, "dropped: tx_failure, not tx_done");
    // Queue c is empty, so channel c stays silent; the other keeps retrying.
    let a = watch(&mut sys, 200);
    assert!(!a.tx[c], "no further frame on channel {c}");
    assert!(!a.req[c], "no further request to channel {c}");
    assert!(a.tx[1 - c], "the other channel keeps retrying its frame");
    assert_eq!(counts(&mut sys), expect, "the other queue is untouched");
    int
}

#[test]
fn normal_abort_a_drops_the_queue_and_the_frame_in_channel_a() {
    abort_in_flight(0);
}

#[test]
fn normal_abort_b_drops_queue_b_and_leaves_queue_a() {
    abort_in_flight(1);
}

/// §11.3: the drop by the channel raises the failing channel's own bit.
#[test]
fn an_aborted_frame_raises_the_channels_tx_failure_bit() {
    for (c, own) in [(0, I_TX_FAILURE_A), (1, I_TX_FAILURE_B)] {
        let int = abort_in_flight(c);
        assert_eq!(int & (I_TX_FAILURE_A | I_TX_FAILURE_B), own, "channel {c}");
    }
}

/// A frame pushed to queue B reaches channel B only at an edge where the read
/// port serves B (`rd_sel == 1`, §6). Pushed at edge E with `rd_sel == 0`
/// before E+1, its request would be raised at E+2, the first edge a following
/// write can be taken: an abort there finds `busy_b` 0, so queue B keeps
/// nothing (count 0), no request is raised and channel B never sees the frame.
#[test]
fn normal_abort_before_the_channel_has_the_frame_empties_the_queue() {
    let mut sys = lone_normal();
    // Find rd_sel's phase: a push to A at edge E0 raises A's request at the
    // first of E0+1, E0+2 where rd_sel is 0 before the edge.
    sys.push(0, &long_frame(0x101), 0);
    let mut x = sys.clock;
    if !sys.nodes[0].out.probes.chan_a_transmission_req {
        sys.step();
        x = sys.clock;
        assert!(sys.nodes[0].out.probes.chan_a_transmission_req);
    }
    // rd_sel before edge Y is (Y - x) mod 2. Stage for queue B, then push at
    // an edge E with (E - x) odd: rd_sel before E+1 is 0, before E+2 it is 1.
    let f = long_frame(0x201);
    sys.write(0, TX_ID, f.id);
    sys.write(0, TX_CTRL, 8 | 1 << 8);
    // long_frame's eight bytes are all the low byte of its id.
    let data = 0x0101_0101 * (f.id & 0xFF);
    sys.write(0, TX_DATA0, data);
    sys.write(0, TX_DATA1, data);
    if (sys.clock + 1 - x).is_multiple_of(2) {
        sys.step();
    }
    let push = write_watch(&mut sys, 0, TX_CMD, PUSH);
    let abort = write_watch(&mut sys, 0, TX_CMD, ABORT_B);
    assert!(push[0].wb_ack && abort[0].wb_ack, "both writes are taken");
    let mut a = Activity::default();
    for o in push.iter().chain(abort.iter()) {
        a.add(o);
    }
    assert!(!a.req[1], "no request for queue B at the push or the abort");
    assert_eq!(counts(&mut sys), [1, 0], "A keeps its frame, B is empty");
    let a = watch(&mut sys, 200);
    assert!(!a.req[1] && !a.tx[1], "channel B never sends");
    assert!(a.tx[0], "channel A keeps retrying");
    // Nothing was in channel B: no event (§11.5, "no event").
    assert_eq!(sys.read(0, INT_STATUS) & I_TX, 0);
}

/// §11.5: the queue keeps the frame channel c holds only if the channel's
/// `tx_done` and `tx_failed` are 0 at the write edge. Queue A holds two frames,
/// a plain node acknowledges. The edge E where channel A's `tx_done` for the
/// head is seen is found on copies of the system (the first edge after which
/// `INT_STATUS.tx_done_a` reads 1, §11.3: it is set at that edge). `abort_a`
/// taken at E finds the head sent: queue A keeps nothing (count 0; the head is
/// popped by that `tx_done`, the frame behind it dropped), no request follows
/// and only the head is on the bus, with `tx_done` and no `tx_failure`.
#[test]
fn normal_abort_at_the_tx_done_edge_keeps_nothing() {
    let mut sys = Sys::new(1);
    let p = sys.add_plain(0, true);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    let frames = [0x111, 0x112].map(long_frame);
    for f in &frames {
        sys.push(0, f, 0);
    }
    assert_eq!(counts(&mut sys), [2, 0]);
    // From state k (k edges so far), a read taken at edge k + 1 returns
    // INT_STATUS after edge k.
    let mut probe = sys.clone();
    let e = loop {
        if probe.clone().read(0, INT_STATUS) & I_TX_DONE_A != 0 {
            break probe.clock;
        }
        probe.step();
        assert!(probe.clock < sys.clock + 300 * CPB, "the head is sent");
    };
    assert!(e > sys.clock, "the head was not sent yet");
    while sys.clock < e - 1 {
        sys.step();
    }
    let o = write_watch(&mut sys, 0, TX_CMD, ABORT_A);
    assert!(o[0].wb_ack && !o[0].wb_err, "the abort is taken");
    assert_eq!(counts(&mut sys), [0, 0], "nothing kept: the head was sent");
    let a = watch(&mut sys, 300);
    assert!(!a.req[0], "no further request to channel A");
    assert_eq!(sys.plain[p].received, frames[..1], "only the head is sent");
    assert_eq!(sys.read(0, INT_STATUS) & I_TX, I_TX_DONE);
    assert_eq!(counts(&mut sys), [0, 0]);
}

/// `push` with an abort bit: refused (ERR, `illegal`), nothing done: the staged
/// frame is not queued, no frame is dropped and the channels are not aborted.
#[test]
fn push_with_abort_is_refused_and_changes_nothing() {
    let mut sys = lone_normal();
    sys.push(0, &long_frame(0x101), 0);
    sys.push(0, &long_frame(0x102), 0);
    sys.push(0, &long_frame(0x201), 1);
    watch(&mut sys, 10);
    assert_eq!(counts(&mut sys), [2, 1]);
    for (cmd, queue) in [
        (PUSH | ABORT_A, 0),
        (PUSH | ABORT_B, 1),
        (PUSH | ABORT_A | ABORT_B, 0),
    ] {
        sys.write(0, TX_CTRL, 8 | queue << 8);
        let o = write_watch(&mut sys, 0, TX_CMD, cmd);
        assert!(o[0].wb_err && !o[0].wb_ack, "TX_CMD {cmd:#x} refused");
        assert_eq!(sys.read(0, INT_STATUS) & I_TX, I_ILLEGAL, "{cmd:#x}");
        sys.write(0, INT_STATUS, I_ILLEGAL);
        assert_eq!(counts(&mut sys), [2, 1], "{cmd:#x}: queues unchanged");
    }
    // No abort reached a channel: both keep retrying their head frame and
    // nothing is dropped.
    let a = watch(&mut sys, 300);
    assert_eq!(a.tx, [true, true]);
    assert_eq!(counts(&mut sys), [2, 1]);
    assert_eq!(sys.read(0, INT_STATUS) & I_TX, 0);
}

/// DMR mode (`CTRL.dmr`): any write with an abort bit is refused.
#[test]
fn abort_in_dmr_mode_is_refused() {
    let mut sys = Sys::new(1);
    sys.start(0, DMR | policy(1) | k(1));
    assert_eq!(sys.read(0, CTRL) & (DMR | RESET_MODE), DMR, "DMR mode");
    sys.run(20 * CPB);
    sys.push(0, &long_frame(0x101), 0);
    sys.push(0, &long_frame(0x102), 0);
    // Two pushes to the one logical queue (A); nobody acknowledges, so
    // neither is sent.
    assert_eq!(counts(&mut sys), [2, 0]);
    for cmd in [ABORT_A, ABORT_B, ABORT_A | ABORT_B] {
        let o = write_watch(&mut sys, 0, TX_CMD, cmd);
        assert!(o[0].wb_err && !o[0].wb_ack, "TX_CMD {cmd:#x} refused");
        assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, I_ILLEGAL);
        sys.write(0, INT_STATUS, I_ILLEGAL);
        assert_eq!(counts(&mut sys), [2, 0], "{cmd:#x}: queue unchanged");
    }
}

/// Reset mode: the queues are empty and an abort is taken and does nothing;
/// afterwards a frame is sent as usual.
#[test]
fn abort_in_reset_mode_does_nothing() {
    let mut sys = Sys::new(1);
    let p = sys.add_plain(0, true);
    let o = write_watch(&mut sys, 0, TX_CMD, ABORT_A | ABORT_B);
    assert!(o[0].wb_ack && !o[0].wb_err, "not refused");
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0);
    assert_eq!(counts(&mut sys), [0, 0]);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    let f = long_frame(0x155);
    sys.push(0, &f, 0);
    watch(&mut sys, 200);
    assert_eq!(sys.plain[p].received, vec![f], "the frame is sent once");
    assert_eq!(sys.read(0, INT_STATUS) & I_TX, I_TX_DONE);
    assert_eq!(counts(&mut sys), [0, 0]);
}

/// Redundancy mode: `abort_b` is ignored (queue B is unused); `abort_a` keeps
/// the head (count 1: queue A not empty, no pop by the main FSM at that edge,
/// its first attempt being on bus A) and drops the two frames behind it. The
/// head is delivered once, on A, and popped ("finish", tx_done); nothing else
/// is sent on either bus.
#[test]
fn redundancy_abort_keeps_the_head_and_drops_the_rest() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    sys.start(0, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let frames = [0x301, 0x302, 0x303].map(long_frame);
    for f in &frames {
        sys.push(0, f, 0);
    }
    // 30 clocks of pushes: the head's attempt (over 100 bits) is in progress.
    assert_eq!(counts(&mut sys), [3, 0]);
    let o = write_watch(&mut sys, 0, TX_CMD, ABORT_B);
    assert!(o[0].wb_ack, "abort_b is not refused");
    assert_eq!(counts(&mut sys), [3, 0], "abort_b ignored");
    let o = write_watch(&mut sys, 0, TX_CMD, ABORT_A);
    assert!(o[0].wb_ack, "abort_a is taken");
    assert_eq!(counts(&mut sys), [1, 0], "only the head stays");
    watch(&mut sys, 400);
    assert_eq!(sys.plain[pa].received, vec![frames[0]], "the head, once");
    assert!(sys.plain[pb].received.is_empty(), "nothing on bus B");
    assert_eq!(counts(&mut sys), [0, 0]);
    assert_eq!(sys.read(0, INT_STATUS) & I_TX, I_TX_DONE);
    assert_eq!(status_state(sys.read(0, STATUS)), IDLE1);
}
