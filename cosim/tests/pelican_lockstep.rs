//! The SJA1000 view's top (`drcc_hdl::pelican::top::DrccPelican`,
//! `rtl-out/drcc_pelican.v`) in lock step with the view's reference model
//! (`drcc_cosim::model::pelican`, written from `pelican_contract.md`). Every
//! clock the top's outputs (the Wishbone read data, acknowledge and error, `irq`
//! and the CAN pins) must equal the model's.
//!
//! - The view model's own scenarios (`model_pelican/`, expected values from the
//!   contract and the SJA1000 data sheet) run again with the RTL beside the
//!   model: in rust-hdl's simulator for every generation key they use, and, for
//!   the keys `rtl-out/drcc_pelican.v` is generated with, also Verilated.
//! - The data sheet's conformance tests (`model_pelican/conformance/`), so the
//!   RTL meets them too: on the Verilated top alone, with the keys that only
//!   set `XMODE` and `XK` written there after reset (`Net::keyed`); in rust-hdl's
//!   simulator for other strides and sizes, and without Verilator. The model's
//!   bus-off scenarios (`busoff`: recoveries of 128 x 11 bits) run the same way. (The side-by-side runs against the independent SJA1000
//!   core, `model_pelican/side_by_side.rs`, stay on the model: in rust-hdl's
//!   simulator they would take ten minutes, and the lock step ties the RTL to
//!   the model.)
//! - Random register traffic (`random`): every register read and written with
//!   random bytes and lane patterns, commands, mode and key changes, frames from
//!   the other nodes, line cuts, in lock step on the Verilated top.
//!
//! - A Linux driver's traffic while line A is cut mid-frame (`cut`): every
//!   frame arrives exactly once, both ways.
//!
//! Without Verilator the Verilated half skips, except in CI.

#[path = "model_support/mod.rs"]
mod support;

#[path = "model_pelican/acceptance.rs"]
mod acceptance;
#[path = "model_pelican/busoff.rs"]
mod busoff;
#[path = "model_pelican/conformance/mod.rs"]
mod conformance;
#[path = "model_pelican/drivers.rs"]
mod drivers;
#[path = "model_pelican/harness.rs"]
mod harness;
#[path = "model_pelican/map.rs"]
mod map;

/// Verilator is here, or the test may skip (not in CI).
fn verilator_present() -> bool {
    let built = match verilator_sys::unavailable_reason() {
        None => Ok(()),
        Some(why) => Err(why),
    };
    drcc_tools::verilated("drcc_pelican top", built).is_some()
}

/// The RTL beside the model.
mod shadow {
    use drcc_cosim::engine::pelican::{PelicanRustHdl, PelicanVerilator};
    use drcc_cosim::model::pelican::{PelicanInputs, PelicanModel, PelicanParams};

    /// The rust-hdl top and, for `rtl-out`'s keys, the Verilated one; both
    /// `None` in a cloned `Net`.
    pub struct Shadow {
        hdl: Option<PelicanRustHdl>,
        rtl: Option<PelicanVerilator>,
        clock: u64,
    }

    impl Clone for Shadow {
        fn clone(&self) -> Self {
            Shadow {
                hdl: None,
                rtl: None,
                clock: self.clock,
            }
        }
    }

    impl Shadow {
        pub fn new(p: &PelicanParams) -> Self {
            Self::with(p, true)
        }

        /// `hdl`: run rust-hdl's simulator too (the random traffic runs the
        /// Verilated top alone, for speed).
        pub fn with(p: &PelicanParams, hdl: bool) -> Self {
            let hdl = hdl.then(|| PelicanRustHdl::new(p).unwrap_or_else(|e| panic!("{e}")));
            let rtl = (*p == PelicanVerilator::params() && crate::verilator_present())
                .then(|| PelicanVerilator::new().expect("Verilated drcc_pelican"));
            Shadow { hdl, rtl, clock: 0 }
        }

        /// The top of `Net::keyed` (the conformance and bus-off tests): the
        /// Verilated top alone beside the model, where Verilator is here and `p` has the
        /// stride and the sizes it was generated with (the other keys are
        /// `XMODE` and `XK`, which the harness writes). `None` otherwise: the
        /// test runs on a top generated with `p`, in rust-hdl's simulator.
        pub fn keyed(p: &PelicanParams) -> Option<(PelicanParams, Self)> {
            let g = PelicanVerilator::params();
            (p.stride == g.stride && p.core == g.core && crate::verilator_present())
                .then(|| (g, Self::with(&g, false)))
        }

        /// The Verilated top runs beside the model.
        pub fn verilated(&self) -> bool {
            self.rtl.is_some()
        }

        /// Step the RTL with the model's inputs of this clock and compare.
        pub fn edge(&mut self, i: &PelicanInputs, dut: &PelicanModel) {
            let k = self.clock;
            self.clock += 1;
            let m = dut.outputs();
            let o = self.hdl.as_mut().map(|x| x.step(i));
            if let (Some(o), Some(x)) = (o, self.hdl.as_ref()) {
                if o != m {
                    let (head, count, ready) = x.rx_fifo();
                    eprintln!(
                        "on the mismatch: RTL FIFO head {head:x}, count {count}, rx_ready {ready}; model head {:?}, count {}",
                        dut.core().core_view().head,
                        dut.core().core_view().rx_count
                    );
                }
            }
            if let Some(o) = o {
                assert_eq!(
                    o, m,
                    "rust-hdl drcc_pelican against the model, clock {k}, inputs {i:?}"
                );
            }
            if let Some(r) = self.rtl.as_mut() {
                let o = r.step(i);
                assert_eq!(
                    o, m,
                    "Verilated drcc_pelican against the model, clock {k}, inputs {i:?}"
                );
            }
        }
    }
}

/// A driver's traffic while line A is cut.
#[path = "pelican_lockstep/cut.rs"]
mod cut;

/// Random register traffic on the Verilated top.
#[path = "pelican_lockstep/random.rs"]
mod random;
