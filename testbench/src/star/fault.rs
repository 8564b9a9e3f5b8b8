//! The faults of the star experiments: which links of which hub port fail and
//! how, the ports a fault targets and the isolation kind the hub must report.

use super::*;

/// The fault of a star scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StarFault {
    None,
    UplinkStuckDominant,
    UplinkBitFlipping,
    UplinkStuckRecessive,
    DownlinkCut,
    SublinkStuckDominant,
    InterlinkLost,
    AllInterlinksLost,
    TransientDecoupling,
    PermanentDecoupling,
    HubIgnoresTwin,
    HubLeaksAck,
}

impl StarFault {
    /// Every fault, in report order.
    pub const ALL: [StarFault; 12] = [
        StarFault::None,
        StarFault::UplinkStuckDominant,
        StarFault::UplinkBitFlipping,
        StarFault::UplinkStuckRecessive,
        StarFault::DownlinkCut,
        StarFault::SublinkStuckDominant,
        StarFault::InterlinkLost,
        StarFault::AllInterlinksLost,
        StarFault::TransientDecoupling,
        StarFault::PermanentDecoupling,
        StarFault::HubIgnoresTwin,
        StarFault::HubLeaksAck,
    ];

    /// Name as reports and the CLI spell it.
    pub fn name(self) -> &'static str {
        match self {
            StarFault::None => "no_fault",
            StarFault::UplinkStuckDominant => "uplink_stuck_dominant",
            StarFault::UplinkBitFlipping => "uplink_bit_flipping",
            StarFault::UplinkStuckRecessive => "uplink_stuck_recessive",
            StarFault::DownlinkCut => "downlink_cut",
            StarFault::SublinkStuckDominant => "sublink_stuck_dominant",
            StarFault::InterlinkLost => "interlink_lost",
            StarFault::AllInterlinksLost => "all_interlinks_lost",
            StarFault::TransientDecoupling => "transient_decoupling",
            StarFault::PermanentDecoupling => "permanent_decoupling",
            StarFault::HubIgnoresTwin => "hub_ignores_twin",
            StarFault::HubLeaksAck => "hub_leaks_ack",
        }
    }

    /// Looks a fault up by name.
    pub fn from_name(s: &str) -> Option<StarFault> {
        StarFault::ALL.into_iter().find(|f| f.name() == s)
    }

    /// One fault (one link, one interlink as a unit, or one faulty hub). Losing
    /// every interlink is a multiple fault. With NRAP (hub contract §9) the product
    /// promises no frame lost for both kinds.
    pub fn is_single(self) -> bool {
        !self.cuts_every_interlink()
    }

    /// Both interlinks cut: the hubs lose each other and NRAP decides.
    pub fn cuts_every_interlink(self) -> bool {
        matches!(
            self,
            StarFault::AllInterlinksLost
                | StarFault::TransientDecoupling
                | StarFault::PermanentDecoupling
        )
    }

    /// A hub's own fault, injected through its `CTRL` (hub, `CTRL` bits) for the
    /// fault window: `fi_no_twin` (§9.6) or `fi_ack_leak` (§4.1).
    pub fn hub_injection(self) -> Option<(usize, HubConfig)> {
        match self {
            StarFault::HubIgnoresTwin => Some((
                1,
                HubConfig {
                    fi_no_twin: true,
                    ..HubConfig::default()
                },
            )),
            StarFault::HubLeaksAck => Some((
                0,
                HubConfig {
                    fi_ack_leak: true,
                    ..HubConfig::default()
                },
            )),
            _ => None,
        }
    }

    /// What is faulty, in words.
    pub fn describe(self) -> &'static str {
        match self {
            StarFault::None => "nothing",
            StarFault::UplinkStuckDominant => "node 0 -> hub 1 uplink stuck dominant",
            StarFault::UplinkBitFlipping => {
                "node 1 -> hub 1 uplink inverted for 1 bit time in every 23"
            }
            StarFault::UplinkStuckRecessive => "node 2 -> hub 1 uplink stuck recessive",
            StarFault::DownlinkCut => "hub 1 -> node 3 downlink cut (reads recessive)",
            StarFault::SublinkStuckDominant => {
                "hub 2 -> hub 1 sublink of interlink 0 stuck dominant"
            }
            StarFault::InterlinkLost => "interlink 0 cut (both sublinks)",
            StarFault::AllInterlinksLost => {
                "both interlinks cut (all four sublinks) for 9000 bit times"
            }
            StarFault::TransientDecoupling => {
                "both interlinks cut for 1500 bit times (NRAP recouples)"
            }
            StarFault::PermanentDecoupling => "both interlinks cut for good",
            StarFault::HubIgnoresTwin => {
                "hub 2 does not couple hub 1's contribution (CTRL.fi_no_twin, paper section 3)"
            }
            StarFault::HubLeaksAck => {
                "hub 1 passes its own nodes' ACK (CTRL.fi_ack_leak); its ACK unit blocks it"
            }
        }
    }

    /// The links the fault acts on, with the kind.
    pub(super) fn links(self) -> Vec<(Link, LinkFaultKind)> {
        use LinkFaultKind::*;
        let sub = |from, interlink| Link::Sublink { from, interlink };
        match self {
            StarFault::None => vec![],
            StarFault::UplinkStuckDominant => {
                vec![(Link::Uplink { hub: 0, node: 0 }, StuckDominant)]
            }
            StarFault::UplinkBitFlipping => vec![(
                Link::Uplink { hub: 0, node: 1 },
                BitFlip {
                    period: 23 * CLOCKS_PER_BIT,
                    width: CLOCKS_PER_BIT,
                },
            )],
            StarFault::UplinkStuckRecessive => {
                vec![(Link::Uplink { hub: 0, node: 2 }, StuckRecessive)]
            }
            StarFault::DownlinkCut => vec![(Link::Downlink { hub: 0, node: 3 }, StuckRecessive)],
            StarFault::SublinkStuckDominant => vec![(sub(1, 0), StuckDominant)],
            StarFault::InterlinkLost => {
                vec![(sub(0, 0), StuckRecessive), (sub(1, 0), StuckRecessive)]
            }
            StarFault::AllInterlinksLost
            | StarFault::TransientDecoupling
            | StarFault::PermanentDecoupling => (0..HUB_M)
                .flat_map(|j| [(sub(0, j), StuckRecessive), (sub(1, j), StuckRecessive)])
                .collect(),
            StarFault::HubIgnoresTwin | StarFault::HubLeaksAck => vec![],
        }
    }

    /// The hub ports (hub, port) the fault should get isolated: the guarded input
    /// the faulty link feeds. A cut downlink feeds no guarded input, but it makes the
    /// node's uplink on that hub faulty: the node's controller never hears its own
    /// bits, so each dominant bit it sends is a bit error and its active error flags
    /// restart back to back (ISO 11898-1 10.11.2) until it is error passive, a
    /// dominant run the hub isolates as stuck-at-dominant (contract §6 rule SD).
    pub fn target_ports(self) -> Vec<(usize, usize)> {
        self.links()
            .into_iter()
            .map(|(l, _)| match l {
                Link::Uplink { hub, node } | Link::Downlink { hub, node } => (hub, node),
                Link::Sublink { from, interlink } => (1 - from, HUB_N + interlink),
            })
            .collect()
    }

    /// The fault kind (`PORT_p[3:1]`, contract §6) the target ports should show:
    /// 1 stuck-dominant, 2 silent, 3 bit-flipping.
    pub fn expected_kind(self) -> Option<u32> {
        match self {
            StarFault::None => None,
            StarFault::UplinkStuckDominant
            | StarFault::DownlinkCut
            | StarFault::SublinkStuckDominant => Some(1),
            StarFault::UplinkStuckRecessive
            | StarFault::InterlinkLost
            | StarFault::AllInterlinksLost
            | StarFault::TransientDecoupling
            | StarFault::PermanentDecoupling => Some(2),
            StarFault::UplinkBitFlipping => Some(3),
            StarFault::HubIgnoresTwin | StarFault::HubLeaksAck => None,
        }
    }
}
