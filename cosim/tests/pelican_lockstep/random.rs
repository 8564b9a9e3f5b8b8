//! Random register traffic in lock step on the Verilated `drcc_pelican`: the
//! whole map (0..127) read and written with random bytes, the commands, the
//! mode and extension keys changed in reset mode and refused in operating mode,
//! refused lane patterns, the other nodes sending frames on both lines, and the
//! lines cut and mended. The expected outputs are the model's, every clock
//! (`crate::shadow`); the traffic checks nothing by itself.

use crate::harness::{Net, BIT};
use crate::shadow::Shadow;
use drcc_cosim::model::pelican::{PelicanInputs, PelicanParams};
use drcc_cosim::Frame;

/// xorshift64*: the stimulus, reproducible by seed.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn percent(&mut self, p: u64) -> bool {
        self.below(100) < p
    }
    fn byte(&mut self) -> u8 {
        self.next() as u8
    }
}

/// A random frame for the other nodes.
fn frame(rng: &mut Rng) -> Frame {
    let ide = rng.percent(30);
    let rtr = rng.percent(10);
    let mut data = [0u8; 8];
    let dlc = rng.below(9) as u8;
    for b in data.iter_mut().take(dlc as usize) {
        *b = rng.byte();
    }
    Frame {
        id: if ide {
            rng.next() as u32 & 0x1FFF_FFFF
        } else {
            rng.next() as u32 & 0x7FF
        },
        ide,
        rtr,
        dlc,
        data: if rtr { [0; 8] } else { data },
    }
}

/// A register write the SJA1000 software or a confused one might do.
fn random_write(n: &mut Net, rng: &mut Rng) {
    let (r, b) = match rng.below(16) {
        // MOD: reset / operating with listen-only, self-test, filter mode, SM
        0 | 1 => (
            0,
            [0x00, 0x01, 0x02, 0x04, 0x08, 0x09, 0x10, 0x03][rng.below(8) as usize],
        ),
        // CMR: TR, TR+AT, AT, RRB, CDO, SRR, SRR+AT, anything
        2..=4 => (
            1,
            [0x01, 0x03, 0x02, 0x04, 0x08, 0x10, 0x12, rng.byte()][rng.below(8) as usize],
        ),
        5 => (4, rng.byte()),
        // the TX buffer through the window (operating mode) or ACR/AMR (reset)
        6 | 7 => (16 + rng.below(13) as u8, rng.byte()),
        // XMODE (modes, policies, star, dual_tx, bom), XK, XIER, the window
        8 => (115, rng.byte() & 0x7F),
        9 => (116 + rng.below(12) as u8, rng.byte()),
        // bit timing, EWLR, counters, CDR, RBSA: mostly the harness's timing
        10 => (
            [6, 7, 13, 14, 15, 31, 30, 8][rng.below(8) as usize],
            if rng.percent(60) {
                [0x00, 0x14, 0x60, 0x00][rng.below(4) as usize]
            } else {
                rng.byte()
            },
        ),
        // the RX RAM, TXB and SCR at their RAM addresses, anything
        _ => (rng.below(128) as u8, rng.byte()),
    };
    n.w(r, b);
}

/// One random access with any lane pattern (refusals included).
fn random_raw(n: &mut Net, rng: &mut Rng) {
    let we = rng.percent(30);
    let adr = rng.below(128) as u8;
    let dat = rng.next() as u32;
    let sel = rng.below(16) as u8;
    n.access(we, adr, dat, sel);
}

/// `ops` random operations on a top with the generator's default keys.
fn run(seed: u64, ops: usize) {
    let p = PelicanParams::default();
    let mut n = Net::new(p);
    n.shadow = Shadow::with(&p, false);
    if !n.shadow.verilated() {
        return;
    }
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    for _ in 0..4 {
        n.clk(PelicanInputs {
            rst: true,
            ..Default::default()
        });
    }
    // start as a driver would, then wander
    n.linux_start(0xFF, 0x00);
    for _ in 0..ops {
        match rng.below(20) {
            0..=6 => random_write(&mut n, &mut rng),
            7..=11 => {
                let r = rng.below(128) as u8;
                n.r(r);
            }
            12 => random_raw(&mut n, &mut rng),
            13 | 14 => {
                let x = rng.below(2) as usize;
                if n.peer_req[x].is_none() {
                    n.peer_req[x] = Some(frame(&mut rng));
                }
            }
            15 => {
                let x = rng.below(2) as usize;
                n.cut[x] = rng.percent(30);
            }
            16 if rng.percent(5) => {
                n.clk(PelicanInputs {
                    rst: true,
                    ..Default::default()
                });
            }
            _ => n.idle(rng.below(8 * BIT)),
        }
    }
}

#[test]
fn random_traffic_seed_1() {
    run(1, 3000);
}

#[test]
fn random_traffic_seed_2() {
    run(2, 3000);
}

#[test]
fn random_traffic_seed_3() {
    run(3, 3000);
}
