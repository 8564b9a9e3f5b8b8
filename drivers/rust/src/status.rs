//! Status and statistics registers, decoded (`STATUS`, `CHAN_x_ERR`, `AUX_x`,
//! `STATS0/1`, `TIMES`, `OMISSIONS`, the DMR counters).

use crate::regs::{self, get};

/// One channel's fault confinement and validity (`CHAN_x_ERR`, `AUX_x`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct ChanStatus {
    /// Transmit error counter.
    pub tec: u16,
    /// Receive error counter.
    pub rec: u8,
    /// 0 error active, 1 error passive, 2 bus-off.
    pub err_state: u8,
    /// TEC or REC at or above the warning limit.
    pub err_warning: bool,
    /// Auxiliary FSM state (`regs::AUX_VALID` ...).
    pub aux_state: u8,
    /// `AUX_x` bits [6:2]: causes passive, bus-off, k-failed, stall, warning.
    pub aux_causes: u8,
    /// Failed attempts since the last success.
    pub fail_cnt: u8,
    /// Times judged failed.
    pub failures: u8,
    /// Times recovered.
    pub recoveries: u8,
}

impl ChanStatus {
    /// Decodes `CHAN_x_ERR` and `AUX_x` (both channels share one layout).
    pub fn decode(err: u32, aux: u32) -> ChanStatus {
        let causes = regs::AUX_A_CAUSE_PASSIVE_MASK
            | regs::AUX_A_CAUSE_BUSOFF_MASK
            | regs::AUX_A_CAUSE_KFAIL_MASK
            | regs::AUX_A_CAUSE_STALL_MASK
            | regs::AUX_A_CAUSE_WARNING_MASK;
        ChanStatus {
            tec: get(regs::CHAN_A_ERR_TEC_MASK, regs::CHAN_A_ERR_TEC_SHIFT, err) as u16,
            rec: get(regs::CHAN_A_ERR_REC_MASK, regs::CHAN_A_ERR_REC_SHIFT, err) as u8,
            err_state: get(
                regs::CHAN_A_ERR_ERR_STATE_MASK,
                regs::CHAN_A_ERR_ERR_STATE_SHIFT,
                err,
            ) as u8,
            err_warning: err & regs::CHAN_A_ERR_ERR_WARNING_MASK != 0,
            aux_state: get(regs::AUX_A_STATE_MASK, regs::AUX_A_STATE_SHIFT, aux) as u8,
            aux_causes: get(causes, regs::AUX_A_CAUSE_PASSIVE_SHIFT, aux) as u8,
            fail_cnt: get(regs::AUX_A_FAIL_CNT_MASK, regs::AUX_A_FAIL_CNT_SHIFT, aux) as u8,
            failures: get(regs::AUX_A_FAILURES_MASK, regs::AUX_A_FAILURES_SHIFT, aux) as u8,
            recoveries: get(
                regs::AUX_A_RECOVERIES_MASK,
                regs::AUX_A_RECOVERIES_SHIFT,
                aux,
            ) as u8,
        }
    }
}

/// `STATUS` and both channels, decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Status {
    /// Main FSM state (`regs::STATE_*`).
    pub state: u8,
    /// Channel in use: 0 A, 1 B.
    pub tx_channel: u8,
    /// `CTRL.reset_mode`.
    pub reset_mode: bool,
    /// A transmission is in progress.
    pub tx_going_on: bool,
    /// Frames in TX queue A.
    pub txq_a: u8,
    /// Frames in TX queue B.
    pub txq_b: u8,
    /// Frames in the RX FIFO.
    pub rx_count: u8,
    /// Channel A.
    pub a: ChanStatus,
    /// Channel B.
    pub b: ChanStatus,
}

impl Status {
    /// Decodes `STATUS` with both channels' registers.
    pub fn decode(status: u32, a: ChanStatus, b: ChanStatus) -> Status {
        Status {
            state: get(regs::STATUS_STATE_MASK, regs::STATUS_STATE_SHIFT, status) as u8,
            tx_channel: get(
                regs::STATUS_TX_CHANNEL_MASK,
                regs::STATUS_TX_CHANNEL_SHIFT,
                status,
            ) as u8,
            reset_mode: status & regs::STATUS_RESET_MODE_MASK != 0,
            tx_going_on: status & regs::STATUS_TX_GOING_ON_MASK != 0,
            txq_a: get(
                regs::STATUS_TXQ_A_COUNT_MASK,
                regs::STATUS_TXQ_A_COUNT_SHIFT,
                status,
            ) as u8,
            txq_b: get(
                regs::STATUS_TXQ_B_COUNT_MASK,
                regs::STATUS_TXQ_B_COUNT_SHIFT,
                status,
            ) as u8,
            rx_count: get(
                regs::STATUS_RX_COUNT_MASK,
                regs::STATUS_RX_COUNT_SHIFT,
                status,
            ) as u8,
            a,
            b,
        }
    }
}

/// Statistics (saturating; cleared by `rst` only).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Stats {
    /// Duplicates dropped (`STATS0`).
    pub duplicates: u16,
    /// Frames lost to a full RX FIFO (`STATS0`).
    pub overruns: u16,
    /// Channel switches (`STATS1`).
    pub switches: u16,
    /// Channel recoveries (`STATS1`).
    pub recoveries: u16,
    /// Bit times from the first request to the delivery of the last message (`TIMES`).
    pub last_tx_time: u16,
    /// Bit times from the first request to the failover of the last switch (`TIMES`).
    pub switch_time: u16,
    /// Frames only channel B delivered (`OMISSIONS`).
    pub omissions_a: u16,
    /// Frames only channel A delivered (`OMISSIONS`).
    pub omissions_b: u16,
    /// `DMR_STATUS`, raw (`regs::DMR_STATUS_*` fields).
    pub dmr_status: u32,
    /// `DMR_CS_COUNT`, raw.
    pub dmr_cs_count: u32,
    /// `DMR_RX_STATS`, raw.
    pub dmr_rx_stats: u32,
}

impl Stats {
    /// Decodes `STATS0`, `STATS1`, `TIMES`, `OMISSIONS` and the raw DMR words.
    pub fn decode(s0: u32, s1: u32, times: u32, om: u32, dmr: [u32; 3]) -> Stats {
        Stats {
            duplicates: get(
                regs::STATS0_DUPLICATES_MASK,
                regs::STATS0_DUPLICATES_SHIFT,
                s0,
            ) as u16,
            overruns: get(regs::STATS0_OVERRUNS_MASK, regs::STATS0_OVERRUNS_SHIFT, s0) as u16,
            switches: get(regs::STATS1_SWITCHES_MASK, regs::STATS1_SWITCHES_SHIFT, s1) as u16,
            recoveries: get(
                regs::STATS1_RECOVERIES_MASK,
                regs::STATS1_RECOVERIES_SHIFT,
                s1,
            ) as u16,
            last_tx_time: get(
                regs::TIMES_LAST_TX_TIME_MASK,
                regs::TIMES_LAST_TX_TIME_SHIFT,
                times,
            ) as u16,
            switch_time: get(
                regs::TIMES_SWITCH_TIME_MASK,
                regs::TIMES_SWITCH_TIME_SHIFT,
                times,
            ) as u16,
            omissions_a: get(
                regs::OMISSIONS_OMISSIONS_A_MASK,
                regs::OMISSIONS_OMISSIONS_A_SHIFT,
                om,
            ) as u16,
            omissions_b: get(
                regs::OMISSIONS_OMISSIONS_B_MASK,
                regs::OMISSIONS_OMISSIONS_B_SHIFT,
                om,
            ) as u16,
            dmr_status: dmr[0],
            dmr_cs_count: dmr[1],
            dmr_rx_stats: dmr[2],
        }
    }
}
