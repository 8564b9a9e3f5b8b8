//! The ISO 11898-1 checks of one episode: liveness, integrity, and behaviour
//! once every node has been idle together after the faults.

use super::*;

pub(super) type Key = (u32, bool);

pub(super) fn key(f: &Frame) -> Key {
    let f = f.normalized();
    (f.id, f.ide)
}

/// Every check of a finished episode; adds the liveness timings to `tot`.
pub(super) fn check(
    sc: &Scenario,
    fp: &FaultPlan,
    sys: &System,
    logs: &[NodeLog],
    tot: &mut Totals,
    problems: &mut Vec<String>,
) {
    let t = Times {
        cpb: sc.clocks_per_bit(),
        ff: fp.end,
    };
    check_integrity(sc, sys, &t, problems);
    let bound = check_settling(logs, &t, problems);
    let settled = logs.iter().filter_map(|l| l.settled).max().unwrap_or(t.ff);

    // All nodes idle together: from here on the nodes agree on the bus.
    let quiet = all_idle_from(logs, t.ff);
    let Some(quiet) = quiet else {
        problems.push(format!(
            "LIVENESS: the nodes were never all idle at once after the faults stopped (bit {})",
            t.bit(t.ff)
        ));
        return;
    };
    if quiet > bound + 4 * MAX_FRAME_BITS * t.cpb {
        problems.push(format!(
            "LIVENESS: all nodes idle together only {} bit times after the faults stopped",
            t.bit(quiet - t.ff)
        ));
    }
    check_quiet_nodes(logs, quiet, &t, problems);
    let late = check_fault_free_deliveries(sc, sys, quiet, &t, problems);
    check_recoveries(fp, logs, problems);
    tot.settle_bits = tot.settle_bits.max(t.bit(settled.saturating_sub(t.ff)));
    tot.quiet_bits = tot.quiet_bits.max(t.bit(quiet - t.ff));
    tot.synchronised_frames += late;
}

/// An episode's clock: clocks per bit and the cycle the faults stopped at.
struct Times {
    cpb: u64,
    ff: u64,
}

impl Times {
    fn bit(&self, c: u64) -> u64 {
        c / self.cpb
    }

    fn phase(&self, c: u64) -> &'static str {
        if c < self.ff {
            "during faults"
        } else {
            "fault free"
        }
    }
}

fn check_integrity(sc: &Scenario, sys: &System, t: &Times, problems: &mut Vec<String>) {
    let (bit, phase) = (|c| t.bit(c), |c| t.phase(c));
    // Integrity: deliveries are submitted frames of other nodes; every frame is
    // sent exactly once.
    let submitted: HashMap<Key, (usize, Frame)> = sc
        .frames
        .iter()
        .map(|f| (key(&f.frame), (f.node, f.frame.normalized())))
        .collect();
    for d in sys.deliveries() {
        match submitted.get(&key(&d.frame)) {
            Some((from, f)) if *f == d.frame.normalized() && *from != d.node => {}
            Some((from, _)) if *from == d.node => problems.push(format!(
                "node{} delivered its own frame {} at cycle {} (bit {}, {})",
                d.node,
                d.frame,
                d.cycle,
                bit(d.cycle),
                phase(d.cycle)
            )),
            _ => problems.push(format!(
                "CORRUPTED FRAME ACCEPTED: node{} delivered {} at cycle {} (bit {}, {}), \
                 which no node submitted",
                d.node,
                d.frame,
                d.cycle,
                bit(d.cycle),
                phase(d.cycle)
            )),
        }
    }
    let mut sent: HashMap<Key, usize> = HashMap::new();
    for e in sys.tx_done() {
        match submitted.get(&key(&e.frame)) {
            Some((from, f)) if *f == e.frame.normalized() && *from == e.node => {
                *sent.entry(key(&e.frame)).or_default() += 1;
            }
            _ => problems.push(format!(
                "node{} reported tx_done for {} at cycle {}, which it did not submit",
                e.node, e.frame, e.cycle
            )),
        }
    }
    for f in &sc.frames {
        let n = sent.get(&key(&f.frame)).copied().unwrap_or(0);
        if n != 1 {
            problems.push(format!(
                "frame {} of node{} (due at bit {}) was sent {n} times",
                f.frame,
                f.node,
                bit(f.at_cycle)
            ));
        }
    }
}

/// Every node idle within [`SETTLE_BOUND_BITS`] of the faults' end; returns that
/// bound (a cycle).
fn check_settling(logs: &[NodeLog], t: &Times, problems: &mut Vec<String>) -> u64 {
    let (cpb, ff, bit) = (t.cpb, t.ff, |c| t.bit(c));
    // Liveness: every node idle within the bound after the faults stopped.
    let bound = ff + SETTLE_BOUND_BITS * cpb;
    for (n, l) in logs.iter().enumerate() {
        match l.settled {
            Some(c) if c <= bound => {}
            Some(c) => problems.push(format!(
                "LIVENESS: node{n} first idle {} bit times after the faults stopped (bound {})",
                bit(c - ff),
                SETTLE_BOUND_BITS
            )),
            None => problems.push(format!(
                "LIVENESS: node{n} never idle after the faults stopped (at bit {})",
                bit(ff)
            )),
        }
    }
    bound
}

/// Once all nodes were idle together on a fault-free bus: no error or overload
/// frame, no bus-off, no counter rising, and every node idle after 11 recessive
/// bits.
fn check_quiet_nodes(logs: &[NodeLog], quiet: u64, t: &Times, problems: &mut Vec<String>) {
    let bit = |c| t.bit(c);
    for (n, l) in logs.iter().enumerate() {
        let mut prev: Option<Mark> = None;
        for m in l.trail.iter().filter(|m| m.cycle > quiet) {
            if matches!(
                m.field,
                field::ERROR_FLAG
                    | field::ERROR_DELIM
                    | field::OVERLOAD_FLAG
                    | field::OVERLOAD_DELIM
                    | field::BUS_OFF
                    | field::INTEGRATING
            ) {
                problems.push(format!(
                    "node{n} in {} at cycle {} (bit {}), after all nodes were idle together at \
                     bit {} on a fault-free bus",
                    field::name(m.field),
                    m.cycle,
                    bit(m.cycle),
                    bit(quiet)
                ));
                break;
            }
            if let Some(p) = prev {
                if m.tec > p.tec || m.rec > p.rec || m.err_state > p.err_state {
                    problems.push(format!(
                        "node{n}: counters rose at cycle {} (bit {}) on a fault-free, \
                         synchronised bus: tec {} -> {}, rec {} -> {}, err_state {} -> {}",
                        m.cycle,
                        bit(m.cycle),
                        p.tec,
                        m.tec,
                        p.rec,
                        m.rec,
                        p.err_state,
                        m.err_state
                    ));
                    break;
                }
            }
            prev = Some(*m);
        }
        if let Some(&(c, f)) = l.not_idle.iter().find(|(c, _)| *c > quiet) {
            problems.push(format!(
                "node{n} not idle after 11 recessive bits: field {} ({}) at cycle {} (bit {})",
                f,
                field::name(f),
                c,
                bit(c)
            ));
        }
    }
}

/// Every frame sent once the nodes agree reaches every other node, once;
/// returns how many frames were sent then.
fn check_fault_free_deliveries(
    sc: &Scenario,
    sys: &System,
    quiet: u64,
    t: &Times,
    problems: &mut Vec<String>,
) -> usize {
    let (cpb, bit) = (t.cpb, |c| t.bit(c));
    let mut got: HashMap<(usize, Key), Vec<u64>> = HashMap::new();
    for d in sys.deliveries() {
        got.entry((d.node, key(&d.frame)))
            .or_default()
            .push(d.cycle);
    }
    let late: Vec<&NodeEvent> = sys.tx_done().iter().filter(|e| e.cycle > quiet).collect();
    for e in &late {
        for r in (0..sc.nodes.len()).filter(|&r| r != e.node) {
            let n = got.get(&(r, key(&e.frame))).map_or(0, |v| {
                v.iter()
                    .filter(|&&c| c + 2 * cpb >= e.cycle && c <= e.cycle)
                    .count()
            });
            if n != 1 {
                problems.push(format!(
                    "frame {} sent by node{} at bit {} (fault free) was delivered {n} times to node{r}",
                    e.frame,
                    e.node,
                    bit(e.cycle)
                ));
            }
        }
    }
    let late_deliveries = sys.deliveries().iter().filter(|d| d.cycle > quiet).count();
    if late_deliveries != late.len() * (sc.nodes.len() - 1) {
        problems.push(format!(
            "{late_deliveries} deliveries after all nodes were idle together, for {} frames sent",
            late.len()
        ));
    }
    late.len()
}

/// Every bus-off ended in a recovery, and the faults reached every node's
/// counters.
fn check_recoveries(fp: &FaultPlan, logs: &[NodeLog], problems: &mut Vec<String>) {
    let (offs, recovered): (usize, usize) = logs
        .iter()
        .fold((0, 0), |(o, r), l| (o + l.bus_off, r + l.recovered));
    if recovered != offs {
        problems.push(format!(
            "{offs} bus-off entries but {recovered} recoveries by the end of the run"
        ));
    }
    for (n, l) in logs.iter().enumerate() {
        if l.max_tec == 0 && l.max_rec == 0 && !fp.faults.is_empty() {
            problems.push(format!(
                "FAULTS INEFFECTIVE: node{n}'s counters never left 0"
            ));
        }
    }
}

/// The first cycle at or after `from` at which every node is idle (and not
/// bus-off), from the nodes' trails.
pub(super) fn all_idle_from(logs: &[NodeLog], from: u64) -> Option<u64> {
    let mut idx = vec![0usize; logs.len()];
    let mut cur: Vec<Option<Mark>> = vec![None; logs.len()];
    loop {
        // The next cycle at which some node changes.
        let next = logs
            .iter()
            .zip(&idx)
            .filter_map(|(l, &i)| l.trail.get(i).map(|m| m.cycle))
            .min()?;
        for (n, l) in logs.iter().enumerate() {
            while let Some(m) = l.trail.get(idx[n]).filter(|m| m.cycle == next) {
                cur[n] = Some(*m);
                idx[n] += 1;
            }
        }
        if next >= from
            && cur
                .iter()
                .all(|m| m.is_some_and(|m| m.field == field::IDLE && m.err_state != 2))
        {
            return Some(next);
        }
    }
}
