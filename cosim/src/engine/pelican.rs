//! The engines of the `host = "pelican"` top (`drcc_hdl::pelican::top::DrccPelican`,
//! `rtl-out/drcc_pelican.v`): rust-hdl's simulator, for any generation keys,
//! and the Verilated RTL of `rtl-out/drcc_pelican.v` (the generator's default
//! keys). Both take the inputs of the view's reference model
//! ([`PelicanInputs`]) and give its outputs ([`PelicanOutputs`]), so a test runs
//! either beside the model clock by clock.
//!
//! One `step`: with `clk` low, apply the inputs and settle; raise `clk` and
//! settle; read the outputs (rust-hdl). The Verilated top makes one rising edge.

use super::rusthdl::settle;
use crate::model::pelican::{PelicanInputs, PelicanOutputs, PelicanParams};
use drcc_hdl::config::DrccConfig;
use drcc_hdl::pelican::top::DrccPelican;
use drcc_hdl::pelican::PelicanKeys;
use rust_hdl::prelude::*;

/// Settling budget per half clock.
const MAX_SETTLE_ITERS: usize = 400;

/// The hdl generation of the model's parameters: the core's sizes and the keys.
pub fn hdl_config(p: &PelicanParams) -> (DrccConfig, PelicanKeys) {
    let c = &p.core;
    let cfg = DrccConfig {
        mailboxes: c.mailboxes,
        rx_fifo_depth: c.rx_fifo_depth as usize,
        tx_queue_depth: c.tx_queue_depth as usize,
        history: c.history as usize,
        dmr: c.dmr,
        star: c.star,
    };
    let keys = PelicanKeys {
        stride: p.stride as usize,
        mode: p.mode,
        policy: p.policy,
        k: p.k,
        dual_tx: p.dual_tx,
        star_on: p.star,
        bom: p.bom,
        report_best: p.report_best,
        dmr: c.dmr,
        star: c.star,
    };
    (cfg, keys)
}

/// The top in rust-hdl's simulator, generated with the model's parameters (0
/// or 16 DMR mailboxes). Neither generic nor holding the top by type: a test
/// that owned a `DrccPelican<M>` would compile the top's simulation and its
/// drop glue for itself (a minute of `cargo test`'s build), so the top is
/// behind [`PelicanSim`], all of whose code is compiled here.
pub struct PelicanRustHdl(Box<dyn PelicanSim>);

/// One clock and the probes, for a top of any mailbox count.
trait PelicanSim {
    fn step(&mut self, i: &PelicanInputs) -> PelicanOutputs;
    fn rx_fifo(&self) -> (u128, u64, bool);
}

impl<const M: usize> PelicanSim for DrccPelican<M> {
    fn step(&mut self, i: &PelicanInputs) -> PelicanOutputs {
        step(self, i)
    }

    fn rx_fifo(&self) -> (u128, u64, bool) {
        let c = &self.core;
        (
            c.rx_head.val().to_u128(),
            c.rx_count.val().to_u64(),
            c.rx_ready.val(),
        )
    }
}

impl PelicanRustHdl {
    /// A top generated with `p`, clock low, not yet reset; refuses a mailbox
    /// count the generator does not take.
    pub fn new(p: &PelicanParams) -> Result<Self, String> {
        Ok(PelicanRustHdl(match p.core.mailboxes {
            0 => top::<0>(p),
            16 => top::<16>(p),
            m => return Err(format!("drcc_pelican: {m} DMR mailboxes; 0 or 16")),
        }))
    }

    /// One clock with `i`.
    pub fn step(&mut self, i: &PelicanInputs) -> PelicanOutputs {
        self.0.step(i)
    }

    /// The core's RX FIFO head word, fill count and `rx_ready`, for a report.
    pub fn rx_fifo(&self) -> (u128, u64, bool) {
        self.0.rx_fifo()
    }
}

/// A top generated with `p` (its `core.mailboxes` is `M`), clock low.
fn top<const M: usize>(p: &PelicanParams) -> Box<dyn PelicanSim> {
    let (cfg, keys) = hdl_config(p);
    let mut uut = Box::new(DrccPelican::<M>::with_config(&cfg, &keys));
    uut.connect_all();
    uut.clk.next = Clock::from(false);
    settle(uut.as_mut(), MAX_SETTLE_ITERS, "drcc_pelican");
    uut
}

/// One clock of `u` with `i`.
fn step<const M: usize>(u: &mut DrccPelican<M>, i: &PelicanInputs) -> PelicanOutputs {
    u.clk.next = Clock::from(false);
    u.rst.next = i.rst;
    u.wb_cyc_i.next = i.cyc;
    u.wb_stb_i.next = i.stb;
    u.wb_we_i.next = i.we;
    u.wb_adr_i.next = (i.adr as u64 & 0x7F).into();
    u.wb_dat_i.next = (i.dat as u64).into();
    u.wb_sel_i.next = (i.sel as u64 & 0xF).into();
    u.chan_a_rx.next = i.chan_a_rx;
    u.chan_b_rx.next = i.chan_b_rx;
    settle(u, MAX_SETTLE_ITERS, "drcc_pelican");
    u.clk.next = Clock::from(true);
    settle(u, MAX_SETTLE_ITERS, "drcc_pelican");
    PelicanOutputs {
        dat: u.wb_dat_o.val().to_u64() as u32,
        ack: u.wb_ack_o.val(),
        err: u.wb_err_o.val(),
        irq: u.irq.val(),
        chan_a_tx: u.chan_a_tx.val(),
        chan_b_tx: u.chan_b_tx.val(),
    }
}

/// The Verilated `rtl-out/drcc_pelican.v`: the generator's default keys
/// (stride 4, redundancy, error-passive, `k = 1`, SJA1000 bus-off) over the
/// default core.
pub struct PelicanVerilator {
    top: verilator_sys::DrccPelican,
}

impl PelicanVerilator {
    /// The parameters `rtl-out/drcc_pelican.v` was generated with.
    pub fn params() -> PelicanParams {
        PelicanParams::default()
    }

    /// A fresh instance, not yet reset; fails with Verilator's reason when this
    /// build has no Verilated model.
    pub fn new() -> Result<Self, String> {
        verilator_sys::DrccPelican::new()
            .map(|top| PelicanVerilator { top })
            .map_err(|e| format!("{e:?}"))
    }

    /// One clock with `i`.
    pub fn step(&mut self, i: &PelicanInputs) -> PelicanOutputs {
        let o = self.top.step(&verilator_sys::DrccPelicanIn {
            rst: i.rst as u8,
            wb_cyc_i: i.cyc as u8,
            wb_stb_i: i.stb as u8,
            wb_we_i: i.we as u8,
            wb_adr_i: i.adr & 0x7F,
            wb_dat_i: i.dat,
            wb_sel_i: i.sel & 0xF,
            chan_a_rx: i.chan_a_rx as u8,
            chan_b_rx: i.chan_b_rx as u8,
        });
        PelicanOutputs {
            dat: o.wb_dat_o,
            ack: o.wb_ack_o != 0,
            err: o.wb_err_o != 0,
            irq: o.irq != 0,
            chan_a_tx: o.chan_a_tx != 0,
            chan_b_tx: o.chan_b_tx != 0,
        }
    }
}
