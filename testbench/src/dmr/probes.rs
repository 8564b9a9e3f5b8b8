//! The DMR probes of a DRCC (DMR contract §9), read by the test plan every clock:
//! `dmr_state`, `acl` and the four fault flags. One accessor, so the rest of the plan
//! does not depend on how the engines name them.

use drcc_cosim::engine::drcc::DrccOutputs;

/// The DMR probes of one device after a clock.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DmrProbe {
    /// `dmr_state` (0 redundancy active .. 3 network disconnected).
    pub state: u8,
    /// The active CAN line: false DCL, true RCL.
    pub acl: bool,
    /// Any of `dcl_tx_fault`, `dcl_rx_fault`, `rcl_tx_fault`, `rcl_rx_fault`.
    pub fault: bool,
}

/// The DMR probes of `o`.
pub fn probe(o: &DrccOutputs) -> DmrProbe {
    let p = &o.probes;
    DmrProbe {
        state: p.dmr_state,
        acl: p.acl,
        fault: p.dcl_tx_fault || p.dcl_rx_fault || p.rcl_tx_fault || p.rcl_rx_fault,
    }
}
