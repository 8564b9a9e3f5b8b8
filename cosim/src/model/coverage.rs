//! Functional coverage of the reference model: named bins,
//! counted where the rule they witness is applied, as CTU CAN FD puts PSL cover
//! points beside its rules.
//!
//! A cover point is a call of [`hit`] with the bin's name at the line that applies
//! the rule ("rule c: TEC + 8", "main: ch1 -> abort1", "error: rx stuff in DLC").
//! Counting is off unless a collection runs ([`start`] .. [`stop`]), so campaigns
//! and benchmarks pay one relaxed atomic load per cover point.
//!
//! [`bins`] is the list of bins the product must reach, written from the standard,
//! the papers and the contracts (not from what a run hits); [`unreachable`] lists
//! the combinations that cannot occur, with the reason. A name counted that is in
//! neither list is *unlisted*: an illegal transition or a cover point without a
//! definition; `drcc coverage` reports it and the coverage test fails on it.

use std::cell::OnceCell;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};

/// The counts of one thread. Each thread counts into its own map (a lock nobody
/// else takes while it runs), registered once in [`THREADS`] so that [`stop`]
/// sums the counts of every thread, finished or not.
type Counts = Arc<Mutex<BTreeMap<String, u64>>>;

static ON: AtomicBool = AtomicBool::new(false);
static THREADS: Mutex<Vec<Counts>> = Mutex::new(Vec::new());

thread_local! {
    static MINE: OnceCell<Counts> = const { OnceCell::new() };
}

/// Coverage is being collected.
#[inline]
pub fn enabled() -> bool {
    ON.load(Ordering::Relaxed)
}

/// Counts one hit of bin `name` (when a collection runs).
#[inline]
pub fn hit(name: &str) {
    if enabled() {
        add(name);
    }
}

/// Counts one hit of the bin named by `name()` (built only when collecting).
#[inline]
pub fn hit_with(name: impl FnOnce() -> String) {
    if enabled() {
        add(&name());
    }
}

fn add(name: &str) {
    MINE.with(|cell| {
        let counts = cell.get_or_init(|| {
            let c = Counts::default();
            lock(&THREADS).push(c.clone());
            c
        });
        let mut c = lock(counts);
        match c.get_mut(name) {
            Some(n) => *n += 1,
            None => {
                c.insert(name.to_string(), 1);
            }
        }
    });
}

/// A lock that a panicking test thread may have poisoned: the counts stay valid.
fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// Starts a collection with every count at 0.
pub fn start() {
    for c in lock(&THREADS).iter() {
        lock(c).clear();
    }
    ON.store(true, Ordering::Relaxed);
}

/// Ends the collection and returns the counts by bin name, summed over threads.
pub fn stop() -> BTreeMap<String, u64> {
    ON.store(false, Ordering::Relaxed);
    let mut sum = BTreeMap::new();
    for c in lock(&THREADS).iter() {
        for (name, n) in std::mem::take(&mut *lock(c)) {
            *sum.entry(name).or_default() += n;
        }
    }
    sum
}

mod bins;
pub use bins::*;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bin_names_are_unique() {
        let b = bins();
        let set: std::collections::BTreeSet<_> = b.iter().map(|x| &x.name).collect();
        assert_eq!(set.len(), b.len());
    }

    #[test]
    fn counting_is_off_outside_a_collection() {
        // (the only test of this binary that touches the collector)
        // names no cover point of the model uses (other tests run in parallel)
        hit("test: a");
        start();
        hit("test: a");
        hit_with(|| "test: b".into());
        let c = stop();
        assert_eq!(c.get("test: a"), Some(&1));
        assert_eq!(c.get("test: b"), Some(&1));
        hit("test: a");
        start();
        assert_eq!(stop().get("test: a"), None);
        // counts of threads that ended before the collection stopped are summed
        start();
        hit("test: c");
        std::thread::scope(|s| {
            for _ in 0..3 {
                s.spawn(|| {
                    hit("test: c");
                    hit("test: c");
                });
            }
        });
        assert_eq!(stop().get("test: c"), Some(&7));
    }
}
