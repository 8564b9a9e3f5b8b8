//! NRAP (hub contract §9) on two hub models wired back to back (hub A and hub B,
//! N = 2, M = 1, no nodes): the identification frame on the wire against the
//! independent encoder of `main.rs` (ISO 11898-1), a transient loss of the
//! interlink that ends in recoupling, a permanent one that ends in definitive
//! decoupling, each within the worst-case bounds §9.5 derives from the defaults,
//! and the NRAP registers' clamps.

use super::*;

const NRAP_CFG: u8 = 11;
const NRAP_TIME: u8 = 12;
const NRAP_DDSP: u8 = 13;
const NRAP_STATUS: u8 = 14;
const NRAP_ON: u32 = 1 << 9;
const INT_NRAP: u32 = 1 << 5;

// Phases (§9.2).
const RUN: u8 = 0;
const SRP_FORCE: u8 = 1;
const SRP_EXCHANGE: u8 = 2;
const NRP: u8 = 3;
const DDSP_FORCE: u8 = 4;
const DDSP_SEND: u8 = 5;
const SPLIT: u8 = 6;

/// §9.5 worst cases from the trigger, in bit times, with the default registers.
const RECOUPLE_BOUND: usize = 64 + 1024 + 1024;
const SPLIT_BOUND: usize = 64 + 1024 + 1024 + 64 + 1024;

/// The twins' bit timing: the star scenarios' (BRP 1, TSEG1 13, TSEG2 4, SJW 2,
/// `BTR` encodings of §8), 36 clocks per bit, sample point at 28 clocks: long
/// enough for the hub-to-hub loop (3 edges each way) inside one bit, which the
/// identification frames' arbitration needs (8 clocks per bit is not).
const TWIN_BTR: u32 = 1 | (13 - 1) << 6 | (4 - 1) << 10 | (2 - 1) << 13;
const TCPB: usize = 36;

/// What the interlink does to one direction.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Wire {
    Ok,
    StuckDominant,
    Cut,
}

/// Hub A and hub B, node ports idle (recessive), one interlink.
struct Twins {
    hubs: [HubModel; 2],
    out: [HubOutputs; 2],
    /// `wire[0]`: A -> B, `wire[1]`: B -> A.
    wire: [Wire; 2],
    /// Per step: (A's outputs, B's outputs).
    log: Vec<[HubOutputs; 2]>,
}

impl Twins {
    /// Both hubs reset, NRAP and ACK interdependence on, running.
    fn new() -> Self {
        let mut t = Twins {
            hubs: [
                HubModel::new_hub(0, 2, 1).unwrap(),
                HubModel::new_hub(1, 2, 1).unwrap(),
            ],
            out: [HubOutputs::default(); 2],
            wire: [Wire::Ok; 2],
            log: Vec::new(),
        };
        for _ in 0..2 {
            t.step_both([None, None], true);
        }
        t.write_both(BTR, TWIN_BTR);
        t.write_both(CTRL, ACK_INTERDEP | NRAP_ON);
        t.bits(14);
        t
    }

    fn carried(&self, from: usize) -> u8 {
        match self.wire[from] {
            Wire::Ok => self.out[from].sublink_out & 1,
            Wire::StuckDominant => 0,
            Wire::Cut => 1,
        }
    }

    /// One clock; `wb[h]` a Wishbone request (we, adr, dat) for hub h.
    fn step_both(&mut self, wb: [Option<(bool, u8, u32)>; 2], rst: bool) {
        let sub = [self.carried(1), self.carried(0)];
        for h in 0..2 {
            let mut i = HubInputs {
                rst,
                uplink: 0b11,
                sublink_in: sub[h],
                ..HubInputs::default()
            };
            if let Some((we, adr, dat)) = wb[h] {
                i.wb_cyc = true;
                i.wb_stb = true;
                i.wb_we = we;
                i.wb_adr = adr;
                i.wb_dat_w = dat;
            }
            self.out[h] = self.hubs[h].step(&i);
        }
        self.log.push(self.out);
    }

    fn write_both(&mut self, adr: u8, dat: u32) {
        self.step_both([Some((true, adr, dat)); 2], false);
        self.step_both([None, None], false);
    }

    fn read(&mut self, h: usize, adr: u8) -> u32 {
        let mut wb = [None, None];
        wb[h] = Some((false, adr, 0));
        self.step_both(wb, false);
        let v = self.out[h].wb_dat_r;
        self.step_both([None, None], false);
        v
    }

    fn bits(&mut self, n: usize) {
        for _ in 0..n * TCPB {
            self.step_both([None, None], false);
        }
    }

    /// (step, phase) of every phase change of hub h.
    fn phases(&self, h: usize) -> Vec<(usize, u8)> {
        let mut v = Vec::new();
        let mut prev = RUN;
        for (k, o) in self.log.iter().enumerate() {
            let p = o[h].probes.nrap_phase;
            if p != prev {
                v.push((k, p));
                prev = p;
            }
        }
        v
    }
}

/// Hub B's incoming sublink held dominant for 40 bit times: B isolates it (rule
/// SD, 28 bits) and starts NRAP; its forcing makes A isolate its own sublink.
fn trigger(t: &mut Twins) -> usize {
    t.wire[0] = Wire::StuckDominant;
    let k = t.log.len();
    t.bits(40);
    t.wire[0] = Wire::Ok;
    k
}

#[test]
fn hub_a_sends_its_identification_frame_bit_for_bit() {
    let mut t = Twins::new();
    trigger(&mut t);
    t.bits(800);
    // The first dominant bit A sends in SRP_EXCHANGE is its SOF; every later bit
    // lasts TCPB clocks (A resynchronises on no edge of its own).
    let log = &t.log;
    let sof = (1..log.len())
        .find(|&k| {
            log[k][0].probes.nrap_phase == SRP_EXCHANGE
                && !log[k][0].probes.hub_tx
                && log[k - 1][0].probes.hub_tx
        })
        .expect("hub A sends in SRP_EXCHANGE");
    let want = encode(0x000, false, false, 0, &[]);
    let sent: Vec<bool> = (0..=want.crc_delim)
        .map(|j| log[sof + j * TCPB + TCPB / 2][0].probes.hub_tx)
        .collect();
    assert_eq!(sent, want.bits[..=want.crc_delim].to_vec());
    // And it reaches the twin one edge later on the sublink.
    for j in 0..=want.crc_delim {
        let k = sof + j * TCPB + TCPB / 2;
        assert_eq!(log[k + 1][0].sublink_out & 1 == 1, want.bits[j], "bit {j}");
    }
}

#[test]
fn a_transient_loss_of_the_interlink_ends_in_recoupling_within_the_bound() {
    let mut t = Twins::new();
    let k = trigger(&mut t);
    t.bits(RECOUPLE_BOUND + 200);
    let (a, b) = (t.phases(0), t.phases(1));
    let seq = |v: &[(usize, u8)]| v.iter().map(|x| x.1).collect::<Vec<_>>();
    assert_eq!(seq(&b), [SRP_FORCE, SRP_EXCHANGE, NRP, RUN], "hub B: {b:?}");
    assert_eq!(seq(&a), [SRP_FORCE, SRP_EXCHANGE, NRP, RUN], "hub A: {a:?}");
    // B triggers when its sublink has been dominant for sd_run_sub (28) bits; A
    // when B's forcing has been on its sublink for 28 bits (+ sampling skew).
    let b_trig = (b[0].0 - k) / TCPB;
    let a_trig = (a[0].0 - b[0].0) / TCPB;
    assert!(
        (28..=30).contains(&b_trig),
        "B triggered after {b_trig} bits"
    );
    assert!(
        (28..=30).contains(&a_trig),
        "A triggered {a_trig} bits after B"
    );
    // Both recouple at the ACK slot of the same frame (counted on the coupled bus).
    let (a_end, b_end) = (a[3].0, b[3].0);
    assert!(a_end.abs_diff(b_end) < TCPB, "A at {a_end}, B at {b_end}");
    for (h, v) in [(0, &a), (1, &b)] {
        let took = (v[3].0 - v[0].0) / TCPB;
        assert!(took <= RECOUPLE_BOUND, "hub {h} took {took} bits");
        assert!(!t.out[h].probes.decoupled);
        // The sublink was disabled for the exchange and restored when silent; the
        // node ports stayed enabled.
        let (srp, nrp, end) = (v[1].0, v[2].0, v[3].0);
        assert_eq!(t.log[srp][h].probes.port_enabled, 0b011, "hub {h}");
        assert_eq!(t.log[nrp - 1][h].probes.port_enabled, 0b111, "hub {h}");
        assert_eq!(t.log[end][h].probes.port_enabled, 0b111, "hub {h}");
    }
    let st = t.read(0, NRAP_STATUS);
    assert_eq!(st & 7, RUN as u32);
    assert_eq!(st >> 3 & 1, 1, "outcome: recoupled");
    assert_eq!(st >> 4 & 0xF, 1, "one run");
    assert_eq!(t.read(1, INT_STATUS) & INT_NRAP, INT_NRAP);
}

#[test]
fn a_permanent_loss_ends_in_definitive_decoupling_within_the_bound() {
    let mut t = Twins::new();
    trigger(&mut t);
    // Both hubs have triggered (A 28 bits after B) before the interlink is lost.
    t.bits(40);
    t.wire = [Wire::Cut; 2];
    t.bits(SPLIT_BOUND + 200);
    for h in 0..2 {
        let v = t.phases(h);
        let seq: Vec<u8> = v.iter().map(|x| x.1).collect();
        assert_eq!(
            seq,
            [SRP_FORCE, SRP_EXCHANGE, DDSP_FORCE, DDSP_SEND, SPLIT],
            "hub {h}: {v:?}"
        );
        let took = (v[4].0 - v[0].0) / TCPB;
        assert!(took <= SPLIT_BOUND, "hub {h} took {took} bits");
        // The exchange timed out after srp_bits (1024) in SRP_EXCHANGE.
        assert_eq!((v[2].0 - v[1].0) / TCPB, 1024, "hub {h}");
        assert!(t.out[h].probes.decoupled);
        // A decided hub keeps its sublinks recessive (§9.4).
        assert!(t.log[t.log.len() - 200..]
            .iter()
            .all(|o| o[h].sublink_out & 1 == 1));
        let st = t.read(h, NRAP_STATUS);
        assert_eq!(st & 7, SPLIT as u32);
        assert_eq!(st >> 3 & 1, 0, "outcome: split");
    }
}

#[test]
fn nrap_registers_clamp_zero_settings_and_refuse_writes_outside_reset_mode() {
    let mut b = Bench::new(2, 1);
    assert_eq!(b.read(NRAP_CFG), 64 | 2 << 12 | 2 << 16 | 8 << 20);
    assert_eq!(b.read(NRAP_TIME), 1024 | 1024 << 16);
    assert_eq!(b.read(NRAP_DDSP), 1024 | 16 << 16);
    b.write(NRAP_CFG, 0);
    b.write(NRAP_TIME, 0);
    b.write(NRAP_DDSP, 0);
    assert_eq!(b.read(NRAP_CFG), 64 | 1 << 12 | 1 << 16 | 1 << 20);
    assert_eq!(b.read(NRAP_TIME), 256 | 256 << 16);
    assert_eq!(b.read(NRAP_DDSP), 256, "block_frames 0 stays 0 (off)");
    b.write(NRAP_DDSP, 300 | 2 << 16);
    assert_eq!(b.read(NRAP_DDSP), 300 | 4 << 16, "block_frames 1..3 -> 4");
    b.write(NRAP_CFG, 1000 | 15 << 12 | 9 << 16 | 3 << 20 | 0xF << 24);
    assert_eq!(b.read(NRAP_CFG), 1000 | 15 << 12 | 9 << 16 | 3 << 20);
    assert_eq!(b.read(CTRL), RESET_MODE | ACK_INTERDEP | NRAP_ON);
    // Outside reset mode: refused, illegal; so is a change of nrap_on.
    b.write(CTRL, ACK_INTERDEP | NRAP_ON);
    b.write(NRAP_TIME, 5000);
    assert_eq!(b.read(NRAP_TIME), 256 | 256 << 16);
    assert_eq!(b.read(INT_STATUS) & INT_ILLEGAL, INT_ILLEGAL);
    b.write(INT_STATUS, INT_ILLEGAL);
    b.write(CTRL, ACK_INTERDEP);
    assert_eq!(b.read(INT_STATUS) & INT_ILLEGAL, INT_ILLEGAL);
    assert_eq!(b.read(CTRL) & NRAP_ON, NRAP_ON);
    assert_eq!(
        b.read(NRAP_STATUS) & 0xFFFF,
        0,
        "RUN, no run yet, nothing counted"
    );
    b.write(NRAP_STATUS, 1);
    assert_eq!(b.read(INT_STATUS) & INT_ILLEGAL, INT_ILLEGAL);
    // Hub B's ID names it (bit 12).
    let mut hb = Bench::on(HubModel::new_hub(1, 2, 1).unwrap(), 2, 1);
    assert_eq!(hb.read(ID), 0x4855_0000 | 1 << 12 | 2 << 8 | 1);
}
