//! Conformance of the SJA1000 view to the SJA1000 data sheet (PeliCAN mode,
//! "DS" 6.4 and 6.5) and to `pelican_contract.md` (rules `P-...`): one test, or
//! a few, per row of the table "Every SJA1000 PeliCAN behaviour, and its state
//! here" of `docs/pelican.md`, named after the behaviour. Rows marked "differs"
//! or "refused" test the documented difference.
//!
//! Expected values come from the data sheet and the contract, never from the
//! model; each assertion group names its source. Frames are used only where a
//! bit needs one, so that the lock step (`pelican_lockstep.rs`) stays fast.
//!
//! - `map`: every address 0..127: reset value, read-back, reset vs operating
//!   mode writes, read-only and reserved addresses, RAM windows, extension,
//!   lanes.
//! - `mode`: MOD (RM, LOM, STM, AFM, SM) and the common registers of DS 6.5
//!   (BTR0, BTR1 bit timing; OCR, CDR, BasicCAN).
//! - `command`: CMR (TR, AT, RRB, CDO, SRR; one-shot, self-reception).
//! - `status_interrupt`: SR, IR, IER, `irq`.
//! - `capture`: ALC, ECC, RXERR, TXERR, EWLR, bus-off.
//! - `filter`: ACR/AMR single and dual filter, own frames.
//! - `logical`: the channel in use's captures and counters, bus-off with
//!   redundancy.
//! - `buffers`: TX buffer and RX window layout, RMC, RBSA, FIFO and overrun,
//!   entering reset mode.
//! - `window`: the extension's window onto the native registers (P-X-3, P-X-4).

mod buffers;
mod capture;
mod command;
mod filter;
mod logical;
mod map;
mod mode;
mod status_interrupt;
mod window;

use crate::harness::*;
use drcc_cosim::model::pelican::PelicanParams;
use drcc_cosim::Frame;

/// Register addresses (DS 6.4.1, PeliCAN address allocation; P-MAP-1, §13).
pub mod reg {
    pub const MOD: u8 = 0;
    pub const CMR: u8 = 1;
    pub const SR: u8 = 2;
    pub const IR: u8 = 3;
    pub const IER: u8 = 4;
    pub const BTR0: u8 = 6;
    pub const BTR1: u8 = 7;
    pub const OCR: u8 = 8;
    pub const ALC: u8 = 11;
    pub const ECC: u8 = 12;
    pub const EWLR: u8 = 13;
    pub const RXERR: u8 = 14;
    pub const TXERR: u8 = 15;
    pub const WIN: u8 = 16;
    pub const RMC: u8 = 29;
    pub const RBSA: u8 = 30;
    pub const CDR: u8 = 31;
    pub const TXB: u8 = 96;
    pub const XMODE: u8 = 115;
    pub const XK: u8 = 116;
    pub const XSTAT: u8 = 117;
    pub const XERR: u8 = 118;
    pub const XIR: u8 = 120;
    pub const XIER: u8 = 121;
}

/// MOD bits (DS 6.4.3).
pub mod md {
    pub const RM: u8 = 0x01;
    pub const LOM: u8 = 0x02;
    pub const STM: u8 = 0x04;
    pub const AFM: u8 = 0x08;
    pub const SM: u8 = 0x10;
}

/// CMR bits (DS 6.4.4).
pub mod cmd {
    pub const TR: u8 = 0x01;
    pub const AT: u8 = 0x02;
    pub const RRB: u8 = 0x04;
    pub const CDO: u8 = 0x08;
    pub const SRR: u8 = 0x10;
}

/// SR bits (DS 6.4.5).
pub mod sr {
    pub const RBS: u8 = 0x01;
    pub const DOS: u8 = 0x02;
    pub const TBS: u8 = 0x04;
    pub const TCS: u8 = 0x08;
    pub const RS: u8 = 0x10;
    pub const TS: u8 = 0x20;
    pub const ES: u8 = 0x40;
    pub const BS: u8 = 0x80;
}

/// IR bits (DS 6.4.6); IER has the same layout (DS 6.4.7).
pub mod ir {
    pub const RI: u8 = 0x01;
    pub const TI: u8 = 0x02;
    pub const EI: u8 = 0x04;
    pub const DOI: u8 = 0x08;
    pub const WUI: u8 = 0x10;
    pub const EPI: u8 = 0x20;
    pub const ALI: u8 = 0x40;
    pub const BEI: u8 = 0x80;
}

/// XIR bits (§13).
pub mod xir {
    pub const SWITCH: u8 = 0x01;
    pub const BUS: u8 = 0x20;
    pub const WIN: u8 = 0x40;
    pub const IGN: u8 = 0x80;
}

/// A `single_a` top at stride 4 with SJA1000 bus-off, started as Linux does
/// (reset mode, accept all, `ier`), in operating mode with `mod_` and
/// integrated on the bus.
pub fn op_single(ier: u8, mod_: u8) -> Net {
    let mut n = Net::keyed(single_a(4, true));
    n.linux_start(ier, mod_);
    n
}

/// The same on a top with parameters `p`.
pub fn op_with(p: PelicanParams, ier: u8, mod_: u8) -> Net {
    let mut n = Net::keyed(p);
    n.linux_start(ier, mod_);
    n
}

/// Run until `SR.TBS` (the message completed), then two clocks so that a bus
/// read sees everything the completion set (§15).
pub fn wait_tbs(n: &mut Net, max_bits: u64) {
    n.until(max_bits * BIT, |n| n.dut.read(reg::SR) & sr::TBS != 0);
    n.idle(2);
}

/// The peer of line `x` sends `f`; returns when it has completed it (and the
/// DUT's FIFO write, if any, is visible to a read, §15).
pub fn peer_sends(n: &mut Net, x: usize, f: Frame) {
    n.peer_req[x] = Some(f);
    n.until(600 * BIT, |n| {
        n.peer_req[x].is_none() && !n.peer_out[x].tx_pending
    });
    n.idle(4);
}

/// Both peers send `f` at once (the redundant copies of one message);
/// returns when the RX writer has judged both copies (its duplicate scan
/// takes H + 3 clocks a copy, drcc contract §7).
pub fn peers_send_both(n: &mut Net, f: Frame) {
    n.peer_req = [Some(f), Some(f)];
    n.until(600 * BIT, |n| {
        (0..2).all(|x| n.peer_req[x].is_none() && !n.peer_out[x].tx_pending)
    });
    n.idle(6 * BIT);
}

/// One clock with `rst`: a hardware reset in the middle of a test.
pub fn hardware_reset(n: &mut Net) {
    n.hardware_reset();
}

/// A standard remote frame.
pub fn base_rtr(id: u32, dlc: u8) -> Frame {
    Frame {
        rtr: true,
        dlc,
        ..Frame::base(id, &[])
    }
}

/// An extended remote frame.
pub fn ext_rtr(id: u32, dlc: u8) -> Frame {
    Frame {
        rtr: true,
        dlc,
        ..ext(id, &[])
    }
}
