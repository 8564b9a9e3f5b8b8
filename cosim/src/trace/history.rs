//! A ring buffer of the last samples of a system, so a trace around an event (a
//! co-simulation divergence) can be written after the fact without tracing the
//! whole run. Pushing reuses the memory of the sample it drops.

use std::collections::VecDeque;

use crate::system::Sample;

/// The last `capacity` samples.
#[derive(Clone, Debug)]
pub struct History {
    capacity: usize,
    buf: VecDeque<Sample>,
}

impl History {
    /// An empty history keeping at most `capacity` samples (at least 1).
    pub fn new(capacity: usize) -> Self {
        let capacity = capacity.max(1);
        History {
            capacity,
            buf: VecDeque::with_capacity(capacity),
        }
    }

    /// Appends a copy of `s`, dropping the oldest sample when full.
    pub fn push(&mut self, s: &Sample) {
        if self.buf.len() == self.capacity {
            if let Some(mut old) = self.buf.pop_front() {
                old.clone_from(s);
                self.buf.push_back(old);
                return;
            }
        }
        self.buf.push_back(s.clone());
    }

    /// The samples, oldest first.
    pub fn iter(&self) -> impl Iterator<Item = &Sample> {
        self.buf.iter()
    }

    /// Number of samples held.
    pub fn len(&self) -> usize {
        self.buf.len()
    }

    /// Whether no sample is held.
    pub fn is_empty(&self) -> bool {
        self.buf.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_the_last_samples() {
        let mut h = History::new(3);
        for c in 0..10 {
            h.push(&Sample {
                cycle: c,
                ..Default::default()
            });
        }
        let cycles: Vec<u64> = h.iter().map(|s| s.cycle).collect();
        assert_eq!(cycles, vec![7, 8, 9]);
        assert_eq!(h.len(), 3);
    }
}
