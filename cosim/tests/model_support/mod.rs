//! Shared helpers for the reference model tests: an independent frame encoder
//! (fields, CRC by polynomial long division, stuffing), a wired-AND bus of models,
//! and a "lower tester" that drives exact bit sequences into one model.
//!
//! Nothing here uses the model's own encoder or CRC: expected values come from the
//! standard's definitions, computed a second way.
#![allow(dead_code)]

use drcc_cosim::model::ChannelModel;
use drcc_cosim::{BitTiming, ChannelInputs, ChannelOutputs, ControllerConfig, Frame};

/// Field codes, copied from the table of the timing contract §4.1.
pub mod code {
    pub const INTEGRATING: u8 = 0;
    pub const IDLE: u8 = 1;
    pub const ID_A: u8 = 2;
    pub const SRR_RTR: u8 = 3;
    pub const IDE: u8 = 4;
    pub const ID_B: u8 = 5;
    pub const RTR_EXT: u8 = 6;
    pub const R1: u8 = 7;
    pub const R0: u8 = 8;
    pub const DLC: u8 = 9;
    pub const DATA: u8 = 10;
    pub const CRC: u8 = 11;
    pub const CRC_DELIM: u8 = 12;
    pub const ACK_SLOT: u8 = 13;
    pub const ACK_DELIM: u8 = 14;
    pub const EOF: u8 = 15;
    pub const INTERMISSION: u8 = 16;
    pub const SUSPEND: u8 = 17;
    pub const ERROR_FLAG: u8 = 18;
    pub const ERROR_DELIM: u8 = 19;
    pub const OVERLOAD_FLAG: u8 = 20;
    pub const OVERLOAD_DELIM: u8 = 21;
    pub const BUS_OFF: u8 = 22;
}

/// The reference bit timing: 8 tq, sample point after 6 tq, SJW 1.
pub fn timing(brp: u16) -> BitTiming {
    BitTiming {
        brp,
        tseg1: 5,
        tseg2: 2,
        sjw: 1,
        triple_sampling: false,
    }
}

/// One bit on the bus as the independent encoder sees it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bit {
    pub value: bool,
    /// Field code (§4.1) of the bit; a stuff bit carries the field of the bit after it.
    pub field: u8,
    pub stuff: bool,
}

/// CRC-15 by polynomial long division: remainder of M(x) * x^15 modulo
/// x^15 + x^14 + x^10 + x^8 + x^7 + x^4 + x^3 + 1.
pub fn crc15_division(message: &[bool]) -> u16 {
    // Generator coefficients from x^15 down to x^0.
    let g: [bool; 16] = {
        let mut g = [false; 16];
        for e in [15, 14, 10, 8, 7, 4, 3, 0] {
            g[15 - e] = true;
        }
        g
    };
    let mut work: Vec<bool> = message.to_vec();
    work.extend(std::iter::repeat_n(false, 15));
    for i in 0..message.len() {
        if work[i] {
            for (j, &gj) in g.iter().enumerate() {
                work[i + j] ^= gj;
            }
        }
    }
    work[message.len()..]
        .iter()
        .fold(0u16, |acc, &b| (acc << 1) | b as u16)
}

fn push_bits(out: &mut Vec<(bool, u8)>, value: u64, n: u32, field: u8) {
    for i in (0..n).rev() {
        out.push(((value >> i) & 1 == 1, field));
    }
}

/// Unstuffed bits from SOF to the last CRC bit, each with its field code.
/// `corrupt_crc` flips the given CRC bit (0 = first CRC bit sent).
pub fn unstuffed(f: &Frame, corrupt_crc: Option<usize>) -> Vec<(bool, u8)> {
    let mut v = Vec::new();
    v.push((false, code::IDLE)); // SOF (labelled by the state it leaves)
    if f.ide {
        let id = (f.id & 0x1FFF_FFFF) as u64;
        push_bits(&mut v, id >> 18, 11, code::ID_A);
        v.push((true, code::SRR_RTR));
        v.push((true, code::IDE));
        push_bits(&mut v, id & 0x3FFFF, 18, code::ID_B);
        v.push((f.rtr, code::RTR_EXT));
        v.push((false, code::R1));
        v.push((false, code::R0));
    } else {
        push_bits(&mut v, (f.id & 0x7FF) as u64, 11, code::ID_A);
        v.push((f.rtr, code::SRR_RTR));
        v.push((false, code::IDE));
        v.push((false, code::R0));
    }
    let dlc = f.dlc & 0xF;
    push_bits(&mut v, dlc as u64, 4, code::DLC);
    if !f.rtr {
        for &byte in &f.data[..(dlc as usize).min(8)] {
            push_bits(&mut v, byte as u64, 8, code::DATA);
        }
    }
    let message: Vec<bool> = v.iter().map(|&(b, _)| b).collect();
    let mut crc = crc15_division(&message);
    if let Some(k) = corrupt_crc {
        crc ^= 1 << (14 - k);
    }
    push_bits(&mut v, crc as u64, 15, code::CRC);
    v
}

/// Stuffs SOF..CRC (a stuff bit after 5 equal bits, stuff bits included in the
/// count, possibly after the last CRC bit) and appends CRC delimiter, ACK slot
/// (`ack` = value on the bus), ACK delimiter and 7 EOF bits.
pub fn frame_bits(f: &Frame, ack: bool, corrupt_crc: Option<usize>) -> Vec<Bit> {
    let raw = unstuffed(f, corrupt_crc);
    let mut out: Vec<Bit> = Vec::new();
    let mut run = 0;
    let mut last = true;
    for (i, &(b, field)) in raw.iter().enumerate() {
        out.push(Bit {
            value: b,
            field,
            stuff: false,
        });
        if b == last {
            run += 1;
        } else {
            last = b;
            run = 1;
        }
        if run == 5 {
            let next_field = raw.get(i + 1).map(|x| x.1).unwrap_or(code::CRC_DELIM);
            out.push(Bit {
                value: !b,
                field: next_field,
                stuff: true,
            });
            last = !b;
            run = 1;
        }
    }
    let fixed = [
        (true, code::CRC_DELIM),
        (ack, code::ACK_SLOT),
        (true, code::ACK_DELIM),
    ];
    for (value, field) in fixed {
        out.push(Bit {
            value,
            field,
            stuff: false,
        });
    }
    for _ in 0..7 {
        out.push(Bit {
            value: true,
            field: code::EOF,
            stuff: false,
        });
    }
    out
}

/// The field probe expected right after sampling `bits[k]`: the field of the next
/// non-stuff bit (INTERMISSION after the last EOF bit).
pub fn field_after(bits: &[Bit], k: usize) -> u8 {
    bits[k + 1..]
        .iter()
        .find(|b| !b.stuff)
        .map(|b| b.field)
        .unwrap_or(code::INTERMISSION)
}

/// Models on a wired-AND bus: every node's `rx` in cycle n is the AND of every
/// connected node's `tx` from cycle n-1 (and of a forced dominant level).
pub struct Bus {
    pub nodes: Vec<ChannelModel>,
    pub tx: Vec<bool>,
    pub connected: Vec<bool>,
    pub timing: BitTiming,
    /// Configuration inputs of each node (captured at reset edges, §6).
    pub configs: Vec<ControllerConfig>,
    /// `tx_abort` of each node for the next step only.
    pub abort: Vec<bool>,
    pub force_dominant: bool,
    /// Each node's `boff_hold` input (timing contract §4.5), 0 unless a test sets it.
    pub boff_hold: Vec<bool>,
    /// Each node's `tx_single` input (timing contract §8), applied at every step
    /// (it matters only with an accepted `tx_req`), 0 unless a test sets it.
    pub tx_single: Vec<bool>,
    pub clock: u64,
}

impl Bus {
    pub fn new(n: usize, timing: BitTiming) -> Self {
        Bus {
            nodes: (0..n).map(|_| ChannelModel::new()).collect(),
            tx: vec![true; n],
            connected: vec![true; n],
            timing,
            configs: vec![ControllerConfig::default(); n],
            abort: vec![false; n],
            force_dominant: false,
            boff_hold: vec![false; n],
            tx_single: vec![false; n],
            clock: 0,
        }
    }

    /// The bus level the nodes see in the next step.
    pub fn level(&self) -> bool {
        !self.force_dominant && self.tx.iter().zip(&self.connected).all(|(&t, &c)| t || !c)
    }

    /// One clock; `req[i]` requests a transmission on node i.
    pub fn step(&mut self, req: &[Option<Frame>]) -> Vec<ChannelOutputs> {
        let rx = self.level();
        let mut outs = Vec::with_capacity(self.nodes.len());
        for (i, node) in self.nodes.iter_mut().enumerate() {
            let r = req.get(i).copied().flatten();
            let out = node.step(&ChannelInputs {
                rst: false,
                rx,
                timing: self.timing,
                config: self.configs[i],
                tx_req: r.is_some(),
                tx_frame: r.unwrap_or_default(),
                tx_abort: std::mem::take(&mut self.abort[i]),
                err_reset: false,
                boff_hold: self.boff_hold[i],
                tx_single: self.tx_single[i],
            });
            self.tx[i] = out.tx;
            outs.push(out);
        }
        self.clock += 1;
        outs
    }

    /// One reset edge on every node (captures `timing` and `configs`).
    pub fn reset(&mut self) {
        for (i, node) in self.nodes.iter_mut().enumerate() {
            let out = node.step(&ChannelInputs {
                rst: true,
                rx: true,
                timing: self.timing,
                config: self.configs[i],
                ..Default::default()
            });
            self.tx[i] = out.tx;
        }
        self.clock += 1;
    }

    /// Steps with no requests until every node is idle (bus integration done).
    pub fn integrate(&mut self) {
        for _ in 0..(20 * self.timing.clocks_per_bit()) {
            self.step(&[]);
        }
    }
}

/// A lower tester: drives a bit sequence into one model, one bit every
/// `clocks_per_bit` clocks, wired-AND with the model's own `tx`.
pub struct Tester {
    pub node: ChannelModel,
    pub tx: bool,
    pub timing: BitTiming,
    /// Outputs at every sample point of the node, in order.
    pub samples: Vec<ChannelOutputs>,
    /// Every `rx_valid` pulse.
    pub received: Vec<Frame>,
    /// A transmission request applied at the next clock.
    pub request: Option<Frame>,
    /// Configuration inputs (captured at the first edge and at reset edges).
    pub config: ControllerConfig,
    /// Every output, clock by clock (only when `record` is set).
    pub record: bool,
    pub trace: Vec<ChannelOutputs>,
}

impl Tester {
    pub fn new(timing: BitTiming) -> Self {
        Tester {
            node: ChannelModel::new(),
            tx: true,
            timing,
            samples: Vec::new(),
            received: Vec::new(),
            request: None,
            config: ControllerConfig::default(),
            record: false,
            trace: Vec::new(),
        }
    }

    /// A tester whose node runs with `config`.
    pub fn with_config(timing: BitTiming, config: ControllerConfig) -> Self {
        let mut t = Tester::new(timing);
        t.config = config;
        t
    }

    /// Drives one bit value for one bit time.
    pub fn drive(&mut self, value: bool) {
        for _ in 0..self.timing.clocks_per_bit() {
            let req = self.request.take();
            let out = self.node.step(&ChannelInputs {
                rst: false,
                rx: value && self.tx,
                timing: self.timing,
                config: self.config,
                tx_req: req.is_some(),
                tx_frame: req.unwrap_or_default(),
                tx_abort: false,
                err_reset: false,
                boff_hold: false,
                tx_single: false,
            });
            self.tx = out.tx;
            if self.record {
                self.trace.push(out);
            }
            if out.probes.sample_point {
                self.samples.push(out);
            }
            if out.rx_valid {
                self.received.push(out.rx_frame);
            }
        }
    }

    pub fn drive_all(&mut self, bits: impl IntoIterator<Item = bool>) {
        for b in bits {
            self.drive(b);
        }
    }

    /// Drives `n` recessive bits.
    pub fn idle(&mut self, n: usize) {
        for _ in 0..n {
            self.drive(true);
        }
    }

    /// The outputs at the last sample point.
    pub fn last(&self) -> ChannelOutputs {
        *self.samples.last().expect("no sample point yet")
    }
}

/// ISO 11898-1 12.1.4.2 rule l: a bus-off node recovers after 128 occurrences of
/// 11 consecutive recessive bits.
pub const RECOVERY_SAMPLES: u32 = 128 * 11;

/// Node 0 of a two-node bus driven into bus-off as in `bus_off_and_recovery`
/// (its own DATA bits forced dominant: bit errors, TEC + 8 each, rule c), with
/// `boff_hold` = `hold` from the start (§4.5: the hold acts only once bus-off,
/// so the way there is the same). At the edge where node 0 becomes bus-off, node
/// 1 is cut from the bus, so that from then on the bus is node 0's recessive `tx`
/// unless the test forces it. Returns the bus and node 0's frame.
pub fn bus_off_node_0(hold: bool) -> (Bus, Frame) {
    let t = timing(0);
    let mut bus = Bus::new(2, t);
    bus.boff_hold[0] = hold;
    bus.integrate();
    let f = Frame::base(0x0C4, &[0xFF]);
    let mut req = vec![Some(f), None];
    let mut prev = bus.nodes[0].outputs();
    for _ in 0..4000 * t.clocks_per_bit() {
        bus.force_dominant = prev.probes.field == code::DATA && prev.tx;
        let o = bus.step(&req);
        req = vec![None, None];
        prev = o[0];
        if prev.probes.err_state == 2 {
            assert_eq!(prev.probes.tec, 256, "bus-off at TEC 256 (rule j)");
            assert_eq!(prev.probes.field, code::BUS_OFF);
            bus.force_dominant = false;
            bus.connected[1] = false;
            return (bus, f);
        }
    }
    panic!("node 0 never became bus-off");
}

/// Steps until node 0 leaves bus-off, forcing nothing; returns the number of
/// recessive samples it took from the first step on (the recovering edge is a
/// sample point and counts). Every step before it: still bus-off, `tx` recessive,
/// the frame pending; at it TEC = REC = 0, error active, IDLE (§4.5).
pub fn samples_to_recovery(bus: &mut Bus, limit: u32) -> u32 {
    let mut samples = 0;
    loop {
        let a = bus.step(&[])[0];
        let p = a.probes;
        assert!(a.tx, "a bus-off node drives recessive");
        if p.sample_point {
            assert!(p.sampled_bit, "nothing drives the bus dominant");
            samples += 1;
        }
        if p.err_state != 2 {
            assert!(p.sample_point, "recovery at a SAMPLE edge");
            assert_eq!((p.tec, p.rec, p.err_state, p.field), (0, 0, 0, code::IDLE));
            return samples;
        }
        assert_eq!(p.field, code::BUS_OFF);
        assert!(a.tx_pending, "the frame stays pending");
        assert!(samples <= limit, "no recovery within {limit} samples");
    }
}
