//! The centralized algorithm's master on ring node 0 (after the King's start-up):
//! the heartbeat, the scan right then left, the final decision and the retelling
//! of the "beyond" letters (see the module above for the rules).

use super::{
    answer_of, beyond_letter, final_lag, page1_letter, CentralTiming, CONNECT_LEFT, CONNECT_RIGHT,
    RING_GROUP, TRANSPARENT,
};
use crate::raw_id;
use alloc::vec;
use alloc::vec::Vec;
use embedded_can::Frame;

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
pub struct Master<F> {
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
    /// where a slave would take them for a poll): taken by the runner, before
    /// the letters of the same poll.
    pub flush: bool,
    /// Letters to send (taken by the runner, after a flush if `flush`: the
    /// letters of a poll are for the side the relay is still on, which changes
    /// `settle` later).
    pub outbox: Vec<F>,
    /// RCM command to write (taken by the runner).
    pub command: Option<u8>,
    /// When the master detected the fault (left `Run`).
    pub detected_at: Option<u64>,
}

impl<F: Frame> Master<F> {
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
    pub fn poll(&mut self, now: u64, rx: &[F]) {
        let t = self.timing;
        let answers: Vec<u8> = rx.iter().filter_map(answer_of).collect();
        // A plain node is alive while its frames come (its answers, or any frame
        // on an envelope of its own: the application's `app_base + node`).
        for f in rx {
            let from = raw_id(f).checked_sub(self.app_base).map(|k| k as usize);
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
            MState::Run { next_hb } => self.heartbeat(now, next_hb),
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
            MState::Final { at } => self.final_decision(now, at),
            MState::Retell { at } => {
                if now >= at {
                    let told: Vec<F> = self.told.iter().map(|&k| beyond_letter(k)).collect();
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

    /// Running: the heartbeat every T1, until a ring slave misses 2 T1 of
    /// answers or a plain node is silent for `plain_silence` (the detection).
    fn heartbeat(&mut self, now: u64, next_hb: u64) {
        let t = self.timing;
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

    /// The final decision at 2 T2 after the scan began (or later, at `at`).
    fn final_decision(&mut self, now: u64, at: u64) {
        let t = self.timing;
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
