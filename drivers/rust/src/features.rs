//! The driver features of the register map 1.2: identification (`VERSION`,
//! `SIZES`), acceptance filters (`FILT_ID0/1`, `FILT_MASK0/1`), the bit-time
//! clock of the RX timestamps (`RX_TIME.now`), clearing the statistics
//! (`STATS_CLR`) and the error / arbitration-lost captures (`CAP_A`, `CAP_B`).

use crate::regs::{self, get, put};
use crate::{Drcc, Error, Registers};

/// `VERSION` and `SIZES`, decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Ident {
    /// `VERSION.major` (1 for every map this driver accepts).
    pub major: u8,
    /// `VERSION.minor` (registers added since 1.0).
    pub minor: u8,
    /// RX FIFO entries.
    pub rx_fifo_depth: u8,
    /// Entries of each TX queue.
    pub tx_queue_depth: u8,
    /// Duplicate-removal history entries.
    pub history: u8,
    /// DMR mailboxes (0 or 16).
    pub mailboxes: u8,
    /// `CTRL.dmr` can be set.
    pub dmr: bool,
    /// `CTRL.star` can be set.
    pub star: bool,
}

impl Ident {
    /// Decodes the `VERSION` and `SIZES` words.
    pub fn decode(version: u32, sizes: u32) -> Ident {
        let f = |mask, shift| get(mask, shift, sizes) as u8;
        Ident {
            major: get(regs::VERSION_MAJOR_MASK, regs::VERSION_MAJOR_SHIFT, version) as u8,
            minor: get(regs::VERSION_MINOR_MASK, regs::VERSION_MINOR_SHIFT, version) as u8,
            rx_fifo_depth: f(
                regs::SIZES_RX_FIFO_DEPTH_MASK,
                regs::SIZES_RX_FIFO_DEPTH_SHIFT,
            ),
            tx_queue_depth: f(
                regs::SIZES_TX_QUEUE_DEPTH_MASK,
                regs::SIZES_TX_QUEUE_DEPTH_SHIFT,
            ),
            history: f(regs::SIZES_HISTORY_MASK, regs::SIZES_HISTORY_SHIFT),
            mailboxes: f(regs::SIZES_MAILBOXES_MASK, regs::SIZES_MAILBOXES_SHIFT),
            dmr: sizes & regs::SIZES_DMR_MASK != 0,
            star: sizes & regs::SIZES_STAR_MASK != 0,
        }
    }
}

/// One channel's capture register (`CAP_A` / `CAP_B`), decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Capture {
    /// An error was captured since the last re-arm.
    pub err_valid: bool,
    /// 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK (the `ERR_*` constants).
    pub err_kind: u8,
    /// The frame field of the error (the channel's field code, e.g.
    /// [`Capture::FIELD_ACK_SLOT`]).
    pub err_field: u8,
    /// The channel was transmitting.
    pub err_tx: bool,
    /// An arbitration loss was captured since the last re-arm.
    pub alc_valid: bool,
    /// The lost bit: base-identifier bit i (most significant first) is i,
    /// SRR/RTR 11, IDE 12, extension bit j is 13 + j, extended RTR 31.
    pub alc: u8,
}

impl Capture {
    /// `err_kind` of a bit error.
    pub const ERR_BIT: u8 = 1;
    /// `err_kind` of a stuff error.
    pub const ERR_STUFF: u8 = 2;
    /// `err_kind` of a CRC error.
    pub const ERR_CRC: u8 = 3;
    /// `err_kind` of a form error.
    pub const ERR_FORM: u8 = 4;
    /// `err_kind` of an ACK error.
    pub const ERR_ACK: u8 = 5;
    /// `err_field` of the ACK slot.
    pub const FIELD_ACK_SLOT: u8 = 13;

    /// Decodes a `CAP_A` / `CAP_B` word.
    pub fn decode(w: u32) -> Capture {
        Capture {
            err_valid: w & regs::CAP_A_ERR_VALID_MASK != 0,
            err_kind: get(regs::CAP_A_ERR_KIND_MASK, regs::CAP_A_ERR_KIND_SHIFT, w) as u8,
            err_field: get(regs::CAP_A_ERR_FIELD_MASK, regs::CAP_A_ERR_FIELD_SHIFT, w) as u8,
            err_tx: w & regs::CAP_A_ERR_TX_MASK != 0,
            alc_valid: w & regs::CAP_A_ALC_VALID_MASK != 0,
            alc: get(regs::CAP_A_ALC_MASK, regs::CAP_A_ALC_SHIFT, w) as u8,
        }
    }
}

/// An acceptance filter: a frame passes if its format is the filter's
/// (standard or extended), its identifier agrees in every bit set in the mask
/// (Linux convention: 1 = compare), and, if set, its remote flag is `rtr`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Filter {
    id: u32,
    mask: u32,
    extended: bool,
    rtr: Option<bool>,
}

impl Filter {
    /// Standard frames whose 11-bit identifier agrees with `id` where `mask`
    /// is 1 (extended frames never pass). `None` if either exceeds 11 bits.
    pub fn standard(id: u16, mask: u16) -> Option<Filter> {
        (id <= 0x7FF && mask <= 0x7FF).then_some(Filter {
            id: u32::from(id),
            mask: u32::from(mask),
            extended: false,
            rtr: None,
        })
    }

    /// Extended frames whose 29-bit identifier agrees with `id` where `mask`
    /// is 1 (standard frames never pass). `None` if either exceeds 29 bits.
    pub fn extended(id: u32, mask: u32) -> Option<Filter> {
        (id <= 0x1FFF_FFFF && mask <= 0x1FFF_FFFF).then_some(Filter {
            id,
            mask,
            extended: true,
            rtr: None,
        })
    }

    /// The same filter passing only remote (`true`) or only data frames.
    pub fn with_rtr(mut self, rtr: bool) -> Filter {
        self.rtr = Some(rtr);
        self
    }

    /// The `FILT_IDk` and `FILT_MASKk` words (enable set; the `ide` mask bit
    /// always set, so the format must match).
    pub fn words(&self) -> (u32, u32) {
        let id = put(regs::FILT_ID0_ID_MASK, regs::FILT_ID0_ID_SHIFT, self.id)
            | put(
                regs::FILT_ID0_IDE_MASK,
                regs::FILT_ID0_IDE_SHIFT,
                u32::from(self.extended),
            )
            | put(
                regs::FILT_ID0_RTR_MASK,
                regs::FILT_ID0_RTR_SHIFT,
                u32::from(self.rtr == Some(true)),
            );
        let mask = put(
            regs::FILT_MASK0_ID_MASK,
            regs::FILT_MASK0_ID_SHIFT,
            self.mask,
        ) | regs::FILT_MASK0_IDE_MASK
            | put(
                regs::FILT_MASK0_RTR_MASK,
                regs::FILT_MASK0_RTR_SHIFT,
                u32::from(self.rtr.is_some()),
            )
            | regs::FILT_MASK0_ENABLE_MASK;
        (id, mask)
    }
}

impl<R: Registers> Drcc<R> {
    /// Sets acceptance filter `index` (0 or 1) to `filter` and enables it, or
    /// disables it (`None`). With no filter enabled every frame is accepted.
    /// Filters are configuration: outside reset mode this enters reset mode
    /// (emptying the queues and the FIFO), writes and leaves it with the
    /// configuration kept; in reset mode it stays there.
    pub fn set_filter(&mut self, index: u8, filter: Option<Filter>) -> Result<(), Error> {
        if index > 1 {
            return Err(Error::Invalid);
        }
        let words = filter.map_or((0, 0), |f| f.words());
        let mut all = [None, None];
        all[usize::from(index)] = Some(words);
        self.write_filters(all)
    }

    /// Disables both filters (every frame accepted), as [`Drcc::set_filter`].
    pub fn clear_filters(&mut self) -> Result<(), Error> {
        self.write_filters([Some((0, 0)), Some((0, 0))])
    }

    fn write_filters(&mut self, words: [Option<(u32, u32)>; 2]) -> Result<(), Error> {
        let step = regs::FILT_ID1_OFFSET - regs::FILT_ID0_OFFSET;
        let running = self.regs.read32(regs::STATUS_OFFSET) & regs::STATUS_RESET_MODE_MASK == 0;
        if running {
            self.enter_reset()?;
        }
        for (k, w) in (0u32..).zip(words) {
            if let Some((id, mask)) = w {
                self.write_checked(regs::FILT_ID0_OFFSET + k * step, id)?;
                self.write_checked(regs::FILT_MASK0_OFFSET + k * step, mask)?;
            }
        }
        if running {
            self.start(self.ctrl)?;
        }
        Ok(())
    }

    /// `RX_TIME.now`: nominal bit times since reset mode was left (16 bits,
    /// wrapping), the clock of [`crate::Frame::timestamp`].
    pub fn now(&mut self) -> u16 {
        get(
            regs::RX_TIME_NOW_MASK,
            regs::RX_TIME_NOW_SHIFT,
            self.regs.read32(regs::RX_TIME_OFFSET),
        ) as u16
    }

    /// `STATS_CLR`: clears `STATS0`, `STATS1`, `OMISSIONS`, `DMR_RX_STATS` and
    /// the `AUX_x` failures and recoveries counts (`TIMES` and the CAN error
    /// counters stay).
    pub fn clear_stats(&mut self) {
        self.regs
            .write32(regs::STATS_CLR_OFFSET, regs::STATS_CLR_CLEAR_MASK);
    }

    /// Reads `CAP_A` and `CAP_B` (no side effect: they stay held).
    pub fn captures(&mut self) -> (Capture, Capture) {
        (
            Capture::decode(self.regs.read32(regs::CAP_A_OFFSET)),
            Capture::decode(self.regs.read32(regs::CAP_B_OFFSET)),
        )
    }

    /// Re-arms the captures by acknowledging `INT_STATUS.bus_error` (if
    /// `errors`) and `INT_STATUS.arb_lost` (if `arb`): clears `err_valid` /
    /// `alc_valid` of both channels, so the next event is captured.
    pub fn rearm_captures(&mut self, errors: bool, arb: bool) {
        let mask = if errors {
            regs::INT_STATUS_BUS_ERROR_MASK
        } else {
            0
        } | if arb {
            regs::INT_STATUS_ARB_LOST_MASK
        } else {
            0
        };
        if mask != 0 {
            self.regs.write32(regs::INT_STATUS_OFFSET, mask);
        }
    }
}
