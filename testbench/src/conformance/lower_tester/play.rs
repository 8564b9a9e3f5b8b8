//! Playing a [`Script`] against the IUT bit by bit and checking its `tx`, probes
//! and counters: the first deviation panics with a table of the bits around it.

use super::*;

impl LowerTester {
    /// Plays `script`; panics with a bit table at the first bit where the IUT's
    /// `tx` differs from the expectation or the IUT lost the bit synchronisation.
    pub fn run(&mut self, script: &Script) -> Run {
        let mut recs: Vec<BitRecord> = Vec::with_capacity(script.bits.len());
        // Per bit: (the grid exists, this bit starts a new grid).
        let mut grid: Vec<(bool, bool)> = Vec::with_capacity(script.bits.len());
        let mut failure: Option<(usize, String)> = None;
        for (i, sb) in script.bits.iter().enumerate() {
            if let Some(f) = sb.request {
                self.request(f);
            }
            let synced_before = self.synced;
            let waited = sb.await_sof.map(|w| self.await_sof(w));
            let mut rec = match &sb.shape {
                Some(segs) => self.shaped_bit(segs, &sb.label),
                None => self.bit(sb.drive, &sb.label),
            };
            rec.waited = waited;
            grid.push((
                self.synced,
                waited.is_some() || (!synced_before && self.synced),
            ));
            recs.push(rec);
            // The previous bit is complete now.
            if i > 0 {
                let mut prev = recs[i - 1].clone();
                self.fill(&mut prev);
                recs[i - 1] = prev;
                self.check_bit(script, &recs, grid[i - 1], i - 1, &mut failure);
            }
            if failure.as_ref().is_some_and(|f| recs.len() > f.0 + 8) {
                break;
            }
        }
        if failure.is_none() && !recs.is_empty() {
            let i = recs.len() - 1;
            self.check_bit(script, &recs, grid[i], i, &mut failure);
        }
        if let Some((i, why)) = failure {
            panic!(
                "{}: {}bit {i} ({}): {why}\n{}",
                self.iut.name(),
                self.ctx(),
                script.bits[i].label,
                table(script, &recs, i)
            );
        }
        Run { recs }
    }

    fn check_bit(
        &mut self,
        script: &Script,
        recs: &[BitRecord],
        (synced, new_grid): (bool, bool),
        i: usize,
        failure: &mut Option<(usize, String)>,
    ) {
        if failure.is_some() {
            return;
        }
        if new_grid {
            self.sample_offset = None;
        }
        let (sb, rec) = (&script.bits[i], &recs[i]);
        if synced && sb.shape.is_none() {
            match (rec.sample_offset, self.sample_offset) {
                (None, _) => {
                    *failure = Some((i, "no sample point in this bit".into()));
                    return;
                }
                (Some(o), None) => self.sample_offset = Some(o),
                (Some(o), Some(e)) if o != e => {
                    *failure = Some((
                        i,
                        format!(
                            "the IUT sampled clock {o} of the bit instead of {e}: \
                             it lost the bit synchronisation"
                        ),
                    ));
                    return;
                }
                _ => {}
            }
        }
        if let Some(e) = sb.expect {
            if rec.tx != e {
                *failure = Some((
                    i,
                    format!(
                        "IUT tx {} where {} was expected",
                        val(rec.tx),
                        if e { "recessive" } else { "dominant" }
                    ),
                ));
            }
        }
    }

    /// Asserts (TEC, REC, error state) now.
    #[track_caller]
    pub fn assert_counters(&self, tec: u16, rec: u8, err_state: u8, what: &str) {
        let p = self.last.probes;
        assert_eq!(
            (p.tec, p.rec, p.err_state),
            (tec, rec, err_state),
            "{}: {}{what}: (TEC, REC, state) expected ({tec}, {rec}, {err_state}), got ({}, {}, {})",
            self.iut.name(),
            self.ctx(),
            p.tec,
            p.rec,
            p.err_state
        );
    }

    /// Asserts the `field` probe now.
    #[track_caller]
    pub fn assert_field(&self, code: u8, what: &str) {
        assert_eq!(
            self.last.probes.field,
            code,
            "{}: {}{what}: field {} expected, got {}",
            self.iut.name(),
            self.ctx(),
            field::name(code),
            field::name(self.last.probes.field)
        );
    }
}
