//! The DRCC model's register file (DRCC contract §3, DMR contract §2.1): the
//! stored registers and the read side of the Wishbone map. The write side stays
//! in the edge of [`super::DrccModel`] (`edge.rs`, its host-access phase), beside
//! the blocks it drives.

use super::ecss::Ecss;
use super::features::Filters;
use super::regs::*;
use super::DrccModel;
use crate::engine::drcc::DrccInputs;
use crate::engine::ChannelOutputs;
use crate::frame::Frame;
use crate::model::coverage;

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
    /// `FILT_ID0` .. `FILT_MASK1` (§11.1): cleared by `rst` only.
    pub(super) filt: Filters,
    /// `recover_a`, `recover_b` (§11.6): the host's permission for a bus-off
    /// channel to count its recovery; taken only while the channel is bus-off.
    pub(super) recover: [bool; 2],
    /// `ECSS_CFG`, `ECSS_HB`, `ECSS_PERIOD` and the bus selection (§12).
    pub(super) ecss: Ecss,
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
            filt: Filters::default(),
            recover: [false; 2],
            ecss: Ecss::default(),
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
    /// DMR first-copy delivery (dmr_contract.md §8.1).
    pub(super) fn first_copy(&self) -> bool {
        self.ctrl & ctrl::FIRST_COPY != 0
    }
    /// Manual bus-off recovery (§11.6).
    pub(super) fn busoff_manual(&self) -> bool {
        self.ctrl & ctrl::BUSOFF_MANUAL != 0
    }
    /// Channel `c`'s `boff_hold` input (§11.6): `busoff_manual && !recover_c`.
    pub(super) fn boff_hold(&self, c: usize) -> bool {
        self.busoff_manual() && !self.recover[c]
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
            // §11: the filters, the head's timestamp with the present `now`; the
            // write-only STATS_CLR reads 0.
            idx::FILT_ID0 => r.filt.id[0],
            idx::FILT_MASK0 => r.filt.mask[0],
            idx::FILT_ID1 => r.filt.id[1],
            idx::FILT_MASK1 => r.filt.mask[1],
            idx::RX_TIME => self.rx.rd_ts as u32 | (self.rx.now as u32) << 16,
            idx::STATS_CLR => 0,
            // §12.1: the ECSS registers.
            idx::ECSS_CFG..=idx::ECSS_STATUS => r.ecss.read(adr).unwrap_or(0),
            // DMR registers (dmr_contract.md §2.1); TX_CMD, RX_CMD (write only) and
            // unmapped words read 0.
            _ => self
                .dmr
                .read(adr, r.reset_mode(), self.rx.dmr_stats())
                .unwrap_or(0),
        }
    }
}

/// What the Wishbone access taken at an edge asks of the other blocks.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Access {
    /// An access is taken at this edge (§2).
    pub(super) take: bool,
    /// `INT_STATUS.illegal` when the access is refused (§9).
    pub(super) ints: u32,
    /// The W1C bits of an `INT_STATUS` write.
    pub(super) w1c: u32,
    /// `TX_CMD.push`: the target queue and the staged frame, normalized.
    pub(super) push: Option<(usize, Frame)>,
    /// `TX_CMD.abort_a`, `abort_b` (§11.5), legal ones only.
    pub(super) abort: [bool; 2],
    /// `TX_CMD.recover_a`, `recover_b` (§11.6) of a write not refused here (a
    /// push the queues refuse cancels them too).
    pub(super) recover: [bool; 2],
    /// `RX_CMD.pop`.
    pub(super) pop: bool,
    /// A DMR register write, applied after the DMR block's edge.
    pub(super) dmr_write: Option<(u8, u32)>,
    /// `STATS_CLR.clear` (§11.4).
    pub(super) stats_clr: bool,
}

impl DrccModel {
    /// The Wishbone access of this edge (§2, §3, §9, §11): the writes to the
    /// register file go to `n` (the registers after the edge), the rest is
    /// returned for the blocks it drives.
    #[inline]
    pub(super) fn access(&self, i: &DrccInputs, n: &mut Regs) -> Access {
        let r = &self.r;
        n.wb_dat = 0;
        // bus_contract.md §1: an access is taken unless it is the one just
        // answered; a refused one (it raises `illegal`) ends with ERR.
        if i.wb_cyc && i.wb_stb && !(r.wb_ack || r.wb_err) {
            self.access_taken(i, n)
        } else {
            // Most clocks: no access, decided here without the call.
            Access::default()
        }
    }

    /// [`Self::access`] of an access taken at this edge.
    #[inline(never)]
    fn access_taken(&self, i: &DrccInputs, n: &mut Regs) -> Access {
        let r = &self.r;
        let reset_mode = r.reset_mode();
        let (redundancy, dmr_mode) = (r.redundancy(), r.dmr());
        let mut a = Access {
            take: true,
            ..Access::default()
        };
        let adr = i.wb_adr & 0x3F;
        // Byte lanes: the staged frame's words merge the selected bytes into
        // their value; every other word takes only a whole-word write.
        let lanes = (0..4)
            .filter(|b| i.wb_sel >> b & 1 != 0)
            .fold(0u32, |m, b| m | 0xFF << (8 * b));
        let laned = matches!(
            adr,
            idx::TX_ID | idx::TX_CTRL | idx::TX_DATA0 | idx::TX_DATA1
        );
        let d = if laned {
            (self.read_reg(adr) & !lanes) | (i.wb_dat_w & lanes)
        } else {
            i.wb_dat_w
        };
        if !i.wb_we {
            n.wb_dat = self.read_reg(adr);
        } else if lanes != u32::MAX && !laned {
            coverage::hit("drcc register port: a partial write to a whole word is refused");
            a.ints |= int::ILLEGAL;
        } else {
            if lanes != u32::MAX {
                coverage::hit("drcc register port: a partial write to a staged TX word");
            }
            match adr {
                idx::CTRL => {
                    let w = clamp_k(d & ctrl::DEFINED);
                    if reset_mode {
                        let listen_only = |shift: u32| (w >> shift) & 3 == 1;
                        let any_listen_only =
                            listen_only(ctrl::MODE_A_SHIFT) || listen_only(ctrl::MODE_B_SHIFT);
                        let (red, dmr) = (w & ctrl::REDUNDANCY != 0, w & ctrl::DMR != 0);
                        // §1.1: a mode the configuration lacks is refused.
                        let absent =
                            (dmr && !self.params.dmr) || (w & ctrl::STAR != 0 && !self.params.star);
                        // DMR §2: one mode at a time; both lines must transmit.
                        if (red && (any_listen_only || dmr)) || (dmr && any_listen_only) || absent {
                            a.ints |= int::ILLEGAL;
                        } else if !self.params.dmr {
                            // DMR §2: `first_copy` is stored only with the DMR function.
                            n.ctrl = w & !ctrl::FIRST_COPY;
                        } else {
                            n.ctrl = w;
                        }
                    } else {
                        if w & ctrl::CFG != r.ctrl & ctrl::CFG {
                            a.ints |= int::ILLEGAL;
                        }
                        n.ctrl = (r.ctrl & !ctrl::RESET_MODE) | (w & ctrl::RESET_MODE);
                    }
                }
                idx::BTR | idx::RMB_CFG | idx::DEDUP_CFG => {
                    if !reset_mode {
                        a.ints |= int::ILLEGAL;
                    } else if adr == idx::BTR {
                        n.btr = d & btr::DEFINED;
                    } else if adr == idx::RMB_CFG {
                        n.rmb = d;
                    } else {
                        n.dedup = d & dedup::WINDOW_MASK;
                    }
                }
                idx::INT_STATUS => a.w1c = d & int::ALL,
                idx::INT_ENABLE => n.int_enable = d & int::ALL,
                idx::TX_ID => n.tx_id = d & (frame_id::ID_MASK | frame_id::IDE | frame_id::RTR),
                idx::TX_CTRL => n.tx_ctrl = d & frame_ctrl::DEFINED,
                idx::TX_DATA0 => n.tx_data[0] = d,
                idx::TX_DATA1 => n.tx_data[1] = d,
                idx::TX_CMD => {
                    let aborts = [tx_cmd::ABORT_A, tx_cmd::ABORT_B].map(|b| d & b != 0);
                    if aborts.contains(&true) && (d & tx_cmd::PUSH != 0 || dmr_mode) {
                        // §11.5: an abort with a push, or in DMR mode; the
                        // refused write takes no recover either (§11.6).
                        a.ints |= int::ILLEGAL;
                    } else {
                        // §11.6: never refused on its own; acts by its own rule
                        // beside a push or an abort (a refused push takes it
                        // back, in the edge).
                        a.recover = [tx_cmd::RECOVER_A, tx_cmd::RECOVER_B].map(|b| d & b != 0);
                        if d & tx_cmd::PUSH == 0 {
                            a.abort = aborts;
                        } else {
                            let q = if redundancy || dmr_mode {
                                0
                            } else {
                                (r.tx_ctrl & frame_ctrl::QUEUE != 0) as usize
                            };
                            a.push = Some((q, r.staged()));
                        }
                    }
                }
                idx::RX_CMD => a.pop = d & 1 != 0,
                // DMR registers: applied after the DMR block's edge.
                idx::DMR_CFG..=idx::MB_STATE => a.dmr_write = Some((adr, d)),
                // §11.1: the filters are cfg registers.
                idx::FILT_ID0..=idx::FILT_MASK1 => {
                    let (k, mask) = ((adr - idx::FILT_ID0) as usize / 2, adr & 1 != 0);
                    if !reset_mode {
                        a.ints |= int::ILLEGAL;
                    } else if !mask {
                        n.filt.id[k] = d & filt::WORD;
                    } else {
                        n.filt.mask[k] = d;
                    }
                }
                // §11.4: never refused; bit 0 = 0 does nothing.
                idx::STATS_CLR => a.stats_clr = d & 1 != 0,
                // §12.1: cfg registers holding legal values only (ECSS_STATUS
                // is read-only, below).
                idx::ECSS_CFG..=idx::ECSS_PERIOD => {
                    if !n.ecss.cfg.write(adr, d, reset_mode) {
                        a.ints |= int::ILLEGAL;
                    }
                }
                // Read-only and unmapped words.
                _ => a.ints |= int::ILLEGAL,
            }
        }
        a
    }
}
