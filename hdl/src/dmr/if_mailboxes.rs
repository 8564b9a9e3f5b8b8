//! A block that exists only in a DRCC generated with DMR mailboxes (`M > 0`,
//! DMR contract §2): the mailbox engine and the identifier memory. With `M = 0`
//! the wrapper holds nothing, so the emitted Verilog has no such instance and
//! synthesis reports the DRCC without them (`drcc_m0`, `drcc synth`).
//!
//! rust-hdl walks it as an array (`name$0`), so an HDL kernel uses it like one:
//! `for i in 0..M.min(1) { self.dmr_eng[i].clk.next = ... }`.

use rust_hdl::prelude::*;
use std::ops::{Deref, DerefMut};

/// One `B` if `M > 0`, none if `M = 0`.
pub struct IfMailboxes<B, const M: usize>(Vec<B>);

impl<B: Default, const M: usize> Default for IfMailboxes<B, M> {
    fn default() -> Self {
        Self((0..M.min(1)).map(|_| B::default()).collect())
    }
}

impl<B, const M: usize> Deref for IfMailboxes<B, M> {
    type Target = Vec<B>;
    fn deref(&self) -> &Vec<B> {
        &self.0
    }
}

impl<B, const M: usize> DerefMut for IfMailboxes<B, M> {
    fn deref_mut(&mut self) -> &mut Vec<B> {
        &mut self.0
    }
}

impl<B: Block, const M: usize> Block for IfMailboxes<B, M> {
    fn connect_all(&mut self) {
        self.0.connect_all();
    }
    fn update_all(&mut self) {
        self.0.update_all();
    }
    fn has_changed(&self) -> bool {
        self.0.has_changed()
    }
    fn accept(&self, name: &str, probe: &mut dyn Probe) {
        self.0.accept(name, probe);
    }
}

impl<B: Logic, const M: usize> Logic for IfMailboxes<B, M> {
    fn update(&mut self) {}
}
