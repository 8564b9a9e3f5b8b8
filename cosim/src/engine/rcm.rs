//! The REDCAN relay module (RCM, `ring_contract.md` §2) behind one trait, on every
//! engine: `model` (the oracle, `crate::model::rcm`), `rust-hdl` (the block
//! `drcc_hdl::redcan::rcm::Rcm` in rust-hdl's simulator) and `verilator`
//! (`rtl-out/rcm.v`, the sign-off engine).

use super::rusthdl::settle;
use crate::model::rcm::RcmModel;
pub use crate::model::rcm::{RcmInputs, RcmOutputs};
use drcc_hdl::redcan::rcm::Rcm;
use rust_hdl::prelude::*;

/// One RCM, on some engine.
pub trait RcmEngine {
    /// Engine name as the CLI spells it.
    fn name(&self) -> &'static str;
    /// Apply inputs, clock once, return the outputs after the edge.
    fn step(&mut self, inputs: &RcmInputs) -> RcmOutputs;
}

/// The reference model.
#[derive(Clone, Debug, Default)]
pub struct RcmModelEngine {
    model: RcmModel,
}

impl RcmEngine for RcmModelEngine {
    fn name(&self) -> &'static str {
        "model"
    }

    fn step(&mut self, inputs: &RcmInputs) -> RcmOutputs {
        self.model.step(inputs)
    }
}

/// The rust-hdl block in rust-hdl's simulator.
pub struct RcmRustHdlEngine {
    uut: Box<Rcm>,
}

impl Default for RcmRustHdlEngine {
    fn default() -> Self {
        let mut uut = Box::<Rcm>::default();
        uut.connect_all();
        uut.clk.next = Clock::from(false);
        settle(uut.as_mut(), 50, "rcm");
        RcmRustHdlEngine { uut }
    }
}

impl RcmEngine for RcmRustHdlEngine {
    fn name(&self) -> &'static str {
        "rust-hdl"
    }

    fn step(&mut self, i: &RcmInputs) -> RcmOutputs {
        let u = self.uut.as_mut();
        u.clk.next = Clock::from(false);
        u.rst.next = i.rst;
        u.ctl_we.next = i.ctl_we;
        u.ctl.next = ((i.ctl & 3) as u64).into();
        settle(u, 50, "rcm");
        u.clk.next = Clock::from(true);
        settle(u, 50, "rcm");
        RcmOutputs {
            relay: u.relay.val(),
            node_left: u.node_left.val(),
            node_right: u.node_right.val(),
            term_left: u.term_left.val(),
            term_right: u.term_right.val(),
            mode: u.mode.val().index() as u8,
            illegal: u.illegal.val(),
            changes: u.changes.val().index() as u8,
        }
    }
}

/// The Verilated `rtl-out/rcm.v`.
pub struct RcmVerilatorEngine {
    top: verilator_sys::Rcm,
    pin: verilator_sys::RcmIn,
    pout: verilator_sys::RcmOut,
}

impl RcmVerilatorEngine {
    /// A fresh RCM, not yet reset. Fails with an actionable message when this build
    /// has no Verilated model (Verilator missing, or the RTL not generated).
    pub fn new() -> Result<Self, String> {
        Ok(RcmVerilatorEngine {
            top: verilator_sys::Rcm::new().map_err(|e| e.to_string())?,
            pin: Default::default(),
            pout: Default::default(),
        })
    }
}

impl RcmEngine for RcmVerilatorEngine {
    fn name(&self) -> &'static str {
        "verilator"
    }

    fn step(&mut self, i: &RcmInputs) -> RcmOutputs {
        self.pin = verilator_sys::RcmIn {
            rst: i.rst as u8,
            ctl_we: i.ctl_we as u8,
            ctl: i.ctl & 3,
        };
        self.top.step_into(&self.pin, &mut self.pout);
        let o = &self.pout;
        RcmOutputs {
            relay: o.relay != 0,
            node_left: o.node_left != 0,
            node_right: o.node_right != 0,
            term_left: o.term_left != 0,
            term_right: o.term_right != 0,
            mode: o.mode,
            illegal: o.illegal != 0,
            changes: o.changes,
        }
    }
}

/// An RCM engine by CLI name.
pub fn rcm_engine(name: &str) -> Result<Box<dyn RcmEngine>, String> {
    match name {
        "model" => Ok(Box::<RcmModelEngine>::default()),
        "rust-hdl" => Ok(Box::<RcmRustHdlEngine>::default()),
        "verilator" => Ok(Box::new(RcmVerilatorEngine::new()?)),
        other => Err(format!(
            "unknown RCM engine '{other}': give model, rust-hdl or verilator"
        )),
    }
}
