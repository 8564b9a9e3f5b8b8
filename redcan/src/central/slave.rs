//! The centralized algorithm's slave on a ring node other than 0 (a City: its
//! Mayor answers the polls): detection, the side flags, Table 1's decisions and
//! the end of an arm (see the module above for the rules).

use super::{
    decide, final_lag, CentralTiming, CONNECT_LEFT, CONNECT_RIGHT, REDCAN_ENVELOPE, TRANSPARENT,
};
use crate::base_data;
use cankingdom::Mayor;
use embedded_can::Frame;

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
    pub fn poll<F: Frame>(&mut self, now: u64, mayor: &Mayor, rx: &[F]) {
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
                let beyond = rx.iter().filter_map(base_data).any(|(id, data)| {
                    id == REDCAN_ENVELOPE && data.len() >= 2 && data[..2] == [self.address, 1]
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
