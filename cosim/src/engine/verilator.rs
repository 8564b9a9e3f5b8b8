//! The `verilator` engine: the emitted Verilog (`rtl-out/can_channel.v`) compiled
//! by Verilator, driven through `verilator-sys`. This is the sign-off engine: it
//! runs the very RTL that goes to synthesis.
//!
//! One `step` is one FFI call (apply inputs, `clk` 0 then 1, read outputs) and
//! allocates nothing. Port encodings: tseg1/tseg2/sjw travel as `value - 1`,
//! the data bytes as [`Frame::data_word`] (byte 0 in bits 63..56), the mode as
//! [`Mode::code`](super::Mode::code).
//!
//! In the quiet stretches of `System::run_for` ([`ChannelEngine::step_quiet`]) the
//! port structs are kept from clock to clock: only `rx` is written, and only `tx`,
//! `tx_pending` and the pulses are read, unless a pulse is set: converting every
//! input and output every clock took a large share of a clock once the model's
//! own evaluation no longer recomputed unchanged inputs (`docs/design.md`,
//! "Engine speed").
//!
//! VCD traces ([`VerilatorEngine::open_vcd`]) stamp the `clk = 0` phase of step
//! `n` at time `2n` and the `clk = 1` phase at `2n + 1` (half clock periods).

use super::{ChannelEngine, ChannelInputs, ChannelOutputs, Diagnostics, Probes};
use crate::frame::Frame;
use std::path::Path;
use verilator_sys::{CanChannel, CanChannelIn, CanChannelOut};

/// Whether a missing Verilator must fail instead of being skipped: the one rule of
/// [`verilator_sys::required`] (`DRCC_REQUIRE_VERILATOR` or `CI` set to anything
/// but empty, `0`, `false`, `no`, `off`), re-exported for the crates above.
pub use verilator_sys::required as verilator_required;

/// The Verilated `can_channel`.
pub struct VerilatorEngine {
    ch: CanChannel,
    ports_in: CanChannelIn,
    ports_out: CanChannelOut,
    /// `ports_in` holds the encoding of the inputs of the current quiet stretch
    /// (set by `step_quiet`, cleared by `step`).
    quiet: bool,
}

impl std::fmt::Debug for VerilatorEngine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("VerilatorEngine").finish_non_exhaustive()
    }
}

impl VerilatorEngine {
    /// A fresh channel, not yet reset (drive `rst` for a few steps). Fails with
    /// an actionable message when this build has no Verilated model (Verilator
    /// not installed, or `rtl-out/can_channel.v` not generated).
    pub fn new() -> Result<Self, String> {
        let ch = CanChannel::new().map_err(|e| e.to_string())?;
        Ok(VerilatorEngine {
            ch,
            ports_in: CanChannelIn::default(),
            ports_out: CanChannelOut::default(),
            quiet: false,
        })
    }

    /// Whether this build has the Verilated model.
    pub fn available() -> bool {
        verilator_sys::available()
    }

    /// Starts a VCD trace of every RTL signal into `path` (closing an open one).
    pub fn open_vcd(&mut self, path: impl AsRef<Path>) -> std::io::Result<()> {
        self.ch.trace_open(path)
    }

    /// Flushes and closes the VCD trace, if one is open.
    pub fn close_vcd(&mut self) {
        self.ch.trace_close();
    }
}

impl ChannelEngine for VerilatorEngine {
    fn name(&self) -> &'static str {
        "verilator"
    }

    #[inline]
    fn step(&mut self, inputs: &ChannelInputs) -> ChannelOutputs {
        self.quiet = false;
        encode(inputs, &mut self.ports_in);
        self.ch.step_into(&self.ports_in, &mut self.ports_out);
        decode(&self.ports_out)
    }

    #[inline]
    fn step_quiet(&mut self, inputs: &ChannelInputs, out: &mut ChannelOutputs) -> bool {
        if self.quiet {
            // Only rx changes within a stretch (the trait's contract).
            debug_assert_eq!(
                {
                    let mut p = CanChannelIn::default();
                    encode(inputs, &mut p);
                    p.rx = self.ports_in.rx;
                    p
                },
                self.ports_in,
                "step_quiet: an input other than rx changed within a quiet stretch"
            );
            self.ports_in.rx = inputs.rx as u8;
        } else {
            encode(inputs, &mut self.ports_in);
            self.quiet = true;
        }
        self.ch.step_into(&self.ports_in, &mut self.ports_out);
        let p = &self.ports_out;
        if (p.tx_done | p.arb_lost | p.tx_failed | p.rx_valid) != 0 {
            *out = decode(p);
            return true;
        }
        let pending = p.tx_pending != 0;
        let changed = pending != out.tx_pending;
        out.tx = p.tx != 0;
        out.tx_pending = pending;
        out.tx_done = false;
        out.arb_lost = false;
        out.tx_failed = false;
        out.rx_valid = false;
        changed
    }

    fn gains_from_quiet(&self) -> bool {
        true
    }

    fn complete_outputs(&mut self, out: &mut ChannelOutputs) {
        *out = decode(&self.ports_out);
    }
}

/// `ChannelInputs` -> port values, clamped like the rust-hdl engine does.
#[inline]
fn encode(i: &ChannelInputs, p: &mut CanChannelIn) {
    let t = &i.timing;
    let c = &i.config;
    let f = &i.tx_frame;
    *p = CanChannelIn {
        rst: i.rst as u8,
        cfg_brp: t.brp.min(1023) as _,
        cfg_tseg1: t.tseg1.clamp(1, 16) - 1,
        cfg_tseg2: t.tseg2.clamp(1, 8) - 1,
        cfg_sjw: t.sjw.clamp(1, 4) - 1,
        cfg_triple: t.triple_sampling as u8,
        cfg_mode: c.mode.code(),
        cfg_ewl: c.ewl,
        cfg_single_shot: c.single_shot as u8,
        rx: i.rx as u8,
        tx_req: i.tx_req as u8,
        tx_id: f.id & 0x1FFF_FFFF,
        tx_ide: f.ide as u8,
        tx_rtr: f.rtr as u8,
        tx_dlc: f.dlc & 0xF,
        tx_data: f.data_word(),
        tx_abort: i.tx_abort as u8,
        tx_single: i.tx_single as u8,
        err_reset: i.err_reset as u8,
        boff_hold: i.boff_hold as u8,
    };
}

/// Port values -> `ChannelOutputs`.
#[inline]
fn decode(p: &CanChannelOut) -> ChannelOutputs {
    ChannelOutputs {
        tx: p.tx != 0,
        tx_pending: p.tx_pending != 0,
        tx_done: p.tx_done != 0,
        arb_lost: p.arb_lost != 0,
        tx_failed: p.tx_failed != 0,
        rx_valid: p.rx_valid != 0,
        rx_frame: Frame {
            id: p.rx_id,
            ide: p.rx_ide != 0,
            rtr: p.rx_rtr != 0,
            dlc: p.rx_dlc,
            data: p.rx_data.to_be_bytes(),
        },
        probes: Probes {
            sample_point: p.sample_point != 0,
            sampled_bit: p.sampled_bit != 0,
            field: p.field,
            tec: p.tec,
            rec: p.rec,
            err_state: p.err_state,
            is_tx: p.is_tx != 0,
            boff_runs: p.boff_runs,
        },
        diag: Diagnostics {
            err_warning: p.err_warning != 0,
            err_valid: p.err_valid != 0,
            err_kind: p.err_kind,
            err_field: p.err_field,
            err_tx: p.err_tx != 0,
            alc: p.alc,
            cnt_bit: p.cnt_bit,
            cnt_stuff: p.cnt_stuff,
            cnt_crc: p.cnt_crc,
            cnt_form: p.cnt_form,
            cnt_ack: p.cnt_ack,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::{BitTiming, ControllerConfig, Mode};

    #[test]
    fn encode_uses_minus_one_encodings_and_data_word() {
        let inputs = ChannelInputs {
            rst: true,
            rx: false,
            timing: BitTiming {
                brp: 3,
                tseg1: 13,
                tseg2: 2,
                sjw: 2,
                triple_sampling: true,
            },
            config: ControllerConfig {
                mode: Mode::SelfTest,
                ewl: 200,
                single_shot: true,
            },
            tx_req: true,
            tx_frame: Frame {
                id: 0x1234_5678,
                ide: true,
                rtr: false,
                dlc: 8,
                data: [1, 2, 3, 4, 5, 6, 7, 8],
            },
            tx_abort: true,
            tx_single: true,
            err_reset: true,
            boff_hold: true,
        };
        let mut p = CanChannelIn::default();
        encode(&inputs, &mut p);
        assert_eq!(
            p,
            CanChannelIn {
                rst: 1,
                cfg_brp: 3,
                cfg_tseg1: 12,
                cfg_tseg2: 1,
                cfg_sjw: 1,
                cfg_triple: 1,
                cfg_mode: 2,
                cfg_ewl: 200,
                cfg_single_shot: 1,
                rx: 0,
                tx_req: 1,
                tx_id: 0x1234_5678,
                tx_ide: 1,
                tx_rtr: 0,
                tx_dlc: 8,
                tx_data: 0x0102_0304_0506_0708,
                tx_abort: 1,
                tx_single: 1,
                err_reset: 1,
                boff_hold: 1,
            }
        );
        // Every mode travels as its code.
        for mode in [
            Mode::Normal,
            Mode::ListenOnly,
            Mode::SelfTest,
            Mode::Loopback,
        ] {
            let i = ChannelInputs {
                config: ControllerConfig {
                    mode,
                    ..ControllerConfig::default()
                },
                ..ChannelInputs::default()
            };
            encode(&i, &mut p);
            assert_eq!(Mode::from_code(p.cfg_mode), mode);
            assert_eq!(
                (
                    p.cfg_ewl,
                    p.cfg_single_shot,
                    p.tx_abort,
                    p.tx_single,
                    p.err_reset,
                    p.boff_hold
                ),
                (96, 0, 0, 0, 0, 0)
            );
        }
    }

    #[test]
    fn decode_maps_every_port() {
        let p = CanChannelOut {
            tx: 1,
            tx_pending: 1,
            tx_done: 0,
            arb_lost: 1,
            tx_failed: 1,
            rx_valid: 1,
            rx_id: 0x7FF,
            rx_ide: 0,
            rx_rtr: 1,
            rx_dlc: 2,
            rx_data: 0xAABB << 48,
            sample_point: 1,
            sampled_bit: 0,
            field: 15,
            tec: 256,
            rec: 127,
            err_state: 2,
            is_tx: 1,
            boff_runs: 100,
            err_warning: 1,
            err_valid: 0,
            err_kind: 4,
            err_field: 19,
            err_tx: 1,
            alc: 31,
            cnt_bit: 1,
            cnt_stuff: 2,
            cnt_crc: 3,
            cnt_form: 255,
            cnt_ack: 5,
        };
        let o = decode(&p);
        assert!(o.tx && o.tx_pending && !o.tx_done && o.arb_lost && o.rx_valid && o.tx_failed);
        assert_eq!(
            o.rx_frame,
            Frame {
                id: 0x7FF,
                ide: false,
                rtr: true,
                dlc: 2,
                data: [0xAA, 0xBB, 0, 0, 0, 0, 0, 0],
            }
        );
        assert_eq!(
            o.probes,
            Probes {
                sample_point: true,
                sampled_bit: false,
                field: 15,
                tec: 256,
                rec: 127,
                err_state: 2,
                is_tx: true,
                boff_runs: 100,
            }
        );
        assert_eq!(
            o.diag,
            Diagnostics {
                err_warning: true,
                err_valid: false,
                err_kind: 4,
                err_field: 19,
                err_tx: true,
                alc: 31,
                cnt_bit: 1,
                cnt_stuff: 2,
                cnt_crc: 3,
                cnt_form: 255,
                cnt_ack: 5,
            }
        );
    }

    #[test]
    fn new_reports_why_it_is_unavailable() {
        match VerilatorEngine::new() {
            Ok(e) => assert_eq!(e.name(), "verilator"),
            Err(msg) => {
                assert!(!VerilatorEngine::available());
                assert_eq!(Some(msg.as_str()), verilator_sys::unavailable_reason());
            }
        }
    }

    #[test]
    fn reset_leaves_the_bus_recessive() {
        let Ok(mut e) = VerilatorEngine::new() else {
            return; // covered by verilator-sys's tests, which refuse to skip in CI
        };
        let mut i = ChannelInputs {
            rst: true,
            rx: true,
            ..ChannelInputs::default()
        };
        for _ in 0..3 {
            e.step(&i);
        }
        i.rst = false;
        for _ in 0..100 {
            let o = e.step(&i);
            assert!(o.tx && !o.tx_pending);
            assert_eq!((o.probes.tec, o.probes.rec, o.probes.err_state), (0, 0, 0));
        }
    }
}
