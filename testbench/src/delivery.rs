//! Which scenario frames one host popped, and how often: where the tallies of
//! the dual-bus, star and ECSS fault runs start. A scenario frame names its
//! sender and its index in its first two data bytes (`data[0]`, `data[1]`); a
//! popped frame that names a frame of the scenario but differs from it, or names
//! none, is foreign. (The campaigns' tally, `crate::campaign::tally`, also keeps
//! each copy's channel and clock to tell CAN's own double reception apart.)

use drcc_cosim::Frame;

/// A frame one receiver should have had once: `(receiver, sender, index)`.
pub type FrameRef = (usize, usize, usize);

/// The copies of every scenario frame one host popped.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Deliveries {
    /// `seen[sender][k]`: copies of sender's frame `k`.
    pub seen: Vec<Vec<usize>>,
    /// Popped frames that are no scenario frame.
    pub foreign: usize,
    /// Popped frames `skip` said are not the scenario's traffic.
    pub skipped: usize,
}

impl Deliveries {
    /// Counts the `received` frames of a scenario of `senders` nodes sending
    /// `per_sender` frames each, `frame(sender, k)` being the frame as received;
    /// frames `skip` names (heartbeats, the hubs' identification frames) are only
    /// counted as skipped.
    pub fn count(
        received: impl IntoIterator<Item = Frame>,
        senders: usize,
        per_sender: usize,
        skip: impl Fn(&Frame) -> bool,
        frame: impl Fn(usize, usize) -> Frame,
    ) -> Self {
        let mut d = Deliveries {
            seen: vec![vec![0; per_sender]; senders],
            foreign: 0,
            skipped: 0,
        };
        for f in received {
            if skip(&f) {
                d.skipped += 1;
                continue;
            }
            let (sender, k) = (f.data[0] as usize, f.data[1] as usize);
            if sender < senders && k < per_sender && f == frame(sender, k) {
                d.seen[sender][k] += 1;
            } else {
                d.foreign += 1;
            }
        }
        d
    }

    /// Copies of the frames of `sender`.
    pub fn of(&self, sender: usize) -> usize {
        self.seen[sender].iter().sum()
    }

    /// Copies of every sender's frames.
    pub fn total(&self) -> usize {
        (0..self.seen.len()).map(|s| self.of(s)).sum()
    }

    /// Judges, for receiver `rx`, every frame of another sender that `sent`
    /// says went out: no copy is `missing`, more than one `duplicates`. Returns
    /// how many frames it judged.
    pub fn judge(
        &self,
        rx: usize,
        sent: impl Fn(usize, usize) -> bool,
        missing: &mut Vec<FrameRef>,
        duplicates: &mut Vec<FrameRef>,
    ) -> usize {
        let mut judged = 0;
        for (sender, counts) in self.seen.iter().enumerate() {
            for (k, &c) in counts.iter().enumerate() {
                if sender == rx || !sent(sender, k) {
                    continue;
                }
                judged += 1;
                match c {
                    0 => missing.push((rx, sender, k)),
                    1 => {}
                    _ => duplicates.push((rx, sender, k)),
                }
            }
        }
        judged
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(sender: usize, k: usize) -> Frame {
        Frame::base(0x100 + sender as u32, &[sender as u8, k as u8, 0xAA])
    }

    #[test]
    fn copies_foreign_and_skipped_frames_are_told_apart() {
        let other = Frame::base(0x100, &[0, 1, 0xBB]); // names frame (0, 1), differs
        let hb = Frame::base(0x700, &[]);
        let got = [
            frame(0, 0),
            frame(0, 0),
            frame(1, 1),
            other,
            hb,
            frame(2, 0),
        ];
        let d = Deliveries::count(got, 2, 2, |f| f.id == 0x700, frame);
        assert_eq!(d.seen, vec![vec![2, 0], vec![0, 1]]);
        assert_eq!((d.foreign, d.skipped), (2, 1), "(0,1) altered and sender 2");
        assert_eq!((d.of(0), d.total()), (2, 3));
        let (mut missing, mut dups) = (Vec::new(), Vec::new());
        // receiver 1: its own frames are not judged; sender 0's frame 1 was not sent
        let judged = d.judge(1, |s, k| !(s == 0 && k == 1), &mut missing, &mut dups);
        assert_eq!(judged, 1);
        assert_eq!((missing, dups), (vec![], vec![(1, 0, 0)]));
        let (mut missing, mut dups) = (Vec::new(), Vec::new());
        assert_eq!(d.judge(0, |_, _| true, &mut missing, &mut dups), 2);
        assert_eq!((missing, dups), (vec![(0, 1, 0)], vec![]));
    }
}
