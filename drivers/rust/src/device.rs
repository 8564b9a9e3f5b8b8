//! [`Drcc`]: bring-up, modes, send, receive, the interrupt handler, status and
//! statistics over a [`Registers`] implementation, and the `embedded-can`
//! traits.

use crate::config::{Config, Mode};
use crate::features::{Capture, Ident};
use crate::frame::{Channel, Frame};
use crate::regs::{self, get, put};
use crate::status::{ChanStatus, Stats, Status};
use crate::{Error, Registers};

/// What [`Drcc::isr`] did.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct IrqResult {
    /// `INT_STATUS` as read and acknowledged.
    pub events: u32,
    /// Frames stored into the caller's buffer.
    pub frames: usize,
    /// The buffer filled up while the FIFO still held frames.
    pub more: bool,
    /// `CAP_A` as read before the acknowledgement re-armed it (read only when
    /// `bus_error` or `arb_lost` was set, else empty).
    pub cap_a: Capture,
    /// `CAP_B`, likewise.
    pub cap_b: Capture,
}

impl IrqResult {
    fn has(&self, mask: u32) -> bool {
        self.events & mask != 0
    }
    /// `INT_STATUS.bus_error`: a channel detected an error.
    pub fn bus_error(&self) -> bool {
        self.has(regs::INT_STATUS_BUS_ERROR_MASK)
    }
    /// `INT_STATUS.arb_lost`: a channel lost arbitration.
    pub fn arb_lost(&self) -> bool {
        self.has(regs::INT_STATUS_ARB_LOST_MASK)
    }
    /// `INT_STATUS.err_warning`: a channel's warning flag changed.
    pub fn err_warning(&self) -> bool {
        self.has(regs::INT_STATUS_ERR_WARNING_MASK)
    }
    /// `INT_STATUS.tx_done_a` / `tx_done_b`: that channel transmitted a frame.
    pub fn tx_done_on(&self, channel: Channel) -> bool {
        self.has(match channel {
            Channel::A => regs::INT_STATUS_TX_DONE_A_MASK,
            Channel::B => regs::INT_STATUS_TX_DONE_B_MASK,
        })
    }
    /// `INT_STATUS.tx_failure_a` / `tx_failure_b`: that channel dropped its frame.
    pub fn tx_failure_on(&self, channel: Channel) -> bool {
        self.has(match channel {
            Channel::A => regs::INT_STATUS_TX_FAILURE_A_MASK,
            Channel::B => regs::INT_STATUS_TX_FAILURE_B_MASK,
        })
    }
}

/// One DRCC behind its register hooks.
#[derive(Debug)]
pub struct Drcc<R: Registers> {
    pub(crate) regs: R,
    pub(crate) ctrl: u32,
    tx_queue_depth: u8,
    ident: Ident,
}

impl<R: Registers> Drcc<R> {
    /// Binds the hooks, checks the `ID` register ([`Error::NoDevice`] if it
    /// does not read "DRCC") and reads `VERSION` and `SIZES`
    /// ([`Error::Version`] unless the major version is 1; the TX queue depth
    /// is taken from `SIZES`). Nothing is written.
    pub fn new(mut regs: R) -> Result<Self, Error> {
        if regs.read32(regs::ID_OFFSET) != regs::ID_VALUE {
            return Err(Error::NoDevice);
        }
        let ident = Ident::decode(
            regs.read32(regs::VERSION_OFFSET),
            regs.read32(regs::SIZES_OFFSET),
        );
        // Major 0 is the map before VERSION existed (its address reads 0).
        if ident.major != 1 {
            return Err(Error::Version);
        }
        let ctrl = regs.read32(regs::CTRL_OFFSET) & !regs::CTRL_RESET_MODE_MASK;
        Ok(Drcc {
            regs,
            ctrl,
            tx_queue_depth: ident.tx_queue_depth,
            ident,
        })
    }

    /// `VERSION` and `SIZES` as [`Drcc::new`] read them.
    pub fn ident(&self) -> Ident {
        self.ident
    }

    /// The register hooks back.
    pub fn release(self) -> R {
        self.regs
    }

    /// The register hooks, for accesses the driver does not offer.
    pub fn registers(&mut self) -> &mut R {
        &mut self.regs
    }

    /// Enters reset mode (channels held in reset, TX queues and RX FIFO emptied).
    pub fn enter_reset(&mut self) -> Result<(), Error> {
        // Outside reset mode only reset_mode is taken, and a CTRL write whose
        // cfg fields differ is flagged illegal: write back what CTRL holds.
        let ctrl = self.regs.read32(regs::CTRL_OFFSET);
        self.regs
            .write32(regs::CTRL_OFFSET, ctrl | regs::CTRL_RESET_MODE_MASK);
        if self.regs.read32(regs::STATUS_OFFSET) & regs::STATUS_RESET_MODE_MASK == 0 {
            return Err(Error::Refused);
        }
        Ok(())
    }

    pub(crate) fn write_checked(&mut self, offset: u32, value: u32) -> Result<(), Error> {
        self.regs.write32(offset, value);
        if self.regs.read32(offset) == value {
            Ok(())
        } else {
            Err(Error::Refused)
        }
    }

    /// Writes CTRL with `reset_mode` 0; [`Error::Refused`] if it was not taken.
    pub(crate) fn start(&mut self, ctrl: u32) -> Result<(), Error> {
        self.regs.write32(regs::CTRL_OFFSET, ctrl);
        if self.regs.read32(regs::CTRL_OFFSET) != ctrl {
            return Err(Error::Refused);
        }
        self.ctrl = ctrl;
        Ok(())
    }

    fn ctrl_word(cfg: &Config) -> Result<u32, Error> {
        let k = u32::from(cfg.k.max(1));
        if k > 15 {
            return Err(Error::Invalid);
        }
        Ok(put(
            regs::CTRL_REDUNDANCY_MASK,
            regs::CTRL_REDUNDANCY_SHIFT,
            u32::from(cfg.mode == Mode::Redundancy),
        ) | put(
            regs::CTRL_DMR_MASK,
            regs::CTRL_DMR_SHIFT,
            u32::from(cfg.mode == Mode::Dmr),
        ) | put(
            regs::CTRL_POLICY_MASK,
            regs::CTRL_POLICY_SHIFT,
            cfg.policy.code(),
        ) | put(
            regs::CTRL_DUAL_TX_MASK,
            regs::CTRL_DUAL_TX_SHIFT,
            u32::from(cfg.dual_tx),
        ) | put(
            regs::CTRL_STAR_MASK,
            regs::CTRL_STAR_SHIFT,
            u32::from(cfg.star),
        ) | put(regs::CTRL_K_MASK, regs::CTRL_K_SHIFT, k)
            | put(
                regs::CTRL_MODE_A_MASK,
                regs::CTRL_MODE_A_SHIFT,
                cfg.mode_a.code(),
            )
            | put(
                regs::CTRL_MODE_B_MASK,
                regs::CTRL_MODE_B_SHIFT,
                cfg.mode_b.code(),
            )
            | put(
                regs::CTRL_SINGLE_SHOT_MASK,
                regs::CTRL_SINGLE_SHOT_SHIFT,
                u32::from(cfg.single_shot),
            )
            | put(
                regs::CTRL_BUSOFF_MANUAL_MASK,
                regs::CTRL_BUSOFF_MANUAL_SHIFT,
                u32::from(cfg.busoff_manual),
            )
            | put(
                regs::CTRL_FIRST_COPY_MASK,
                regs::CTRL_FIRST_COPY_SHIFT,
                u32::from(cfg.mode == Mode::Dmr && cfg.dmr.first_copy),
            ))
    }

    /// Enters reset mode, writes the whole configuration and leaves reset mode
    /// with `CTRL` (the mode) in one write. [`Error::Refused`] if the controller
    /// did not take a word (it then stays in reset mode);
    /// [`Error::Unsupported`] (nothing written) for
    /// [`Config::busoff_manual`] on an instance older than map 1.3, and for
    /// DMR first-copy delivery on one older than map 1.4.
    pub fn configure(&mut self, cfg: &Config) -> Result<(), Error> {
        let btr = cfg.timing.btr(cfg.ewl)?;
        let ctrl = Self::ctrl_word(cfg)?;
        if cfg.busoff_manual && self.ident.minor < crate::MINOR_BUSOFF_MANUAL {
            return Err(Error::Unsupported);
        }
        if ctrl & regs::CTRL_FIRST_COPY_MASK != 0 && self.ident.minor < crate::MINOR_FIRST_COPY {
            return Err(Error::Unsupported);
        }
        if cfg.dedup_window > 0x7FFF
            || (cfg.tx_queue_depth != 0 && cfg.tx_queue_depth != self.ident.tx_queue_depth)
        {
            return Err(Error::Invalid);
        }
        let d = &cfg.dmr;
        if cfg.mode == Mode::Dmr
            && (d.timeout == 0
                || d.tick_bits == 0
                || d.recovery_delay == 0
                || d.cs_id_dcl > 0x7FF
                || d.cs_id_rcl > 0x7FF
                || d.cs_id_dcl == d.cs_id_rcl)
        {
            return Err(Error::Invalid);
        }
        self.enter_reset()?;
        self.write_checked(regs::BTR_OFFSET, btr)?;
        self.write_checked(
            regs::RMB_CFG_OFFSET,
            put(
                regs::RMB_CFG_RECOVERY_BITS_MASK,
                regs::RMB_CFG_RECOVERY_BITS_SHIFT,
                u32::from(cfg.recovery_bits),
            ) | put(
                regs::RMB_CFG_STALL_LIMIT_MASK,
                regs::RMB_CFG_STALL_LIMIT_SHIFT,
                u32::from(cfg.stall_limit),
            ),
        )?;
        self.write_checked(
            regs::DEDUP_CFG_OFFSET,
            put(
                regs::DEDUP_CFG_WINDOW_MASK,
                regs::DEDUP_CFG_WINDOW_SHIFT,
                u32::from(cfg.dedup_window),
            ),
        )?;
        if cfg.mode == Mode::Dmr {
            self.write_checked(
                regs::DMR_CFG_OFFSET,
                put(
                    regs::DMR_CFG_TIMEOUT_MASK,
                    regs::DMR_CFG_TIMEOUT_SHIFT,
                    u32::from(d.timeout),
                ) | put(
                    regs::DMR_CFG_CS_PERIOD_MASK,
                    regs::DMR_CFG_CS_PERIOD_SHIFT,
                    u32::from(d.cs_period),
                ),
            )?;
            self.write_checked(
                regs::DMR_TIME_OFFSET,
                put(
                    regs::DMR_TIME_TICK_BITS_MASK,
                    regs::DMR_TIME_TICK_BITS_SHIFT,
                    u32::from(d.tick_bits),
                ) | put(
                    regs::DMR_TIME_RECOVERY_DELAY_MASK,
                    regs::DMR_TIME_RECOVERY_DELAY_SHIFT,
                    u32::from(d.recovery_delay),
                ),
            )?;
            let cs = put(
                regs::DMR_CS_CS_ID_DCL_MASK,
                regs::DMR_CS_CS_ID_DCL_SHIFT,
                u32::from(d.cs_id_dcl),
            ) | put(
                regs::DMR_CS_CS_ID_RCL_MASK,
                regs::DMR_CS_CS_ID_RCL_SHIFT,
                u32::from(d.cs_id_rcl),
            );
            // Refused while a mailbox is enabled: skip an unchanged value.
            if self.regs.read32(regs::DMR_CS_OFFSET) != cs {
                self.write_checked(regs::DMR_CS_OFFSET, cs)?;
            }
        }
        self.regs.write32(regs::INT_ENABLE_OFFSET, cfg.int_enable);
        self.start(ctrl)
    }

    /// Changes only the operating mode, through reset mode (the queues and the
    /// FIFO are emptied); the rest of the configuration stays.
    pub fn set_mode(&mut self, mode: Mode) -> Result<(), Error> {
        let mut ctrl = self.ctrl
            & !(regs::CTRL_REDUNDANCY_MASK | regs::CTRL_DMR_MASK | regs::CTRL_RESET_MODE_MASK);
        ctrl |= match mode {
            Mode::Normal => 0,
            Mode::Redundancy => regs::CTRL_REDUNDANCY_MASK,
            Mode::Dmr => regs::CTRL_DMR_MASK,
        };
        self.enter_reset()?;
        self.start(ctrl)
    }

    /// DMR mode: configures mailbox `index` (call in reset mode, before
    /// [`Drcc::configure`] with [`Mode::Dmr`]). `transmit` is the direction,
    /// `mask` bits set must match, `limit` 1..=127.
    #[allow(clippy::too_many_arguments)]
    pub fn dmr_mailbox(
        &mut self,
        index: u8,
        id: u32,
        extended: bool,
        transmit: bool,
        mask: u32,
        limit: u8,
    ) -> Result<(), Error> {
        let id_max = if extended { regs::MB_ID_ID_MASK } else { 0x7FF };
        if u32::from(index) > regs::MB_SEL_INDEX_MASK
            || !(1..=127).contains(&limit)
            || id > id_max
            || mask > regs::MB_MASK_MASK_MASK
        {
            return Err(Error::Invalid);
        }
        if self.regs.read32(regs::STATUS_OFFSET) & regs::STATUS_RESET_MODE_MASK == 0 {
            return Err(Error::State);
        }
        self.write_checked(regs::MB_SEL_OFFSET, u32::from(index))?;
        self.write_checked(
            regs::MB_ID_OFFSET,
            id | put(
                regs::MB_ID_IDE_MASK,
                regs::MB_ID_IDE_SHIFT,
                u32::from(extended),
            ) | put(
                regs::MB_ID_DIR_MASK,
                regs::MB_ID_DIR_SHIFT,
                u32::from(transmit),
            ),
        )?;
        self.write_checked(regs::MB_MASK_OFFSET, mask)?;
        self.write_checked(
            regs::MB_CFG_OFFSET,
            u32::from(limit) | regs::MB_CFG_ENABLE_MASK,
        )
    }

    /// Queues `frame`: `queue` [`Channel::A`] or [`Channel::B`] in normal mode,
    /// ignored in redundancy and DMR mode. [`Error::Full`] when the queue is
    /// full, [`Error::State`] in reset mode.
    pub fn send(&mut self, frame: &Frame, queue: Channel) -> Result<(), Error> {
        use embedded_can::Frame as _;
        let normal = self.ctrl & (regs::CTRL_REDUNDANCY_MASK | regs::CTRL_DMR_MASK) == 0;
        let queue = if normal { queue } else { Channel::A };
        let status = self.regs.read32(regs::STATUS_OFFSET);
        if status & regs::STATUS_RESET_MODE_MASK != 0 {
            return Err(Error::State);
        }
        let count = match queue {
            Channel::A => get(
                regs::STATUS_TXQ_A_COUNT_MASK,
                regs::STATUS_TXQ_A_COUNT_SHIFT,
                status,
            ),
            Channel::B => get(
                regs::STATUS_TXQ_B_COUNT_MASK,
                regs::STATUS_TXQ_B_COUNT_SHIFT,
                status,
            ),
        };
        if count >= u32::from(self.tx_queue_depth) {
            return Err(Error::Full);
        }
        let data = frame.raw_data();
        let id = frame.raw_id()
            | put(
                regs::TX_ID_IDE_MASK,
                regs::TX_ID_IDE_SHIFT,
                u32::from(frame.is_extended()),
            )
            | put(
                regs::TX_ID_RTR_MASK,
                regs::TX_ID_RTR_SHIFT,
                u32::from(frame.is_remote_frame()),
            );
        self.regs.write32(regs::TX_ID_OFFSET, id);
        self.regs.write32(
            regs::TX_CTRL_OFFSET,
            put(
                regs::TX_CTRL_DLC_MASK,
                regs::TX_CTRL_DLC_SHIFT,
                u32::from(frame.dlc_code()),
            ) | put(
                regs::TX_CTRL_QUEUE_MASK,
                regs::TX_CTRL_QUEUE_SHIFT,
                u32::from(queue == Channel::B),
            ),
        );
        let word = |b: &[u8]| u32::from_le_bytes([b[0], b[1], b[2], b[3]]);
        self.regs.write32(regs::TX_DATA0_OFFSET, word(&data[0..4]));
        self.regs.write32(regs::TX_DATA1_OFFSET, word(&data[4..8]));
        self.regs
            .write32(regs::TX_CMD_OFFSET, regs::TX_CMD_PUSH_MASK);
        Ok(())
    }

    /// Takes the head of the RX FIFO, or `None` when it is empty.
    pub fn try_receive(&mut self) -> Option<Frame> {
        let id = self.regs.read32(regs::RX_ID_OFFSET);
        if id & regs::RX_ID_RX_READY_MASK == 0 {
            return None;
        }
        // RX_ID's other fields, RX_CTRL and RX_DATA* are valid while rx_ready.
        let ctrl = self.regs.read32(regs::RX_CTRL_OFFSET);
        let d0 = self.regs.read32(regs::RX_DATA0_OFFSET).to_le_bytes();
        let d1 = self.regs.read32(regs::RX_DATA1_OFFSET).to_le_bytes();
        let time = self.regs.read32(regs::RX_TIME_OFFSET);
        self.regs
            .write32(regs::RX_CMD_OFFSET, regs::RX_CMD_POP_MASK);
        let data = [d0[0], d0[1], d0[2], d0[3], d1[0], d1[1], d1[2], d1[3]];
        let channel = if ctrl & regs::RX_CTRL_CHANNEL_MASK != 0 {
            Channel::B
        } else {
            Channel::A
        };
        // A frame the hardware delivered always fits (29-bit field, 4-bit DLC).
        Frame::from_raw(
            get(regs::RX_ID_ID_MASK, regs::RX_ID_ID_SHIFT, id),
            id & regs::RX_ID_IDE_MASK != 0,
            id & regs::RX_ID_RTR_MASK != 0,
            get(regs::RX_CTRL_DLC_MASK, regs::RX_CTRL_DLC_SHIFT, ctrl) as u8,
            data,
        )
        .map(|f| {
            f.with_channel(channel).with_timestamp(get(
                regs::RX_TIME_RX_TIME_MASK,
                regs::RX_TIME_RX_TIME_SHIFT,
                time,
            ) as u16)
        })
    }

    /// The interrupt handler: reads `INT_STATUS`, and `CAP_A` / `CAP_B` when
    /// `bus_error` or `arb_lost` is set; acknowledges `INT_STATUS` (write 1 to
    /// clear, which re-arms the captures), then drains the RX FIFO into `buf`.
    /// Loses no event: a frame arriving during the drain sets `INT_STATUS.rx`
    /// again.
    pub fn isr(&mut self, buf: &mut [Frame]) -> IrqResult {
        let events = self.regs.read32(regs::INT_STATUS_OFFSET);
        let (cap_a, cap_b) =
            if events & (regs::INT_STATUS_BUS_ERROR_MASK | regs::INT_STATUS_ARB_LOST_MASK) != 0 {
                self.captures()
            } else {
                (Capture::default(), Capture::default())
            };
        self.regs.write32(regs::INT_STATUS_OFFSET, events);
        let mut result = IrqResult {
            events,
            cap_a,
            cap_b,
            ..IrqResult::default()
        };
        let mut frames = 0;
        while frames < buf.len() {
            match self.try_receive() {
                Some(f) => {
                    buf[frames] = f;
                    frames += 1;
                }
                None => {
                    result.frames = frames;
                    return result;
                }
            }
        }
        result.frames = frames;
        result.more = self.regs.read32(regs::RX_ID_OFFSET) & regs::RX_ID_RX_READY_MASK != 0;
        result
    }

    /// Sets `INT_ENABLE`.
    pub fn irq_enable(&mut self, mask: u32) {
        self.regs.write32(regs::INT_ENABLE_OFFSET, mask);
    }

    /// Reads `INT_STATUS`.
    pub fn irq_status(&mut self) -> u32 {
        self.regs.read32(regs::INT_STATUS_OFFSET)
    }

    /// Clears the `INT_STATUS` bits of `mask`.
    pub fn irq_ack(&mut self, mask: u32) {
        self.regs.write32(regs::INT_STATUS_OFFSET, mask);
    }

    /// Reads `STATUS` and both channels' error and auxiliary registers.
    pub fn status(&mut self) -> Status {
        let s = self.regs.read32(regs::STATUS_OFFSET);
        let a = ChanStatus::decode(
            self.regs.read32(regs::CHAN_A_ERR_OFFSET),
            self.regs.read32(regs::AUX_A_OFFSET),
        );
        let b = ChanStatus::decode(
            self.regs.read32(regs::CHAN_B_ERR_OFFSET),
            self.regs.read32(regs::AUX_B_OFFSET),
        );
        Status::decode(s, a, b)
    }

    /// Reads the statistics registers.
    pub fn stats(&mut self) -> Stats {
        let s0 = self.regs.read32(regs::STATS0_OFFSET);
        let s1 = self.regs.read32(regs::STATS1_OFFSET);
        let t = self.regs.read32(regs::TIMES_OFFSET);
        let o = self.regs.read32(regs::OMISSIONS_OFFSET);
        let dmr = [
            self.regs.read32(regs::DMR_STATUS_OFFSET),
            self.regs.read32(regs::DMR_CS_COUNT_OFFSET),
            self.regs.read32(regs::DMR_RX_STATS_OFFSET),
        ];
        Stats::decode(s0, s1, t, o, dmr)
    }
}

impl<R: Registers> embedded_can::nb::Can for Drcc<R> {
    type Frame = Frame;
    type Error = Error;

    /// Queues the frame (queue A in normal mode); `WouldBlock` while the queue
    /// is full. A queued frame is never replaced by a new one (the queues are
    /// FIFOs; [`Drcc::abort`] drops frames explicitly): `Ok(None)`.
    fn transmit(&mut self, frame: &Frame) -> nb::Result<Option<Frame>, Error> {
        match self.send(frame, Channel::A) {
            Ok(()) => Ok(None),
            Err(Error::Full) => Err(nb::Error::WouldBlock),
            Err(e) => Err(nb::Error::Other(e)),
        }
    }

    /// The head of the RX FIFO; `WouldBlock` while it is empty.
    fn receive(&mut self) -> nb::Result<Frame, Error> {
        self.try_receive().ok_or(nb::Error::WouldBlock)
    }
}

impl<R: Registers> embedded_can::blocking::Can for Drcc<R> {
    type Frame = Frame;
    type Error = Error;

    /// Queues the frame, polling while the queue is full.
    fn transmit(&mut self, frame: &Frame) -> Result<(), Error> {
        nb::block!(embedded_can::nb::Can::transmit(self, frame)).map(|_| ())
    }

    /// Polls until a frame is in the RX FIFO and takes it.
    fn receive(&mut self) -> Result<Frame, Error> {
        nb::block!(embedded_can::nb::Can::receive(self))
    }
}
