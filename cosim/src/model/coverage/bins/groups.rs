//! The catalogue's bins group by group, in the order [`super::bins`] lists them:
//! the main FSM, the auxiliary FSMs, fault confinement, the hub's isolation and
//! restoration, the register ports' byte lanes, DMR, the replicated star node
//! and the hubs' NRAP. The error cross is beside its name builder in the parent.

use super::{named, Bin, MAIN_TRANSITIONS};

/// The main FSM's transitions (Table 1 of the DRCC paper, DRCC contract §4.1).
pub(super) fn main_fsm_bins() -> Vec<Bin> {
    let mut v = Vec::new();
    for (a, b) in MAIN_TRANSITIONS {
        v.push(Bin {
            group: "main FSM (Table 1)",
            name: format!("main: {a} -> {b}"),
            source: "DRCC paper Table 1; DRCC contract §4.1",
        });
    }
    v
}

/// The auxiliary FSMs' failure causes and recovery transitions (DRCC contract §5).
pub(super) fn aux_fsm_bins() -> Vec<Bin> {
    let mut v = Vec::new();
    for cause in [
        "error passive",
        "bus-off",
        "k failed",
        "stall",
        "warning limit",
    ] {
        v.push(Bin {
            group: "auxiliary FSMs",
            name: format!("aux: valid -> failed ({cause})"),
            source: "DRCC contract §5 failure causes",
        });
    }
    for (a, b) in [
        ("failed", "restart"),
        ("restart", "probation"),
        ("probation", "valid"),
    ] {
        v.push(Bin {
            group: "auxiliary FSMs",
            name: format!("aux: {a} -> {b}"),
            source: "DRCC contract §5",
        });
    }
    v.push(Bin {
        group: "auxiliary FSMs",
        name: "aux: probation count restarted by an error".into(),
        source: "DRCC contract §5 probation",
    });
    v
}

/// The fault confinement rules a to l (ISO 11898-1 12.1.4.2).
pub(super) fn fault_confinement_bins() -> Vec<Bin> {
    named(
        "fault confinement",
        &[
            ("rule a: REC + 1", "ISO 11898-1 12.1.4.2 a"),
            (
                "rule b: REC + 8 (dominant first bit after its error flag)",
                "12.1.4.2 b",
            ),
            ("rule c: TEC + 8", "12.1.4.2 c"),
            (
                "rule c exception 1: passive ACK error, TEC unchanged",
                "12.1.4.2 c exc. 1",
            ),
            (
                "rule c exception 1 ended: dominant bit in the passive flag, TEC + 8",
                "12.1.4.2 c exc. 1",
            ),
            (
                "rule c exception 2: stuff error in arbitration, TEC unchanged",
                "12.1.4.2 c exc. 2",
            ),
            ("rule d: TEC + 8 (bit error in its flag)", "12.1.4.2 d"),
            ("rule e: REC + 8 (bit error in its flag)", "12.1.4.2 e"),
            (
                "rule f: TEC + 8 (8 dominant bits after its flag)",
                "12.1.4.2 f",
            ),
            (
                "rule f: REC + 8 (8 dominant bits after its flag)",
                "12.1.4.2 f",
            ),
            ("rule g: TEC - 1", "12.1.4.2 g"),
            ("rule g: TEC stays 0", "12.1.4.2 g"),
            ("rule h: REC - 1", "12.1.4.2 h"),
            ("rule h: REC above 127 back to 119..127", "12.1.4.2 h"),
            ("rule h: REC stays 0", "12.1.4.2 h"),
            ("rule i: error passive (TEC >= 128)", "12.1.4.2 i"),
            ("rule i: error passive (REC >= 128)", "12.1.4.2 i"),
            ("rule j: bus-off (TEC > 255)", "12.1.4.2 j"),
            ("rule k: error active again", "12.1.4.2 k"),
            (
                "rule l: bus-off recovery (128 x 11 recessive bits)",
                "12.1.4.2 l",
            ),
        ],
    )
}

/// The hub's isolation and restoration of its ports, per port kind and fault,
/// and its decoupling (hub contract §6, §7).
pub(super) fn hub_isolation_bins() -> Vec<Bin> {
    let mut v = Vec::new();
    for port in ["node port", "sublink"] {
        let kinds: &[&str] = if port == "node port" {
            &[
                "stuck dominant",
                "reserved identifier",
                "bit flipping",
                "silent",
            ]
        } else {
            &["stuck dominant", "bit flipping", "silent"]
        };
        for k in kinds {
            v.push(Bin {
                group: "hub isolation and restoration",
                name: format!("hub: isolate {port} ({k})"),
                source: "hub contract §6; ReCANcentrate paper section 3",
            });
        }
        v.push(Bin {
            group: "hub isolation and restoration",
            name: format!("hub: restore {port}"),
            source: "hub contract §6 restoration",
        });
    }
    v.extend(named(
        "hub isolation and restoration",
        &[
            ("hub: decouple (no sublink left)", "hub contract §7"),
            (
                "hub: decouple (forced)",
                "hub contract §7, CTRL.force_decouple",
            ),
            ("hub: recouple", "hub contract §7, CTRL.recouple"),
        ],
    ));
    v
}

/// The register ports' byte lanes (bus contract §1).
pub(super) fn register_port_bins() -> Vec<Bin> {
    named(
        "register port byte lanes",
        &[
            (
                "drcc register port: a partial write to a staged TX word",
                "bus contract §1 (TX_ID, TX_CTRL, TX_DATA0/1 honour byte lanes)",
            ),
            (
                "drcc register port: a partial write to a whole word is refused",
                "bus contract §1 (ERR, INT_STATUS.illegal)",
            ),
            (
                "hub register port: a partial write is refused",
                "bus contract §1 (every hub word is written whole)",
            ),
        ],
    )
}

/// The DMR block's faults, ACL switch, recovery and states (CiA 701, DMR
/// contract).
pub(super) fn dmr_bins() -> Vec<Bin> {
    named(
        "DMR",
        &[
            (
                "dmr: tx fault (timeout)",
                "CiA 701 Table 2; DMR contract §4.2, §6",
            ),
            (
                "dmr: rx fault (timeout)",
                "CiA 701 Table 3; DMR contract §4.2, §6",
            ),
            ("dmr: tx fault (deviation)", "DMR contract §4.2, §6"),
            ("dmr: rx fault (deviation)", "DMR contract §4.2, §6"),
            ("dmr: tx fault (bus-off)", "DMR contract §6"),
            (
                "dmr: tx fault (connection service failed)",
                "DMR contract §7",
            ),
            (
                "dmr: rx fault on a line already unable to transmit",
                "DMR contract §6",
            ),
            ("dmr: ACL switch", "CiA 701; DMR contract §8"),
            (
                "dmr: recovery (connection service after a fault)",
                "DMR contract §7",
            ),
            (
                "dmr: receive mailbox re-balanced after a recovery",
                "DMR contract §4.2 settling",
            ),
            (
                "dmr: state active -> passive",
                "CiA 701 Figure 6; DMR contract §6",
            ),
            (
                "dmr: state active -> disabled",
                "CiA 701 Figure 6; DMR contract §6",
            ),
            (
                "dmr: state passive -> active",
                "CiA 701 Figure 6; DMR contract §6",
            ),
            (
                "dmr: state disabled -> active",
                "CiA 701 Figure 6; DMR contract §6",
            ),
            (
                "dmr: state passive -> disabled",
                "CiA 701 Figure 6; DMR contract §6",
            ),
        ],
    )
}

/// The replicated star node: the echo, the hubs' decision and omissions
/// (ReCANcentrate, DRCC contract §4.4, §4.5, §7).
pub(super) fn star_node_bins() -> Vec<Bin> {
    // The echo completes the message while its attempt is in flight on A (ch1)
    // or on B (ch2), or while the FSM waits for a failed channel to be quiet
    // (wait2, wait4: the NRAP rows reach them). An echo in abort1/abort2 is a race
    // of the same kind as the main FSM's (the echo against the abort) and is not a
    // bin yet; if a workload reaches it, the collection names it as unlisted.
    named(
        "replicated star node",
        &[
            (
                "star echo: completes the message in ch1",
                "ReCANcentrate 2.1; DRCC contract §4.4",
            ),
            (
                "star echo: completes the message in ch2",
                "ReCANcentrate 2.1; DRCC contract §4.4",
            ),
            (
                "star echo: completes the message in wait2",
                "ReCANcentrate 2.1; DRCC contract §4.4 (the echo ahead of a failure)",
            ),
            (
                "star echo: completes the message in wait4",
                "ReCANcentrate 2.1; DRCC contract §4.4 (the echo ahead of a failure)",
            ),
            (
                "drcc star: the hubs' decision changes the domain",
                "ReCANcentrate 5; DRCC contract §4.5",
            ),
            (
                "rx: an omission (history entry expired unmatched)",
                "ReCANcentrate 2.1; DRCC contract §7 omissions",
            ),
        ],
    )
}

/// The hubs' node restoration protocol (ReCANcentrate 5, hub contract §9).
pub(super) fn hub_nrap_bins() -> Vec<Bin> {
    named(
        "hub NRAP",
        &[
            (
                "hub nrap: triggered (no sublink left)",
                "ReCANcentrate 5; hub contract §9.2",
            ),
            (
                "hub nrap: triggered (network blocked)",
                "ReCANcentrate 3; hub contract §9.2",
            ),
            (
                "hub nrap: joins the twin's exchange",
                "hub contract §9.2 joining",
            ),
            (
                "hub nrap: silent sublink restored",
                "ReCANcentrate 5; hub contract §9.2",
            ),
            (
                "hub nrap: acknowledges the twin's identification frame",
                "ReCANcentrate 5; hub contract §9.3",
            ),
            (
                "hub nrap: transmitter withdraws (arbitration or bit error)",
                "ISO 11898-1 arbitration; hub contract §9.3",
            ),
            (
                "hub nrap: a pair of identification frames",
                "ReCANcentrate 5; hub contract §9.2 pairs",
            ),
            (
                "hub nrap: sublinks agreed (to node restoration)",
                "ReCANcentrate 5; hub contract §9.2",
            ),
            ("hub nrap: recoupled", "ReCANcentrate 5; hub contract §9.2"),
            (
                "hub nrap: definitive decoupling",
                "ReCANcentrate 5; hub contract §9.2",
            ),
            (
                "hub nrap: split (each star on its own)",
                "ReCANcentrate 4, 5; hub contract §9.2",
            ),
            (
                "hub nrap: a node port errs and is disabled",
                "ReCANcentrate 5; hub contract §9.2",
            ),
        ],
    )
}
