//! Reference model of the DRCC top (`drcc_contract.md`, DRCC paper Table 1 and
//! section IV). Expected values come from the contract and the paper; the harness
//! (two wired-AND buses, a Wishbone master taking 2 clocks per access as contract §2,
//! plain `ChannelModel` nodes as partners) is written here, and the register map
//! below is copied from the contract's table, not from the model.

use drcc_cosim::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::model::drcc::DrccParams;
use drcc_cosim::model::ChannelModel;
use drcc_cosim::{BitTiming, ChannelInputs, ChannelOutputs, ControllerConfig, Frame};

mod busoff_recovery;
mod channel_switching;
mod driver_features;
mod ecss;
mod filters;
mod identification;
mod reception;
mod registers;
mod star_node;
mod stats_clear;
mod timestamps_events;
mod tx_abort;

// Word indices (contract §3).
const ID: u8 = 0;
const CTRL: u8 = 1;
const BTR: u8 = 2;
const RMB_CFG: u8 = 3;
const DEDUP_CFG: u8 = 4;
const STATUS: u8 = 5;
const INT_STATUS: u8 = 6;
const INT_ENABLE: u8 = 7;
const CHAN_A_ERR: u8 = 8;
const CHAN_B_ERR: u8 = 9;
const AUX_A: u8 = 10;
const AUX_B: u8 = 11;
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
const STATS1: u8 = 23;
const TIMES: u8 = 24;
const VERSION: u8 = 38;
const SIZES: u8 = 39;
const CAP_A: u8 = 40;
const CAP_B: u8 = 41;

// CTRL fields.
const RESET_MODE: u32 = 1;
const REDUNDANCY: u32 = 1 << 1;
const fn policy(p: u32) -> u32 {
    p << 2
}
const DUAL_TX: u32 = 1 << 4;
const fn k(k: u32) -> u32 {
    k << 8
}

// INT_STATUS bits.
const I_RX: u32 = 1;
const I_TX_DONE: u32 = 1 << 1;
const I_SWITCH: u32 = 1 << 2;
const I_ERR_STATE: u32 = 1 << 3;
const I_OVERRUN: u32 = 1 << 4;
const I_TX_FAILURE: u32 = 1 << 5;
const I_ILLEGAL: u32 = 1 << 6;
const I_AUX: u32 = 1 << 7;
const I_ERR_WARNING: u32 = 1 << 10;
const I_ARB_LOST: u32 = 1 << 11;
const I_BUS_ERROR: u32 = 1 << 12;

// Main FSM states (Table 1) and aux states (§5).
const IDLE1: u8 = 0;
const WAIT1: u8 = 1;
const CH1: u8 = 2;
const ABORT1: u8 = 3;
const WAIT2: u8 = 4;
const IDLE2: u8 = 5;
const WAIT3: u8 = 6;
const CH2: u8 = 7;
const WAIT4: u8 = 9;
const VALID: u8 = 0;
const FAILED: u8 = 1;
const RESTART: u8 = 2;
const PROBATION: u8 = 3;

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

fn frame(id: u32, ide: bool, rtr: bool, dlc: u8, data: &[u8]) -> Frame {
    let mut d = [0u8; 8];
    d[..data.len()].copy_from_slice(data);
    Frame {
        id,
        ide,
        rtr,
        dlc,
        data: d,
    }
}

/// A DRCC node: its engine, its last outputs and the Wishbone inputs of the next clock.
#[derive(Clone)]
struct Node {
    engine: DrccModelEngine,
    out: DrccOutputs,
    wb: DrccInputs,
    /// Connected to bus A / bus B.
    on: [bool; 2],
}

/// A plain channel on one bus: acknowledges, receives, transmits on request.
#[derive(Clone)]
struct Plain {
    chan: ChannelModel,
    out: ChannelOutputs,
    bus: usize,
    connected: bool,
    req: Option<Frame>,
    received: Vec<Frame>,
    done: usize,
}

/// Two wired-AND buses (A = 0, B = 1) of DRCC nodes and plain nodes.
#[derive(Clone)]
struct Sys {
    nodes: Vec<Node>,
    plain: Vec<Plain>,
    clock: u64,
    /// Node 0's paper probes, every clock.
    trace: Trace,
    /// Bus A / B held dominant (a fault of the line), whatever the nodes drive.
    stuck: [bool; 2],
}

impl Sys {
    fn new(drcc: usize) -> Self {
        Self::with_params(drcc, &DrccParams::default())
    }

    /// `drcc` DRCC nodes generated with the sizes of `p` (contract §1.1).
    fn with_params(drcc: usize, p: &DrccParams) -> Self {
        let nodes = (0..drcc)
            .map(|_| Node {
                engine: DrccModelEngine::with_params(p),
                out: DrccOutputs {
                    chan_a_tx: true,
                    chan_b_tx: true,
                    ..Default::default()
                },
                wb: DrccInputs::default(),
                on: [true, true],
            })
            .collect();
        Sys {
            nodes,
            plain: Vec::new(),
            clock: 0,
            trace: Trace::default(),
            stuck: [false; 2],
        }
    }

    /// Adds a plain node on `bus`; returns its index.
    fn add_plain(&mut self, bus: usize, connected: bool) -> usize {
        let chan = ChannelModel::new();
        let out = chan.outputs();
        self.plain.push(Plain {
            chan,
            out,
            bus,
            connected,
            req: None,
            received: Vec::new(),
            done: 0,
        });
        self.plain.len() - 1
    }

    /// The level of each bus as the nodes see it in the next step.
    fn levels(&self) -> [bool; 2] {
        let mut l = self.stuck.map(|s| !s);
        for n in &self.nodes {
            l[0] &= n.out.chan_a_tx || !n.on[0];
            l[1] &= n.out.chan_b_tx || !n.on[1];
        }
        for p in &self.plain {
            if p.connected {
                l[p.bus] &= p.out.tx;
            }
        }
        l
    }

    /// One clock of everything.
    fn step(&mut self) {
        let l = self.levels();
        for n in &mut self.nodes {
            let mut i = n.wb;
            i.chan_a_rx = if n.on[0] { l[0] } else { true };
            i.chan_b_rx = if n.on[1] { l[1] } else { true };
            n.out = n.engine.step(&i);
        }
        for p in &mut self.plain {
            let r = p.req.take();
            p.out = p.chan.step(&ChannelInputs {
                rst: false,
                rx: if p.connected { l[p.bus] } else { true },
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
                p.received.push(p.out.rx_frame);
            }
            if p.out.tx_done {
                p.done += 1;
            }
        }
        self.clock += 1;
        if let Some(n) = self.nodes.first() {
            self.trace.record(self.clock, &n.out);
        }
    }

    fn run(&mut self, clocks: u64) {
        for _ in 0..clocks {
            self.step();
        }
    }

    /// Wishbone access (contract §2): the request clock (taken: ack 1 after it) and
    /// the ack clock (the master drops the strobe: ack 0 after it).
    fn access(&mut self, n: usize, adr: u8, we: bool, dat: u32) -> u32 {
        self.access_lanes(n, adr, we, dat, 0xF).0
    }

    /// An access with the byte lanes `sel` (bus_contract.md §1): the read data
    /// and whether it ended with ERR.
    fn access_lanes(&mut self, n: usize, adr: u8, we: bool, dat: u32, sel: u8) -> (u32, bool) {
        assert!(
            !(self.nodes[n].out.wb_ack || self.nodes[n].out.wb_err),
            "no access while ack or err is high"
        );
        self.nodes[n].wb = DrccInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: we,
            wb_adr: adr,
            wb_dat_w: dat,
            wb_sel: sel,
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
        assert!(
            !(self.nodes[n].out.wb_ack || self.nodes[n].out.wb_err),
            "ack and err are one-clock pulses"
        );
        assert_eq!(self.nodes[n].out.wb_dat_r, 0, "wb_dat_o is 0 without ack");
        if we {
            assert_eq!(o.wb_dat_r, 0, "a write returns no data");
        }
        (o.wb_dat_r, o.wb_err)
    }

    fn write(&mut self, n: usize, adr: u8, dat: u32) {
        self.access(n, adr, true, dat);
    }

    fn read(&mut self, n: usize, adr: u8) -> u32 {
        self.access(n, adr, false, 0)
    }

    /// Writes CTRL, clearing reset mode.
    fn start(&mut self, n: usize, ctrl: u32) {
        self.write(n, CTRL, ctrl & !RESET_MODE);
    }

    /// Stages `f` and pushes it (TX_CTRL.queue = `queue`).
    fn push(&mut self, n: usize, f: &Frame, queue: u32) {
        let id = f.id | (f.ide as u32) << 29 | (f.rtr as u32) << 30;
        self.write(n, TX_ID, id);
        self.write(n, TX_CTRL, f.dlc as u32 | queue << 8);
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
}

/// STATUS fields.
fn status_state(s: u32) -> u8 {
    (s & 0xF) as u8
}
fn status_txq(s: u32, q: u32) -> u32 {
    s >> (16 + 4 * q) & 0xF
}
fn status_rx_count(s: u32) -> u32 {
    s >> 24 & 0x3F
}

/// Everything the paper scenario records, clock by clock.
#[derive(Clone, Default)]
struct Trace {
    states: Vec<(u64, u8)>,
    aux_a: Vec<(u64, u8)>,
    tec_a: Vec<u16>,
    ack: Vec<u64>,
    success: Vec<u64>,
    failure: Vec<(u64, u8)>,
    sample_a: Vec<(u64, bool)>,
}

impl Trace {
    fn record(&mut self, clock: u64, o: &DrccOutputs) {
        let p = o.probes;
        if self.states.last().map(|s| s.1) != Some(p.state) {
            self.states.push((clock, p.state));
        }
        if self.aux_a.last().map(|s| s.1) != Some(p.aux_a_state) {
            self.aux_a.push((clock, p.aux_a_state));
        }
        if self.tec_a.last() != Some(&p.chan_a_bsp_tx_err_cnt) {
            self.tec_a.push(p.chan_a_bsp_tx_err_cnt);
        }
        if p.transmission_ack {
            self.ack.push(clock);
        }
        if p.tx_success {
            self.success.push(clock);
        }
        if p.tx_failure {
            self.failure.push((clock, p.tx_failure_channel));
        }
        self.sample_a.push((clock, p.chan_a_sample_point));
        // Contract §4 outputs derived from the state.
        assert_eq!(p.tx_channel, p.state >= IDLE2);
        assert_eq!(p.tx_going_on, p.state != IDLE1 && p.state != IDLE2);
        assert_eq!(
            p.chan_a_bsp_node_error_passive,
            p.chan_a_err_state != 0,
            "error passive probe"
        );
    }

    fn state_seq(&self) -> Vec<u8> {
        self.states.iter().map(|s| s.1).collect()
    }

    fn clock_of(&self, state: u8) -> u64 {
        self.states.iter().find(|s| s.1 == state).unwrap().0
    }
}
