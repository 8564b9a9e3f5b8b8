//! Reference model of the bus front ends (the APB and AXI4-Lite bridges in front of
//! the register port), written clock by clock from their contract, `bus_contract.md`
//! (included below as [`contract`]), and the AMBA specifications it cites (APB
//! protocol v2.0, AXI and ACE protocol, AXI4-Lite subset). It is independent of the
//! RTL: nothing here is derived from the generated Verilog or the rust-hdl blocks.
//!
//! - [`ApbBridge`] (§2, [`apb`]) is combinational: [`ApbBridge::port_in`] maps this
//!   clock's APB inputs to the register port, [`ApbBridge::outputs`] maps the register
//!   port's outputs to the APB outputs.
//! - [`AxiLiteBridge`] (§3, [`axi_lite`]) is registered: the register port's inputs
//!   and the bus outputs come from its state only; [`AxiLiteBridge::edge`] applies
//!   rules 1 to 4 of §3 to the values before the edge.
//!
//! The register block behind the port (§1) is not modelled here; [`PortIn`] and
//! [`PortOut`] are the seam. Composition per clock (a registered design, every
//! next-state value from the values before the edge): `pin = bridge.port_in(..)`;
//! `port_before` = the register block's outputs after the previous edge; step the
//! register block with `pin` (or reset it); `bridge.edge(&bus_in, &port_before)` (or
//! [`AxiLiteBridge::reset`] when `rst`); then `bridge.outputs(..)`.
//!
//! ## Interpretations (where the contract leaves a choice)
//!
//! 1. Field widths: `PortIn::adr` is the word index (6 bits on the native and hub
//!    tops, 7 on the SJA1000 view's), `PortIn::sel` and every strobe 4 bits. Input
//!    bits above a port's width (`pstrb[7:4]`, `wstrb[7:4]`) are ignored (masked
//!    off), as a narrower port would. A byte address is the value its port
//!    carries (8 bits, or 9 on the view's tops: the caller gives no wider one),
//!    so `paddr[A-1:2]` / `awaddr[A-1:2]` / `araddr[A-1:2]` always fit 7 bits.
//! 2. APB: the bridge passes the register port straight through, in every clock and
//!    every phase: `wb_we_i`, `wb_adr_i`, `wb_dat_i` and `wb_sel_i` follow the inputs
//!    even when `psel & penable` is 0 (only `cyc` gates the port). `prdata` is
//!    `wb_dat_o` unmasked: it is 0 outside an acknowledged read because §1 says
//!    `wb_dat_o` is, not because the bridge masks it. The bridge checks no APB rule
//!    (an access phase without a setup phase, or one held after `pready`, is passed
//!    to the port as it is; the latter makes the port take a second access two
//!    clocks later, which is the master's protocol error).
//! 3. AXI: the registers `we`, `aw_adr`, `ar_adr`, `w_dat`, `w_strb` are not
//!    cleared when an access ends, so the register port's `we`, `adr`, `dat`, `sel`
//!    keep their last values while `cyc` is 0 (the port ignores them there). During
//!    a read, `wb_dat_i` and `wb_sel_i` are still `w_dat` and `w_strb`, which change
//!    if W takes a new beat while the read is in flight (`wready` is 1 then): the
//!    contract says so, and §1 ignores both on reads. Likewise
//!    `bresp`, `rdata` and `rresp` keep the last response after their valid falls
//!    (AXI leaves them undefined while the valid is low).
//! 4. AXI rule 3 decides write or read by `we` (the kind of the access started), and
//!    the response by `wb_err_o` alone: if a faulty port raised `ack` and `err`
//!    together, the response would be `SLVERR`. `done` while `cyc` is 0 is ignored.
//! 5. AXI rules 1 to 4 are applied to the values before the edge; in every reachable
//!    state no register is written by two rules at one edge (§3 rules 4 and 5 say
//!    why), so their order does not matter; the model applies them in the order 1, 2,
//!    3, 4.
//! 6. AXI timing (§3 "Timing"): "after the third edge from there" counts the edges
//!    after the one that takes AW and W: that edge is E0, the access starts at E1,
//!    the port takes it at E2 and it ends at E3, so `bvalid` is 1 in the clock after
//!    E3. The same holds for AR and `rvalid`.
//! 7. `rst` clears only the bridge ([`AxiLiteBridge::reset`]); the register block's
//!    reset is the composer's. The APB bridge has no state, so `rst` does nothing to
//!    it.

pub mod apb;
pub mod axi_lite;
#[cfg(test)]
mod fake_regs;

pub use apb::{ApbBridge, ApbIn, ApbOut};
pub use axi_lite::{AxiIn, AxiLiteBridge, AxiOut};

/// The clock-level contract this model follows (`bus_contract.md`).
#[doc = include_str!("../bus_contract.md")]
pub mod contract {}

/// AXI response code `OKAY` (`2'b00`).
pub const OKAY: u8 = 0;
/// AXI response code `SLVERR` (`2'b10`).
pub const SLVERR: u8 = 2;

/// The register port's inputs, driven by a front end into the register block
/// (contract §1; `cyc` stands for `wb_cyc_i = wb_stb_i`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PortIn {
    /// `wb_cyc_i` and `wb_stb_i` (always equal from these front ends).
    pub cyc: bool,
    /// `wb_we_i`.
    pub we: bool,
    /// `wb_adr_i[W-1:0]`: the word index (byte address / 4).
    pub adr: u8,
    /// `wb_dat_i`.
    pub dat: u32,
    /// `wb_sel_i[3:0]`: byte lane `i` is `dat[8i+7:8i]`.
    pub sel: u8,
}

/// The register port's outputs (from the register block) after an edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PortOut {
    /// `wb_ack_o`.
    pub ack: bool,
    /// `wb_err_o`.
    pub err: bool,
    /// `wb_dat_o`.
    pub dat: u32,
}

/// The word index of a byte address: `addr[A-1:2]`, at most 7 bits (the
/// port's byte address is `A` = 8 bits wide on the native and hub tops, 9 on
/// the SJA1000 view's; Interpretation 1).
#[inline]
fn word_index(byte_addr: u16) -> u8 {
    ((byte_addr >> 2) & 0x7F) as u8
}

/// A 4-bit byte-lane strobe from a wider field (Interpretation 1).
#[inline]
fn strobe(s: u8) -> u8 {
    s & 0xF
}
