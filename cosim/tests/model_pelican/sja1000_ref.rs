//! An SJA1000 register core in PeliCAN mode, written from the NXP (Philips)
//! SJA1000 data sheet alone ("Stand-alone CAN controller", product
//! specification 2000 Jan 04): section 6.4 (PeliCAN mode: 6.4.1 address layout,
//! Table 11 reset values, Tables 12..24 MOD, CMR, SR, IR, IER, ALC, ECC, EWLR,
//! RXERR, TXERR, 6.4.13 transmit buffer, 6.4.14 receive buffer, 6.4.16 RMC,
//! 6.4.17 RBSA) and 6.5 (BTR0, BTR1, OCR, CDR). Nothing here comes from the
//! DRCC's PeliCAN model, its RTL or its contract: it is the independent oracle
//! of `side_by_side.rs`. Table numbers are those of that data sheet (Table 11
//! reset values, 12 MOD, 13 CMR, 14 SR, 15 IR, 16 IER, 22..24 EWLR/RXERR/TXERR,
//! 42 RMC, 43 RBSA, 44..49 BTR0/BTR1/OCR/CDR); the access rules by address
//! (which mode reads or writes what, 00H at 5, 10, 24..28 in reset mode and
//! 112..127) are those of its PeliCAN address allocation table in 6.4.1.
//!
//! The CAN bus is abstracted. Time runs in XTAL clocks (`advance`); the only
//! bus events are "the bus stayed recessive" (bus integration after leaving
//! reset mode, derived from BTR0/BTR1) and `tx_success` (told by the test when
//! the other node has received the frame). What the data sheet leaves undefined
//! (Table 11 "X" at hardware reset, the RAM) or what depends on bus timing the
//! abstraction does not model is returned as unknown bits (`V::k`).

/// A byte with a mask of the bits whose value is defined (`k` = known).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V {
    pub v: u8,
    pub k: u8,
}

impl V {
    pub const UNDEF: V = V { v: 0, k: 0 };
    pub const fn of(v: u8) -> V {
        V { v, k: 0xFF }
    }
    /// Does `x` agree with every known bit?
    pub fn matches(self, x: u8) -> bool {
        (x ^ self.v) & self.k == 0
    }
}

// SR bits (Table 14).
const BS: u8 = 0x80;
const ES: u8 = 0x40;
const TS: u8 = 0x20;
const RS: u8 = 0x10;
const TCS: u8 = 0x08;
const TBS: u8 = 0x04;
// IR / IER bits (Tables 15, 16).
const WUI: u8 = 0x10;
const EI: u8 = 0x04;
const TI: u8 = 0x02;
const RI: u8 = 0x01;

#[derive(Clone, Debug)]
pub struct Sja1000 {
    /// CDR.7 (6.5.4.5): PeliCAN. Only PeliCAN is modelled; in BasicCAN every
    /// read is unknown (the BasicCAN layout of 6.3 is not written here).
    cdr: u8,
    /// A BasicCAN-layout write happened: nothing is known any more.
    lost: bool,
    /// MOD bits (Table 12).
    rm: bool,
    lom: bool,
    stm: bool,
    afm: bool,
    sm: bool,
    /// SR.7, SR.6, SR.3, SR.2 (Table 14); RS/TS are derived, DOS/RBS are 0
    /// (no reception is modelled: the RX FIFO stays empty).
    bs: bool,
    es: bool,
    tcs: bool,
    tbs: bool,
    /// IR (Table 15) with unknown bits (an event while IER was undefined).
    ir: V,
    ier: V,
    btr0: V,
    btr1: V,
    ocr: V,
    alc: u8,
    ecc: u8,
    ewlr: u8,
    rxerr: u8,
    txerr: u8,
    acr: [V; 4],
    amr: [V; 4],
    rmc: u8,
    rbsa: u8,
    /// Internal RAM 0..79 (6.4.17): 0..63 RX FIFO, 64..76 TX buffer, 77..79 free.
    ram: [V; 80],
    /// A transmission request is pending or under way (TBS = 0).
    tx_pending: bool,
    /// Clocks since reset mode was left (bus integration, Table 11 note on
    /// SR.4/SR.5: after reset 11 recessive bits until idle).
    since_op: u64,
}

impl Default for Sja1000 {
    fn default() -> Self {
        Self::new()
    }
}

impl Sja1000 {
    /// The state after a hardware reset (Table 11, column "reset by hardware";
    /// CDR 00000000 in Intel mode, 6.5.4).
    pub fn new() -> Self {
        Sja1000 {
            cdr: 0x00,
            lost: false,
            rm: true,
            lom: false,
            stm: false,
            afm: false,
            sm: false,
            bs: false,
            es: false,
            tcs: true,
            tbs: true,
            ir: V::of(0),
            // Table 11: IER, BTR0, BTR1, OCR, ACR, AMR, TXB, RXB are "X".
            ier: V::UNDEF,
            btr0: V::UNDEF,
            btr1: V::UNDEF,
            ocr: V::UNDEF,
            alc: 0,
            ecc: 0,
            ewlr: 96,
            rxerr: 0,
            txerr: 0,
            acr: [V::UNDEF; 4],
            amr: [V::UNDEF; 4],
            rmc: 0,
            rbsa: 0,
            ram: [V::UNDEF; 80],
            tx_pending: false,
            since_op: 0,
        }
    }

    /// MOD.0.
    pub fn reset_mode(&self) -> bool {
        self.rm
    }

    /// Operating mode, and bus integration (11 recessive bits) maybe not done.
    pub fn integrating(&self) -> bool {
        !self.rm && self.integrated() != Some(true)
    }

    /// False once a write left the modelled PeliCAN layout.
    pub fn modelled(&self) -> bool {
        !self.lost
    }

    fn pelican(&self) -> bool {
        self.cdr & 0x80 != 0 && !self.lost
    }

    /// XTAL clocks of one bit, (lowest, highest): 6.5.1.1 tscl = 2 tCLK (BRP+1),
    /// 6.5.2.2 bit = (1 + TSEG1+1 + TSEG2+1) tscl. The highest lengthens the
    /// bit to 8 tq: docs/pelican.md row "bit timing with fewer than 8 tq |
    /// differs" (the data sheet itself gives the lowest).
    fn bit_clocks(&self) -> Option<(u64, u64)> {
        if self.btr0.k != 0xFF || self.btr1.k != 0xFF {
            return None;
        }
        let tscl = 2 * ((self.btr0.v & 0x3F) as u64 + 1);
        let tq = 3 + (self.btr1.v & 0x0F) as u64 + ((self.btr1.v >> 4) & 7) as u64;
        Some((tscl * tq, tscl * tq.max(8)))
    }

    /// Bus integration after leaving reset mode: Some(true) done, Some(false)
    /// not yet, None within the margin the abstract bus cannot resolve.
    fn integrated(&self) -> Option<bool> {
        let (lo, hi) = self.bit_clocks()?;
        if self.since_op < 10 * lo {
            Some(false)
        } else if self.since_op > 14 * hi {
            Some(true)
        } else {
            None
        }
    }

    pub fn advance(&mut self, clocks: u64) {
        if !self.rm {
            self.since_op = self.since_op.saturating_add(clocks);
        }
    }

    /// Raise interrupt bit `b` if its IER bit is set (Table 15: "... and the
    /// xIE bit is set within the interrupt enable register").
    fn raise(&mut self, b: u8) {
        if self.ir.k & self.ir.v & b != 0 {
            // Already set.
        } else if self.ier.k & b == 0 {
            self.ir.k &= !b;
        } else if self.ier.v & b != 0 {
            self.ir.v |= b;
        }
    }

    /// SR.6 (Table 14 note 2): at least one counter at or above EWLR.
    fn update_es(&mut self) {
        let es = self.rxerr >= self.ewlr || self.txerr >= self.ewlr;
        if es != self.es {
            self.es = es;
            // IR.2: on every change of ES or BS.
            self.raise(EI);
        }
    }

    /// Entering reset mode by software (Table 11, column "setting MOD.0 by
    /// software"): SM 0; TS, RS 1; TBS 1; DOS, RBS 0; IR 0 but EI; RMC 0; a
    /// pending transmission is gone (TBS released, TCS unchanged: "X").
    fn enter_reset(&mut self) {
        self.rm = true;
        self.sm = false;
        self.tbs = true;
        self.tx_pending = false;
        self.ir.v &= EI;
        self.ir.k |= !EI;
        self.rmc = 0;
    }

    /// The other node received our frame: the transmission succeeded
    /// (Table 14: TBS released, TCS complete, TS idle; IR.1 on TBS 0 -> 1).
    pub fn tx_success(&mut self) {
        assert!(self.tx_pending && !self.rm);
        self.tx_pending = false;
        self.tbs = true;
        self.tcs = true;
        self.raise(TI);
    }

    pub fn write(&mut self, a: u8, b: u8) {
        if self.cdr & 0x80 == 0 {
            // BasicCAN: only the switch to PeliCAN (CDR.7, reset mode only) is
            // modelled; any other write leaves the model of 6.4 behind.
            if a == 31 && self.rm {
                self.cdr = b & 0xEF;
            } else if a == 0 && b == 0x01 && self.rm {
                // CR (6.3.3) with only the reset request: reset mode stays.
            } else {
                self.lost = true;
            }
            return;
        }
        let rm = self.rm;
        match a {
            0 => {
                // Table 12 note: MOD.1..3 writable only if reset mode was
                // entered previously; MOD.0 always.
                if rm {
                    self.lom = b & 0x02 != 0;
                    self.stm = b & 0x04 != 0;
                    self.afm = b & 0x08 != 0;
                }
                if b & 0x01 != 0 {
                    if !rm {
                        self.enter_reset();
                    }
                } else if rm {
                    self.rm = false;
                    self.since_op = 0;
                    // 6.4.10/6.4.11: ES and EI forced by new EWLR or counter
                    // contents occur when reset mode is cancelled.
                    self.update_es();
                }
                // MOD.4 SM (Table 12 note 1): not settable in reset mode, and
                // only after bus-free was detected again; clearing wakes up
                // (IR.4 WUI when WUIE). A sleep request refused because an
                // interrupt is pending (WUI at once) is not modelled.
                if !self.rm {
                    let sm = b & 0x10 != 0;
                    if sm && !self.sm && self.integrated() == Some(true) {
                        self.sm = true;
                    } else if !sm && self.sm {
                        self.sm = false;
                        self.raise(WUI);
                    }
                }
            }
            1 => {
                // 6.4.4: TR, AT, SRR act in operating mode only; RRB on the
                // empty FIFO and CDO with DOS = 0 change nothing.
                if rm {
                    return;
                }
                if b & 0x11 != 0 && self.tbs {
                    // TR or SRR: TBS locked, TCS incomplete (Table 14 notes 4, 5).
                    self.tbs = false;
                    self.tcs = false;
                    self.tx_pending = true;
                }
                if b & 0x02 != 0 && self.tx_pending {
                    // AT (Table 13 note 5): a transmission not yet under way is
                    // cancelled; the buffer is released (IR.1 TI, IER.1 text:
                    // "e.g. after an abort transmission command"); TCS stays 0.
                    // Whether it is under way once the bus is integrated is bus
                    // timing, which this model does not have.
                    assert_eq!(
                        self.integrated(),
                        Some(false),
                        "AT is modelled only before the transmission can start"
                    );
                    self.tx_pending = false;
                    self.tbs = true;
                    self.raise(TI);
                }
            }
            4 => self.ier = V::of(b),
            6 if rm => self.btr0 = V::of(b),
            7 if rm => self.btr1 = V::of(b),
            8 if rm => self.ocr = V::of(b),
            13 if rm => self.ewlr = b,
            // 6.4.11/6.4.12: counters written in reset mode only.
            14 if rm => self.rxerr = b,
            15 if rm => self.txerr = b,
            16..=19 if rm => self.acr[a as usize - 16] = V::of(b),
            20..=23 if rm => self.amr[a as usize - 20] = V::of(b),
            // 6.4.13 / Table 14 note 5: the TX buffer (RAM 64..76) takes the
            // byte only while TBS = 1; otherwise it is lost.
            16..=28 if !rm && self.tbs => self.ram[64 + a as usize - 16] = V::of(b),
            16..=28 if !rm => {}
            // RBSA: written in reset mode (6.4.17), 6 bits (Table 43).
            30 if rm => self.rbsa = b & 0x3F,
            31 => {
                // 6.5.4: CD.2..0 always; clock off, RXINTEN, CBP, CAN mode in
                // reset mode only; CDR.4 cannot be written (reads 0).
                let m = if rm { 0xEF } else { 0x07 };
                self.cdr = (self.cdr & !m) | (b & m);
            }
            // 6.4.17: the internal RAM is written in reset mode only.
            32..=111 if rm => self.ram[a as usize - 32] = V::of(b),
            // 2, 3, 5, 10, 11, 12, 29, 112..127 read only; 9 is the production
            // test register, not modelled (callers must not write it).
            _ => {}
        }
    }

    /// What a read of `a` returns, with its side effects (IR clears).
    pub fn read(&mut self, a: u8) -> V {
        if !self.pelican() {
            return V::UNDEF;
        }
        let rm = self.rm;
        match a {
            // Table 12: MOD.7..5 reserved, read 0.
            0 => V::of(
                self.rm as u8
                    | (self.lom as u8) << 1
                    | (self.stm as u8) << 2
                    | (self.afm as u8) << 3
                    | (self.sm as u8) << 4,
            ),
            // 6.4.4: all bits of CMR return 0 when read.
            1 => V::of(0),
            2 => self.sr(),
            3 => {
                // Table 15 note: reading IR clears all bits but RI.
                let r = self.ir;
                self.ir.v &= RI;
                self.ir.k |= !RI;
                r
            }
            4 => self.ier,
            // Reserved addresses read 00H.
            5 | 10 => V::of(0),
            6 => self.btr0,
            7 => self.btr1,
            8 => self.ocr,
            // Production test register: not defined for use.
            9 => V::UNDEF,
            11 => V::of(self.alc),
            12 => V::of(self.ecc),
            13 => V::of(self.ewlr),
            14 => V::of(self.rxerr),
            15 => V::of(self.txerr),
            16..=19 if rm => self.acr[a as usize - 16],
            20..=23 if rm => self.amr[a as usize - 20],
            // Reset mode: 24..28 are reserved, 00H.
            24..=28 if rm => V::of(0),
            // Operating mode: the RX window, RAM from RBSA on (6.4.14, 6.4.17).
            16..=28 => self.ram[(self.rbsa as usize + a as usize - 16) % 64],
            29 => V::of(self.rmc & 0x1F),
            30 => V::of(self.rbsa & 0x3F),
            // CDR.4 reads 0 (Table 49 note).
            31 => V::of(self.cdr & 0xEF),
            32..=111 => self.ram[a as usize - 32],
            // 112..127: 00H.
            _ => V::of(0),
        }
    }

    /// SR (Table 14, Table 11).
    fn sr(&self) -> V {
        let mut v = ((self.bs as u8) * BS)
            | ((self.es as u8) * ES)
            | ((self.tcs as u8) * TCS)
            | ((self.tbs as u8) * TBS);
        let mut k = 0xFF;
        if self.rm {
            // "1 (wait idle)" in reset mode.
            v |= TS | RS;
        } else {
            match self.integrated() {
                Some(false) => v |= TS | RS,
                // The frame on the bus is not modelled bit by bit: while it
                // may be under way, RS and TS are not defined here.
                Some(true) if !self.tx_pending => {}
                _ => k &= !(TS | RS),
            }
        }
        V { v, k }
    }
}
