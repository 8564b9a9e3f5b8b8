//! Reference model of the DRCC's DMR mode (`dmr_contract.md`, CiA 701 as in seed
//! 001). Expected values come from the contract and the seed, computed by hand in
//! each test with the rule cited; the harness (two wired-AND lines, DMR devices
//! whose channels can be cut or swapped, lines that can be short-circuited, plain
//! `ChannelModel` nodes as partners, a Wishbone master taking 2 clocks per access as
//! §D.2) is written here, and the register map below is copied from the contract's
//! tables, not from the model.

use drcc_cosim::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::model::ChannelModel;
use drcc_cosim::{BitTiming, ChannelInputs, ChannelOutputs, ControllerConfig, Frame};

mod driver_features;
mod engine;
mod network;
mod reception;
mod recovery;
mod registers;
mod transmission;

// Word indices (drcc_contract.md §3, dmr_contract.md §2.1).
const CTRL: u8 = 1;
const DEDUP_CFG: u8 = 4;
const STATUS: u8 = 5;
const INT_STATUS: u8 = 6;
const INT_ENABLE: u8 = 7;
const TX_ID: u8 = 12;
const TX_CTRL: u8 = 13;
const TX_DATA0: u8 = 14;
const TX_DATA1: u8 = 15;
const TX_CMD: u8 = 16;
const RX_ID: u8 = 17;
const RX_CTRL: u8 = 18;
const RX_DATA0: u8 = 19;
const RX_DATA1: u8 = 20;
const RX_CMD: u8 = 21;
const STATS0: u8 = 22;
const DMR_CFG: u8 = 25;
const DMR_TIME: u8 = 26;
const DMR_CS: u8 = 27;
const DMR_STATUS: u8 = 28;
const DMR_CS_COUNT: u8 = 29;
const DMR_RX_STATS: u8 = 30;
const MB_SEL: u8 = 31;
const MB_ID: u8 = 32;
const MB_MASK: u8 = 33;
const MB_CFG: u8 = 34;
const MB_STATE: u8 = 35;

// CTRL fields.
const RESET_MODE: u32 = 1;
const REDUNDANCY: u32 = 1 << 1;
const DMR: u32 = 1 << 17;
const fn mode_a(m: u32) -> u32 {
    m << 12
}
const fn mode_b(m: u32) -> u32 {
    m << 14
}
const LISTEN_ONLY: u32 = 1;

// INT_STATUS bits.
const I_TX_DONE: u32 = 1 << 1;
const I_TX_FAILURE: u32 = 1 << 5;
const I_ILLEGAL: u32 = 1 << 6;
const I_DMR: u32 = 1 << 8;

// MB_ID / MB_CFG fields.
const MB_IDE: u32 = 1 << 29;
const MB_TX: u32 = 1 << 30;
const MB_ENABLE: u32 = 1 << 31;

// dmr_state (§1) and DMR_STATUS.cause (§2.1).
const ACTIVE: u8 = 0;
const PASSIVE: u8 = 1;
const DISABLED: u8 = 2;
const DISCONNECTED: u8 = 3;
const TIMEOUT: u32 = 0;
const DEVIATION: u32 = 1;
const BUSOFF: u32 = 2;
const CS_FAILED: u32 = 3;

// Lines.
const DCL: usize = 0;
const RCL: usize = 1;

/// Clocks per bit of the reset BTR: brp 0, 1 + 5 + 2 tq.
const CPB: u64 = 8;

/// The bit timing of the reset BTR, for the plain nodes.
fn timing() -> BitTiming {
    BitTiming {
        brp: 0,
        tseg1: 5,
        tseg2: 2,
        sjw: 1,
        triple_sampling: false,
    }
}

fn frame(id: u32, ide: bool, dlc: u8, data: &[u8]) -> Frame {
    let mut d = [0u8; 8];
    d[..data.len()].copy_from_slice(data);
    Frame {
        id,
        ide,
        rtr: false,
        dlc,
        data: d,
    }
}

/// The CS frame (§7): base format, the line's identifier, DLC 0.
fn cs(id: u32) -> Frame {
    frame(id, false, 0, &[])
}

/// A DMR device: its engine, its last outputs, the Wishbone inputs of the next
/// clock and the wiring of its channels (A = DCL pins, B = RCL pins).
struct Node {
    engine: DrccModelEngine,
    out: DrccOutputs,
    wb: DrccInputs,
    /// The line each channel is wired to; `None`: the stub is cut and the
    /// transceiver hears only itself (§10).
    wire: [Option<usize>; 2],
    /// DMR tick pulses seen (probe `dmr_tick`) and the clock of the last one.
    ticks: u64,
    last_tick: u64,
}

/// A plain channel on one line: acknowledges, receives, transmits on request.
struct Plain {
    chan: ChannelModel,
    out: ChannelOutputs,
    line: usize,
    req: Option<Frame>,
    received: Vec<(u64, Frame)>,
    done: usize,
}

/// Two wired-AND lines (DCL = 0, RCL = 1).
struct Sys {
    nodes: Vec<Node>,
    plain: Vec<Plain>,
    clock: u64,
    /// A short-circuited line reads recessive everywhere (§10).
    short: [bool; 2],
}

impl Sys {
    /// `n` devices with the default 16 mailboxes.
    fn new(n: usize) -> Self {
        Self::with_mailboxes(n, 16)
    }

    fn with_mailboxes(n: usize, m: usize) -> Self {
        let nodes = (0..n)
            .map(|_| Node {
                engine: DrccModelEngine::with_mailboxes(m),
                out: DrccOutputs {
                    chan_a_tx: true,
                    chan_b_tx: true,
                    ..Default::default()
                },
                wb: DrccInputs::default(),
                wire: [Some(DCL), Some(RCL)],
                ticks: 0,
                last_tick: 0,
            })
            .collect();
        Sys {
            nodes,
            plain: Vec::new(),
            clock: 0,
            short: [false; 2],
        }
    }

    /// Adds a plain node on `line`; returns its index.
    fn add_plain(&mut self, line: usize) -> usize {
        let chan = ChannelModel::new();
        let out = chan.outputs();
        self.plain.push(Plain {
            chan,
            out,
            line,
            req: None,
            received: Vec::new(),
            done: 0,
        });
        self.plain.len() - 1
    }

    /// The level of each line as the nodes see it in the next step.
    fn levels(&self) -> [bool; 2] {
        let mut l = [true, true];
        for n in &self.nodes {
            for (c, tx) in [n.out.chan_a_tx, n.out.chan_b_tx].into_iter().enumerate() {
                if let Some(line) = n.wire[c] {
                    l[line] &= tx;
                }
            }
        }
        for p in &self.plain {
            l[p.line] &= p.out.tx;
        }
        for (line, s) in self.short.iter().enumerate() {
            if *s {
                l[line] = true;
            }
        }
        l
    }

    /// One clock of everything.
    fn step(&mut self) {
        let l = self.levels();
        let clock = self.clock + 1;
        for n in &mut self.nodes {
            let mut i = n.wb;
            let own = [n.out.chan_a_tx, n.out.chan_b_tx];
            let rx = |c: usize| n.wire[c].map(|line| l[line]).unwrap_or(own[c]);
            i.chan_a_rx = rx(0);
            i.chan_b_rx = rx(1);
            n.out = n.engine.step(&i);
            if n.out.probes.dmr_tick {
                n.ticks += 1;
                n.last_tick = clock;
            }
        }
        for p in &mut self.plain {
            let r = p.req.take();
            p.out = p.chan.step(&ChannelInputs {
                rst: false,
                rx: l[p.line],
                timing: timing(),
                config: ControllerConfig::default(),
                tx_req: r.is_some(),
                tx_frame: r.unwrap_or_default(),
                tx_abort: false,
                err_reset: false,
                boff_hold: false,
                tx_single: false,
            });
            if p.out.rx_valid {
                p.received.push((self.clock + 1, p.out.rx_frame));
            }
            if p.out.tx_done {
                p.done += 1;
            }
        }
        self.clock += 1;
    }

    fn run(&mut self, clocks: u64) {
        for _ in 0..clocks {
            self.step();
        }
    }

    /// Runs until `cond` holds (at most `limit` clocks); panics with `what` if not.
    fn run_until(&mut self, limit: u64, what: &str, cond: impl Fn(&Sys) -> bool) {
        for _ in 0..limit {
            if cond(self) {
                return;
            }
            self.step();
        }
        assert!(cond(self), "timed out waiting for {what}");
    }

    /// Runs until node `n` has seen `k` more DMR ticks.
    fn run_ticks(&mut self, n: usize, k: u64) {
        let t = self.nodes[n].ticks + k;
        self.run_until(u64::MAX, "DMR ticks", |s| s.nodes[n].ticks >= t);
    }

    /// Wishbone access (§D.2): the request clock and the ack clock.
    fn access(&mut self, n: usize, adr: u8, we: bool, dat: u32) -> u32 {
        self.nodes[n].wb = DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: we,
            wb_adr: adr,
            wb_dat_w: dat,
            ..Default::default()
        };
        self.step();
        let o = self.nodes[n].out;
        assert!(
            o.wb_ack != o.wb_err,
            "ack or err one clock after the request"
        );
        self.nodes[n].wb = DrccInputs::default();
        self.step();
        o.wb_dat_r
    }

    fn write(&mut self, n: usize, adr: u8, dat: u32) {
        self.access(n, adr, true, dat);
    }

    fn read(&mut self, n: usize, adr: u8) -> u32 {
        self.access(n, adr, false, 0)
    }

    /// Writes `dat` to `adr` and tells whether it was refused: the register is
    /// unchanged (if readable) and `INT_STATUS.illegal` is set (§2.2).
    fn refused(&mut self, n: usize, adr: u8, dat: u32) -> bool {
        self.write(n, INT_STATUS, 0x1FF);
        self.write(n, adr, dat);
        self.read(n, INT_STATUS) & I_ILLEGAL != 0
    }

    /// Configures mailbox `i` of node `n` (reset mode): id word (with ide / dir),
    /// mask, limit, enabled.
    fn mailbox(&mut self, n: usize, i: u32, id: u32, mask: u32, limit: u32) {
        self.write(n, MB_SEL, i);
        self.write(n, MB_ID, id);
        self.write(n, MB_MASK, mask);
        self.write(n, MB_CFG, limit | MB_ENABLE);
        assert_eq!(
            self.read(n, INT_STATUS) & I_ILLEGAL,
            0,
            "mailbox {i} set up"
        );
    }

    /// DMR timing of node `n` (reset mode): `tick_bits`, `timeout`, `recovery_delay`.
    fn dmr_times(&mut self, n: usize, tick_bits: u32, timeout: u32, recovery: u32) {
        self.write(n, DMR_CFG, timeout);
        self.write(n, DMR_TIME, tick_bits | recovery << 16);
    }

    /// Leaves reset mode in DMR mode.
    fn start(&mut self, n: usize) {
        self.write(n, CTRL, DMR);
    }

    /// Stages `f` and pushes it into the one logical queue.
    fn push(&mut self, n: usize, f: &Frame) {
        let id = f.id | (f.ide as u32) << 29 | (f.rtr as u32) << 30;
        self.write(n, TX_ID, id);
        self.write(n, TX_CTRL, f.dlc as u32);
        self.write(
            n,
            TX_DATA0,
            u32::from_le_bytes(f.data[..4].try_into().unwrap()),
        );
        self.write(
            n,
            TX_DATA1,
            u32::from_le_bytes(f.data[4..].try_into().unwrap()),
        );
        self.write(n, TX_CMD, 1);
    }

    /// Reads the head of the RX FIFO (frame, channel) and pops it.
    fn pop(&mut self, n: usize) -> Option<(Frame, u32)> {
        let id = self.read(n, RX_ID);
        if id >> 31 == 0 {
            return None;
        }
        let ctrl = self.read(n, RX_CTRL);
        let d0 = self.read(n, RX_DATA0);
        let d1 = self.read(n, RX_DATA1);
        self.write(n, RX_CMD, 1);
        let mut data = [0u8; 8];
        data[..4].copy_from_slice(&d0.to_le_bytes());
        data[4..].copy_from_slice(&d1.to_le_bytes());
        Some((
            Frame {
                id: id & 0x1FFF_FFFF,
                ide: id >> 29 & 1 == 1,
                rtr: id >> 30 & 1 == 1,
                dlc: (ctrl & 0xF) as u8,
                data,
            },
            ctrl >> 8 & 1,
        ))
    }

    /// Every frame in node `n`'s RX FIFO, popped.
    fn drain(&mut self, n: usize) -> Vec<(Frame, u32)> {
        let mut v = Vec::new();
        while let Some(f) = self.pop(n) {
            v.push(f);
        }
        v
    }

    /// Plain node `p` sends `f`; returns when it is done.
    fn send(&mut self, p: usize, f: Frame) {
        let done = self.plain[p].done;
        self.plain[p].req = Some(f);
        self.run_until(400 * CPB, "a plain transmission", |s| {
            s.plain[p].done > done
        });
    }

    /// Frames plain node `p` received with identifier `id`.
    fn got(&self, p: usize, f: &Frame) -> usize {
        self.plain[p].received.iter().filter(|r| r.1 == *f).count()
    }

    fn probes(&self, n: usize) -> drcc_cosim::engine::drcc::DrccProbes {
        self.nodes[n].out.probes
    }
}

/// DMR_STATUS fields (§2.1).
struct DmrStatus(u32);

impl DmrStatus {
    fn state(&self) -> u8 {
        (self.0 & 3) as u8
    }
    fn acl(&self) -> usize {
        (self.0 >> 2 & 1) as usize
    }
    /// `[dcl_tx, dcl_rx, rcl_tx, rcl_rx]`.
    fn flags(&self) -> [bool; 4] {
        [3, 4, 5, 6].map(|b| self.0 >> b & 1 == 1)
    }
    fn cause(&self) -> u32 {
        self.0 >> 8 & 3
    }
    fn cause_line(&self) -> usize {
        (self.0 >> 10 & 1) as usize
    }
    fn cause_mb(&self) -> u32 {
        self.0 >> 12 & 0xF
    }
    fn state_changes(&self) -> u32 {
        self.0 >> 16 & 0xFF
    }
    fn acl_switches(&self) -> u32 {
        self.0 >> 24
    }
}

fn status(sys: &mut Sys, n: usize) -> DmrStatus {
    DmrStatus(sys.read(n, DMR_STATUS))
}

/// `MB_STATE` of mailbox `i` (live): (counter, timer).
fn mb_state(sys: &mut Sys, n: usize, i: u32) -> (i8, u16) {
    sys.write(n, MB_SEL, i);
    let s = sys.read(n, MB_STATE);
    (s as u8 as i8, (s >> 16) as u16)
}

/// TX queue A count (STATUS[19:16]) and RX FIFO count (STATUS[29:24]).
fn txq_count(sys: &mut Sys, n: usize) -> u32 {
    sys.read(n, STATUS) >> 16 & 0xF
}
fn rx_count(sys: &mut Sys, n: usize) -> u32 {
    sys.read(n, STATUS) >> 24 & 0x3F
}
