//! The `rust-hdl` engine of the hub: the `drcc_hdl::hub::hub::Hub` block in
//! rust-hdl's own simulator, for any supported shape (N node ports 2..=8, M
//! interlinks 1..=4). It runs the Rust description `rtl-out/hub.v` is emitted from,
//! so comparing it with the Verilated RTL checks that the Verilog means what the
//! Rust means.
//!
//! One `step`: with `clk` low, apply the inputs and settle; raise `clk` and settle;
//! read the outputs (inputs change away from the clock edge). The block's shape is
//! a set of const generics, so the engine holds one monomorphised simulator behind
//! a small object-safe trait, picked from (N, M) at construction.

use super::hub::{HubEngine, HubInputs, HubOutputs, HubProbes, MAX_INTERLINKS, MAX_NODE_PORTS};
use super::rusthdl::settle;
use drcc_hdl::hub::hub::Hub;
use rust_hdl::prelude::*;

/// Settling budget per half clock.
const MAX_SETTLE_ITERS: usize = 200;

/// One monomorphised hub simulator.
trait HubSim {
    fn step(&mut self, i: &HubInputs) -> HubOutputs;
}

struct Sim<const N: usize, const M: usize, const P: usize, const H: usize> {
    uut: Box<Hub<N, M, P, H>>,
}

impl<const N: usize, const M: usize, const P: usize, const H: usize> Sim<N, M, P, H> {
    fn new() -> Self {
        let mut uut = Box::<Hub<N, M, P, H>>::default();
        uut.connect_all();
        uut.clk.next = Clock::from(false);
        let mut s = Sim { uut };
        s.settle();
        s
    }

    fn settle(&mut self) {
        settle(self.uut.as_mut(), MAX_SETTLE_ITERS, "hub");
    }
}

impl<const N: usize, const M: usize, const P: usize, const H: usize> HubSim for Sim<N, M, P, H> {
    fn step(&mut self, i: &HubInputs) -> HubOutputs {
        let u = self.uut.as_mut();
        u.clk.next = Clock::from(false);
        u.rst.next = i.rst;
        u.wb_cyc_i.next = i.wb_cyc;
        u.wb_stb_i.next = i.wb_stb;
        u.wb_we_i.next = i.wb_we;
        u.wb_adr_i.next = ((i.wb_adr & 0x3F) as u64).into();
        u.wb_dat_i.next = (i.wb_dat_w as u64).into();
        u.wb_sel_i.next = ((i.wb_sel & 0xF) as u64).into();
        u.uplink.next = ((i.uplink as u64) & ((1u64 << N) - 1)).into();
        u.sublink_in.next = ((i.sublink_in as u64) & ((1u64 << M) - 1)).into();
        self.settle();
        self.uut.clk.next = Clock::from(true);
        self.settle();
        let u = &self.uut;
        HubOutputs {
            wb_ack: u.wb_ack_o.val(),
            wb_err: u.wb_err_o.val(),
            wb_dat_r: u.wb_dat_o.val().to_u64() as u32,
            irq: u.irq.val(),
            downlink: u.downlink.val().to_u64() as u16,
            sublink_out: u.sublink_out.val().to_u64() as u8,
            probes: HubProbes {
                coupled: u.coupled.val(),
                sample_point: u.sample_point.val(),
                trk_state: u.trk_state.val().to_u64() as u8,
                ack_window: u.ack_window.val(),
                decoupled: u.decoupled.val(),
                port_enabled: u.port_enabled.val().to_u64() as u16,
                nrap_phase: u.nrap_phase.val().to_u64() as u8,
                hub_tx: u.hub_tx.val(),
            },
        }
    }
}

/// The hub block in rust-hdl's simulator.
pub struct HubRustHdlEngine {
    sim: Box<dyn HubSim>,
    n: usize,
    m: usize,
}

impl std::fmt::Debug for HubRustHdlEngine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("HubRustHdlEngine")
            .field("n", &self.n)
            .field("m", &self.m)
            .finish_non_exhaustive()
    }
}

macro_rules! pick {
    ($n:expr, $m:expr; $( ($N:literal, $M:literal, $P:literal) ),* $(,)?) => {
        match ($n, $m) {
            $( ($N, $M) => Some(Box::new(Sim::<$N, $M, $P, 0>::new()) as Box<dyn HubSim>), )*
            _ => None,
        }
    };
}

impl HubRustHdlEngine {
    /// A fresh hub with `n` node ports and `m` interlinks, clock low, not yet reset
    /// (drive `rst` for a few steps). Fails, naming the legal ranges, for a shape
    /// the hub does not support.
    pub fn new(n: usize, m: usize) -> Result<Self, String> {
        let sim = pick!(n, m;
            (2, 1, 3), (2, 2, 4), (2, 3, 5), (2, 4, 6),
            (3, 1, 4), (3, 2, 5), (3, 3, 6), (3, 4, 7),
            (4, 1, 5), (4, 2, 6), (4, 3, 7), (4, 4, 8),
            (5, 1, 6), (5, 2, 7), (5, 3, 8), (5, 4, 9),
            (6, 1, 7), (6, 2, 8), (6, 3, 9), (6, 4, 10),
            (7, 1, 8), (7, 2, 9), (7, 3, 10), (7, 4, 11),
            (8, 1, 9), (8, 2, 10), (8, 3, 11), (8, 4, 12),
        )
        .ok_or_else(|| {
            format!(
                "hub shape N = {n}, M = {m} is not supported: N node ports must be \
                 2..={MAX_NODE_PORTS} and M interlinks 1..={MAX_INTERLINKS}"
            )
        })?;
        Ok(HubRustHdlEngine { sim, n, m })
    }
}

impl HubRustHdlEngine {
    /// Hub `hub_id` (0 = A, 1 = B: the identification frame it sends, hub
    /// contract §9.1). Hub B exists in the emitted shape (N = 4, M = 2) only, the
    /// shape of `hub_b.v` and of the star scenarios.
    pub fn new_hub(hub_id: u8, n: usize, m: usize) -> Result<Self, String> {
        match (hub_id, n, m) {
            (0, ..) => Self::new(n, m),
            (_, 4, 2) => Ok(HubRustHdlEngine {
                sim: Box::new(Sim::<4, 2, 6, 1>::new()),
                n,
                m,
            }),
            _ => Err(format!(
                "the rust-hdl engine has hub B (identification frame 0x001) only in the \
                 emitted shape N = 4, M = 2 (asked for N = {n}, M = {m})"
            )),
        }
    }
}

impl HubEngine for HubRustHdlEngine {
    fn name(&self) -> &'static str {
        "rust-hdl"
    }

    fn shape(&self) -> (usize, usize) {
        (self.n, self.m)
    }

    fn step(&mut self, i: &HubInputs) -> HubOutputs {
        self.sim.step(i)
    }
}
