//! Directed tests of the AXI4-Lite bridge with the fake register block; the
//! random-traffic property test is in [`random`].

use super::super::fake_regs::{FakeRegs, BYTES, RO, RO_VALUE, WHOLE, WHOLE2};
use super::*;

/// The bridge and the fake register block, composed as the module doc says.
#[derive(Default)]
struct Sys {
    bridge: AxiLiteBridge,
    regs: FakeRegs,
}

impl Sys {
    /// The AXI outputs in the current clock.
    fn out(&self) -> AxiOut {
        self.bridge.outputs()
    }
    /// One edge with `i` applied in the clock before it.
    fn edge(&mut self, i: &AxiIn) {
        let pin = self.bridge.port_in();
        let before = self.regs.out();
        self.regs.step(&pin);
        self.bridge.edge(i, &before);
    }
    /// Edges with `i` until `f(outputs)` holds; the number of edges.
    fn until(&mut self, i: &AxiIn, f: impl Fn(&AxiOut) -> bool) -> u32 {
        let mut n = 0;
        while !f(&self.out()) {
            self.edge(i);
            n += 1;
            assert!(n < 64, "stuck");
        }
        n
    }
    /// A whole write as a simple master makes it (AW and W together, `bready`
    /// high): the response.
    fn write(&mut self, awaddr: u8, wdata: u32, wstrb: u8) -> u8 {
        let i = AxiIn {
            awaddr: awaddr.into(),
            awvalid: true,
            wdata,
            wstrb,
            wvalid: true,
            ..IDLE
        };
        assert!(self.out().awready && self.out().wready);
        self.edge(&i);
        let ready = AxiIn {
            bready: true,
            ..IDLE
        };
        self.until(&ready, |o| o.bvalid);
        let bresp = self.out().bresp;
        self.edge(&ready);
        assert!(!self.out().bvalid);
        bresp
    }
    /// A whole read (`rready` high): `(rdata, rresp)`.
    fn read(&mut self, araddr: u8) -> (u32, u8) {
        assert!(self.out().arready);
        self.edge(&AxiIn {
            araddr: araddr.into(),
            arvalid: true,
            ..IDLE
        });
        let ready = AxiIn {
            rready: true,
            ..IDLE
        };
        self.until(&ready, |o| o.rvalid);
        let o = self.out();
        self.edge(&ready);
        assert!(!self.out().rvalid);
        (o.rdata, o.rresp)
    }
}

const IDLE: AxiIn = AxiIn {
    awaddr: 0,
    awvalid: false,
    wdata: 0,
    wstrb: 0,
    wvalid: false,
    bready: false,
    araddr: 0,
    arvalid: false,
    rready: false,
};

/// The outputs of an idle bridge.
const READY: AxiOut = AxiOut {
    awready: true,
    wready: true,
    bresp: OKAY,
    bvalid: false,
    arready: true,
    rdata: 0,
    rresp: OKAY,
    rvalid: false,
};

#[test]
fn aw_and_w_in_one_clock() {
    let mut s = Sys::default();
    assert_eq!(s.out(), READY);
    let i = AxiIn {
        awaddr: u16::from(4 * WHOLE2 + 3), // awaddr[1:0] ignored
        awvalid: true,
        wdata: 0xCAFE_F00D,
        wstrb: 0xF,
        wvalid: true,
        ..IDLE
    };
    s.edge(&i); // E0: AW and W taken
    assert_eq!(
        s.out(),
        AxiOut {
            awready: false,
            wready: false,
            ..READY
        }
    );
    assert!(!s.bridge.port_in().cyc);
    s.edge(&IDLE); // E1: the access starts
    let pin = PortIn {
        cyc: true,
        we: true,
        adr: WHOLE2,
        dat: 0xCAFE_F00D,
        sel: 0xF,
    };
    assert_eq!(s.bridge.port_in(), pin);
    assert!(!s.out().bvalid);
    s.edge(&IDLE); // E2: the port takes it
    assert_eq!(s.regs.log.len(), 1);
    assert_eq!(s.regs.mem[WHOLE2 as usize], 0xCAFE_F00D);
    assert_eq!(s.bridge.port_in(), pin, "held until the answer is seen");
    assert!(!s.out().bvalid);
    s.edge(&IDLE); // E3: the access ends
    assert_eq!(
        s.out(),
        AxiOut {
            bvalid: true,
            bresp: OKAY,
            ..READY
        }
    );
    assert!(!s.bridge.port_in().cyc);
    // bready low: B is held, nothing else happens.
    for _ in 0..5 {
        s.edge(&IDLE);
        assert_eq!(
            s.out(),
            AxiOut {
                bvalid: true,
                bresp: OKAY,
                ..READY
            }
        );
    }
    s.edge(&AxiIn {
        bready: true,
        ..IDLE
    });
    assert_eq!(s.out(), READY);
    assert_eq!(s.regs.log.len(), 1, "taken once");
}

#[test]
fn aw_before_w() {
    let mut s = Sys::default();
    s.edge(&AxiIn {
        awaddr: u16::from(4 * WHOLE),
        awvalid: true,
        ..IDLE
    }); // E0
    for _ in 0..3 {
        assert_eq!(
            s.out(),
            AxiOut {
                awready: false,
                ..READY
            }
        );
        assert!(!s.bridge.port_in().cyc, "no access without W");
        s.edge(&IDLE);
    }
    s.edge(&AxiIn {
        wdata: 5,
        wstrb: 0xF,
        wvalid: true,
        ..IDLE
    }); // W taken
    assert_eq!(s.until(&IDLE, |o| o.bvalid), 3);
    assert_eq!(
        s.out(),
        AxiOut {
            bvalid: true,
            ..READY
        }
    );
    assert_eq!(s.regs.mem[WHOLE as usize], 5);
}

#[test]
fn w_before_aw() {
    let mut s = Sys::default();
    s.edge(&AxiIn {
        wdata: 0x0000_AB00,
        wstrb: 0x2,
        wvalid: true,
        ..IDLE
    });
    for _ in 0..3 {
        assert_eq!(
            s.out(),
            AxiOut {
                wready: false,
                ..READY
            }
        );
        assert!(!s.bridge.port_in().cyc, "no access without AW");
        s.edge(&IDLE);
    }
    s.edge(&AxiIn {
        awaddr: u16::from(4 * BYTES),
        awvalid: true,
        ..IDLE
    });
    assert_eq!(s.until(&IDLE, |o| o.bvalid), 3);
    assert_eq!(
        s.out(),
        AxiOut {
            bvalid: true,
            bresp: OKAY,
            ..READY
        }
    );
    assert_eq!(s.regs.mem[BYTES as usize], 0x0000_AB00);
}

#[test]
fn read_held_until_rready() {
    let mut s = Sys::default();
    assert_eq!(s.write(4 * BYTES, 0x1234_5678, 0xF), OKAY);
    s.edge(&AxiIn {
        araddr: u16::from(4 * BYTES + 2),
        arvalid: true,
        ..IDLE
    }); // E0
    assert_eq!(
        s.out(),
        AxiOut {
            arready: false,
            ..READY
        }
    );
    s.edge(&IDLE); // E1: start
    assert!(s.bridge.port_in().cyc);
    assert!(!s.bridge.port_in().we);
    assert_eq!(s.bridge.port_in().adr, BYTES);
    assert_eq!(
        s.out(),
        AxiOut {
            arready: false,
            ..READY
        }
    );
    s.edge(&IDLE); // E2: taken
    assert_eq!(
        s.out(),
        AxiOut {
            arready: false,
            ..READY
        }
    );
    s.edge(&IDLE); // E3: ended, R valid
    let r = AxiOut {
        rvalid: true,
        rdata: 0x1234_5678,
        rresp: OKAY,
        ..READY
    };
    assert_eq!(s.out(), r);
    // rready low: rdata held. The AR register is free again (§3 rule 3), so a
    // second AR is taken, but its access waits for the R handshake.
    s.edge(&IDLE);
    assert_eq!(s.out(), r);
    s.edge(&AxiIn {
        araddr: u16::from(4 * RO),
        arvalid: true,
        ..IDLE
    });
    let held = AxiOut {
        arready: false,
        ..r
    };
    for _ in 0..5 {
        assert_eq!(s.out(), held);
        assert!(!s.bridge.port_in().cyc);
        s.edge(&IDLE);
    }
    assert_eq!(s.regs.log.len(), 2, "one write, one read");
    s.edge(&AxiIn {
        rready: true,
        ..IDLE
    }); // R handshake
    assert_eq!(
        s.out(),
        AxiOut {
            arready: false,
            rvalid: false,
            ..r
        }
    );
    // The second read: start, take, end.
    assert_eq!(s.until(&IDLE, |o| o.rvalid), 3);
    assert_eq!(
        s.out(),
        AxiOut {
            rvalid: true,
            rdata: RO_VALUE,
            ..READY
        }
    );
}

#[test]
fn refused_writes_give_slverr() {
    let mut s = Sys::default();
    assert_eq!(s.write(4 * WHOLE, 0x1111_1111, 0xF), OKAY);
    assert_eq!(s.write(4 * WHOLE, 0x2222_2222, 0xC), SLVERR);
    assert_eq!(s.write(4 * WHOLE, 0x2222_2222, 0x0), SLVERR);
    assert_eq!(s.read(4 * WHOLE), (0x1111_1111, OKAY));
    assert_eq!(s.write(4 * RO, 0, 0xF), SLVERR);
    assert_eq!(s.read(4 * RO), (RO_VALUE, OKAY));
    assert_eq!(s.write(4 * 63, 1, 0xF), SLVERR);
    assert_eq!(s.read(4 * 63), (0, OKAY));
    assert_eq!(s.write(4 * BYTES, 0xAABB_CCDD, 0xF), OKAY);
    assert_eq!(s.write(4 * BYTES, 0x1122_3344, 0x9), OKAY);
    assert_eq!(s.read(4 * BYTES), (0x11BB_CC44, OKAY));
    // wstrb bits above the port are ignored (Interpretation 1).
    assert_eq!(s.write(4 * WHOLE, 0x3333_3333, 0xFF), OKAY);
    assert_eq!(s.regs.log.last().map(|a| a.sel), Some(0xF));
    // A read after an error response: the R channel is unaffected.
    assert_eq!(s.read(4 * WHOLE), (0x3333_3333, OKAY));
}

/// Both a write and a read always ready: they alternate, the write first
/// (`last_write` is 0 after reset).
#[test]
fn arbitration_alternates() {
    let mut s = Sys::default();
    let all = AxiIn {
        awaddr: u16::from(4 * WHOLE),
        awvalid: true,
        wdata: 9,
        wstrb: 0xF,
        wvalid: true,
        bready: true,
        araddr: u16::from(4 * RO),
        arvalid: true,
        rready: true,
    };
    s.edge(&all); // E0: AW, W, AR taken
    s.edge(&all); // E1: the write starts
    assert!(s.bridge.port_in().we);
    for _ in 0..60 {
        s.edge(&all);
    }
    let kinds: Vec<bool> = s.regs.log.iter().map(|a| a.we).collect();
    assert!(kinds.len() >= 10, "{kinds:?}");
    for (k, we) in kinds.iter().enumerate() {
        assert_eq!(*we, k % 2 == 0, "{kinds:?}");
    }
}

/// `bready` low holds B and blocks the next write, not a read (§3 rule 2: a
/// held response blocks only its own kind); the channels still take one
/// address and one data beat each.
#[test]
fn bready_back_pressure() {
    let mut s = Sys::default();
    s.edge(&AxiIn {
        awaddr: u16::from(4 * WHOLE),
        awvalid: true,
        wdata: 1,
        wstrb: 0xF,
        wvalid: true,
        ..IDLE
    });
    s.until(&IDLE, |o| o.bvalid);
    assert_eq!(
        s.out(),
        AxiOut {
            bvalid: true,
            ..READY
        }
    );
    // A read and a second write arrive while B is held (rready low too).
    s.edge(&AxiIn {
        awaddr: u16::from(4 * WHOLE2),
        awvalid: true,
        wdata: 2,
        wstrb: 0xF,
        wvalid: true,
        araddr: u16::from(4 * WHOLE),
        arvalid: true,
        ..IDLE
    });
    // The read is served: start, take, end (3 edges from the AR's).
    s.until(&IDLE, |o| o.rvalid);
    assert!(s.out().bvalid, "B still held");
    assert_eq!(s.out().rdata, 1);
    for _ in 0..10 {
        let o = s.out();
        assert!(o.bvalid && o.rvalid, "both responses held");
        assert!(!o.awready && !o.wready, "the second write is held");
        assert!(!s.bridge.port_in().cyc, "no access while both kinds wait");
        s.edge(&IDLE);
    }
    assert_eq!(s.regs.log.len(), 2);
    let ready = AxiIn {
        bready: true,
        rready: true,
        ..IDLE
    };
    s.edge(&ready); // both handshakes; no start at this edge (bvalid was 1)
    assert!(!s.out().bvalid && !s.out().rvalid);
    assert!(!s.bridge.port_in().cyc);
    s.edge(&ready); // start: the held write
    assert_eq!(
        s.bridge.port_in(),
        PortIn {
            cyc: true,
            we: true,
            adr: WHOLE2,
            dat: 2,
            sel: 0xF
        }
    );
    s.until(&ready, |o| o.bvalid);
    assert_eq!(s.regs.mem[WHOLE2 as usize], 2);
    let kinds: Vec<(bool, u8)> = s.regs.log.iter().map(|a| (a.we, a.adr)).collect();
    assert_eq!(kinds, [(true, WHOLE), (false, WHOLE), (true, WHOLE2)]);
}

#[test]
fn reset_clears_everything() {
    let mut s = Sys::default();
    s.edge(&AxiIn {
        awaddr: 4,
        awvalid: true,
        wstrb: 0xF,
        wvalid: true,
        arvalid: true,
        ..IDLE
    });
    s.edge(&IDLE);
    assert!(s.bridge.port_in().cyc);
    s.bridge.reset();
    assert_eq!(s.out(), READY);
    assert_eq!(s.bridge.port_in(), PortIn::default());
}

mod random;
