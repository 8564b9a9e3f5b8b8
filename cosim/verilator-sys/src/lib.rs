//! verilator-sys: the Verilated RTL tops of `rtl-out/` behind a small C ABI, plus
//! safe wrappers.
//!
//! The tops are found by their port tables `shim/<top>_ports.h`, which
//! `drcc generate` writes from the rust-hdl blocks (`drcc_hdl::tops::TOPS`).
//! `build.rs` turns each table into the Rust port structs `<Top>In` /
//! `<Top>Out`, the wrapper `<Top>` ([`CanChannel`], [`Drcc`], [`Hub`]) and a C++
//! shim, verilates `rtl-out/<top>.v` (override the directory with
//! `DRCC_RTL_DIR`) and links it all. Without Verilator or without the RTL the
//! crate still builds: [`available`] is then `false` and every `new` returns
//! [`VerilatorUnavailable`], unless Verilator is [`required`] (CI), which makes
//! that a build error instead.
//!
//! # When Verilator is required
//! One rule, [`required`] (from `drcc-tools`), used by the build script and by
//! every test and tool that skips without Verilator:
//! required iff `DRCC_REQUIRE_VERILATOR` or `CI` is set to a value other than
//! empty, `0`, `false`, `no` or `off` (case-insensitive).
//!
//! # Clocking and traces
//! [`CanChannel::step`] applies the inputs, evaluates `clk = 0`, then `clk = 1`
//! (one rising edge) and returns the outputs after the edge. When no trace is open
//! and [`CanChannel::fast_edge`] is true, it makes one eval with `clk = 1` instead,
//! after resetting the model's "previous clk" trigger state: Verilator settles the
//! input logic before the edge-triggered logic in one eval, so the outputs are the
//! same (the tests step an instance each way in lockstep and compare them), at
//! about 1.4 times the speed. When [`CanChannel::skips_settled_inputs`] is also
//! true, that eval is the shim's copy of Verilator's evaluation loop, which skips
//! the input-combinational region in a clock where no input changed (the model is
//! settled for those inputs already; `drcc::evalStep` in
//! `shim/drcc_shim_common.h` says why that is exact): about half the work of most
//! clocks, since a CAN input changes at most once per bit. [`CanChannel::set_exact`]
//! forces the two evals.
//! With a VCD trace open,
//! step number `n` (counted from 0 since the instance was created) dumps the
//! `clk = 0` phase at time `2n` and the `clk = 1` phase at `2n + 1`: one VCD time
//! unit is half a clock period, whatever `$timescale` the file header states.
//!
//! # When the RTL ports change
//! Nothing here is edited: change the block, run `drcc generate`, and the table,
//! the C structs and the Rust structs follow. The shim's compile checks that every
//! table port exists on the Verilated model and fits its C type; each `new()`
//! panics if the C and Rust layouts differ (a fingerprint of every field's name,
//! offset, size and width), which can only happen with a stale build.
//!
//! Each instance has its own `VerilatedContext`: several instances (the nodes of
//! one bus) can live in one process and be stepped alternately, on any thread,
//! but one instance is never stepped from two threads at once (`Send`, not `Sync`).

pub use drcc_tools::{required, REQUIRE_VARS};

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
                /// 0: two evals per step; 1: one eval; 2: one eval that skips the
                /// input-combinational region when no input changed.
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

            /// Whether those single evals also skip the input-combinational region
            /// in a clock where no input changed (see the crate docs).
            pub fn skips_settled_inputs() -> bool {
                // SAFETY: plain function without arguments.
                unsafe { $ffi::$fast_c() == 2 }
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

            /// No model, no fast edge.
            pub fn skips_settled_inputs() -> bool {
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

// The port structs, layout fingerprints and wrappers of every top, generated by
// build.rs from the tables `shim/<top>_ports.h` (see `build/tables.rs`):
// `CanChannelIn` / `CanChannelOut` / `can_channel_abi` / `CanChannel`,
// `DrccIn` / `DrccOut` / `drcc_abi` / `Drcc`, `HubIn` / `HubOut` / `hub_abi` / `Hub`.
include!(concat!(env!("OUT_DIR"), "/tops.rs"));

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
