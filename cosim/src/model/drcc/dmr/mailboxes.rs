//! DMR mailboxes (dmr_contract.md §4.1, §4.2 and the window registers of §2.1): one
//! counter and one timer per mailbox (the seed's Figure 3), the lowest-index match
//! of a frame key, the counter step of a transfer and the periodic evaluation that
//! turns an unbalanced counter into a fault against a line.

use crate::frame::Frame;

/// The key of a frame: `{ide, id[28:0]}`, base identifiers right-aligned (§4.1).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Key {
    pub ide: bool,
    pub id: u32,
}

impl Key {
    /// The key of `f`.
    pub fn of(f: &Frame) -> Self {
        Key {
            ide: f.ide,
            id: f.id & 0x1FFF_FFFF,
        }
    }
}

/// Mailbox direction (`MB_ID.dir`).
pub const RECEIVE: bool = false;
pub const TRANSMIT: bool = true;

/// One DMR mailbox: its configuration and its state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mailbox {
    /// `MB_ID`, `MB_MASK`: a memory `rst` does not clear (§2.1).
    pub id: u32,
    pub ide: bool,
    pub dir: bool,
    pub mask: u32,
    /// `MB_CFG`: registers (`rst`: 3 and 0).
    pub limit: u8,
    pub enable: bool,
    /// Two's complement, saturating at -128 / 127.
    pub counter: i8,
    /// DMR ticks left, 0 = stopped.
    pub timer: u16,
    /// §4.2 settling: set where a recovery clears counter and timer; the
    /// mailbox's first timeout after that re-balances it. 0 in reset mode.
    pub settle: bool,
    /// §4.2 debt: set by a timeout, which keeps the counter: the copies the
    /// judged line owes pay it back instead of starting a new imbalance. Cleared
    /// when the counter is back at 0, by a deviation and by every clearing.
    pub owed: bool,
}

impl Default for Mailbox {
    fn default() -> Self {
        Mailbox {
            id: 0,
            ide: false,
            dir: RECEIVE,
            mask: 0,
            limit: super::super::regs::dmr::LIMIT_RESET,
            enable: false,
            counter: 0,
            timer: 0,
            settle: false,
            owed: false,
        }
    }
}

/// A verdict of the evaluation (§4.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// `DEVIATION` (true) or `TIMEOUT` (false).
    pub deviation: bool,
    /// The faulty line: `counter > 0 ? RCL : DCL` (0 DCL, 1 RCL).
    pub line: usize,
    /// The mailbox's direction: a transmit mailbox judges `tx`, a receive one `rx`.
    pub dir: bool,
}

impl Mailbox {
    /// §4.1: `enable && dir == d && ide == key.ide && ((key.id ^ id) & mask) == 0`.
    pub fn matches(&self, key: &Key, dir: bool) -> bool {
        self.enable
            && self.dir == dir
            && self.ide == key.ide
            && ((key.id ^ self.id) & self.mask & 0x1FFF_FFFF) == 0
    }

    /// `MB_ID` register value.
    pub fn id_reg(&self) -> u32 {
        (self.id & 0x1FFF_FFFF) | (self.ide as u32) << 29 | (self.dir as u32) << 30
    }

    /// `MB_CFG` register value.
    pub fn cfg_reg(&self) -> u32 {
        self.limit as u32 | (self.enable as u32) << 31
    }

    /// `MB_STATE` register value: [7:0] counter, [31:16] timer.
    pub fn state_reg(&self) -> u32 {
        self.counter as u8 as u32 | (self.timer as u32) << 16
    }

    /// `REQ(L)` (§4.1): "The DLL transmission request loads a configured timeout value".
    pub fn request(&mut self, timeout: u16) {
        self.timer = timeout;
    }

    /// Counter step of a transfer on `line` (§4.1): +1 for the DCL, -1 for the RCL;
    /// balanced stops the timer (and pays off a debt), the first copy or a copy
    /// from the lagging line (re)starts it, a copy from the leading line leaves
    /// it; while a debt is owed (§4.2) no copy starts the timer.
    pub fn step(&mut self, line: usize, timeout: u16) {
        let c = self.counter as i16;
        let c1 = (c + if line == 0 { 1 } else { -1 }).clamp(-128, 127);
        if c1 == 0 {
            self.timer = 0;
            self.owed = false;
        } else if !self.owed && (c == 0 || c1.abs() < c.abs()) {
            self.timer = timeout;
        }
        self.counter = c1 as i8;
    }

    /// One evaluation of an enabled mailbox (§4.2, seed Figure 4), on its values before it.
    pub fn evaluate(&mut self) -> Option<Verdict> {
        let t1 = self.timer.saturating_sub(1);
        let c = self.counter as i16;
        // The sign names the faulty line: "A positive value denotes that more
        // messages have been transferred over DCL, hence the RCL is faulty".
        let verdict = |deviation| Verdict {
            deviation,
            line: if c > 0 { 1 } else { 0 },
            dir: self.dir,
        };
        let (v, judged) = if c.abs() > self.limit as i16 {
            (Some(verdict(true)), true)
        } else if c != 0 && t1 == 0 && !self.owed {
            // A mailbox's first timeout after a clearing is a new balance point:
            // the skew of the copies in flight at the clearing (§4.2).
            let rebalance = self.settle;
            (
                if rebalance {
                    crate::model::coverage::hit(
                        "dmr: receive mailbox re-balanced after a recovery",
                    );
                    None
                } else {
                    Some(verdict(false))
                },
                true,
            )
        } else {
            (None, false)
        };
        if judged {
            // A timeout keeps the counter as the judged line's debt (§4.2): its
            // late copies pay it back; a deviation or a re-balance clears it.
            let timeout = v.is_some_and(|v| !v.deviation);
            if !timeout {
                self.counter = 0;
            }
            self.owed = timeout;
            self.timer = 0;
            self.settle = false;
        } else {
            self.timer = t1;
        }
        v
    }
}

/// The `M` mailboxes (generation parameter, 0..16).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mailboxes {
    pub mb: Vec<Mailbox>,
}

impl Mailboxes {
    /// `m` mailboxes after FPGA configuration.
    pub fn new(m: usize) -> Self {
        assert!(m <= 16, "DMR mailboxes: M is 0..16");
        Mailboxes {
            mb: vec![Mailbox::default(); m],
        }
    }

    /// Number of mailboxes `M`.
    pub fn m(&self) -> usize {
        self.mb.len()
    }

    /// A `rst` edge: the registers clear, the identifier memory stays.
    pub fn rst(&mut self) {
        for b in &mut self.mb {
            *b = Mailbox {
                id: b.id,
                ide: b.ide,
                dir: b.dir,
                mask: b.mask,
                ..Mailbox::default()
            };
        }
    }

    /// Reset mode (and every mode but DMR): counters and timers clear (§2.1), no
    /// mailbox settles (§4.2).
    pub fn clear_state(&mut self) {
        for b in &mut self.mb {
            b.counter = 0;
            b.timer = 0;
            b.settle = false;
            b.owed = false;
        }
    }

    /// A recovery (§7): counters and timers clear and every mailbox settles (§4.2).
    pub fn clear_for_recovery(&mut self) {
        for b in &mut self.mb {
            b.counter = 0;
            b.timer = 0;
            b.settle = true;
            b.owed = false;
        }
    }

    /// Any mailbox enabled (§2.2: `DMR_CS` is refused then).
    pub fn any_enabled(&self) -> bool {
        self.mb.iter().any(|b| b.enable)
    }
}
