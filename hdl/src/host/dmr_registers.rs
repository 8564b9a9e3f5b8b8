//! The DMR registers of the DRCC map (word indices 25..35; DMR contract §2): the
//! CiA 701 configuration, status and mailbox window, as entries of the one table
//! (`super::registers::REGISTERS`). Codes: [`DmrState`], [`DmrCause`].

use super::codes::{DmrCause, DmrState};
use super::map::{cfg, f, Access, Register};
use super::registers as map;

/// Mailboxes of the default generation (`M`, DMR contract §2).
pub const MAILBOXES: u32 = 16;

pub const DMR_CFG_REG: Register = Register {
    name: "DMR_CFG",
    index: map::DMR_CFG,
    access: Access::Rw,
    desc: "DMR timing; writable only in reset mode (timeout 0 is refused)",
    fields: &[
        cfg(
            "timeout",
            0,
            16,
            100,
            "mailbox and connection-service timeout in DMR ticks (0 refused)",
        ),
        cfg(
            "cs_period",
            16,
            16,
            0,
            "DMR ticks between periodic connection-service frames (0 = none)",
        ),
    ],
};

pub const DMR_TIME_REG: Register = Register {
    name: "DMR_TIME",
    index: map::DMR_TIME,
    access: Access::Rw,
    desc: "DMR time base and fault recovery; writable only in reset mode (0 refused)",
    fields: &[
        cfg(
            "tick_bits",
            0,
            16,
            125,
            "nominal bit times per DMR tick (125 = 1 ms at 125 kbit/s)",
        ),
        cfg(
            "recovery_delay",
            16,
            16,
            2000,
            "DMR ticks from the last fault of a line to its recovery (seed: 2 s)",
        ),
    ],
};

pub const DMR_CS_REG: Register = Register {
    name: "DMR_CS",
    index: map::DMR_CS,
    access: Access::Rw,
    desc: "Connection-service identifiers (base format, DLC 0); reset mode only, refused if equal or while a mailbox is enabled",
    fields: &[
        cfg("cs_id_dcl", 0, 11, 0x7EA, "identifier of the connection service on the DCL (channel A)"),
        cfg("cs_id_rcl", 16, 11, 0x7EB, "identifier of the connection service on the RCL (channel B)"),
    ],
};

pub const DMR_STATUS_REG: Register = Register {
    name: "DMR_STATUS",
    index: map::DMR_STATUS,
    access: Access::Ro,
    desc: "DMR state, active CAN line and fault flags (counts cleared by rst only)",
    fields: &[
        f("dmr_state", 0, 2, 0, "DMR state (seed Figure 6)").coded(DmrState::ENCODING),
        f(
            "acl",
            2,
            1,
            0,
            "active CAN line: 0 DCL (channel A), 1 RCL (channel B)",
        ),
        f("dcl_tx_fault", 3, 1, 0, "the DCL cannot transmit"),
        f(
            "dcl_rx_fault",
            4,
            1,
            0,
            "a fault on reception was found on the DCL",
        ),
        f("rcl_tx_fault", 5, 1, 0, "the RCL cannot transmit"),
        f(
            "rcl_rx_fault",
            6,
            1,
            0,
            "a fault on reception was found on the RCL",
        ),
        f("cause", 8, 2, 0, "cause of the last fault set").coded(DmrCause::ENCODING),
        f(
            "cause_line",
            10,
            1,
            0,
            "line of the last fault: 0 DCL, 1 RCL",
        ),
        f(
            "cause_mb",
            12,
            4,
            0,
            "mailbox of the last timeout or deviation fault",
        ),
        f(
            "state_changes",
            16,
            8,
            0,
            "DMR state changes (saturating 255)",
        ),
        f(
            "acl_switches",
            24,
            8,
            0,
            "active-line switches (saturating 255)",
        ),
    ],
};

pub const DMR_CS_COUNT_REG: Register = Register {
    name: "DMR_CS_COUNT",
    index: map::DMR_CS_COUNT,
    access: Access::Ro,
    desc: "Connection-service frames received (saturating 255, cleared by rst only)",
    fields: &[
        f(
            "dcl_good",
            0,
            8,
            0,
            "the DCL's identifier received on the DCL",
        ),
        f(
            "dcl_bad",
            8,
            8,
            0,
            "the RCL's identifier received on the DCL (miswiring)",
        ),
        f(
            "rcl_good",
            16,
            8,
            0,
            "the RCL's identifier received on the RCL",
        ),
        f(
            "rcl_bad",
            24,
            8,
            0,
            "the DCL's identifier received on the RCL (miswiring)",
        ),
    ],
};

pub const DMR_RX_STATS_REG: Register = Register {
    name: "DMR_RX_STATS",
    index: map::DMR_RX_STATS,
    access: Access::Ro,
    desc: "DMR reception statistics (saturating, cleared by rst only)",
    fields: &[
        f(
            "pcl_frames",
            0,
            16,
            0,
            "frames received on the passive CAN line",
        ),
        f(
            "released",
            16,
            8,
            0,
            "waiting PCL frames delivered at an active-line switch",
        ),
        f(
            "expired",
            24,
            8,
            0,
            "PCL frames dropped unseen on the active line",
        ),
    ],
};

pub const MB_SEL_REG: Register = Register {
    name: "MB_SEL",
    index: map::MB_SEL,
    access: Access::Rw,
    desc: "Mailbox addressed by MB_ID, MB_MASK, MB_CFG and MB_STATE (an index >= M is refused)",
    fields: &[f("index", 0, 4, 0, "mailbox index")],
};

pub const MB_ID_REG: Register = Register {
    name: "MB_ID",
    index: map::MB_ID,
    access: Access::Rw,
    desc: "Selected mailbox: identifier and direction; reset mode only (reads 0 outside it)",
    fields: &[
        cfg("id", 0, 29, 0, "identifier (base frame: id[10:0])"),
        cfg("ide", 29, 1, 0, "extended frame"),
        cfg("dir", 30, 1, 0, "0 receive, 1 transmit"),
    ],
};

pub const MB_MASK_REG: Register = Register {
    name: "MB_MASK",
    index: map::MB_MASK,
    access: Access::Rw,
    desc: "Selected mailbox: identifier mask; reset mode only (reads 0 outside it)",
    fields: &[cfg("mask", 0, 29, 0, "a 1 bit must match")],
};

pub const MB_CFG_REG: Register = Register {
    name: "MB_CFG",
    index: map::MB_CFG,
    access: Access::Rw,
    desc: "Selected mailbox: deviation limit and enable; reset mode only (reads 0 outside it)",
    fields: &[
        cfg(
            "limit",
            0,
            7,
            3,
            "deviation limit 1..127 (enable with 0 is refused)",
        ),
        cfg("enable", 31, 1, 0, "the mailbox counts and is evaluated"),
    ],
};

pub const MB_STATE_REG: Register = Register {
    name: "MB_STATE",
    index: map::MB_STATE,
    access: Access::Ro,
    desc: "Selected mailbox: DMR counter and timer (live)",
    fields: &[
        f(
            "counter",
            0,
            8,
            0,
            "transfers on the DCL minus transfers on the RCL (two's complement)",
        ),
        f("timer", 16, 16, 0, "DMR ticks left, 0 = stopped"),
    ],
};
