//! Network faults of a dual-bus system beyond what [`crate::bus::Bus`] injects: a
//! node *detached* from one line (its stub is open), and the *short circuit* of a
//! whole line. These are the faults of the CiA 701 test plan (seed 001, Table 2:
//! F1..F8 "CAN bus disconnected", F9..F10 "CAN lines short-circuited"; DMR contract
//! §10).
//!
//! - **Detach** ([`Detach`]): node `node` loses its connection to the line during
//!   clocks `start .. start + cycles`. Its transceiver hears only itself (its `rx` is
//!   its own `tx`: no other node, no acknowledgement), and the other nodes do not see
//!   its `tx` (it contributes recessive to their wired AND). Other faults of the line
//!   still act on the connected nodes; the detached node's `rx` is its `tx`, untouched
//!   by them (nothing reaches an open stub).
//! - **Short circuit** ([`short_circuit`]): CAN_H tied to CAN_L leaves no differential
//!   voltage, so every transceiver reads recessive and no dominant bit reaches anyone.
//!   That is exactly a line fault stuck recessive ([`FaultTarget::Bus`] +
//!   [`FaultKind::StuckRecessive`]), so no new mechanism is needed; the helper names it.
//!
//! A fault may be present from cycle 0 (a "startup failure": `start = 0`) or arise at
//! run time; `cycles = u64::MAX` never ends.

use crate::bus::{Fault, FaultKind, FaultTarget};

/// Node `node` detached from one line during clocks `start .. start + cycles`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Detach {
    pub node: usize,
    pub start: u64,
    pub cycles: u64,
}

impl Detach {
    /// Whether the node is detached in clock `cycle`.
    pub fn active(&self, cycle: u64) -> bool {
        cycle >= self.start && cycle - self.start < self.cycles
    }

    /// First clock after the fault (saturating).
    pub fn end(&self) -> u64 {
        self.start.saturating_add(self.cycles)
    }
}

/// The short circuit of a whole line during clocks `start .. start + cycles`: every
/// node reads recessive (see the module documentation).
pub fn short_circuit(start: u64, cycles: u64) -> Fault {
    Fault {
        target: FaultTarget::Bus,
        kind: FaultKind::StuckRecessive,
        start,
        cycles,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_detach_is_active_in_its_window_only() {
        let d = Detach {
            node: 1,
            start: 10,
            cycles: 5,
        };
        assert!(!d.active(9));
        assert!(d.active(10) && d.active(14));
        assert!(!d.active(15));
        assert_eq!(d.end(), 15);
        let forever = Detach {
            node: 0,
            start: 0,
            cycles: u64::MAX,
        };
        assert!(forever.active(0) && forever.active(u64::MAX - 1));
        assert_eq!(forever.end(), u64::MAX);
    }

    #[test]
    fn a_short_circuit_is_a_line_stuck_recessive() {
        let f = short_circuit(3, 7);
        assert_eq!(f.target, FaultTarget::Bus);
        assert_eq!(f.kind, FaultKind::StuckRecessive);
        assert_eq!((f.start, f.cycles), (3, 7));
    }
}
