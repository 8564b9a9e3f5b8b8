//! Reference model of the DRCC top (`drcc_contract.md`, DRCC paper Table 1 and
//! section IV). Expected values come from the contract and the paper; the harness
//! (two wired-AND buses, a Wishbone master taking 2 clocks per access as contract §2,
//! plain `ChannelModel` nodes as partners) is written here, and the register map
//! below is copied from the contract's table, not from the model.

use drcc_cosim::engine::drcc::{DrccEngine, DrccInputs, DrccOutputs};
use drcc_cosim::engine::drcc_model::DrccModelEngine;
use drcc_cosim::model::ChannelModel;
use drcc_cosim::{BitTiming, ChannelInputs, ChannelOutputs, ControllerConfig, Frame};

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
struct Node {
    engine: DrccModelEngine,
    out: DrccOutputs,
    wb: DrccInputs,
    /// Connected to bus A / bus B.
    on: [bool; 2],
}

/// A plain channel on one bus: acknowledges, receives, transmits on request.
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
struct Sys {
    nodes: Vec<Node>,
    plain: Vec<Plain>,
    clock: u64,
    /// Node 0's paper probes, every clock.
    trace: Trace,
}

impl Sys {
    fn new(drcc: usize) -> Self {
        let nodes = (0..drcc)
            .map(|_| Node {
                engine: DrccModelEngine::new(),
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
        let mut l = [true, true];
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
        assert!(!self.nodes[n].out.wb_ack, "no access while ack is high");
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
        assert!(o.wb_ack, "ack one clock after the request");
        self.nodes[n].wb = DrccInputs::default();
        self.step();
        assert!(!self.nodes[n].out.wb_ack, "ack is a one-clock pulse");
        assert_eq!(self.nodes[n].out.wb_dat_r, 0, "wb_dat_o is 0 without ack");
        if we {
            assert_eq!(o.wb_dat_r, 0, "a write returns no data");
        }
        o.wb_dat_r
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

// ---------------------------------------------------------------------------
// (a) reset values and ID
// ---------------------------------------------------------------------------

/// Every register at its reset value (contract §3), also after `rst`.
#[test]
fn reset_values_and_id() {
    let expected: [(u8, u32); 25] = [
        (ID, 0x4452_4343),
        // reset_mode 1, redundancy 0, policy 1, dual_tx 0, k 1, modes 0, single shot 0.
        (CTRL, 1 | 1 << 2 | 1 << 8),
        // brp 0, tseg1 4, tseg2 1, sjw 0, triple 0, ewl 96.
        (BTR, 4 << 6 | 1 << 10 | 96 << 16),
        (RMB_CFG, 1024),
        (DEDUP_CFG, 1024),
        // state idle1, aux valid, error active, reset_mode 1, queues empty.
        (STATUS, 1 << 13),
        (INT_STATUS, 0),
        (INT_ENABLE, 0),
        (CHAN_A_ERR, 0),
        (CHAN_B_ERR, 0),
        (AUX_A, 0),
        (AUX_B, 0),
        (TX_ID, 0),
        (TX_CTRL, 0),
        (TX_DATA0, 0),
        (TX_DATA1, 0),
        (TX_CMD, 0),
        (RX_ID, 0),
        (RX_CTRL, 0),
        (RX_DATA0, 0),
        (RX_DATA1, 0),
        (RX_CMD, 0),
        (STATS0, 0),
        (STATS1, 0),
        (TIMES, 0),
    ];
    let mut sys = Sys::new(1);
    for &(adr, v) in &expected {
        assert_eq!(sys.read(0, adr), v, "register {adr} at power-up");
    }
    for adr in 25..64 {
        assert_eq!(sys.read(0, adr), 0, "unmapped word {adr} reads 0");
    }
    // Change some registers, then `rst` brings every one back.
    sys.write(0, INT_ENABLE, 0xFF);
    sys.write(0, BTR, 0x0012_3456);
    sys.write(0, TX_DATA0, 0xDEAD_BEEF);
    sys.write(0, CTRL, REDUNDANCY | policy(2) | k(3));
    sys.run(50);
    assert_ne!(sys.read(0, STATUS) & 1 << 13, 1 << 13, "left reset mode");
    sys.nodes[0].wb.rst = true;
    sys.step();
    sys.nodes[0].wb.rst = false;
    assert!(!sys.nodes[0].out.wb_ack && !sys.nodes[0].out.irq);
    for &(adr, v) in &expected {
        assert_eq!(sys.read(0, adr), v, "register {adr} after rst");
    }
    // The paper probes after rst.
    let p = sys.nodes[0].out.probes;
    assert_eq!(p.state, IDLE1);
    assert!(!p.tx_channel && !p.tx_going_on && !p.transmission_ack && !p.tx_success);
    assert_eq!((p.tx_ok_channel, p.tx_failure_channel), (0, 0));
    assert!(sys.nodes[0].out.chan_a_tx && sys.nodes[0].out.chan_b_tx);
}

// ---------------------------------------------------------------------------
// (b) illegal writes (§9)
// ---------------------------------------------------------------------------

/// Reads INT_STATUS.illegal and clears it (W1C).
fn take_illegal(sys: &mut Sys) -> bool {
    let s = sys.read(0, INT_STATUS) & I_ILLEGAL != 0;
    sys.write(0, INT_STATUS, I_ILLEGAL);
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, 0, "W1C clears");
    s
}

#[test]
fn illegal_writes_set_illegal_with_the_documented_effect() {
    let mut sys = Sys::new(1);
    let ctrl0 = sys.read(0, CTRL);

    // CTRL with policy 3 in reset mode: the whole write refused.
    sys.write(0, CTRL, RESET_MODE | REDUNDANCY | policy(3) | k(5));
    assert!(take_illegal(&mut sys));
    assert_eq!(sys.read(0, CTRL), ctrl0);

    // k = 0 is clamped to 1, not illegal.
    sys.write(0, CTRL, RESET_MODE | policy(2) | k(0));
    assert!(!take_illegal(&mut sys));
    assert_eq!(sys.read(0, CTRL), RESET_MODE | policy(2) | k(1));
    // Reserved bits are not stored.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1) | 0xE0 | 0xFFFE_0000);
    assert!(!take_illegal(&mut sys));
    assert_eq!(sys.read(0, CTRL), RESET_MODE | policy(1) | k(1));

    // recovery_bits = 0 is stored as written.
    sys.write(0, RMB_CFG, 0x0005_0000);
    assert!(!take_illegal(&mut sys));
    assert_eq!(sys.read(0, RMB_CFG), 0x0005_0000);
    sys.write(0, RMB_CFG, 1024);
    // DEDUP_CFG window is 15 bits.
    sys.write(0, DEDUP_CFG, 0xFFFF_FFFF);
    assert_eq!(sys.read(0, DEDUP_CFG), 0x7FFF);
    sys.write(0, DEDUP_CFG, 1024);

    // Push in reset mode: refused.
    sys.push(0, &frame(0x10, false, false, 1, &[1]), 0);
    assert!(take_illegal(&mut sys));
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0);

    // Pop on an empty RX FIFO: refused.
    sys.write(0, RX_CMD, 1);
    assert!(take_illegal(&mut sys));
    // A command write without the command bit does nothing.
    sys.write(0, RX_CMD, 0);
    sys.write(0, TX_CMD, 0);
    assert!(!take_illegal(&mut sys));

    // Read-only and unmapped words: refused.
    for adr in [
        ID, STATUS, CHAN_A_ERR, CHAN_B_ERR, AUX_A, AUX_B, RX_ID, RX_CTRL, RX_DATA0, RX_DATA1,
        STATS0, STATS1, TIMES, 25, 40, 63,
    ] {
        let before = sys.read(0, adr);
        sys.write(0, adr, 0x1234_5678);
        assert!(take_illegal(&mut sys), "write to word {adr}");
        assert_eq!(sys.read(0, adr), before, "word {adr} unchanged");
    }

    // Leave reset mode (normal mode). CTRL cfg changes outside reset mode: only
    // reset_mode is taken, illegal set.
    sys.start(0, policy(1) | k(1));
    assert!(!take_illegal(&mut sys));
    sys.write(0, CTRL, policy(2) | k(4) | REDUNDANCY);
    assert!(take_illegal(&mut sys));
    assert_eq!(sys.read(0, CTRL), policy(1) | k(1));
    // Same cfg, k = 0 (clamps to the current 1): legal.
    sys.write(0, CTRL, policy(1) | k(0));
    assert!(!take_illegal(&mut sys));
    // BTR, RMB_CFG, DEDUP_CFG outside reset mode: refused.
    for (adr, v) in [(BTR, 0x0060_0501), (RMB_CFG, 7), (DEDUP_CFG, 9)] {
        let before = sys.read(0, adr);
        sys.write(0, adr, v);
        assert!(
            take_illegal(&mut sys),
            "write to word {adr} outside reset mode"
        );
        assert_eq!(sys.read(0, adr), before);
    }

    // Push to a full queue: 8 fit (nobody acknowledges, nothing leaves), the 9th is
    // refused.
    let f = frame(0x55, false, false, 2, &[0xA, 0xB]);
    for i in 0..8 {
        sys.push(0, &f, 0);
        assert!(!take_illegal(&mut sys), "push {i}");
    }
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 8);
    sys.push(0, &f, 0);
    assert!(take_illegal(&mut sys));
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 8);
    // Queue B is independent.
    sys.push(0, &f, 1);
    assert!(!take_illegal(&mut sys));
    assert_eq!(status_txq(sys.read(0, STATUS), 1), 1);

    // irq = |(INT_STATUS & INT_ENABLE), one clock after.
    sys.write(0, INT_ENABLE, I_ILLEGAL);
    assert!(!sys.nodes[0].out.irq);
    sys.write(0, ID, 0);
    assert!(sys.nodes[0].out.irq);
    sys.write(0, INT_STATUS, I_ILLEGAL);
    assert!(
        !sys.nodes[0].out.irq,
        "irq follows the clear one clock later"
    );

    // Entering reset mode empties both TX queues; statistics stay.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1));
    assert!(!take_illegal(&mut sys));
    let s = sys.read(0, STATUS);
    assert_eq!((status_txq(s, 0), status_txq(s, 1)), (0, 0));
    assert_eq!(s >> 13 & 1, 1);
}

// ---------------------------------------------------------------------------
// (c) normal mode: queue A on channel A, queue B on channel B
// ---------------------------------------------------------------------------

#[test]
fn normal_mode_queue_a_on_channel_a_queue_b_on_channel_b() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB); // bus integration
    let f1 = frame(
        0x123,
        false,
        false,
        8,
        &[0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88],
    );
    let f2 = frame(0x1ABC_DEF0, true, false, 3, &[0xC0, 0xFF, 0xEE]);
    sys.push(0, &f1, 0);
    let mut b_dominant = false;
    let mut a_dominant = false;
    for _ in 0..(200 * CPB) {
        sys.step();
        b_dominant |= !sys.nodes[0].out.chan_b_tx;
        a_dominant |= !sys.nodes[0].out.chan_a_tx;
    }
    assert!(
        a_dominant && !b_dominant,
        "queue A leaves on channel A only"
    );
    assert_eq!(sys.plain[pa].received, vec![f1]);
    assert!(sys.plain[pb].received.is_empty());
    let st = sys.read(0, INT_STATUS);
    assert_eq!(st & (I_TX_DONE | I_TX_FAILURE), I_TX_DONE);
    sys.write(0, INT_STATUS, 0xFF);
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0, "popped at tx_done");

    sys.push(0, &f2, 1);
    let mut a_dominant = false;
    let mut b_dominant = false;
    for _ in 0..(200 * CPB) {
        sys.step();
        b_dominant |= !sys.nodes[0].out.chan_b_tx;
        a_dominant |= !sys.nodes[0].out.chan_a_tx;
    }
    assert!(
        b_dominant && !a_dominant,
        "queue B leaves on channel B only"
    );
    assert_eq!(sys.plain[pb].received, vec![f2]);
    assert_eq!(sys.plain[pa].received, vec![f1]);
    assert_eq!(sys.read(0, INT_STATUS) & I_TX_DONE, I_TX_DONE);
    let s = sys.read(0, STATUS);
    assert_eq!((status_txq(s, 0), status_txq(s, 1)), (0, 0));
    // The FSM stays in idle1 in normal mode.
    assert_eq!(status_state(s), IDLE1);

    // Both queues at once: each goes on its own channel, in order.
    let g: Vec<Frame> = (0..3)
        .map(|i| frame(0x200 + i, false, false, 1, &[i as u8]))
        .collect();
    for f in &g {
        sys.push(0, f, 0);
        sys.push(0, f, 1);
    }
    sys.run(600 * CPB);
    assert_eq!(sys.plain[pa].received[1..], g[..]);
    assert_eq!(sys.plain[pb].received[1..], g[..]);
}

// ---------------------------------------------------------------------------
// (d) paper Fig 5-7: error-passive policy, channel A without an acknowledging node
// ---------------------------------------------------------------------------

/// Everything the paper scenario records, clock by clock.
#[derive(Default)]
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

#[test]
fn error_passive_policy_switches_to_channel_b_paper_fig5_to_7() {
    let mut sys = Sys::new(1);
    // Channel A: nobody else (every attempt is an ACK error). Channel B: one node.
    let pb = sys.add_plain(1, true);
    sys.start(0, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let f = frame(0x2A5, false, false, 2, &[0xC3, 0x3C]);
    sys.push(0, &f, 0);
    sys.run(4000 * CPB);

    // TEC of A climbs by 8 per failed attempt up to 0x80, never above; then the
    // restart of channel A clears it.
    let climb: Vec<u16> = (0..=16).map(|i| i * 8).collect();
    assert_eq!(
        sys.trace.tec_a[..17],
        climb[..],
        "TEC A: {:?}",
        sys.trace.tec_a
    );
    assert_eq!(
        sys.trace.tec_a[17..],
        [0],
        "TEC A after the switch: {:?}",
        sys.trace.tec_a
    );

    // Main FSM: idle1 wait1 ch1 abort1 wait2 idle2 wait3 ch2 idle2, then back to A
    // once aux A is valid again (idle2 wait4 idle1).
    assert_eq!(
        sys.trace.state_seq(),
        [IDLE1, WAIT1, CH1, ABORT1, WAIT2, IDLE2, WAIT3, CH2, IDLE2, WAIT4, IDLE1],
        "{:?}",
        sys.trace.states
    );
    // Aux A: valid -> failed (error passive) -> restart -> probation -> valid.
    assert_eq!(
        sys.trace.aux_a.iter().map(|s| s.1).collect::<Vec<_>>(),
        [VALID, FAILED, RESTART, PROBATION, VALID]
    );
    // Sent once on B, acknowledged by the node there.
    assert_eq!(sys.plain[pb].received, vec![f]);
    // transmission_ack then tx_success, one clock each, consecutive.
    assert_eq!(sys.trace.ack.len(), 1);
    assert_eq!(sys.trace.success, vec![sys.trace.ack[0] + 1]);
    // The ack comes with the ch2 -> idle2 edge.
    assert_eq!(sys.trace.ack[0], sys.trace.states[8].0);
    // tx_failure once, for channel A (01), at the wait2 -> idle2 edge.
    assert_eq!(sys.trace.failure, vec![(sys.trace.clock_of(IDLE2), 0b01)]);
    let p = sys.nodes[0].out.probes;
    assert_eq!(p.tx_ok_channel, 0b10, "delivered on channel B");
    assert_eq!(p.tx_failure_channel, 0b01, "latched");

    // Host view.
    let aux_a = sys.read(0, AUX_A);
    assert_eq!(aux_a & 3, VALID as u32);
    assert_eq!(aux_a >> 2 & 0xF, 0b0001, "cause error-passive only");
    assert_eq!(aux_a >> 16 & 0xFF, 1, "one failure");
    assert_eq!(aux_a >> 24 & 0xFF, 1, "one recovery");
    assert_eq!(sys.read(0, AUX_B), 0);
    let stats1 = sys.read(0, STATS1);
    assert_eq!(stats1 & 0xFFFF, 2, "switch to B and back");
    assert_eq!(stats1 >> 16, 1, "one recovery");
    let ints = sys.read(0, INT_STATUS);
    for bit in [I_TX_DONE, I_SWITCH, I_ERR_STATE, I_TX_FAILURE, I_AUX] {
        assert_eq!(ints & bit, bit, "INT_STATUS bit {bit:#x} in {ints:#x}");
    }
    assert_eq!(ints & (I_RX | I_OVERRUN | I_ILLEGAL), 0);
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0, "popped");

    // TIMES: tx_time counts nominal bits from the wait1 -> ch1 edge (cleared there).
    // switch_time is latched at wait2 -> idle2; last_tx_time at the finish (the
    // resend on B does not clear tx_time).
    let times = sys.read(0, TIMES);
    let ch1 = sys.trace.clock_of(CH1);
    let switch_bits = (sys.trace.clock_of(IDLE2) - ch1) / CPB;
    let total_bits = (sys.trace.ack[0] - ch1) / CPB;
    assert!(
        (times >> 16).abs_diff(switch_bits as u32) <= 1,
        "switch_time {} vs {switch_bits}",
        times >> 16
    );
    assert!(
        (times & 0xFFFF).abs_diff(total_bits as u32) <= 1,
        "last_tx_time {} vs {total_bits}",
        times & 0xFFFF
    );
    assert!(switch_bits > 16 * 40, "sixteen attempts before the switch");
}

// ---------------------------------------------------------------------------
// (e) k-failed policy, k = 1
// ---------------------------------------------------------------------------

#[test]
fn k_failed_policy_switches_after_one_failed_attempt() {
    let mut sys = Sys::new(1);
    let pb = sys.add_plain(1, true);
    sys.write(0, RMB_CFG, 50_000); // no recovery during the test
    sys.start(0, REDUNDANCY | policy(2) | k(1));
    sys.run(20 * CPB);
    let f = frame(0x0F0, false, false, 1, &[0x5A]);
    sys.push(0, &f, 0);
    sys.run(400 * CPB);
    // One ACK error (TEC 8), the abort is carried out before any retry, then the
    // restart clears TEC.
    assert_eq!(sys.trace.tec_a, [0, 8, 0], "TEC A: {:?}", sys.trace.tec_a);
    assert_eq!(
        sys.trace.state_seq(),
        [IDLE1, WAIT1, CH1, ABORT1, WAIT2, IDLE2, WAIT3, CH2, IDLE2]
    );
    assert_eq!(
        sys.trace.aux_a.iter().map(|s| s.1).collect::<Vec<_>>(),
        [VALID, FAILED, RESTART, PROBATION]
    );
    assert_eq!(sys.plain[pb].received, vec![f]);
    assert_eq!(sys.trace.success, vec![sys.trace.ack[0] + 1]);
    assert_eq!(sys.nodes[0].out.probes.tx_ok_channel, 0b10);
    let aux_a = sys.read(0, AUX_A);
    assert_eq!(aux_a & 3, PROBATION as u32);
    assert_eq!(aux_a >> 2 & 0xF, 0b0100, "cause k-failed");
    assert_eq!(aux_a >> 8 & 0xF, 0, "failed attempts cleared at restart");
    assert_eq!(aux_a >> 16 & 0xFF, 1);
    // k = 2: two failed attempts (TEC 16) before the switch.
    let mut sys = Sys::new(1);
    sys.add_plain(1, true);
    sys.write(0, RMB_CFG, 50_000);
    sys.start(0, REDUNDANCY | policy(2) | k(2));
    sys.run(20 * CPB);
    sys.push(0, &f, 0);
    sys.run(400 * CPB);
    assert_eq!(
        sys.trace.tec_a,
        [0, 8, 16, 0],
        "TEC A: {:?}",
        sys.trace.tec_a
    );
    assert_eq!(sys.plain[0].received, vec![f]);
}

// ---------------------------------------------------------------------------
// (f) recovery of channel A and return to it
// ---------------------------------------------------------------------------

#[test]
fn recovery_returns_to_channel_a_after_probation() {
    const R: u64 = 100;
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, false); // channel A cut: its only partner is missing
    let pb = sys.add_plain(1, true);
    sys.write(0, RMB_CFG, R as u32);
    sys.start(0, REDUNDANCY | policy(2) | k(1));
    sys.run(20 * CPB);
    let f1 = frame(0x101, false, false, 1, &[1]);
    sys.push(0, &f1, 0);
    // Run until the message is delivered on B, then repair line A.
    while sys.trace.ack.is_empty() {
        sys.run(1);
    }
    assert_eq!(sys.plain[pb].received, vec![f1]);
    sys.plain[pa].connected = true;
    sys.run((R + 50) * CPB);
    assert_eq!(
        sys.trace.aux_a.iter().map(|s| s.1).collect::<Vec<_>>(),
        [VALID, FAILED, RESTART, PROBATION, VALID]
    );
    // Probation lasts `recovery_bits` sample points of channel A: they are counted
    // at the edges after entering probation, and the edge after probe_cnt reaches R
    // returns to valid.
    let enter = sys.trace.aux_a[3].0;
    let valid = sys.trace.aux_a[4].0;
    let samples = sys
        .trace
        .sample_a
        .iter()
        .filter(|&&(c, s)| s && c >= enter && c <= valid - 2)
        .count() as u64;
    assert_eq!(samples, R);
    // Main FSM: idle2 -> wait4 at the next edge, wait4 -> idle1 at the one after.
    assert_eq!(
        sys.trace.state_seq(),
        [IDLE1, WAIT1, CH1, ABORT1, WAIT2, IDLE2, WAIT3, CH2, IDLE2, WAIT4, IDLE1]
    );
    assert_eq!(sys.trace.clock_of(WAIT4), valid + 1);
    assert_eq!(sys.trace.states[10].0, valid + 2);
    let stats1 = sys.read(0, STATS1);
    assert_eq!(stats1, 2 | 1 << 16, "two switches, one recovery");
    // The next message goes on channel A (acknowledged by the repaired node).
    let f2 = frame(0x102, false, false, 1, &[2]);
    sys.push(0, &f2, 0);
    let mut b_dominant = false;
    for _ in 0..(200 * CPB) {
        sys.step();
        b_dominant |= !sys.nodes[0].out.chan_b_tx;
    }
    assert!(!b_dominant);
    assert_eq!(sys.plain[pa].received, vec![f2]);
    assert_eq!(sys.plain[pb].received, vec![f1]);
    assert_eq!(sys.nodes[0].out.probes.tx_ok_channel, 0b01);
    assert_eq!(sys.trace.ack.len(), 2);
    assert_eq!(
        sys.trace.success,
        vec![sys.trace.ack[0] + 1, sys.trace.ack[1] + 1]
    );
    assert_eq!(sys.read(0, AUX_A) >> 24, 1, "one recovery of A");
}

// ---------------------------------------------------------------------------
// (g) RX FIFO: channel tag, order, overrun at 33 frames
// ---------------------------------------------------------------------------

#[test]
fn rx_fifo_tags_channels_and_counts_overrun() {
    let mut sys = Sys::new(1);
    let pa = sys.add_plain(0, true);
    let pb = sys.add_plain(1, true);
    sys.start(0, policy(1) | k(1));
    sys.run(20 * CPB);
    let frames: Vec<Frame> = (0..33u32)
        .map(|i| {
            let n = (i % 9) as usize;
            let data: Vec<u8> = (0..n as u8).map(|b| b ^ i as u8).collect();
            match i % 4 {
                0 => frame(0x100 + i, false, false, n as u8, &data),
                1 => frame(0x1000_0000 | i, true, false, n as u8, &data),
                2 => frame(0x300 + i, false, true, (i % 16) as u8, &[]),
                _ => frame(0x400 + i, false, false, 12, &[1, 2, 3, 4, 5, 6, 7, 8]),
            }
        })
        .collect();
    for (i, f) in frames.iter().enumerate() {
        let p = if i % 2 == 0 { pa } else { pb };
        let done = sys.plain[p].done;
        sys.plain[p].req = Some(*f);
        while sys.plain[p].done == done {
            sys.step();
        }
        sys.run(20 * CPB);
    }
    let s = sys.read(0, STATUS);
    assert_eq!(status_rx_count(s), 32);
    assert_eq!(sys.read(0, STATS0), 1 << 16, "one overrun, no duplicates");
    assert_eq!(
        sys.read(0, INT_STATUS) & (I_RX | I_OVERRUN),
        I_RX | I_OVERRUN
    );
    for (i, f) in frames.iter().take(32).enumerate() {
        let (g, ch) = sys.pop(0).expect("frame in the FIFO");
        assert_eq!(g, *f, "frame {i}");
        assert_eq!(ch, (i % 2) as u32, "channel of frame {i}");
        assert_eq!(status_rx_count(sys.read(0, STATUS)), 31 - i as u32);
    }
    assert!(sys.pop(0).is_none(), "the 33rd frame was dropped");
    sys.write(0, INT_STATUS, 0xFF);
    sys.write(0, RX_CMD, 1);
    assert_eq!(sys.read(0, INT_STATUS) & I_ILLEGAL, I_ILLEGAL);
    // Normal mode never drops duplicates: the same frame on both channels is
    // delivered twice.
    let f = frame(0x77, false, false, 1, &[7]);
    sys.plain[pa].req = Some(f);
    sys.plain[pb].req = Some(f);
    sys.run(200 * CPB);
    assert_eq!(
        sys.pop(0),
        Some((f, 0)),
        "A first when both arrive together"
    );
    assert_eq!(sys.pop(0), Some((f, 1)));
    assert_eq!(sys.read(0, STATS0) & 0xFFFF, 0);
}

// ---------------------------------------------------------------------------
// (h) duplicate removal with dual_tx
// ---------------------------------------------------------------------------

#[test]
fn dual_tx_receiver_gets_each_message_once() {
    // Node 0 sends every message on A then its copy on B; node 1 receives.
    let mut sys = Sys::new(2);
    sys.start(0, REDUNDANCY | policy(1) | k(1) | DUAL_TX);
    sys.start(1, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let msgs = [
        frame(0x301, false, false, 2, &[1, 2]),
        frame(0x00AB_CDEF, true, false, 0, &[]),
        frame(0x301, false, false, 2, &[1, 2]), // the same frame again
    ];
    for m in &msgs {
        sys.push(0, m, 0);
    }
    sys.run(1200 * CPB);
    // Each message: transmission_ack after A (no tx_success for the first copy),
    // then after B with tx_success.
    assert_eq!(sys.trace.ack.len(), 6, "{:?}", sys.trace.ack);
    assert_eq!(
        sys.trace.success,
        vec![
            sys.trace.ack[1] + 1,
            sys.trace.ack[3] + 1,
            sys.trace.ack[5] + 1
        ]
    );
    assert_eq!(sys.nodes[0].out.probes.tx_ok_channel, 0b11, "both channels");
    // Every round trip passes idle2 and back through wait4, never a switch.
    assert_eq!(sys.read(0, STATS1) & 0xFFFF, 0);
    assert_eq!(status_txq(sys.read(0, STATUS), 0), 0);
    // Receiver: each message once, from channel A; the copies on B were dropped.
    let mut got = Vec::new();
    while let Some(x) = sys.pop(1) {
        got.push(x);
    }
    assert_eq!(got, msgs.iter().map(|m| (*m, 0)).collect::<Vec<_>>());
    assert_eq!(
        sys.read(1, STATS0),
        3,
        "three duplicates dropped, no overrun"
    );
    assert_eq!(sys.read(1, INT_STATUS) & I_RX, I_RX);

    // window = 0 turns dedup off: both copies are delivered.
    let mut sys = Sys::new(2);
    sys.start(0, REDUNDANCY | policy(1) | k(1) | DUAL_TX);
    sys.write(1, DEDUP_CFG, 0);
    sys.start(1, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    sys.push(0, &msgs[0], 0);
    sys.run(400 * CPB);
    assert_eq!(sys.pop(1), Some((msgs[0], 0)));
    assert_eq!(sys.pop(1), Some((msgs[0], 1)));
    assert_eq!(sys.pop(1), None);
    assert_eq!(sys.read(1, STATS0), 0);
}

/// Copies older than `window` bit times are not duplicates: with a window of 10 bits
/// the copy on B (more than a frame later) is delivered.
#[test]
fn dedup_window_expires_entries() {
    let mut sys = Sys::new(2);
    sys.start(0, REDUNDANCY | policy(1) | k(1) | DUAL_TX);
    sys.write(1, DEDUP_CFG, 10);
    sys.start(1, REDUNDANCY | policy(1) | k(1));
    sys.run(20 * CPB);
    let m = frame(0x42, false, false, 1, &[0x42]);
    sys.push(0, &m, 0);
    sys.run(400 * CPB);
    assert_eq!(sys.pop(1), Some((m, 0)));
    assert_eq!(sys.pop(1), Some((m, 1)));
    assert_eq!(sys.read(1, STATS0), 0);
}

/// `RX_ID[31]` (`rx_ready`, §7) is 1 only when the read data holds the new head:
/// polling RX_ID back to back (every 2 clocks, at both clock phases) while a frame
/// arrives in an empty FIFO whose RAM head still holds an older frame never shows
/// the valid flag with the old frame.
#[test]
fn rx_ready_never_pairs_the_flag_with_a_stale_head() {
    for phase in 0..2 {
        let mut sys = Sys::new(1);
        let pa = sys.add_plain(0, true);
        sys.start(0, policy(1) | k(1));
        sys.run(20 * CPB);
        let old = frame(0x111, false, false, 1, &[1]);
        let new = frame(0x222, false, false, 1, &[2]);
        // Fill all 32 RAM entries with `old` (so the next head holds it), pop them.
        for _ in 0..32 {
            let d = sys.plain[pa].done;
            sys.plain[pa].req = Some(old);
            while sys.plain[pa].done == d {
                sys.step();
            }
        }
        sys.run(20 * CPB);
        for _ in 0..32 {
            assert_eq!(sys.pop(0), Some((old, 0)));
        }
        sys.run(phase);
        sys.plain[pa].req = Some(new);
        let mut seen = false;
        for _ in 0..(120 * CPB / 2) {
            let id = sys.read(0, RX_ID);
            if id >> 31 == 1 {
                assert_eq!(
                    id & 0x7FF,
                    0x222,
                    "phase {phase}: valid flag with a stale head"
                );
                seen = true;
            }
        }
        assert!(seen, "phase {phase}: the new frame arrived");
    }
}

/// Contract §9: redundancy mode needs both channels able to transmit; a CTRL write
/// asking for redundancy with a LISTEN_ONLY channel (§C.7 mode 1) is refused.
#[test]
fn redundancy_with_a_listen_only_channel_is_refused() {
    let mut sys = Sys::new(1);
    let ctrl0 = sys.read(0, CTRL);
    for mode in [1u32 << 12, 1u32 << 14] {
        sys.write(0, CTRL, RESET_MODE | REDUNDANCY | policy(1) | k(1) | mode);
        assert!(take_illegal(&mut sys), "mode bits {mode:#x}");
        assert_eq!(sys.read(0, CTRL), ctrl0, "the whole write is refused");
    }
    // The same channel modes are fine in normal mode.
    sys.write(0, CTRL, RESET_MODE | policy(1) | k(1) | 1 << 12);
    assert!(!take_illegal(&mut sys));
}

/// Contract §6: the write that clears reset mode may also carry the configuration;
/// the channels stay in reset one more clock and take it. Here channel A becomes
/// SELF_TEST (§C.7: no ACK needed) in that very write: alone on its line, it then
/// sends a frame successfully instead of collecting ACK errors.
#[test]
fn configuration_in_the_write_that_leaves_reset_mode_is_taken() {
    let mut sys = Sys::new(1);
    sys.write(0, CTRL, policy(1) | k(1) | 2 << 12); // reset_mode 0, mode_a SELF_TEST
    sys.run(20 * CPB);
    let f = frame(0x321, false, false, 1, &[0x5A]);
    sys.push(0, &f, 0);
    sys.run(200 * CPB);
    assert_eq!(
        sys.read(0, INT_STATUS) & (I_TX_DONE | I_TX_FAILURE),
        I_TX_DONE,
        "self-test frame sent without acknowledgement"
    );
    assert_eq!(sys.read(0, CHAN_A_ERR) & 0x1FF, 0, "no ACK error counted");
}
