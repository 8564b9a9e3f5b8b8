//! Following the hubs' decision in a replicated star node (DRCC contract §4.5):
//! the hubs' identification frames (base data frames 0x000 / 0x001, DLC 0) are
//! taken out of the RX path and tell the node whether the hubs form one domain or
//! have split into two stars (`STAR_STATUS`, `INT_STATUS.domain`).

use crate::frame::Frame;

/// `STAR_STATUS` state (reset values in the comments).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StarFollow {
    /// [0] the hubs decoupled for good, as this node saw it.
    pub split: bool,
    /// [0] per channel: 0 none, 1 hub A's frame last, 2 hub B's.
    pub last: [u8; 2],
    /// [0] per channel: identification frames received (saturating 255).
    pub hub_frames: [u8; 2],
}

/// A hub's identification frame: base data frame, DLC 0, identifier 0x000 or
/// 0x001. Returns the hub (0 = A, 1 = B).
pub fn identification(f: &Frame) -> Option<u8> {
    (!f.ide && !f.rtr && f.dlc == 0 && f.id >> 1 == 0).then_some(f.id as u8 & 1)
}

impl StarFollow {
    /// `STAR_STATUS`.
    pub fn reg(&self) -> u32 {
        self.split as u32
            | (self.last[0] as u32) << 2
            | (self.last[1] as u32) << 4
            | (self.hub_frames[0] as u32) << 8
            | (self.hub_frames[1] as u32) << 16
    }

    /// One edge: `on` = star mode and running; `rx_valid` and `frames` the
    /// channels' outputs before the edge. Returns, per channel, whether its
    /// reception is an identification frame (kept from the RX path), and whether
    /// `split` changed (`INT_STATUS.domain`).
    pub fn edge(
        &mut self,
        on: bool,
        rx_valid: [bool; 2],
        frames: [&Frame; 2],
    ) -> ([bool; 2], bool) {
        let mut hubf = [false; 2];
        if !on {
            return (hubf, false);
        }
        let before = self.split;
        let mut split = self.split;
        // Channel B first, so that channel A's verdict wins at the same edge.
        for x in [1usize, 0] {
            let Some(h) = rx_valid[x].then(|| identification(frames[x])).flatten() else {
                continue;
            };
            hubf[x] = true;
            // Channel x hangs on hub x: its own hub's frame is h == x.
            if h as usize != x {
                split = false;
            } else if self.last[x] == x as u8 + 1 {
                split = true;
            }
            self.last[x] = h + 1;
            self.hub_frames[x] = self.hub_frames[x].saturating_add(1);
        }
        self.split = split;
        (hubf, split != before)
    }
}
