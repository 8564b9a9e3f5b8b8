//! The ECSS bus-selection registers of the DRCC map (word indices 48..51; DRCC
//! contract §12): `Bdefault`, `Ttoggle`, `Ntoggle` and `Ctoggle` of
//! ECSS-E-ST-50-15C's redundancy object, the master's heartbeat and its period,
//! as entries of the one table (`super::registers::REGISTERS`).

use super::map::{cfg, f, Access, Register};
use super::registers as map;

pub const ECSS_CFG_REG: Register = Register {
    name: "ECSS_CFG",
    index: map::ECSS_CFG,
    access: Access::Rw,
    desc: "ECSS bus selection (contract §12); writable only in reset mode; ttoggle 0 or a reserved bit set is refused",
    fields: &[
        cfg("ttoggle", 0, 8, 3, "heartbeat periods without a heartbeat before a toggle (Ttoggle, 1..255; 0 refused)"),
        cfg("ntoggle", 8, 8, 3, "toggles in a row without a heartbeat (Ntoggle, 0..255; 0 = never toggle)"),
        cfg("bdefault", 24, 1, 0, "the bus used on leaving reset mode (Bdefault): 0 A, 1 B"),
        cfg("enable", 31, 1, 0, "redundancy mode: the channel in use follows the master's heartbeat"),
    ],
};

pub const ECSS_HB_REG: Register = Register {
    name: "ECSS_HB",
    index: map::ECSS_HB,
    access: Access::Rw,
    desc:
        "The master's heartbeat (contract §12); writable only in reset mode; [31:30] set is refused",
    fields: &[
        cfg(
            "id",
            0,
            29,
            0x701,
            "identifier (base frame: id[10:0]; CANopen: 0x700 + the master's node-ID)",
        ),
        cfg("ide", 29, 1, 0, "extended frame"),
    ],
};

pub const ECSS_PERIOD_REG: Register = Register {
    name: "ECSS_PERIOD",
    index: map::ECSS_PERIOD,
    access: Access::Rw,
    desc: "The master's heartbeat period (contract §12); writable only in reset mode; 0 or [31:24] set is refused",
    fields: &[cfg(
        "period",
        0,
        24,
        100_000,
        "consumer heartbeat time in nominal bit times (1..16777215; 0 refused)",
    )],
};

pub const ECSS_STATUS_REG: Register = Register {
    name: "ECSS_STATUS",
    index: map::ECSS_STATUS,
    access: Access::Ro,
    desc: "ECSS bus selection state (contract §12)",
    fields: &[
        f(
            "ctoggle",
            0,
            8,
            0,
            "toggles (Ctoggle, saturating; cleared by rst and STATS_CLR)",
        ),
        f("bus", 8, 1, 0, "the bus in use: 0 A, 1 B"),
        f(
            "no_master",
            9,
            1,
            0,
            "ntoggle toggles in a row found no heartbeat: the node stays",
        ),
        f(
            "missed",
            16,
            8,
            0,
            "heartbeat periods missed since the last heartbeat or toggle",
        ),
    ],
};
