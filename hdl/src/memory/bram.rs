//! Single-clock block RAM with a registered, enabled read port, for the DRCC
//! memories (contract §6, §7). Same simulation semantics as rust-hdl's `RAM`
//! (a read at an edge returns the contents before that edge's write) plus a
//! read enable (`read_enable = 0` holds `read_data`).
//!
//! The memory carries yosys' `no_rw_check` attribute: a read and a write of the
//! same address at one edge is declared undefined, so yosys maps the RAM to
//! iCE40 `SB_RAM40_4K` cells directly instead of emulating read-before-write
//! (a one-clock write delay plus a bypass multiplexer: about 1 LUT4 and 2 FFs
//! per data bit). Every user therefore guarantees that the read data loaded at
//! an edge where the read and write addresses meet is never observed, or
//! disables the read there; each user's header says why its collisions are
//! unobservable.

use rust_hdl::prelude::*;
use std::collections::BTreeMap;

/// Block RAM: `2^N` words of `D`, one clock, read enable, undefined collisions.
#[derive(LogicBlock, Default)]
pub struct Bram<D: Synth, const N: usize> {
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// The word read at this edge.
    pub read_address: Signal<In, Bits<N>>,
    /// Load `read_data` at this edge; 0 holds it.
    pub read_enable: Signal<In, Bit>,
    /// Read data register: the word at `read_address` before this edge's write.
    pub read_data: Signal<Out, D>,
    /// The word written at this edge.
    pub write_address: Signal<In, Bits<N>>,
    /// The value written.
    pub write_data: Signal<In, D>,
    /// Write `write_data` at this edge.
    pub write_enable: Signal<In, Bit>,
    _sim: BTreeMap<Bits<N>, D>,
}

impl<D: Synth, const N: usize> Bram<D, N> {
    /// The simulated word at `address` (what a read would return): for lock-step
    /// benches that compare a memory's contents with a model's.
    pub fn peek(&self, address: Bits<N>) -> D {
        *self._sim.get(&address).unwrap_or(&D::default())
    }
}

impl<D: Synth, const N: usize> Logic for Bram<D, N> {
    fn update(&mut self) {
        if self.clk.pos_edge() {
            if self.read_enable.val() {
                self.read_data.next = *self
                    ._sim
                    .get(&self.read_address.val())
                    .unwrap_or(&D::default());
            }
            if self.write_enable.val() {
                self._sim
                    .insert(self.write_address.val(), self.write_data.val());
            }
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "\
(* no_rw_check *)
reg[{D}:0] mem[{Acount}:0];

always @(posedge clk) begin
   if (read_enable) begin
      read_data <= mem[read_address];
   end
end

always @(posedge clk) begin
   if (write_enable) begin
      mem[write_address] <= write_data;
   end
end
            ",
            D = D::BITS - 1,
            Acount = (1 << N) - 1,
        ))
    }
}
