//! Shared by the integration tests: the Verilated dual bus (or the CI rule for
//! a missing model), the register hooks of the Rust driver on it, the frames
//! the tests send (the oracle) and the send/receive loop.
#![allow(dead_code)]

use drcc_driver::{Channel, Drcc, Error, Frame, Registers};
use drcc_driver_sim::{CDriver, CFrame, DualBus, NodePort};
use embedded_can::{ExtendedId, Frame as _, Id, StandardId};
use std::cell::RefCell;
use std::rc::Rc;

/// Module clock of the bench and the bit rate the tests use: 16 clocks a bit.
pub const CLOCK_HZ: u32 = 16_000_000;
/// Bit rate of the tests.
pub const BITRATE: u32 = 1_000_000;
/// Clocks per bit at that rate.
pub const BIT: u64 = (CLOCK_HZ / BITRATE) as u64;

/// The Rust driver's register hooks: one Wishbone cycle on one node per access.
pub struct Regs(pub NodePort);

impl Registers for Regs {
    fn read32(&mut self, offset: u32) -> u32 {
        self.0.read32(offset)
    }
    fn write32(&mut self, offset: u32, value: u32) {
        self.0.write32(offset, value)
    }
}

/// The bus, or `None` (skipped) when the Verilated model is missing; a
/// missing model fails the test when it is required (CI), as in
/// cosim/verilator-sys/tests/drcc.rs.
pub fn bus_or_skip() -> Option<Rc<RefCell<DualBus>>> {
    if !drcc_driver_sim::available() {
        assert!(
            !drcc_driver_sim::required(),
            "the Verilated model is required in CI: {:?}",
            drcc_driver_sim::unavailable_reason()
        );
        eprintln!("skipped: {:?}", drcc_driver_sim::unavailable_reason());
        return None;
    }
    Some(DualBus::shared().expect("model available"))
}

/// The port of `node` on `bus`.
pub fn port(bus: &Rc<RefCell<DualBus>>, node: usize) -> NodePort {
    NodePort {
        bus: bus.clone(),
        node,
    }
}

/// A frame as a test states it: the oracle every received frame is compared with.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sent {
    /// Identifier.
    pub id: u32,
    /// Extended format.
    pub ext: bool,
    /// Remote frame.
    pub rtr: bool,
    /// Data length code.
    pub dlc: u8,
    /// Data bytes (empty for a remote frame).
    pub data: Vec<u8>,
}

/// The frames every transfer test sends: base and extended, data and remote,
/// DLC 0 and 8, the extreme identifiers.
pub fn frames() -> Vec<Sent> {
    let d = |id, ext, data: &[u8]| Sent {
        id,
        ext,
        rtr: false,
        dlc: data.len() as u8,
        data: data.to_vec(),
    };
    let r = |id, ext, dlc| Sent {
        id,
        ext,
        rtr: true,
        dlc,
        data: vec![],
    };
    vec![
        d(0x123, false, &[0x11, 0x22, 0x33]),
        d(
            0x1ABC_DEF0,
            true,
            &[0xDE, 0xAD, 0xBE, 0xEF, 0x01, 0x02, 0x03, 0x04],
        ),
        r(0x7FF, false, 4),
        d(0x000, false, &[]),
        d(0x555, false, &[0, 1, 2, 3, 4, 5, 6, 7]),
        r(0x1FFF_FFFF, true, 0),
        d(0x0000_0001, true, &[]),
        d(0x2AA, false, &[0xFF; 8]),
    ]
}

impl Sent {
    /// As the C driver's `drcc_frame`.
    pub fn to_c(&self) -> CFrame {
        let mut data = [0; 8];
        data[..self.data.len()].copy_from_slice(&self.data);
        CFrame {
            id: self.id,
            ide: u8::from(self.ext),
            rtr: u8::from(self.rtr),
            dlc: self.dlc,
            channel: 0,
            data,
            timestamp: 0,
        }
    }

    /// As the Rust driver's frame.
    pub fn to_rust(&self) -> Frame {
        let id: Id = if self.ext {
            ExtendedId::new(self.id).unwrap().into()
        } else {
            StandardId::new(self.id as u16).unwrap().into()
        };
        if self.rtr {
            Frame::remote_frame(id, self.dlc).unwrap()
        } else {
            Frame::data_frame(id, &self.data).unwrap()
        }
    }

    /// A frame the C driver received, with its channel (0 A, 1 B).
    pub fn from_c(f: &CFrame) -> (Sent, u8) {
        let len = if f.rtr != 0 {
            0
        } else {
            usize::from(f.dlc.min(8))
        };
        let sent = Sent {
            id: f.id,
            ext: f.ide != 0,
            rtr: f.rtr != 0,
            dlc: f.dlc,
            data: f.data[..len].to_vec(),
        };
        (sent, f.channel)
    }

    /// A frame the Rust driver received, with its channel (0 A, 1 B).
    pub fn from_rust(f: &Frame) -> (Sent, u8) {
        let sent = Sent {
            id: f.raw_id(),
            ext: f.is_extended(),
            rtr: f.is_remote_frame(),
            dlc: f.dlc_code(),
            data: f.data().to_vec(),
        };
        (sent, u8::from(f.channel() == Channel::B))
    }
}

/// Sends `frames` through `send` (false: queue full, try again later) and
/// collects what the receiver's interrupt handler `isr` drains whenever node
/// `rx_node`'s `irq` is high, until every frame arrived and `settle_bits`
/// more bit times passed (a duplicate would show up then), or `budget_bits`
/// bit times ran out. `at_clock` runs once per bus clock with the number of
/// frames received so far (to inject faults). Returns the frames with their
/// channel, in arrival order.
pub fn exchange(
    bus: &Rc<RefCell<DualBus>>,
    rx_node: usize,
    frames: &[Sent],
    mut send: impl FnMut(&Sent) -> bool,
    mut isr: impl FnMut() -> Vec<(Sent, u8)>,
    mut at_clock: impl FnMut(&mut DualBus, usize),
    budget: Budget,
) -> Vec<(Sent, u8)> {
    let Budget {
        settle_bits,
        budget_bits,
    } = budget;
    let start = bus.borrow().clock();
    let mut queued = 0;
    let mut got = Vec::new();
    let mut done_at = None;
    loop {
        let now = bus.borrow().clock() - start;
        if now > budget_bits * BIT {
            break;
        }
        if queued < frames.len() && send(&frames[queued]) {
            queued += 1;
        }
        {
            let mut b = bus.borrow_mut();
            b.step();
            at_clock(&mut b, got.len());
        }
        if bus.borrow().irq(rx_node) {
            got.extend(isr());
        }
        if got.len() >= frames.len() && queued == frames.len() {
            let t = *done_at.get_or_insert(now);
            if now - t > settle_bits * BIT {
                break;
            }
        }
    }
    // The handler once more: anything left in the FIFO counts too.
    got.extend(isr());
    got
}

/// How long [`exchange`] runs: `settle_bits` after the last expected frame
/// arrived, `budget_bits` at most in all.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    /// Bit times to wait for duplicates after every frame arrived.
    pub settle_bits: u64,
    /// Bit times at most.
    pub budget_bits: u64,
}

/// Bit times for one frame with margin (at most 135 bits with stuffing, plus
/// intermission), used for budgets.
pub const FRAME_BITS: u64 = 160;

/// Frame k goes to queue k % 2 (0 = A, 1 = B) in normal mode.
pub fn queue_of(k: usize) -> u32 {
    (k % 2) as u32
}

/// Queues frames through the C driver (`drcc_send`, frame k to `queue_of(k)`);
/// false while the queue is full (DRCC_E_FULL).
pub fn c_send(c: &mut CDriver) -> impl FnMut(&Sent) -> bool + '_ {
    let mut k = 0;
    move |f| {
        let rc = c.send(&f.to_c(), queue_of(k));
        assert!(rc == 0 || rc == -5, "drcc_send: {rc}");
        if rc == 0 {
            k += 1;
        }
        rc == 0
    }
}

/// Queues frames through the Rust driver (`Drcc::send`, frame k to
/// `queue_of(k)`); false while the queue is full.
pub fn rust_send(d: &mut Drcc<Regs>) -> impl FnMut(&Sent) -> bool + '_ {
    let mut k = 0;
    move |f| {
        let q = if queue_of(k) == 1 {
            Channel::B
        } else {
            Channel::A
        };
        match d.send(&f.to_rust(), q) {
            Ok(()) => {
                k += 1;
                true
            }
            Err(Error::Full) => false,
            Err(e) => panic!("send: {e:?}"),
        }
    }
}

/// The C driver's interrupt handler (`drcc_isr`, a 4-frame buffer, called
/// again while it reports more).
pub fn c_isr(c: &mut CDriver) -> impl FnMut() -> Vec<(Sent, u8)> + '_ {
    move || {
        let mut buf = [CFrame::default(); 4];
        let mut out = Vec::new();
        loop {
            let r = c.isr(&mut buf);
            out.extend(buf[..r.frames].iter().map(Sent::from_c));
            if r.more == 0 {
                return out;
            }
        }
    }
}

/// The Rust driver's interrupt handler (`Drcc::isr`, a 4-frame buffer).
pub fn rust_isr(d: &mut Drcc<Regs>) -> impl FnMut() -> Vec<(Sent, u8)> + '_ {
    move || {
        let mut buf = [Frame::data_frame(StandardId::ZERO, &[]).unwrap(); 4];
        let mut out = Vec::new();
        loop {
            let r = d.isr(&mut buf);
            out.extend(buf[..r.frames].iter().map(Sent::from_rust));
            if !r.more {
                return out;
            }
        }
    }
}

/// Registers where `ID` reads "DRCC", `VERSION` reads `version`, `SIZES`
/// the default top's, everything else 0; writes are recorded. For the
/// version rules of the drivers, without a bus.
pub struct Fake {
    pub version: u32,
    pub writes: Vec<(u32, u32)>,
}

impl Registers for Fake {
    fn read32(&mut self, offset: u32) -> u32 {
        match offset {
            drcc_driver::regs::ID_OFFSET => drcc_driver::regs::ID_VALUE,
            drcc_driver::regs::VERSION_OFFSET => self.version,
            drcc_driver::regs::SIZES_OFFSET => drcc_driver::regs::SIZES_RESET,
            _ => 0,
        }
    }
    fn write32(&mut self, offset: u32, value: u32) {
        self.writes.push((offset, value));
    }
}
