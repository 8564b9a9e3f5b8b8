//! The `rust-hdl` engine of the DRCC tops: the `drcc_hdl::drcc::DrccTop<M>` block
//! (`M` DMR mailboxes: `drcc` 16, `drcc_m0` 0) in
//! rust-hdl's own simulator. It runs the Rust description `rtl-out/drcc.v` is
//! emitted from, so comparing it with the model and the Verilated RTL checks that
//! the Verilog means what the Rust means. Slow (every clock settles the whole
//! netlist in Rust): for register scripts and short runs, not network scenarios.
//!
//! One `step`: with `clk` low, apply the inputs and settle; raise `clk` and settle;
//! read the outputs (inputs change away from the clock edge).

use super::drcc::{DrccEngine, DrccInputs, DrccOutputs, DrccProbes};
use super::rusthdl::{field_code, settle};
use drcc_hdl::config::DrccConfig;
use drcc_hdl::drcc::DrccTop;
use rust_hdl::prelude::*;

/// The DRCC probes of the native top, read after an edge.
macro_rules! drcc_probes {
    ($u:expr) => {{
        let u = $u;
        let b = |s: &Signal<Out, Bit>| s.val();
        DrccProbes {
            state: u.state.val().to_u64() as u8,
            tx_channel: b(&u.tx_channel),
            transmission_ack: b(&u.transmission_ack),
            chan_a_transmission_req: b(&u.chan_a_transmission_req),
            chan_b_transmission_req: b(&u.chan_b_transmission_req),
            tx_success: b(&u.tx_success),
            tx_ok_channel: u.tx_ok_channel.val().to_u64() as u8,
            tx_failure: b(&u.tx_failure),
            tx_failure_channel: u.tx_failure_channel.val().to_u64() as u8,
            tx_going_on: b(&u.tx_going_on),
            chan_a_bsp_tx_err_cnt: u.chan_a_bsp_tx_err_cnt.val().to_u64() as u16,
            chan_a_bsp_node_error_passive: b(&u.chan_a_bsp_node_error_passive),
            chan_b_bsp_tx_err_cnt: u.chan_b_bsp_tx_err_cnt.val().to_u64() as u16,
            chan_b_bsp_node_error_passive: b(&u.chan_b_bsp_node_error_passive),
            aux_a_state: u.aux_a_state.val().to_u64() as u8,
            aux_b_state: u.aux_b_state.val().to_u64() as u8,
            chan_a_sample_point: b(&u.chan_a_sample_point),
            chan_b_sample_point: b(&u.chan_b_sample_point),
            chan_a_field: field_code(&u.chan_a_field.val()),
            chan_b_field: field_code(&u.chan_b_field.val()),
            chan_a_rec: u.chan_a_rec.val().to_u64() as u8,
            chan_b_rec: u.chan_b_rec.val().to_u64() as u8,
            chan_a_err_state: u.chan_a_err_state.val().to_u64() as u8,
            chan_b_err_state: u.chan_b_err_state.val().to_u64() as u8,
            dmr_state: u.dmr_state.val().to_u64() as u8,
            acl: b(&u.acl),
            dcl_tx_fault: b(&u.dcl_tx_fault),
            dcl_rx_fault: b(&u.dcl_rx_fault),
            rcl_tx_fault: b(&u.rcl_tx_fault),
            rcl_rx_fault: b(&u.rcl_rx_fault),
            dmr_tick: b(&u.dmr_tick),
        }
    }};
}

/// Settling budget per half clock.
const MAX_SETTLE_ITERS: usize = 400;

/// The DRCC block with `M` DMR mailboxes in rust-hdl's simulator. Its users
/// get it as a `Box<dyn DrccEngine>` ([`drcc`], [`drcc_m0`], [`with_config`]),
/// so that its simulation and drop glue are compiled here once, not again in
/// every crate or test that owns one (half a minute of `cargo test`'s build
/// each, measured on the testbench suite).
struct DrccCoreRustHdlEngine<const M: usize> {
    uut: Box<DrccTop<M>>,
}

/// The `drcc` top (16 DMR mailboxes) in rust-hdl's simulator, clock low, not
/// yet reset (drive `rst` for a few steps).
pub fn drcc() -> Box<dyn DrccEngine> {
    Box::new(DrccCoreRustHdlEngine::<16>::new())
}

/// The `drcc_m0` top (no DMR mailboxes) in rust-hdl's simulator.
pub fn drcc_m0() -> Box<dyn DrccEngine> {
    Box::new(DrccCoreRustHdlEngine::<0>::new())
}

/// A DRCC generated with the sizes of `cfg` in rust-hdl's simulator: with 16
/// DMR mailboxes when `cfg.mailboxes` is not 0 (the generator's two builds).
pub fn with_config(cfg: &DrccConfig) -> Box<dyn DrccEngine> {
    match cfg.mailboxes {
        0 => Box::new(DrccCoreRustHdlEngine::<0>::with_config(cfg)),
        _ => Box::new(DrccCoreRustHdlEngine::<16>::with_config(cfg)),
    }
}

impl<const M: usize> std::fmt::Debug for DrccCoreRustHdlEngine<M> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DrccRustHdlEngine").finish_non_exhaustive()
    }
}

impl<const M: usize> DrccCoreRustHdlEngine<M> {
    /// A fresh DRCC, clock low, not yet reset (drive `rst` for a few steps).
    pub fn new() -> Self {
        Self::from_block(Box::<DrccTop<M>>::default())
    }

    /// A fresh DRCC generated with the sizes of `cfg` (its `mailboxes` is `M`).
    pub fn with_config(cfg: &DrccConfig) -> Self {
        Self::from_block(Box::new(DrccTop::<M>::with_config(cfg)))
    }

    fn from_block(mut uut: Box<DrccTop<M>>) -> Self {
        uut.connect_all();
        uut.clk.next = Clock::from(false);
        let mut e = DrccCoreRustHdlEngine { uut };
        e.settle();
        e
    }

    fn settle(&mut self) {
        settle(self.uut.as_mut(), MAX_SETTLE_ITERS, "drcc");
    }
}

impl<const M: usize> DrccEngine for DrccCoreRustHdlEngine<M> {
    fn name(&self) -> &'static str {
        "rust-hdl"
    }

    fn step(&mut self, i: &DrccInputs) -> DrccOutputs {
        let u = self.uut.as_mut();
        u.clk.next = Clock::from(false);
        u.rst.next = i.rst;
        u.wb_cyc_i.next = i.wb_cyc;
        u.wb_stb_i.next = i.wb_stb;
        u.wb_we_i.next = i.wb_we;
        u.wb_adr_i.next = ((i.wb_adr & 0x3F) as u64).into();
        u.wb_dat_i.next = (i.wb_dat_w as u64).into();
        u.wb_sel_i.next = ((i.wb_sel & 0xF) as u64).into();
        u.chan_a_rx.next = i.chan_a_rx;
        u.chan_b_rx.next = i.chan_b_rx;
        self.settle();
        self.uut.clk.next = Clock::from(true);
        self.settle();
        let u = &self.uut;
        DrccOutputs {
            wb_ack: u.wb_ack_o.val(),
            wb_err: u.wb_err_o.val(),
            wb_dat_r: u.wb_dat_o.val().to_u64() as u32,
            irq: u.irq.val(),
            chan_a_tx: u.chan_a_tx.val(),
            chan_b_tx: u.chan_b_tx.val(),
            probes: drcc_probes!(u),
        }
    }
}
