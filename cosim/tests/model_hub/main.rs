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

mod ack_unit;
mod coupling;
mod decoupling;
mod guards;
mod nrap;
mod registers;

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
const ACK_UNIT: u8 = 10;
const PORT0: u8 = 16;

const RESET_MODE: u32 = 1;
const FORCE_DECOUPLE: u32 = 1 << 1;
const RECOUPLE: u32 = 1 << 2;
const FI_ACK_LEAK: u32 = 1 << 3;
const ACK_INTERDEP: u32 = 1 << 8;

const INT_ISOLATION: u32 = 1;
const INT_RESTORATION: u32 = 2;
const INT_DECOUPLED: u32 = 4;
const INT_ILLEGAL: u32 = 8;
const INT_ACK_UNIT: u32 = 16;

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
        Bench::on(HubModel::new(n, m).expect("supported shape"), n, m)
    }

    /// [`Bench::new`] on a given model (e.g. one without its ACK unit).
    fn on(hub: HubModel, n: usize, m: usize) -> Self {
        let mut b = Bench {
            hub,
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

    /// [`Bench::running`] on a given model (e.g. one without its ACK unit), no
    /// configuration, ACK interdependence on.
    fn running_hub(hub: HubModel, n: usize, m: usize) -> Self {
        let mut b = Bench::on(hub, n, m);
        b.write(CTRL, ACK_INTERDEP);
        b.idle_bits(14);
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
        assert!(o.wb_ack != o.wb_err, "access to word {adr} not answered");
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
