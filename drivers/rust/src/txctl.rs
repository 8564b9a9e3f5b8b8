//! Transmit abort (`TX_CMD.abort_a` / `abort_b`, contract §11.5, map 1.2) and
//! manual bus-off recovery (`TX_CMD.recover_a` / `recover_b` with
//! `CTRL.busoff_manual`, contract §11.6, map 1.3).

use crate::frame::Channel;
use crate::regs;
use crate::{Drcc, Error, Registers};

/// `VERSION.minor` from which `TX_CMD.abort_a` / `abort_b` exist.
pub const MINOR_ABORT: u8 = 2;
/// `VERSION.minor` from which `CTRL.busoff_manual` and `TX_CMD.recover_a` /
/// `recover_b` exist.
pub const MINOR_BUSOFF_MANUAL: u8 = 3;

/// A non-empty set of channels: [`Drcc::abort`] and [`Drcc::recover`] act on
/// all of them in one register write (at the same clock). A single
/// [`Channel`] converts into it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Channels {
    a: bool,
    b: bool,
}

impl Channels {
    /// Channel A (queue A).
    pub const A: Channels = Channels { a: true, b: false };
    /// Channel B (queue B).
    pub const B: Channels = Channels { a: false, b: true };
    /// Both channels.
    pub const BOTH: Channels = Channels { a: true, b: true };

    /// Whether the set holds `channel`.
    pub fn contains(self, channel: Channel) -> bool {
        match channel {
            Channel::A => self.a,
            Channel::B => self.b,
        }
    }

    /// The `TX_CMD` word with `a` for channel A and `b` for channel B.
    fn bits(self, a: u32, b: u32) -> u32 {
        (if self.a { a } else { 0 }) | (if self.b { b } else { 0 })
    }
}

impl From<Channel> for Channels {
    fn from(channel: Channel) -> Channels {
        match channel {
            Channel::A => Channels::A,
            Channel::B => Channels::B,
        }
    }
}

impl<R: Registers> Drcc<R> {
    /// Transmit abort of the queues in `channels` (`TX_CMD.abort_a` /
    /// `abort_b`, one write).
    ///
    /// - Normal mode: the queue's frames that no channel holds yet are
    ///   dropped (no event); the frame the channel holds is aborted as the
    ///   SJA1000's `CMR.AT` does: dropped at once if it is not on the bus,
    ///   else the attempt in progress ends (a success stays a success) and is
    ///   not retried. Either way that frame ends with `INT_STATUS.tx_done` or
    ///   `tx_failure` and the channel's per-channel bit
    ///   ([`crate::IrqResult::tx_done_on`], [`crate::IrqResult::tx_failure_on`]),
    ///   and the queue count drops to 0.
    /// - Redundancy mode: one logical queue, aborted whatever `channels`
    ///   holds (`abort_a`). Its head, the message the redundancy manager
    ///   holds, is kept and ends as every message does (sent once, or
    ///   failed); the messages behind it are dropped.
    /// - DMR mode: the hardware refuses an abort (CiA 701 sends every message
    ///   on both lines): [`Error::State`], nothing written.
    /// - Reset mode: the queues are empty; the write does nothing.
    ///
    /// [`Error::Unsupported`] (nothing written) below map 1.2.
    pub fn abort(&mut self, channels: impl Into<Channels>) -> Result<(), Error> {
        let channels = channels.into();
        if self.ident().minor < MINOR_ABORT {
            return Err(Error::Unsupported);
        }
        if self.ctrl & regs::CTRL_DMR_MASK != 0 {
            return Err(Error::State);
        }
        let cmd = if self.ctrl & regs::CTRL_REDUNDANCY_MASK != 0 {
            regs::TX_CMD_ABORT_A_MASK
        } else {
            channels.bits(regs::TX_CMD_ABORT_A_MASK, regs::TX_CMD_ABORT_B_MASK)
        };
        self.regs.write32(regs::TX_CMD_OFFSET, cmd);
        Ok(())
    }

    /// Manual bus-off recovery (`TX_CMD.recover_a` / `recover_b`, one
    /// write): allows the channels in `channels`, when bus-off and held by
    /// [`crate::Config::busoff_manual`], to start their recovery: 128 x 11
    /// recessive bits from the write on (never shorter), then error active
    /// (`err_state` 0, `INT_STATUS.err_state`), and the frame the channel
    /// held is sent. The permission is taken only from a bus-off channel:
    /// call it once the channel is bus-off ([`Drcc::status`]); for a channel
    /// that is not bus-off, or without `busoff_manual`, the write does
    /// nothing. Every mode.
    ///
    /// [`Error::Unsupported`] (nothing written) below map 1.3.
    pub fn recover(&mut self, channels: impl Into<Channels>) -> Result<(), Error> {
        let channels = channels.into();
        if self.ident().minor < MINOR_BUSOFF_MANUAL {
            return Err(Error::Unsupported);
        }
        let cmd = channels.bits(regs::TX_CMD_RECOVER_A_MASK, regs::TX_CMD_RECOVER_B_MASK);
        self.regs.write32(regs::TX_CMD_OFFSET, cmd);
        Ok(())
    }
}
