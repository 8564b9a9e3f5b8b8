//! REDCAN's distributed algorithm (seed 000 §4) as ring contract §6 schedules it:
//! no master; every ring node runs the same rules from its own detection time.
//!
//! - **Run**: an *alive* letter every Ta; a ring node silent for 2 Ta (or a *D*
//!   letter from a node that detected) starts the rebuild, with a *D* of its own.
//! - **Phases** of length L from the node's detection: in phase `slot(i)` node i
//!   connects right and probes its right neighbour (O), which, connected left,
//!   answers (O, N); adjacent nodes never share a slot. Phase 3: a node whose test
//!   failed on exactly one side connects towards it and probes the node beyond (a
//!   powered-off neighbour rests transparent): D?, answered O!.
//! - **Decision** at 4 L: both links good: transparent; one: connect towards it
//!   (a bus end, which announces itself); none: connect left. The lowest-numbered
//!   ring node it heard alive, hearing no end, holds both terminations (connect
//!   left): without an end the ring would be closed.

use crate::{base_data, letter, CONNECT_LEFT, CONNECT_RIGHT, TRANSPARENT};
use alloc::vec;
use alloc::vec::Vec;
use embedded_can::Frame;

/// Envelope of the alive letters: `ALIVE_BASE + node`.
pub const ALIVE_BASE: u32 = 0x020;
/// Envelope of the *D* letter (a node detected a fault).
pub const DETECT_ENVELOPE: u32 = 0x01F;
/// Envelope of the link letters: `[kind, from, to]`.
pub const LINK_ENVELOPE: u32 = 0x018;

const PROBE: u8 = 1;
const REPLY: u8 = 2;
const END: u8 = 3;

/// The algorithm's times in microseconds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DistTiming {
    /// Alive period Ta.
    pub ta: u64,
    /// Phase length L.
    pub phase: u64,
    /// Relay operate time plus a margin.
    pub settle: u64,
    /// Probe repetition within a phase.
    pub probe_every: u64,
    /// After the decision: when the holder decides (the ends have announced).
    pub holder_after: u64,
    /// A plain node is judged lost when none of its frames came for this long.
    pub plain_silence: u64,
}

impl DistTiming {
    /// Ta = 10 ms, L = Ta + 5 ms, for relays of `relay_us`.
    pub fn standard(relay_us: u64) -> Self {
        DistTiming {
            ta: 10_000,
            phase: 15_000,
            settle: relay_us + 1_000,
            probe_every: 3_000,
            // the ends announce after the relays settle (3 ms) every 3 ms until
            // 5 ms before: at 3, 6 and 9 ms, each letter ~0.5 ms at 125 kbit/s
            holder_after: 15_000,
            plain_silence: 250_000,
        }
    }

    /// The silence that judges a plain node lost, for plain nodes that send every
    /// `period` (ring contract §6, "plain nodes"): one period plus 2 Ta, the
    /// tolerance the alive letters get, for the queueing of a periodic frame.
    pub fn plain_silence_for(&self, period: u64) -> u64 {
        period + 2 * self.ta
    }

    /// How long before its detection a fault may have begun (ring contract §5.1):
    /// the longest silence judged (2 Ta for a ring node, `plain_silence` for a
    /// plain node), plus Ta for the skew between the parts of a broken ring.
    pub fn resend_horizon(&self) -> u64 {
        (2 * self.ta).max(self.plain_silence) + self.ta
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum State {
    Run,
    Rebuild { t0: u64 },
    Decided { at: u64 },
}

/// One ring node's distributed REDCAN.
#[derive(Clone, Debug)]
pub struct DistNode<F> {
    i: usize,
    n: usize,
    t: DistTiming,
    state: State,
    next_alive: u64,
    heard: Vec<Option<u64>>,
    /// Plain nodes (`n..`), heard through their application frames.
    plain_heard: Vec<Option<u64>>,
    app_base: u32,
    alive_at_detection: Vec<bool>,
    left_ok: bool,
    right_ok: bool,
    end_heard: bool,
    last_probe: u64,
    mode: u8,
    /// Letters to send (taken by the runner, after a flush if `flush`).
    pub outbox: Vec<F>,
    /// Give up what is queued before sending (on detection).
    pub flush: bool,
    /// RCM command to write (taken by the runner).
    pub command: Option<u8>,
    /// When this node detected the fault.
    pub detected_at: Option<u64>,
}

impl<F: Frame> DistNode<F> {
    /// Ring node `i` of `n` among `total` nodes (plain nodes `n..`, whose
    /// application frames come on `app_base + node`), running from `now`; node 0
    /// holds both terminations in the fault-free ring.
    pub fn new(i: usize, n: usize, total: usize, app_base: u32, t: DistTiming, now: u64) -> Self {
        let mode = if i == 0 { CONNECT_LEFT } else { TRANSPARENT };
        DistNode {
            i,
            n,
            t,
            state: State::Run,
            next_alive: now,
            heard: vec![Some(now); n],
            // A plain node is watched from its first frame on: the application
            // starts after the algorithm, up to a period later for the last node.
            plain_heard: vec![None; total],
            app_base,
            alive_at_detection: vec![true; n],
            left_ok: false,
            right_ok: false,
            end_heard: false,
            last_probe: 0,
            mode: TRANSPARENT,
            outbox: Vec::new(),
            flush: false,
            command: (mode != TRANSPARENT).then_some(mode),
            detected_at: None,
        }
        .with_mode(mode)
    }

    fn with_mode(mut self, mode: u8) -> Self {
        self.mode = mode;
        self
    }

    /// Whether the ring is settled: no rebuild, and no holder's decision pending
    /// (whose relay change would restart the controller).
    pub fn settled(&self) -> bool {
        self.state == State::Run
    }

    fn set(&mut self, mode: u8) {
        if mode != self.mode {
            self.mode = mode;
            self.command = Some(mode);
            // A relay change restarts the controller (reset mode): a short met in
            // the last attachment may have left it bus-off, and a bus-off node
            // could neither probe nor answer for 128 x 11 bit times; frames queued
            // for the old side are given up with it.
            self.flush = true;
        }
    }

    /// The slot of node `k`: its phase for testing its right section.
    fn slot(&self, k: usize) -> u64 {
        if self.n % 2 == 1 && k == self.n - 1 {
            2
        } else {
            (k % 2) as u64
        }
    }

    fn detect(&mut self, now: u64) {
        self.detected_at.get_or_insert(now);
        self.alive_at_detection = self
            .heard
            .iter()
            .map(|h| h.is_some_and(|t| now.saturating_sub(t) <= 2 * self.t.ta))
            .collect();
        self.alive_at_detection[self.i] = true;
        self.left_ok = false;
        self.right_ok = false;
        self.end_heard = false;
        self.flush = true;
        self.outbox.push(letter(DETECT_ENVELOPE, &[self.i as u8]));
        self.state = State::Rebuild { t0: now };
    }

    /// One poll at `now` with the frames received since the last one.
    pub fn poll(&mut self, now: u64, rx: &[F]) {
        let (n, i) = (self.n, self.i);
        let left = (i + n - 1) % n;
        let right = (i + 1) % n;
        let mut detect_letter = false;
        for (id, data) in rx.iter().filter_map(base_data) {
            if id >= ALIVE_BASE && id < ALIVE_BASE + n as u32 {
                self.heard[(id - ALIVE_BASE) as usize] = Some(now);
            } else if let Some(k) = id
                .checked_sub(self.app_base)
                .map(|k| k as usize)
                .filter(|&k| k >= n && k < self.plain_heard.len())
            {
                self.plain_heard[k] = Some(now);
            } else if id == DETECT_ENVELOPE {
                detect_letter = true;
            } else if id == LINK_ENVELOPE && data.len() >= 3 {
                let (kind, from, to) = (data[0], data[1] as usize, data[2] as usize);
                match kind {
                    PROBE if to == i => {
                        // The prober is on the side this node is connected to.
                        match self.mode {
                            CONNECT_LEFT => self.left_ok = true,
                            CONNECT_RIGHT => self.right_ok = true,
                            _ => {
                                self.left_ok |= from == left;
                                self.right_ok |= from == right;
                            }
                        }
                        self.outbox
                            .push(letter(LINK_ENVELOPE, &[REPLY, i as u8, from as u8]));
                    }
                    REPLY if to == i => match self.mode {
                        CONNECT_RIGHT => self.right_ok = true,
                        CONNECT_LEFT => self.left_ok = true,
                        _ => {}
                    },
                    END => self.end_heard = true,
                    _ => {}
                }
            }
        }
        match self.state {
            State::Run | State::Decided { .. } => {
                if let State::Decided { at } = self.state {
                    if now >= at + self.t.holder_after {
                        // The holder: the lowest-numbered node alive at detection.
                        let lowest = (0..n).find(|&k| self.alive_at_detection[k]);
                        if lowest == Some(i) && !self.end_heard && self.mode == TRANSPARENT {
                            self.set(CONNECT_LEFT);
                        }
                        // Every node is looked for again only once it is heard:
                        // one that fell silent just before the detection (a
                        // babbling idiot detected within 2 Ta) would otherwise
                        // start the rebuild again and again.
                        self.heard.iter_mut().for_each(|h| *h = None);
                        self.plain_heard.iter_mut().for_each(|h| *h = None);
                        self.next_alive = now;
                        self.state = State::Run;
                    } else if self.left_ok != self.right_ok
                        && now >= at + self.t.settle
                        && now + 5_000 < at + self.t.holder_after
                        && now >= self.last_probe + self.t.probe_every
                    {
                        // An end announces itself until the holders decide.
                        self.last_probe = now;
                        self.outbox.push(letter(LINK_ENVELOPE, &[END, i as u8, 0]));
                    }
                }
                if self.state == State::Run {
                    let silent = (0..n).any(|k| {
                        k != i
                            && self.heard[k].is_some_and(|t| now.saturating_sub(t) > 2 * self.t.ta)
                    }) || self
                        .plain_heard
                        .iter()
                        .any(|h| h.is_some_and(|t| now.saturating_sub(t) > self.t.plain_silence));
                    if silent || detect_letter {
                        self.detect(now);
                        return;
                    }
                    if now >= self.next_alive {
                        self.next_alive = now + self.t.ta;
                        self.outbox.push(letter(ALIVE_BASE + i as u32, &[i as u8]));
                    }
                }
            }
            State::Rebuild { t0 } => {
                let p = (now - t0) / self.t.phase;
                let into = (now - t0) % self.t.phase;
                if p < 3 {
                    // Connect right in this node's slot, else left.
                    let testing_right = p == self.slot(i);
                    self.set(if testing_right {
                        CONNECT_RIGHT
                    } else {
                        CONNECT_LEFT
                    });
                    if testing_right
                        && !self.right_ok
                        && into >= self.t.settle
                        && now >= self.last_probe + self.t.probe_every
                    {
                        self.last_probe = now;
                        self.outbox
                            .push(letter(LINK_ENVELOPE, &[PROBE, i as u8, right as u8]));
                    }
                } else if p == 3 {
                    // A silent neighbour: test for the node beyond it.
                    match (self.left_ok, self.right_ok) {
                        (true, true) => self.set(TRANSPARENT),
                        (true, false) => {
                            self.set(CONNECT_RIGHT);
                            if into >= self.t.settle && now >= self.last_probe + self.t.probe_every
                            {
                                self.last_probe = now;
                                let beyond = (i + 2) % n;
                                self.outbox
                                    .push(letter(LINK_ENVELOPE, &[PROBE, i as u8, beyond as u8]));
                            }
                        }
                        (false, true) => {
                            self.set(CONNECT_LEFT);
                            if into >= self.t.settle && now >= self.last_probe + self.t.probe_every
                            {
                                self.last_probe = now;
                                let beyond = (i + n - 2) % n;
                                self.outbox
                                    .push(letter(LINK_ENVELOPE, &[PROBE, i as u8, beyond as u8]));
                            }
                        }
                        (false, false) => self.set(CONNECT_LEFT),
                    }
                } else {
                    let m = match (self.left_ok, self.right_ok) {
                        (true, true) => TRANSPARENT,
                        (true, false) => CONNECT_LEFT,
                        (false, true) => CONNECT_RIGHT,
                        (false, false) => CONNECT_LEFT,
                    };
                    self.set(m);
                    self.last_probe = 0;
                    self.state = State::Decided { at: now };
                }
            }
        }
    }
}
