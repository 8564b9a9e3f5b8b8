//! The `verilator` engine of the hub tops: `rtl-out/hub.v` (hub A) and
//! `rtl-out/hub_b.v` (hub B) (N = 4 node ports, M = 2 interlinks) compiled by Verilator, driven through `verilator-sys`. The sign-off
//! engine of the hub (`hub_contract.md`).

use super::hub::{HubEngine, HubInputs, HubOutputs, HubProbes};
use std::path::Path;
use verilator_sys::{Hub, HubB, HubBIn, HubBOut, HubIn, HubOut};

/// Node ports of the emitted hubs.
pub const N: usize = 4;
/// Interlinks of the emitted hubs.
pub const M: usize = 2;

/// One of the two emitted hub tops: `hub.v` (hub A, identification frame 0x000)
/// or `hub_b.v` (hub B, 0x001, hub contract §9.1). Their ports are the same.
enum Top {
    A(Hub, HubIn, HubOut),
    B(HubB, HubBIn, HubBOut),
}

/// The Verilated `hub` or `hub_b`.
pub struct HubVerilatorEngine {
    top: Top,
}

impl std::fmt::Debug for HubVerilatorEngine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("HubVerilatorEngine").finish_non_exhaustive()
    }
}

impl HubVerilatorEngine {
    /// A fresh hub A (`hub.v`), not yet reset. Fails with an actionable message
    /// when this build has no Verilated model (Verilator missing, or the RTL not
    /// generated).
    pub fn new() -> Result<Self, String> {
        Self::new_hub(0)
    }

    /// Hub `hub_id`: 0 = `hub.v`, 1 = `hub_b.v`.
    pub fn new_hub(hub_id: u8) -> Result<Self, String> {
        let top = match hub_id {
            0 => Top::A(
                Hub::new().map_err(|e| e.to_string())?,
                HubIn::default(),
                HubOut::default(),
            ),
            _ => Top::B(
                HubB::new().map_err(|e| e.to_string())?,
                HubBIn::default(),
                HubBOut::default(),
            ),
        };
        Ok(HubVerilatorEngine { top })
    }

    /// Starts a VCD trace of every RTL signal (Verilator's own trace; times in half
    /// clock periods).
    pub fn open_vcd(&mut self, path: impl AsRef<Path>) -> std::io::Result<()> {
        match &mut self.top {
            Top::A(t, ..) => t.trace_open(path),
            Top::B(t, ..) => t.trace_open(path),
        }
    }

    /// Flushes and closes the VCD trace, if one is open.
    pub fn close_vcd(&mut self) {
        match &mut self.top {
            Top::A(t, ..) => t.trace_close(),
            Top::B(t, ..) => t.trace_close(),
        }
    }
}

/// The two tops' port structs have the same fields: one body for both.
macro_rules! step_top {
    ($top:expr, $pin:expr, $pout:expr, $In:ident, $i:expr) => {{
        *$pin = $In {
            rst: $i.rst as u8,
            wb_cyc_i: $i.wb_cyc as u8,
            wb_stb_i: $i.wb_stb as u8,
            wb_we_i: $i.wb_we as u8,
            wb_adr_i: $i.wb_adr & 0x3F,
            wb_dat_i: $i.wb_dat_w,
            wb_sel_i: $i.wb_sel & 0xF,
            uplink: ($i.uplink & ((1 << N) - 1)) as u8,
            sublink_in: $i.sublink_in & ((1 << M) - 1),
        };
        $top.step_into($pin, $pout);
        let o = &*$pout;
        HubOutputs {
            wb_ack: o.wb_ack_o != 0,
            wb_err: o.wb_err_o != 0,
            wb_dat_r: o.wb_dat_o,
            irq: o.irq != 0,
            downlink: o.downlink as u16,
            sublink_out: o.sublink_out,
            probes: HubProbes {
                coupled: o.coupled != 0,
                sample_point: o.sample_point != 0,
                trk_state: o.trk_state,
                ack_window: o.ack_window != 0,
                decoupled: o.decoupled != 0,
                port_enabled: o.port_enabled as u16,
                nrap_phase: o.nrap_phase,
                hub_tx: o.hub_tx != 0,
            },
        }
    }};
}

impl HubEngine for HubVerilatorEngine {
    fn name(&self) -> &'static str {
        "verilator"
    }

    fn shape(&self) -> (usize, usize) {
        (N, M)
    }

    #[inline]
    fn step(&mut self, i: &HubInputs) -> HubOutputs {
        match &mut self.top {
            Top::A(t, pin, pout) => step_top!(t, pin, pout, HubIn, i),
            Top::B(t, pin, pout) => step_top!(t, pin, pout, HubBIn, i),
        }
    }
}
