//! `drcc-driver`: a `#![no_std]` driver for the DRCC dual-redundancy CAN 2.0B
//! controller, through its own Wishbone register view (`docs/registers.md`).
//!
//! Register access goes through [`Registers`], which the user implements
//! (`read32` / `write32` at byte offsets, e.g. volatile accesses to the mapped
//! base). [`Drcc`] brings the controller up ([`Drcc::configure`]), switches
//! between normal, redundancy and DMR mode, sends and receives [`Frame`]s,
//! drains the receive FIFO from an interrupt handler ([`Drcc::isr`]) and reads
//! status and statistics. It implements `embedded-can` 0.4's
//! [`embedded_can::blocking::Can`] and [`embedded_can::nb::Can`].
//!
//! Identification: [`Drcc::new`] reads `VERSION` and `SIZES` ([`Drcc::ident`],
//! [`Ident`]) and refuses a register map whose major version is not 1
//! ([`Error::Version`]). Acceptance filters: [`Drcc::set_filter`] with a
//! [`Filter`], [`Drcc::clear_filters`]. Every received [`Frame`] carries its
//! RX FIFO timestamp in nominal bit times ([`Frame::timestamp`]), and
//! [`Drcc::now`] reads the same clock. [`Drcc::clear_stats`] clears the
//! statistics. The error and arbitration-lost captures ([`Capture`]) are read
//! by [`Drcc::captures`] and by the interrupt handler before it acknowledges
//! (which re-arms them, [`Drcc::rearm_captures`]); [`IrqResult`] decodes the
//! bus-error, arbitration-lost, error-warning and per-channel transmit events.
//!
//! The register constants in [`regs`] are generated at build time from the C
//! header `rtl-out/drcc_regs.h`. The C driver in `drivers/c` offers the same
//! functions.
//!
//! Transmit abort ([`Drcc::abort`], map 1.2) and manual bus-off recovery
//! ([`Config::busoff_manual`], [`Drcc::recover`], map 1.3) act on a set of
//! [`Channels`]; on an instance whose `VERSION.minor` is older they return
//! [`Error::Unsupported`] and write nothing.
#![no_std]
#![deny(missing_docs)]

mod config;
mod device;
mod features;
mod frame;
pub mod regs;
mod status;
mod timing;
mod txctl;

pub use config::{ChanMode, Config, DmrConfig, Mode, Policy, MINOR_FIRST_COPY};
pub use device::{Drcc, IrqResult};
pub use features::{Capture, Filter, Ident};
pub use frame::{Channel, Frame};
pub use status::{ChanStatus, Stats, Status};
pub use timing::BitTiming;
pub use txctl::{Channels, MINOR_ABORT, MINOR_BUSOFF_MANUAL};

/// Register access the user provides: 32-bit words at byte offsets
/// (`regs::*_OFFSET`).
pub trait Registers {
    /// Reads the word at byte offset `offset`.
    fn read32(&mut self, offset: u32) -> u32;
    /// Writes the whole word at byte offset `offset`.
    fn write32(&mut self, offset: u32, value: u32);
}

impl<R: Registers + ?Sized> Registers for &mut R {
    fn read32(&mut self, offset: u32) -> u32 {
        (**self).read32(offset)
    }
    fn write32(&mut self, offset: u32, value: u32) {
        (**self).write32(offset, value)
    }
}

/// Errors of the driver (the C driver's `DRCC_E_*`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Error {
    /// An argument is out of range (identifier, DLC, field value).
    Invalid,
    /// No bit timing gives exactly the bit rate from the clock.
    NoTiming,
    /// The `ID` register does not read "DRCC".
    NoDevice,
    /// The controller did not take a write (read back differs): a mode the top
    /// was generated without, redundancy with a listen-only channel, ...
    Refused,
    /// The target TX queue is full.
    Full,
    /// The RX FIFO is empty.
    Empty,
    /// The controller is not in the state the call needs (e.g. reset mode).
    State,
    /// `VERSION.major` is not 1: a register map this driver does not know.
    Version,
    /// The instance's `VERSION.minor` is below the one the feature needs
    /// ([`MINOR_ABORT`], [`MINOR_BUSOFF_MANUAL`], [`MINOR_FIRST_COPY`]); nothing
    /// was written.
    Unsupported,
}

impl embedded_can::Error for Error {
    fn kind(&self) -> embedded_can::ErrorKind {
        embedded_can::ErrorKind::Other
    }
}
