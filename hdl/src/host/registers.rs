//! The DRCC register map (DRCC contract §3, §4.5, §5, §7, §8, §9): the one source
//! of truth.
//!
//! A constant table ([`MAP`]): every register with its word index, access and
//! fields (bit ranges, reset values, descriptions, named codes). The register
//! block (`super::wishbone`) decodes with the index constants and takes its field
//! positions from the table; the named codes ([`Mode`], [`SwitchPolicy`],
//! [`ChannelMode`], ...) are the ones the RTL, the testbench host and the
//! documents use. `markdown()` generates `docs/registers.md` and `c_header()`
//! `rtl-out/drcc_regs.h` (written by `drcc generate`, checked by
//! `drcc generate --check`).

use super::map::{cfg, cmd, f, CodeList, RegisterMap};
pub use super::map::{Access, Field, Register};
use super::register_fields::{
    AUX_FIELDS, CAP_FIELDS, CHAN_ERR_FIELDS, FILT_ID_FIELDS, FILT_MASK_FIELDS, INT_FIELDS,
};

pub use super::codes::{
    AuxState, ChannelMode, DmrCause, DmrState, ErrState, MainState, Mode, StarLast, SwitchPolicy,
};

// Word indices (the Wishbone decoder uses these).
pub const ID: u32 = 0;
pub const CTRL: u32 = 1;
pub const BTR: u32 = 2;
pub const RMB_CFG: u32 = 3;
pub const DEDUP_CFG: u32 = 4;
pub const STATUS: u32 = 5;
pub const INT_STATUS: u32 = 6;
pub const INT_ENABLE: u32 = 7;
pub const CHAN_A_ERR: u32 = 8;
pub const CHAN_B_ERR: u32 = 9;
pub const AUX_A: u32 = 10;
pub const AUX_B: u32 = 11;
pub const TX_ID: u32 = 12;
pub const TX_CTRL: u32 = 13;
pub const TX_DATA0: u32 = 14;
pub const TX_DATA1: u32 = 15;
pub const TX_CMD: u32 = 16;
pub const RX_ID: u32 = 17;
pub const RX_CTRL: u32 = 18;
pub const RX_DATA0: u32 = 19;
pub const RX_DATA1: u32 = 20;
pub const RX_CMD: u32 = 21;
pub const STATS0: u32 = 22;
pub const STATS1: u32 = 23;
pub const TIMES: u32 = 24;
pub const DMR_CFG: u32 = 25;
pub const DMR_TIME: u32 = 26;
pub const DMR_CS: u32 = 27;
pub const DMR_STATUS: u32 = 28;
pub const DMR_CS_COUNT: u32 = 29;
pub const DMR_RX_STATS: u32 = 30;
pub const MB_SEL: u32 = 31;
pub const MB_ID: u32 = 32;
pub const MB_MASK: u32 = 33;
pub const MB_CFG: u32 = 34;
pub const MB_STATE: u32 = 35;
pub const STAR_STATUS: u32 = 36;
pub const OMISSIONS: u32 = 37;
pub const VERSION: u32 = 38;
pub const SIZES: u32 = 39;
pub const CAP_A: u32 = 40;
pub const CAP_B: u32 = 41;
pub const FILT_ID0: u32 = 42;
pub const FILT_MASK0: u32 = 43;
pub const FILT_ID1: u32 = 44;
pub const FILT_MASK1: u32 = 45;
pub const RX_TIME: u32 = 46;
pub const STATS_CLR: u32 = 47;
pub const ECSS_CFG: u32 = 48;
pub const ECSS_HB: u32 = 49;
pub const ECSS_PERIOD: u32 = 50;
pub const ECSS_STATUS: u32 = 51;

/// The constant read from `ID`: "DRCC" in ASCII.
pub const ID_VALUE: u32 = 0x4452_4343;

/// `VERSION.major` (contract §10.1): changes when a register or field moves or
/// changes its meaning.
pub const VERSION_MAJOR: u32 = 1;
/// `VERSION.minor`: changes when a register or field is added.
pub const VERSION_MINOR: u32 = 5;

/// The register map, in index order.
pub const REGISTERS: &[Register] = &[
    Register {
        name: "ID",
        index: ID,
        access: Access::Ro,
        desc: "Identification constant \"DRCC\"",
        fields: &[f("id", 0, 32, ID_VALUE, "0x44524343")],
    },
    Register {
        name: "CTRL",
        index: CTRL,
        access: Access::Rw,
        desc: "Control; cfg fields are writable only in reset mode",
        fields: &[
            f("reset_mode", 0, 1, 1, "1 = reset mode: channels held in reset, queues and FIFO emptied"),
            cfg("redundancy", 1, 1, 0, "operating mode (redundancy is refused with a listen-only channel)").coded(Mode::ENCODING),
            cfg("policy", 2, 2, 1, "channel failure policy (contract §5)").coded(SwitchPolicy::ENCODING),
            cfg("dual_tx", 4, 1, 0, "redundancy mode: send every message on A, then its copy on B"),
            cfg("star", 5, 1, 0, "redundancy mode: replicated star node, the other channel's echo of an own frame completes it and the hubs' identification frames are followed, not received (DRCC contract §4.4, §4.5)"),
            cfg("k", 8, 4, 1, "failed attempts for the k-failed policy (1..15; 0 is stored as 1)"),
            cfg("mode_a", 12, 2, 0, "channel A mode").coded(ChannelMode::ENCODING),
            cfg("mode_b", 14, 2, 0, "channel B mode").coded(ChannelMode::ENCODING),
            cfg("single_shot", 16, 1, 0, "no automatic retransmission (normal mode only)"),
            cfg("dmr", 17, 1, 0, "CiA 701 DMR mode (DMR contract; refused with redundancy or a listen-only channel)"),
            cfg("busoff_manual", 18, 1, 0, "a bus-off channel starts its recovery only after `TX_CMD.recover_x` (contract §11.6)"),
            cfg("first_copy", 19, 1, 0, "DMR mode: deliver the first copy of a frame from either line instead of the ACL's only (DMR contract §8.1)"),
        ],
    },
    Register {
        name: "BTR",
        index: BTR,
        access: Access::Rw,
        desc: "Bit timing of both channels (fields carry value - 1); writable only in reset mode",
        fields: &[
            cfg("brp", 0, 6, 0, "BRP[5:0]: time quantum = BRP + 1 clocks, BRP = {brp_ext, brp} (0..1023)"),
            cfg("tseg1", 6, 4, 4, "TSEG1 = tseg1 + 1 quanta"),
            cfg("tseg2", 10, 3, 1, "TSEG2 = tseg2 + 1 quanta"),
            cfg("sjw", 13, 2, 0, "SJW = sjw + 1 quanta"),
            cfg("triple", 15, 1, 0, "triple sampling"),
            cfg("ewl", 16, 8, 96, "error warning limit"),
            cfg("brp_ext", 24, 4, 0, "BRP[9:6], the prescaler's high bits (0 for BRP 0..63: the 6-bit layout reads the same)"),
        ],
    },
    Register {
        name: "RMB_CFG",
        index: RMB_CFG,
        access: Access::Rw,
        desc: "Redundancy management; writable only in reset mode",
        fields: &[
            cfg("recovery_bits", 0, 16, 1024, "error-free bit times before a failed channel is valid again (0 = 1)"),
            cfg("stall_limit", 16, 16, 0, "bit times a message may stay pending before the channel is judged failed (0 = off)"),
        ],
    },
    Register {
        name: "DEDUP_CFG",
        index: DEDUP_CFG,
        access: Access::Rw,
        desc: "Duplicate removal (redundancy mode); writable only in reset mode",
        fields: &[cfg("window", 0, 15, 1024, "window in nominal bit times; 0 = duplicate removal off")],
    },
    Register {
        name: "STATUS",
        index: STATUS,
        access: Access::Ro,
        desc: "Status",
        fields: &[
            f("state", 0, 4, 0, "main FSM state (Table 1)").coded(MainState::ENCODING),
            f("tx_channel", 4, 1, 0, "channel in use: 0 A, 1 B"),
            f("aux_a_state", 5, 2, 0, "aux FSM A state").coded(AuxState::ENCODING),
            f("aux_b_state", 7, 2, 0, "aux FSM B state").coded(AuxState::ENCODING),
            f("err_state_a", 9, 2, 0, "channel A error state").coded(ErrState::ENCODING),
            f("err_state_b", 11, 2, 0, "channel B error state").coded(ErrState::ENCODING),
            f("reset_mode", 13, 1, 1, "CTRL.reset_mode"),
            f("tx_going_on", 14, 1, 0, "a transmission is in progress (main FSM not idle)"),
            f("txq_a_count", 16, 4, 0, "TX queue A count (0..TX_QUEUE_DEPTH: 8, drcc_small 4)"),
            f("txq_b_count", 20, 4, 0, "TX queue B count (0..TX_QUEUE_DEPTH)"),
            f("rx_count", 24, 6, 0, "RX FIFO count (0..RX_FIFO_DEPTH: 32, drcc_small 8)"),
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
        name: "CHAN_A_ERR",
        index: CHAN_A_ERR,
        access: Access::Ro,
        desc: "Channel A fault confinement",
        fields: CHAN_ERR_FIELDS,
    },
    Register {
        name: "CHAN_B_ERR",
        index: CHAN_B_ERR,
        access: Access::Ro,
        desc: "Channel B fault confinement",
        fields: CHAN_ERR_FIELDS,
    },
    Register {
        name: "AUX_A",
        index: AUX_A,
        access: Access::Ro,
        desc: "Auxiliary FSM of channel A",
        fields: AUX_FIELDS,
    },
    Register {
        name: "AUX_B",
        index: AUX_B,
        access: Access::Ro,
        desc: "Auxiliary FSM of channel B",
        fields: AUX_FIELDS,
    },
    Register {
        name: "TX_ID",
        index: TX_ID,
        access: Access::Rw,
        desc: "Staged frame: identifier",
        fields: &[
            f("id", 0, 29, 0, "identifier (base frame: id[10:0])"),
            f("ide", 29, 1, 0, "extended frame"),
            f("rtr", 30, 1, 0, "remote frame"),
        ],
    },
    Register {
        name: "TX_CTRL",
        index: TX_CTRL,
        access: Access::Rw,
        desc: "Staged frame: length and queue",
        fields: &[
            f("dlc", 0, 4, 0, "data length code"),
            f("queue", 8, 1, 0, "normal mode: 0 queue A, 1 queue B (ignored in redundancy mode)"),
        ],
    },
    Register {
        name: "TX_DATA0",
        index: TX_DATA0,
        access: Access::Rw,
        desc: "Staged frame: data bytes 0..3 (byte 0 in [7:0])",
        fields: &[f("data", 0, 32, 0, "bytes 0..3")],
    },
    Register {
        name: "TX_DATA1",
        index: TX_DATA1,
        access: Access::Rw,
        desc: "Staged frame: data bytes 4..7 (byte 4 in [7:0])",
        fields: &[f("data", 0, 32, 0, "bytes 4..7")],
    },
    Register {
        name: "TX_CMD",
        index: TX_CMD,
        access: Access::Wo,
        desc: "Transmit command",
        fields: &[
            cmd("push", 0, "append the staged frame to a TX queue (refused in reset mode or when full)"),
            cmd("abort_a", 1, "drop queue A's frames no channel holds; normal mode: abort channel A's frame (contract §11.5; refused with push or in DMR mode)"),
            cmd("abort_b", 2, "the same for queue B (normal mode only)"),
            cmd("recover_a", 3, "with `CTRL.busoff_manual`: bus-off channel A starts its recovery (contract §11.6)"),
            cmd("recover_b", 4, "the same for channel B"),
        ],
    },
    Register {
        name: "RX_ID",
        index: RX_ID,
        access: Access::Ro,
        desc: "Head of the RX FIFO: identifier",
        fields: &[
            f("id", 0, 29, 0, "identifier (valid while `rx_ready`)").not_reset(),
            f("ide", 29, 1, 0, "extended frame (valid while `rx_ready`)").not_reset(),
            f("rtr", 30, 1, 0, "remote frame (valid while `rx_ready`)").not_reset(),
            f("rx_ready", 31, 1, 0, "the head is valid: the RX FIFO was not empty at the previous edge"),
        ],
    },
    Register {
        name: "RX_CTRL",
        index: RX_CTRL,
        access: Access::Ro,
        desc: "Head of the RX FIFO: length and channel",
        fields: &[
            f("dlc", 0, 4, 0, "data length code as received (valid while `RX_ID.rx_ready`)")
                .not_reset(),
            f("channel", 8, 1, 0, "channel the frame came from: 0 A, 1 B (valid while `RX_ID.rx_ready`)")
                .not_reset(),
        ],
    },
    Register {
        name: "RX_DATA0",
        index: RX_DATA0,
        access: Access::Ro,
        desc: "Head of the RX FIFO: data bytes 0..3 (byte 0 in [7:0])",
        fields: &[f("data", 0, 32, 0, "bytes 0..3 (valid while `RX_ID.rx_ready`)").not_reset()],
    },
    Register {
        name: "RX_DATA1",
        index: RX_DATA1,
        access: Access::Ro,
        desc: "Head of the RX FIFO: data bytes 4..7 (byte 4 in [7:0])",
        fields: &[f("data", 0, 32, 0, "bytes 4..7 (valid while `RX_ID.rx_ready`)").not_reset()],
    },
    Register {
        name: "RX_CMD",
        index: RX_CMD,
        access: Access::Wo,
        desc: "Receive command",
        fields: &[cmd("pop", 0, "remove the head of the RX FIFO (refused when empty)")],
    },
    Register {
        name: "STATS0",
        index: STATS0,
        access: Access::Ro,
        desc: "Receive statistics (saturating, cleared by rst only)",
        fields: &[
            f("duplicates", 0, 16, 0, "duplicates dropped"),
            f("overruns", 16, 16, 0, "frames dropped because the RX FIFO was full"),
        ],
    },
    Register {
        name: "STATS1",
        index: STATS1,
        access: Access::Ro,
        desc: "Redundancy statistics (saturating, cleared by rst only)",
        fields: &[
            f("switches", 0, 16, 0, "channel switches"),
            f("recoveries", 16, 16, 0, "channel recoveries (both channels)"),
        ],
    },
    Register {
        name: "TIMES",
        index: TIMES,
        access: Access::Ro,
        desc: "Redundancy timing in nominal bit times (saturating, cleared by rst only)",
        fields: &[
            f("last_tx_time", 0, 16, 0, "bit times from the first request to the delivery of the last message"),
            f("switch_time", 16, 16, 0, "bit times from the first request to the failover of the last switch"),
        ],
    },
    super::dmr_registers::DMR_CFG_REG,
    super::dmr_registers::DMR_TIME_REG,
    super::dmr_registers::DMR_CS_REG,
    super::dmr_registers::DMR_STATUS_REG,
    super::dmr_registers::DMR_CS_COUNT_REG,
    super::dmr_registers::DMR_RX_STATS_REG,
    super::dmr_registers::MB_SEL_REG,
    super::dmr_registers::MB_ID_REG,
    super::dmr_registers::MB_MASK_REG,
    super::dmr_registers::MB_CFG_REG,
    super::dmr_registers::MB_STATE_REG,
    Register {
        name: "STAR_STATUS",
        index: STAR_STATUS,
        access: Access::Ro,
        desc: "Replicated star node: the hubs' decision as their identification frames tell it (contract §4.5); cleared in reset mode",
        fields: &[
            f("split", 0, 1, 0, "the hubs decoupled for good: two of a channel's own hub's frames in a row, none of the other hub's between"),
            f("last_a", 2, 2, 0, "whose identification frame channel A received last").coded(StarLast::ENCODING),
            f("last_b", 4, 2, 0, "whose identification frame channel B received last").coded(StarLast::ENCODING),
            f("hub_frames_a", 8, 8, 0, "identification frames received on channel A (saturating)"),
            f("hub_frames_b", 16, 8, 0, "identification frames received on channel B (saturating)"),
        ],
    },
    Register {
        name: "OMISSIONS",
        index: OMISSIONS,
        access: Access::Ro,
        desc: "Redundancy mode with duplicate removal: frames only one channel delivered within the window (contract §7; saturating, cleared by rst only)",
        fields: &[
            f("omissions_a", 0, 16, 0, "frames only channel B delivered (omissions of channel A)"),
            f("omissions_b", 16, 16, 0, "frames only channel A delivered (omissions of channel B)"),
        ],
    },
    Register {
        name: "VERSION",
        index: VERSION,
        access: Access::Ro,
        desc: "Version of this register map (contract §10.1; 0 on maps before it)",
        fields: &[
            f("minor", 0, 8, VERSION_MINOR, "a register or field was added"),
            f("major", 8, 8, VERSION_MAJOR, "a register or field moved or changed its meaning"),
        ],
    },
    Register {
        name: "SIZES",
        index: SIZES,
        access: Access::Ro,
        desc: "The sizes this instance was built with, Verilog parameters included (contract §1.1, §10.1); reset values are the default top's",
        fields: &[
            f("rx_fifo_depth", 0, 6, 32, "RX FIFO entries (RX_FIFO_DEPTH)"),
            f("tx_queue_depth", 8, 4, 8, "entries of each TX queue (TX_QUEUE_DEPTH)"),
            f("history", 16, 6, 32, "duplicate-removal history entries (HISTORY)"),
            f("mailboxes", 24, 5, 16, "DMR mailboxes (M)"),
            f("dmr", 29, 1, 1, "CTRL.dmr can be set (DMR)"),
            f("star", 30, 1, 1, "CTRL.star can be set (STAR)"),
        ],
    },
    Register {
        name: "CAP_A",
        index: CAP_A,
        access: Access::Ro,
        desc: "Channel A: the first error and the first lost arbitration since their interrupt was acknowledged (contract §10.2; cleared by rst only)",
        fields: CAP_FIELDS,
    },
    Register {
        name: "CAP_B",
        index: CAP_B,
        access: Access::Ro,
        desc: "Channel B: the same as CAP_A",
        fields: CAP_FIELDS,
    },
    Register {
        name: "FILT_ID0",
        index: FILT_ID0,
        access: Access::Rw,
        desc: "Acceptance filter 0: the frame word {rtr, ide, id} to compare (contract §11.1); writable only in reset mode",
        fields: FILT_ID_FIELDS,
    },
    Register {
        name: "FILT_MASK0",
        index: FILT_MASK0,
        access: Access::Rw,
        desc: "Acceptance filter 0: the bits compared and the enable; a frame is accepted if no filter is enabled or an enabled one matches",
        fields: FILT_MASK_FIELDS,
    },
    Register {
        name: "FILT_ID1",
        index: FILT_ID1,
        access: Access::Rw,
        desc: "Acceptance filter 1: as FILT_ID0",
        fields: FILT_ID_FIELDS,
    },
    Register {
        name: "FILT_MASK1",
        index: FILT_MASK1,
        access: Access::Rw,
        desc: "Acceptance filter 1: as FILT_MASK0",
        fields: FILT_MASK_FIELDS,
    },
    Register {
        name: "RX_TIME",
        index: RX_TIME,
        access: Access::Ro,
        desc: "Timestamps (contract §11.2): the RX FIFO head's, and the bit-time counter now",
        fields: &[
            f("rx_time", 0, 16, 0, "now at the edge the head frame was written into the RX FIFO"),
            f("now", 16, 16, 0, "nominal bit times since reset mode was left (wrapping)"),
        ],
    },
    Register {
        name: "STATS_CLR",
        index: STATS_CLR,
        access: Access::Wo,
        desc: "Clears STATS0, STATS1, OMISSIONS, DMR_RX_STATS, ECSS_STATUS.ctoggle and the AUX_x failures and recoveries counts (contract §11.4)",
        fields: &[cmd("clear", 0, "1 = clear the statistics")],
    },
    super::ecss_registers::ECSS_CFG_REG,
    super::ecss_registers::ECSS_HB_REG,
    super::ecss_registers::ECSS_PERIOD_REG,
    super::ecss_registers::ECSS_STATUS_REG,
];

/// Main FSM state encodings (paper Table 1), for the header (`DRCC_STATE_*`).
pub const MAIN_STATES: &[super::map::Encoding] = MainState::ENCODING;

/// Auxiliary FSM state encodings, for the header (`DRCC_AUX_*`).
pub const AUX_STATES: &[super::map::Encoding] = AuxState::ENCODING;

/// The DRCC map with its document and header text.
pub static MAP: RegisterMap = RegisterMap {
    title: "DRCC register map",
    prefix: "DRCC",
    header: "drcc_regs.h",
    source: "hdl/src/host/registers.rs",
    intro: "Behaviour: `cosim/src/model/drcc_contract.md` §2, §3, §8, §9.\n\n\
        Wishbone B4 classic slave, 32-bit words, `wb_adr_i` is the word index (byte offset = \
        4 x index). Every access takes two clocks (request, ack). Unmapped addresses read 0; a \
        write to a read-only or unmapped address, a cfg field written outside reset mode, a \
        CTRL write with redundancy and a listen-only channel (refused as a whole), a refused \
        push or pop sets `INT_STATUS.illegal`. DMR mode (registers 25..35): \
        `cosim/src/model/dmr_contract.md` §2; its illegal configurations are refused the same way. \
        ECSS bus selection (registers 48..51): contract §12.",
    registers: REGISTERS,
    lists: &[
        CodeList {
            name: "STATE",
            desc: "Main FSM states (`STATUS.state`, DRCC paper Table 1)",
            codes: MAIN_STATES,
        },
        CodeList {
            name: "AUX",
            desc: "Auxiliary FSM states (`STATUS.aux_x_state`, `AUX_x.state`)",
            codes: AUX_STATES,
        },
        CodeList {
            name: "DMR",
            desc: "DMR states (`DMR_STATUS.dmr_state`, CiA 701)",
            codes: DmrState::ENCODING,
        },
    ],
    defines: &[("ID_VALUE", ID_VALUE)],
    sizes: &[
        ("RX_FIFO_DEPTH", "SIZES", "rx_fifo_depth"),
        ("TX_QUEUE_DEPTH", "SIZES", "tx_queue_depth"),
        ("HISTORY", "SIZES", "history"),
        ("MAILBOXES", "SIZES", "mailboxes"),
    ],
};

/// The register named `name`.
pub fn register(name: &str) -> Option<&'static Register> {
    MAP.register(name)
}

/// `docs/registers.md`.
pub fn markdown() -> String {
    super::generate::markdown(&MAP)
}

/// `rtl-out/drcc_regs.h`.
pub fn c_header() -> String {
    super::generate::c_header(&MAP)
}
