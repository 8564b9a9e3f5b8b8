//! The field lists that more than one register of the DRCC map shares
//! (`INT_STATUS` and `INT_ENABLE`, `CHAN_A_ERR` and `CHAN_B_ERR`, `CAP_A` and
//! `CAP_B`, `AUX_A` and `AUX_B`, the two acceptance filters): one list each, so the pairs cannot drift
//! (DRCC contract §3, §5, §8, §10, §11). The table is `super::registers`.

use super::codes::{AuxState, ErrState};
use super::map::{cfg, f, Field};

pub(super) const INT_FIELDS: &[Field] = &[
    f("rx", 0, 1, 0, "a frame was written to the RX FIFO"),
    f(
        "tx_done",
        1,
        1,
        0,
        "a message was sent (normal mode: a channel's tx_done; redundancy mode: with tx_success)",
    ),
    f(
        "switch",
        2,
        1,
        0,
        "the main FSM switched channel (failover changed)",
    ),
    f("err_state", 3, 1, 0, "a channel's error state changed"),
    f(
        "overrun",
        4,
        1,
        0,
        "a received frame was dropped because the RX FIFO was full",
    ),
    f(
        "tx_failure",
        5,
        1,
        0,
        "a message failed (normal mode: a channel's tx_failed; redundancy mode: with tx_failure)",
    ),
    f(
        "illegal",
        6,
        1,
        0,
        "an illegal register access was refused (contract §9)",
    ),
    f(
        "aux",
        7,
        1,
        0,
        "an auxiliary FSM judged a channel failed, or recovered it",
    ),
    f(
        "dmr",
        8,
        1,
        0,
        "DMR mode: the DMR state or the active CAN line changed",
    ),
    f(
        "domain",
        9,
        1,
        0,
        "replicated star node: the hubs' decision (STAR_STATUS.split) changed (contract §4.5)",
    ),
    f(
        "err_warning",
        10,
        1,
        0,
        "a channel's err_warning (TEC or REC >= BTR.ewl) changed, either way (contract §10.2)",
    ),
    f(
        "arb_lost",
        11,
        1,
        0,
        "a channel lost arbitration (CAP_x.alc; writing 1 here re-arms its capture)",
    ),
    f(
        "bus_error",
        12,
        1,
        0,
        "a channel detected a bus error (CAP_x.err_*; writing 1 here re-arms its capture)",
    ),
    f(
        "tx_done_a",
        13,
        1,
        0,
        "channel A's tx_done: the frame it sent became valid (contract §11.3)",
    ),
    f("tx_done_b", 14, 1, 0, "channel B's tx_done"),
    f(
        "tx_failure_a",
        15,
        1,
        0,
        "channel A's tx_failed: it dropped the frame it held (single shot, an abort, a refusal)",
    ),
    f("tx_failure_b", 16, 1, 0, "channel B's tx_failed"),
    f(
        "bus_toggle",
        17,
        1,
        0,
        "ECSS bus selection: the node toggled bus, or stopped toggling (contract §12)",
    ),
];

/// `FILT_IDk` (contract §11.1): the `TX_ID` layout.
pub(super) const FILT_ID_FIELDS: &[Field] = &[
    cfg(
        "id",
        0,
        29,
        0,
        "identifier to compare (a base identifier in id[10:0])",
    ),
    cfg("ide", 29, 1, 0, "IDE to compare"),
    cfg("rtr", 30, 1, 0, "RTR to compare"),
];

/// `FILT_MASKk`: a mask bit 1 = that bit of the frame must equal `FILT_IDk`'s.
pub(super) const FILT_MASK_FIELDS: &[Field] = &[
    cfg("id", 0, 29, 0, "identifier bits compared"),
    cfg(
        "ide",
        29,
        1,
        0,
        "compare IDE (set it to tell base from extended frames)",
    ),
    cfg("rtr", 30, 1, 0, "compare RTR"),
    cfg(
        "enable",
        31,
        1,
        0,
        "the filter is in use (no filter enabled: every frame is accepted)",
    ),
];

pub(super) const CHAN_ERR_FIELDS: &[Field] = &[
    f("tec", 0, 9, 0, "transmit error counter"),
    f("rec", 16, 8, 0, "receive error counter"),
    f("err_state", 24, 2, 0, "fault confinement state").coded(ErrState::ENCODING),
    f("err_warning", 26, 1, 0, "TEC or REC >= error warning limit"),
];

pub(super) const CAP_FIELDS: &[Field] = &[
    f(
        "err_kind",
        0,
        3,
        0,
        "kind of the captured error: 0 none, 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK",
    ),
    f(
        "err_field",
        3,
        5,
        0,
        "frame field of the bit in error (the channel's field code, timing contract §4.1)",
    ),
    f("err_tx", 8, 1, 0, "the channel was transmitter at the error"),
    f(
        "err_valid",
        9,
        1,
        0,
        "an error was captured; later errors are not, until INT_STATUS.bus_error is written 1",
    ),
    f(
        "alc",
        16,
        5,
        0,
        "arbitration lost at: base-ID bit i (0 = first) is i, SRR/RTR 11, IDE 12, extension bit j is 13 + j, extended RTR 31",
    ),
    f(
        "alc_valid",
        21,
        1,
        0,
        "a lost arbitration was captured; later ones are not, until INT_STATUS.arb_lost is written 1",
    ),
];

pub(super) const AUX_FIELDS: &[Field] = &[
    f("state", 0, 2, 0, "aux FSM state").coded(AuxState::ENCODING),
    f(
        "cause_passive",
        2,
        1,
        0,
        "judged failed because error passive (latched)",
    ),
    f(
        "cause_busoff",
        3,
        1,
        0,
        "judged failed because bus-off (latched)",
    ),
    f(
        "cause_kfail",
        4,
        1,
        0,
        "judged failed after k failed attempts (latched)",
    ),
    f(
        "cause_stall",
        5,
        1,
        0,
        "judged failed because a message stalled (latched)",
    ),
    f(
        "cause_warning",
        6,
        1,
        0,
        "judged failed because TEC or REC reached the warning limit, policy WARNING (latched)",
    ),
    f(
        "fail_cnt",
        8,
        4,
        0,
        "failed attempts since the last success (saturating 15)",
    ),
    f(
        "failures",
        16,
        8,
        0,
        "times judged failed (saturating 255, cleared by rst only)",
    ),
    f(
        "recoveries",
        24,
        8,
        0,
        "times recovered (saturating 255, cleared by rst only)",
    ),
];
