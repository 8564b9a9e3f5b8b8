//! The DRCC model's register file (DRCC contract §3, DMR contract §2.1): the
//! stored registers and the read side of the Wishbone map. The write side stays
//! in the edge of [`super::DrccModel`], beside the blocks it drives.

use super::regs::*;
use super::DrccModel;
use crate::engine::ChannelOutputs;
use crate::frame::Frame;

/// The register file and the small top-level registers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Regs {
    pub(super) ctrl: u32,
    pub(super) btr: u32,
    pub(super) rmb: u32,
    pub(super) dedup: u32,
    pub(super) int_status: u32,
    pub(super) int_enable: u32,
    pub(super) irq: bool,
    pub(super) wb_ack: bool,
    /// Wishbone `ERR`: the last access was refused (bus_contract.md §1).
    pub(super) wb_err: bool,
    pub(super) wb_dat: u32,
    pub(super) tx_id: u32,
    pub(super) tx_ctrl: u32,
    pub(super) tx_data: [u32; 2],
    /// Nominal bit tick counters (§4.3).
    pub(super) tq_cnt: u16,
    pub(super) bit_cnt: u8,
    /// Channel `err_state` one clock earlier (INT_STATUS.err_state).
    pub(super) err_q: [u8; 2],
    /// Channel `err_warning` one clock earlier (INT_STATUS.err_warning, §10.2).
    pub(super) warn_q: [bool; 2],
    /// `CAP_A`, `CAP_B` (§10.2): cleared by `rst` only.
    pub(super) cap: [Capture; 2],
    /// STATS1[31:16].
    pub(super) recoveries: u16,
    /// `reset_mode` one edge earlier: the channels stay in reset one clock longer
    /// so that they capture the configuration written with the write that leaves
    /// reset mode (contract §6).
    pub(super) reset_mode_q: bool,
}

impl Regs {
    pub(super) fn reset() -> Self {
        Regs {
            ctrl: ctrl::RESET,
            btr: btr::RESET,
            rmb: rmb::RESET,
            dedup: dedup::RESET,
            int_status: 0,
            int_enable: 0,
            irq: false,
            wb_ack: false,
            wb_err: false,
            wb_dat: 0,
            tx_id: 0,
            tx_ctrl: 0,
            tx_data: [0; 2],
            tq_cnt: 0,
            bit_cnt: 0,
            err_q: [0; 2],
            warn_q: [false; 2],
            cap: [Capture::default(); 2],
            recoveries: 0,
            reset_mode_q: true,
        }
    }
    pub(super) fn reset_mode(&self) -> bool {
        self.ctrl & ctrl::RESET_MODE != 0
    }
    pub(super) fn redundancy(&self) -> bool {
        self.ctrl & ctrl::REDUNDANCY != 0
    }
    /// DMR mode (dmr_contract.md §2).
    pub(super) fn dmr(&self) -> bool {
        self.ctrl & ctrl::DMR != 0
    }
    pub(super) fn policy(&self) -> u32 {
        (self.ctrl & ctrl::POLICY_MASK) >> ctrl::POLICY_SHIFT
    }
    pub(super) fn dual_tx(&self) -> bool {
        self.ctrl & ctrl::DUAL_TX != 0
    }
    /// Replicated star node (§4.4).
    pub(super) fn star(&self) -> bool {
        self.ctrl & ctrl::STAR != 0
    }
    pub(super) fn k(&self) -> u8 {
        ((self.ctrl & ctrl::K_MASK) >> ctrl::K_SHIFT) as u8
    }
    pub(super) fn window(&self) -> u16 {
        (self.dedup & dedup::WINDOW_MASK) as u16
    }
    pub(super) fn brp(&self) -> u16 {
        btr::brp(self.btr)
    }
    /// `1 + (tseg1+1) + (tseg2+1)` from the fields as written.
    pub(super) fn tq_per_bit(&self) -> u8 {
        (((self.btr >> btr::TSEG1_SHIFT) & 0xF) + ((self.btr >> btr::TSEG2_SHIFT) & 0x7) + 3) as u8
    }
    /// The frame staged in TX_ID..TX_DATA1, normalized as a push stores it (§6):
    /// as a receiver would deliver it (a base identifier's upper bits, bytes past
    /// min(dlc, 8) and a remote frame's bytes read 0).
    pub(super) fn staged(&self) -> Frame {
        let mut data = [0u8; 8];
        data[..4].copy_from_slice(&self.tx_data[0].to_le_bytes());
        data[4..].copy_from_slice(&self.tx_data[1].to_le_bytes());
        let ide = self.tx_id & frame_id::IDE != 0;
        let rtr = self.tx_id & frame_id::RTR != 0;
        let dlc = (self.tx_ctrl & frame_ctrl::DLC_MASK) as u8;
        let len = if rtr { 0 } else { dlc.min(8) as usize };
        data[len..].fill(0);
        Frame {
            id: self.tx_id & if ide { frame_id::ID_MASK } else { 0x7FF },
            ide,
            rtr,
            dlc,
            data,
        }
    }
}

/// One channel's capture registers (§10.2): the first error and the first lost
/// arbitration since the host last re-armed them, held until then.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Capture {
    pub(super) err_kind: u8,
    pub(super) err_field: u8,
    pub(super) err_tx: bool,
    pub(super) err_valid: bool,
    pub(super) alc: u8,
    pub(super) alc_valid: bool,
}

impl Capture {
    /// The edge of one channel's captures, on the channel outputs before the edge
    /// (the channel loaded `err_kind/err_field/err_tx` and `alc` at the edge that
    /// raised `err_valid` / `arb_lost`, so they already describe this event). A
    /// re-arm clears the valid bit; a capture at the same edge wins.
    pub(super) fn edge(&self, o: &ChannelOutputs, rearm_err: bool, rearm_alc: bool) -> Self {
        let mut c = *self;
        if rearm_err {
            c.err_valid = false;
        }
        if rearm_alc {
            c.alc_valid = false;
        }
        if o.diag.err_valid && !c.err_valid {
            c.err_kind = o.diag.err_kind;
            c.err_field = o.diag.err_field;
            c.err_tx = o.diag.err_tx;
            c.err_valid = true;
        }
        if o.arb_lost && !c.alc_valid {
            c.alc = o.diag.alc;
            c.alc_valid = true;
        }
        c
    }

    /// The `CAP_x` word.
    pub(super) fn reg(&self) -> u32 {
        (self.err_kind as u32 & cap::ERR_KIND_MASK)
            | (self.err_field as u32 & cap::ERR_FIELD_MASK) << cap::ERR_FIELD_SHIFT
            | if self.err_tx { cap::ERR_TX } else { 0 }
            | if self.err_valid { cap::ERR_VALID } else { 0 }
            | (self.alc as u32 & cap::ALC_MASK) << cap::ALC_SHIFT
            | if self.alc_valid { cap::ALC_VALID } else { 0 }
    }
}

/// `CTRL` write value with `k = 0` clamped to 1 (§9).
pub(super) fn clamp_k(w: u32) -> u32 {
    if w & ctrl::K_MASK == 0 {
        w | (1 << ctrl::K_SHIFT)
    } else {
        w
    }
}

impl DrccModel {
    /// `SIZES` (§10.1): the generation parameters of §1.1, and whether
    /// `CTRL.dmr` / `CTRL.star` can be set (the same predicates that refuse them).
    fn sizes(&self) -> u32 {
        let p = &self.params;
        (p.rx_fifo_depth as u32 & 0x3F) << sizes::RX_FIFO_DEPTH_SHIFT
            | (p.tx_queue_depth as u32 & 0xF) << sizes::TX_QUEUE_DEPTH_SHIFT
            | (p.history as u32 & 0x3F) << sizes::HISTORY_SHIFT
            | (p.mailboxes as u32 & 0x1F) << sizes::MAILBOXES_SHIFT
            | if p.dmr { sizes::DMR } else { 0 }
            | if p.star { sizes::STAR } else { 0 }
    }

    /// The value a Wishbone read of word `adr` returns (registers before the edge).
    pub(super) fn read_reg(&self, adr: u8) -> u32 {
        let r = &self.r;
        let chan_err = |o: &ChannelOutputs| {
            (o.probes.tec as u32 & 0x1FF)
                | (o.probes.rec as u32) << 16
                | (o.probes.err_state as u32 & 3) << 24
                | (o.diag.err_warning as u32) << 26
        };
        let (rx_frame, rx_ch) = self.rx.rd;
        match adr {
            idx::ID => ID_VALUE,
            idx::CTRL => r.ctrl,
            idx::BTR => r.btr,
            idx::RMB_CFG => r.rmb,
            idx::DEDUP_CFG => r.dedup,
            idx::STATUS => {
                self.fsm.state as u32
                    | (self.fsm.tx_channel() as u32) << 4
                    | (self.aux[0].state as u32) << 5
                    | (self.aux[1].state as u32) << 7
                    | (self.out[0].probes.err_state as u32 & 3) << 9
                    | (self.out[1].probes.err_state as u32 & 3) << 11
                    | (r.reset_mode() as u32) << 13
                    | (self.fsm.tx_going_on() as u32) << 14
                    | (self.txq.count[0] as u32) << 16
                    | (self.txq.count[1] as u32) << 20
                    | (self.rx.count as u32) << 24
            }
            idx::INT_STATUS => r.int_status,
            idx::INT_ENABLE => r.int_enable,
            idx::CHAN_A_ERR => chan_err(&self.out[0]),
            idx::CHAN_B_ERR => chan_err(&self.out[1]),
            idx::AUX_A => self.aux[0].reg(),
            idx::AUX_B => self.aux[1].reg(),
            idx::TX_ID => r.tx_id,
            idx::TX_CTRL => r.tx_ctrl,
            idx::TX_DATA0 => r.tx_data[0],
            idx::TX_DATA1 => r.tx_data[1],
            idx::RX_ID => {
                (rx_frame.id & frame_id::ID_MASK)
                    | if rx_frame.ide { frame_id::IDE } else { 0 }
                    | if rx_frame.rtr { frame_id::RTR } else { 0 }
                    | if self.rx.rx_ready {
                        frame_id::NOT_EMPTY
                    } else {
                        0
                    }
            }
            idx::RX_CTRL => (rx_frame.dlc as u32 & 0xF) | (rx_ch as u32 & 1) << 8,
            idx::RX_DATA0 => u32::from_le_bytes(rx_frame.data[..4].try_into().unwrap()),
            idx::RX_DATA1 => u32::from_le_bytes(rx_frame.data[4..].try_into().unwrap()),
            idx::STATS0 => self.rx.duplicates as u32 | (self.rx.overruns as u32) << 16,
            idx::STATS1 => self.fsm.switches as u32 | (r.recoveries as u32) << 16,
            idx::TIMES => self.fsm.last_tx_time as u32 | (self.fsm.switch_time as u32) << 16,
            idx::STAR_STATUS => self.star.reg(),
            idx::OMISSIONS => self.rx.omissions[0] as u32 | (self.rx.omissions[1] as u32) << 16,
            // §10.1: identification.
            idx::VERSION => VERSION_VALUE,
            idx::SIZES => self.sizes(),
            // §10.2: the held captures.
            idx::CAP_A => r.cap[0].reg(),
            idx::CAP_B => r.cap[1].reg(),
            // DMR registers (dmr_contract.md §2.1); TX_CMD, RX_CMD (write only) and
            // unmapped words read 0.
            _ => self
                .dmr
                .read(adr, r.reset_mode(), self.rx.dmr_stats())
                .unwrap_or(0),
        }
    }
}
