//! The CAN bus as a wired-AND line of N nodes (`true` = recessive), with fault
//! injection.
//!
//! Every node drives its `tx`; the line is dominant (`false`) as soon as one node
//! drives dominant. Faults override values for a window of clock cycles:
//!
//! - on the line itself ([`FaultTarget::Bus`]): every receiver sees the fault,
//! - on one node's transmitter ([`FaultTarget::Tx`]): that node's contribution to
//!   the AND is replaced (e.g. a transceiver stuck dominant),
//! - on one node's receiver ([`FaultTarget::Rx`]): only that node sees the fault
//!   (e.g. a broken receive path).
//!
//! A fault is stuck dominant, stuck recessive, or a bit flip (the value is
//! inverted) during `cycles` clocks starting at clock `start`. A flip of one
//! clock models a glitch; a flip of one bit time models a flipped bit.
//!
//! The cycle index is the one of the step whose `rx` inputs are being computed
//! (see the timing contract, section 1: rx of cycle n = AND of tx from step n-1).

/// Where a fault acts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaultTarget {
    /// The line: every node's receiver sees the faulty value.
    Bus,
    /// The transmitter of one node (its contribution to the wired AND).
    Tx(usize),
    /// The receiver of one node (only this node sees the faulty value).
    Rx(usize),
}

/// What a fault does to the value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaultKind {
    /// Forced to dominant (`false`).
    StuckDominant,
    /// Forced to recessive (`true`).
    StuckRecessive,
    /// Inverted.
    Flip,
}

impl FaultKind {
    /// The faulty value of `v`.
    pub fn apply(self, v: bool) -> bool {
        match self {
            FaultKind::StuckDominant => false,
            FaultKind::StuckRecessive => true,
            FaultKind::Flip => !v,
        }
    }

    /// Name as the scenario format spells it.
    pub fn name(self) -> &'static str {
        match self {
            FaultKind::StuckDominant => "stuck_dominant",
            FaultKind::StuckRecessive => "stuck_recessive",
            FaultKind::Flip => "flip",
        }
    }
}

/// One injected fault: `kind` on `target` during clocks `start .. start + cycles`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fault {
    /// Where the fault acts.
    pub target: FaultTarget,
    /// What it does.
    pub kind: FaultKind,
    /// First affected clock cycle.
    pub start: u64,
    /// Number of affected clock cycles (at least 1).
    pub cycles: u64,
}

impl Fault {
    /// Whether the fault is active in clock cycle `cycle`.
    pub fn active(&self, cycle: u64) -> bool {
        cycle >= self.start && cycle - self.start < self.cycles
    }

    /// First cycle after the fault.
    pub fn end(&self) -> u64 {
        self.start.saturating_add(self.cycles)
    }
}

/// Wired AND of the given transmit values (`true` = recessive; empty = recessive).
pub fn wired_and(tx: &[bool]) -> bool {
    tx.iter().all(|&b| b)
}

/// A wired-AND bus of a fixed number of nodes with a list of faults.
#[derive(Clone, Debug)]
pub struct Bus {
    nodes: usize,
    faults: Vec<Fault>,
    /// Cycle after which no fault is active any more (fast path).
    faults_end: u64,
}

impl Bus {
    /// A fault-free bus of `nodes` nodes.
    pub fn new(nodes: usize) -> Self {
        Bus {
            nodes,
            faults: Vec::new(),
            faults_end: 0,
        }
    }

    /// Number of nodes.
    pub fn nodes(&self) -> usize {
        self.nodes
    }

    /// The injected faults.
    pub fn faults(&self) -> &[Fault] {
        &self.faults
    }

    /// Repairs the bus at clock `at`: a fault still active then ends just before
    /// `at`, one not started yet is dropped (a served network's `fault heal`).
    pub fn end_faults(&mut self, at: u64) {
        self.faults.retain(|f| f.start < at);
        for f in &mut self.faults {
            if f.end() > at {
                f.cycles = at - f.start;
            }
        }
        self.faults_end = self.faults.iter().map(Fault::end).max().unwrap_or(0);
    }

    /// Adds a fault; refuses a node index out of range or an empty window.
    pub fn add_fault(&mut self, fault: Fault) -> Result<(), String> {
        match fault.target {
            FaultTarget::Tx(n) | FaultTarget::Rx(n) if n >= self.nodes => {
                return Err(format!(
                    "fault targets node {n}, but the bus has {} nodes (0..={})",
                    self.nodes,
                    self.nodes.saturating_sub(1)
                ));
            }
            _ => {}
        }
        if fault.cycles == 0 {
            return Err("fault lasts 0 cycles: give a duration of at least 1".to_string());
        }
        self.faults_end = self.faults_end.max(fault.end());
        self.faults.push(fault);
        Ok(())
    }

    /// Whether some fault may be active at `cycle` or later.
    pub fn has_faults_from(&self, cycle: u64) -> bool {
        cycle < self.faults_end
    }

    /// Resolves the bus for clock `cycle`: from every node's `tx` (as returned by the
    /// previous step) computes the line value and every node's `rx` (written into
    /// `rx`, which must have one entry per node). Returns the line value.
    pub fn resolve(&self, cycle: u64, tx: &[bool], rx: &mut [bool]) -> bool {
        debug_assert_eq!(tx.len(), self.nodes);
        debug_assert_eq!(rx.len(), self.nodes);
        if cycle >= self.faults_end {
            let line = wired_and(tx);
            rx.iter_mut().for_each(|r| *r = line);
            return line;
        }
        let active = || self.faults.iter().filter(move |f| f.active(cycle));
        // Transmitter faults change one node's contribution.
        let mut line = true;
        for (i, &t) in tx.iter().enumerate() {
            let mut v = t;
            for f in active() {
                if f.target == FaultTarget::Tx(i) {
                    v = f.kind.apply(v);
                }
            }
            line &= v;
        }
        // Line faults are seen by everyone.
        for f in active() {
            if f.target == FaultTarget::Bus {
                line = f.kind.apply(line);
            }
        }
        // Receiver faults are seen by one node.
        for (i, r) in rx.iter_mut().enumerate() {
            let mut v = line;
            for f in active() {
                if f.target == FaultTarget::Rx(i) {
                    v = f.kind.apply(v);
                }
            }
            *r = v;
        }
        line
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fault(target: FaultTarget, kind: FaultKind, start: u64, cycles: u64) -> Fault {
        Fault {
            target,
            kind,
            start,
            cycles,
        }
    }

    #[test]
    fn wired_and_is_dominant_if_any_node_is_dominant() {
        let bus = Bus::new(3);
        let mut rx = [false; 3];
        assert!(bus.resolve(0, &[true, true, true], &mut rx));
        assert_eq!(rx, [true; 3]);
        assert!(!bus.resolve(0, &[true, false, true], &mut rx));
        assert_eq!(rx, [false; 3]);
        assert!(wired_and(&[]));
    }

    #[test]
    fn faults_act_in_their_window_only() {
        let mut bus = Bus::new(2);
        bus.add_fault(fault(FaultTarget::Bus, FaultKind::StuckDominant, 10, 5))
            .unwrap();
        let mut rx = [true; 2];
        assert!(bus.resolve(9, &[true, true], &mut rx));
        assert!(!bus.resolve(10, &[true, true], &mut rx));
        assert!(!bus.resolve(14, &[true, true], &mut rx));
        assert!(bus.resolve(15, &[true, true], &mut rx));
        assert!(!bus.has_faults_from(15));
    }

    #[test]
    fn a_repair_ends_active_faults_and_drops_later_ones() {
        let mut bus = Bus::new(2);
        bus.add_fault(fault(
            FaultTarget::Bus,
            FaultKind::StuckDominant,
            10,
            u64::MAX - 10,
        ))
        .unwrap();
        bus.add_fault(fault(FaultTarget::Bus, FaultKind::StuckDominant, 50, 5))
            .unwrap();
        let mut rx = [true; 2];
        assert!(!bus.resolve(19, &[true, true], &mut rx));
        bus.end_faults(20);
        assert!(bus.resolve(20, &[true, true], &mut rx), "repaired at 20");
        assert!(
            bus.resolve(50, &[true, true], &mut rx),
            "the later fault is gone"
        );
        assert!(!bus.has_faults_from(20));
        assert_eq!(bus.faults().len(), 1);
    }

    #[test]
    fn tx_and_rx_faults_are_local() {
        let mut bus = Bus::new(3);
        bus.add_fault(fault(FaultTarget::Tx(1), FaultKind::StuckRecessive, 0, 100))
            .unwrap();
        bus.add_fault(fault(FaultTarget::Rx(2), FaultKind::Flip, 0, 1))
            .unwrap();
        let mut rx = [true; 3];
        // Node 1's dominant bit never reaches the line.
        assert!(bus.resolve(0, &[true, false, true], &mut rx));
        assert_eq!(rx, [true, true, false]);
        // Node 0's does; node 2's flip window is over.
        assert!(!bus.resolve(1, &[false, true, true], &mut rx));
        assert_eq!(rx, [false, false, false]);
    }

    #[test]
    fn bad_faults_are_refused() {
        let mut bus = Bus::new(2);
        assert!(bus
            .add_fault(fault(FaultTarget::Rx(2), FaultKind::Flip, 0, 1))
            .is_err());
        assert!(bus
            .add_fault(fault(FaultTarget::Bus, FaultKind::Flip, 0, 0))
            .is_err());
    }
}
