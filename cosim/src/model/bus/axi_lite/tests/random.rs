//! Random AXI4-Lite traffic against the bridge and the fake register block.

use super::Sys;
use crate::model::bus::fake_regs::{self, FakeRegs};
use crate::model::bus::{AxiIn, AxiOut, PortIn, OKAY, SLVERR};

/// xorshift64 (Marsaglia), enough for test traffic.
struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn chance(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }
    /// A byte address in words 0..6 (mapped, read-only and unmapped words).
    fn addr(&mut self) -> u8 {
        (self.below(6) * 4 + self.below(4)) as u8
    }
}

/// Random AXI4-Lite traffic from a master that keeps the AXI rules (a valid
/// stays up until its handshake, the payload is stable while valid; a valid
/// never waits for a ready), checked against the AXI rules and the fake block.
fn random_traffic(seed: u64, n: usize, busy: u64, ready: u64) {
    let mut rng = XorShift(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let mut s = Sys::default();
    let (mut aw, mut w, mut ar) = (None::<u8>, None::<(u32, u8)>, None::<u8>);
    let (mut aw_sent, mut w_sent, mut ar_sent) = (Vec::new(), Vec::new(), Vec::new());
    let (mut bs, mut rs) = (Vec::new(), Vec::new());
    let mut prev: Option<(AxiOut, AxiIn)> = None;
    // The current run of `cyc = 1` on the port: its inputs and the takes in it.
    let mut run: Option<(PortIn, usize)> = None;
    let mut clocks = 0;
    while bs.len() < n || rs.len() < n {
        clocks += 1;
        assert!(clocks < 200 * n + 1000, "no progress (seed {seed})");
        let o = s.out();
        // AXI: a valid stays up, with its payload, until its handshake.
        if let Some((po, pi)) = prev {
            if po.bvalid & !pi.bready {
                assert!(o.bvalid && o.bresp == po.bresp, "B dropped (seed {seed})");
            }
            if po.rvalid & !pi.rready {
                assert!(o.rvalid && (o.rdata, o.rresp) == (po.rdata, po.rresp));
            }
        }
        // A response only for an address (and data) taken at an earlier edge.
        if o.bvalid {
            assert!(bs.len() < aw_sent.len().min(w_sent.len()));
            assert!(o.bresp == OKAY || o.bresp == SLVERR);
        }
        if o.rvalid {
            assert!(rs.len() < ar_sent.len());
        }
        // The master: new requests, never waiting for a ready.
        if aw.is_none() && aw_sent.len() < n && rng.chance(busy) {
            aw = Some(rng.addr());
        }
        if w.is_none() && w_sent.len() < n && rng.chance(busy) {
            let strb = if rng.chance(70) {
                0xF
            } else {
                rng.below(16) as u8
            };
            w = Some((rng.next() as u32, strb));
        }
        if ar.is_none() && ar_sent.len() < n && rng.chance(busy) {
            ar = Some(rng.addr());
        }
        let junk = rng.next();
        let i = AxiIn {
            awaddr: aw.unwrap_or(junk as u8).into(),
            awvalid: aw.is_some(),
            wdata: w.map_or(junk as u32, |w| w.0),
            wstrb: w.map_or((junk >> 8) as u8 & 0xF, |w| w.1),
            wvalid: w.is_some(),
            bready: rng.chance(ready),
            araddr: ar.unwrap_or((junk >> 16) as u8).into(),
            arvalid: ar.is_some(),
            rready: rng.chance(ready),
        };
        if i.awvalid & o.awready {
            aw_sent.push(aw.take().unwrap());
        }
        if i.wvalid & o.wready {
            w_sent.push(w.take().unwrap());
        }
        if i.arvalid & o.arready {
            ar_sent.push(ar.take().unwrap());
        }
        if o.bvalid & i.bready {
            bs.push(o.bresp);
        }
        if o.rvalid & i.rready {
            rs.push((o.rdata, o.rresp));
        }
        // Wishbone: inputs stable over a run of cyc, one take per run.
        let pin = s.bridge.port_in();
        let takes = s.regs.log.len();
        run = match (run, pin.cyc) {
            (None, false) => None,
            (None, true) => Some((pin, 0)),
            (Some((p, k)), true) => {
                // `dat` and `sel` matter only on writes (§1: `sel` is ignored on
                // reads); during a read they follow `w_dat`/`w_strb`, which may
                // take a new W beat.
                let key = |p: PortIn| (p.we, p.adr, p.we.then_some((p.dat, p.sel)));
                assert_eq!(key(p), key(pin), "port inputs changed during an access");
                Some((p, k))
            }
            (Some((_, k)), false) => {
                assert_eq!(k, 1, "one take per access");
                None
            }
        };
        s.edge(&i);
        if let Some((_, k)) = &mut run {
            *k += s.regs.log.len() - takes;
        }
        // At most one access of each kind from its take to its response
        // handshake (§3 rule 2: a held response blocks only its own kind).
        let w_taken = s.regs.log.iter().filter(|a| a.we).count();
        let r_taken = s.regs.log.len() - w_taken;
        assert!(w_taken <= bs.len() + 1, "seed {seed}: two writes in flight");
        assert!(r_taken <= rs.len() + 1, "seed {seed}: two reads in flight");
        prev = Some((o, i));
    }
    // Every AW+W pair got one B, in order; every AR one R, in order.
    let writes: Vec<_> = s.regs.log.iter().filter(|a| a.we).collect();
    let reads: Vec<_> = s.regs.log.iter().filter(|a| !a.we).collect();
    assert_eq!((writes.len(), reads.len()), (n, n));
    for (k, a) in writes.iter().enumerate() {
        assert_eq!(
            (a.adr, a.dat, a.sel),
            (aw_sent[k] >> 2, w_sent[k].0, w_sent[k].1)
        );
        let refused = fake_regs::refused(a.adr, a.sel);
        assert_eq!(
            bs[k],
            if refused { SLVERR } else { OKAY },
            "seed {seed} write {k}"
        );
    }
    for (k, a) in reads.iter().enumerate() {
        assert_eq!(a.adr, ar_sent[k] >> 2);
        assert_eq!(rs[k], (a.held, OKAY), "seed {seed} read {k}");
    }
    // rdata is what the block holds: replay the accesses on a shadow of §1.
    let mut shadow = FakeRegs::default();
    for a in &s.regs.log {
        if a.we {
            if !fake_regs::refused(a.adr, a.sel) {
                for lane in 0..4 {
                    if a.sel >> lane & 1 == 1 {
                        let m = 0xFFu32 << (8 * lane);
                        let word = &mut shadow.mem[a.adr as usize];
                        *word = (*word & !m) | (a.dat & m);
                    }
                }
            }
        } else {
            assert_eq!(a.held, shadow.read(a.adr), "seed {seed}");
        }
    }
    assert_eq!(shadow.mem, s.regs.mem);
}

#[test]
fn random_traffic_keeps_axi_rules() {
    for seed in 1..=24u64 {
        let busy = [10, 50, 90, 100][seed as usize % 4];
        let ready = [100, 70, 30, 5][seed as usize / 4 % 4];
        random_traffic(seed, 150, busy, ready);
    }
}
