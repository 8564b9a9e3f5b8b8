//! The SJA1000 receive buffer start address `RBSA` (pelican_contract.md P-RX-4;
//! SJA1000 data sheet 6.4.17): the byte address in the SJA1000's 64-byte RX
//! FIFO where the frame at the head would start. The DRCC stores frames in
//! slots, so the register addresses nothing here; it advances as the data
//! sheet's does, for software that reads it.
//!
//! At every release of the receive buffer (a pop): `RBSA <= (RBSA + len) mod
//! 64`, `len = 3 + 2 x ide + (rtr ? 0 : min(dlc, 8))` of the released frame
//! (FI, two or four identifier bytes, the data). A host write in reset mode
//! sets it (bits [5:0]); `rst` clears it; reset mode keeps it.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// `RBSA` and its advance.
#[derive(LogicBlock, Default)]
pub struct Rbsa {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: `RBSA` 0.
    pub rst: Signal<In, Bit>,
    // ---- the released frame ----
    /// The receive buffer is released at this edge (the FIFO pops its head).
    pub pop: Signal<In, Bit>,
    /// The released frame's IDE (extended: four identifier bytes).
    pub ide: Signal<In, Bit>,
    /// The released frame's RTR (remote: no data bytes).
    pub rtr: Signal<In, Bit>,
    /// The released frame's DLC (9..15 carry 8 bytes).
    pub dlc: Signal<In, Bits<4>>,
    // ---- the host ----
    /// A write of `RBSA` in reset mode is taken at this edge.
    pub write: Signal<In, Bit>,
    /// Bits [5:0] of the byte written (the register keeps six).
    pub wdata: Signal<In, Bits<6>>,
    /// `RBSA` as read: [5:0] the address, [7:6] 0.
    pub rbsa: Signal<Out, Bits<8>>,
    // ---- registers ----
    addr: DFF<Bits<6>>,
    /// The released frame's length in FIFO bytes.
    len: Signal<Local, Bits<6>>,
    data_len: Signal<Local, Bits<6>>,
    hdr_std: Const<6, 3>,
    hdr_ext: Const<6, 5>,
    eight: Const<6, 8>,
    zero6: Const<6, 0>,
}

impl Logic for Rbsa {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, addr);
        // min(dlc, 8) data bytes; none for a remote frame.
        self.data_len.next = bit_cast::<6, 4>(self.dlc.val());
        if self.dlc.val().get_bit(3) {
            self.data_len.next = self.eight.val();
        }
        if self.rtr.val() {
            self.data_len.next = self.zero6.val();
        }
        self.len.next = self.hdr_std.val() + self.data_len.val();
        if self.ide.val() {
            self.len.next = self.hdr_ext.val() + self.data_len.val();
        }
        // 6-bit sum: mod 64 by construction.
        if self.pop.val() {
            self.addr.d.next = self.addr.q.val() + self.len.val();
        }
        if self.write.val() {
            self.addr.d.next = self.wdata.val();
        }
        if self.rst.val() {
            self.addr.d.next = self.zero6.val();
        }
        self.rbsa.next = bit_cast::<8, 6>(self.addr.q.val());
    }
}
