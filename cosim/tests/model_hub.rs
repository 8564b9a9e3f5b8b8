//! Reference model of the ReCANcentrate hub (`model::hub`) against its contract
//! (`hub_contract.md`). Every expected value is derived here from the contract text
//! and ISO 11898-1, never from running the model: register values and clamps (§8),
//! the coupling and its 3-edge delay (§2, §3), the ACK window mask (§4), the
//! tracker's states at every sample point of base and extended frames (§5, frames
//! encoded bit-exactly below), the guard rules (§6) and decoupling (§7).
//!
//! Timing used throughout (BTR at its reset value: BRP 0, TSEG1 5 tq, TSEG2 2 tq,
//! so 8 clocks per bit, every clock a tick): a value presented at a pin in step `k`
//! is in `s1` after edge `k`, in `in_s` after `k+1`, in `coupled_q`/`port_q` after
//! `k+2`, so the bit timing logic sees it (`rx_s` before the edge) at edge `k+3`.
//! A recessive-to-dominant edge there in `IDLE_WAIT` is a hard synchronisation
//! (that tq is SYNC_SEG), TSEG1 lasts 5 tq, so the sample point is edge `k+8`, then
//! every 8 clocks: bit `j` of a frame whose SOF starts at step `t0` is sampled at
//! edge `t0 + 8j + 8` (its edges fall in SYNC_SEG: phase error 0, no resync).

use drcc_cosim::engine::hub::{HubInputs, HubOutputs};
use drcc_cosim::model::crc::crc15;
use drcc_cosim::model::hub::HubModel;

/// Clocks per bit with the reset BTR (1 + 5 + 2 tq of one clock).
const CPB: usize = 8;

// Register word indices (contract §8), written from the table.
const ID: u8 = 0;
const CTRL: u8 = 1;
const BTR: u8 = 2;
const GUARD_CFG: u8 = 3;
const BF_CFG: u8 = 4;
const RESTORE_CFG: u8 = 5;
const STATUS: u8 = 6;
const INT_STATUS: u8 = 7;
const INT_ENABLE: u8 = 8;
const STATS: u8 = 9;
const PORT0: u8 = 16;

const RESET_MODE: u32 = 1;
const FORCE_DECOUPLE: u32 = 1 << 1;
const RECOUPLE: u32 = 1 << 2;
const ACK_INTERDEP: u32 = 1 << 8;

const INT_ISOLATION: u32 = 1;
const INT_RESTORATION: u32 = 2;
const INT_DECOUPLED: u32 = 4;
const INT_ILLEGAL: u32 = 8;

// Tracker states.
const IDLE_WAIT: u8 = 0;
const FRAME: u8 = 1;
const ACK_SLOT: u8 = 2;
const ACK_DELIM: u8 = 3;

// ---------------------------------------------------------------------------
// ISO 11898-1 frame encoder (independent of the model).

/// A frame as it appears on the bus from SOF to the end of EOF.
struct Encoded {
    /// Stuffed bit stream, 1 = recessive, SOF first, ending with 7 EOF bits.
    bits: Vec<bool>,
    /// Index in `bits` of each unstuffed bit from SOF to the last CRC bit.
    raw_at: Vec<usize>,
    /// Index of the CRC delimiter.
    crc_delim: usize,
    /// Index of the ACK slot.
    ack: usize,
}

fn push_bits(v: &mut Vec<bool>, value: u32, n: u32) {
    for i in (0..n).rev() {
        v.push((value >> i) & 1 == 1);
    }
}

/// Classical CAN data or remote frame (ISO 11898-1 10.4.2): SOF, arbitration
/// field, control field, data field, CRC-15 over SOF..data, bit stuffing from SOF
/// to the end of the CRC sequence (a stuff bit after the last CRC bit included),
/// CRC delimiter, ACK slot (recessive from the transmitter), ACK delimiter, EOF.
fn encode(id: u32, ide: bool, rtr: bool, dlc: u8, data: &[u8]) -> Encoded {
    let mut raw = vec![false]; // SOF
    if ide {
        push_bits(&mut raw, id >> 18, 11);
        raw.push(true); // SRR
        raw.push(true); // IDE
        push_bits(&mut raw, id & 0x3FFFF, 18);
        raw.push(rtr);
        raw.push(false); // r1
        raw.push(false); // r0
    } else {
        push_bits(&mut raw, id, 11);
        raw.push(rtr);
        raw.push(false); // IDE
        raw.push(false); // r0
    }
    push_bits(&mut raw, dlc as u32, 4);
    if !rtr {
        for &byte in &data[..(dlc.min(8) as usize)] {
            push_bits(&mut raw, byte as u32, 8);
        }
    }
    let crc = crc15(raw.iter().copied());
    push_bits(&mut raw, crc as u32, 15);

    let mut bits = Vec::new();
    let mut raw_at = Vec::new();
    let mut run = 0;
    let mut prev = None;
    for &b in &raw {
        raw_at.push(bits.len());
        run = if prev == Some(b) { run + 1 } else { 1 };
        bits.push(b);
        prev = Some(b);
        if run == 5 {
            bits.push(!b);
            prev = Some(!b);
            run = 1;
        }
    }
    let crc_delim = bits.len();
    bits.push(true); // CRC delimiter
    let ack = bits.len();
    bits.push(true); // ACK slot (the transmitter sends recessive)
    bits.push(true); // ACK delimiter
    bits.extend([true; 7]); // EOF
    Encoded {
        bits,
        raw_at,
        crc_delim,
        ack,
    }
}

// ---------------------------------------------------------------------------
// Bench: one hub, its pins (all ports packed, bit p = port p), a Wishbone master.

struct Bench {
    hub: HubModel,
    n: usize,
    m: usize,
    /// Pin values, bit p = port p (node ports 0..N, sublinks N..N+M), 1 = recessive.
    pins: u16,
    /// Outputs after every step (index = step number).
    log: Vec<HubOutputs>,
}

impl Bench {
    /// A hub after two `rst` clocks (reset mode).
    fn new(n: usize, m: usize) -> Self {
        let mut b = Bench {
            hub: HubModel::new(n, m).expect("supported shape"),
            n,
            m,
            pins: u16::MAX,
            log: Vec::new(),
        };
        for _ in 0..2 {
            b.step_with(HubInputs {
                rst: true,
                ..b.pin_inputs()
            });
        }
        b
    }

    /// A running hub: reset, `cfg` written in reset mode, reset mode left with
    /// `ack_interdep` = `interdep`, then 14 recessive bits so that the tracker
    /// has integrated (10 recessive samples).
    fn running(n: usize, m: usize, cfg: &[(u8, u32)], interdep: bool) -> Self {
        let mut b = Bench::new(n, m);
        for &(a, d) in cfg {
            b.write(a, d);
        }
        b.write(CTRL, if interdep { ACK_INTERDEP } else { 0 });
        b.idle_bits(14);
        b
    }

    fn port_mask(&self) -> u16 {
        (1 << (self.n + self.m)) - 1
    }

    fn pin_inputs(&self) -> HubInputs {
        HubInputs {
            uplink: self.pins & ((1 << self.n) - 1),
            sublink_in: (self.pins >> self.n) as u8,
            ..HubInputs::default()
        }
    }

    fn step_with(&mut self, i: HubInputs) -> HubOutputs {
        let o = self.hub.step(&i);
        self.log.push(o);
        o
    }

    /// One clock with the current pins and no Wishbone request; returns its step
    /// number.
    fn step(&mut self) -> usize {
        let i = self.pin_inputs();
        self.step_with(i);
        self.log.len() - 1
    }

    /// The step number the next `step` will have.
    fn now(&self) -> usize {
        self.log.len()
    }

    /// Wishbone access: the request clock (taken, ack after it), then one idle
    /// clock in which the master drops the request.
    fn access(&mut self, we: bool, adr: u8, dat: u32) -> u32 {
        let o = self.step_with(HubInputs {
            wb_cyc: true,
            wb_stb: true,
            wb_we: we,
            wb_adr: adr,
            wb_dat_w: dat,
            ..self.pin_inputs()
        });
        assert!(o.wb_ack, "access to word {adr} not acknowledged");
        let data = o.wb_dat_r;
        let idle = self.step_with(self.pin_inputs());
        assert!(!idle.wb_ack && idle.wb_dat_r == 0);
        data
    }

    fn write(&mut self, adr: u8, d: u32) {
        self.access(true, adr, d);
    }

    fn read(&mut self, adr: u8) -> u32 {
        self.access(false, adr, 0)
    }

    fn port_reg(&mut self, p: usize) -> u32 {
        self.read(PORT0 + p as u8)
    }

    /// Drives each value (all ports, bit p = port p) for one bit time; returns the
    /// step number of the first clock of the first bit.
    fn drive(&mut self, bits: &[u16]) -> usize {
        let start = self.now();
        for &v in bits {
            self.pins = v;
            for _ in 0..CPB {
                self.step();
            }
        }
        start
    }

    fn idle_bits(&mut self, n: usize) {
        let v = vec![self.port_mask(); n];
        self.drive(&v);
    }

    /// One frame sent by port `tx`, acknowledged (dominant ACK slot) by the ports
    /// in `ackers`, followed by 3 recessive bits (intermission).
    fn frame_lanes(&self, f: &Encoded, tx: usize, ackers: u16) -> Vec<u16> {
        let all = self.port_mask();
        let mut v: Vec<u16> = f
            .bits
            .iter()
            .enumerate()
            .map(|(k, &b)| {
                let mut w = all;
                if !b {
                    w &= !(1 << tx);
                }
                if k == f.ack {
                    w &= !ackers;
                }
                w
            })
            .collect();
        v.extend([all; 3]);
        v
    }

    /// Sends a frame; returns the step of its SOF's first clock.
    fn send(&mut self, f: &Encoded, tx: usize, ackers: u16) -> usize {
        let lanes = self.frame_lanes(f, tx, ackers);
        self.drive(&lanes)
    }
}

/// The step whose edge samples bit `j` of a frame whose SOF starts at step `t0`.
fn sample_step(t0: usize, j: usize) -> usize {
    t0 + CPB * j + 8
}

fn enabled(o: &HubOutputs, p: usize) -> bool {
    o.probes.port_enabled >> p & 1 == 1
}

fn pec(port_reg: u32) -> u32 {
    (port_reg >> 8) & 0xFF
}

fn kind(port_reg: u32) -> u32 {
    (port_reg >> 1) & 7
}

// ---------------------------------------------------------------------------
// Shape and registers (§8).

#[test]
fn shapes_outside_the_contract_are_refused() {
    for (n, m) in [(1, 1), (9, 1), (2, 0), (2, 5), (0, 0)] {
        let e = HubModel::new(n, m).expect_err("shape must be refused");
        assert!(e.contains("2..=8") && e.contains("1..=4"), "{e}");
    }
    for (n, m) in [(2, 1), (4, 2), (8, 4)] {
        assert!(HubModel::new(n, m).is_ok());
    }
}

#[test]
fn id_register_names_the_shape() {
    for (n, m, id) in [
        (4, 2, 0x4855_0402),
        (2, 1, 0x4855_0201),
        (8, 4, 0x4855_0804),
    ] {
        let mut b = Bench::new(n, m);
        assert_eq!(b.read(ID), id, "N={n} M={m}");
    }
}

#[test]
fn registers_reset_to_the_contract_values() {
    let mut b = Bench::new(4, 2);
    assert_eq!(b.read(CTRL), RESET_MODE | ACK_INTERDEP);
    assert_eq!(b.read(BTR), (4 << 6) | (1 << 10));
    assert_eq!(b.read(GUARD_CFG), 14 | 16 << 8 | 8 << 16);
    assert_eq!(b.read(BF_CFG), 32 | 64 << 8);
    assert_eq!(b.read(RESTORE_CFG), 1408 | 4096 << 16);
    // STATUS: reset mode, not decoupled, no ACK window, IDLE_WAIT, 6 ports enabled.
    assert_eq!(b.read(STATUS), 1 | 0x3F << 16);
    assert_eq!(b.read(INT_STATUS), 0);
    assert_eq!(b.read(INT_ENABLE), 0);
    assert_eq!(b.read(STATS), 0);
    for p in 0..6 {
        assert_eq!(b.port_reg(p), 1, "PORT_{p}: enabled, nothing else");
    }
    // PORT_p beyond N + M and other unmapped words read 0.
    assert_eq!(b.read(PORT0 + 6), 0);
    assert_eq!(b.read(10), 0);
    assert_eq!(b.read(63), 0);
}

#[test]
fn wishbone_access_takes_two_clocks() {
    let mut b = Bench::new(2, 1);
    // A request held for 4 clocks is taken every other clock (§D.2).
    let req = HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_adr: ID,
        ..b.pin_inputs()
    };
    let acks: Vec<(bool, u32)> = (0..4)
        .map(|_| {
            let o = b.step_with(req);
            (o.wb_ack, o.wb_dat_r)
        })
        .collect();
    let id = 0x4855_0201;
    assert_eq!(acks, [(true, id), (false, 0), (true, id), (false, 0)]);
    // cyc without stb is no access.
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        ..b.pin_inputs()
    });
    assert!(!o.wb_ack);
}

#[test]
fn configuration_writes_are_clamped_in_reset_mode() {
    let mut b = Bench::new(4, 2);
    b.write(GUARD_CFG, 5 | 13 << 8 | 3 << 16);
    assert_eq!(b.read(GUARD_CFG), 14 | 14 << 8 | 3 << 16);
    b.write(GUARD_CFG, 40 | 63 << 8 | 15 << 16 | 0xFFF0_0000);
    assert_eq!(b.read(GUARD_CFG), 40 | 63 << 8 | 15 << 16);
    b.write(BF_CFG, 2 | 7 << 8);
    assert_eq!(b.read(BF_CFG), 8 | 8 << 8);
    b.write(BF_CFG, 200 | 9 << 8);
    assert_eq!(b.read(BF_CFG), 200 | 9 << 8);
    b.write(BTR, 0xFFFF_FFFF);
    assert_eq!(b.read(BTR), 0x7FFF, "BTR [31:15] read 0");
    b.write(RESTORE_CFG, 0x1234_5678);
    assert_eq!(b.read(RESTORE_CFG), 0x1234_5678);
    b.write(INT_ENABLE, 0xFF);
    assert_eq!(b.read(INT_ENABLE), 0xF);
    assert_eq!(b.read(INT_STATUS), 0, "legal writes");
}

#[test]
fn refused_writes_set_illegal_and_change_nothing() {
    let mut b = Bench::running(4, 2, &[], true);
    let illegal_after = |b: &mut Bench, adr: u8, d: u32| {
        b.write(adr, d);
        let s = b.read(INT_STATUS);
        b.write(INT_STATUS, 0xF);
        s & INT_ILLEGAL != 0
    };
    // cfg registers outside reset mode.
    assert!(illegal_after(&mut b, BTR, 0));
    assert!(illegal_after(&mut b, GUARD_CFG, 20));
    assert!(illegal_after(&mut b, BF_CFG, 20));
    assert!(illegal_after(&mut b, RESTORE_CFG, 20));
    assert_eq!(b.read(BTR), (4 << 6) | (1 << 10));
    assert_eq!(b.read(GUARD_CFG), 14 | 16 << 8 | 8 << 16);
    assert_eq!(b.read(RESTORE_CFG), 1408 | 4096 << 16);
    // Read-only and unmapped words.
    for adr in [ID, STATUS, STATS, PORT0, PORT0 + 5, PORT0 + 6, 10, 15, 63] {
        assert!(illegal_after(&mut b, adr, 0), "write to word {adr}");
    }
    // Legal writes do not set it.
    assert!(!illegal_after(&mut b, INT_ENABLE, 0));
    assert!(!illegal_after(&mut b, CTRL, ACK_INTERDEP));
    // CTRL outside reset mode: a different ack_interdep is illegal, not taken, and
    // the rest of the write (reset_mode) is taken.
    assert!(illegal_after(&mut b, CTRL, 0));
    assert_eq!(b.read(CTRL), ACK_INTERDEP);
    // Both commands in one write: refused whole (reset_mode 1 is not taken).
    assert!(illegal_after(
        &mut b,
        CTRL,
        ACK_INTERDEP | FORCE_DECOUPLE | RECOUPLE | RESET_MODE
    ));
    assert_eq!(b.read(CTRL), ACK_INTERDEP);
    assert_eq!(b.read(STATUS) & 3, 0, "neither reset mode nor decoupled");
    // A changed ack_interdep outside reset mode with reset_mode 1: illegal, and
    // reset mode is entered; in reset mode ack_interdep is taken.
    assert!(illegal_after(&mut b, CTRL, RESET_MODE));
    assert_eq!(b.read(CTRL), RESET_MODE | ACK_INTERDEP);
    assert!(!illegal_after(&mut b, CTRL, RESET_MODE));
    assert_eq!(b.read(CTRL), RESET_MODE);
}

#[test]
fn irq_is_registered_one_clock_after_int_status() {
    let mut b = Bench::running(2, 1, &[(INT_ENABLE, INT_ILLEGAL)], true);
    // The illegal write's edge sets INT_STATUS.illegal; irq follows one edge later.
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: ID,
        ..b.pin_inputs()
    });
    assert!(o.wb_ack && !o.irq);
    let s = b.step();
    assert!(b.log[s].irq);
    assert_eq!(b.read(INT_STATUS), INT_ILLEGAL);
    // W1C: cleared at the write edge, irq one edge later.
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: INT_STATUS,
        wb_dat_w: INT_ILLEGAL,
        ..b.pin_inputs()
    });
    assert!(o.irq, "irq still shows INT_STATUS before the write edge");
    let s = b.step();
    assert!(!b.log[s].irq);
    // A masked event raises no irq.
    b.write(INT_ENABLE, INT_ISOLATION);
    b.write(ID, 0);
    b.idle_bits(1);
    assert!(!b.log.last().unwrap().irq);
    assert_eq!(b.read(INT_STATUS), INT_ILLEGAL);
}

// ---------------------------------------------------------------------------
// Coupling (§2, §3).

#[test]
fn reset_mode_is_a_transparent_two_stage_and_star() {
    let mut b = Bench::new(3, 2);
    let nodes = 0b111u16;
    let subs = 0b11u8;
    // Node port 1 dominant at step s: downlink and sublink_out follow 3 edges later
    // (after the edge of step s + 2), all bits alike.
    b.pins = 0x1F & !(1 << 1);
    let s = b.step();
    b.step();
    b.step();
    for k in [s, s + 1] {
        assert_eq!(b.log[k].downlink, nodes, "step {}", k - s);
        assert_eq!(b.log[k].sublink_out, subs);
        assert!(b.log[k].probes.coupled);
    }
    assert_eq!(b.log[s + 2].downlink, 0);
    assert_eq!(b.log[s + 2].sublink_out, 0);
    assert!(!b.log[s + 2].probes.coupled);
    // Released: recessive again 3 edges later.
    b.pins = 0x1F;
    let r = b.step();
    b.step();
    b.step();
    assert_eq!(b.log[r + 1].downlink, 0);
    assert_eq!(b.log[r + 2].downlink, nodes);
    assert_eq!(b.log[r + 2].sublink_out, subs);
    // Twin contribution (sublink 1 = port 4): reaches the downlinks, not the
    // outgoing sublinks.
    b.pins = 0x1F & !(1 << 4);
    let t = b.step();
    b.step();
    b.step();
    assert_eq!(b.log[t + 1].downlink, nodes);
    assert_eq!(b.log[t + 2].downlink, 0);
    assert_eq!(b.log[t + 2].sublink_out, subs);
    // A stuck-dominant node for 300 bit times is never isolated in reset mode.
    b.drive(&[0x1F & !1; 300]);
    assert!(b.log.iter().all(|o| o.probes.port_enabled == 0x1F));
    assert!(b.log.iter().all(|o| !o.probes.sample_point));
    assert_eq!(b.read(STATUS), 1 | 0x1F << 16);
}

#[test]
fn running_hub_couples_own_and_twin_in_two_stages() {
    let mut b = Bench::running(2, 2, &[], true);
    // Twin dominant on sublink 0 (port 2): downlink dominant, sublink_out not.
    b.pins = 0xF & !(1 << 2);
    let s = b.step();
    b.step();
    b.step();
    assert_eq!(b.log[s + 1].downlink, 0b11);
    assert_eq!((b.log[s + 2].downlink, b.log[s + 2].sublink_out), (0, 0b11));
    assert!(!b.log[s + 2].probes.coupled);
    // Plus a node: both.
    b.pins &= !1;
    let s = b.step();
    b.step();
    b.step();
    assert_eq!((b.log[s + 2].downlink, b.log[s + 2].sublink_out), (0, 0));
}

// ---------------------------------------------------------------------------
// Tracker (§5).

#[test]
fn tracker_follows_base_and_extended_frames_to_the_ack_slot() {
    let mut b = Bench::running(3, 1, &[], true);
    let frames = [
        encode(0x123, false, false, 2, &[0xA5, 0x0F]),
        encode(0x7F0, false, false, 8, &[0xFF; 8]), // long runs: many stuff bits
        encode(0x040, false, false, 15, &[0; 8]),   // DLC > 8: 8 bytes
        encode(0x3AA, false, true, 5, &[]),         // remote: no data field
        encode(0x1FFF_FFFF, true, false, 1, &[0x80]),
        encode(0x1555_0F0F, true, true, 3, &[]),
        encode(0x1234_5678, true, false, 8, &[1, 2, 3, 4, 5, 6, 7, 8]),
    ];
    let mut stuffed_any = 0;
    for (i, f) in frames.iter().enumerate() {
        stuffed_any += f.crc_delim - f.raw_at.len();
        // Port 0 sends, every other port acknowledges.
        let t0 = b.send(f, 0, b.port_mask() & !1);
        let trk_at = |j: usize| {
            let o = &b.log[sample_step(t0, j)];
            assert!(o.probes.sample_point, "frame {i}: bit {j} is sampled there");
            o.probes.trk_state
        };
        for j in 0..f.crc_delim {
            assert_eq!(trk_at(j), FRAME, "frame {i}: bit {j}");
        }
        assert_eq!(trk_at(f.crc_delim), ACK_SLOT, "frame {i}: CRC delimiter");
        assert_eq!(trk_at(f.ack), ACK_DELIM, "frame {i}: ACK slot");
        assert_eq!(trk_at(f.ack + 1), IDLE_WAIT, "frame {i}: ACK delimiter");
        assert_eq!(b.read(STATS), i as u32 + 1, "frame {i}: frames tracked");
    }
    assert!(stuffed_any > 10, "the frames exercise destuffing");
    // Every port was active in every frame, nobody blamed.
    for p in 0..4 {
        assert_eq!(b.port_reg(p), 1, "PORT_{p}");
    }
}

#[test]
fn stats_count_frames_and_tracker_errors() {
    let mut b = Bench::running(2, 1, &[], true);
    let f = encode(0x2A5, false, false, 1, &[0x33]);
    b.send(&f, 0, 0b110);
    // A stuff error: six dominant bits after SOF (an error flag at the start).
    let mut flag = vec![0b111 & !1u16; 7];
    flag.extend([0b111; 12]);
    let t0 = b.drive(&flag);
    // SOF + 4 bits make 5, the 6th dominant is the stuff error: IDLE_WAIT again.
    assert_eq!(b.log[sample_step(t0, 4)].probes.trk_state, FRAME);
    assert_eq!(b.log[sample_step(t0, 5)].probes.trk_state, IDLE_WAIT);
    // A form error: dominant CRC delimiter.
    let mut lanes = b.frame_lanes(&f, 0, 0b110);
    lanes[f.crc_delim] &= !1;
    let t1 = b.drive(&lanes);
    assert_eq!(
        b.log[sample_step(t1, f.crc_delim)].probes.trk_state,
        IDLE_WAIT
    );
    b.idle_bits(12);
    b.send(&f, 1, 0b101);
    assert_eq!(b.read(STATS), 2 | 2 << 16);
    // Reset mode clears STATS.
    b.write(CTRL, RESET_MODE | ACK_INTERDEP);
    assert_eq!(b.read(STATS), 0);
}

// ---------------------------------------------------------------------------
// ACK interdependence (§4).

/// One frame from port 0 of a 2x1 hub, ACKed by node port 1 and, if `twin_ack`,
/// by the sublink (port 2). Returns the bench and the step of the ACK slot's
/// first clock.
fn ack_run(interdep: bool, twin_ack: bool, decouple: bool) -> (Bench, usize) {
    let mut b = Bench::running(2, 1, &[], interdep);
    if decouple {
        b.write(
            CTRL,
            FORCE_DECOUPLE | if interdep { ACK_INTERDEP } else { 0 },
        );
        b.idle_bits(2);
    }
    let f = encode(0x155, false, false, 1, &[0xC3]);
    let ackers = if twin_ack { 0b110 } else { 0b010 };
    let t0 = b.send(&f, 0, ackers);
    (b, t0 + CPB * f.ack)
}

#[test]
fn ack_window_masks_downlinks_to_the_twin() {
    let (b, ta) = ack_run(true, false, false);
    // ACK_SLOT from the CRC delimiter's sample edge (= step ta), ACK_DELIM from
    // the ACK slot's, IDLE_WAIT from the ACK delimiter's (ta + 16).
    for k in ta - 4..ta + 20 {
        let w = (ta..ta + 16).contains(&k);
        assert_eq!(
            b.log[k].probes.ack_window,
            w,
            "step ta{:+}",
            k as i64 - ta as i64
        );
    }
    // Node 1's ACK is on the pins during ta..ta+8 and would reach the downlinks at
    // ta+2..ta+10; the mask applies to edges ta+1..=ta+16 (ack_window before them).
    for k in ta + 1..=ta + 16 {
        assert_eq!(b.log[k].downlink, 0b11, "masked downlink at ta+{}", k - ta);
    }
    for k in ta + 2..ta + 10 {
        // The hub itself sees the ACK and forwards it to the twin.
        assert!(!b.log[k].probes.coupled);
        assert_eq!(b.log[k].sublink_out, 0);
    }
    // The twin's ACK reaches the downlinks.
    let (b, ta) = ack_run(true, true, false);
    for k in ta + 2..ta + 10 {
        assert_eq!(b.log[k].downlink, 0, "twin ACK at ta+{}", k - ta);
    }
    assert_eq!(b.log[ta + 10].downlink, 0b11);
    // No mask without ack_interdep, nor while decoupled.
    for (interdep, decouple) in [(false, false), (true, true)] {
        let (b, ta) = ack_run(interdep, false, decouple);
        assert!(b.log[ta + 5].probes.ack_window);
        for k in ta + 2..ta + 10 {
            assert_eq!(b.log[k].downlink, 0, "unmasked ACK at ta+{}", k - ta);
        }
    }
}

// ---------------------------------------------------------------------------
// Guards (§6).

#[test]
fn stuck_dominant_node_port_is_isolated_at_its_14th_dominant_sample() {
    let mut b = Bench::running(2, 1, &[(INT_ENABLE, INT_ISOLATION)], true);
    b.pins = 0b111 & !1;
    let k = b.now();
    for _ in 0..40 * CPB {
        b.step();
    }
    // Samples at k+8, k+16, ...: dom_run reaches 14 at the 14th.
    let iso = k + 8 + 13 * CPB;
    assert!(b.log[iso].probes.sample_point);
    assert!(enabled(&b.log[iso - 1], 0));
    assert!(!enabled(&b.log[iso], 0));
    // Effective on the coupling at the next edge.
    assert!(!b.log[iso].probes.coupled && b.log[iso].downlink == 0);
    assert!(b.log[iso + 1].probes.coupled && b.log[iso + 1].downlink == 0b11);
    assert!(!b.log[iso].irq && b.log[iso + 1].irq);
    assert_eq!(b.port_reg(0), 1 << 1 | 1 << 16, "kind 1, one isolation");
    assert_eq!(b.port_reg(1), 1);
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION);
    assert_eq!(b.read(STATUS) >> 16, 0b110);
}

#[test]
fn stuck_dominant_sublink_is_isolated_at_its_16th_dominant_sample() {
    let mut b = Bench::running(2, 1, &[], true);
    b.pins = 0b011;
    let k = b.now();
    for _ in 0..40 * CPB {
        b.step();
    }
    let iso = k + 8 + 15 * CPB;
    assert!(enabled(&b.log[iso - 1], 2));
    assert!(!enabled(&b.log[iso], 2));
    assert!(b.log[iso + 1].probes.coupled);
    assert_eq!(b.port_reg(2), 1 << 1 | 1 << 16);
    // Thresholds from GUARD_CFG: sd_run_sub 20.
    let mut b = Bench::running(2, 1, &[(GUARD_CFG, 14 | 20 << 8 | 8 << 16)], true);
    b.pins = 0b011;
    let k = b.now();
    for _ in 0..40 * CPB {
        b.step();
    }
    let iso = k + 8 + 19 * CPB;
    assert!(enabled(&b.log[iso - 1], 2) && !enabled(&b.log[iso], 2));
}

#[test]
fn isolation_event_beats_a_w1c_clear_at_the_same_edge() {
    let mut b = Bench::running(2, 1, &[], true);
    b.pins = 0b110;
    let k = b.now();
    let iso = k + 8 + 13 * CPB;
    while b.now() < iso {
        b.step();
    }
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: INT_STATUS,
        wb_dat_w: 0xF,
        ..b.pin_inputs()
    });
    assert!(o.wb_ack && !enabled(&o, 0));
    b.step();
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION);
}

/// Port 1 of a 3x1 hub drives dominant in the r0 bit (after the arbitration
/// field) of a frame it does not send; the transmitter's r0 is dominant too, so
/// the frame is undisturbed. Everybody else acknowledges.
fn flipping_frame(b: &Bench, flip: bool) -> Vec<u16> {
    let f = encode(0x2B4, false, false, 2, &[0x5A, 0x11]);
    let mut lanes = b.frame_lanes(&f, 0, 0b1110);
    if flip {
        lanes[f.raw_at[14]] &= !(1 << 1); // r0
    }
    lanes
}

#[test]
fn bit_flipping_port_is_blamed_per_frame_and_isolated_at_bf_up() {
    let mut b = Bench::running(3, 1, &[], true);
    let f = encode(0x2B4, false, false, 2, &[0x5A, 0x11]);
    assert!(!f.bits[f.raw_at[14]], "r0 is dominant");
    for i in 1..=3u32 {
        let lanes = flipping_frame(&b, true);
        b.drive(&lanes);
        let r = b.port_reg(1);
        assert_eq!(
            pec(r),
            8 * i,
            "frame {i}: +8, no decrement in a blamed frame"
        );
        assert_eq!(r & 1, 1);
        assert_eq!(pec(b.port_reg(0)), 0, "the transmitter is not blamed");
    }
    // The 4th blamed frame: pec 32 >= bf_up 32, isolated at the r0 sample.
    let lanes = flipping_frame(&b, true);
    let t0 = b.drive(&lanes);
    let at = sample_step(t0, f.raw_at[14]);
    assert!(enabled(&b.log[at - 1], 1) && !enabled(&b.log[at], 1));
    let r = b.port_reg(1);
    assert_eq!((r & 1, kind(r), pec(r), r >> 16 & 0xFF), (0, 3, 32, 1));
    assert_eq!(b.read(STATS) & 0xFFFF, 4);
}

#[test]
fn clean_frames_decrement_the_port_error_counter() {
    let mut b = Bench::running(3, 1, &[], true);
    for _ in 0..2 {
        let lanes = flipping_frame(&b, true);
        b.drive(&lanes);
    }
    assert_eq!(pec(b.port_reg(1)), 16);
    for i in 1..=3u32 {
        let lanes = flipping_frame(&b, false);
        b.drive(&lanes);
        assert_eq!(pec(b.port_reg(1)), 16 - i);
    }
    // bf_up from BF_CFG: 8 isolates at the first blame.
    let mut b = Bench::running(3, 1, &[(BF_CFG, 8 | 64 << 8)], true);
    let lanes = flipping_frame(&b, true);
    b.drive(&lanes);
    assert_eq!(kind(b.port_reg(1)), 3);
}

#[test]
fn six_recessive_bits_blame_the_transmitter() {
    let mut b = Bench::running(2, 1, &[], true);
    // Port 0 sends SOF and then six recessive bits: it failed to stuff.
    let mut lanes = vec![0b110u16];
    lanes.extend([0b111; 16]);
    let t0 = b.drive(&lanes);
    assert_eq!(b.log[sample_step(t0, 5)].probes.trk_state, FRAME);
    assert_eq!(b.log[sample_step(t0, 6)].probes.trk_state, IDLE_WAIT);
    assert_eq!(b.port_reg(0), 1 | 8 << 8);
    assert_eq!(b.port_reg(1), 1, "not a candidate: not blamed");
    assert_eq!(b.read(STATS), 1 << 16);
}

#[test]
fn reserved_identifier_from_a_node_port_isolates_it() {
    for id in [0x000, 0x001] {
        let mut b = Bench::running(2, 1, &[], true);
        let f = encode(id, false, false, 0, &[]);
        // Nobody acknowledges: once port 0 is cut off, the bus is recessive for
        // more than 10 bits and a dominant ACK would be a start of frame.
        let t0 = b.send(&f, 0, 0);
        // Isolated at the sample of identifier bit 10 (data bit pos 10).
        let at = sample_step(t0, f.raw_at[10]);
        assert!(enabled(&b.log[at - 1], 0), "id {id:#x}");
        assert!(!enabled(&b.log[at], 0), "id {id:#x}");
        let r = b.port_reg(0);
        assert_eq!((kind(r), r & 1), (4, 0), "id {id:#x}");
        assert_eq!(b.port_reg(1), 1);
        assert_eq!(b.read(INT_STATUS), INT_ISOLATION);
    }
    // The rule looks at identifier bits 1..10 before IDE is known, so an extended
    // frame whose base part is 0x000 / 0x001 is caught as well.
    let mut b = Bench::running(2, 1, &[], true);
    let f = encode(0x0000_0F0F, true, false, 0, &[]);
    let t0 = b.send(&f, 0, 0);
    assert!(!enabled(&b.log[sample_step(t0, f.raw_at[10])], 0));
    assert_eq!(kind(b.port_reg(0)), 4);
    // 0x002 is an ordinary identifier.
    let mut b = Bench::running(2, 1, &[], true);
    b.send(&encode(0x002, false, false, 0, &[]), 0, 0b110);
    assert_eq!(b.port_reg(0), 1);
    assert_eq!(b.read(STATS), 1);
}

#[test]
fn reserved_identifier_from_a_sublink_is_legitimate() {
    let mut b = Bench::running(2, 1, &[], true);
    let f = encode(0x000, false, false, 0, &[]);
    b.send(&f, 2, 0b011);
    for p in 0..3 {
        assert_eq!(b.port_reg(p), 1, "PORT_{p}");
    }
    assert_eq!(b.read(STATS), 1);
    assert_eq!(b.read(INT_STATUS), 0);
}

#[test]
fn silent_port_is_isolated_after_sr_frames() {
    let mut b = Bench::running(3, 1, &[], true);
    let f = encode(0x0F1, false, false, 1, &[0x42]);
    // Port 0 sends, ports 1 and the sublink (3) acknowledge, port 2 says nothing.
    for i in 1..=7 {
        b.send(&f, 0, 0b1010);
        assert_eq!(b.port_reg(2), 1, "frame {i}");
    }
    let t0 = b.send(&f, 0, 0b1010);
    let at = sample_step(t0, f.ack);
    assert!(enabled(&b.log[at - 1], 2) && !enabled(&b.log[at], 2));
    let r = b.port_reg(2);
    assert_eq!((r & 1, kind(r)), (0, 2));
    for p in [0, 1, 3] {
        assert_eq!(b.port_reg(p), 1, "PORT_{p}");
    }
    // sr_frames = 0: the silence rule is off.
    let mut b = Bench::running(3, 1, &[(GUARD_CFG, 14 | 16 << 8)], true);
    for _ in 0..10 {
        b.send(&f, 0, 0b1010);
    }
    assert_eq!(b.port_reg(2), 1);
}

#[test]
fn isolated_port_is_restored_after_restore_bits_symptom_free_samples() {
    let cfg = [(RESTORE_CFG, 20 | 4096 << 16), (INT_ENABLE, 0xF)];
    let mut b = Bench::running(2, 1, &cfg, true);
    b.pins = 0b110;
    let k = b.now();
    for _ in 0..20 * CPB {
        b.step();
    }
    // Isolated at the 14th sample; released at k + 160: the last dominant sample
    // is k + 160 (pb = pin of step 157), the first recessive one k + 168.
    assert!(!enabled(&b.log[k + 8 + 13 * CPB], 0));
    b.pins = 0b111;
    for _ in 0..40 * CPB {
        b.step();
    }
    let back = k + 168 + 19 * CPB; // the 20th symptom-free sample
    assert!(b.log[back].probes.sample_point);
    for s in k + 8 + 13 * CPB..back {
        assert!(!enabled(&b.log[s], 0), "step k+{}", s - k);
    }
    assert!(enabled(&b.log[back], 0));
    let r = b.port_reg(0);
    // enabled, kind kept (1), pec 0, 1 isolation, 1 restoration.
    assert_eq!(r, 1 | 1 << 1 | 1 << 16 | 1 << 24);
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION | INT_RESTORATION);
    // restore_bits = 0: never restored.
    let mut b = Bench::running(2, 1, &[(RESTORE_CFG, 4096 << 16)], true);
    b.pins = 0b110;
    for _ in 0..20 * CPB {
        b.step();
    }
    b.idle_bits(300);
    assert_eq!(b.port_reg(0) & 1, 0);
}

// ---------------------------------------------------------------------------
// Decoupling (§7).

#[test]
fn decoupling_after_decouple_bits_is_sticky_until_recouple() {
    let cfg = [(RESTORE_CFG, 10 | 30 << 16)];
    let mut b = Bench::running(2, 1, &cfg, true);
    // The only sublink stuck dominant: isolated at its 16th sample.
    b.pins = 0b011;
    let k = b.now();
    for _ in 0..60 * CPB {
        b.step();
    }
    let iso = k + 8 + 15 * CPB;
    assert!(!enabled(&b.log[iso], 2));
    // no_twin counts from the next sample (the isolation edge still had it
    // enabled before the edge): decoupled at the 30th sample after it.
    let dec = iso + 30 * CPB;
    assert!(!b.log[dec - 1].probes.decoupled);
    assert!(b.log[dec].probes.decoupled);
    // Released and quiet for far longer than restore_bits: frozen while decoupled.
    b.pins = 0b111;
    b.idle_bits(100);
    assert!(b.log[b.now() - 1].probes.decoupled);
    assert_eq!(b.read(STATUS) & 0b10, 0b10);
    assert_eq!(b.read(STATUS) >> 16, 0b011);
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION | INT_DECOUPLED);
    // recouple: at the write edge, decoupled cleared and the sublink enabled with
    // its kind and counts kept.
    let o = b.step_with(HubInputs {
        wb_cyc: true,
        wb_stb: true,
        wb_we: true,
        wb_adr: CTRL,
        wb_dat_w: ACK_INTERDEP | RECOUPLE,
        ..b.pin_inputs()
    });
    assert!(!o.probes.decoupled && enabled(&o, 2));
    b.step();
    assert_eq!(b.port_reg(2), 1 | 1 << 1 | 1 << 16);
    assert_eq!(b.read(CTRL), ACK_INTERDEP, "commands read 0");
}

#[test]
fn forced_decoupling_makes_the_hub_a_star_of_its_own() {
    let mut b = Bench::running(2, 1, &[], true);
    b.write(CTRL, ACK_INTERDEP | FORCE_DECOUPLE);
    assert!(b.log[b.now() - 2].probes.decoupled, "at the write edge");
    assert_eq!(b.read(INT_STATUS), INT_DECOUPLED);
    // The twin (sublink, still enabled) no longer reaches the hub's view.
    b.pins = 0b011;
    let s = b.step();
    b.step();
    b.step();
    assert!(b.log[s + 2].probes.coupled);
    assert_eq!(b.log[s + 2].downlink, 0b11);
    assert_eq!(b.read(STATUS) >> 16, 0b111);
    // Own nodes still do, and go to the twin.
    b.pins = 0b010;
    let s = b.step();
    b.step();
    b.step();
    assert!(!b.log[s + 2].probes.coupled);
    assert_eq!((b.log[s + 2].downlink, b.log[s + 2].sublink_out), (0, 0));
    // recouple: the twin counts again.
    b.pins = 0b111;
    b.idle_bits(2);
    b.write(CTRL, ACK_INTERDEP | RECOUPLE);
    b.pins = 0b011;
    let s = b.step();
    b.step();
    b.step();
    assert!(!b.log[s + 2].probes.coupled);
    // Commands in reset mode do nothing.
    b.pins = 0b111;
    b.idle_bits(2);
    b.write(CTRL, ACK_INTERDEP | RESET_MODE);
    b.write(CTRL, ACK_INTERDEP | RESET_MODE | FORCE_DECOUPLE);
    assert!(
        !b.log[b.now() - 2].probes.decoupled,
        "not at the write edge"
    );
    assert_eq!(b.read(STATUS) & 0b10, 0);
}

#[test]
fn entering_reset_mode_clears_the_guards_but_keeps_int_status() {
    let mut b = Bench::running(2, 1, &[], true);
    b.drive(&[0b110; 20]);
    b.idle_bits(2);
    assert_eq!(b.port_reg(0) & 1, 0);
    b.write(CTRL, ACK_INTERDEP | RESET_MODE);
    assert_eq!(b.port_reg(0), 1);
    assert_eq!(b.read(STATUS), 1 | 0b111 << 16);
    assert_eq!(b.read(STATS), 0);
    assert_eq!(b.read(INT_STATUS), INT_ISOLATION);
}
