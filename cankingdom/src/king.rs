//! The King: the Capital's start-up driver and membership agreement.
//!
//! [`King::poll`] runs, with the caller's time in microseconds:
//!
//! 1. First `poll`: 125 kbit/s, Communicate; send the Default Letter, and
//!    again every `default_letter_period_us` (50 ms) while the first
//!    `default_window_us` (200 ms) last, so that every City's 200 ms
//!    Silent window (step 2) sees one even if it started a little later.
//! 2. At the end of that window: one broadcast King's Page 1 (address 0)
//!    with the base number and "respond with Mayor's Page 0". Broadcast,
//!    because the seed has the King learn each City's address from the
//!    reply's envelope (envelope - base number). Repeated after
//!    `reply_timeout_us` while an expected City is missing, at most
//!    `page1_attempts` times in all.
//! 3. Membership agreement: each reply's EAN is checked against the
//!    expected City at that address; missing, mismatched and unknown
//!    Cities are reported. If all agree: the pages queued with
//!    [`King::send_page`] go out, then King's Page 0 (Run + Communicate,
//!    broadcast), and the King is [`KingPhase::Running`]. Otherwise it is
//!    [`KingPhase::Halted`]: it orders nothing itself (the Kingdom Founder
//!    approves all Cities or none run); queued pages still go out, so the
//!    application may order Run anyway with `send_page`.
//!
//! Mayor's Letters (envelopes base + 1 ..= base + 255, same format) are
//! recorded in any phase, so later requests for Mayor's Page 1 (serial
//! numbers) via `send_page` are collected too.

use embedded_can::Frame;

use crate::king_pages::{
    Action, BaseNumber, Initiation, KingLetter, KingPage, RuntimeControl, BROADCAST,
};
use crate::letter::{
    EncodeError, Envelope, Letter, Reject, RejectCounters, DEFAULT_KING_ENVELOPE, MAX_EXTENDED,
};
use crate::mayor_pages::MayorPage;
use crate::postmaster::{BitRate, CommMode, Outbox, Postmaster, MAX_RX_PER_POLL};

/// A City the Kingdom Founder approved: its address and EAN.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ExpectedCity {
    /// City address, 1..=255.
    pub address: u8,
    /// EAN-13 without check digit (40-bit).
    pub ean: u64,
}

/// What the Kingdom Founder configures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct KingConfig<const N: usize> {
    /// The approved Cities.
    pub cities: [ExpectedCity; N],
    /// The base number (its format chooses standard/extended envelopes).
    pub base_number: Envelope,
    /// Envelope of the King's Letters (default 0, standard).
    pub king_envelope: Envelope,
    /// Default Letter repetition period (default 50 ms).
    pub default_letter_period_us: u64,
    /// How long Default Letters are sent (default 200 ms).
    pub default_window_us: u64,
    /// Wait for Mayor's replies after each King's Page 1 (default 100 ms).
    pub reply_timeout_us: u64,
    /// King's Page 1 sendings at most (default 3; 0 counts as 1).
    pub page1_attempts: u8,
}

impl<const N: usize> KingConfig<N> {
    /// A configuration with the defaults above.
    pub const fn new(cities: [ExpectedCity; N], base_number: Envelope) -> Self {
        Self {
            cities,
            base_number,
            king_envelope: DEFAULT_KING_ENVELOPE,
            default_letter_period_us: 50_000,
            default_window_us: 200_000,
            reply_timeout_us: 100_000,
            page1_attempts: 3,
        }
    }
}

/// A configuration [`King::new`] refuses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KingConfigError {
    /// An expected City with address 0.
    AddressZero,
    /// Base number 0 or `0x1FFF_FFFF` (no wire form in King's Page 1).
    BaseNotExpressible,
    /// Base number + some City address does not fit the format.
    BaseOutOfRange,
}

/// Why [`King::send_page`] refused a page.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SendError {
    /// The page has no wire form.
    Encode(EncodeError),
    /// The queue is full.
    QueueFull,
}

/// Where the King stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum KingPhase {
    /// `poll` not called yet.
    NotStarted,
    /// Sending Default Letters.
    DefaultLetters,
    /// King's Page 1 sent (`attempt`, from 1), collecting Mayor's Page 0.
    Polling {
        /// Which sending of Page 1.
        attempt: u8,
    },
    /// Membership agreed; Page 0 Run + Communicate ordered.
    Running,
    /// Membership not agreed; nothing ordered.
    Halted,
}

/// The agreement of one expected City.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CityStatus {
    /// No Mayor's Page 0 from its address.
    Missing,
    /// Reported the expected EAN.
    Agreed,
    /// Reported another EAN.
    Mismatch,
}

/// What the King knows of one expected City.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct CityReport {
    /// City address.
    pub address: u8,
    /// The EAN the Founder expects.
    pub expected_ean: u64,
    /// The EAN the Mayor reported (Mayor's Page 0).
    pub reported_ean: Option<u64>,
    /// The serial number the Mayor reported (Mayor's Page 1).
    pub serial: Option<u64>,
}

impl CityReport {
    /// This City's agreement.
    pub fn status(&self) -> CityStatus {
        match self.reported_ean {
            None => CityStatus::Missing,
            Some(e) if e == self.expected_ean => CityStatus::Agreed,
            Some(_) => CityStatus::Mismatch,
        }
    }
}

/// A City that answered but is not expected.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct UnknownCity {
    /// Its address (envelope - base number).
    pub address: u8,
    /// The EAN it reported, if any.
    pub ean: Option<u64>,
    /// The serial number it reported, if any.
    pub serial: Option<u64>,
}

/// Unknown Cities remembered individually (more are only counted).
pub const MAX_UNKNOWN: usize = 8;

/// The membership agreement.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Membership {
    /// Still polling.
    Pending,
    /// Every expected City reported its EAN; no other City answered.
    Agreed,
    /// Something is wrong.
    Disagreed {
        /// Expected Cities that did not answer.
        missing: usize,
        /// Expected Cities that reported another EAN.
        mismatched: usize,
        /// Cities that answered but are not expected.
        unknown: usize,
    },
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum State {
    NotStarted,
    Default { start: u64, next: u64 },
    Polling { attempt: u8, sent_at: u64 },
    Running,
    Halted,
}

/// The Capital's King for `N` expected Cities, with room for `QUEUE`
/// application-queued King's Letters.
#[derive(Debug, Clone)]
pub struct King<const N: usize, const QUEUE: usize = 8> {
    cfg: KingConfig<N>,
    state: State,
    reports: [CityReport; N],
    unknown: [Option<UnknownCity>; MAX_UNKNOWN],
    unknown_count: usize,
    rejects: RejectCounters,
    outbox: Outbox<4>,
    queue: Outbox<QUEUE>,
}

impl<const N: usize, const QUEUE: usize> King<N, QUEUE> {
    /// A King that starts on the first `poll`.
    pub fn new(cfg: KingConfig<N>) -> Result<Self, KingConfigError> {
        let b = cfg.base_number;
        if b.number() == 0 || b.number() == MAX_EXTENDED {
            return Err(KingConfigError::BaseNotExpressible);
        }
        for c in &cfg.cities {
            if c.address == 0 {
                return Err(KingConfigError::AddressZero);
            }
            if b.offset(u32::from(c.address)).is_none() {
                return Err(KingConfigError::BaseOutOfRange);
            }
        }
        Ok(Self {
            reports: cfg.cities.map(|c| CityReport {
                address: c.address,
                expected_ean: c.ean,
                reported_ean: None,
                serial: None,
            }),
            cfg,
            state: State::NotStarted,
            unknown: [None; MAX_UNKNOWN],
            unknown_count: 0,
            rejects: RejectCounters::default(),
            outbox: Outbox::new(),
            queue: Outbox::new(),
        })
    }

    /// Queue a King's Letter to `address` (0 = all). Queued letters go out
    /// once the membership check is over (before Page 0 Run), then at once.
    pub fn send_page(&mut self, address: u8, page: KingPage) -> Result<(), SendError> {
        let page = KingLetter { address, page }
            .encode()
            .map_err(SendError::Encode)?;
        let letter = Letter {
            envelope: self.cfg.king_envelope,
            page,
        };
        self.queue.push(letter).map_err(|_| SendError::QueueFull)
    }

    /// Run the King: read the controller, advance the start-up, send.
    pub fn poll<P: Postmaster>(&mut self, now_us: u64, post: &mut P) {
        self.poll_with(now_us, post, |_| {});
    }

    /// As [`poll`](Self::poll), handing frames that are not Mayor's Letters
    /// to `other`.
    pub fn poll_with<P: Postmaster>(
        &mut self,
        now_us: u64,
        post: &mut P,
        mut other: impl FnMut(&P::Frame),
    ) {
        if self.state == State::NotStarted {
            post.set_bit_rate(BitRate::Kbit125);
            post.set_comm_mode(CommMode::Communicate);
            self.state = State::Default {
                start: now_us,
                next: now_us,
            };
        }
        for _ in 0..MAX_RX_PER_POLL {
            match post.receive() {
                Ok(f) => self.handle(&f, &mut other),
                Err(_) => break,
            }
        }
        self.advance(now_us);
        self.outbox.flush(post);
        if matches!(self.state, State::Running | State::Halted) && self.outbox.len() == 0 {
            self.queue.flush(post);
        }
    }

    fn advance(&mut self, now: u64) {
        match self.state {
            State::Default { start, next } => {
                if now.saturating_sub(start) >= self.cfg.default_window_us {
                    self.send_page1(now, 1);
                } else if now >= next {
                    let _ = self.outbox.push(Letter::DEFAULT);
                    let next = next.saturating_add(self.cfg.default_letter_period_us.max(1));
                    self.state = State::Default { start, next };
                }
            }
            State::Polling { attempt, sent_at } => {
                if now.saturating_sub(sent_at) < self.cfg.reply_timeout_us {
                    return;
                }
                let missing = self.reports.iter().any(|r| r.reported_ean.is_none());
                if missing && attempt < self.cfg.page1_attempts {
                    self.send_page1(now, attempt + 1);
                } else if self.membership_now() == Membership::Agreed {
                    let run = KingPage::Page0(RuntimeControl {
                        action: Some(Action::Run),
                        comm: Some(CommMode::Communicate),
                        city_mode: 0,
                    });
                    let letter = self.king_letter(BROADCAST, run);
                    if let Some(l) = letter {
                        // After the pages the application queued; if that
                        // queue is full, ahead of them.
                        if let Err(l) = self.queue.push(l) {
                            let _ = self.outbox.push(l);
                        }
                    }
                    self.state = State::Running;
                } else {
                    self.state = State::Halted;
                }
            }
            State::NotStarted | State::Running | State::Halted => {}
        }
    }

    fn king_letter(&self, address: u8, page: KingPage) -> Option<Letter> {
        let page = KingLetter { address, page }.encode().ok()?;
        Some(Letter {
            envelope: self.cfg.king_envelope,
            page,
        })
    }

    fn send_page1(&mut self, now: u64, attempt: u8) {
        let page1 = KingPage::Page1(Initiation {
            response: Some(0),
            base: BaseNumber::Set(self.cfg.base_number),
        });
        if let Some(l) = self.king_letter(BROADCAST, page1) {
            let _ = self.outbox.push(l);
        }
        self.state = State::Polling {
            attempt,
            sent_at: now,
        };
    }

    fn handle<F: Frame>(&mut self, f: &F, other: &mut impl FnMut(&F)) {
        let env = Envelope::from_id(f.id());
        let base = self.cfg.base_number;
        let offset = env.number().wrapping_sub(base.number());
        if env.is_extended() != base.is_extended() || !(1..=255).contains(&offset) {
            return other(f);
        }
        let address = offset as u8;
        if f.is_remote_frame() {
            return self.rejects.record(Reject::RemoteFrame);
        }
        let page = match MayorPage::decode(f.data()) {
            Ok(p) => p,
            Err(r) => return self.rejects.record(r),
        };
        let (ean, serial) = match page {
            MayorPage::Identification { ean } => (Some(ean), None),
            MayorPage::Serial { serial } => (None, Some(serial)),
        };
        let mut known = false;
        for r in self.reports.iter_mut().filter(|r| r.address == address) {
            known = true;
            r.reported_ean = ean.or(r.reported_ean);
            r.serial = serial.or(r.serial);
        }
        if known {
            return;
        }
        if let Some(u) = self
            .unknown
            .iter_mut()
            .flatten()
            .find(|u| u.address == address)
        {
            u.ean = ean.or(u.ean);
            u.serial = serial.or(u.serial);
            return;
        }
        let entry = UnknownCity {
            address,
            ean,
            serial,
        };
        if let Some(slot) = self.unknown.iter_mut().find(|s| s.is_none()) {
            *slot = Some(entry);
        }
        self.unknown_count = self.unknown_count.saturating_add(1);
    }

    fn membership_now(&self) -> Membership {
        let count = |s| self.reports.iter().filter(|r| r.status() == s).count();
        let (missing, mismatched) = (count(CityStatus::Missing), count(CityStatus::Mismatch));
        if missing == 0 && mismatched == 0 && self.unknown_count == 0 {
            Membership::Agreed
        } else {
            Membership::Disagreed {
                missing,
                mismatched,
                unknown: self.unknown_count,
            }
        }
    }

    /// The membership agreement (`Pending` until polling is over; kept up
    /// to date with replies that come later).
    pub fn membership(&self) -> Membership {
        match self.state {
            State::Running | State::Halted => self.membership_now(),
            _ => Membership::Pending,
        }
    }

    /// Where the King stands.
    pub fn phase(&self) -> KingPhase {
        match self.state {
            State::NotStarted => KingPhase::NotStarted,
            State::Default { .. } => KingPhase::DefaultLetters,
            State::Polling { attempt, .. } => KingPhase::Polling { attempt },
            State::Running => KingPhase::Running,
            State::Halted => KingPhase::Halted,
        }
    }

    /// One report per expected City, in configuration order.
    pub fn cities(&self) -> &[CityReport; N] {
        &self.reports
    }

    /// The report of the expected City at `address`.
    pub fn city(&self, address: u8) -> Option<&CityReport> {
        self.reports.iter().find(|r| r.address == address)
    }

    /// Cities that answered but are not expected (the first [`MAX_UNKNOWN`]).
    pub fn unknown_cities(&self) -> impl Iterator<Item = &UnknownCity> {
        self.unknown.iter().flatten()
    }

    /// Number of unexpected Cities that answered: distinct addresses up to
    /// [`MAX_UNKNOWN`], beyond that every further reply is counted.
    pub fn unknown_count(&self) -> usize {
        self.unknown_count
    }

    /// Mayor's Letters rejected for `reason`.
    pub fn rejected(&self, reason: Reject) -> u32 {
        self.rejects.get(reason)
    }

    /// All rejection counters.
    pub fn rejects(&self) -> &RejectCounters {
        &self.rejects
    }

    /// Letters the application queued that are not yet sent.
    pub fn queued(&self) -> usize {
        self.queue.len()
    }

    /// The configuration.
    pub fn config(&self) -> &KingConfig<N> {
        &self.cfg
    }
}
