//! DRCC register map (contract §3): word indices, field positions, reset values and
//! interrupt bits. Written from the contract's table; nothing else lives here.

/// `ID` register value: "DRCC" in ASCII.
pub const ID_VALUE: u32 = 0x4452_4343;

/// `VERSION` register value (§10.1): `major` 1 in [15:8], `minor` 5 in [7:0]
/// (§11.1-§11.5 added registers, §11.6 fields, `CTRL.first_copy` of DMR §8.1,
/// the ECSS registers of §12).
pub const VERSION_VALUE: u32 = 0x0000_0105;

/// Word indices (`wb_adr_i`, byte offset / 4).
pub mod idx {
    pub const ID: u8 = 0;
    pub const CTRL: u8 = 1;
    pub const BTR: u8 = 2;
    pub const RMB_CFG: u8 = 3;
    pub const DEDUP_CFG: u8 = 4;
    pub const STATUS: u8 = 5;
    pub const INT_STATUS: u8 = 6;
    pub const INT_ENABLE: u8 = 7;
    pub const CHAN_A_ERR: u8 = 8;
    pub const CHAN_B_ERR: u8 = 9;
    pub const AUX_A: u8 = 10;
    pub const AUX_B: u8 = 11;
    pub const TX_ID: u8 = 12;
    pub const TX_CTRL: u8 = 13;
    pub const TX_DATA0: u8 = 14;
    pub const TX_DATA1: u8 = 15;
    pub const TX_CMD: u8 = 16;
    pub const RX_ID: u8 = 17;
    pub const RX_CTRL: u8 = 18;
    pub const RX_DATA0: u8 = 19;
    pub const RX_DATA1: u8 = 20;
    pub const RX_CMD: u8 = 21;
    pub const STATS0: u8 = 22;
    pub const STATS1: u8 = 23;
    pub const TIMES: u8 = 24;
    // DMR mode (dmr_contract.md §2.1).
    pub const DMR_CFG: u8 = 25;
    pub const DMR_TIME: u8 = 26;
    pub const DMR_CS: u8 = 27;
    pub const DMR_STATUS: u8 = 28;
    pub const DMR_CS_COUNT: u8 = 29;
    pub const DMR_RX_STATS: u8 = 30;
    pub const MB_SEL: u8 = 31;
    pub const MB_ID: u8 = 32;
    pub const MB_MASK: u8 = 33;
    pub const MB_CFG: u8 = 34;
    pub const MB_STATE: u8 = 35;
    /// Replicated star node: the hubs' decision (§4.5).
    pub const STAR_STATUS: u8 = 36;
    /// Frames only the other channel delivered, per channel (§7).
    pub const OMISSIONS: u8 = 37;
    /// Identification (§10.1): the map's version and the instance's sizes.
    pub const VERSION: u8 = 38;
    pub const SIZES: u8 = 39;
    /// Error and arbitration-lost captures of channel A / B (§10.2).
    pub const CAP_A: u8 = 40;
    pub const CAP_B: u8 = 41;
    /// Acceptance filters (§11.1): identifier / mask pairs 0 and 1.
    pub const FILT_ID0: u8 = 42;
    pub const FILT_MASK0: u8 = 43;
    pub const FILT_ID1: u8 = 44;
    pub const FILT_MASK1: u8 = 45;
    /// The RX FIFO head's timestamp and the present `now` (§11.2).
    pub const RX_TIME: u8 = 46;
    /// Clearing the statistics (§11.4).
    pub const STATS_CLR: u8 = 47;
    /// ECSS bus selection (§12.1).
    pub const ECSS_CFG: u8 = 48;
    pub const ECSS_HB: u8 = 49;
    pub const ECSS_PERIOD: u8 = 50;
    pub const ECSS_STATUS: u8 = 51;
}

/// `CTRL` fields.
pub mod ctrl {
    pub const RESET_MODE: u32 = 1 << 0;
    pub const REDUNDANCY: u32 = 1 << 1;
    pub const POLICY_SHIFT: u32 = 2;
    pub const POLICY_MASK: u32 = 0x3 << POLICY_SHIFT;
    pub const DUAL_TX: u32 = 1 << 4;
    /// Replicated star node (§4.4): the other channel's echo completes a message.
    pub const STAR: u32 = 1 << 5;
    pub const K_SHIFT: u32 = 8;
    pub const K_MASK: u32 = 0xF << K_SHIFT;
    pub const MODE_A_SHIFT: u32 = 12;
    pub const MODE_B_SHIFT: u32 = 14;
    pub const SINGLE_SHOT: u32 = 1 << 16;
    /// DMR mode (dmr_contract.md §2): the third DRCC mode.
    pub const DMR: u32 = 1 << 17;
    /// Manual bus-off recovery (§11.6).
    pub const BUSOFF_MANUAL: u32 = 1 << 18;
    /// DMR mode: first-copy delivery instead of the ACL rule (dmr_contract.md §8.1).
    pub const FIRST_COPY: u32 = 1 << 19;
    /// Every defined bit (reserved bits read 0).
    pub const DEFINED: u32 = 0xF_FF3F;
    /// Every cfg field (all defined bits but `reset_mode`).
    pub const CFG: u32 = DEFINED & !RESET_MODE;
    /// Reset value: reset mode, policy error-passive, k = 1.
    pub const RESET: u32 = RESET_MODE | (1 << POLICY_SHIFT) | (1 << K_SHIFT);
    /// Policy codes.
    pub const POLICY_NONE: u32 = 0;
    pub const POLICY_PASSIVE: u32 = 1;
    pub const POLICY_KFAIL: u32 = 2;
    /// Warning limit (§5): the channel's TEC or REC at or above `ewl`.
    pub const POLICY_WARNING: u32 = 3;
}

/// `BTR` fields (value - 1 encodings as the channel ports, §C.6).
pub mod btr {
    /// BRP[5:0].
    pub const BRP_MASK: u32 = 0x3F;
    /// `brp_ext` [27:24] is BRP[9:6].
    pub const BRP_EXT_SHIFT: u32 = 24;
    pub const TSEG1_SHIFT: u32 = 6;
    pub const TSEG2_SHIFT: u32 = 10;
    pub const SJW_SHIFT: u32 = 13;
    pub const TRIPLE: u32 = 1 << 15;
    pub const EWL_SHIFT: u32 = 16;
    pub const DEFINED: u32 = 0x0FFF_FFFF;

    /// The prescaler BRP of a `BTR` value: `{brp_ext, brp}`, 0..1023.
    pub fn brp(btr: u32) -> u16 {
        ((btr & BRP_MASK) | ((btr >> BRP_EXT_SHIFT) & 0xF) << 6) as u16
    }
    /// Reset value: brp 0, tseg1 4 (5 tq), tseg2 1 (2 tq), sjw 0 (1 tq), ewl 96.
    pub const RESET: u32 = (4 << TSEG1_SHIFT) | (1 << TSEG2_SHIFT) | (96 << EWL_SHIFT);
}

/// `RMB_CFG`: [15:0] recovery_bits, [31:16] stall_limit.
pub mod rmb {
    pub const RESET: u32 = 1024;
}

/// `DEDUP_CFG`: [14:0] window.
pub mod dedup {
    pub const WINDOW_MASK: u32 = 0x7FFF;
    pub const RESET: u32 = 1024;
}

/// `INT_STATUS` / `INT_ENABLE` bits.
pub mod int {
    pub const RX: u32 = 1 << 0;
    pub const TX_DONE: u32 = 1 << 1;
    pub const SWITCH: u32 = 1 << 2;
    pub const ERR_STATE: u32 = 1 << 3;
    pub const OVERRUN: u32 = 1 << 4;
    pub const TX_FAILURE: u32 = 1 << 5;
    pub const ILLEGAL: u32 = 1 << 6;
    pub const AUX: u32 = 1 << 7;
    /// DMR state or ACL changed (dmr_contract.md §2.1).
    pub const DMR: u32 = 1 << 8;
    /// The hubs' decision changed (§4.5).
    pub const DOMAIN: u32 = 1 << 9;
    /// Either channel's `err_warning` changed, either direction (§10.2).
    pub const ERR_WARNING: u32 = 1 << 10;
    /// Either channel lost arbitration (§10.2); writing it re-arms `alc`.
    pub const ARB_LOST: u32 = 1 << 11;
    /// Either channel raised `err_valid` (§10.2); writing it re-arms the error
    /// capture.
    pub const BUS_ERROR: u32 = 1 << 12;
    /// Per-channel transmit events (§11.3): the channel's `tx_done` / `tx_failed`.
    pub const TX_DONE_A: u32 = 1 << 13;
    pub const TX_DONE_B: u32 = 1 << 14;
    pub const TX_FAILURE_A: u32 = 1 << 15;
    pub const TX_FAILURE_B: u32 = 1 << 16;
    /// The ECSS bus selection toggled or gave up (`no_master` rose, §12).
    pub const BUS_TOGGLE: u32 = 1 << 17;
    /// The 18 bits of `INT_STATUS` / `INT_ENABLE` (§12).
    pub const ALL: u32 = 0x3_FFFF;
}

/// ECSS registers (§12.1): fields and reset values.
pub mod ecss {
    /// `ECSS_CFG`: [7:0] ttoggle [3], [15:8] ntoggle [3], [24] bdefault [0],
    /// [31] enable [0]; [23:16] and [30:25] reserved.
    pub const TTOGGLE_MASK: u32 = 0xFF;
    pub const NTOGGLE_SHIFT: u32 = 8;
    pub const BDEFAULT: u32 = 1 << 24;
    pub const ENABLE: u32 = 1 << 31;
    pub const CFG_RESERVED: u32 = 0x7E00_0000 | 0x00FF_0000;
    pub const CFG_RESET: u32 = 3 | 3 << NTOGGLE_SHIFT;
    /// `ECSS_HB`: [28:0] id [0x701], [29] ide [0]; [31:30] reserved.
    pub const HB_IDE: u32 = 1 << 29;
    pub const HB_RESERVED: u32 = 0xC000_0000;
    pub const HB_RESET: u32 = 0x701;
    /// `ECSS_PERIOD`: [23:0] period [100000]; [31:24] reserved.
    pub const PERIOD_MASK: u32 = 0x00FF_FFFF;
    pub const PERIOD_RESET: u32 = 100_000;
    /// `ECSS_STATUS`: [7:0] ctoggle, [8] bus, [9] no_master, [23:16] missed.
    pub const BUS: u32 = 1 << 8;
    pub const NO_MASTER: u32 = 1 << 9;
    pub const MISSED_SHIFT: u32 = 16;
}

/// `SIZES` fields (§10.1): the generation parameters of §1.1.
pub mod sizes {
    pub const RX_FIFO_DEPTH_SHIFT: u32 = 0;
    pub const TX_QUEUE_DEPTH_SHIFT: u32 = 8;
    pub const HISTORY_SHIFT: u32 = 16;
    pub const MAILBOXES_SHIFT: u32 = 24;
    /// `CTRL.dmr` can be set.
    pub const DMR: u32 = 1 << 29;
    /// `CTRL.star` can be set.
    pub const STAR: u32 = 1 << 30;
}

/// `CAP_A` / `CAP_B` fields (§10.2; codes of the channel's §C.9).
pub mod cap {
    pub const ERR_KIND_MASK: u32 = 0x7;
    pub const ERR_FIELD_SHIFT: u32 = 3;
    pub const ERR_FIELD_MASK: u32 = 0x1F;
    pub const ERR_TX: u32 = 1 << 8;
    pub const ERR_VALID: u32 = 1 << 9;
    pub const ALC_SHIFT: u32 = 16;
    pub const ALC_MASK: u32 = 0x1F;
    pub const ALC_VALID: u32 = 1 << 21;
}

/// `FILT_IDk` / `FILT_MASKk` fields (§11.1): the `TX_ID` layout; the mask adds
/// `enable`.
pub mod filt {
    /// The frame word `{rtr, ide, id}`: [28:0] id, [29] ide, [30] rtr.
    pub const WORD: u32 = 0x7FFF_FFFF;
    pub const ENABLE: u32 = 1 << 31;
}

/// `TX_ID` / `RX_ID` fields.
pub mod frame_id {
    pub const ID_MASK: u32 = 0x1FFF_FFFF;
    pub const IDE: u32 = 1 << 29;
    pub const RTR: u32 = 1 << 30;
    pub const NOT_EMPTY: u32 = 1 << 31;
}

/// `TX_CTRL` / `RX_CTRL` fields.
pub mod frame_ctrl {
    pub const DLC_MASK: u32 = 0xF;
    /// TX: queue select; RX: channel the frame came from.
    pub const QUEUE: u32 = 1 << 8;
    pub const DEFINED: u32 = DLC_MASK | QUEUE;
}

/// `TX_CMD` fields (write only).
pub mod tx_cmd {
    /// Append the staged frame to a TX queue (§6).
    pub const PUSH: u32 = 1 << 0;
    /// Drop queue A's / B's frames not yet in a channel (§11.5).
    pub const ABORT_A: u32 = 1 << 1;
    pub const ABORT_B: u32 = 1 << 2;
    /// Let a bus-off channel A / B held by `CTRL.busoff_manual` recover (§11.6).
    pub const RECOVER_A: u32 = 1 << 3;
    pub const RECOVER_B: u32 = 1 << 4;
}

/// Main FSM state encoding (Table 1).
pub mod state {
    pub const IDLE1: u8 = 0;
    pub const WAIT1: u8 = 1;
    pub const CH1: u8 = 2;
    pub const ABORT1: u8 = 3;
    pub const WAIT2: u8 = 4;
    pub const IDLE2: u8 = 5;
    pub const WAIT3: u8 = 6;
    pub const CH2: u8 = 7;
    pub const ABORT2: u8 = 8;
    pub const WAIT4: u8 = 9;
}

/// Auxiliary FSM state encoding (§5).
pub mod aux {
    pub const VALID: u8 = 0;
    pub const FAILED: u8 = 1;
    pub const RESTART: u8 = 2;
    pub const PROBATION: u8 = 3;
    /// Cause bits as they sit in AUX_x[5:2], shifted down by 2.
    pub const CAUSE_PASSIVE: u8 = 1 << 0;
    pub const CAUSE_BUSOFF: u8 = 1 << 1;
    pub const CAUSE_KFAIL: u8 = 1 << 2;
    pub const CAUSE_STALL: u8 = 1 << 3;
    pub const CAUSE_WARNING: u8 = 1 << 4;
}

/// DMR registers (dmr_contract.md §2.1): fields and reset values.
pub mod dmr {
    /// `DMR_CFG`: [15:0] timeout [100], [31:16] cs_period [0].
    pub const CFG_RESET: u32 = 100;
    /// `DMR_TIME`: [15:0] tick_bits [125], [31:16] recovery_delay [2000].
    pub const TIME_RESET: u32 = 125 | 2000 << 16;
    /// `DMR_CS`: [10:0] cs_id_dcl [0x7EA], [26:16] cs_id_rcl [0x7EB].
    pub const CS_RESET: u32 = 0x7EA | 0x7EB << 16;
    pub const CS_DEFINED: u32 = 0x07FF_07FF;
    /// `MB_ID`: [28:0] id, [29] ide, [30] dir.
    pub const MB_ID_DEFINED: u32 = 0x7FFF_FFFF;
    pub const MB_IDE: u32 = 1 << 29;
    pub const MB_DIR: u32 = 1 << 30;
    /// `MB_CFG`: [6:0] limit [3], [31] enable [0].
    pub const MB_LIMIT_MASK: u32 = 0x7F;
    pub const MB_ENABLE: u32 = 1 << 31;
    pub const LIMIT_RESET: u8 = 3;
    /// `dmr_state` encoding (§1).
    pub const ACTIVE: u8 = 0;
    pub const PASSIVE: u8 = 1;
    pub const DISABLED: u8 = 2;
    pub const DISCONNECTED: u8 = 3;
    /// `DMR_STATUS.cause` encoding.
    pub const CAUSE_TIMEOUT: u8 = 0;
    pub const CAUSE_DEVIATION: u8 = 1;
    pub const CAUSE_BUSOFF: u8 = 2;
    pub const CAUSE_CS_FAILED: u8 = 3;
    /// Default number of mailboxes (generation parameter `M`).
    pub const M_DEFAULT: usize = 16;
}
