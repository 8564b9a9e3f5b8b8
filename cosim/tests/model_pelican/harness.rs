//! A PeliCAN top on line A (and B) with one plain channel model per line as
//! the other node, and a Wishbone master doing SJA1000 byte accesses.

use crate::support;
use drcc_cosim::model::pelican::{PelicanInputs, PelicanModel, PelicanOutputs, PelicanParams};
use drcc_cosim::model::ChannelModel;
use drcc_cosim::{ChannelInputs, ChannelOutputs, ControllerConfig, Frame, Mode};

/// Clocks per bit with BTR0 = 0, BTR1 = 0x14: 2 clocks a tq, 8 tq.
pub const BIT: u64 = 16;

#[derive(Clone)]
pub struct Net {
    pub dut: PelicanModel,
    pub peer: [ChannelModel; 2],
    pub peer_out: [ChannelOutputs; 2],
    pub peer_mode: Mode,
    /// The peer of line x is on the bus.
    pub peer_on: [bool; 2],
    /// Line x is cut at the DUT (it sees recessive, its tx goes nowhere).
    pub cut: [bool; 2],
    /// Something else drives line x dominant (another node's bit, or a fault):
    /// the DUT and the peer both see it.
    pub force_dom: [bool; 2],
    pub tx: [bool; 2],
    pub out: PelicanOutputs,
    pub clock: u64,
    /// The frame the peer of line x is asked to send.
    pub peer_req: [Option<Frame>; 2],
    pub received: Vec<(usize, Frame)>,
    /// Whatever the test binary runs beside the model, edge by edge
    /// (`crate::shadow`: nothing here; the RTL core in the core lock step).
    pub shadow: crate::shadow::Shadow,
    /// Reset the other nodes at the next clock (`reset_peers`).
    pub peer_rst: bool,
    /// `XMODE` and `XK` written in reset mode after every hardware reset
    /// (`keyed`).
    pub rekey: Option<(u8, u8)>,
}

impl Net {
    /// A top generated with the keys `p`.
    pub fn new(p: PelicanParams) -> Self {
        Self::build(p, crate::shadow::Shadow::new(&p))
    }

    /// A top that behaves as one generated with the keys `p`. The keys that
    /// differ only in what `XMODE` and `XK` hold set only those registers'
    /// reset values (P-GEN-1, §13), so where the lock step has a top built
    /// with other such keys (`crate::shadow::Shadow::keyed`), that top runs
    /// with `XMODE` and `XK` written in reset mode after every hardware reset.
    /// Elsewhere this is `new(p)`.
    pub fn keyed(p: PelicanParams) -> Self {
        match crate::shadow::Shadow::keyed(&p) {
            Some((built, shadow)) if built != p => {
                let mut n = Self::build(built, shadow);
                n.rekey = Some((p.xmode(), p.k));
                n.write_keys();
                n
            }
            Some((_, shadow)) => Self::build(p, shadow),
            None => Self::new(p),
        }
    }

    fn build(p: PelicanParams, shadow: crate::shadow::Shadow) -> Self {
        let peer = [ChannelModel::new(), ChannelModel::new()];
        let peer_out = [peer[0].outputs(), peer[1].outputs()];
        let mut n = Net {
            dut: PelicanModel::new(p),
            peer,
            peer_out,
            peer_mode: Mode::Normal,
            peer_on: [true, true],
            cut: [false, false],
            force_dom: [false, false],
            tx: [true, true],
            out: PelicanOutputs {
                dat: 0,
                ack: false,
                err: false,
                irq: false,
                chan_a_tx: true,
                chan_b_tx: true,
            },
            clock: 0,
            peer_req: [None, None],
            received: vec![],
            shadow,
            peer_rst: false,
            rekey: None,
        };
        // the documented minimum reset: 4 edges with rst high
        for _ in 0..4 {
            n.clk(PelicanInputs {
                rst: true,
                ..Default::default()
            });
        }
        n
    }

    /// One clock with `rst` (a hardware reset in the middle of a test), then
    /// the keys of a `keyed` top.
    pub fn hardware_reset(&mut self) {
        self.clk(PelicanInputs {
            rst: true,
            ..Default::default()
        });
        self.write_keys();
    }

    /// `XMODE` and `XK` of a `keyed` top, written in reset mode (after a
    /// reset, P-MOD-1).
    fn write_keys(&mut self) {
        if let Some((xmode, k)) = self.rekey {
            self.w(115, xmode);
            self.w(116, k);
        }
    }

    /// One clock with the Wishbone inputs of `i`.
    pub fn clk(&mut self, mut i: PelicanInputs) -> PelicanOutputs {
        // Line x: the peer's tx (if on) AND the DUT's tx (unless cut) AND
        // whatever else drives it.
        let line = |x: usize, s: &Net| {
            (!s.peer_on[x] || s.peer_out[x].tx) && (s.cut[x] || s.tx[x]) && !s.force_dom[x]
        };
        let (pa, pb) = (line(0, self), line(1, self));
        i.chan_a_rx = self.cut[0] || pa;
        i.chan_b_rx = self.cut[1] || pb;
        self.out = self.dut.step(&i);
        self.shadow.edge(&i, &self.dut);
        self.tx = [self.out.chan_a_tx, self.out.chan_b_tx];
        for (x, prx) in [pa, pb].into_iter().enumerate() {
            let rst = self.clock == 0 || self.peer_rst;
            let req = self.peer_req[x];
            let o = self.peer[x].step(&ChannelInputs {
                rst,
                rx: prx,
                timing: support::timing(1),
                config: ControllerConfig {
                    mode: self.peer_mode,
                    ..Default::default()
                },
                tx_req: req.is_some() && !self.peer_out[x].tx_pending,
                tx_frame: req.unwrap_or_default(),
                ..Default::default()
            });
            if o.tx_pending {
                self.peer_req[x] = None;
            }
            if o.rx_valid {
                self.received.push((x, o.rx_frame));
            }
            self.peer_out[x] = o;
        }
        self.peer_rst = false;
        self.clock += 1;
        self.out
    }

    /// Reset the other nodes for one clock with `mode` (e.g. SELF_TEST: a
    /// node that needs no ACK); the DUT runs on. Pending requests are dropped.
    pub fn reset_peers(&mut self, mode: Mode) {
        self.peer_mode = mode;
        self.peer_req = [None, None];
        self.peer_rst = true;
        self.idle(1);
    }

    pub fn idle(&mut self, n: u64) {
        for _ in 0..n {
            self.clk(PelicanInputs::default());
        }
    }

    /// A Wishbone access with raw address and lanes; returns (dat, ack, err).
    pub fn access(&mut self, we: bool, adr: u8, dat: u32, sel: u8) -> (u32, bool, bool) {
        let o = self.clk(PelicanInputs {
            cyc: true,
            stb: true,
            we,
            adr,
            dat,
            sel,
            ..Default::default()
        });
        self.clk(PelicanInputs::default());
        (o.dat, o.ack, o.err)
    }

    /// Register byte write in the SJA1000 sense at either stride.
    pub fn w(&mut self, r: u8, b: u8) {
        let (_, ack, _) = if self.dut.params().stride == 4 {
            self.access(true, r, b as u32, 1)
        } else {
            let l = r & 3;
            self.access(true, r >> 2, (b as u32) << (8 * l), 1 << l)
        };
        assert!(ack, "write of register {r} acknowledged");
    }

    /// Register byte read.
    pub fn r(&mut self, r: u8) -> u8 {
        if self.dut.params().stride == 4 {
            let (d, ack, _) = self.access(false, r, 0, 1);
            assert!(ack);
            d as u8
        } else {
            let l = r & 3;
            let (d, ack, _) = self.access(false, r >> 2, 0, 1 << l);
            assert!(ack);
            (d >> (8 * l)) as u8
        }
    }

    /// Run until `f` holds or `max` clocks pass; returns the clocks taken.
    pub fn until(&mut self, max: u64, mut f: impl FnMut(&mut Net) -> bool) -> u64 {
        for k in 0..max {
            if f(self) {
                return k;
            }
            self.clk(PelicanInputs::default());
        }
        panic!("condition not reached in {max} clocks");
    }

    /// The Linux `sja1000.c` start: reset mode, CDR with the PeliCAN bit, bit
    /// timing, accept all, IER, operating mode; then bus integration.
    pub fn linux_start(&mut self, ier: u8, mode: u8) {
        self.w(0, 0x01);
        self.w(31, 0x80 | 0x40);
        self.w(6, 0x00);
        self.w(7, 0x14);
        for k in 0..4 {
            self.w(16 + k, 0x00);
            self.w(20 + k, 0xFF);
        }
        self.w(8, 0x1A);
        self.w(4, ier);
        self.w(0, mode);
        self.idle(20 * BIT);
    }

    /// Write a frame into the TX window at 16.. (standard or extended layout).
    pub fn load_tx(&mut self, f: &Frame) {
        let fi = (f.ide as u8) << 7 | (f.rtr as u8) << 6 | f.dlc;
        let mut b = vec![fi];
        if f.ide {
            b.extend([
                (f.id >> 21) as u8,
                (f.id >> 13) as u8,
                (f.id >> 5) as u8,
                (f.id << 3) as u8,
            ]);
        } else {
            b.extend([(f.id >> 3) as u8, (f.id << 5) as u8]);
        }
        b.extend(&f.data[..f.dlc.min(8) as usize]);
        for (k, x) in b.into_iter().enumerate() {
            self.w(16 + k as u8, x);
        }
    }

    /// Read the receive window 16.. as a frame.
    pub fn read_rx(&mut self) -> Frame {
        let fi = self.r(16);
        let (ide, rtr, dlc) = (fi & 0x80 != 0, fi & 0x40 != 0, fi & 0x0F);
        let (id, d0) = if ide {
            let b: Vec<u8> = (17..21).map(|r| self.r(r)).collect();
            (
                (b[0] as u32) << 21 | (b[1] as u32) << 13 | (b[2] as u32) << 5 | (b[3] as u32) >> 3,
                21,
            )
        } else {
            let b: Vec<u8> = (17..19).map(|r| self.r(r)).collect();
            ((b[0] as u32) << 3 | (b[1] as u32) >> 5, 19)
        };
        let mut data = [0u8; 8];
        for k in 0..if rtr { 0 } else { dlc.min(8) } {
            data[k as usize] = self.r(d0 + k);
        }
        Frame {
            id,
            ide,
            rtr,
            dlc,
            data,
        }
    }
}

/// Parameters for a `single_a` top at `stride`.
pub fn single_a(stride: u8, bom: bool) -> PelicanParams {
    PelicanParams {
        stride,
        mode: 0,
        bom,
        ..PelicanParams::default()
    }
}

/// An extended frame.
pub fn ext(id: u32, data: &[u8]) -> Frame {
    let mut d = [0u8; 8];
    d[..data.len()].copy_from_slice(data);
    Frame {
        id,
        ide: true,
        rtr: false,
        dlc: data.len() as u8,
        data: d,
    }
}
