//! Lock step of the bus tops (`rtl-out/drcc_apb.v`, `rtl-out/drcc_axi.v`):
//! the Verilated RTL against the reference model, the bus front end's model
//! (`model::bus`, bus_contract.md §2, §3) in front of the DRCC model, every
//! clock, on random bus traffic that keeps the bus's rules (APB setup and
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
use verilator_sys::{available, required, unavailable_reason};
use verilator_sys::{DrccApb, DrccApbIn, DrccAxi, DrccAxiIn};

/// Word indices (drcc_contract.md §3).
const CTRL: u8 = 1;
const INT_ENABLE: u8 = 7;
const TX_ID: u8 = 12;
const TX_DATA1: u8 = 15;
const TX_CMD: u8 = 16;
const RX_CMD: u8 = 21;

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
    if available() {
        return true;
    }
    assert!(
        !required(),
        "the Verilated bus tops are required in CI: {:?}",
        unavailable_reason()
    );
    eprintln!("SKIPPED: {:?}", unavailable_reason());
    false
}

/// One random register access: (write, byte address, data, strobes). Mostly
/// the frame to send and its push, reads anywhere, sometimes any word.
fn random_access(rng: &mut Rng) -> (bool, u8, u32, u8) {
    let strb = if rng.percent(25) {
        rng.below(16) as u8
    } else {
        0xF
    };
    match rng.below(10) {
        0..=2 => (
            true,
            4 * (TX_ID + rng.below(4) as u8),
            rng.next() as u32,
            strb,
        ),
        3 => (true, 4 * TX_CMD, 1, 0xF),
        4 => (true, 4 * RX_CMD, 1, strb),
        5 => (
            true,
            4 * rng.below(64) as u8 + rng.below(4) as u8,
            rng.next() as u32,
            strb,
        ),
        _ => (false, 4 * rng.below(40) as u8, 0, 0xF),
    }
}

/// The setup every run starts with: interrupts on, leave reset mode in
/// normal mode (the reset configuration otherwise), stage a frame.
const SETUP: [(u8, u32); 5] = [
    (INT_ENABLE, 0x3FF),
    (CTRL, 0x104),
    (TX_ID, 0x123),
    (TX_DATA1, 0xA5A5_5A5A),
    (TX_CMD, 1),
];

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

fn run_apb(seed: u64, clocks: u64) -> (u64, u64) {
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let mut rtl = DrccApb::new().expect("model available");
    let mut model = DrccModel::new();
    let bridge = ApbBridge;
    let mut bus = ApbIn::default();
    let mut out = ApbOut::default();
    // the outputs the master saw in the clock of `bus` (before its edge)
    let mut seen = ApbOut::default();
    let mut tx = (true, true);
    let mut setup = SETUP.iter();
    let (mut transfers, mut errors) = (0, 0);
    for clock in 0..clocks {
        let rst = clock < 4 || rng.below(40_000) == 0;
        // the master: an access phase ends at the edge where pready is 1
        if bus.psel && bus.penable && seen.pready {
            transfers += 1;
            errors += seen.pslverr as u64;
            bus = ApbIn::default();
        } else if bus.psel {
            bus.penable = true;
        } else if !rst && rng.percent(30) {
            let (write, paddr, pwdata, pstrb) = match setup.next() {
                Some(&(adr, dat)) => (true, 4 * adr, dat, 0xF),
                None => random_access(&mut rng),
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
        let o = model.step(&core_in(rst, &pin, tx));
        seen = out;
        out = bridge.outputs(&port_out(&o));
        let r = rtl.step(&DrccApbIn {
            rst: rst as u8,
            s_apb_psel: bus.psel as u8,
            s_apb_penable: bus.penable as u8,
            s_apb_pwrite: bus.pwrite as u8,
            s_apb_paddr: bus.paddr,
            s_apb_pwdata: bus.pwdata,
            s_apb_pstrb: bus.pstrb,
            chan_a_rx: tx.0 as u8,
            chan_b_rx: tx.1 as u8,
        });
        let want = (
            out.prdata,
            out.pready,
            out.pslverr,
            o.irq,
            o.chan_a_tx,
            o.chan_b_tx,
        );
        let got = (
            r.s_apb_prdata,
            r.s_apb_pready != 0,
            r.s_apb_pslverr != 0,
            r.irq != 0,
            r.chan_a_tx != 0,
            r.chan_b_tx != 0,
        );
        assert_eq!(
            got, want,
            "drcc_apb seed {seed} clock {clock}: (prdata, pready, pslverr, irq, tx a, tx b) \
             RTL vs model, bus in {bus:?}"
        );
        tx = (o.chan_a_tx, o.chan_b_tx);
    }
    (transfers, errors)
}

/// The AXI master's three request channels and its response readiness.
#[derive(Default)]
struct AxiMaster {
    aw: Option<u8>,
    w: Option<(u32, u8)>,
    ar: Option<u8>,
}

fn run_axi(seed: u64, clocks: u64) -> (u64, u64) {
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let mut rtl = DrccAxi::new().expect("model available");
    let mut model = DrccModel::new();
    let mut bridge = AxiLiteBridge::default();
    let mut m = AxiMaster::default();
    let mut out = AxiOut::default();
    // the outputs the master saw in the clock of `bus` (before its edge)
    let mut seen = AxiOut::default();
    let mut bus = AxiIn::default();
    let mut port_before = PortOut::default();
    let mut tx = (true, true);
    let mut setup = SETUP.iter();
    let (mut responses, mut errors) = (0, 0);
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
            responses += 1;
        }
        if bus.bready && seen.bvalid && seen.bresp == 2 {
            errors += 1;
        }
        if rst {
            m = AxiMaster::default();
        } else if m.aw.is_none() && m.w.is_none() && rng.percent(20) {
            let (write, addr, data, strb) = match setup.next() {
                Some(&(adr, dat)) => (true, 4 * adr, dat, 0xF),
                None => random_access(&mut rng),
            };
            if write {
                m.aw = Some(addr);
                m.w = Some((data, strb));
            } else if m.ar.is_none() {
                m.ar = Some(addr);
            }
        }
        // AW and W apart sometimes: hold one back a few clocks
        let hold_w = rng.percent(30);
        bus = AxiIn {
            awaddr: m.aw.unwrap_or(rng.next() as u8),
            awvalid: m.aw.is_some(),
            wdata: m.w.map_or(rng.next() as u32, |w| w.0),
            wstrb: m.w.map_or(rng.below(16) as u8, |w| w.1),
            wvalid: m.w.is_some() && !hold_w,
            bready: rng.percent(70),
            araddr: m.ar.unwrap_or(rng.next() as u8),
            arvalid: m.ar.is_some(),
            rready: rng.percent(70),
        };
        let pin = bridge.port_in();
        let o = model.step(&core_in(rst, &pin, tx));
        if rst {
            bridge.reset();
        } else {
            bridge.edge(&bus, &port_before);
        }
        port_before = port_out(&o);
        seen = out;
        out = bridge.outputs();
        let r = rtl.step(&DrccAxiIn {
            rst: rst as u8,
            s_axi_awaddr: bus.awaddr,
            s_axi_awvalid: bus.awvalid as u8,
            s_axi_wdata: bus.wdata,
            s_axi_wstrb: bus.wstrb,
            s_axi_wvalid: bus.wvalid as u8,
            s_axi_bready: bus.bready as u8,
            s_axi_araddr: bus.araddr,
            s_axi_arvalid: bus.arvalid as u8,
            s_axi_rready: bus.rready as u8,
            chan_a_rx: tx.0 as u8,
            chan_b_rx: tx.1 as u8,
        });
        let got = AxiOut {
            awready: r.s_axi_awready != 0,
            wready: r.s_axi_wready != 0,
            bresp: r.s_axi_bresp,
            bvalid: r.s_axi_bvalid != 0,
            arready: r.s_axi_arready != 0,
            rdata: r.s_axi_rdata,
            rresp: r.s_axi_rresp,
            rvalid: r.s_axi_rvalid != 0,
        };
        assert_eq!(
            (got, r.irq != 0, r.chan_a_tx != 0, r.chan_b_tx != 0),
            (out, o.irq, o.chan_a_tx, o.chan_b_tx),
            "drcc_axi seed {seed} clock {clock}: (bus, irq, tx a, tx b) RTL vs model, bus in {bus:?}"
        );
        tx = (o.chan_a_tx, o.chan_b_tx);
    }
    (responses, errors)
}

#[test]
fn drcc_apb_in_lock_step_with_the_model() {
    if !verilator_present() {
        return;
    }
    for seed in 0..4 {
        let (transfers, errors) = run_apb(0xA9B0_0000 + seed, 60_000);
        eprintln!("drcc_apb seed {seed}: {transfers} transfers, {errors} PSLVERR");
        // the traffic did what it is for: transfers, and refused ones among them
        assert!(
            transfers > 1_000 && errors > 10,
            "seed {seed}: {transfers}, {errors}"
        );
    }
}

#[test]
fn drcc_axi_in_lock_step_with_the_model() {
    if !verilator_present() {
        return;
    }
    for seed in 0..4 {
        let (responses, errors) = run_axi(0xA41_0000 + seed, 60_000);
        eprintln!("drcc_axi seed {seed}: {responses} responses, {errors} SLVERR");
        assert!(
            responses > 1_000 && errors > 10,
            "seed {seed}: {responses}, {errors}"
        );
    }
}
