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

use crate::{base_data, letter};
use cankingdom::king_pages::{BaseNumber, Initiation, KingLetter, KingPage};
use cankingdom::MayorPage;
use embedded_can::Frame;

pub use crate::{CONNECT_LEFT, CONNECT_RIGHT, TRANSPARENT};

mod master;
mod slave;

pub use master::Master;
pub use slave::Slave;

/// Envelope of the REDCAN letters (the master's "the node beyond you answered").
pub const REDCAN_ENVELOPE: u32 = 0x010;
/// Envelope of the King's Letters (CanKingdom default).
pub const KING_ENVELOPE: u32 = 0x000;
/// The Kingdom's base number: a City answers on `BASE + address`.
pub const BASE: u32 = 0x400;

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
pub fn page1_letter<F: Frame>(address: u8) -> F {
    let page = KingLetter {
        address,
        page: KingPage::Page1(Initiation {
            response: Some(0),
            base: BaseNumber::Keep,
        }),
    }
    .encode()
    .expect("a valid King's Page 1");
    letter(KING_ENVELOPE, &page)
}

/// The REDCAN letter "the node beyond you answered", to City `address`.
pub fn beyond_letter<F: Frame>(address: u8) -> F {
    letter(REDCAN_ENVELOPE, &[address, 1])
}

/// The City address that answered with `f` (a Mayor's Page on `BASE + address`).
pub fn answer_of<F: Frame>(f: &F) -> Option<u8> {
    let (id, data) = base_data(f)?;
    if id <= BASE || id > BASE + 255 {
        return None;
    }
    MayorPage::decode(data).ok()?;
    Some((id - BASE) as u8)
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
