//! The coverage catalogue: the bins the product must reach,
//! written from the standard, the papers and the contracts (not from what a run
//! hits), the combinations that cannot occur with the reason, and the bin-name
//! builders the cover points use. Counting lives in the parent module.

use std::collections::BTreeMap;

use crate::model::field;

mod groups;

/// One bin the product must reach.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Bin {
    /// Group, for the report ("main FSM", "fault confinement", ...).
    pub group: &'static str,
    /// The name its cover point counts under.
    pub name: String,
    /// Where the rule comes from.
    pub source: &'static str,
}

/// A combination that cannot occur, with the reason.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unreachable {
    pub group: &'static str,
    /// The bin names (or a pattern in words) that cannot be hit.
    pub what: String,
    pub reason: &'static str,
}

/// Main FSM state names (DRCC contract §4, Table 1 of the DRCC paper).
pub const MAIN_STATES: [&str; 10] = [
    "idle1", "wait1", "ch1", "abort1", "wait2", "idle2", "wait3", "ch2", "abort2", "wait4",
];

/// The main FSM's transitions of Table 1 (DRCC contract §4.1).
const MAIN_TRANSITIONS: [(&str, &str); 20] = [
    ("idle1", "wait1"),
    ("idle1", "idle2"),
    ("wait1", "ch1"),
    ("ch1", "idle1"),
    ("ch1", "idle2"),
    ("ch1", "abort1"),
    ("abort1", "idle1"),
    ("abort1", "idle2"),
    ("abort1", "wait2"),
    ("wait2", "idle1"),
    ("wait2", "idle2"),
    ("idle2", "wait3"),
    ("idle2", "wait4"),
    ("wait3", "ch2"),
    ("ch2", "idle2"),
    ("ch2", "abort2"),
    ("abort2", "idle2"),
    ("abort2", "wait4"),
    ("wait4", "idle1"),
    ("wait4", "idle2"),
];

/// The name of a main FSM transition bin.
pub fn main_transition(from: u8, to: u8) -> String {
    let s = |x: u8| MAIN_STATES.get(x as usize).copied().unwrap_or("unused");
    format!("main: {} -> {}", s(from), s(to))
}

/// The name of a star-node echo bin: the main FSM state the echo completed the
/// message in (DRCC contract §4.4).
pub fn star_echo(state: u8) -> String {
    let s = MAIN_STATES.get(state as usize).copied().unwrap_or("unused");
    format!("star echo: completes the message in {s}")
}

/// Auxiliary FSM state names (DRCC contract §5).
pub const AUX_STATES: [&str; 4] = ["valid", "failed", "restart", "probation"];

/// Roles and error kinds of the error cross.
pub const ROLES: [&str; 2] = ["tx", "rx"];
pub const ERROR_KINDS: [&str; 6] = ["bit", "stuff", "stuff in arbitration", "crc", "form", "ack"];

/// The name of an error bin: the role, the kind and the field it was detected in.
pub fn error_bin(transmitter: bool, kind: &str, field_code: u8) -> String {
    let role = if transmitter { "tx" } else { "rx" };
    format!("error: {role} {kind} in {}", field::name(field_code))
}

/// Fields a transmitter drives as frame bits (base and extended, data and remote).
const TX_FRAME_FIELDS: [u8; 10] = [
    field::ID_A,
    field::SRR_RTR,
    field::IDE,
    field::ID_B,
    field::RTR_EXT,
    field::R1,
    field::R0,
    field::DLC,
    field::DATA,
    field::CRC,
];

/// Which (role, kind, field) errors ISO 11898-1 allows (clause 10.11 error
/// detection; 12.1.4.2 for the exceptions), with the source. Everything else of
/// the cross is in [`unreachable`]. The field is the `field` probe's at the
/// detecting SAMPLE edge (timing contract §4.1): the field of the bit sampled, and
/// for a stuff bit the field of the next non-stuff bit (a stuff bit after the last
/// CRC bit is "in CRC_DELIM", one after RTR of an extended frame "in R1").
fn error_bins() -> Vec<Bin> {
    let mut v = Vec::new();
    let mut add = |tx: bool, kind: &str, f: u8, source: &'static str| {
        v.push(Bin {
            group: "error kind x field x role",
            name: error_bin(tx, kind, f),
            source,
        })
    };
    // Transmitter bit errors: a bit it sends read back different, in every field it
    // drives outside arbitration and the ACK slot (10.11.2), its SOF included (read
    // back at IDLE or at the 3rd intermission bit), and in its active error and
    // overload flags (rules d).
    for f in TX_FRAME_FIELDS {
        add(true, "bit", f, "ISO 11898-1 10.11.2");
    }
    // A transmitter monitors the recessive CRC delimiter, ACK delimiter and EOF it
    // sends: a dominant one is a bit error (10.11.2) before it is a form error
    // (timing contract §4.5: the capture code is bit).
    for f in [field::CRC_DELIM, field::ACK_DELIM, field::EOF] {
        add(true, "bit", f, "ISO 11898-1 10.11.2; timing contract §4.5");
    }
    add(true, "bit", field::IDLE, "ISO 11898-1 10.11.2 (its SOF)");
    add(
        true,
        "bit",
        field::ERROR_FLAG,
        "ISO 11898-1 12.1.4.2 rule d",
    );
    add(
        true,
        "bit",
        field::OVERLOAD_FLAG,
        "ISO 11898-1 12.1.4.2 rule d",
    );
    // A recessive stuff bit of the transmitter read dominant "during arbitration":
    // the last non-stuff bit before it is in ID_A, SRR/RTR, IDE (extended), ID_B or
    // RTR (extended) (timing contract §4.5), so the next bit is in ID_A, SRR_RTR,
    // IDE, ID_B, RTR_EXT or R1.
    for f in [
        field::ID_A,
        field::SRR_RTR,
        field::IDE,
        field::ID_B,
        field::RTR_EXT,
        field::R1,
    ] {
        add(
            true,
            "stuff in arbitration",
            f,
            "ISO 11898-1 12.1.4.2 rule c exception 2; timing contract §4.5",
        );
    }
    // Form errors: a dominant bit in a fixed-form field (10.11.4): the receivers'
    // delimiters and EOF, and both roles' error and overload delimiters.
    for f in [field::CRC_DELIM, field::ACK_DELIM, field::EOF] {
        add(false, "form", f, "ISO 11898-1 10.11.4");
    }
    for tx in [true, false] {
        for f in [field::ERROR_DELIM, field::OVERLOAD_DELIM] {
            add(tx, "form", f, "ISO 11898-1 10.11.4");
        }
    }
    add(true, "ack", field::ACK_SLOT, "ISO 11898-1 10.11.5");
    // Receiver: stuff errors in the stuffed fields (10.11.3), CRC errors signalled
    // after the ACK delimiter (10.11.3 / 10.4.4), bit errors on what it sends: its
    // ACK and its active flags (10.11.2, rule e).
    // stuff bits are labelled by the next bit's field: from inside the identifier
    // (ID_A) to the one after the last CRC bit (CRC_DELIM)
    for f in TX_FRAME_FIELDS {
        add(false, "stuff", f, "ISO 11898-1 10.11.3");
    }
    add(
        false,
        "stuff",
        field::CRC_DELIM,
        "ISO 11898-1 10.5 (the stuff bit after the last CRC bit)",
    );
    add(false, "crc", field::ACK_DELIM, "ISO 11898-1 10.11.3");
    add(
        false,
        "bit",
        field::ACK_SLOT,
        "ISO 11898-1 10.11.2 (its ACK)",
    );
    add(
        false,
        "bit",
        field::ERROR_FLAG,
        "ISO 11898-1 12.1.4.2 rule e",
    );
    add(
        false,
        "bit",
        field::OVERLOAD_FLAG,
        "ISO 11898-1 12.1.4.2 rule e",
    );
    v
}

/// Bins of `group` named in a (name, source) list.
fn named(group: &'static str, list: &[(&str, &'static str)]) -> Vec<Bin> {
    list.iter()
        .map(|&(name, source)| Bin {
            group,
            name: name.to_string(),
            source,
        })
        .collect()
}

/// Every bin the product must reach, group by group.
pub fn bins() -> Vec<Bin> {
    let mut v = groups::main_fsm_bins();
    v.extend(groups::aux_fsm_bins());
    v.extend(groups::fault_confinement_bins());
    v.extend(error_bins());
    v.extend(groups::hub_isolation_bins());
    v.extend(groups::register_port_bins());
    v.extend(groups::dmr_bins());
    v.extend(groups::star_node_bins());
    v.extend(groups::hub_nrap_bins());
    v
}

/// The combinations that cannot occur, with the reason.
pub fn unreachable() -> Vec<Unreachable> {
    let u = |group, what: &str, reason| Unreachable {
        group,
        what: what.to_string(),
        reason,
    };
    vec![
        u(
            "main FSM (Table 1)",
            "main: the other state pairs, and the unused encodings 10..15",
            "Table 1 has no such transition; the unused encodings are never entered (the state register is only written with Table 1 states) and would return to idle1",
        ),
        u(
            "auxiliary FSMs",
            "aux: failed -> valid, restart -> failed, probation -> failed",
            "contract §5: a failed channel is restarted before it is trusted; probation ends only in valid (an error restarts its count instead)",
        ),
        u(
            "error kind x field x role",
            "error: tx stuff in any field",
            "a transmitter compares every bit it sends, stuff bits included: a wrong stuff bit is a bit error first (10.11.2), six equal bits never reach its destuffer",
        ),
        u(
            "error kind x field x role",
            "error: tx form in CRC_DELIM, ACK_DELIM, EOF",
            "the transmitter sends these bits recessive and monitors them: a dominant one is its bit error (10.11.2; timing contract §4.5)",
        ),
        u(
            "error kind x field x role",
            "error: tx crc in any field",
            "the CRC check is a receiver's (10.11.3); the transmitter sent the sequence",
        ),
        u(
            "error kind x field x role",
            "error: rx ack in any field",
            "the ACK error is the transmitter's (10.11.5)",
        ),
        u(
            "error kind x field x role",
            "error: tx bit in ACK_SLOT, SRR/RTR/IDE/ID recessive bits read dominant",
            "sending recessive and reading dominant in the ACK slot is the acknowledgement, and in arbitration it is a lost arbitration (10.11.2 exceptions)",
        ),
        u(
            "error kind x field x role",
            "error: rx bit in frame fields other than the ACK slot",
            "a receiver sends nothing but its ACK and its flags",
        ),
        u(
            "error kind x field x role",
            "error: stuff in ACK_SLOT .. EOF, interframe and error fields; crc anywhere but ACK_DELIM",
            "stuffing ends with the stuff bit after the CRC sequence (10.5); the CRC is checked once, at the ACK delimiter",
        ),
        u(
            "error kind x field x role",
            "error: stuff in arbitration before R0, DLC, DATA, CRC, CRC_DELIM, or as receiver",
            "a stuff bit after a base frame's IDE or later is in the control field or beyond, not in arbitration (12.1.4.2 c exc. 2, 10.4.2.3; timing contract §4.5); a receiver has no arbitration",
        ),
        u(
            "error kind x field x role",
            "error: form in frame fields before the CRC delimiter, in flags and IDLE/INTERMISSION",
            "form errors are dominant bits in fixed-form fields only (10.11.4); a dominant intermission bit is an overload or a SOF",
        ),
        u(
            "hub isolation and restoration",
            "hub: isolate sublink (reserved identifier)",
            "rule RID applies to node ports only: the hubs' identifiers legitimately come over the sublinks (hub contract §6)",
        ),
    ]
}

/// The counted names that are neither a bin nor covered by [`unreachable`]'s
/// groups: every name is matched against the bin list exactly.
pub fn unlisted(counts: &BTreeMap<String, u64>) -> Vec<(String, u64)> {
    let known: std::collections::BTreeSet<String> = bins().into_iter().map(|b| b.name).collect();
    counts
        .iter()
        .filter(|(n, _)| !known.contains(*n))
        .map(|(n, c)| (n.clone(), *c))
        .collect()
}
