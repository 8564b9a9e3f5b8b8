//! Lock step of a whole ring run on two engines (the model and the Verilated RTL),
//! clock by clock: the project's rule that a block works when its Verilated
//! Verilog matches the model clock by clock, applied to every DRCC node and every
//! relay module (RCM) of a REDCAN ring running CanKingdom and a REDCAN algorithm.
//!
//! The Verilator engine is not `Send`, so the two runs cannot share a thread pair;
//! they go one after the other, through [`run_observed`]:
//!
//! 1. the left run records, after every clock, a 64-bit [`digest`] of what the
//!    dual-bus lock step (`drcc_cosim::dual::lockstep::compare`) compares, for
//!    every DRCC node: its outputs (pins, Wishbone, every probe) and its inputs;
//!    and of every RCM's outputs;
//! 2. the right run compares its digest with the record after every clock and
//!    stops at the first mismatch, keeping its full [`Snapshot`] of that clock;
//! 3. on a mismatch the left run is made again up to that clock, and the two
//!    snapshots name the first node (or RCM) and signal that differ, with both
//!    values ([`RingDivergence`], worded as the dual-bus lock step words it).
//!
//! As long as the outputs agree the two runs are the same run: the hosts (the
//! CanKingdom and REDCAN software) react only to what the nodes output.
//!
//! Memory: one `u64` per clock. A ring clock is a microsecond, and the longest run
//! the CLI makes, [`RingScenario::standard`] (450 ms + 1.4 s), has 1.85 M clocks:
//! 15 MB of digests, so no coarser (per bit time) record is needed.
//!
//! The digest folds the signals in a fixed order, `h = (rotl(h, 5) ^ v) * K` with
//! an odd `K`: for a given `v` each step is a bijection of `h`, and for a given `h`
//! distinct `v` give distinct results, so two clocks that differ in one signal
//! always have distinct digests; several differing signals collide with a chance
//! of about 2^-64. The signal lists destructure the port structs without `..`: a
//! port added to `DrccInputs`, `DrccOutputs`, `DrccProbes` or `RcmOutputs` does not
//! compile until it is compared.

use super::{run_observed, RingReport, RingScenario};
use crate::engines::EngineKind;
use drcc_cosim::engine::drcc::{DrccInputs, DrccOutputs, DrccProbes};
use drcc_cosim::engine::rcm::RcmOutputs;
use drcc_cosim::ring::RingSystem;
use std::fmt;

/// One signal: its name (the Verilog port's) and value.
pub type Signal = (&'static str, u64);

/// Signals compared per DRCC node.
pub const NODE_SIGNALS: usize = 46;
/// Signals compared per RCM.
pub const RCM_SIGNALS: usize = 8;

/// Every signal of one DRCC node at one clock: the outputs in the order of the
/// dual-bus trace (the paper's Fig. 7 probes, the pins, the Wishbone and channel
/// probes, the DMR probes), then the inputs.
pub fn node_signals(i: &DrccInputs, o: &DrccOutputs) -> [Signal; NODE_SIGNALS] {
    let DrccOutputs {
        wb_ack,
        wb_err,
        wb_dat_r,
        irq,
        chan_a_tx,
        chan_b_tx,
        probes,
    } = *o;
    let DrccProbes {
        state,
        tx_channel,
        transmission_ack,
        chan_a_transmission_req,
        chan_b_transmission_req,
        tx_success,
        tx_ok_channel,
        tx_failure,
        tx_failure_channel,
        tx_going_on,
        chan_a_bsp_tx_err_cnt,
        chan_a_bsp_node_error_passive,
        chan_b_bsp_tx_err_cnt,
        chan_b_bsp_node_error_passive,
        aux_a_state,
        aux_b_state,
        chan_a_sample_point,
        chan_b_sample_point,
        chan_a_field,
        chan_b_field,
        chan_a_rec,
        chan_b_rec,
        chan_a_err_state,
        chan_b_err_state,
        dmr_state,
        acl,
        dcl_tx_fault,
        dcl_rx_fault,
        rcl_tx_fault,
        rcl_rx_fault,
        dmr_tick,
    } = probes;
    let DrccInputs {
        rst,
        wb_cyc,
        wb_stb,
        wb_we,
        wb_adr,
        wb_dat_w,
        wb_sel,
        chan_a_rx,
        chan_b_rx,
    } = *i;
    [
        ("chan_a_bsp_tx_err_cnt", chan_a_bsp_tx_err_cnt as u64),
        (
            "chan_a_bsp_node_error_passive",
            chan_a_bsp_node_error_passive as u64,
        ),
        ("chan_b_bsp_tx_err_cnt", chan_b_bsp_tx_err_cnt as u64),
        (
            "chan_b_bsp_node_error_passive",
            chan_b_bsp_node_error_passive as u64,
        ),
        ("tx_channel", tx_channel as u64),
        ("transmission_ack", transmission_ack as u64),
        ("chan_a_transmission_req", chan_a_transmission_req as u64),
        ("chan_b_transmission_req", chan_b_transmission_req as u64),
        ("tx_success", tx_success as u64),
        ("tx_ok_channel", tx_ok_channel as u64),
        ("tx_failure", tx_failure as u64),
        ("tx_failure_channel", tx_failure_channel as u64),
        ("tx_going_on", tx_going_on as u64),
        ("state", state as u64),
        ("aux_a_state", aux_a_state as u64),
        ("aux_b_state", aux_b_state as u64),
        ("chan_a_tx", chan_a_tx as u64),
        ("chan_b_tx", chan_b_tx as u64),
        ("irq", irq as u64),
        ("wb_ack_o", wb_ack as u64),
        ("wb_err_o", wb_err as u64),
        ("wb_dat_o", wb_dat_r as u64),
        ("chan_a_sample_point", chan_a_sample_point as u64),
        ("chan_b_sample_point", chan_b_sample_point as u64),
        ("chan_a_field", chan_a_field as u64),
        ("chan_b_field", chan_b_field as u64),
        ("chan_a_rec", chan_a_rec as u64),
        ("chan_b_rec", chan_b_rec as u64),
        ("chan_a_err_state", chan_a_err_state as u64),
        ("chan_b_err_state", chan_b_err_state as u64),
        ("dmr_state", dmr_state as u64),
        ("acl", acl as u64),
        ("dcl_tx_fault", dcl_tx_fault as u64),
        ("dcl_rx_fault", dcl_rx_fault as u64),
        ("rcl_tx_fault", rcl_tx_fault as u64),
        ("rcl_rx_fault", rcl_rx_fault as u64),
        ("dmr_tick", dmr_tick as u64),
        ("rst", rst as u64),
        ("wb_cyc_i", wb_cyc as u64),
        ("wb_stb_i", wb_stb as u64),
        ("wb_we_i", wb_we as u64),
        ("wb_adr_i", wb_adr as u64),
        ("wb_dat_i", wb_dat_w as u64),
        ("wb_sel_i", wb_sel as u64),
        ("chan_a_rx", chan_a_rx as u64),
        ("chan_b_rx", chan_b_rx as u64),
    ]
}

/// Every output of one RCM at one clock (its inputs are the host's command, which
/// the DRCC node's Wishbone signals already carry).
pub fn rcm_signals(o: &RcmOutputs) -> [Signal; RCM_SIGNALS] {
    let RcmOutputs {
        relay,
        node_left,
        node_right,
        term_left,
        term_right,
        mode,
        illegal,
        changes,
    } = *o;
    [
        ("relay", relay as u64),
        ("node_left", node_left as u64),
        ("node_right", node_right as u64),
        ("term_left", term_left as u64),
        ("term_right", term_right as u64),
        ("mode", mode as u64),
        ("illegal", illegal as u64),
        ("changes", changes as u64),
    ]
}

/// Folds `signals` into the digest `h` (see the module docs).
pub fn fold(h: u64, signals: &[Signal]) -> u64 {
    const K: u64 = 0x517c_c1b7_2722_0a95;
    signals
        .iter()
        .fold(h, |h, &(_, v)| (h.rotate_left(5) ^ v).wrapping_mul(K))
}

/// The digest of the clock `sys` just made: every node's signals in node order,
/// then every RCM's in ring node order.
pub fn digest(sys: &RingSystem) -> u64 {
    let h = sys
        .nodes()
        .iter()
        .fold(0, |h, n| fold(h, &node_signals(&n.inputs, &n.outputs)));
    sys.modules()
        .iter()
        .fold(h, |h, m| fold(h, &rcm_signals(&m.outputs)))
}

/// Where a signal is: a DRCC node, or ring node `i`'s relay module.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// DRCC node `i` (ring nodes `0..N`, then the plain nodes).
    Node(usize),
    /// Ring node `i`'s RCM.
    Rcm(usize),
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Unit::Node(i) => write!(f, "node{i}"),
            Unit::Rcm(i) => write!(f, "rcm{i}"),
        }
    }
}

/// Everything the lock step compares at one clock, in full.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Snapshot {
    /// The clock (from 0).
    pub cycle: u64,
    /// Every DRCC node's inputs and outputs.
    pub nodes: Vec<(DrccInputs, DrccOutputs)>,
    /// Every RCM's outputs.
    pub modules: Vec<RcmOutputs>,
}

impl Snapshot {
    /// The clock `sys` just made.
    pub fn of(sys: &RingSystem) -> Self {
        Snapshot {
            cycle: sys.cycle().saturating_sub(1),
            nodes: sys.nodes().iter().map(|n| (n.inputs, n.outputs)).collect(),
            modules: sys.modules().iter().map(|m| m.outputs).collect(),
        }
    }

    /// Its digest: [`digest`] of the system it was taken of.
    pub fn digest(&self) -> u64 {
        let h = (self.nodes.iter()).fold(0, |h, (i, o)| fold(h, &node_signals(i, o)));
        (self.modules.iter()).fold(h, |h, m| fold(h, &rcm_signals(m)))
    }

    /// Every signal, with its unit, in digest order.
    pub fn signals(&self) -> Vec<(Unit, Signal)> {
        let nodes = self.nodes.iter().enumerate().flat_map(|(k, (i, o))| {
            node_signals(i, o)
                .into_iter()
                .map(move |s| (Unit::Node(k), s))
        });
        let rcms = (self.modules.iter().enumerate())
            .flat_map(|(k, m)| rcm_signals(m).into_iter().map(move |s| (Unit::Rcm(k), s)));
        nodes.chain(rcms).collect()
    }

    /// The first signal (in digest order) whose value differs in `other`: its
    /// unit, name, and the values here and there.
    pub fn first_difference(&self, other: &Snapshot) -> Option<(Unit, &'static str, u64, u64)> {
        let (a, b) = (self.signals(), other.signals());
        if a.len() != b.len() {
            return Some((Unit::Node(0), "ring size", a.len() as u64, b.len() as u64));
        }
        a.into_iter()
            .zip(b)
            .find(|((_, (_, x)), (_, (_, y)))| x != y)
            .map(|((u, (name, x)), (_, (_, y)))| (u, name, x, y))
    }
}

/// The first clock at which two ring runs differ.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RingDivergence {
    /// The clock (from 0; one clock per microsecond).
    pub cycle: u64,
    /// The first unit, in digest order, with a differing signal.
    pub unit: Unit,
    /// The signal's name.
    pub signal: &'static str,
    /// Its value in the left run.
    pub left: u64,
    /// Its value in the right run.
    pub right: u64,
    /// The left run's engine.
    pub left_engine: &'static str,
    /// The right run's engine.
    pub right_engine: &'static str,
}

impl fmt::Display for RingDivergence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "divergence at cycle {} on {}: `{}` is {:#x} in {} but {:#x} in {}",
            self.cycle,
            self.unit,
            self.signal,
            self.left,
            self.left_engine,
            self.right,
            self.right_engine
        )
    }
}

/// The digests of a recorded run, checked clock by clock against another's.
#[derive(Clone, Debug)]
pub struct DigestCheck<'a> {
    record: &'a [u64],
    next: usize,
}

impl<'a> DigestCheck<'a> {
    /// A check against `record` (one digest per clock, from clock 0).
    pub fn new(record: &'a [u64]) -> Self {
        DigestCheck { record, next: 0 }
    }

    /// Takes the next clock's digest: `Err(clock)` when it differs from the
    /// record's, or when the record has no such clock.
    pub fn check(&mut self, digest: u64) -> Result<(), u64> {
        let clock = self.next;
        self.next += 1;
        match self.record.get(clock) {
            Some(&d) if d == digest => Ok(()),
            _ => Err(clock as u64),
        }
    }

    /// Clocks checked so far.
    pub fn clocks(&self) -> u64 {
        self.next as u64
    }
}

/// The first clock at which `digests` differ from `record` (a shorter sequence
/// than the record is no mismatch: see [`DigestCheck::clocks`]).
pub fn first_mismatch(record: &[u64], digests: impl IntoIterator<Item = u64>) -> Option<u64> {
    let mut c = DigestCheck::new(record);
    digests.into_iter().find_map(|d| c.check(d).err())
}

/// What a lock-step run showed.
#[derive(Clone, Debug)]
pub struct RingLockstep {
    /// The left (recording) run's report.
    pub report: RingReport,
    /// Clocks compared: the whole run, or up to and with the divergence.
    pub clocks: u64,
    /// The first clock at which the runs differ, if any.
    pub divergence: Option<RingDivergence>,
}

/// What the right run's observer returns to stop the run at a mismatch.
const STOP: &str = "lock step: stopped at the first mismatch";

/// Runs `s` on engine `left`, then on engine `right`, comparing every clock (see
/// the module docs); `observe_left` sees every clock of the left run (e.g. a
/// traffic tap) and may end it with an error.
pub fn run_lockstep(
    s: &RingScenario,
    left: EngineKind,
    right: EngineKind,
    observe_left: impl FnMut(&RingSystem) -> Result<(), String>,
) -> Result<RingLockstep, String> {
    compare_runs((s, left), (s, right), observe_left)
}

/// [`run_lockstep`] of two runs that may differ in their scenario as well (of the
/// same length: `onset_us + after_us`), e.g. to show that the lock step sees a
/// difference.
pub fn compare_runs(
    (ls, lk): (&RingScenario, EngineKind),
    (rs, rk): (&RingScenario, EngineKind),
    mut observe_left: impl FnMut(&RingSystem) -> Result<(), String>,
) -> Result<RingLockstep, String> {
    let (ll, rl) = (ls.onset_us + ls.after_us, rs.onset_us + rs.after_us);
    if ll != rl {
        return Err(format!(
            "lock step of runs of {ll} and {rl} clocks: the runs must be as long"
        ));
    }
    let mut record: Vec<u64> = Vec::with_capacity(ll as usize + 1);
    let report = run_observed(ls, lk, |sys| {
        record.push(digest(sys));
        observe_left(sys)
    })?;
    let mut check = DigestCheck::new(&record);
    let mut at: Option<Snapshot> = None;
    let right_run = run_observed(rs, rk, |sys| match check.check(digest(sys)) {
        Ok(()) => Ok(()),
        Err(_) => {
            at = Some(Snapshot::of(sys));
            Err(STOP.to_string())
        }
    });
    let clocks = check.clocks();
    let Some(there) = at else {
        right_run?;
        if clocks != record.len() as u64 {
            return Err(format!(
                "lock step: the {} run made {} clocks, the {} run {clocks}",
                lk.name(),
                record.len(),
                rk.name()
            ));
        }
        return Ok(RingLockstep {
            report,
            clocks,
            divergence: None,
        });
    };
    // The left run again, up to the clock of the mismatch.
    let cycle = there.cycle;
    let mut here: Option<Snapshot> = None;
    let rerun = run_observed(ls, lk, |sys| {
        if sys.cycle().saturating_sub(1) < cycle {
            return Ok(());
        }
        here = Some(Snapshot::of(sys));
        Err(STOP.to_string())
    });
    let Some(here) = here else {
        rerun?;
        return Err(format!(
            "lock step: the {} run made fewer clocks than {cycle} when run again",
            lk.name()
        ));
    };
    let Some((unit, signal, l, r)) = here.first_difference(&there) else {
        return Err(format!(
            "lock step: the digests differ at cycle {cycle}, but the {} run made again \
             matches the {} run there: the {} run is not repeatable",
            lk.name(),
            rk.name(),
            lk.name()
        ));
    };
    Ok(RingLockstep {
        report,
        clocks,
        divergence: Some(RingDivergence {
            cycle,
            unit,
            signal,
            left: l,
            right: r,
            left_engine: lk.name(),
            right_engine: rk.name(),
        }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two digest sequences that differ at a known clock: the check names it, and
    /// only it; a sequence longer than the record differs at the record's end.
    #[test]
    fn the_check_names_the_first_differing_clock() {
        let record: Vec<u64> = (0..1_000u64).map(|k| k.wrapping_mul(0x9E37)).collect();
        assert_eq!(first_mismatch(&record, record.iter().copied()), None);
        for at in [0, 1, 417, 999] {
            let mut other = record.clone();
            other[at] ^= 1 << 40;
            other[(at + 3).min(999)] ^= 1;
            assert_eq!(first_mismatch(&record, other), Some(at as u64));
        }
        let longer = record.iter().copied().chain([7]);
        assert_eq!(first_mismatch(&record, longer), Some(1_000));
    }

    /// Any one signal of any node or RCM changed by any amount changes the digest,
    /// and the snapshot comparison names that unit and signal with both values.
    #[test]
    fn one_changed_signal_changes_the_digest_and_is_named() {
        let base = Snapshot {
            cycle: 5,
            nodes: vec![(DrccInputs::default(), DrccOutputs::default()); 3],
            modules: vec![RcmOutputs::default(); 2],
        };
        let signals = base.signals();
        assert_eq!(signals.len(), 3 * NODE_SIGNALS + 2 * RCM_SIGNALS);
        // A signal changed in place: the fold over the changed list.
        let digest_with = |k: usize, v: u64| {
            let mut s: Vec<Signal> = signals.iter().map(|&(_, s)| s).collect();
            s[k].1 = v;
            fold(0, &s)
        };
        assert_eq!(
            digest_with(0, 0),
            base.digest(),
            "same fold as the snapshot"
        );
        for k in 0..signals.len() {
            for v in [1, 2, 0x8000_0000, u64::MAX] {
                assert_ne!(digest_with(k, v), base.digest(), "signal {k} = {v:#x}");
            }
        }
        // Real fields: the first and last of a node, a middle probe, an RCM's.
        let mut other = base.clone();
        other.nodes[1].1.probes.chan_b_rec = 0x7F;
        other.nodes[2].0.chan_b_rx = true;
        assert_ne!(other.digest(), base.digest());
        assert_eq!(
            base.first_difference(&other),
            Some((Unit::Node(1), "chan_b_rec", 0, 0x7F))
        );
        let mut other = base.clone();
        other.modules[1].changes = 3;
        assert_ne!(other.digest(), base.digest());
        assert_eq!(
            base.first_difference(&other),
            Some((Unit::Rcm(1), "changes", 0, 3))
        );
        assert_eq!(base.first_difference(&base.clone()), None);
        let names: std::collections::HashSet<&str> = signals
            .iter()
            .take(NODE_SIGNALS)
            .map(|(_, (n, _))| *n)
            .collect();
        assert_eq!(
            names.len(),
            NODE_SIGNALS,
            "every node signal has its own name"
        );
    }
}
