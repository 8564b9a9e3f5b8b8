//! Lock step of the bus tops (`rtl-out/drcc_apb.v`, `rtl-out/drcc_axi.v`, and
//! the SJA1000 view's `rtl-out/drcc_pelican_apb.v`, `rtl-out/drcc_pelican_axi.v`):
//! the Verilated RTL against the reference model, the bus front end's model
//! (`model::bus`, bus_contract.md §2, §3) in front of the DRCC model or the
//! view's model (pelican_contract.md), every clock, on random bus traffic that keeps the bus's rules (APB setup and
//! access phases; AXI4-Lite valids held until ready, the three request
//! channels independent, random `bready` / `rready`), with random byte
//! strobes, refused accesses, frames pushed and sent, and resets. Each node
//! hears its own lines (a node alone on its bus: no ACK, so error frames and
//! counters too). The expected values are the model's, never the RTL's.
//! Without Verilator it skips, except in CI.

use drcc_cosim::engine::drcc::{DrccInputs, DrccOutputs};
use drcc_cosim::model::bus::{
    ApbBridge, ApbIn, ApbOut, AxiIn, AxiLiteBridge, AxiOut, PortIn, PortOut,
};
use drcc_cosim::model::drcc::DrccModel;
use drcc_cosim::model::pelican::{PelicanInputs, PelicanModel, PelicanParams};
use verilator_sys::unavailable_reason;
use verilator_sys::{DrccApb, DrccApbIn, DrccAxi, DrccAxiIn};
use verilator_sys::{DrccPelicanApb, DrccPelicanApbIn, DrccPelicanAxi, DrccPelicanAxiIn};

/// Word indices (drcc_contract.md §3).
const CTRL: u16 = 1;
const INT_ENABLE: u16 = 7;
const TX_ID: u16 = 12;
const TX_DATA1: u16 = 15;
const TX_CMD: u16 = 16;
const RX_CMD: u16 = 21;

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
}

fn verilator_present() -> bool {
    let built = match unavailable_reason() {
        None => Ok(()),
        Some(why) => Err(why),
    };
    drcc_tools::verilated("bus tops", built).is_some()
}

/// One random register access of the native map: (write, byte address, data,
/// strobes). Mostly the frame to send and its push, reads anywhere, sometimes
/// any word.
fn native_access(rng: &mut Rng) -> (bool, u16, u32, u8) {
    let strb = if rng.percent(25) {
        rng.below(16) as u8
    } else {
        0xF
    };
    match rng.below(10) {
        0..=2 => (
            true,
            4 * (TX_ID + rng.below(4) as u16),
            rng.next() as u32,
            strb,
        ),
        3 => (true, 4 * TX_CMD, 1, 0xF),
        4 => (true, 4 * RX_CMD, 1, strb),
        5 => (
            true,
            4 * rng.below(64) as u16 + rng.below(4) as u16,
            rng.next() as u32,
            strb,
        ),
        _ => (false, 4 * rng.below(40) as u16, 0, 0xF),
    }
}

/// One random access of the SJA1000 view at stride 4 (register `r` at byte
/// `4r`): the TX buffer and the commands mostly, any register sometimes, with
/// byte or word strobes and refused ones (lane 0 missing), reads anywhere.
fn pelican_access(rng: &mut Rng) -> (bool, u16, u32, u8) {
    let strb = match rng.below(8) {
        0 => rng.below(16) as u8,
        1 => 0xF,
        _ => 0x1,
    };
    let low = rng.below(4) as u16; // paddr[1:0] are ignored
    match rng.below(10) {
        // the TX window, then TR (sometimes with AT or SRR)
        0..=2 => (
            true,
            4 * (16 + rng.below(13) as u16) + low,
            rng.next() as u32,
            strb,
        ),
        3 => (
            true,
            4 + low,
            [0x01, 0x01, 0x03, 0x10, 0x04][rng.below(5) as usize],
            0x1,
        ),
        // MOD: reset and back, listen-only, self test
        4 if rng.percent(30) => (false, 0, 0, 0),
        4 => (
            true,
            0,
            [0x00, 0x01, 0x00, 0x02, 0x04][rng.below(5) as usize],
            0x1,
        ),
        5 => (
            true,
            4 * rng.below(128) as u16 + low,
            rng.next() as u32,
            strb,
        ),
        _ => (false, 4 * rng.below(128) as u16 + low, 0, 0xF),
    }
}

/// What a run gets before its random traffic: (byte address, data) writes.
type Setup = &'static [(u16, u32)];

/// The native map's start: interrupts on, leave reset mode in normal mode (the
/// reset configuration otherwise), stage a frame.
const NATIVE_SETUP: Setup = &[
    (4 * INT_ENABLE, 0x3FF),
    (4 * CTRL, 0x104),
    (4 * TX_ID, 0x123),
    (4 * TX_DATA1, 0xA5A5_5A5A),
    (4 * TX_CMD, 1),
];

/// The SJA1000 view's start as Linux's driver makes it (register `r` at `4r`):
/// reset mode, CDR, the fastest bit timing (BTR0 0, BTR1 0x14), the filter open,
/// every interrupt on, operating mode, a standard frame and TR.
const PELICAN_SETUP: Setup = &[
    (0, 0x01),
    (4 * 31, 0xC0),
    (4 * 6, 0x00),
    (4 * 7, 0x14),
    (4 * 20, 0xFF),
    (4 * 21, 0xFF),
    (4 * 22, 0xFF),
    (4 * 23, 0xFF),
    (4 * 4, 0xFF),
    (0, 0x00),
    (4 * 16, 0x02),
    (4 * 17, 0x24),
    (4 * 18, 0x60),
    (4 * 19, 0x5A),
    (4 * 20, 0xA5),
    (4, 0x01),
];

/// The register block behind a front end's port, as its model: one clock with
/// the port's inputs and the CAN lines; the port's answer, `irq` and the pins.
trait Behind {
    fn step(&mut self, rst: bool, pin: &PortIn, rx: (bool, bool)) -> (PortOut, bool, bool, bool);
}

impl Behind for DrccModel {
    fn step(&mut self, rst: bool, pin: &PortIn, rx: (bool, bool)) -> (PortOut, bool, bool, bool) {
        let o = DrccModel::step(self, &core_in(rst, pin, rx));
        (port_out(&o), o.irq, o.chan_a_tx, o.chan_b_tx)
    }
}

impl Behind for PelicanModel {
    fn step(&mut self, rst: bool, pin: &PortIn, rx: (bool, bool)) -> (PortOut, bool, bool, bool) {
        let o = PelicanModel::step(
            self,
            &PelicanInputs {
                rst,
                cyc: pin.cyc,
                stb: pin.cyc,
                we: pin.we,
                adr: pin.adr,
                dat: pin.dat,
                sel: pin.sel,
                chan_a_rx: rx.0,
                chan_b_rx: rx.1,
            },
        );
        let port = PortOut {
            ack: o.ack,
            err: o.err,
            dat: o.dat,
        };
        (port, o.irq, o.chan_a_tx, o.chan_b_tx)
    }
}

/// A Verilated APB top, one clock: the APB outputs, `irq` and the pins.
trait ApbRtl {
    fn step(&mut self, rst: bool, bus: &ApbIn, rx: (bool, bool)) -> (ApbOut, bool, bool, bool);
}

macro_rules! apb_rtl {
    ($top:ty, $input:ident, $addr:ty) => {
        impl ApbRtl for $top {
            fn step(
                &mut self,
                rst: bool,
                bus: &ApbIn,
                rx: (bool, bool),
            ) -> (ApbOut, bool, bool, bool) {
                let r = <$top>::step(
                    self,
                    &$input {
                        rst: rst as u8,
                        s_apb_psel: bus.psel as u8,
                        s_apb_penable: bus.penable as u8,
                        s_apb_pwrite: bus.pwrite as u8,
                        s_apb_paddr: bus.paddr as $addr,
                        s_apb_pwdata: bus.pwdata,
                        s_apb_pstrb: bus.pstrb,
                        chan_a_rx: rx.0 as u8,
                        chan_b_rx: rx.1 as u8,
                    },
                );
                let out = ApbOut {
                    prdata: r.s_apb_prdata,
                    pready: r.s_apb_pready != 0,
                    pslverr: r.s_apb_pslverr != 0,
                };
                (out, r.irq != 0, r.chan_a_tx != 0, r.chan_b_tx != 0)
            }
        }
    };
}
apb_rtl!(DrccApb, DrccApbIn, u8);
apb_rtl!(DrccPelicanApb, DrccPelicanApbIn, u16);

/// A Verilated AXI4-Lite top, one clock: the AXI outputs, `irq` and the pins.
trait AxiRtl {
    fn step(&mut self, rst: bool, bus: &AxiIn, rx: (bool, bool)) -> (AxiOut, bool, bool, bool);
}

macro_rules! axi_rtl {
    ($top:ty, $input:ident, $addr:ty) => {
        impl AxiRtl for $top {
            fn step(
                &mut self,
                rst: bool,
                bus: &AxiIn,
                rx: (bool, bool),
            ) -> (AxiOut, bool, bool, bool) {
                let r = <$top>::step(
                    self,
                    &$input {
                        rst: rst as u8,
                        s_axi_awaddr: bus.awaddr as $addr,
                        s_axi_awvalid: bus.awvalid as u8,
                        s_axi_wdata: bus.wdata,
                        s_axi_wstrb: bus.wstrb,
                        s_axi_wvalid: bus.wvalid as u8,
                        s_axi_bready: bus.bready as u8,
                        s_axi_araddr: bus.araddr as $addr,
                        s_axi_arvalid: bus.arvalid as u8,
                        s_axi_rready: bus.rready as u8,
                        chan_a_rx: rx.0 as u8,
                        chan_b_rx: rx.1 as u8,
                    },
                );
                let out = AxiOut {
                    awready: r.s_axi_awready != 0,
                    wready: r.s_axi_wready != 0,
                    bresp: r.s_axi_bresp,
                    bvalid: r.s_axi_bvalid != 0,
                    arready: r.s_axi_arready != 0,
                    rdata: r.s_axi_rdata,
                    rresp: r.s_axi_rresp,
                    rvalid: r.s_axi_rvalid != 0,
                };
                (out, r.irq != 0, r.chan_a_tx != 0, r.chan_b_tx != 0)
            }
        }
    };
}
axi_rtl!(DrccAxi, DrccAxiIn, u8);
axi_rtl!(DrccPelicanAxi, DrccPelicanAxiIn, u16);

/// What a run did: completed transfers (APB) or responses (AXI), refused ones
/// among them, clocks with a CAN pin dominant, clocks with `irq` high.
#[derive(Debug, Default)]
struct Stats {
    done: u64,
    refused: u64,
    dominant: u64,
    irq: u64,
}

impl Stats {
    /// The traffic did what it is for: transfers, refused ones among them, the
    /// CAN pins driven and the interrupt raised.
    fn check(&self, name: &str, seed: u64) {
        eprintln!("{name} seed {seed}: {self:?}");
        assert!(
            self.done > 1_000 && self.refused > 10 && self.dominant > 100 && self.irq > 100,
            "{name} seed {seed}: {self:?}"
        );
    }
}

/// One top on one bus: its name, the traffic it gets, its model and its RTL.
struct Run<M, R> {
    name: &'static str,
    setup: Setup,
    access: fn(&mut Rng) -> (bool, u16, u32, u8),
    model: M,
    rtl: R,
}

/// The DRCC model's inputs for a register-port request.
fn core_in(rst: bool, pin: &PortIn, rx: (bool, bool)) -> DrccInputs {
    DrccInputs {
        rst,
        wb_cyc: pin.cyc,
        wb_stb: pin.cyc,
        wb_we: pin.we,
        wb_adr: pin.adr,
        wb_dat_w: pin.dat,
        wb_sel: pin.sel,
        chan_a_rx: rx.0,
        chan_b_rx: rx.1,
    }
}

fn port_out(o: &DrccOutputs) -> PortOut {
    PortOut {
        ack: o.wb_ack,
        err: o.wb_err,
        dat: o.wb_dat_r,
    }
}

fn run_apb<M: Behind, R: ApbRtl>(run: &mut Run<M, R>, seed: u64, clocks: u64) -> Stats {
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let bridge = ApbBridge;
    let mut bus = ApbIn::default();
    let mut out = ApbOut::default();
    // the outputs the master saw in the clock of `bus` (before its edge)
    let mut seen = ApbOut::default();
    let mut tx = (true, true);
    let mut setup = run.setup.iter();
    let mut stats = Stats::default();
    for clock in 0..clocks {
        let rst = clock < 4 || rng.below(40_000) == 0;
        // the master: an access phase ends at the edge where pready is 1
        if bus.psel && bus.penable && seen.pready {
            stats.done += 1;
            stats.refused += seen.pslverr as u64;
            bus = ApbIn::default();
        } else if bus.psel {
            bus.penable = true;
        } else if !rst && rng.percent(30) {
            let (write, paddr, pwdata, pstrb) = match setup.next() {
                Some(&(adr, dat)) => (true, adr, dat, 0xF),
                None => (run.access)(&mut rng),
            };
            bus = ApbIn {
                psel: true,
                penable: false,
                pwrite: write,
                paddr,
                pwdata,
                pstrb,
            };
        }
        let pin = bridge.port_in(&bus);
        let (port, irq, tx_a, tx_b) = run.model.step(rst, &pin, tx);
        seen = out;
        out = bridge.outputs(&port);
        let got = run.rtl.step(rst, &bus, tx);
        assert_eq!(
            got,
            (out, irq, tx_a, tx_b),
            "{} seed {seed} clock {clock}: (bus, irq, tx a, tx b) RTL vs model, bus in {bus:?}",
            run.name
        );
        tx = (tx_a, tx_b);
        stats.dominant += !(tx_a && tx_b) as u64;
        stats.irq += irq as u64;
    }
    stats
}

/// The AXI master's three request channels and its response readiness.
#[derive(Default)]
struct AxiMaster {
    aw: Option<u16>,
    w: Option<(u32, u8)>,
    ar: Option<u16>,
}

fn run_axi<M: Behind, R: AxiRtl>(run: &mut Run<M, R>, seed: u64, clocks: u64) -> Stats {
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let mut bridge = AxiLiteBridge::default();
    let mut m = AxiMaster::default();
    let mut out = AxiOut::default();
    // the outputs the master saw in the clock of `bus` (before its edge)
    let mut seen = AxiOut::default();
    let mut bus = AxiIn::default();
    let mut port_before = PortOut::default();
    let mut tx = (true, true);
    let mut setup = run.setup.iter();
    let mut stats = Stats::default();
    for clock in 0..clocks {
        let rst = clock < 4 || rng.below(40_000) == 0;
        // handshakes at the last edge: valid and ready before it
        if bus.awvalid && seen.awready {
            m.aw = None;
        }
        if bus.wvalid && seen.wready {
            m.w = None;
        }
        if bus.arvalid && seen.arready {
            m.ar = None;
        }
        if (bus.bready && seen.bvalid) || (bus.rready && seen.rvalid) {
            stats.done += 1;
        }
        if bus.bready && seen.bvalid && seen.bresp == 2 {
            stats.refused += 1;
        }
        if rst {
            m = AxiMaster::default();
        } else if m.aw.is_none() && m.w.is_none() && rng.percent(20) {
            let (write, addr, data, strb) = match setup.next() {
                Some(&(adr, dat)) => (true, adr, dat, 0xF),
                None => (run.access)(&mut rng),
            };
            if write {
                m.aw = Some(addr);
                m.w = Some((data, strb));
            } else if m.ar.is_none() {
                m.ar = Some(addr);
            }
        }
        // AW and W apart sometimes: hold one back a few clocks; the addresses
        // of idle channels are junk of the port's width
        let hold_w = rng.percent(30);
        let junk = rng.next();
        bus = AxiIn {
            awaddr: m.aw.unwrap_or(junk as u16 & 0xFF),
            awvalid: m.aw.is_some(),
            wdata: m.w.map_or(rng.next() as u32, |w| w.0),
            wstrb: m.w.map_or(rng.below(16) as u8, |w| w.1),
            wvalid: m.w.is_some() && !hold_w,
            bready: rng.percent(70),
            araddr: m.ar.unwrap_or((junk >> 16) as u16 & 0xFF),
            arvalid: m.ar.is_some(),
            rready: rng.percent(70),
        };
        let pin = bridge.port_in();
        let (port, irq, tx_a, tx_b) = run.model.step(rst, &pin, tx);
        if rst {
            bridge.reset();
        } else {
            bridge.edge(&bus, &port_before);
        }
        port_before = port;
        seen = out;
        out = bridge.outputs();
        let got = run.rtl.step(rst, &bus, tx);
        assert_eq!(
            got,
            (out, irq, tx_a, tx_b),
            "{} seed {seed} clock {clock}: (bus, irq, tx a, tx b) RTL vs model, bus in {bus:?}",
            run.name
        );
        tx = (tx_a, tx_b);
        stats.dominant += !(tx_a && tx_b) as u64;
        stats.irq += irq as u64;
    }
    stats
}

#[test]
fn drcc_apb_in_lock_step_with_the_model() {
    if !verilator_present() {
        return;
    }
    for seed in 0..4 {
        let mut run = Run {
            name: "drcc_apb",
            setup: NATIVE_SETUP,
            access: native_access,
            model: DrccModel::new(),
            rtl: DrccApb::new().expect("model available"),
        };
        run_apb(&mut run, 0xA9B0_0000 + seed, 60_000).check(run.name, seed);
    }
}

#[test]
fn drcc_axi_in_lock_step_with_the_model() {
    if !verilator_present() {
        return;
    }
    for seed in 0..4 {
        let mut run = Run {
            name: "drcc_axi",
            setup: NATIVE_SETUP,
            access: native_access,
            model: DrccModel::new(),
            rtl: DrccAxi::new().expect("model available"),
        };
        run_axi(&mut run, 0xA41_0000 + seed, 60_000).check(run.name, seed);
    }
}

/// The SJA1000 view behind APB at stride 4, the generator's default keys
/// (`rtl-out/drcc_pelican_apb.v`): register 127's byte address needs the ninth
/// address bit, which the traffic uses.
#[test]
fn drcc_pelican_apb_in_lock_step_with_the_model() {
    if !verilator_present() {
        return;
    }
    for seed in 0..2 {
        let mut run = Run {
            name: "drcc_pelican_apb",
            setup: PELICAN_SETUP,
            access: pelican_access,
            model: PelicanModel::new(PelicanParams::default()),
            rtl: DrccPelicanApb::new().expect("model available"),
        };
        run_apb(&mut run, 0x5A_0000 + seed, 60_000).check(run.name, seed);
    }
}

/// The SJA1000 view behind AXI4-Lite at stride 4 (`rtl-out/drcc_pelican_axi.v`).
#[test]
fn drcc_pelican_axi_in_lock_step_with_the_model() {
    if !verilator_present() {
        return;
    }
    for seed in 0..2 {
        let mut run = Run {
            name: "drcc_pelican_axi",
            setup: PELICAN_SETUP,
            access: pelican_access,
            model: PelicanModel::new(PelicanParams::default()),
            rtl: DrccPelicanAxi::new().expect("model available"),
        };
        run_axi(&mut run, 0x5A41_0000 + seed, 60_000).check(run.name, seed);
    }
}
