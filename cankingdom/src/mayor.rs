//! The Mayor: a City's CanKingdom state machine.
//!
//! Start-up (seed, "Startup sequence"), driven by [`Mayor::poll`]:
//!
//! 1. Internal tests: the application's job before the first `poll`.
//! 2. First `poll`: 125 kbit/s, Silent, for 200 ms, waiting for the Default
//!    Letter (envelope 2031 standard, 8 x `0xAA`). Other letters are not
//!    acted upon in this window (the bit timing is not yet confirmed).
//!    - 2a. Default Letter received: keep the bit timing, switch to Listen
//!      Only and wait for the King's Letters ([`JoinPath::DefaultLetter`]).
//!      The King is evidently running the start-up, so the Mayor does not
//!      announce itself: the King's Page 1 asks for that.
//!    - 2b. No Default Letter in 200 ms: load the presumed bit rate, still
//!      Silent, wait for any correctly received Letter (any frame the
//!      controller delivers; CAN's CRC has checked it).
//! 3. That Letter received (steps 3a/3b continue 2b, where they stand in
//!    the seed's list):
//!    - 3a. Base number known: Communicate, send Mayor's Page 0 on
//!      base + address ([`JoinPath::Announced`]).
//!    - 3b. Otherwise: Listen Only, wait for the King's Letters
//!      ([`JoinPath::Listening`]).
//!
//! Once joined, the King's Letters (King's envelope, Line 0 = own address,
//! one of the City's groups, or 0) are decoded and applied; a malformed or
//! unstorable letter is rejected whole and counted per [`Reject`] reason.
//! Letters addressed to other cities are ignored without being decoded.

use embedded_can::Frame;

use crate::king_pages::{Action, BaseNumber, KingLetter, KingPage, BROADCAST};
use crate::letter::{Envelope, Letter, Reject, RejectCounters, DEFAULT_KING_ENVELOPE};
use crate::mayor_pages::{MayorPage, MAX_40_BIT};
use crate::postmaster::{BitRate, CommMode, Outbox, Postmaster, MAX_RX_PER_POLL};
use crate::tables::{FolderTable, IntervalTable, LinkTable};

/// The start-up window at 125 kbit/s, in microseconds (200 ms).
pub const STARTUP_WINDOW_US: u64 = 200_000;

/// Number of group addresses a City can belong to.
pub const MAX_GROUPS: usize = 4;

/// What the City Founder configures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MayorConfig {
    /// City address, 1..=255.
    pub address: u8,
    /// Group addresses this City answers to besides its own (0 = unused).
    pub groups: [u8; MAX_GROUPS],
    /// EAN-13 without check digit, 40-bit (Mayor's Page 0).
    pub ean: u64,
    /// Serial number, 40-bit (Mayor's Page 1).
    pub serial: u64,
    /// The Kingdom's base number if known a priori.
    pub base_number: Option<Envelope>,
    /// Bit rate of the "presumed Kingdom and location" (step 2b).
    pub presumed_bit_rate: BitRate,
    /// Envelope of the King's Letters (default 0, standard).
    pub king_envelope: Envelope,
}

impl MayorConfig {
    /// A configuration with no groups, no known base number, presumed
    /// bit rate 125 kbit/s and the default King's envelope.
    pub const fn new(address: u8, ean: u64, serial: u64) -> Self {
        Self {
            address,
            groups: [0; MAX_GROUPS],
            ean,
            serial,
            base_number: None,
            presumed_bit_rate: BitRate::Kbit125,
            king_envelope: DEFAULT_KING_ENVELOPE,
        }
    }
}

/// A configuration [`Mayor::new`] refuses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MayorConfigError {
    /// City address 0 (that is the broadcast address).
    AddressZero,
    /// EAN or serial number wider than 40 bits.
    ValueTooLarge,
    /// Known base number + address does not fit the base number's format.
    BaseOutOfRange,
}

/// How the City joined the Kingdom.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JoinPath {
    /// 2a: Default Letter received; Listen Only.
    DefaultLetter,
    /// 3a: base number known; Communicate, Mayor's Page 0 sent.
    Announced,
    /// 3b: base number unknown; Listen Only.
    Listening,
}

/// Where the start-up sequence stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Startup {
    /// `poll` not called yet.
    NotStarted,
    /// Step 2: Silent at 125 kbit/s, waiting for the Default Letter.
    AwaitingDefaultLetter,
    /// Step 2b: Silent at the presumed bit rate, waiting for any Letter.
    AwaitingLetter,
    /// Joined; the King's Letters are applied.
    Joined(JoinPath),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum State {
    NotStarted,
    WaitDefault { since: u64 },
    WaitLetter,
    Joined(JoinPath),
}

/// A City's Mayor with `FOLDERS` envelope assignments, `LINKS`
/// action/reaction links and `INTERVALS` minimum intervals.
#[derive(Debug, Clone)]
pub struct Mayor<const FOLDERS: usize = 16, const LINKS: usize = 8, const INTERVALS: usize = 16> {
    cfg: MayorConfig,
    state: State,
    base: Option<Envelope>,
    comm: CommMode,
    bit_rate: BitRate,
    action: Option<Action>,
    city_mode: u8,
    folders: FolderTable<FOLDERS>,
    links: LinkTable<LINKS>,
    intervals: IntervalTable<INTERVALS>,
    rejects: RejectCounters,
    accepted: u32,
    unsent: u32,
    outbox: Outbox<4>,
}

impl<const FOLDERS: usize, const LINKS: usize, const INTERVALS: usize>
    Mayor<FOLDERS, LINKS, INTERVALS>
{
    /// A Mayor that starts its start-up sequence on the first `poll`.
    pub fn new(cfg: MayorConfig) -> Result<Self, MayorConfigError> {
        if cfg.address == 0 {
            return Err(MayorConfigError::AddressZero);
        }
        if cfg.ean > MAX_40_BIT || cfg.serial > MAX_40_BIT {
            return Err(MayorConfigError::ValueTooLarge);
        }
        if let Some(b) = cfg.base_number {
            if b.offset(u32::from(cfg.address)).is_none() {
                return Err(MayorConfigError::BaseOutOfRange);
            }
        }
        Ok(Self {
            cfg,
            state: State::NotStarted,
            base: cfg.base_number,
            comm: CommMode::Silent,
            bit_rate: BitRate::Kbit125,
            action: None,
            city_mode: 0,
            folders: FolderTable::default(),
            links: LinkTable::default(),
            intervals: IntervalTable::default(),
            rejects: RejectCounters::default(),
            accepted: 0,
            unsent: 0,
            outbox: Outbox::new(),
        })
    }

    /// Back to power-on: the next `poll` starts the sequence again; what
    /// the King configured is forgotten, the counters are kept. (For the
    /// City application, e.g. on [`Action::Reset`].)
    pub fn restart(&mut self) {
        let (rejects, accepted, unsent) = (self.rejects, self.accepted, self.unsent);
        if let Ok(fresh) = Self::new(self.cfg) {
            *self = fresh;
        }
        self.rejects = rejects;
        self.accepted = accepted;
        self.unsent = unsent;
    }

    /// Run the Mayor: read the controller, act, send what is due.
    /// `now_us` is the caller's monotonic time in microseconds.
    pub fn poll<P: Postmaster>(&mut self, now_us: u64, post: &mut P) {
        self.poll_with(now_us, post, |_| {});
    }

    /// As [`poll`](Self::poll), handing every received frame that is neither
    /// a King's Letter nor the Default Letter to `other` (the application's
    /// letters).
    pub fn poll_with<P: Postmaster>(
        &mut self,
        now_us: u64,
        post: &mut P,
        mut other: impl FnMut(&P::Frame),
    ) {
        if self.state == State::NotStarted {
            self.bit_rate = BitRate::Kbit125;
            post.set_bit_rate(BitRate::Kbit125);
            self.comm = CommMode::Silent;
            post.set_comm_mode(CommMode::Silent);
            self.state = State::WaitDefault { since: now_us };
        }
        for _ in 0..MAX_RX_PER_POLL {
            match post.receive() {
                Ok(frame) => self.handle(&frame, post, &mut other),
                Err(_) => break,
            }
        }
        if let State::WaitDefault { since } = self.state {
            if now_us.saturating_sub(since) >= STARTUP_WINDOW_US {
                self.bit_rate = self.cfg.presumed_bit_rate;
                post.set_bit_rate(self.bit_rate);
                self.state = State::WaitLetter; // 2b: still Silent
            }
        }
        if self.comm != CommMode::Silent {
            self.outbox.flush(post);
        }
    }

    fn handle<P: Postmaster>(
        &mut self,
        f: &P::Frame,
        post: &mut P,
        other: &mut impl FnMut(&P::Frame),
    ) {
        let is_default = Letter::from_frame(f).is_ok_and(|l| l.is_default_letter());
        match self.state {
            State::NotStarted | State::Joined(_) => {}
            State::WaitDefault { .. } => {
                if is_default {
                    self.set_comm(CommMode::ListenOnly, post); // 2a
                    self.state = State::Joined(JoinPath::DefaultLetter);
                } else if Envelope::from_id(f.id()) != self.cfg.king_envelope {
                    other(f);
                }
                return;
            }
            State::WaitLetter => {
                if self.own_envelope().is_some() {
                    self.set_comm(CommMode::Communicate, post); // 3a
                    self.send(MayorPage::Identification { ean: self.cfg.ean });
                    self.state = State::Joined(JoinPath::Announced);
                } else {
                    self.set_comm(CommMode::ListenOnly, post); // 3b
                    self.state = State::Joined(JoinPath::Listening);
                }
            }
        }
        if Envelope::from_id(f.id()) == self.cfg.king_envelope {
            self.king_letter(f, post);
        } else if !is_default {
            other(f);
        }
    }

    fn addressed(&self, address: u8) -> bool {
        address == BROADCAST
            || address == self.cfg.address
            || self.cfg.groups.iter().any(|&g| g != 0 && g == address)
    }

    fn king_letter<P: Postmaster>(&mut self, f: &P::Frame, post: &mut P) {
        if f.is_remote_frame() {
            self.rejects.record(Reject::RemoteFrame);
            return;
        }
        let data = f.data();
        match data.first() {
            None => return self.rejects.record(Reject::WrongLength),
            Some(&a) if !self.addressed(a) => return,
            Some(_) => {}
        }
        let result = KingLetter::decode(data).and_then(|l| self.apply(l.page, post));
        match result {
            Ok(()) => self.accepted = self.accepted.saturating_add(1),
            Err(r) => self.rejects.record(r),
        }
    }

    fn apply<P: Postmaster>(&mut self, page: KingPage, post: &mut P) -> Result<(), Reject> {
        match page {
            KingPage::Page0(rc) => {
                if let Some(a) = rc.action {
                    self.action = Some(a);
                }
                if let Some(m) = rc.comm {
                    self.set_comm(m, post);
                }
                if rc.city_mode != 0 {
                    self.city_mode = rc.city_mode;
                }
                Ok(())
            }
            KingPage::Page1(init) => {
                let reply = match init.response {
                    None => None,
                    Some(0) => Some(MayorPage::Identification { ean: self.cfg.ean }),
                    Some(1) => Some(MayorPage::Serial {
                        serial: self.cfg.serial,
                    }),
                    Some(_) => return Err(Reject::UnsupportedResponsePage),
                };
                let base = match init.base {
                    BaseNumber::Keep => self.base,
                    BaseNumber::Undefined => None,
                    BaseNumber::Set(b) => {
                        b.offset(u32::from(self.cfg.address))
                            .ok_or(Reject::EnvelopeOutOfRange)?;
                        Some(b)
                    }
                };
                if reply.is_some() && base.is_none() {
                    return Err(Reject::BaseNumberUnknown);
                }
                self.base = base;
                if let Some(page) = reply {
                    self.send(page);
                }
                Ok(())
            }
            KingPage::Page2(a) => self.folders.apply(&a),
            KingPage::Page5(l) => self.links.add(l),
            KingPage::Page10(m) => self.intervals.set(m),
        }
    }

    fn set_comm<P: Postmaster>(&mut self, mode: CommMode, post: &mut P) {
        post.set_comm_mode(mode);
        self.comm = mode;
        if mode == CommMode::Silent {
            let dropped = self.outbox.clear() as u32;
            self.unsent = self.unsent.saturating_add(dropped);
        }
    }

    /// Queue a Mayor's page on base + address (counted as unsent if Silent,
    /// no base number, or no room).
    fn send(&mut self, page: MayorPage) {
        let queued = match (self.own_envelope(), page.encode()) {
            (Some(envelope), Ok(page)) if self.comm != CommMode::Silent => {
                self.outbox.push(Letter { envelope, page }).is_ok()
            }
            _ => false,
        };
        if !queued {
            self.unsent = self.unsent.saturating_add(1);
        }
    }

    /// The configuration.
    pub fn config(&self) -> &MayorConfig {
        &self.cfg
    }

    /// Where the start-up sequence stands.
    pub fn startup(&self) -> Startup {
        match self.state {
            State::NotStarted => Startup::NotStarted,
            State::WaitDefault { .. } => Startup::AwaitingDefaultLetter,
            State::WaitLetter => Startup::AwaitingLetter,
            State::Joined(p) => Startup::Joined(p),
        }
    }

    /// The Communication Mode last given to the Postmaster.
    pub fn comm_mode(&self) -> CommMode {
        self.comm
    }

    /// The bit rate last given to the Postmaster.
    pub fn bit_rate(&self) -> BitRate {
        self.bit_rate
    }

    /// The Action Mode last ordered by King's Page 0 (`None` before any).
    pub fn action(&self) -> Option<Action> {
        self.action
    }

    /// The City Mode last ordered by King's Page 0 (0 before any).
    pub fn city_mode(&self) -> u8 {
        self.city_mode
    }

    /// The base number, if known.
    pub fn base_number(&self) -> Option<Envelope> {
        self.base
    }

    /// The Mayor's transmit envelope, base number + city address.
    pub fn own_envelope(&self) -> Option<Envelope> {
        self.base?.offset(u32::from(self.cfg.address))
    }

    /// Envelope assignments (King's Page 2).
    pub fn folders(&self) -> &FolderTable<FOLDERS> {
        &self.folders
    }

    /// Action/reaction links (King's Page 5).
    pub fn links(&self) -> &LinkTable<LINKS> {
        &self.links
    }

    /// Mutable links, for the City application to delete one.
    pub fn links_mut(&mut self) -> &mut LinkTable<LINKS> {
        &mut self.links
    }

    /// Minimum transmission intervals (King's Page 10).
    pub fn intervals(&self) -> &IntervalTable<INTERVALS> {
        &self.intervals
    }

    /// King's Letters rejected for `reason`.
    pub fn rejected(&self, reason: Reject) -> u32 {
        self.rejects.get(reason)
    }

    /// All rejection counters.
    pub fn rejects(&self) -> &RejectCounters {
        &self.rejects
    }

    /// King's Letters addressed to this City and applied.
    pub fn letters_accepted(&self) -> u32 {
        self.accepted
    }

    /// Mayor's Letters that were due but not sent (Silent mode, no base
    /// number, full queue).
    pub fn unsent(&self) -> u32 {
        self.unsent
    }

    /// Mayor's Letters queued for the controller.
    pub fn pending(&self) -> usize {
        self.outbox.len()
    }
}
