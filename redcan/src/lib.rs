//! # redcan
//!
//! The host side of REDCAN (seed 000: H. Sivencrona, G. Nilsson, F. Björn): a
//! ring of CAN bus sections joined by relay modules (RCM), reconfigured by the
//! nodes when a section or a node fails. Two algorithms, as the ring contract
//! (`cosim/src/model/ring_contract.md`) and `docs/redcan.md` make them precise:
//!
//! - [`central`]: the centralized algorithm (seed §3) on CanKingdom (seed 002):
//!   the King on ring node 0 is the master, every other ring node a slave;
//! - [`distributed`]: the distributed algorithm (seed §4): no master, every ring
//!   node runs the same rules from its own detection time.
//!
//! Both are plain state machines for a `no_std` node with an allocator: `poll`
//! takes the caller's time in microseconds and the frames received since the
//! last poll, as any [`embedded_can::Frame`]; the letters to send wait in
//! `outbox` (after giving up the node's queued frames when `flush` is set), and
//! the relay command for the node's RCM in `command`. Nothing here keeps a clock
//! or touches a controller.

#![no_std]

extern crate alloc;

pub mod central;
pub mod distributed;

use embedded_can::{Frame, Id, StandardId};

/// RCM control word (ring contract §2): connect left, disconnect right (a bus
/// end towards the left; the master's rest position holds both terminations).
pub const CONNECT_LEFT: u8 = 0b01;
/// Connect right, disconnect left.
pub const CONNECT_RIGHT: u8 = 0b10;
/// Relay closed: the node's two sections are one bus.
pub const TRANSPARENT: u8 = 0b11;

/// A letter (data frame) on the 11-bit envelope `envelope`, with `data` (at most
/// 8 bytes). Every envelope of this crate is an 11-bit one by construction.
fn letter<F: Frame>(envelope: u32, data: &[u8]) -> F {
    let id = StandardId::new((envelope & 0x7FF) as u16).expect("11 bits");
    F::new(id, data).expect("at most 8 data bytes")
}

/// The identifier of `f`, 11 or 29 bits.
fn raw_id<F: Frame>(f: &F) -> u32 {
    match f.id() {
        Id::Standard(s) => s.as_raw() as u32,
        Id::Extended(e) => e.as_raw(),
    }
}

/// The envelope and data of a base-format data frame; `None` for an extended or
/// a remote frame.
fn base_data<F: Frame>(f: &F) -> Option<(u32, &[u8])> {
    if f.is_extended() || f.is_remote_frame() {
        return None;
    }
    Some((raw_id(f), f.data()))
}

#[cfg(test)]
mod tests;
