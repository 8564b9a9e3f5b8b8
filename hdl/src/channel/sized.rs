//! A sized constant that carries its value in its type, so a block built only
//! of signals, flip-flops and these constants can `#[derive(Default)]`.
//!
//! rust-hdl's `Constant<T>` has no `Default` (its value is given at run time),
//! which forces a hand-written `Default` listing every field of the block.
//! `Const<N, V>` is the same atom (a Verilog `localparam` of N bits), with the
//! value fixed at compile time: adding one is a one-line field declaration.

use rust_hdl::prelude::*;

/// An N-bit constant of value V, emitted as a sized `localparam`.
#[derive(Copy, Clone, Debug)]
pub struct Const<const N: usize, const V: u64>(Constant<Bits<N>>);

impl<const N: usize, const V: u64> Default for Const<N, V> {
    fn default() -> Self {
        Self(Constant::new(Bits::<N>::from(V)))
    }
}

impl<const N: usize, const V: u64> Const<N, V> {
    /// The value, usable in HDL kernels (`self.k.val()`).
    pub fn val(&self) -> Bits<N> {
        self.0.val()
    }
}

/// The atom and block traits of a sized constant newtype (`Const`, `LastIndex`).
macro_rules! sized_constant_atom {
    ($ty:ident, $p:ident, $pt:ty) => {
        impl<const N: usize, const $p: $pt> Logic for $ty<N, $p> {
            fn update(&mut self) {}
        }

        impl<const N: usize, const $p: $pt> Atom for $ty<N, $p> {
            fn bits(&self) -> usize {
                self.0.bits()
            }
            fn connected(&self) -> bool {
                true
            }
            fn changed(&self) -> bool {
                false
            }
            fn kind(&self) -> AtomKind {
                AtomKind::Constant
            }
            fn descriptor(&self) -> TypeDescriptor {
                self.0.descriptor()
            }
            fn vcd(&self) -> VCDValue {
                self.0.vcd()
            }
            fn verilog(&self) -> VerilogLiteral {
                self.0.verilog()
            }
            fn id(&self) -> usize {
                self.0.id()
            }
            fn constraints(&self) -> Vec<PinConstraint> {
                vec![]
            }
        }

        impl<const N: usize, const $p: $pt> Block for $ty<N, $p> {
            fn connect_all(&mut self) {}
            fn update_all(&mut self) {}
            fn has_changed(&self) -> bool {
                false
            }
            fn accept(&self, name: &str, probe: &mut dyn Probe) {
                probe.visit_atom(name, self);
            }
        }
    };
}

sized_constant_atom!(Const, V, u64);

/// An N-bit constant of value `M - 1` (0 for `M = 0`): the last index of a block
/// generated with `M` of something (mailboxes), which `Const` cannot spell while
/// `M` is a generic parameter (no arithmetic on const generics in stable Rust).
#[derive(Copy, Clone, Debug)]
pub struct LastIndex<const N: usize, const M: usize>(Constant<Bits<N>>);

impl<const N: usize, const M: usize> Default for LastIndex<N, M> {
    fn default() -> Self {
        Self(Constant::new(Bits::<N>::from(M.saturating_sub(1) as u64)))
    }
}

impl<const N: usize, const M: usize> LastIndex<N, M> {
    /// The value, usable in HDL kernels (`self.last.val()`).
    pub fn val(&self) -> Bits<N> {
        self.0.val()
    }
}

sized_constant_atom!(LastIndex, M, usize);

/// An N-bit generation parameter: a constant whose default value `D` (the
/// proven default configuration) is in its type, so blocks keep
/// `#[derive(Default)]`, and whose value a block's `new(...)` may set to another
/// configuration's (RX FIFO depth, history size: `crate::config`).
#[derive(Copy, Clone, Debug)]
pub struct Param<const N: usize, const D: u64>(Constant<Bits<N>>);

impl<const N: usize, const D: u64> Default for Param<N, D> {
    fn default() -> Self {
        Self::new(D)
    }
}

impl<const N: usize, const D: u64> Param<N, D> {
    /// The parameter with value `v` (must fit N bits).
    pub fn new(v: u64) -> Self {
        assert!(N >= 64 || v < 1 << N, "parameter {v} does not fit {N} bits");
        Self(Constant::new(Bits::<N>::from(v)))
    }

    /// The value, usable in HDL kernels (`self.depth.val()`).
    pub fn val(&self) -> Bits<N> {
        self.0.val()
    }
}

sized_constant_atom!(Param, D, u64);
