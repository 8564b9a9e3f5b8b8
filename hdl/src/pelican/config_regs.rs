//! The SJA1000 view's configuration registers (pelican_contract.md §4, §11,
//! P-CFG-1, P-CFG-2, P-CFG-4, P-CFG-5, P-ACF-1, P-BO-6; SJA1000 data sheet
//! 6.4.5 BTR0/BTR1, 6.4.10 EWLR, 6.4.15 ACR/AMR, 6.5 CDR): `BTR0`, `BTR1`,
//! `OCR`, `EWLR`, `CDR`, `ACR0..3`, `AMR0..3`, and the native `BTR` word the
//! core takes from them.
//!
//! - `BTR0` (6), `BTR1` (7), `OCR` (8), `EWLR` (13) and `ACR0..3`, `AMR0..3`
//!   (16..23) are written only in reset mode (`RM = 1`); in operating mode the
//!   addresses 16..28 are the frame windows, not these.
//! - `CDR` (31): in reset mode `CDR <= byte & 0xEF` (bit 4 stays 0); in
//!   operating mode only `CD[2:0]` (the clock divider, which drives nothing
//!   here) are written.
//! - `reconfig`: a write taken at this edge changes `BTR0`, `BTR1` or `EWLR`
//!   (P-BO-6: while the bus-off hold is on, that is a restart).
//! - The native `BTR` (P-CFG-2): `brp = 2 x BTR0[5:0] + 1`, so one time quantum
//!   is `2 x (BRP + 1)` clocks, as on an SJA1000 with `fosc = clk`.
//!
//! Reset values (§16): `BTR0 0x00`, `BTR1 0x14`, `OCR 0x00`, `EWLR 96`, `CDR
//! 0x00`, `ACR 0x00`, `AMR 0xFF`.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// `BTR0/1`, `OCR`, `EWLR`, `CDR`, `ACR0..3`, `AMR0..3`.
#[derive(LogicBlock, Default)]
pub struct ConfigRegs {
    // ---- clock and reset ----
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: the reset values above.
    pub rst: Signal<In, Bit>,
    // ---- the host's register access ----
    /// A register write is taken at this edge.
    pub wr: Signal<In, Bit>,
    /// The register number 0..127.
    pub addr: Signal<In, Bits<7>>,
    /// The byte written.
    pub wdata: Signal<In, Bits<8>>,
    /// `MOD.RM` before the edge: reset mode.
    pub rm: Signal<In, Bit>,
    /// The byte at `addr` for a read (0 outside this block's registers; 16..23
    /// only in reset mode).
    pub rdata: Signal<Out, Bits<8>>,
    // ---- to the view and the core ----
    /// A write at this edge changes `BTR0`, `BTR1` or `EWLR` (P-BO-6).
    pub reconfig: Signal<Out, Bit>,
    /// The native `BTR` word for the core (P-CFG-2).
    pub view_btr: Signal<Out, Bits<28>>,
    /// `ACR0..3`, `ACR0` in [7:0].
    pub acr: Signal<Out, Bits<32>>,
    /// `AMR0..3`, `AMR0` in [7:0].
    pub amr: Signal<Out, Bits<32>>,
    // ---- registers ----
    btr0: DFF<Bits<8>>,
    btr1: DFF<Bits<8>>,
    ocr: DFF<Bits<8>>,
    ewlr: DFF<Bits<8>>,
    cdr: DFF<Bits<8>>,
    acr_q: DFF<Bits<32>>,
    amr_q: DFF<Bits<32>>,
    // ---- decode ----
    /// `2 x BTR0[5:0] + 1`, the channels' `cfg_brp` (7 bits).
    brp: Signal<Local, Bits<7>>,
    /// `addr` is 16..23 (`addr[6:3] = 2`), and its byte in the words.
    acf_page: Signal<Local, Bit>,
    acf_shift: Signal<Local, Bits<5>>,
    acf_byte: Signal<Local, Bits<32>>,
    /// The addressed word, `ACR` or `AMR`.
    acf_read: Signal<Local, Bits<32>>,
    one7: Const<7, 1>,
    a_btr0: Const<7, 6>,
    a_btr1: Const<7, 7>,
    a_ocr: Const<7, 8>,
    a_ewlr: Const<7, 13>,
    a_cdr: Const<7, 31>,
    page_acf: Const<4, 2>,
    btr1_reset: Const<8, 0x14>,
    ewlr_reset: Const<8, 96>,
    cdr_rm_mask: Const<8, 0xEF>,
    cdr_op_mask: Const<8, 0xF8>,
    cd_mask: Const<8, 0x07>,
    ones32: Const<32, 0xFFFF_FFFF>,
    byte_mask: Const<32, 0xFF>,
    zero8: Const<8, 0>,
    zero32: Const<32, 0>,
}

impl Logic for ConfigRegs {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, btr0, btr1, ocr, ewlr, cdr, acr_q, amr_q);
        self.acf_page.next = self.addr.val().get_bits::<4>(3) == self.page_acf.val();
        // byte k of the 32-bit word: ACR0 / AMR0 in [7:0]
        self.acf_shift.next = bit_cast::<5, 2>(self.addr.val().get_bits::<2>(0)) << 3;
        self.acf_byte.next = bit_cast::<32, 8>(self.wdata.val()) << self.acf_shift.val();
        // ---- writes: P-CFG-1 (reset mode only), P-CFG-5 (CDR) ----
        self.reconfig.next = false;
        if self.wr.val() && self.rm.val() {
            if self.addr.val() == self.a_btr0.val() {
                self.btr0.d.next = self.wdata.val();
                self.reconfig.next = self.wdata.val() != self.btr0.q.val();
            }
            if self.addr.val() == self.a_btr1.val() {
                self.btr1.d.next = self.wdata.val();
                self.reconfig.next = self.wdata.val() != self.btr1.q.val();
            }
            if self.addr.val() == self.a_ocr.val() {
                self.ocr.d.next = self.wdata.val();
            }
            if self.addr.val() == self.a_ewlr.val() {
                self.ewlr.d.next = self.wdata.val();
                self.reconfig.next = self.wdata.val() != self.ewlr.q.val();
            }
            if self.acf_page.val() {
                if self.addr.val().get_bit(2) {
                    self.amr_q.d.next = (self.amr_q.q.val()
                        & !(self.byte_mask.val() << self.acf_shift.val()))
                        | self.acf_byte.val();
                } else {
                    self.acr_q.d.next = (self.acr_q.q.val()
                        & !(self.byte_mask.val() << self.acf_shift.val()))
                        | self.acf_byte.val();
                }
            }
        }
        if self.wr.val() && (self.addr.val() == self.a_cdr.val()) {
            if self.rm.val() {
                self.cdr.d.next = self.wdata.val() & self.cdr_rm_mask.val();
            } else {
                self.cdr.d.next = (self.cdr.q.val() & self.cdr_op_mask.val())
                    | (self.wdata.val() & self.cd_mask.val());
            }
        }
        if self.rst.val() {
            self.btr0.d.next = self.zero8.val();
            self.btr1.d.next = self.btr1_reset.val();
            self.ocr.d.next = self.zero8.val();
            self.ewlr.d.next = self.ewlr_reset.val();
            self.cdr.d.next = self.zero8.val();
            self.acr_q.d.next = self.zero32.val();
            self.amr_q.d.next = self.ones32.val();
        }
        // ---- reads ----
        self.rdata.next = self.zero8.val();
        if self.addr.val() == self.a_btr0.val() {
            self.rdata.next = self.btr0.q.val();
        }
        if self.addr.val() == self.a_btr1.val() {
            self.rdata.next = self.btr1.q.val();
        }
        if self.addr.val() == self.a_ocr.val() {
            self.rdata.next = self.ocr.q.val();
        }
        if self.addr.val() == self.a_ewlr.val() {
            self.rdata.next = self.ewlr.q.val();
        }
        if self.addr.val() == self.a_cdr.val() {
            self.rdata.next = self.cdr.q.val();
        }
        self.acf_read.next = self.acr_q.q.val();
        if self.addr.val().get_bit(2) {
            self.acf_read.next = self.amr_q.q.val();
        }
        if self.acf_page.val() && self.rm.val() {
            match self.addr.val().get_bits::<2>(0).index() {
                0 => self.rdata.next = self.acf_read.val().get_bits::<8>(0),
                1 => self.rdata.next = self.acf_read.val().get_bits::<8>(8),
                2 => self.rdata.next = self.acf_read.val().get_bits::<8>(16),
                _ => self.rdata.next = self.acf_read.val().get_bits::<8>(24),
            }
        }
        // ---- the native BTR word (P-CFG-2; drcc_contract.md §3 BTR) ----
        self.brp.next =
            (bit_cast::<7, 6>(self.btr0.q.val().get_bits::<6>(0)) << 1) | self.one7.val();
        self.view_btr.next = bit_cast::<28, 6>(self.brp.val().get_bits::<6>(0))
            | (bit_cast::<28, 1>(self.brp.val().get_bit(6).into()) << 24)
            | (bit_cast::<28, 4>(self.btr1.q.val().get_bits::<4>(0)) << 6)
            | (bit_cast::<28, 3>(self.btr1.q.val().get_bits::<3>(4)) << 10)
            | (bit_cast::<28, 2>(self.btr0.q.val().get_bits::<2>(6)) << 13)
            | (bit_cast::<28, 1>(self.btr1.q.val().get_bit(7).into()) << 15)
            | (bit_cast::<28, 8>(self.ewlr.q.val()) << 16);
        self.acr.next = self.acr_q.q.val();
        self.amr.next = self.amr_q.q.val();
    }
}
