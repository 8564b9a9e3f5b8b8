//! A small register block for the bus tests, written from contract §1 only (not from
//! the register table): it takes an access at an edge where
//! `cyc & !(ack | err)` and answers with `ack` or `err` for one clock.
//!
//! Map: word [`WHOLE`] and word [`WHOLE2`] are read-write and refuse partial writes;
//! word [`BYTES`] honours byte lanes (like `TX_DATA0`); word [`RO`] is read-only
//! (reads [`RO_VALUE`], a write is refused); every other word is unmapped (reads 0,
//! a write is refused).

use super::{PortIn, PortOut};

/// Read-write, whole-word writes only.
pub const WHOLE: u8 = 0;
/// Read-write, honours byte lanes.
pub const BYTES: u8 = 1;
/// Read-only.
pub const RO: u8 = 2;
/// Read-write, whole-word writes only.
pub const WHOLE2: u8 = 3;
/// The value of the read-only word.
pub const RO_VALUE: u32 = 0xC0DE_0002;

/// One access the block took.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Access {
    pub we: bool,
    pub adr: u8,
    pub dat: u32,
    pub sel: u8,
    /// Answered with `err` (refused).
    pub err: bool,
    /// The word's value before the edge (what a read returns).
    pub held: u32,
}

#[derive(Clone, Debug, Default)]
pub struct FakeRegs {
    /// Words `WHOLE`, `BYTES`, `WHOLE2` (index = word index; index `RO` unused).
    pub mem: [u32; 4],
    out: PortOut,
    /// Every access taken, in order.
    pub log: Vec<Access>,
}

/// §1: is this write refused? (Reads never are.)
pub fn refused(adr: u8, sel: u8) -> bool {
    match adr {
        WHOLE | WHOLE2 => sel != 0xF,
        BYTES => false,
        _ => true,
    }
}

impl FakeRegs {
    /// The outputs after the last edge.
    pub fn out(&self) -> PortOut {
        self.out
    }

    /// The value a read of word `adr` returns.
    pub fn read(&self, adr: u8) -> u32 {
        match adr {
            WHOLE | BYTES | WHOLE2 => self.mem[adr as usize],
            RO => RO_VALUE,
            _ => 0,
        }
    }

    /// One rising edge with the port inputs `p`.
    pub fn step(&mut self, p: &PortIn) {
        let taken = p.cyc && !(self.out.ack || self.out.err);
        let mut next = PortOut::default();
        if taken {
            let held = self.read(p.adr);
            let mut err = false;
            if p.we {
                err = refused(p.adr, p.sel);
                if !err {
                    let mut mask = 0u32;
                    for lane in 0..4 {
                        if p.sel >> lane & 1 == 1 {
                            mask |= 0xFF << (8 * lane);
                        }
                    }
                    let w = &mut self.mem[p.adr as usize];
                    *w = (*w & !mask) | (p.dat & mask);
                }
            } else {
                next.dat = held;
            }
            next.ack = !err;
            next.err = err;
            self.log.push(Access {
                we: p.we,
                adr: p.adr,
                dat: p.dat,
                sel: p.sel,
                err,
                held,
            });
        }
        self.out = next;
    }
}
