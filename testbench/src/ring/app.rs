//! One node's application traffic on the ring (ring contract §5.1): a frame every
//! application period, and on a ring node the REDCAN rule that keeps them through
//! a rebuild.
//!
//! A ring node cannot send while it rebuilds the ring: its controller is
//! restarted at every relay change, and a frame queued ahead of its link letters
//! would delay them. It does not give its frames up either:
//!
//! - frames that fall due while the ring is being rebuilt are **held**, in order;
//! - at the detection, the frames it submitted within the **resend horizon**
//!   before it are held again, ahead of those: the fault began at most that long
//!   before the detection (the longest silence the algorithm waits for, plus one
//!   period of what it listens to), so any of them may have reached only part of
//!   the ring, or still sat in the controller's queue that the restart empties;
//! - once the ring is settled again, the held frames are submitted, oldest first,
//!   **one per pace** (2 Ta): every ring node releases at once, and a burst in a
//!   node's transmit queue would hold its own alive letter back long enough for
//!   the others to judge it silent (measured on 10-node rings: the rebuild
//!   started again and again).
//!
//! The centralized algorithm keeps the seed's behaviour instead (`keep` off): its
//! rebuild takes up to 2 T2 (about 1 s), and a ring node simply sends nothing
//! while it lasts; what it had queued at the detection is given up.
//!
//! The delivery is thus at least once: a receiver that had a frame before the
//! fault gets it a second time, in the sender's order, and an application
//! recognises the repeat by the sequence number every frame carries (as CAN's own
//! double reception already asks of it, ISO 11898-1:2015 10.7). A plain node runs
//! no REDCAN and sends whatever the bus lets it: its frames sent while the ring is
//! partitioned reach only its own part.

use drcc_cosim::Frame;
use std::collections::VecDeque;

/// What the node's REDCAN says at this poll.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RingState {
    /// A plain node, or a ring node before its algorithm starts: frames go out
    /// as they fall due.
    Plain,
    /// A ring node on a settled ring.
    Settled,
    /// A ring node rebuilding the ring: frames are held.
    Rebuilding,
}

/// The application frames of one node.
#[derive(Clone, Debug)]
pub struct AppTraffic {
    node: usize,
    base: u32,
    period: u64,
    keep: bool,
    horizon: u64,
    pace: u64,
    next: u64,
    next_release: u64,
    seq: u32,
    was_rebuilding: bool,
    /// Frames waiting for the ring, oldest first.
    held: VecDeque<Frame>,
    /// Frames submitted, with the time: the last `horizon` of them.
    recent: VecDeque<(u64, Frame)>,
    /// Frames submitted a second time after a detection.
    pub resent: usize,
}

impl AppTraffic {
    /// Node `node`'s frames on `base + node`, one every `period` from `first`,
    /// resending what it submitted within `horizon` before a detection, and
    /// submitting at most one frame per `pace`.
    pub fn new(node: usize, base: u32, period: u64, first: u64, horizon: u64, pace: u64) -> Self {
        AppTraffic {
            node,
            base,
            period,
            keep: true,
            horizon,
            pace,
            next: first,
            next_release: 0,
            seq: 0,
            was_rebuilding: false,
            held: VecDeque::new(),
            recent: VecDeque::new(),
            resent: 0,
        }
    }

    /// The seed's behaviour (centralized algorithm): nothing falls due while the
    /// ring is rebuilt, and nothing is held or resent.
    pub fn without_keeping(mut self) -> Self {
        self.keep = false;
        self
    }

    /// The frame with sequence number `seq`: `[seq_hi, seq_lo, node, 0x5A]`.
    pub fn frame(&self, seq: u32) -> Frame {
        Frame::base(
            self.base + self.node as u32,
            &[(seq >> 8) as u8, seq as u8, self.node as u8, 0x5A],
        )
    }

    /// One poll at `now`: `due` when the application may run (the kingdom is up).
    /// Returns the sequence number of a frame that fell due now (the application
    /// produced it, whether it goes out now or later) and the frame to submit
    /// now, if any.
    pub fn poll(&mut self, now: u64, due: bool, state: RingState) -> (Option<u32>, Vec<Frame>) {
        let rebuilding = state == RingState::Rebuilding;
        if rebuilding && !self.keep {
            return (None, Vec::new());
        }
        if rebuilding && !self.was_rebuilding {
            // The detection: what went out within the horizon may not have
            // reached every part of the ring, or may still be queued.
            let since = now.saturating_sub(self.horizon);
            let again: Vec<Frame> = self
                .recent
                .drain(..)
                .filter(|&(at, _)| at >= since)
                .map(|(_, f)| f)
                .collect();
            self.resent += again.len();
            for f in again.into_iter().rev() {
                self.held.push_front(f);
            }
        }
        self.was_rebuilding = rebuilding;
        let mut produced = None;
        if due && now >= self.next {
            let seq = self.seq;
            self.seq += 1;
            self.next = now + self.period;
            self.held.push_back(self.frame(seq));
            produced = Some(seq);
        }
        if rebuilding || now < self.next_release {
            return (produced, Vec::new());
        }
        let out: Vec<Frame> = self.held.pop_front().into_iter().collect();
        if !out.is_empty() {
            self.next_release = now + self.pace;
        }
        if state == RingState::Settled {
            self.recent.extend(out.iter().map(|&f| (now, f)));
            while self
                .recent
                .front()
                .is_some_and(|&(at, _)| at + self.horizon < now)
            {
                self.recent.pop_front();
            }
        }
        (produced, out)
    }
}
