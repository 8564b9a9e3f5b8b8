//! The `verilator` engine of the DRCC tops: `rtl-out/drcc.v` (`M = 16` DMR
//! mailboxes), `rtl-out/drcc_m0.v` (`M = 0`) or `rtl-out/drcc_small.v` (the small
//! configuration, `drcc_hdl::config`) compiled by Verilator, driven
//! through `verilator-sys`. The sign-off engine for everything the DRCC adds to the
//! channels (redundancy management, RAMs, registers, DMR).

use super::drcc::{DrccEngine, DrccInputs, DrccOutputs, DrccProbes};
use std::path::Path;
use verilator_sys::{
    Drcc, DrccIn, DrccM0, DrccM0In, DrccM0Out, DrccOut, DrccSmall, DrccSmallIn, DrccSmallOut,
};

/// The outputs of a Verilated DRCC top (`DrccOut` or `DrccM0Out`: the same fields).
macro_rules! decode_fields {
    ($o:ident) => {{
        let o = $o;
        DrccOutputs {
            wb_ack: o.wb_ack_o != 0,
            wb_err: o.wb_err_o != 0,
            wb_dat_r: o.wb_dat_o,
            irq: o.irq != 0,
            chan_a_tx: o.chan_a_tx != 0,
            chan_b_tx: o.chan_b_tx != 0,
            probes: DrccProbes {
                state: o.state,
                tx_channel: o.tx_channel != 0,
                transmission_ack: o.transmission_ack != 0,
                chan_a_transmission_req: o.chan_a_transmission_req != 0,
                chan_b_transmission_req: o.chan_b_transmission_req != 0,
                tx_success: o.tx_success != 0,
                tx_ok_channel: o.tx_ok_channel,
                tx_failure: o.tx_failure != 0,
                tx_failure_channel: o.tx_failure_channel,
                tx_going_on: o.tx_going_on != 0,
                chan_a_bsp_tx_err_cnt: o.chan_a_bsp_tx_err_cnt,
                chan_a_bsp_node_error_passive: o.chan_a_bsp_node_error_passive != 0,
                chan_b_bsp_tx_err_cnt: o.chan_b_bsp_tx_err_cnt,
                chan_b_bsp_node_error_passive: o.chan_b_bsp_node_error_passive != 0,
                aux_a_state: o.aux_a_state,
                aux_b_state: o.aux_b_state,
                chan_a_sample_point: o.chan_a_sample_point != 0,
                chan_b_sample_point: o.chan_b_sample_point != 0,
                chan_a_field: o.chan_a_field,
                chan_b_field: o.chan_b_field,
                chan_a_rec: o.chan_a_rec,
                chan_b_rec: o.chan_b_rec,
                chan_a_err_state: o.chan_a_err_state,
                chan_b_err_state: o.chan_b_err_state,
                dmr_state: o.dmr_state,
                acl: o.acl != 0,
                dcl_tx_fault: o.dcl_tx_fault != 0,
                dcl_rx_fault: o.dcl_rx_fault != 0,
                rcl_tx_fault: o.rcl_tx_fault != 0,
                rcl_rx_fault: o.rcl_rx_fault != 0,
                dmr_tick: o.dmr_tick != 0,
            },
        }
    }};
}

/// One engine type per Verilated DRCC top (the two have the same ports).
macro_rules! drcc_verilator_engine {
    ($(#[$doc:meta])* $engine:ident, $top:ident, $inp:ident, $out:ident, $decode:ident) => {
        $(#[$doc])*
        pub struct $engine {
            top: $top,
            ports_in: $inp,
            ports_out: $out,
        }

        impl std::fmt::Debug for $engine {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.debug_struct(stringify!($engine)).finish_non_exhaustive()
            }
        }

        impl $engine {
            /// A fresh instance, not yet reset. Fails with an actionable message when
            /// this build has no Verilated model (Verilator missing, or the RTL not
            /// generated).
            pub fn new() -> Result<Self, String> {
                let top = $top::new().map_err(|e| e.to_string())?;
                Ok($engine {
                    top,
                    ports_in: $inp::default(),
                    ports_out: $out::default(),
                })
            }

            /// Starts a VCD trace of every RTL signal (Verilator's own trace; times in
            /// half clock periods).
            pub fn open_vcd(&mut self, path: impl AsRef<Path>) -> std::io::Result<()> {
                self.top.trace_open(path)
            }

            /// Flushes and closes the VCD trace, if one is open.
            pub fn close_vcd(&mut self) {
                self.top.trace_close();
            }
        }

        impl DrccEngine for $engine {
            fn name(&self) -> &'static str {
                "verilator"
            }

            #[inline]
            fn open_rtl_trace(&mut self, path: &Path) -> Result<(), String> {
                self.open_vcd(path)
                    .map_err(|e| format!("{}: {e}", path.display()))
            }

            fn step(&mut self, i: &DrccInputs) -> DrccOutputs {
                self.ports_in = $inp {
                    rst: i.rst as u8,
                    wb_cyc_i: i.wb_cyc as u8,
                    wb_stb_i: i.wb_stb as u8,
                    wb_we_i: i.wb_we as u8,
                    wb_adr_i: i.wb_adr,
                    wb_dat_i: i.wb_dat_w,
                    wb_sel_i: i.wb_sel & 0xF,
                    chan_a_rx: i.chan_a_rx as u8,
                    chan_b_rx: i.chan_b_rx as u8,
                };
                self.top.step_into(&self.ports_in, &mut self.ports_out);
                $decode(&self.ports_out)
            }
        }

        #[inline]
        fn $decode(o: &$out) -> DrccOutputs {
            decode_fields!(o)
        }
    };
}

drcc_verilator_engine!(
    /// The Verilated `drcc` (16 DMR mailboxes).
    DrccVerilatorEngine,
    Drcc,
    DrccIn,
    DrccOut,
    decode
);

drcc_verilator_engine!(
    /// The Verilated `drcc_small` (the small configuration: no DMR mailboxes, RX
    /// FIFO 8, TX queues 4, history 16).
    DrccSmallVerilatorEngine,
    DrccSmall,
    DrccSmallIn,
    DrccSmallOut,
    decode_small
);

drcc_verilator_engine!(
    /// The Verilated `drcc_m0` (no DMR mailboxes).
    DrccM0VerilatorEngine,
    DrccM0,
    DrccM0In,
    DrccM0Out,
    decode_m0
);
