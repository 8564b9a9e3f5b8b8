//! What [`crate::Drcc::configure`] writes: operating mode, channel modes,
//! switch policy, bit timing, redundancy and DMR parameters.

use crate::regs;
use crate::timing::BitTiming;

/// Operating mode (`CTRL.redundancy`, `CTRL.dmr`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Mode {
    /// Two independent controllers, one TX queue per channel.
    #[default]
    Normal,
    /// One logical controller on a redundant channel pair (the paper's RMB).
    Redundancy,
    /// CiA 701 DMR (a generation option: `drcc_small` refuses it).
    Dmr,
}

/// Channel failure policy in redundancy mode (`CTRL.policy`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Policy {
    /// Never leave channel A.
    None,
    /// Leave a channel when it turns error passive (the paper's policy).
    #[default]
    ErrorPassive,
    /// Leave a channel after `k` failed attempts.
    KFailed,
    /// Leave a channel when its TEC or REC reaches the warning limit.
    Warning,
}

impl Policy {
    pub(crate) fn code(self) -> u32 {
        match self {
            Policy::None => regs::CTRL_POLICY_NONE,
            Policy::ErrorPassive => regs::CTRL_POLICY_ERROR_PASSIVE,
            Policy::KFailed => regs::CTRL_POLICY_K_FAILED,
            Policy::Warning => regs::CTRL_POLICY_WARNING,
        }
    }
}

/// Channel mode (`CTRL.mode_a`, `CTRL.mode_b`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ChanMode {
    /// ISO 11898-1 operation.
    #[default]
    Normal,
    /// Receive only, never drive dominant.
    ListenOnly,
    /// A frame is successful without an acknowledgement.
    SelfTest,
    /// The channel hears its own transmit output only.
    Loopback,
}

impl ChanMode {
    pub(crate) fn code(self) -> u32 {
        match self {
            ChanMode::Normal => regs::CTRL_MODE_A_NORMAL,
            ChanMode::ListenOnly => regs::CTRL_MODE_A_LISTEN_ONLY,
            ChanMode::SelfTest => regs::CTRL_MODE_A_SELF_TEST,
            ChanMode::Loopback => regs::CTRL_MODE_A_LOOPBACK,
        }
    }
}

/// DMR mode parameters (`DMR_CFG`, `DMR_TIME`, `DMR_CS`); written only in DMR mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DmrConfig {
    /// Mailbox and connection-service timeout in DMR ticks (not 0).
    pub timeout: u16,
    /// DMR ticks between periodic connection-service frames (0 = none).
    pub cs_period: u16,
    /// Nominal bit times per DMR tick (not 0).
    pub tick_bits: u16,
    /// DMR ticks from a line's last fault to its recovery (not 0).
    pub recovery_delay: u16,
    /// Connection-service identifier on the DCL (channel A), 11 bits.
    pub cs_id_dcl: u16,
    /// Connection-service identifier on the RCL (channel B), 11 bits, not `cs_id_dcl`.
    pub cs_id_rcl: u16,
    /// `CTRL.first_copy` (map 1.4, [`MINOR_FIRST_COPY`]): deliver the first copy
    /// of each frame from either line instead of the active line's only (DMR
    /// contract §8.1; needs a duplicate window).
    pub first_copy: bool,
}

/// `VERSION.minor` from which `CTRL.first_copy` exists.
pub const MINOR_FIRST_COPY: u8 = 4;

impl Default for DmrConfig {
    /// The registers' reset values.
    fn default() -> Self {
        DmrConfig {
            timeout: regs::get(
                regs::DMR_CFG_TIMEOUT_MASK,
                regs::DMR_CFG_TIMEOUT_SHIFT,
                regs::DMR_CFG_RESET,
            ) as u16,
            cs_period: regs::get(
                regs::DMR_CFG_CS_PERIOD_MASK,
                regs::DMR_CFG_CS_PERIOD_SHIFT,
                regs::DMR_CFG_RESET,
            ) as u16,
            tick_bits: regs::get(
                regs::DMR_TIME_TICK_BITS_MASK,
                regs::DMR_TIME_TICK_BITS_SHIFT,
                regs::DMR_TIME_RESET,
            ) as u16,
            recovery_delay: regs::get(
                regs::DMR_TIME_RECOVERY_DELAY_MASK,
                regs::DMR_TIME_RECOVERY_DELAY_SHIFT,
                regs::DMR_TIME_RESET,
            ) as u16,
            cs_id_dcl: regs::get(
                regs::DMR_CS_CS_ID_DCL_MASK,
                regs::DMR_CS_CS_ID_DCL_SHIFT,
                regs::DMR_CS_RESET,
            ) as u16,
            cs_id_rcl: regs::get(
                regs::DMR_CS_CS_ID_RCL_MASK,
                regs::DMR_CS_CS_ID_RCL_SHIFT,
                regs::DMR_CS_RESET,
            ) as u16,
            first_copy: regs::get(
                regs::CTRL_FIRST_COPY_MASK,
                regs::CTRL_FIRST_COPY_SHIFT,
                regs::CTRL_RESET,
            ) != 0,
        }
    }
}

/// The whole configuration; [`Config::default`] holds the registers' reset values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    /// Bit timing of both channels.
    pub timing: BitTiming,
    /// Error warning limit (`BTR.ewl`).
    pub ewl: u8,
    /// Operating mode.
    pub mode: Mode,
    /// Switch policy (redundancy mode).
    pub policy: Policy,
    /// Failed attempts for [`Policy::KFailed`], 1..=15 (0 is taken as 1).
    pub k: u8,
    /// Redundancy mode: every message on A, then its copy on B.
    pub dual_tx: bool,
    /// Redundancy mode: replicated star node (a generation option).
    pub star: bool,
    /// Channel A mode.
    pub mode_a: ChanMode,
    /// Channel B mode.
    pub mode_b: ChanMode,
    /// No automatic retransmission (normal mode).
    pub single_shot: bool,
    /// `CTRL.busoff_manual` (every mode, map 1.3): a channel that goes bus-off
    /// stays bus-off until [`crate::Drcc::recover`] allows its recovery.
    /// `false`: automatic recovery after 128 x 11 recessive bits (ISO
    /// 11898-1). `true` on an instance older than 1.3: [`crate::Drcc::configure`]
    /// returns [`crate::Error::Unsupported`] and writes nothing.
    pub busoff_manual: bool,
    /// Error-free bit times before a failed channel is valid again.
    pub recovery_bits: u16,
    /// Bit times a message may stay pending before its channel is judged failed (0 = off).
    pub stall_limit: u16,
    /// Duplicate-removal window in bit times, 0..=32767 (0 = off).
    pub dedup_window: u16,
    /// `INT_ENABLE` bits (`regs::INT_ENABLE_*_MASK`).
    pub int_enable: u32,
    /// Frames per TX queue: 0 takes `SIZES.tx_queue_depth` (read by
    /// [`crate::Drcc::new`]); any other value must equal it.
    pub tx_queue_depth: u8,
    /// DMR parameters (written in [`Mode::Dmr`] only).
    pub dmr: DmrConfig,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            timing: BitTiming::RESET,
            ewl: regs::get(regs::BTR_EWL_MASK, regs::BTR_EWL_SHIFT, regs::BTR_RESET) as u8,
            mode: Mode::Normal,
            policy: Policy::ErrorPassive,
            k: 1,
            dual_tx: false,
            star: false,
            mode_a: ChanMode::Normal,
            mode_b: ChanMode::Normal,
            single_shot: false,
            busoff_manual: false,
            recovery_bits: regs::get(
                regs::RMB_CFG_RECOVERY_BITS_MASK,
                regs::RMB_CFG_RECOVERY_BITS_SHIFT,
                regs::RMB_CFG_RESET,
            ) as u16,
            stall_limit: 0,
            dedup_window: regs::get(
                regs::DEDUP_CFG_WINDOW_MASK,
                regs::DEDUP_CFG_WINDOW_SHIFT,
                regs::DEDUP_CFG_RESET,
            ) as u16,
            int_enable: 0,
            tx_queue_depth: 0,
            dmr: DmrConfig::default(),
        }
    }
}
