//! Traffic export: what the nodes of a simulated network delivered, and the errors
//! they saw, as events ([`TrafficEvent`]) that can be written as a candump log
//! ([`candump`]) or a pcap file ([`pcap`]) for the user's own CAN tools, or handed
//! to clients as they happen (`drcc serve`).
//!
//! Time is simulated time: cycle / clock in Hz, from 0 at the first clock.
//!
//! # Which signal becomes which event
//!
//! A bus of CAN channels ([`ChannelTap`], timing contract §4.4, §4.5, §9), per node:
//!
//! | signal | event |
//! |---|---|
//! | `rx_valid` with `rx_frame` | [`TrafficKind::Frame`]: the frame the node delivered |
//! | `err_valid` with `err_kind`, `err_field`, `err_tx`, `tx` | error frame [`error::CAN_ERR_PROT`] (type bit / stuff / form; bit errors split by the sent value into BIT0 and BIT1; a CRC error is located at the CRC sequence), or [`error::CAN_ERR_ACK`] for an ACK error; with [`error::CAN_ERR_BUSERROR`], `CAN_ERR_PROT_TX` for a transmitter and the location from `err_field` |
//! | `tec`, `rec`, `err_state` and the EWL crossing a boundary | error frame [`error::CAN_ERR_CRTL`] (warning, passive, back to active), [`error::CAN_ERR_BUSOFF`], or [`error::CAN_ERR_RESTARTED`] when bus-off ends |
//!
//! Every error frame carries TEC and REC after the event ([`error::CAN_ERR_CNT`]).
//!
//! DRCC nodes ([`NodeTap`]: on a dual bus or a replicated star), per node and per
//! channel (on a REDCAN ring, channel A only):
//!
//! | signal | event |
//! |---|---|
//! | a frame the host popped from the RX FIFO (`HostDriver::received`) | [`TrafficKind::Frame`] on the line `RX_CTRL.channel` names, at the clock of the pop: the DRCC delivers each message once, after duplicate removal |
//! | `chan_x_field` entering ERROR_FLAG | error frame [`error::CAN_ERR_PROT`] of unspecified type (the DRCC's ports carry no error capture per channel), located at the field it left, with [`error::CAN_ERR_BUSERROR`] |
//! | `chan_x_bsp_tx_err_cnt`, `chan_x_rec`, `chan_x_err_state` and the EWL of `BTR` | state changes as above |
//!
//! A DRCC channel shows neither a new error flag started by a bit error inside its
//! own active error flag (the field stays ERROR_FLAG) nor the error that takes it
//! to bus-off (no flag follows it): there only the bus-off frame appears.
//!
//! # Interface names
//!
//! [`interface`]: `node<i>` on a bus of channels, `node<i>a` / `node<i>b` for the
//! channel on line A / B of a dual bus or a star (`i` is the node index, as in the
//! traces; scenario node names may hold characters a log line cannot). On a REDCAN
//! ring every node, ring or plain, is on the ring with its channel A alone
//! (channel B unwired): `node<i>`, with the ring's node numbering.

pub mod candump;
pub mod error;
pub mod pcap;
mod state;
mod tap;

#[cfg(test)]
mod tests;

pub use error::ErrorFrame;
pub use tap::{ChannelTap, NodeTap};

use crate::frame::Frame;

/// What happened.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrafficKind {
    /// A frame the node delivered to its host.
    Frame(Frame),
    /// An error frame (SocketCAN encoding).
    Error(ErrorFrame),
}

/// One event at one node (and line).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TrafficEvent {
    /// Clock cycle, from 0.
    pub cycle: u64,
    /// Node index.
    pub node: usize,
    /// 0 = line / channel A, 1 = B; `None` on a single-channel bus.
    pub line: Option<u8>,
    /// The frame or error.
    pub kind: TrafficKind,
}

impl TrafficEvent {
    /// The interface name of the event's node and line ([`interface`]).
    pub fn interface(&self) -> String {
        interface(self.node, self.line)
    }
}

/// The interface name of `node` on `line`: `node0`; `node0a`, `node0b`.
pub fn interface(node: usize, line: Option<u8>) -> String {
    match line {
        None => format!("node{node}"),
        Some(0) => format!("node{node}a"),
        Some(_) => format!("node{node}b"),
    }
}

/// Simulated time of `cycle` at `clock_hz`: whole seconds and nanoseconds,
/// rounded down.
pub fn timestamp(cycle: u64, clock_hz: u64) -> (u64, u32) {
    let hz = clock_hz.max(1) as u128;
    let ns = cycle as u128 * 1_000_000_000 / hz;
    ((ns / 1_000_000_000) as u64, (ns % 1_000_000_000) as u32)
}
