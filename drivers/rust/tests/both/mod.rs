//! One interface over both drivers for the tests of the register map 1.2
//! features (identification, filters, timestamps, captures, statistics,
//! per-channel events): every such test runs once with the C driver and once
//! with the Rust driver through [`Node`].
#![allow(dead_code)]

use crate::common::{port, Regs, Sent, BIT, BITRATE, CLOCK_HZ};
use drcc_driver::{
    regs, BitTiming, Capture, ChanStatus, Channel, Channels, Config, Drcc, Error, Filter, Ident,
    Mode, Status,
};
use drcc_driver_sim::{
    CCapture, CChanStatus, CConfig, CDriver, CFrame, CStatus, DualBus, C_MODE_DMR, C_MODE_NORMAL,
    C_MODE_REDUNDANCY,
};
use embedded_can::{Frame as _, StandardId};
use std::cell::RefCell;
use std::rc::Rc;

/// Which driver a node runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// `drivers/c` through the sim glue.
    C,
    /// The `drcc-driver` crate.
    Rust,
}

/// Both drivers, for `for kind in KINDS`.
pub const KINDS: [Kind; 2] = [Kind::C, Kind::Rust];

/// A received frame with its channel (0 A, 1 B) and timestamp.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rx {
    /// The frame.
    pub frame: Sent,
    /// Channel it came from.
    pub channel: u8,
    /// RX_TIME.rx_time.
    pub stamp: u16,
}

/// What one interrupt-handler call returned.
#[derive(Clone, Debug, Default)]
pub struct Isr {
    /// INT_STATUS as read and acknowledged.
    pub events: u32,
    /// CAP_A as the handler read it.
    pub cap_a: Capture,
    /// CAP_B as the handler read it.
    pub cap_b: Capture,
    /// Frames drained.
    pub frames: Vec<Rx>,
}

/// The driver calls the tests use, the same for both drivers.
pub trait Node {
    /// Queues `f` on queue `q` (0 A, 1 B); false while the queue is full.
    fn send(&mut self, f: &Sent, q: u32) -> bool;
    /// One frame from the RX FIFO.
    fn receive(&mut self) -> Option<Rx>;
    /// The interrupt handler (a 4-frame buffer, called again while more).
    fn isr(&mut self) -> Isr;
    /// RX_TIME.now.
    fn now(&mut self) -> u16;
    /// Sets (or disables) a filter: (id, mask, extended).
    fn set_filter(&mut self, index: u8, f: Option<(u32, u32, bool)>);
    /// Disables both filters.
    fn clear_filters(&mut self);
    /// CAP_A, CAP_B.
    fn captures(&mut self) -> (Capture, Capture);
    /// Re-arms the captures.
    fn rearm(&mut self, errors: bool, arb: bool);
    /// INT_STATUS.
    fn irq_status(&mut self) -> u32;
    /// Clears INT_STATUS bits.
    fn irq_ack(&mut self, mask: u32);
    /// STATS_CLR.
    fn clear_stats(&mut self);
    /// STATS0.overruns.
    fn overruns(&mut self) -> u16;
    /// VERSION and SIZES as read at init.
    fn ident(&self) -> Ident;
    /// Transmit abort of `channels`: 0, or the driver's error as the C
    /// driver's result code ([`code`]).
    fn abort(&mut self, channels: Channels) -> i32;
    /// Manual bus-off recovery of `channels`: 0 or the result code.
    fn recover(&mut self, channels: Channels) -> i32;
    /// STATUS, CHAN_x_ERR and AUX_x, decoded.
    fn status(&mut self) -> Status;
}

/// The C driver's result code of a Rust driver error (drcc.h `DRCC_E_*`).
pub fn code(e: Error) -> i32 {
    match e {
        Error::Invalid => -1,
        Error::NoTiming => -2,
        Error::NoDevice => -3,
        Error::Refused => -4,
        Error::Full => -5,
        Error::Empty => -6,
        Error::State => -7,
        Error::Version => -8,
        Error::Unsupported => -9,
    }
}

/// `DRCC_E_STATE`.
pub const E_STATE: i32 = -7;
/// `DRCC_E_UNSUPPORTED`.
pub const E_UNSUPPORTED: i32 = -9;

/// The C driver's channel mask (`DRCC_CH_A` 1, `DRCC_CH_B` 2) of `channels`.
pub fn c_mask(channels: Channels) -> u32 {
    u32::from(channels.contains(Channel::A)) | u32::from(channels.contains(Channel::B)) << 1
}

fn chan_of_c(c: &CChanStatus) -> ChanStatus {
    ChanStatus {
        tec: c.tec,
        rec: c.rec,
        err_state: c.err_state,
        err_warning: c.err_warning != 0,
        aux_state: c.aux_state,
        aux_causes: c.aux_causes,
        fail_cnt: c.fail_cnt,
        failures: c.failures,
        recoveries: c.recoveries,
    }
}

fn status_of_c(s: &CStatus) -> Status {
    Status {
        state: s.state,
        tx_channel: s.tx_channel,
        reset_mode: s.reset_mode != 0,
        tx_going_on: s.tx_going_on != 0,
        txq_a: s.txq_a,
        txq_b: s.txq_b,
        rx_count: s.rx_count,
        a: chan_of_c(&s.a),
        b: chan_of_c(&s.b),
    }
}

fn cap_of(c: CCapture) -> Capture {
    Capture {
        err_valid: c.err_valid != 0,
        err_kind: c.err_kind,
        err_field: c.err_field,
        err_tx: c.err_tx != 0,
        alc_valid: c.alc_valid != 0,
        alc: c.alc,
    }
}

fn rx_of_c(f: &CFrame) -> Rx {
    let (frame, channel) = Sent::from_c(f);
    Rx {
        frame,
        channel,
        stamp: f.timestamp,
    }
}

impl Node for CDriver {
    fn send(&mut self, f: &Sent, q: u32) -> bool {
        let rc = CDriver::send(self, &f.to_c(), q);
        assert!(rc == 0 || rc == -5, "drcc_send: {rc}");
        rc == 0
    }
    fn receive(&mut self) -> Option<Rx> {
        CDriver::receive(self).ok().map(|f| rx_of_c(&f))
    }
    fn isr(&mut self) -> Isr {
        let mut out = Isr::default();
        let mut buf = [CFrame::default(); 4];
        loop {
            let r = CDriver::isr(self, &mut buf);
            if out.events == 0 {
                (out.events, out.cap_a, out.cap_b) = (r.events, cap_of(r.cap_a), cap_of(r.cap_b));
            }
            out.frames.extend(buf[..r.frames].iter().map(rx_of_c));
            if r.more == 0 {
                return out;
            }
        }
    }
    fn now(&mut self) -> u16 {
        CDriver::now(self)
    }
    fn set_filter(&mut self, index: u8, f: Option<(u32, u32, bool)>) {
        assert_eq!(
            CDriver::set_filter(self, index.into(), f),
            0,
            "drcc_set_filter"
        );
    }
    fn clear_filters(&mut self) {
        assert_eq!(CDriver::clear_filters(self), 0, "drcc_clear_filters");
    }
    fn captures(&mut self) -> (Capture, Capture) {
        let (a, b) = CDriver::captures(self);
        (cap_of(a), cap_of(b))
    }
    fn rearm(&mut self, errors: bool, arb: bool) {
        self.rearm_captures(errors, arb)
    }
    fn irq_status(&mut self) -> u32 {
        CDriver::irq_status(self)
    }
    fn irq_ack(&mut self, mask: u32) {
        CDriver::irq_ack(self, mask)
    }
    fn clear_stats(&mut self) {
        CDriver::clear_stats(self)
    }
    fn overruns(&mut self) -> u16 {
        self.stats_all().overruns
    }
    fn ident(&self) -> Ident {
        let i = CDriver::ident(self);
        Ident {
            major: i.major,
            minor: i.minor,
            rx_fifo_depth: i.rx_fifo_depth,
            tx_queue_depth: i.tx_queue_depth,
            history: i.history,
            mailboxes: i.mailboxes,
            dmr: i.dmr != 0,
            star: i.star != 0,
        }
    }
    fn abort(&mut self, channels: Channels) -> i32 {
        CDriver::abort(self, c_mask(channels))
    }
    fn recover(&mut self, channels: Channels) -> i32 {
        CDriver::recover(self, c_mask(channels))
    }
    fn status(&mut self) -> Status {
        status_of_c(&CDriver::status(self))
    }
}

fn rx_of_rust(f: &drcc_driver::Frame) -> Rx {
    let (frame, channel) = Sent::from_rust(f);
    Rx {
        frame,
        channel,
        stamp: f.timestamp(),
    }
}

impl Node for Drcc<Regs> {
    fn send(&mut self, f: &Sent, q: u32) -> bool {
        let ch = if q == 1 { Channel::B } else { Channel::A };
        match Drcc::send(self, &f.to_rust(), ch) {
            Ok(()) => true,
            Err(Error::Full) => false,
            Err(e) => panic!("send: {e:?}"),
        }
    }
    fn receive(&mut self) -> Option<Rx> {
        self.try_receive().map(|f| rx_of_rust(&f))
    }
    fn isr(&mut self) -> Isr {
        let mut out = Isr::default();
        let mut buf = [drcc_driver::Frame::new(StandardId::ZERO, &[]).unwrap(); 4];
        loop {
            let r = Drcc::isr(self, &mut buf);
            // The decoded flags agree with the raw bits of the contract's map.
            let bit = |m: u32| r.events & m != 0;
            assert_eq!(r.bus_error(), bit(regs::INT_STATUS_BUS_ERROR_MASK));
            assert_eq!(r.arb_lost(), bit(regs::INT_STATUS_ARB_LOST_MASK));
            assert_eq!(r.err_warning(), bit(regs::INT_STATUS_ERR_WARNING_MASK));
            assert_eq!(r.tx_done_on(Channel::A), bit(1 << 13));
            assert_eq!(r.tx_done_on(Channel::B), bit(1 << 14));
            assert_eq!(r.tx_failure_on(Channel::A), bit(1 << 15));
            assert_eq!(r.tx_failure_on(Channel::B), bit(1 << 16));
            if out.events == 0 {
                (out.events, out.cap_a, out.cap_b) = (r.events, r.cap_a, r.cap_b);
            }
            out.frames.extend(buf[..r.frames].iter().map(rx_of_rust));
            if !r.more {
                return out;
            }
        }
    }
    fn now(&mut self) -> u16 {
        Drcc::now(self)
    }
    fn set_filter(&mut self, index: u8, f: Option<(u32, u32, bool)>) {
        let filter = f.map(|(id, mask, ext)| {
            if ext {
                Filter::extended(id, mask).expect("29 bits")
            } else {
                Filter::standard(id as u16, mask as u16).expect("11 bits")
            }
        });
        Drcc::set_filter(self, index, filter).expect("set_filter");
    }
    fn clear_filters(&mut self) {
        Drcc::clear_filters(self).expect("clear_filters");
    }
    fn captures(&mut self) -> (Capture, Capture) {
        Drcc::captures(self)
    }
    fn rearm(&mut self, errors: bool, arb: bool) {
        self.rearm_captures(errors, arb)
    }
    fn irq_status(&mut self) -> u32 {
        Drcc::irq_status(self)
    }
    fn irq_ack(&mut self, mask: u32) {
        Drcc::irq_ack(self, mask)
    }
    fn clear_stats(&mut self) {
        Drcc::clear_stats(self)
    }
    fn overruns(&mut self) -> u16 {
        self.stats().overruns
    }
    fn ident(&self) -> Ident {
        Drcc::ident(self)
    }
    fn abort(&mut self, channels: Channels) -> i32 {
        Drcc::abort(self, channels).map_or_else(code, |()| 0)
    }
    fn recover(&mut self, channels: Channels) -> i32 {
        Drcc::recover(self, channels).map_or_else(code, |()| 0)
    }
    fn status(&mut self) -> Status {
        Drcc::status(self)
    }
}

/// Node `n` of `bus` with driver `kind`, configured in normal mode at
/// `BITRATE` from `CLOCK_HZ` with `int_enable`.
pub fn node(bus: &Rc<RefCell<DualBus>>, n: usize, kind: Kind, int_enable: u32) -> Box<dyn Node> {
    match kind {
        Kind::C => {
            let mut c = CDriver::open(port(bus, n)).expect("drcc_init");
            let rc = c.configure(&CConfig {
                clock_hz: CLOCK_HZ,
                bitrate: BITRATE,
                mode: C_MODE_NORMAL,
                policy: regs::CTRL_POLICY_ERROR_PASSIVE,
                k: 1,
                dual_tx: false,
                stall_limit: 0,
                recovery_bits: 1024,
                dedup_window: 1024,
                int_enable,
            });
            assert_eq!(rc, 0, "drcc_configure");
            Box::new(c)
        }
        Kind::Rust => {
            let mut d = Drcc::new(Regs(port(bus, n))).expect("the DRCC answers");
            let cfg = Config {
                timing: BitTiming::calc(CLOCK_HZ, BITRATE).expect("16 clocks a bit"),
                int_enable,
                ..Config::default()
            };
            d.configure(&cfg).expect("configure");
            Box::new(d)
        }
    }
}

/// Node `n` of `bus` with driver `kind`, configured as [`node`] does but
/// with single-shot transmission (a failed attempt drops the frame).
pub fn single_shot_node(bus: &Rc<RefCell<DualBus>>, n: usize, kind: Kind) -> Box<dyn Node> {
    match kind {
        Kind::C => {
            let mut c = CDriver::open(port(bus, n)).expect("drcc_init");
            assert_eq!(c.configure_single_shot(CLOCK_HZ, BITRATE, 0), 0);
            Box::new(c)
        }
        Kind::Rust => {
            let mut d = Drcc::new(Regs(port(bus, n))).expect("the DRCC answers");
            let cfg = Config {
                timing: BitTiming::calc(CLOCK_HZ, BITRATE).expect("16 clocks a bit"),
                single_shot: true,
                ..Config::default()
            };
            d.configure(&cfg).expect("configure");
            Box::new(d)
        }
    }
}

/// Node `n` of `bus` with driver `kind`, configured in `mode` with
/// `busoff_manual` (the rest at the drivers' defaults) at `BITRATE` from
/// `CLOCK_HZ`, with `int_enable`.
pub fn node_with(
    bus: &Rc<RefCell<DualBus>>,
    n: usize,
    kind: Kind,
    mode: Mode,
    busoff_manual: bool,
    int_enable: u32,
) -> Box<dyn Node> {
    match kind {
        Kind::C => {
            let mut c = CDriver::open(port(bus, n)).expect("drcc_init");
            let m = match mode {
                Mode::Normal => C_MODE_NORMAL,
                Mode::Redundancy => C_MODE_REDUNDANCY,
                Mode::Dmr => C_MODE_DMR,
            };
            let rc = c.configure_manual(CLOCK_HZ, BITRATE, m, busoff_manual, int_enable);
            assert_eq!(rc, 0, "drcc_configure");
            Box::new(c)
        }
        Kind::Rust => {
            let mut d = Drcc::new(Regs(port(bus, n))).expect("the DRCC answers");
            let cfg = Config {
                timing: BitTiming::calc(CLOCK_HZ, BITRATE).expect("16 clocks a bit"),
                mode,
                busoff_manual,
                int_enable,
                ..Config::default()
            };
            d.configure(&cfg).expect("configure");
            Box::new(d)
        }
    }
}

/// `bits` bit times of bus clocks.
pub fn wait_bits(bus: &Rc<RefCell<DualBus>>, bits: u64) {
    bus.borrow_mut().tick(bits * BIT);
}

/// Polls `cond` once a bit time, for at most `bits` bit times.
pub fn wait_until(bus: &Rc<RefCell<DualBus>>, bits: u64, mut cond: impl FnMut() -> bool) -> bool {
    for _ in 0..bits {
        if cond() {
            return true;
        }
        wait_bits(bus, 1);
    }
    cond()
}

/// A base data frame.
pub fn std_frame(id: u32, data: &[u8]) -> Sent {
    Sent {
        id,
        ext: false,
        rtr: false,
        dlc: data.len() as u8,
        data: data.to_vec(),
    }
}

/// An extended data frame.
pub fn ext_frame(id: u32, data: &[u8]) -> Sent {
    Sent {
        ext: true,
        ..std_frame(id, data)
    }
}

/// Sends `f` from `node` on queue `q`, retrying (one bit time apart) while
/// the queue is full.
pub fn send_now(bus: &Rc<RefCell<DualBus>>, node: &mut dyn Node, f: &Sent, q: u32) {
    for _ in 0..10_000 {
        if node.send(f, q) {
            return;
        }
        wait_bits(bus, 1);
    }
    panic!("queue {q} stayed full");
}

/// Every frame in `node`'s RX FIFO.
pub fn drain(node: &mut dyn Node) -> Vec<Rx> {
    std::iter::from_fn(|| node.receive()).collect()
}
