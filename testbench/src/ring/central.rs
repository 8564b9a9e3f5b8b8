//! REDCAN's centralized algorithm (seed 000 §3) on CanKingdom (seed 002), as
//! this module makes it precise (decisions listed in `docs/redcan.md`): the King
//! (ring node 0) is the master.
//!
//! - **Heartbeat** every T1: the King's Page 1 to the ring nodes' Cities (group
//!   `RING_GROUP`), base number "keep", response Mayor's Page 0; each answers on
//!   its envelope. Plain nodes are watched through their own frames.
//! - **Detection**: a slave that hears no King's Letter for 2 T1 connects left,
//!   clears its flags and starts its T2 clock; the master that misses a ring
//!   slave's answer for 2 T1 stops the heartbeat (the paper's signal), so the
//!   slaves on its side detect 2 T1 later (the paper's 4 T1 worst case).
//! - **Scan**: 2 T1 (+ a margin) after its last heartbeat the master connects
//!   right and polls the ring slaves in order (a King's Page 1 to that City). A
//!   polled slave sets the flag of the side it was reached from, goes
//!   transparent, and answers; the master tells the slave before it that the node
//!   beyond answered (a REDCAN letter), which sets its other flag. A slave that
//!   does not answer is skipped once (a crashed node's relay rests transparent);
//!   two silent slaves in a row end the scan in that direction. Having reached
//!   every slave, the master connects left and polls the last one: the ring is
//!   whole and the master holds both terminations. Otherwise, at T2, it connects
//!   left and polls from the other end.
//! - **Decisions** (Table 1): at T2 after its detection a slave decides (T, T)
//!   transparent, (T, F) connect left, (F, F) connect right (awaiting the scan from
//!   the left); at 2 T2 it decides again, with (F, T) connect right (the table's
//!   missing row, by symmetry). The master, at 2 T2 after its scan began, goes
//!   transparent if the scan found a fault (joining the two arms) and keeps
//!   holding both terminations otherwise; then the heartbeat resumes.
//! - **Robustness found in the runs** (`docs/redcan.md`): a silent slave is
//!   skipped once; the master flushes its queued frames before its relay changes
//!   side and retells its "beyond" letters after its final decision; a polled
//!   slave without a "beyond" letter within three poll timeouts connects back to
//!   the side it was reached from (the end of its arm); a slave flushes its queue
//!   on detection, so that its answers are not stuck behind application frames.

use super::post::DrccPost;
use cankingdom::king_pages::{BaseNumber, Initiation, KingLetter, KingPage};
use cankingdom::{Mayor, MayorPage};
use drcc_cosim::Frame;

/// Envelope of the REDCAN letters (the master's "the node beyond you answered").
pub const REDCAN_ENVELOPE: u32 = 0x010;
/// Envelope of the King's Letters (CanKingdom default).
pub const KING_ENVELOPE: u32 = 0x000;
/// The Kingdom's base number: a City answers on `BASE + address`.
pub const BASE: u32 = 0x400;

/// RCM control words (ring contract §2).
pub const CONNECT_LEFT: u8 = 0b01;
/// Connect right, disconnect left.
pub const CONNECT_RIGHT: u8 = 0b10;
/// Relay closed.
pub const TRANSPARENT: u8 = 0b11;

/// The algorithm's times, in microseconds (= clocks of the ring's 1 MHz clock).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CentralTiming {
    /// Heartbeat period T1 (paper: 30 ms).
    pub t1: u64,
    /// Scan window T2 (paper: 500 ms).
    pub t2: u64,
    /// How long the master waits for a polled slave's answer.
    pub poll_timeout: u64,
    /// The relays' operate time plus a margin: the master waits this long after
    /// an answer (the slave's relay closing) or its own relay change before polling.
    pub settle: u64,
    /// A plain node (no RCM, not in the heartbeat) is judged lost when the master
    /// hears none of its frames for this long (seed §2: "information extracted
    /// from normal message frames").
    pub plain_silence: u64,
}

impl CentralTiming {
    /// The paper's T1 = 30 ms and T2 = 500 ms, for relays of `relay_us`.
    pub fn paper(relay_us: u64) -> Self {
        CentralTiming {
            t1: 30_000,
            t2: 500_000,
            // A polled slave's answer waits behind the frames its TX queue holds
            // (8 at most, about 1 ms each at 125 kbit/s).
            poll_timeout: 20_000,
            settle: relay_us + 1_000,
            plain_silence: 250_000,
        }
    }
}

/// The group address of the ring nodes' Cities: the heartbeat goes to them only.
/// Every City answering each heartbeat would load a 20-node kingdom at 125 kbit/s
/// with T1 = 30 ms to about 65 % and delay the last answers past 2 T1 (measured:
/// a spurious detection in the fault-free 10-ring-node table row).
pub const RING_GROUP: u8 = 0xF0;

/// The King's Page 1 with base "keep" and "respond with Mayor's Page 0" to
/// `address` (0 = all Cities): the heartbeat and the poll.
pub fn page1_letter(address: u8) -> Frame {
    let page = KingLetter {
        address,
        page: KingPage::Page1(Initiation {
            response: Some(0),
            base: BaseNumber::Keep,
        }),
    }
    .encode()
    .expect("a valid King's Page 1");
    Frame::base(KING_ENVELOPE, &page)
}

/// The REDCAN letter "the node beyond you answered", to City `address`.
pub fn beyond_letter(address: u8) -> Frame {
    Frame::base(REDCAN_ENVELOPE, &[address, 1])
}

/// The City address that answered with `f` (a Mayor's Page on `BASE + address`).
pub fn answer_of(f: &Frame) -> Option<u8> {
    if f.ide || f.rtr || f.id <= BASE || f.id > BASE + 255 {
        return None;
    }
    MayorPage::decode(&f.data[..f.dlc.min(8) as usize]).ok()?;
    Some((f.id - BASE) as u8)
}

/// What the master is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum MState {
    /// Heartbeat every T1.
    Run { next_hb: u64 },
    /// Silent after detection until the slaves have detected too.
    Quiet { until: u64 },
    /// Scanning right (`dir_left = false`) or left: poll `next` once settled.
    Scan {
        dir_left: bool,
        next: usize,
        at: u64,
        sent: Option<u64>,
        misses: u32,
        last_reached: Option<usize>,
    },
    /// Waiting for the final decision time.
    Final { at: u64 },
    /// Telling again, once the relays of the final configuration have settled,
    /// every slave whose next slave answered (a letter sent while the next
    /// slave's relay joined a stuck section may never have left).
    Retell { at: u64 },
}

/// The REDCAN master on ring node 0 (after the King's start-up).
#[derive(Clone, Debug)]
pub struct Master {
    n: usize,
    app_base: u32,
    timing: CentralTiming,
    state: MState,
    last_answer: Vec<u64>,
    last_hb: u64,
    scan_start: u64,
    reached: Vec<bool>,
    /// The slaves the heartbeat expects (those the last scan reached).
    expected: Vec<bool>,
    /// The scan reached every slave from the right and tests the left side.
    left_test: bool,
    /// Some slave answered the scan from the right / from the left.
    arm_right: bool,
    arm_left: bool,
    fault_found: bool,
    /// The slaves told "the node beyond you answered" in this scan.
    told: Vec<u8>,
    /// Before the master's relay changes side, it gives up the frames it queued
    /// (polls nobody on the old side acknowledged would reach the new side late,
    /// where a slave would take them for a poll): taken by [`Master::poll`].
    flush: bool,
    /// Letters of this step, submitted after the flush.
    outbox: Vec<Frame>,
    /// RCM command to write (taken by the runner).
    pub command: Option<u8>,
    /// When the master detected the fault (left `Run`).
    pub detected_at: Option<u64>,
}

impl Master {
    /// A master of `n` ring nodes among `cities + 1` nodes (every node a City but
    /// the master), starting its heartbeat at `now`.
    pub fn new(n: usize, cities: usize, app_base: u32, timing: CentralTiming, now: u64) -> Self {
        Master {
            n,
            app_base,
            timing,
            state: MState::Run { next_hb: now },
            last_answer: vec![now; cities + 1],
            last_hb: now,
            scan_start: 0,
            reached: vec![false; n],
            expected: vec![true; cities + 1],
            left_test: false,
            arm_right: false,
            arm_left: false,
            fault_found: false,
            told: Vec::new(),
            flush: false,
            outbox: Vec::new(),
            // The fault-free configuration: the master holds both terminations.
            command: Some(CONNECT_LEFT),
            detected_at: None,
        }
    }

    /// One poll at `now` with the frames received since the last one.
    pub fn poll(&mut self, now: u64, rx: &[Frame], post: &mut DrccPost) {
        self.step(now, rx);
        // The flush first: the letters of this step are for the side the relay
        // is still on (it changes `settle` later).
        if std::mem::take(&mut self.flush) {
            post.flush();
        }
        for f in self.outbox.drain(..) {
            post.host.submit(now, f, 0);
        }
    }

    fn step(&mut self, now: u64, rx: &[Frame]) {
        let t = self.timing;
        let answers: Vec<u8> = rx.iter().filter_map(answer_of).collect();
        // A plain node is alive while its frames come (its answers, or any frame
        // on an envelope of its own: the application's `app_base + node`).
        for f in rx {
            let from = f.id.checked_sub(self.app_base).map(|k| k as usize);
            if let Some(i) = from.filter(|&i| i >= self.n && i < self.last_answer.len()) {
                self.last_answer[i] = now;
                self.expected[i] = true;
            }
        }
        for &a in &answers {
            if let Some(t) = self.last_answer.get_mut(a as usize) {
                *t = now;
                // A City that answers is expected to keep answering.
                self.expected[a as usize] = true;
            }
        }
        match self.state {
            MState::Run { next_hb } => {
                let late = (1..self.last_answer.len()).any(|i| {
                    let limit = if i < self.n {
                        2 * t.t1
                    } else {
                        t.plain_silence
                    };
                    self.expected[i] && now.saturating_sub(self.last_answer[i]) > limit
                });
                if late {
                    self.detected_at = Some(now);
                    self.state = MState::Quiet {
                        until: self.last_hb + 2 * t.t1 + t.settle,
                    };
                } else if now >= next_hb {
                    self.outbox.push(page1_letter(RING_GROUP));
                    self.last_hb = now;
                    self.state = MState::Run {
                        next_hb: now + t.t1,
                    };
                }
            }
            MState::Quiet { until } => {
                if now >= until {
                    self.scan_start = now;
                    self.reached = vec![false; self.n];
                    self.left_test = false;
                    self.arm_right = false;
                    self.arm_left = false;
                    self.fault_found = false;
                    self.told.clear();
                    self.start_scan(false, now);
                }
            }
            MState::Scan {
                dir_left,
                next,
                at,
                sent,
                misses,
                last_reached,
            } => {
                if !dir_left && now >= self.scan_start + t.t2 {
                    // Not every slave reached from the right within T2: turn left.
                    self.fault_found = true;
                    self.start_scan(true, now);
                    return;
                }
                if now >= self.scan_start + 2 * t.t2 {
                    self.fault_found |= self.reached.iter().skip(1).any(|r| !r);
                    self.state = MState::Final { at: now };
                    return;
                }
                if now < at {
                    return;
                }
                match sent {
                    None => {
                        self.outbox.push(page1_letter(next as u8));
                        self.state = MState::Scan {
                            dir_left,
                            next,
                            at,
                            sent: Some(now),
                            misses,
                            last_reached,
                        };
                    }
                    Some(s) => {
                        if answers.contains(&(next as u8)) && self.left_test {
                            // The ring is whole: the last slave's right side is
                            // fine too, and the master holds both terminations.
                            self.reached[next] = true;
                            self.outbox.push(beyond_letter(next as u8));
                            self.told.push(next as u8);
                            self.fault_found = false;
                            self.state = MState::Final { at: now };
                        } else if answers.contains(&(next as u8)) {
                            self.reached[next] = true;
                            if dir_left {
                                self.arm_left = true;
                            } else {
                                self.arm_right = true;
                            }
                            if let Some(prev) = last_reached {
                                self.outbox.push(beyond_letter(prev as u8));
                                self.told.push(prev as u8);
                            }
                            self.advance(dir_left, next, now + t.settle, 0, Some(next));
                        } else if now >= s + t.poll_timeout {
                            if misses >= 1 {
                                self.end_direction(dir_left, now, false, last_reached);
                            } else {
                                self.advance(dir_left, next, now, misses + 1, last_reached);
                            }
                        }
                    }
                }
            }
            MState::Final { at } => {
                let done = self.scan_start + 2 * t.t2;
                if now >= done.max(at) {
                    // Holding both terminations when the ring is whole; else
                    // joining the two arms, or ending the one arm there is.
                    self.flush = true;
                    self.command = Some(match (self.fault_found, self.arm_right, self.arm_left) {
                        (true, true, true) => TRANSPARENT,
                        (true, true, false) => CONNECT_RIGHT,
                        _ => CONNECT_LEFT,
                    });
                    // Expected again once they answer: a City cut off by the
                    // fault is not looked for again and again.
                    self.last_answer
                        .iter_mut()
                        .for_each(|a| *a = now + t.settle);
                    self.expected.iter_mut().for_each(|e| *e = false);
                    self.state = MState::Retell { at: now + t.settle };
                }
            }
            MState::Retell { at } => {
                if now >= at {
                    let told: Vec<Frame> = self.told.iter().map(|&k| beyond_letter(k)).collect();
                    self.outbox.extend(told);
                    // The heartbeat resumes once every slave has decided: a King's
                    // Letter before that would count as a poll.
                    self.last_answer
                        .iter_mut()
                        .for_each(|a| *a = now + final_lag(&t));
                    self.state = MState::Run {
                        next_hb: now + final_lag(&t),
                    };
                }
            }
        }
    }

    /// Whether the heartbeat runs (no fault being handled).
    pub fn running(&self) -> bool {
        matches!(self.state, MState::Run { .. })
    }

    fn start_scan(&mut self, dir_left: bool, now: u64) {
        self.flush = true;
        self.command = Some(if dir_left {
            CONNECT_LEFT
        } else {
            CONNECT_RIGHT
        });
        let first = if dir_left { self.n - 1 } else { 1 };
        self.state = MState::Scan {
            dir_left,
            next: first,
            at: now + self.timing.settle,
            sent: None,
            misses: 0,
            last_reached: None,
        };
    }

    /// The next slave in the scan direction, or the end of the ring.
    fn advance(
        &mut self,
        dir_left: bool,
        cur: usize,
        at: u64,
        misses: u32,
        last_reached: Option<usize>,
    ) {
        let next = if dir_left { cur - 1 } else { cur + 1 };
        if next == 0 || next == self.n {
            self.end_direction(dir_left, at, true, last_reached);
            return;
        }
        self.state = MState::Scan {
            dir_left,
            next,
            at,
            sent: None,
            misses,
            last_reached,
        };
    }

    /// A direction ended: at the end of the ring (`at_end`), or at two silent
    /// slaves in a row.
    fn end_direction(&mut self, dir_left: bool, now: u64, at_end: bool, last: Option<usize>) {
        let wait_for_t2 = MState::Scan {
            dir_left: false,
            next: self.n - 1,
            at: u64::MAX,
            sent: None,
            misses: 0,
            last_reached: None,
        };
        if !dir_left {
            match (at_end, last) {
                // The scan went round (silent slaves skipped are powered off, their
                // relays at rest): test the left connection on the last slave
                // that answered, through the master's left side.
                (true, Some(last)) => {
                    self.flush = true;
                    self.command = Some(CONNECT_LEFT);
                    self.left_test = true;
                    self.state = MState::Scan {
                        dir_left: true,
                        next: last,
                        at: now + self.timing.settle,
                        sent: None,
                        misses: 1,
                        last_reached: None,
                    };
                }
                // A fault on the right: scan from the left at T2.
                _ => {
                    self.fault_found = true;
                    self.state = wait_for_t2;
                }
            }
        } else if self.left_test {
            // The left test failed: the fault is between the last slave that
            // answered and the master; scan from the left at T2.
            self.left_test = false;
            self.fault_found = true;
            self.state = wait_for_t2;
        } else {
            self.fault_found = true;
            self.state = MState::Final { at: now };
        }
    }
}

/// How long after 2 T2 a slave takes its final decision: the master's scan began
/// up to 2 T1 (+ its margin) after the slave detected, and the master retells its
/// "beyond" letters one settling time after its own final decision at 2 T2.
pub fn final_lag(t: &CentralTiming) -> u64 {
    2 * t.t1 + 3 * t.settle + t.poll_timeout
}

/// A slave's side flags and its decision by Table 1 (with (F, T) -> right).
pub fn decide(left_ok: bool, right_ok: bool) -> u8 {
    match (left_ok, right_ok) {
        (true, true) => TRANSPARENT,
        (true, false) => CONNECT_LEFT,
        (false, _) => CONNECT_RIGHT,
    }
}

/// What a slave is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SState {
    Run { last_letter: u64 },
    Recovery { since: u64, decided: u8 },
}

/// The REDCAN slave on ring node `address` (a City: its Mayor answers polls).
#[derive(Clone, Debug)]
pub struct Slave {
    address: u8,
    timing: CentralTiming,
    state: SState,
    accepted: u32,
    mode: u8,
    left_ok: bool,
    right_ok: bool,
    reached_from_left: Option<bool>,
    /// Polled and transparent since, waiting for the "beyond" letter.
    waiting_beyond: Option<u64>,
    /// On detection the slave gives up what it queued, so that its answer to a
    /// poll leaves before its relay closes (taken by the runner).
    pub flush: bool,
    /// RCM command to write (taken by the runner).
    pub command: Option<u8>,
    /// When this slave detected the fault.
    pub detected_at: Option<u64>,
}

impl Slave {
    /// Ring node `address`, transparent, running from `now`.
    pub fn new(address: u8, timing: CentralTiming, now: u64) -> Self {
        Slave {
            address,
            timing,
            state: SState::Run { last_letter: now },
            accepted: 0,
            mode: TRANSPARENT,
            left_ok: false,
            right_ok: false,
            reached_from_left: None,
            waiting_beyond: None,
            flush: false,
            command: None,
            detected_at: None,
        }
    }

    /// Whether the slave is not handling a fault.
    pub fn running(&self) -> bool {
        matches!(self.state, SState::Run { .. })
    }

    fn set(&mut self, mode: u8) {
        if mode != self.mode {
            self.mode = mode;
            self.command = Some(mode);
        }
    }

    /// One poll at `now`: `mayor` has just handled the King's Letters; `rx` are the
    /// other frames received since the last poll.
    pub fn poll(&mut self, now: u64, mayor: &Mayor, rx: &[Frame]) {
        let t = self.timing;
        let letters = mayor.letters_accepted();
        let new_letter = letters != self.accepted;
        self.accepted = letters;
        match self.state {
            SState::Run { last_letter } => {
                if new_letter {
                    self.state = SState::Run { last_letter: now };
                } else if now.saturating_sub(last_letter) > 2 * t.t1 {
                    self.detected_at.get_or_insert(now);
                    self.left_ok = false;
                    self.right_ok = false;
                    self.reached_from_left = None;
                    self.flush = true;
                    self.set(CONNECT_LEFT);
                    self.state = SState::Recovery {
                        since: now,
                        decided: 0,
                    };
                }
            }
            SState::Recovery { since, decided } => {
                if new_letter {
                    // Polled: reached from the side it is attached to.
                    let from_left = self.mode != CONNECT_RIGHT;
                    if from_left {
                        self.left_ok = true;
                    } else {
                        self.right_ok = true;
                    }
                    self.reached_from_left = Some(from_left);
                    self.waiting_beyond = Some(now);
                    self.set(TRANSPARENT);
                }
                let beyond = rx.iter().any(|f| {
                    f.id == REDCAN_ENVELOPE
                        && !f.ide
                        && f.dlc >= 2
                        && f.data[0] == self.address
                        && f.data[1] == 1
                });
                if beyond {
                    self.waiting_beyond = None;
                    match self.reached_from_left {
                        Some(true) => self.right_ok = true,
                        Some(false) => self.left_ok = true,
                        None => {}
                    }
                }
                // No "beyond" letter within three poll timeouts: the master found
                // no slave past this one, which is the end of its arm. Its relay,
                // closed by the poll, may have joined the faulty section to the
                // arm (a short kills the arm's bus): connect back to the side it
                // was reached from at once, not at T2.
                if let Some(at) = self.waiting_beyond {
                    if now >= at + 3 * t.poll_timeout {
                        self.waiting_beyond = None;
                        self.set(if self.reached_from_left == Some(false) {
                            CONNECT_RIGHT
                        } else {
                            CONNECT_LEFT
                        });
                    }
                }
                if decided == 0 && now >= since + t.t2 {
                    let m = decide(self.left_ok, self.right_ok);
                    self.set(m);
                    self.state = SState::Recovery { since, decided: 1 };
                } else if decided == 1 && now >= since + 2 * t.t2 + final_lag(&t) {
                    let m = decide(self.left_ok, self.right_ok);
                    self.set(m);
                    // The master's scan began up to 2 T1 (+ its margin) after this
                    // slave detected, and its heartbeat resumes 2 T2 after that:
                    // wait that much longer before judging the heartbeat lost.
                    self.state = SState::Run {
                        last_letter: now + 2 * t.t1 + t.settle,
                    };
                }
            }
        }
    }
}
