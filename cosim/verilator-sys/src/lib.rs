//! verilator-sys: the Verilated RTL tops of `rtl-out/` behind a small C ABI, plus
//! safe wrappers.
//!
//! `build.rs` verilates `rtl-out/can_channel.v` (top `can_channel`; override the
//! directory with `DRCC_RTL_DIR`), compiles `shim/can_channel_shim.cpp` and links
//! both. Without Verilator or without the RTL the crate still builds: [`available`]
//! is then `false` and [`CanChannel::new`] returns [`VerilatorUnavailable`]. Set
//! `DRCC_REQUIRE_VERILATOR=1` (CI does) to make that a build error instead.
//!
//! # Clocking and traces
//! [`CanChannel::step`] applies the inputs, evaluates `clk = 0`, then `clk = 1`
//! (one rising edge) and returns the outputs after the edge. When no trace is open
//! and [`CanChannel::fast_edge`] is true, it makes one eval with `clk = 1` instead,
//! after resetting the model's "previous clk" trigger state: Verilator settles the
//! input logic before the edge-triggered logic in one eval, so the outputs are the
//! same (the tests step an instance each way in lockstep and compare them), at
//! about 1.4 times the speed. [`CanChannel::set_exact`] forces the two evals.
//! With a VCD trace open,
//! step number `n` (counted from 0 since the instance was created) dumps the
//! `clk = 0` phase at time `2n` and the `clk = 1` phase at `2n + 1`: one VCD time
//! unit is half a clock period, whatever `$timescale` the file header states.
//!
//! # When the RTL ports change
//! The port table is `shim/can_channel_ports.h` (C side) and [`CanChannelIn`] /
//! [`CanChannelOut`] here (same fields, same order, same types). `build.rs` compares
//! the C table with the ports Verilator found in the RTL and stops with a message
//! naming each differing port; [`CanChannel::new`] panics if the C and Rust layouts
//! differ (a fingerprint of every field's name, offset, size and width).
//!
//! Each instance has its own `VerilatedContext`: several instances (the nodes of
//! one bus) can live in one process and be stepped alternately, on any thread,
//! but one instance is never stepped from two threads at once (`Send`, not `Sync`).

use std::fmt;

/// Error message when Verilator is not installed.
pub const UNAVAILABLE_MSG: &str =
    "Verilator not found: install it with `apt-get install verilator`";

/// Error message when the Verilog of the `can_channel` top has not been generated.
pub const RTL_MISSING_MSG: &str =
    "an RTL top in rtl-out/ (can_channel.v, drcc.v, hub.v) is missing: run `cargo run -- generate`";

/// Why this build has no Verilated model (set by build.rs; empty when it has one).
const BUILD_REASON: &str = env!("DRCC_VERILATOR_UNAVAILABLE");

/// `true` when the crate was built with the Verilated models (`cfg(drcc_verilator)`).
pub fn available() -> bool {
    cfg!(drcc_verilator)
}

/// The Verilator version the models were built with, e.g. `"5.006"`.
pub fn verilator_version() -> Option<&'static str> {
    Some(env!("DRCC_VERILATOR_VERSION")).filter(|v| !v.is_empty())
}

/// Why [`available`] is false: [`UNAVAILABLE_MSG`], or a message starting like
/// [`RTL_MISSING_MSG`], or a failed Verilator run. `None` when available.
pub fn unavailable_reason() -> Option<&'static str> {
    if available() {
        None
    } else if BUILD_REASON.is_empty() {
        Some(UNAVAILABLE_MSG)
    } else {
        Some(BUILD_REASON)
    }
}

/// The Verilated models are not part of this build; the message says why and how to fix it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VerilatorUnavailable {
    reason: &'static str,
}

impl VerilatorUnavailable {
    #[cfg_attr(drcc_verilator, allow(dead_code))]
    fn new() -> Self {
        VerilatorUnavailable {
            reason: unavailable_reason().unwrap_or(UNAVAILABLE_MSG),
        }
    }
    /// The message (see [`unavailable_reason`]).
    pub fn message(&self) -> &'static str {
        self.reason
    }
}

impl fmt::Display for VerilatorUnavailable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.reason)
    }
}

impl std::error::Error for VerilatorUnavailable {}

/// Declares a `#[repr(C)]` port struct and its layout fingerprint. The field list
/// must match the `X(type, name, width)` list of `shim/<top>_ports.h` line by line.
macro_rules! port_struct {
    (
        $(#[$meta:meta])*
        pub struct $name:ident {
            $( $(#[$fmeta:meta])* $field:ident : $ty:ty = $width:literal ),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[repr(C)]
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
        pub struct $name {
            $( $(#[$fmeta])* pub $field: $ty, )*
        }

        impl $name {
            /// Name and bit width of every port, in field order.
            pub const PORTS: &'static [(&'static str, u32)] = &[$((stringify!($field), $width)),*];

            /// Folds this struct's layout into `h` exactly like `drcc::LayoutHash` in C++.
            #[allow(dead_code)]
            fn layout_hash(h: &mut LayoutHash) {
                $(
                    h.field(
                        stringify!($field),
                        std::mem::offset_of!($name, $field) as u64,
                        std::mem::size_of::<$ty>() as u64,
                        $width,
                    );
                )*
                h.end(std::mem::size_of::<$name>() as u64);
            }
        }
    };
}

/// FNV-1a 64 over the layout, as `drcc::LayoutHash` in `shim/drcc_shim_common.h`.
#[allow(dead_code)]
struct LayoutHash(u64);

#[allow(dead_code)]
impl LayoutHash {
    fn new() -> Self {
        LayoutHash(0xcbf2_9ce4_8422_2325)
    }
    fn byte(&mut self, b: u8) {
        self.0 ^= b as u64;
        self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
    }
    fn u64(&mut self, v: u64) {
        for b in v.to_le_bytes() {
            self.byte(b);
        }
    }
    fn field(&mut self, name: &str, offset: u64, size: u64, width: u64) {
        for b in name.bytes() {
            self.byte(b);
        }
        self.byte(0);
        self.u64(offset);
        self.u64(size);
        self.u64(width);
    }
    fn end(&mut self, size: u64) {
        self.byte(b'|');
        self.u64(size);
    }
}

port_struct! {
    /// Every input of `can_channel` except `clk` (mirror of `CanChannelIn` in
    /// `shim/can_channel_ports.h`). Single-bit ports hold 0 or 1; the shim masks
    /// every value to its port width.
    pub struct CanChannelIn {
        /// Synchronous active-high reset.
        rst: u8 = 1,
        /// Baud-rate prescaler (a time quantum is `cfg_brp + 1` clocks).
        cfg_brp: u8 = 6,
        /// TSEG1 in tq, minus one.
        cfg_tseg1: u8 = 4,
        /// TSEG2 in tq, minus one.
        cfg_tseg2: u8 = 3,
        /// SJW in tq, minus one.
        cfg_sjw: u8 = 2,
        /// Triple sampling.
        cfg_triple: u8 = 1,
        /// Operating mode: 0 normal, 1 listen-only, 2 self-test, 3 loop-back.
        cfg_mode: u8 = 2,
        /// Error warning limit (ISO 11898-1 default 96).
        cfg_ewl: u8 = 8,
        /// No automatic retransmission.
        cfg_single_shot: u8 = 1,
        /// Bus value seen by the receiver (1 = recessive).
        rx: u8 = 1,
        /// One-clock transmit request.
        tx_req: u8 = 1,
        /// Identifier (11 bits in `[10:0]` for base frames).
        tx_id: u32 = 29,
        /// Extended frame.
        tx_ide: u8 = 1,
        /// Remote frame.
        tx_rtr: u8 = 1,
        /// Data length code.
        tx_dlc: u8 = 4,
        /// Data, byte 0 in bits 63..56.
        tx_data: u64 = 64,
        /// One-clock request: abort the pending frame.
        tx_abort: u8 = 1,
    }
}

port_struct! {
    /// Every output of `can_channel` right after a rising edge (mirror of
    /// `CanChannelOut` in `shim/can_channel_ports.h`).
    pub struct CanChannelOut {
        /// Transmit pin (1 = recessive).
        tx: u8 = 1,
        /// A frame is latched and not yet sent.
        tx_pending: u8 = 1,
        /// Pulse: frame sent.
        tx_done: u8 = 1,
        /// Pulse: arbitration lost.
        arb_lost: u8 = 1,
        /// Pulse: the pending frame was dropped (single shot, abort, listen-only).
        tx_failed: u8 = 1,
        /// Pulse: a frame was received.
        rx_valid: u8 = 1,
        /// Received identifier.
        rx_id: u32 = 29,
        /// Received frame is extended.
        rx_ide: u8 = 1,
        /// Received frame is remote.
        rx_rtr: u8 = 1,
        /// Received DLC.
        rx_dlc: u8 = 4,
        /// Received data, byte 0 in bits 63..56.
        rx_data: u64 = 64,
        /// Probe: pulse after each sample point.
        sample_point: u8 = 1,
        /// Probe: bus value at the last sample point.
        sampled_bit: u8 = 1,
        /// Probe: field code of the next bit.
        field: u8 = 5,
        /// Probe: transmit error counter.
        tec: u16 = 9,
        /// Probe: receive error counter.
        rec: u8 = 8,
        /// Probe: 0 active, 1 passive, 2 bus-off.
        err_state: u8 = 2,
        /// TEC or REC at or above the error warning limit.
        err_warning: u8 = 1,
        /// Pulse: an error was detected and captured.
        err_valid: u8 = 1,
        /// Kind of the last error: 1 bit, 2 stuff, 3 CRC, 4 form, 5 ACK.
        err_kind: u8 = 3,
        /// Field code at the last error.
        err_field: u8 = 5,
        /// The node was transmitter at the last error.
        err_tx: u8 = 1,
        /// Arbitration-lost bit position.
        alc: u8 = 5,
        /// Bit errors (saturating).
        cnt_bit: u8 = 8,
        /// Stuff errors (saturating).
        cnt_stuff: u8 = 8,
        /// CRC errors (saturating).
        cnt_crc: u8 = 8,
        /// Form errors (saturating).
        cnt_form: u8 = 8,
        /// ACK errors (saturating).
        cnt_ack: u8 = 8,
    }
}

port_struct! {
    /// Every input of `drcc` except `clk` (mirror of `DrccIn` in `shim/drcc_ports.h`).
    pub struct DrccIn {
        /// Synchronous active-high reset.
        rst: u8 = 1,
        /// Wishbone cycle.
        wb_cyc_i: u8 = 1,
        /// Wishbone strobe.
        wb_stb_i: u8 = 1,
        /// Wishbone write enable.
        wb_we_i: u8 = 1,
        /// Wishbone word address.
        wb_adr_i: u8 = 6,
        /// Wishbone write data.
        wb_dat_i: u32 = 32,
        /// Channel A receive pin (1 = recessive).
        chan_a_rx: u8 = 1,
        /// Channel B receive pin.
        chan_b_rx: u8 = 1,
    }
}

port_struct! {
    /// Every output of `drcc` right after a rising edge (mirror of `DrccOut` in `shim/drcc_ports.h`).
    pub struct DrccOut {
        /// Wishbone read data.
        wb_dat_o: u32 = 32,
        /// Wishbone acknowledge.
        wb_ack_o: u8 = 1,
        /// Interrupt request.
        irq: u8 = 1,
        /// Channel A transmit pin.
        chan_a_tx: u8 = 1,
        /// Channel B transmit pin.
        chan_b_tx: u8 = 1,
        /// Main FSM state (Table 1 encoding).
        state: u8 = 4,
        /// Current channel: 0 = A, 1 = B.
        tx_channel: u8 = 1,
        /// Pulse: a channel acknowledged a transmission.
        transmission_ack: u8 = 1,
        /// Channel A transmit request.
        chan_a_transmission_req: u8 = 1,
        /// Channel B transmit request.
        chan_b_transmission_req: u8 = 1,
        /// Pulse: message done.
        tx_success: u8 = 1,
        /// Channel(s) that delivered the last message.
        tx_ok_channel: u8 = 2,
        /// Pulse: a channel failed the message.
        tx_failure: u8 = 1,
        /// Latched failed channel(s).
        tx_failure_channel: u8 = 2,
        /// A transmission is in progress.
        tx_going_on: u8 = 1,
        /// Channel A TEC.
        chan_a_bsp_tx_err_cnt: u16 = 9,
        /// Channel A not error active.
        chan_a_bsp_node_error_passive: u8 = 1,
        /// Channel B TEC.
        chan_b_bsp_tx_err_cnt: u16 = 9,
        /// Channel B not error active.
        chan_b_bsp_node_error_passive: u8 = 1,
        /// Aux FSM A state.
        aux_a_state: u8 = 2,
        /// Aux FSM B state.
        aux_b_state: u8 = 2,
        /// Channel A sample point pulse.
        chan_a_sample_point: u8 = 1,
        /// Channel B sample point pulse.
        chan_b_sample_point: u8 = 1,
        /// Channel A field code.
        chan_a_field: u8 = 5,
        /// Channel B field code.
        chan_b_field: u8 = 5,
        /// Channel A REC.
        chan_a_rec: u8 = 8,
        /// Channel B REC.
        chan_b_rec: u8 = 8,
        /// Channel A error state.
        chan_a_err_state: u8 = 2,
        /// Channel B error state.
        chan_b_err_state: u8 = 2,
    }
}

/// The layout fingerprint the C side must report (`drcc_drcc_abi`).
pub fn drcc_abi() -> u64 {
    let mut h = LayoutHash::new();
    DrccIn::layout_hash(&mut h);
    DrccOut::layout_hash(&mut h);
    h.0
}

port_struct! {
    /// Every input of `hub` except `clk` (mirror of `HubIn` in `shim/hub_ports.h`).
    pub struct HubIn {
        /// Synchronous active-high reset.
        rst: u8 = 1,
        /// Wishbone cycle.
        wb_cyc_i: u8 = 1,
        /// Wishbone strobe.
        wb_stb_i: u8 = 1,
        /// Wishbone write enable.
        wb_we_i: u8 = 1,
        /// Wishbone word address.
        wb_adr_i: u8 = 6,
        /// Wishbone write data.
        wb_dat_i: u32 = 32,
        /// Node transmit values, bit i = node port i (1 = recessive).
        uplink: u8 = 4,
        /// The twin hub's contribution, bit j = interlink j.
        sublink_in: u8 = 2,
    }
}

port_struct! {
    /// Every output of `hub` right after a rising edge (mirror of `HubOut` in `shim/hub_ports.h`).
    pub struct HubOut {
        /// Wishbone read data.
        wb_dat_o: u32 = 32,
        /// Wishbone acknowledge.
        wb_ack_o: u8 = 1,
        /// Interrupt request.
        irq: u8 = 1,
        /// What node i receives (all bits equal).
        downlink: u8 = 4,
        /// This hub's contribution on every interlink.
        sublink_out: u8 = 2,
        /// `coupled_q`: the signal the hub tracks.
        coupled: u8 = 1,
        /// Bit timing sample point probe.
        sample_point: u8 = 1,
        /// Tracker state.
        trk_state: u8 = 2,
        /// ACK window (contract §4).
        ack_window: u8 = 1,
        /// Decoupled (contract §7).
        decoupled: u8 = 1,
        /// Bit p = port p enabled.
        port_enabled: u8 = 6,
    }
}

/// The layout fingerprint the C side must report (`drcc_hub_abi`).
pub fn hub_abi() -> u64 {
    let mut h = LayoutHash::new();
    HubIn::layout_hash(&mut h);
    HubOut::layout_hash(&mut h);
    h.0
}

/// The layout fingerprint the C side must report (`drcc_can_channel_abi`).
pub fn can_channel_abi() -> u64 {
    let mut h = LayoutHash::new();
    CanChannelIn::layout_hash(&mut h);
    CanChannelOut::layout_hash(&mut h);
    h.0
}

/// Declares the raw FFI module and the safe wrapper of one Verilated top. The C side
/// is `shim/<top>_shim.cpp`, built from the port table `shim/<top>_ports.h`.
macro_rules! verilated_top {
    (
        $(#[$meta:meta])*
        wrapper $name:ident, ports $in:ident / $out:ident, abi $abi:ident, ffi $ffi:ident {
            $abi_c:ident, $new_c:ident, $free_c:ident, $step_c:ident, $fast_c:ident,
            $exact_c:ident, $topen_c:ident, $tdump_c:ident, $tclose_c:ident $(,)?
        }
    ) => {
/// The raw C ABI of shim of one top (declared in `shim/<top>_ports.h`).
        #[cfg(drcc_verilator)]
        pub mod $ffi {
            use super::{$in, $out};
            use std::ffi::{c_char, c_int, c_void};

            extern "C" {
                /// Layout fingerprint of the C structs.
                pub fn $abi_c() -> u64;
                /// New instance (own `VerilatedContext`), or null.
                pub fn $new_c() -> *mut c_void;
                /// Frees an instance (closing its trace); null is ignored.
                pub fn $free_c(handle: *mut c_void);
                /// Applies `*input`, makes one rising edge of `clk`, writes `*output`.
                pub fn $step_c(
                    handle: *mut c_void,
                    input: *const $in,
                    output: *mut $out,
                );
                /// 1 if steps can make one eval instead of two.
                pub fn $fast_c() -> c_int;
                /// `exact != 0`: always two evals per step.
                pub fn $exact_c(handle: *mut c_void, exact: c_int);
                /// Opens a VCD file: 0, or `-errno`.
                pub fn $topen_c(handle: *mut c_void, path: *const c_char) -> c_int;
                /// Dumps the current values at `time` (half clock periods) if a trace is open.
                pub fn $tdump_c(handle: *mut c_void, time: u64);
                /// Flushes and closes the trace, if open.
                pub fn $tclose_c(handle: *mut c_void);
            }
        }

        /// One Verilated instance of the top with its own `VerilatedContext`.
        $(#[$meta])*
        pub struct $name {
            #[cfg(drcc_verilator)]
            raw: std::ptr::NonNull<std::ffi::c_void>,
            #[cfg(not(drcc_verilator))]
            never: std::convert::Infallible,
        }

        // SAFETY: an instance owns its context, model and trace; nothing in it is tied to
        // the creating thread (the shim clears Verilator's thread-current context after
        // construction). `&mut self` on every call rules out concurrent use.
        unsafe impl Send for $name {}

        impl fmt::Debug for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.debug_struct(stringify!($name)).finish_non_exhaustive()
            }
        }

        #[cfg(drcc_verilator)]
        impl $name {
            /// A new instance; registers are as `--x-initial fast` leaves them until the
            /// first step with `rst = 1`.
            ///
            /// # Panics
            /// If the C and Rust port layouts differ (a build inconsistency, see the crate docs).
            pub fn new() -> Result<Self, VerilatorUnavailable> {
                // SAFETY: plain function without arguments.
                let c_abi = unsafe { $ffi::$abi_c() };
                assert_eq!(
                    c_abi,
                    $abi(),
                    "verilator-sys: $in/$out in src/lib.rs do not match \
                     the shim's port table (same fields, order, types and widths needed)"
                );
                // SAFETY: returns an owned instance or null.
                let raw = unsafe { $ffi::$new_c() };
                let raw = std::ptr::NonNull::new(raw).expect(concat!(stringify!($new_c), ": out of memory"));
                Ok($name { raw })
            }

            /// Applies `input`, makes one rising edge of `clk` and writes the outputs after it.
            #[inline]
            pub fn step_into(&mut self, input: &$in, output: &mut $out) {
                // SAFETY: `raw` is a live instance; the structs are #[repr(C)] mirrors of
                // the C ones (checked in new()).
                unsafe { $ffi::$step_c(self.raw.as_ptr(), input, output) }
            }

            /// Applies `input`, makes one rising edge of `clk` and returns the outputs after it.
            #[inline]
            pub fn step(&mut self, input: &$in) -> $out {
                let mut out = $out::default();
                self.step_into(input, &mut out);
                out
            }

            /// Whether steps without a trace make one eval instead of two (see the crate docs).
            pub fn fast_edge() -> bool {
                // SAFETY: plain function without arguments.
                unsafe { $ffi::$fast_c() != 0 }
            }

            /// `true`: always evaluate `clk = 0` and then `clk = 1` (as while tracing);
            /// `false` (the default): use the single-eval edge when [`$name::fast_edge`].
            pub fn set_exact(&mut self, exact: bool) {
                // SAFETY: `raw` is live.
                unsafe { $ffi::$exact_c(self.raw.as_ptr(), exact as _) }
            }

            /// Starts a VCD trace of every signal (closing an open one first). Times are
            /// in half clock periods (see the crate docs).
            pub fn trace_open(&mut self, path: impl AsRef<std::path::Path>) -> std::io::Result<()> {
                let c = path_to_cstring(path.as_ref())?;
                // SAFETY: `raw` is live; `c` outlives the call.
                let rc = unsafe { $ffi::$topen_c(self.raw.as_ptr(), c.as_ptr()) };
                if rc == 0 {
                    Ok(())
                } else {
                    let err = std::io::Error::from_raw_os_error(-rc);
                    Err(std::io::Error::new(
                        err.kind(),
                        format!("cannot open VCD file {}: {err}", path.as_ref().display()),
                    ))
                }
            }

            /// Dumps the current signal values at `time` (half clock periods) if a trace is
            /// open. `step` already dumps both phases; this is for extra samples. Times must
            /// not go backwards.
            pub fn trace_dump(&mut self, time: u64) {
                // SAFETY: `raw` is live.
                unsafe { $ffi::$tdump_c(self.raw.as_ptr(), time) }
            }

            /// Flushes and closes the trace, if one is open.
            pub fn trace_close(&mut self) {
                // SAFETY: `raw` is live.
                unsafe { $ffi::$tclose_c(self.raw.as_ptr()) }
            }
        }

        #[cfg(drcc_verilator)]
        impl Drop for $name {
            fn drop(&mut self) {
                // SAFETY: `raw` came from $new_c and is freed once.
                unsafe { $ffi::$free_c(self.raw.as_ptr()) }
            }
        }

        #[cfg(not(drcc_verilator))]
        impl $name {
            /// Always fails in this build: see [`unavailable_reason`].
            pub fn new() -> Result<Self, VerilatorUnavailable> {
                Err(VerilatorUnavailable::new())
            }

            /// Unreachable: no instance exists in this build.
            pub fn step_into(&mut self, _input: &$in, _output: &mut $out) {
                match self.never {}
            }

            /// Unreachable: no instance exists in this build.
            pub fn step(&mut self, _input: &$in) -> $out {
                match self.never {}
            }

            /// No model, no fast edge.
            pub fn fast_edge() -> bool {
                false
            }

            /// Unreachable: no instance exists in this build.
            pub fn set_exact(&mut self, _exact: bool) {
                match self.never {}
            }

            /// Unreachable: no instance exists in this build.
            pub fn trace_open(&mut self, _path: impl AsRef<std::path::Path>) -> std::io::Result<()> {
                match self.never {}
            }

            /// Unreachable: no instance exists in this build.
            pub fn trace_dump(&mut self, _time: u64) {
                match self.never {}
            }

            /// Unreachable: no instance exists in this build.
            pub fn trace_close(&mut self) {
                match self.never {}
            }
        }
    };
}

verilated_top! {
    /// The `can_channel` top.
    wrapper CanChannel, ports CanChannelIn / CanChannelOut, abi can_channel_abi, ffi ffi {
        drcc_can_channel_abi, drcc_can_channel_new, drcc_can_channel_free,
        drcc_can_channel_step, drcc_can_channel_fast_edge, drcc_can_channel_set_exact,
        drcc_can_channel_trace_open, drcc_can_channel_trace_dump, drcc_can_channel_trace_close,
    }
}

verilated_top! {
    /// The `drcc` top (two channels, redundancy management, RAMs, Wishbone).
    wrapper Drcc, ports DrccIn / DrccOut, abi drcc_abi, ffi drcc_ffi {
        drcc_drcc_abi, drcc_drcc_new, drcc_drcc_free, drcc_drcc_step, drcc_drcc_fast_edge,
        drcc_drcc_set_exact, drcc_drcc_trace_open, drcc_drcc_trace_dump, drcc_drcc_trace_close,
    }
}

verilated_top! {
    /// The `hub` top (ReCANcentrate hub, N = 4 node ports, M = 2 interlinks).
    wrapper Hub, ports HubIn / HubOut, abi hub_abi, ffi hub_ffi {
        drcc_hub_abi, drcc_hub_new, drcc_hub_free, drcc_hub_step, drcc_hub_fast_edge,
        drcc_hub_set_exact, drcc_hub_trace_open, drcc_hub_trace_dump, drcc_hub_trace_close,
    }
}

#[cfg(drcc_verilator)]
fn path_to_cstring(path: &std::path::Path) -> std::io::Result<std::ffi::CString> {
    #[cfg(unix)]
    let bytes = {
        use std::os::unix::ffi::OsStrExt;
        path.as_os_str().as_bytes().to_vec()
    };
    #[cfg(not(unix))]
    let bytes = path.to_string_lossy().into_owned().into_bytes();
    std::ffi::CString::new(bytes).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            format!("VCD path contains a NUL byte: {}", path.display()),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn port_tables_are_consistent() {
        for (name, width) in CanChannelIn::PORTS.iter().chain(CanChannelOut::PORTS) {
            assert!(*width >= 1 && *width <= 64, "{name}");
        }
    }

    #[test]
    fn unavailable_reason_matches_availability() {
        assert_eq!(available(), unavailable_reason().is_none());
        assert_eq!(available(), verilator_version().is_some());
    }
}
