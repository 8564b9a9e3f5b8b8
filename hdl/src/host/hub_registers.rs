//! The hub register map (hub contract §7, §8, §9.5; Wishbone conventions of the DRCC
//! contract §D.2): the one source of truth, in the form of the DRCC's
//! (`super::map`). The hub's register block (`crate::hub::registers`) decodes
//! with the indices below and takes its field positions from the table;
//! `markdown()` generates `docs/hub_registers.md` and `c_header()`
//! `rtl-out/hub_regs.h` (written by `drcc generate`).
//!
//! The hub has N node ports and M interlinks (P = N + M ports). The table
//! describes the emitted tops (N = 4, M = 2): `ID` carries N and M, `STATUS.enabled`
//! has one bit per port, and `PORT_p` is one register repeated at `PORT0 + p`. The
//! two emitted hubs (`hub.v` = hub A, `hub_b.v` = hub B) have the same map; only
//! `ID.hub_id` differs (its reset value in the table is hub A's, 0).

use super::map::{cfg, cmd, f, Access, Field, Register, RegisterMap};
use crate::register_enum;

/// Node ports of the emitted top.
pub const N: u32 = 4;
/// Interlinks of the emitted top.
pub const M: u32 = 2;

/// Word indices (contract §8).
pub const ID: u32 = 0;
pub const CTRL: u32 = 1;
pub const BTR: u32 = 2;
pub const GUARD_CFG: u32 = 3;
pub const BF_CFG: u32 = 4;
pub const RESTORE_CFG: u32 = 5;
pub const STATUS: u32 = 6;
pub const INT_STATUS: u32 = 7;
pub const INT_ENABLE: u32 = 8;
pub const STATS: u32 = 9;
pub const ACK_UNIT: u32 = 10;
pub const NRAP_CFG: u32 = 11;
pub const NRAP_TIME: u32 = 12;
pub const NRAP_DDSP: u32 = 13;
pub const NRAP_STATUS: u32 = 14;
/// `PORT_p` is at word index `PORT0 + p` (p < N + M).
pub const PORT0: u32 = 16;

/// `ID` without the shape: "HU" in the two upper bytes.
pub const ID_BASE: u32 = 0x4855_0000;

/// The `ID` value of hub `hub_id` (0 = hub A, 1 = hub B) with `n` node ports and
/// `m` interlinks.
pub const fn id_value(hub_id: u32, n: u32, m: u32) -> u32 {
    ID_BASE | (hub_id << 12) | (n << 8) | m
}

/// Smallest stored stuck-dominant threshold (`GUARD_CFG.sd_run_*` writes below
/// it are clamped, contract §8).
pub const SD_MIN: u32 = 14;
/// Smallest stored port error counter limit (`BF_CFG.bf_*`, contract §8).
pub const BF_MIN: u32 = 8;
/// Smallest stored NRAP force time (`NRAP_CFG.force_bits`, contract §9.5): above
/// the largest `sd_run_sub`, 63, so the twin always isolates a forced sublink.
pub const FORCE_MIN: u32 = 64;
/// Smallest stored NRAP phase time (`NRAP_TIME.srp_bits`, `NRAP_TIME.nrp_bits`,
/// `NRAP_DDSP.ddsp_bits`, contract §9.5).
pub const NRAP_BITS_MIN: u32 = 256;
/// Smallest stored NRAP count (`NRAP_CFG.srp_pairs`, `nrp_pairs`, `ddsp_frames`:
/// 0 stores 1, §9.5).
pub const NRAP_COUNT_MIN: u32 = 1;
/// Smallest stored non-zero `NRAP_DDSP.block_frames` (1..3 store 4; 0 stays,
/// the blocked-network trigger off, §9.5).
pub const BLOCK_MIN: u32 = 4;

register_enum! {
    /// Frame tracker state (`STATUS.trk`, contract §5).
    pub enum TrackerState {
        /// waiting for a start of frame
        IdleWait = 0 => "IDLE_WAIT",
        /// inside a frame, before its ACK slot
        Frame = 1 => "FRAME",
        AckSlot = 2 => "ACK_SLOT",
        AckDelim = 3 => "ACK_DELIM",
    }
}

register_enum! {
    /// NRAP phase (`NRAP_STATUS.nrap`, the `nrap_phase` probe, contract §9.2).
    pub enum NrapPhase {
        /// coupled (or NRAP off)
        Run = 0 => "RUN",
        /// sublink restoration: own contribution forced dominant
        SrpForce = 1 => "SRP_FORCE",
        /// sublink restoration: identification frames exchanged
        SrpExchange = 2 => "SRP_EXCHANGE",
        /// node restoration
        Nrp = 3 => "NRP",
        /// definitive decoupling signalling: own contribution forced dominant
        DdspForce = 4 => "DDSP_FORCE",
        /// definitive decoupling signalling: own identification frames
        DdspSend = 5 => "DDSP_SEND",
        /// definitively decoupled
        Split = 6 => "SPLIT",
    }
}

register_enum! {
    /// Whose identification frame reached its ACK slot last (`NRAP_STATUS.last`, §9.2).
    pub enum NrapLast {
        None = 0 => "NONE",
        Own = 1 => "OWN",
        Twin = 2 => "TWIN",
    }
}

register_enum! {
    /// Last fault of a port (`PORT_p.kind`, contract §6).
    pub enum FaultKind {
        None = 0 => "NONE",
        StuckDominant = 1 => "STUCK_DOMINANT",
        /// stuck recessive
        Silent = 2 => "SILENT",
        BitFlipping = 3 => "BIT_FLIPPING",
        ReservedId = 4 => "RESERVED_ID",
    }
}

const INT_FIELDS: &[Field] = &[
    f("isolation", 0, 1, 0, "a port was isolated"),
    f("restoration", 1, 1, 0, "an isolated port was restored"),
    f(
        "decoupled",
        2,
        1,
        0,
        "the hub decoupled (§7 or `CTRL.force_decouple`)",
    ),
    f("illegal", 3, 1, 0, "an illegal register access was refused"),
    f(
        "ack_unit",
        4,
        1,
        0,
        "the ACK unit turned a dominant downlink bit recessive (§4.1, once per ACK window)",
    ),
    f("nrap", 5, 1, 0, "the NRAP phase changed (§9)"),
];

/// The register map, in index order (`PORT0` stands for the block `PORT_p`).
pub const REGISTERS: &[Register] = &[
    Register {
        name: "ID",
        index: ID,
        access: Access::Ro,
        desc: "Identification: \"HU\", hub A / B, N, M",
        fields: &[
            f("m", 0, 8, M, "interlinks M"),
            f("n", 8, 4, N, "node ports N"),
            f("hub_id", 12, 4, 0, "0 = hub A (hub.v), 1 = hub B (hub_b.v): the identification frame it sends (§9.1)"),
            f("hu", 16, 16, ID_BASE >> 16, "0x4855 (\"HU\")"),
        ],
    },
    Register {
        name: "CTRL",
        index: CTRL,
        access: Access::Rw,
        desc: "Control; commands act only with reset_mode 0 before the write and in it",
        fields: &[
            f("reset_mode", 0, 1, 1, "1 = reset mode: a transparent two-stage AND star"),
            cmd("force_decouple", 1, "decouple now (NRAP on: NRAP phase SPLIT)"),
            cmd("recouple", 2, "recouple and enable every sublink (NRAP phase RUN); both commands in one write are refused"),
            f("fi_ack_leak", 3, 1, 0, "fault injection (§4.1): the coupler ignores ACK interdependence and passes its own nodes' ACK; taken at every write"),
            f("fi_no_twin", 4, 1, 0, "fault injection (§9.6): the coupler takes the twin's contribution as recessive; taken at every write"),
            cfg("ack_interdep", 8, 1, 1, "ACK interdependence (ReCANcentrate paper section 4)"),
            cfg("nrap_on", 9, 1, 1, "Network Reconfiguration Agreement Protocol (§9; 0: the hub decouples after decouple_bits, §7)"),
        ],
    },
    Register {
        name: "BTR",
        index: BTR,
        access: Access::Rw,
        desc: "Bit timing (fields carry value - 1, as the DRCC's BTR); writable only in reset mode",
        fields: &[
            cfg("brp", 0, 6, 0, "BRP[5:0]: time quantum = BRP + 1 clocks, BRP = {brp_ext, brp} (0..1023)"),
            cfg("tseg1", 6, 4, 4, "TSEG1 = tseg1 + 1 quanta"),
            cfg("tseg2", 10, 3, 1, "TSEG2 = tseg2 + 1 quanta"),
            cfg("sjw", 13, 2, 0, "SJW = sjw + 1 quanta"),
            cfg("brp_ext", 24, 4, 0, "BRP[9:6], the prescaler's high bits (0 for BRP 0..63: the 6-bit layout reads the same)"),
        ],
    },
    Register {
        name: "GUARD_CFG",
        index: GUARD_CFG,
        access: Access::Rw,
        desc: "Port guard thresholds; writable only in reset mode",
        fields: &[
            cfg("sd_run_up", 0, 6, 14, "dominant bits that isolate a node port (writes below 14 store 14)"),
            cfg("sd_run_sub", 8, 6, 28, "dominant bits that isolate an incoming sublink (writes below 14 store 14; the default covers a faulty node port's run joined to 12 legal dominant bits before its own hub isolates it)"),
            cfg("sr_frames", 16, 4, 8, "consecutive silent frames that isolate a port (0 = silence rule off)"),
        ],
    },
    Register {
        name: "BF_CFG",
        index: BF_CFG,
        access: Access::Rw,
        desc: "Bit-flipping limits; writable only in reset mode",
        fields: &[
            cfg("bf_up", 0, 8, 32, "port error counter limit of a node port (writes below 8 store 8)"),
            cfg("bf_sub", 8, 8, 64, "port error counter limit of a sublink (writes below 8 store 8)"),
        ],
    },
    Register {
        name: "RESTORE_CFG",
        index: RESTORE_CFG,
        access: Access::Rw,
        desc: "Restoration and decoupling times in bit times; writable only in reset mode",
        fields: &[
            cfg("restore_bits", 0, 16, 1408, "symptom-free bit times before an isolated port is restored (0 = never)"),
            cfg("decouple_bits", 16, 16, 4096, "bit times without an enabled sublink before definitive decoupling, with NRAP off (0 = never)"),
        ],
    },
    Register {
        name: "STATUS",
        index: STATUS,
        access: Access::Ro,
        desc: "Status",
        fields: &[
            f("reset_mode", 0, 1, 1, "CTRL.reset_mode"),
            f("decoupled", 1, 1, 0, "the hub is decoupled (§7)"),
            f("ack_window", 2, 1, 0, "the tracker is in the ACK slot or delimiter"),
            f("trk", 4, 2, 0, "frame tracker state").coded(TrackerState::ENCODING),
            f("enabled", 16, 16, (1 << (N + M)) - 1, "enabled ports: bit p = port p (bits from N + M read 0)"),
        ],
    },
    Register {
        name: "INT_STATUS",
        index: INT_STATUS,
        access: Access::W1c,
        desc: "Interrupt status; write 1 to clear (an event at the same edge wins)",
        fields: INT_FIELDS,
    },
    Register {
        name: "INT_ENABLE",
        index: INT_ENABLE,
        access: Access::Rw,
        desc: "Interrupt enable: irq = |(INT_STATUS & INT_ENABLE), registered",
        fields: INT_FIELDS,
    },
    Register {
        name: "STATS",
        index: STATS,
        access: Access::Ro,
        desc: "Tracker statistics (saturating)",
        fields: &[
            f("frames", 0, 16, 0, "frames tracked to their ACK slot"),
            f("errors", 16, 16, 0, "tracker errors (stuff and CRC delimiter form)"),
        ],
    },
    Register {
        name: "ACK_UNIT",
        index: ACK_UNIT,
        access: Access::Ro,
        desc: "ACK unit (§4.1, the bus guardian of ACK interdependence)",
        fields: &[
            f("blocks", 0, 16, 0, "ACK windows in which the unit turned a dominant downlink bit recessive (saturating, cleared by rst only)"),
            f("u_window", 16, 1, 0, "the unit's own tracker is in the ACK slot or delimiter"),
        ],
    },
    Register {
        name: "NRAP_CFG",
        index: NRAP_CFG,
        access: Access::Rw,
        desc: "NRAP force time, pair and frame counts (§9.5); writable only in reset mode",
        fields: &[
            cfg("force_bits", 0, 10, 64, "bit times the own contribution is forced dominant in SRP_FORCE and DDSP_FORCE (writes below 64 store 64; 320 forces a transmitting node bus-off, as the seed does)"),
            cfg("srp_pairs", 12, 4, 2, "pairs (hub A's then hub B's identification frame, both acknowledged) that end SRP_EXCHANGE (0 stores 1)"),
            cfg("nrp_pairs", 16, 4, 2, "pairs that end NRP in RUN (0 stores 1)"),
            cfg("ddsp_frames", 20, 4, 8, "own identification frames that end DDSP_SEND (0 stores 1)"),
        ],
    },
    Register {
        name: "NRAP_TIME",
        index: NRAP_TIME,
        access: Access::Rw,
        desc: "NRAP time-outs in bit times (§9.5); writable only in reset mode",
        fields: &[
            cfg("srp_bits", 0, 16, 1024, "SRP_EXCHANGE time-out: then DDSP_FORCE (writes below 256 store 256)"),
            cfg("nrp_bits", 16, 16, 1024, "NRP time-out: then DDSP_FORCE (writes below 256 store 256)"),
        ],
    },
    Register {
        name: "NRAP_DDSP",
        index: NRAP_DDSP,
        access: Access::Rw,
        desc: "NRAP definitive decoupling time-out in bit times, blocked-network trigger (§9.5); writable only in reset mode",
        fields: &[
            cfg("ddsp_bits", 0, 16, 1024, "DDSP_SEND time-out: then SPLIT (writes below 256 store 256)"),
            cfg("block_frames", 16, 5, 16, "frames in a row with an error flag at their ACK delimiter that start NRAP from RUN (0 = off; writes 1..3 store 4)"),
        ],
    },
    Register {
        name: "NRAP_STATUS",
        index: NRAP_STATUS,
        access: Access::Ro,
        desc: "NRAP state (§9.2)",
        fields: &[
            f("nrap", 0, 3, 0, "phase").coded(NrapPhase::ENCODING),
            f("outcome", 3, 1, 0, "1: the last NRAP ended in RUN, 0: in SPLIT, by a rule or by a command that ended an active phase (cleared by rst only)"),
            f("runs", 4, 4, 0, "NRAP runs started (saturating, cleared by rst only)"),
            f("ncnt", 8, 4, 0, "pairs (SRP_EXCHANGE, NRP) or own frames (DDSP_SEND) counted in this phase"),
            f("last", 12, 2, 0, "whose identification frame reached its ACK slot last").coded(NrapLast::ENCODING),
            f("half", 14, 1, 0, "hub A's frame of a pair was acknowledged, hub B's is awaited"),
            f("nt", 16, 16, 0, "SAMPLE edges in this phase (saturating)"),
        ],
    },
    Register {
        name: "PORT0",
        index: PORT0,
        access: Access::Ro,
        desc: "Port p's guard, repeated: `PORT_p` at index 16 + p for p < N + M (node ports first, then the sublinks)",
        fields: &[
            f("enabled", 0, 1, 1, "the port takes part in the coupling"),
            f("kind", 1, 3, 0, "last fault").coded(FaultKind::ENCODING),
            f("pec", 8, 8, 0, "port error counter"),
            f("isolations", 16, 8, 0, "times isolated (saturating)"),
            f("restorations", 24, 8, 0, "times restored (saturating)"),
        ],
    },
];

/// The hub map with its document and header text.
pub static MAP: RegisterMap = RegisterMap {
    title: "Hub register map",
    prefix: "HUB",
    header: "hub_regs.h",
    source: "hdl/src/host/hub_registers.rs",
    intro: "Behaviour: `cosim/src/model/hub_contract.md` §7, §8, §9.\n\n\
        Wishbone B4 classic slave as the DRCC's (`docs/registers.md`): 32-bit words, \
        `wb_adr_i` is the word index, every access takes two clocks (request, ack), \
        unmapped addresses (15 and from 16 + N + M) read 0. A write to a read-only or \
        unmapped address, a cfg field written outside reset mode, a CTRL write that changes \
        `ack_interdep` or `nrap_on` outside reset mode or carries both commands sets \
        `INT_STATUS.illegal`. `INT_STATUS`/`INT_ENABLE` are kept in reset mode.\n\n\
        The hub has N node ports and M interlinks; this page describes the emitted tops, \
        N = 4 and M = 2: hub A (`hub.v`, `ID.hub_id` = 0) and hub B (`hub_b.v`, \
        `ID.hub_id` = 1), whose maps differ only there. `PORT0` stands for the repeated register `PORT_p` at index \
        16 + p (offset 0x40 + 4p), p < N + M.",
    registers: REGISTERS,
    lists: &[],
    defines: &[
        ("ID_VALUE", id_value(0, N, M)),
        ("ID_VALUE_B", id_value(1, N, M)),
        ("PORTS", N + M),
        ("SD_MIN", SD_MIN),
        ("BF_MIN", BF_MIN),
        ("FORCE_MIN", FORCE_MIN),
        ("NRAP_BITS_MIN", NRAP_BITS_MIN),
        ("NRAP_COUNT_MIN", NRAP_COUNT_MIN),
        ("BLOCK_MIN", BLOCK_MIN),
    ],
    sizes: &[],
};

/// The register named `name`.
pub fn register(name: &str) -> Option<&'static Register> {
    MAP.register(name)
}

/// `docs/hub_registers.md`.
pub fn markdown() -> String {
    super::generate::markdown(&MAP)
}

/// `rtl-out/hub_regs.h`.
pub fn c_header() -> String {
    let h = super::generate::c_header(&MAP);
    let port = "/* PORT_p of port p < HUB_PORTS */\n\
                #define HUB_PORT_INDEX(p) (HUB_PORT0_INDEX + (p))\n\
                #define HUB_PORT_OFFSET(p) (HUB_PORT0_OFFSET + 4u * (p))\n\n#endif";
    h.replacen("\n#endif", &format!("\n{port}"), 1)
}
