//! The SJA1000 transmit buffer and the three free RAM bytes (pelican_contract.md
//! P-TX-1, P-MAP-1/3; SJA1000 data sheet 6.4.13 "transmit buffer", the
//! "PeliCAN address allocation" table), and the frame it holds in the DRCC's
//! frame layout.
//!
//! Thirteen bytes `TXB[0..12]`: written through the window 16..28 in operating
//! mode while `TBS = 1` (a write while the buffer is locked is ignored), and at
//! the internal RAM addresses 96..108 in reset mode; read back at 96..108 in
//! both modes. `SCR0..2` (109..111) are written in reset mode and read in both.
//! In both ranges the byte index is `addr[3:0]` (16 = 0x10, 96 = 0x60). `TXB`
//! has no reset (its power-up value is 0); `rst` clears `SCR0..2`.
//!
//! Layout (data sheet "TX frame information", "TX identifier", "TX data"):
//! `TXB[0]` = FI: [7] FF (extended), [6] RTR, [3:0] DLC. Standard: `id[10:3] =
//! TXB[1]`, `id[2:0] = TXB[2][7:5]`, data bytes 1..8 = `TXB[3..10]`.
//! Extended: `id[28:21] = TXB[1]`, `id[20:13] = TXB[2]`, `id[12:5] = TXB[3]`,
//! `id[4:0] = TXB[4][7:3]`, data = `TXB[5..12]`. The frame goes to the core
//! as written; the core's push normalizes it (DRCC contract §6).

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The 13-byte transmit buffer and the scratch bytes.
#[derive(LogicBlock, Default)]
pub struct TxFrameBuffer {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: clears `SCR0..2` only.
    pub rst: Signal<In, Bit>,
    // ---- the host's register access ----
    /// A register write is taken at this edge.
    pub wr: Signal<In, Bit>,
    /// The register number 0..127 (`reg` is a Verilog keyword).
    pub addr: Signal<In, Bits<7>>,
    /// The byte written.
    pub wdata: Signal<In, Bits<8>>,
    /// `MOD.RM` before the edge: reset mode.
    pub rm: Signal<In, Bit>,
    /// `SR.TBS` before the edge: the buffer is released (writable in operating mode).
    pub tbs: Signal<In, Bit>,
    /// The byte at `addr` for a read of 96..111 (0 elsewhere).
    pub rdata: Signal<Out, Bits<8>>,
    // ---- to the core ----
    /// The frame in the DRCC layout: [98] rtr, [97] ide, [96:68] id, [67:64]
    /// dlc, [63:0] data (byte 1 of the data sheet in [63:56]).
    pub frame: Signal<Out, Bits<99>>,
    // ---- registers: TXB[0..12], SCR0..2 ----
    txb0: DFF<Bits<8>>,
    txb1: DFF<Bits<8>>,
    txb2: DFF<Bits<8>>,
    txb3: DFF<Bits<8>>,
    txb4: DFF<Bits<8>>,
    txb5: DFF<Bits<8>>,
    txb6: DFF<Bits<8>>,
    txb7: DFF<Bits<8>>,
    txb8: DFF<Bits<8>>,
    txb9: DFF<Bits<8>>,
    txb10: DFF<Bits<8>>,
    txb11: DFF<Bits<8>>,
    txb12: DFF<Bits<8>>,
    scr0: DFF<Bits<8>>,
    scr1: DFF<Bits<8>>,
    scr2: DFF<Bits<8>>,
    // ---- decode ----
    /// The byte index `addr[3:0]`.
    idx: Signal<Local, Bits<4>>,
    /// A write lands in the buffer (window or RAM address, mode allowing).
    write_txb: Signal<Local, Bit>,
    /// A write lands in `SCR0..2`.
    write_scr: Signal<Local, Bit>,
    /// `addr` is 96..111.
    ram_page: Signal<Local, Bit>,
    id_std: Signal<Local, Bits<29>>,
    id_ext: Signal<Local, Bits<29>>,
    data_std: Signal<Local, Bits<64>>,
    data_ext: Signal<Local, Bits<64>>,
    /// RTR and IDE in place in the frame word.
    fi_flags: Signal<Local, Bits<99>>,
    page_window: Const<3, 1>,
    page_ram: Const<3, 6>,
    last_txb: Const<4, 12>,
    zero8: Const<8, 0>,
}

impl Logic for TxFrameBuffer {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, txb0, txb1, txb2, txb3, txb4, txb5, txb6, txb7, txb8, txb9, txb10, txb11,
            txb12, scr0, scr1, scr2
        );
        self.idx.next = self.addr.val().get_bits::<4>(0);
        self.ram_page.next = self.addr.val().get_bits::<3>(4) == self.page_ram.val();
        // P-TX-1: the window 16..28 in operating mode with TBS = 1; the RAM
        // addresses 96..108 in reset mode. P-MAP-1: SCR0..2 in reset mode.
        self.write_txb.next = self.wr.val()
            && (self.idx.val() <= self.last_txb.val())
            && (((self.addr.val().get_bits::<3>(4) == self.page_window.val())
                && !self.rm.val()
                && self.tbs.val())
                || (self.ram_page.val() && self.rm.val()));
        self.write_scr.next = self.wr.val()
            && self.ram_page.val()
            && (self.idx.val() > self.last_txb.val())
            && self.rm.val();
        if self.write_txb.val() {
            match self.idx.val().index() {
                0 => self.txb0.d.next = self.wdata.val(),
                1 => self.txb1.d.next = self.wdata.val(),
                2 => self.txb2.d.next = self.wdata.val(),
                3 => self.txb3.d.next = self.wdata.val(),
                4 => self.txb4.d.next = self.wdata.val(),
                5 => self.txb5.d.next = self.wdata.val(),
                6 => self.txb6.d.next = self.wdata.val(),
                7 => self.txb7.d.next = self.wdata.val(),
                8 => self.txb8.d.next = self.wdata.val(),
                9 => self.txb9.d.next = self.wdata.val(),
                10 => self.txb10.d.next = self.wdata.val(),
                11 => self.txb11.d.next = self.wdata.val(),
                _ => self.txb12.d.next = self.wdata.val(),
            }
        }
        if self.write_scr.val() {
            match self.idx.val().index() {
                13 => self.scr0.d.next = self.wdata.val(),
                14 => self.scr1.d.next = self.wdata.val(),
                _ => self.scr2.d.next = self.wdata.val(),
            }
        }
        if self.rst.val() {
            self.scr0.d.next = self.zero8.val();
            self.scr1.d.next = self.zero8.val();
            self.scr2.d.next = self.zero8.val();
        }

        // ---- read back at 96..111
        self.rdata.next = self.zero8.val();
        if self.ram_page.val() {
            match self.idx.val().index() {
                0 => self.rdata.next = self.txb0.q.val(),
                1 => self.rdata.next = self.txb1.q.val(),
                2 => self.rdata.next = self.txb2.q.val(),
                3 => self.rdata.next = self.txb3.q.val(),
                4 => self.rdata.next = self.txb4.q.val(),
                5 => self.rdata.next = self.txb5.q.val(),
                6 => self.rdata.next = self.txb6.q.val(),
                7 => self.rdata.next = self.txb7.q.val(),
                8 => self.rdata.next = self.txb8.q.val(),
                9 => self.rdata.next = self.txb9.q.val(),
                10 => self.rdata.next = self.txb10.q.val(),
                11 => self.rdata.next = self.txb11.q.val(),
                12 => self.rdata.next = self.txb12.q.val(),
                13 => self.rdata.next = self.scr0.q.val(),
                14 => self.rdata.next = self.scr1.q.val(),
                _ => self.rdata.next = self.scr2.q.val(),
            }
        }

        // ---- the frame, in the data sheet's two layouts
        self.id_std.next = (bit_cast::<29, 8>(self.txb1.q.val()) << 3)
            | bit_cast::<29, 3>(self.txb2.q.val().get_bits::<3>(5));
        self.id_ext.next = (bit_cast::<29, 8>(self.txb1.q.val()) << 21)
            | (bit_cast::<29, 8>(self.txb2.q.val()) << 13)
            | (bit_cast::<29, 8>(self.txb3.q.val()) << 5)
            | bit_cast::<29, 5>(self.txb4.q.val().get_bits::<5>(3));
        self.data_std.next = (bit_cast::<64, 8>(self.txb3.q.val()) << 56)
            | (bit_cast::<64, 8>(self.txb4.q.val()) << 48)
            | (bit_cast::<64, 8>(self.txb5.q.val()) << 40)
            | (bit_cast::<64, 8>(self.txb6.q.val()) << 32)
            | (bit_cast::<64, 8>(self.txb7.q.val()) << 24)
            | (bit_cast::<64, 8>(self.txb8.q.val()) << 16)
            | (bit_cast::<64, 8>(self.txb9.q.val()) << 8)
            | bit_cast::<64, 8>(self.txb10.q.val());
        self.data_ext.next = (bit_cast::<64, 8>(self.txb5.q.val()) << 56)
            | (bit_cast::<64, 8>(self.txb6.q.val()) << 48)
            | (bit_cast::<64, 8>(self.txb7.q.val()) << 40)
            | (bit_cast::<64, 8>(self.txb8.q.val()) << 32)
            | (bit_cast::<64, 8>(self.txb9.q.val()) << 24)
            | (bit_cast::<64, 8>(self.txb10.q.val()) << 16)
            | (bit_cast::<64, 8>(self.txb11.q.val()) << 8)
            | bit_cast::<64, 8>(self.txb12.q.val());
        // FI: [7] FF, [6] RTR, [3:0] DLC; the frame word has rtr at 98, ide at 97.
        self.fi_flags.next = (bit_cast::<99, 1>(self.txb0.q.val().get_bit(6).into()) << 98)
            | (bit_cast::<99, 1>(self.txb0.q.val().get_bit(7).into()) << 97);
        if self.txb0.q.val().get_bit(7) {
            self.frame.next = self.fi_flags.val()
                | (bit_cast::<99, 29>(self.id_ext.val()) << 68)
                | (bit_cast::<99, 4>(self.txb0.q.val().get_bits::<4>(0)) << 64)
                | bit_cast::<99, 64>(self.data_ext.val());
        } else {
            self.frame.next = self.fi_flags.val()
                | (bit_cast::<99, 29>(self.id_std.val()) << 68)
                | (bit_cast::<99, 4>(self.txb0.q.val().get_bits::<4>(0)) << 64)
                | bit_cast::<99, 64>(self.data_std.val());
        }
    }
}
