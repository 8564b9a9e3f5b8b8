//! Reference model of the REDCAN relay module (RCM), written from
//! `ring_contract.md` §2: the host's two control bits, the refusal of the illegal
//! combination, and the decode to the relay and termination drivers.

/// Mode code: connect left, disconnect right (the paper's Fig. 4).
pub const LEFT: u8 = 1;
/// Mode code: connect right, disconnect left.
pub const RIGHT: u8 = 2;
/// Mode code: transparent (relay closed; the default mode, Fig. 5).
pub const TRANSPARENT: u8 = 3;

/// What the RCM samples at one edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RcmInputs {
    /// Synchronous reset.
    pub rst: bool,
    /// One-clock write strobe for `ctl`.
    pub ctl_we: bool,
    /// Requested mode: bit 0 connect left, bit 1 connect right.
    pub ctl: u8,
}

/// The RCM's outputs after an edge (§2 table).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RcmOutputs {
    /// Relay closed: left and right sections joined.
    pub relay: bool,
    /// The node's transceiver is on the left section.
    pub node_left: bool,
    /// The node's transceiver is on the right section.
    pub node_right: bool,
    /// A termination on the left section's end.
    pub term_left: bool,
    /// A termination on the right section's end.
    pub term_right: bool,
    /// The mode in force (`LEFT`, `RIGHT`, `TRANSPARENT`).
    pub mode: u8,
    /// The last write asked for the illegal combination `00` and was refused.
    pub illegal: bool,
    /// Mode changes since reset, wrapping at 256.
    pub changes: u8,
}

/// The RCM's registers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RcmModel {
    mode: u8,
    illegal: bool,
    changes: u8,
}

impl Default for RcmModel {
    fn default() -> Self {
        Self::new()
    }
}

impl RcmModel {
    /// The reset state: transparent, nothing refused, no change counted.
    pub fn new() -> Self {
        RcmModel {
            mode: TRANSPARENT,
            illegal: false,
            changes: 0,
        }
    }

    /// One rising edge with `i`; the outputs right after it.
    pub fn step(&mut self, i: &RcmInputs) -> RcmOutputs {
        if i.rst {
            *self = RcmModel::new();
        } else if i.ctl_we {
            let ctl = i.ctl & 3;
            if ctl == 0 {
                // §2: 00 would take the node off both sections: refused, mode holds.
                self.illegal = true;
            } else {
                if ctl != self.mode {
                    self.changes = self.changes.wrapping_add(1);
                }
                self.mode = ctl;
                self.illegal = false;
            }
        }
        self.outputs()
    }

    /// The outputs for the registers as they are.
    pub fn outputs(&self) -> RcmOutputs {
        let transparent = self.mode == TRANSPARENT;
        RcmOutputs {
            relay: transparent,
            node_left: self.mode & LEFT != 0,
            node_right: self.mode & RIGHT != 0,
            // An RCM terminates every section end it does not join through (§1).
            term_left: !transparent,
            term_right: !transparent,
            mode: self.mode,
            illegal: self.illegal,
            changes: self.changes,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write(m: &mut RcmModel, ctl: u8) -> RcmOutputs {
        m.step(&RcmInputs {
            rst: false,
            ctl_we: true,
            ctl,
        })
    }

    #[test]
    fn modes_decode_as_the_contract_table() {
        let mut m = RcmModel::new();
        let o = m.outputs();
        // Reset: transparent, relay closed, no termination.
        assert_eq!(
            (
                o.relay,
                o.node_left,
                o.node_right,
                o.term_left,
                o.term_right,
                o.mode
            ),
            (true, true, true, false, false, 3)
        );
        let o = write(&mut m, 0b01);
        assert_eq!(
            (
                o.relay,
                o.node_left,
                o.node_right,
                o.term_left,
                o.term_right,
                o.mode
            ),
            (false, true, false, true, true, 1)
        );
        let o = write(&mut m, 0b10);
        assert_eq!(
            (
                o.relay,
                o.node_left,
                o.node_right,
                o.term_left,
                o.term_right,
                o.mode
            ),
            (false, false, true, true, true, 2)
        );
        assert_eq!(o.changes, 2);
    }

    #[test]
    fn the_illegal_combination_is_refused_and_flagged() {
        let mut m = RcmModel::new();
        write(&mut m, 0b01);
        let o = write(&mut m, 0b00);
        assert_eq!((o.mode, o.illegal, o.changes), (1, true, 1), "mode holds");
        // A legal write clears the flag; writing the mode in force is no change.
        let o = write(&mut m, 0b01);
        assert_eq!((o.mode, o.illegal, o.changes), (1, false, 1));
        // Without the strobe nothing happens.
        let o = m.step(&RcmInputs {
            rst: false,
            ctl_we: false,
            ctl: 0b10,
        });
        assert_eq!(o.mode, 1);
    }

    #[test]
    fn the_change_count_wraps() {
        let mut m = RcmModel::new();
        for k in 0..256u32 {
            write(&mut m, if k % 2 == 0 { 0b01 } else { 0b10 });
        }
        assert_eq!(m.outputs().changes, 0);
    }
}
