//! The hub register map (hub contract §7, §8; Wishbone conventions of the DRCC
//! contract §D.2): the one source of truth, in the form of the DRCC's
//! (`super::map`). The hub's register block (`crate::hub::registers`) decodes
//! with the indices below and takes its field positions from the table;
//! `markdown()` generates `docs/hub_registers.md` and `c_header()`
//! `rtl-out/hub_regs.h` (written by `drcc generate`).
//!
//! The hub has N node ports and M interlinks (P = N + M ports). The table
//! describes the emitted top (N = 4, M = 2): `ID` carries N and M, `STATUS.enabled`
//! has one bit per port, and `PORT_p` is one register repeated at `PORT0 + p`.

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
/// `PORT_p` is at word index `PORT0 + p` (p < N + M).
pub const PORT0: u32 = 16;

/// `ID` without the shape: "HU" in the two upper bytes.
pub const ID_BASE: u32 = 0x4855_0000;

/// The `ID` value of a hub with `n` node ports and `m` interlinks.
pub const fn id_value(n: u32, m: u32) -> u32 {
    ID_BASE | (n << 8) | m
}

/// Smallest stored stuck-dominant threshold (`GUARD_CFG.sd_run_*` writes below
/// it are clamped, contract §8).
pub const SD_MIN: u32 = 14;
/// Smallest stored port error counter limit (`BF_CFG.bf_*`, contract §8).
pub const BF_MIN: u32 = 8;

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
];

/// The register map, in index order (`PORT0` stands for the block `PORT_p`).
pub const REGISTERS: &[Register] = &[
    Register {
        name: "ID",
        index: ID,
        access: Access::Ro,
        desc: "Identification: \"HU\", N, M",
        fields: &[
            f("m", 0, 8, M, "interlinks M"),
            f("n", 8, 8, N, "node ports N"),
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
            cmd("force_decouple", 1, "decouple now"),
            cmd("recouple", 2, "recouple and enable every sublink; both commands in one write are refused"),
            f("fi_ack_leak", 3, 1, 0, "fault injection (§4.1): the coupler ignores ACK interdependence and passes its own nodes' ACK; taken at every write"),
            cfg("ack_interdep", 8, 1, 1, "ACK interdependence (ReCANcentrate paper section 4)"),
        ],
    },
    Register {
        name: "BTR",
        index: BTR,
        access: Access::Rw,
        desc: "Bit timing (fields carry value - 1, as the DRCC's BTR); writable only in reset mode",
        fields: &[
            cfg("brp", 0, 6, 0, "time quantum = brp + 1 clocks"),
            cfg("tseg1", 6, 4, 4, "TSEG1 = tseg1 + 1 quanta"),
            cfg("tseg2", 10, 3, 1, "TSEG2 = tseg2 + 1 quanta"),
            cfg("sjw", 13, 2, 0, "SJW = sjw + 1 quanta"),
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
            cfg("decouple_bits", 16, 16, 4096, "bit times without an enabled sublink before definitive decoupling (0 = never)"),
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
    intro: "Behaviour: `cosim/src/model/hub_contract.md` §7, §8.\n\n\
        Wishbone B4 classic slave as the DRCC's (`docs/registers.md`): 32-bit words, \
        `wb_adr_i` is the word index, every access takes two clocks (request, ack), \
        unmapped addresses (11..15 and from 16 + N + M) read 0. A write to a read-only or \
        unmapped address, a cfg field written outside reset mode, a CTRL write that changes \
        `ack_interdep` outside reset mode or carries both commands sets \
        `INT_STATUS.illegal`. `INT_STATUS`/`INT_ENABLE` are kept in reset mode.\n\n\
        The hub has N node ports and M interlinks; this page describes the emitted top, \
        N = 4 and M = 2. `PORT0` stands for the repeated register `PORT_p` at index \
        16 + p (offset 0x40 + 4p), p < N + M.",
    registers: REGISTERS,
    lists: &[],
    defines: &[
        ("ID_VALUE", id_value(N, M)),
        ("PORTS", N + M),
        ("SD_MIN", SD_MIN),
        ("BF_MIN", BF_MIN),
    ],
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_is_consistent() {
        MAP.check().unwrap();
        for w in REGISTERS.windows(2) {
            assert!(w[0].index < w[1].index, "{} is out of order", w[1].name);
        }
        // reset values of contract §8
        assert_eq!(register("ID").unwrap().reset_value(), 0x4855_0402);
        assert_eq!(register("BTR").unwrap().reset_value(), (4 << 6) | (1 << 10));
        assert_eq!(
            register("GUARD_CFG").unwrap().reset_value(),
            14 | (28 << 8) | (8 << 16)
        );
        assert_eq!(register("BF_CFG").unwrap().reset_value(), 32 | (64 << 8));
        assert_eq!(
            register("RESTORE_CFG").unwrap().reset_value(),
            1408 | (4096 << 16)
        );
        assert_eq!(register("CTRL").unwrap().reset_value(), 0x101);
        let h = c_header();
        assert!(h.contains("#define HUB_PORT0_OFFSET 0x40u"));
        assert!(h.contains("#define HUB_PORT_OFFSET(p)"));
        assert!(h.contains("#define HUB_STATUS_TRK_ACK_SLOT 2u"));
        assert!(h.trim_end().ends_with("#endif /* HUB_REGS_H */"));
        assert!(markdown().contains("| 16 | 0x40 | [`PORT0`]"));
    }
}
