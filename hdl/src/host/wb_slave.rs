//! Wishbone B4 classic slave front end shared by the register blocks of the DRCC
//! (`super::wishbone`) and the hub (`crate::hub::registers`): the bus handshake
//! and the interrupt logic (DRCC contract §2, §8; hub contract §8).
//!
//! - Handshake (Wishbone B4 3.2, classic cycle, one-clock ack): a transaction is
//!   taken at an edge where `cyc & stb & !ack`; then `ack <= 1` and, for a read,
//!   `dat_o <=` the addressed register's value before the edge (`rdata`). At every
//!   other edge `ack <= 0`, `dat_o <= 0`. So every access takes two clocks.
//!   The register block turns the ack of a refused write into `ERR`
//!   (bus_contract.md §1) with a flip-flop of its own: `refused` must not come
//!   back into this block, whose `wr` it depends on.
//! - Interrupts: `INT_STATUS` is write-1-to-clear and an event at the same edge
//!   wins: `int_status <= (int_status & !w1c) | events`; `INT_ENABLE` is stored
//!   when `int_enable_we`; `irq <= |(int_status & int_enable)` (registered, so it
//!   follows `INT_STATUS` by one clock).
//!
//! The register block decodes the address and data (`wr` comes out
//! combinationally) and hands back the read value, the events and the W1C bits.

use rust_hdl::prelude::*;

/// Wishbone B4 classic slave handshake and interrupt status of `W` events.
#[derive(LogicBlock)]
pub struct WbSlave<const W: usize> {
    // ---- clock and reset ----
    /// System clock (`clk_i`).
    pub clk: Signal<In, Clock>,
    /// Synchronous reset: clears ack, read data, interrupts.
    pub rst: Signal<In, Bit>,
    // ---- Wishbone bus (from the master) ----
    /// Cycle in progress.
    pub wb_cyc_i: Signal<In, Bit>,
    /// Strobe: this slave is addressed.
    pub wb_stb_i: Signal<In, Bit>,
    /// Write enable.
    pub wb_we_i: Signal<In, Bit>,
    // ---- Wishbone bus (to the master) ----
    /// Registered read data; 0 except the clock after a read is taken.
    pub wb_dat_o: Signal<Out, Bits<32>>,
    /// Registered acknowledge, one clock per access.
    pub wb_ack_o: Signal<Out, Bit>,
    /// Interrupt request: `|(INT_STATUS & INT_ENABLE)` one clock later.
    pub irq: Signal<Out, Bit>,
    // ---- to the register decoder ----
    /// A write is taken at this edge.
    pub wr: Signal<Out, Bit>,
    /// `INT_STATUS` (registered).
    pub int_status: Signal<Out, Bits<W>>,
    /// `INT_ENABLE` (registered).
    pub int_enable: Signal<Out, Bits<W>>,
    // ---- from the register decoder ----
    /// Value of the addressed register before the edge.
    pub rdata: Signal<In, Bits<32>>,
    /// Interrupt events at this edge (set `INT_STATUS` bits; win over `w1c`).
    pub events: Signal<In, Bits<W>>,
    /// `INT_STATUS` bits written 1 at this edge.
    pub w1c: Signal<In, Bits<W>>,
    /// `INT_ENABLE` is written at this edge ...
    pub int_enable_we: Signal<In, Bit>,
    /// ... with this value.
    pub int_enable_d: Signal<In, Bits<W>>,
    // ---- state ----
    /// An access is taken at this edge (`cyc & stb & !ack`).
    taken: Signal<Local, Bit>,
    ack_q: DFF<Bit>,
    dat_q: DFF<Bits<32>>,
    irq_q: DFF<Bit>,
    int_status_q: DFF<Bits<W>>,
    int_enable_q: DFF<Bits<W>>,
    zero_w: Constant<Bits<W>>,
    zero32: Constant<Bits<32>>,
}

impl<const W: usize> Default for WbSlave<W> {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wb_cyc_i: Default::default(),
            wb_stb_i: Default::default(),
            wb_we_i: Default::default(),
            wb_dat_o: Default::default(),
            wb_ack_o: Default::default(),
            irq: Default::default(),
            taken: Default::default(),
            wr: Default::default(),
            int_status: Default::default(),
            int_enable: Default::default(),
            rdata: Default::default(),
            events: Default::default(),
            w1c: Default::default(),
            int_enable_we: Default::default(),
            int_enable_d: Default::default(),
            ack_q: Default::default(),
            dat_q: Default::default(),
            irq_q: Default::default(),
            int_status_q: Default::default(),
            int_enable_q: Default::default(),
            zero_w: Constant::new(0.into()),
            zero32: Constant::new(0.into()),
        }
    }
}

impl<const W: usize> Logic for WbSlave<W> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, ack_q, dat_q, irq_q, int_status_q, int_enable_q);
        // classic cycle: take a request unless it is the one just acknowledged
        self.taken.next = self.wb_cyc_i.val() & self.wb_stb_i.val() & !self.ack_q.q.val();
        // written out rather than from `taken`, so that Verilator can order `wr`
        // apart from the read data the register block returns on it (no
        // circular logic, UNOPTFLAT)
        self.wr.next =
            self.wb_cyc_i.val() & self.wb_stb_i.val() & !self.ack_q.q.val() & self.wb_we_i.val();
        self.ack_q.d.next = self.taken.val();
        self.dat_q.d.next = self.zero32.val();
        if self.taken.val() & !self.wb_we_i.val() {
            self.dat_q.d.next = self.rdata.val();
        }

        // W1C: an event at the same edge wins over the clear
        self.int_status_q.d.next =
            (self.int_status_q.q.val() & !self.w1c.val()) | self.events.val();
        self.int_enable_q.d.next = self.int_enable_q.q.val();
        if self.int_enable_we.val() {
            self.int_enable_q.d.next = self.int_enable_d.val();
        }
        self.irq_q.d.next =
            (self.int_status_q.q.val() & self.int_enable_q.q.val()) != self.zero_w.val();

        if self.rst.val() {
            self.ack_q.d.next = false;
            self.dat_q.d.next = self.zero32.val();
            self.irq_q.d.next = false;
            self.int_status_q.d.next = self.zero_w.val();
            self.int_enable_q.d.next = self.zero_w.val();
        }

        self.wb_ack_o.next = self.ack_q.q.val();
        self.wb_dat_o.next = self.dat_q.q.val();
        self.irq.next = self.irq_q.q.val();
        self.int_status.next = self.int_status_q.q.val();
        self.int_enable.next = self.int_enable_q.q.val();
    }
}
