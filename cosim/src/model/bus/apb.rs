//! The APB front end (contract §2): a combinational bridge from APB4 to the
//! register port. Every access phase lasts two clocks: the port takes the access at
//! the first edge of the access phase and answers in the second clock, where
//! `pready` is 1.

use super::{strobe, word_index, PortIn, PortOut};

/// The APB inputs in one clock (prefix `s_apb_`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ApbIn {
    pub psel: bool,
    pub penable: bool,
    pub pwrite: bool,
    /// Byte address (`paddr[1:0]` are ignored).
    pub paddr: u16,
    pub pwdata: u32,
    /// `pstrb[3:0]` (an APB3 master ties it to `4'b1111`).
    pub pstrb: u8,
}

/// The APB outputs in one clock.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ApbOut {
    pub prdata: u32,
    pub pready: bool,
    pub pslverr: bool,
}

/// The APB bridge (§2): no state.
#[derive(Clone, Copy, Debug, Default)]
pub struct ApbBridge;

impl ApbBridge {
    /// The register port's inputs for this clock's bus inputs:
    /// `wb_cyc_i = wb_stb_i = psel & penable`, `wb_we_i = pwrite`,
    /// `wb_adr_i = paddr[A-1:2]`, `wb_dat_i = pwdata`, `wb_sel_i = pstrb`.
    pub fn port_in(&self, i: &ApbIn) -> PortIn {
        PortIn {
            cyc: i.psel & i.penable,
            we: i.pwrite,
            adr: word_index(i.paddr),
            dat: i.pwdata,
            sel: strobe(i.pstrb),
        }
    }

    /// The bus outputs after an edge, from the register port's outputs after it:
    /// `pready = wb_ack_o | wb_err_o`, `pslverr = wb_err_o`, `prdata = wb_dat_o`.
    pub fn outputs(&self, port: &PortOut) -> ApbOut {
        ApbOut {
            prdata: port.dat,
            pready: port.ack | port.err,
            pslverr: port.err,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::fake_regs::{FakeRegs, BYTES, RO, RO_VALUE, WHOLE};
    use super::*;

    /// A bridge and the fake register block, one clock at a time.
    #[derive(Default)]
    struct Sys {
        bridge: ApbBridge,
        regs: FakeRegs,
    }

    impl Sys {
        /// The APB outputs in the current clock.
        fn out(&self) -> ApbOut {
            self.bridge.outputs(&self.regs.out())
        }
        /// One edge with `i` applied in the clock before it.
        fn edge(&mut self, i: &ApbIn) {
            self.regs.step(&self.bridge.port_in(i));
        }
        /// One APB transfer as a master makes it (APB §3: setup phase, then access
        /// phase until `pready`), checking every clock; returns `(prdata, pslverr)`
        /// of the last clock and the number of clocks of the access phase.
        fn transfer(&mut self, write: bool, paddr: u8, pwdata: u32, pstrb: u8) -> (u32, bool, u32) {
            let mut i = ApbIn {
                psel: true,
                penable: false,
                pwrite: write,
                paddr: paddr.into(),
                pwdata,
                pstrb,
            };
            assert_eq!(
                self.out(),
                ApbOut::default(),
                "outputs 0 in the setup phase"
            );
            self.edge(&i);
            i.penable = true;
            let mut clocks = 0;
            loop {
                clocks += 1;
                assert!(clocks <= 16, "pready never came");
                let o = self.out();
                if o.pready {
                    self.edge(&i);
                    // The transfer ends: back to idle, every output 0 there.
                    assert_eq!(
                        self.out(),
                        ApbOut::default(),
                        "outputs 0 after the transfer"
                    );
                    return (o.prdata, o.pslverr, clocks);
                }
                assert_eq!(o, ApbOut::default(), "prdata and pslverr only with pready");
                self.edge(&i);
            }
        }
    }

    #[test]
    fn port_mapping() {
        let b = ApbBridge;
        let i = ApbIn {
            psel: true,
            penable: false,
            pwrite: true,
            paddr: 0xFF,
            pwdata: 0x1234_5678,
            pstrb: 0xF5,
        };
        // Setup phase: no access; the other port inputs follow the bus.
        assert_eq!(
            b.port_in(&i),
            PortIn {
                cyc: false,
                we: true,
                adr: 0x3F,
                dat: 0x1234_5678,
                sel: 0x5
            }
        );
        assert!(b.port_in(&ApbIn { penable: true, ..i }).cyc);
        assert!(
            !b.port_in(&ApbIn {
                psel: false,
                penable: true,
                ..i
            })
            .cyc
        );
        assert_eq!(b.port_in(&ApbIn { paddr: 0x13, ..i }).adr, 4);
        let ack = PortOut {
            ack: true,
            err: false,
            dat: 7,
        };
        assert_eq!(
            b.outputs(&ack),
            ApbOut {
                prdata: 7,
                pready: true,
                pslverr: false
            }
        );
        let err = PortOut {
            ack: false,
            err: true,
            dat: 0,
        };
        assert_eq!(
            b.outputs(&err),
            ApbOut {
                prdata: 0,
                pready: true,
                pslverr: true
            }
        );
        assert_eq!(b.outputs(&PortOut::default()), ApbOut::default());
    }

    /// §2 clock by clock: setup, two access-phase clocks, `pready` in the second.
    #[test]
    fn write_then_read_back_clock_by_clock() {
        let mut s = Sys::default();
        let w = ApbIn {
            psel: true,
            penable: false,
            pwrite: true,
            paddr: u16::from(4 * WHOLE + 2), // paddr[1:0] ignored
            pwdata: 0xDEAD_BEEF,
            pstrb: 0xF,
        };
        s.edge(&w); // setup
        assert_eq!(s.out(), ApbOut::default());
        assert!(s.regs.log.is_empty());
        let w = ApbIn { penable: true, ..w };
        s.edge(&w); // first access clock: taken here
        assert_eq!(s.regs.log.len(), 1);
        assert_eq!(
            s.out(),
            ApbOut {
                prdata: 0,
                pready: true,
                pslverr: false
            }
        );
        s.edge(&w); // second access clock: the master ends the transfer
        assert_eq!(s.regs.log.len(), 1, "taken once");
        assert_eq!(s.regs.mem[WHOLE as usize], 0xDEAD_BEEF);
        assert_eq!(s.out(), ApbOut::default());
        s.edge(&ApbIn::default()); // idle

        let (prdata, pslverr, clocks) = s.transfer(false, 4 * WHOLE, 0, 0);
        assert_eq!((prdata, pslverr, clocks), (0xDEAD_BEEF, false, 2));
        let (prdata, pslverr, clocks) = s.transfer(false, 4 * RO + 1, 0, 0xF);
        assert_eq!((prdata, pslverr, clocks), (RO_VALUE, false, 2));
        // Unmapped words read 0, without error.
        assert_eq!(s.transfer(false, 4 * 9, 0, 0xF), (0, false, 2));
    }

    #[test]
    fn refused_writes_give_pslverr() {
        let mut s = Sys::default();
        assert_eq!(s.transfer(true, 4 * WHOLE, 0x1111_1111, 0xF), (0, false, 2));
        // A partial write to a whole-word register: refused, nothing changes.
        assert_eq!(s.transfer(true, 4 * WHOLE, 0x2222_2222, 0x3), (0, true, 2));
        assert_eq!(s.transfer(true, 4 * WHOLE, 0x2222_2222, 0x0), (0, true, 2));
        assert_eq!(s.regs.mem[WHOLE as usize], 0x1111_1111);
        assert_eq!(s.transfer(false, 4 * WHOLE, 0, 0), (0x1111_1111, false, 2));
        // Read-only and unmapped words.
        assert_eq!(s.transfer(true, 4 * RO, 1, 0xF), (0, true, 2));
        assert_eq!(s.transfer(true, 4 * 40, 1, 0xF), (0, true, 2));
        // Byte lanes on the staging-like word.
        assert_eq!(s.transfer(true, 4 * BYTES, 0xAABB_CCDD, 0xF), (0, false, 2));
        assert_eq!(s.transfer(true, 4 * BYTES, 0x1122_3344, 0x5), (0, false, 2));
        assert_eq!(s.transfer(false, 4 * BYTES, 0, 0), (0xAA22_CC44, false, 2));
        // An APB3 master (pstrb tied to 1111) writes whole words.
        assert_eq!(s.transfer(true, 4 * BYTES, 0x0102_0304, 0xF), (0, false, 2));
        assert_eq!(s.transfer(false, 4 * BYTES, 0, 0), (0x0102_0304, false, 2));
    }

    /// Back-to-back transfers (setup right after the last access clock).
    #[test]
    fn back_to_back() {
        let mut s = Sys::default();
        for k in 0..8u32 {
            assert_eq!(s.transfer(true, 4 * WHOLE, k * 3, 0xF), (0, false, 2));
            assert_eq!(s.transfer(false, 4 * WHOLE, 0, 0), (k * 3, false, 2));
        }
        assert_eq!(s.regs.log.len(), 16);
    }
}
