//! RX FIFO (DRCC contract §7): one synchronous RAM of `depth` entries x 116 bits
//! (the 99 frame bits of the channel `rx_*` ports, in [99] the channel the
//! frame came from, in [115:100] its timestamp, §11.2), `head[4:0]`, `count[5:0]`. The read data register is loaded
//! at every edge from `head`; the RX_* registers read it. `rx_ready` (RX_ID[31])
//! is `count != 0` registered (0 in reset mode). The writer (`dedup.rs`)
//! writes only when not full, the register block pops only when not empty.
//!
//! Generation parameter `depth` (4, 8, 16 or 32; `crate::config`): the pointers
//! keep their 5 bits and wrap at `depth` through `mask = depth - 1`, so a smaller
//! FIFO is the same logic with constant-zero upper pointer bits, which synthesis
//! removes; `count` keeps its 6 bits (the `STATUS` field).
//!
//! Block RAM without read-before-write emulation (`super::bram`): the read
//! address is `head + pop`, and the read is disabled at an edge where it meets
//! the write (`wr` with `count == pop`). Equivalence with the contract's RAM:
//! - `count == 0`, a write and no pop: the read data register already holds
//!   `mem[head]` as before this edge (the previous edge read the same address —
//!   `head` only moves with a pop, the read address follows it — and wrote
//!   nothing there: it would have left `count != 0`), so holding it is exact.
//! - at a pop edge the read data loaded is never observed: the pop is a
//!   Wishbone write whose ack blocks the access at the next edge (§2), and the
//!   next edge reads the new `head` as the contract does. Reading `head + 1`
//!   there keeps the read data one step ahead for the case above.

use super::bram::Bram;
use crate::channel::sized::Param;
use rust_hdl::prelude::*;

/// RX FIFO.
#[derive(LogicBlock)]
pub struct RxFifo {
    // clock and clear (rst or reset mode: emptied)
    /// System clock.
    pub clk: Signal<In, Clock>,
    /// `rst` or reset mode: the FIFO is emptied.
    pub clear: Signal<In, Bit>,
    // write side (writer FSM) and pop (RX_CMD)
    /// Write `wr_data` behind the last entry at this edge (only when not full).
    pub wr: Signal<In, Bit>,
    /// The entry: [115:100] timestamp, [99] channel, [98:0] frame (the TX RAM's layout).
    pub wr_data: Signal<In, Bits<116>>,
    /// `RX_CMD` pop: the head leaves at this edge (only when not empty).
    pub pop: Signal<In, Bit>,
    // outputs
    /// Entries in the FIFO (`STATUS.rx_count`).
    pub count: Signal<Out, Bits<6>>,
    /// The head entry (the RAM's read data register), laid out as `wr_data`.
    pub rd_data: Signal<Out, Bits<116>>,
    /// `RX_ID.rx_ready`: `count != 0` registered (0 in reset mode).
    pub rx_ready: Signal<Out, Bit>,
    ram: Bram<Bits<116>, 5>,
    /// `depth - 1`: the pointer wrap (generation parameter).
    mask: Param<5, 31>,
    /// FIFO head (public for lock-step probes).
    pub head: DFF<Bits<5>>,
    cnt: DFF<Bits<6>>,
    ready: DFF<Bit>,
    pop5: Signal<Local, Bits<5>>,
    one5: Constant<Bits<5>>,
    one6: Constant<Bits<6>>,
    zero5: Constant<Bits<5>>,
    zero6: Constant<Bits<6>>,
}

impl Default for RxFifo {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            clear: Default::default(),
            wr: Default::default(),
            wr_data: Default::default(),
            pop: Default::default(),
            count: Default::default(),
            rd_data: Default::default(),
            rx_ready: Default::default(),
            ram: Default::default(),
            mask: Default::default(),
            head: Default::default(),
            cnt: Default::default(),
            ready: Default::default(),
            pop5: Default::default(),
            one5: Constant::new(1.into()),
            one6: Constant::new(1.into()),
            zero5: Constant::new(0.into()),
            zero6: Constant::new(0.into()),
        }
    }
}

impl RxFifo {
    /// An RX FIFO of `depth` entries (a power of two, 4..32).
    pub fn new(depth: usize) -> Self {
        assert!(depth.is_power_of_two() && (4..=32).contains(&depth));
        Self {
            mask: Param::new(depth as u64 - 1),
            ..Default::default()
        }
    }
}

impl Logic for RxFifo {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, head, cnt, ready);
        self.ram.clk.next = self.clk.val();
        self.pop5.next = bit_cast::<5, 1>(self.pop.val().into());
        self.ram.read_address.next = (self.head.q.val() + self.pop5.val()) & self.mask.val();
        self.ram.read_enable.next =
            !(self.wr.val() & (self.cnt.q.val().get_bits::<5>(0) == self.pop5.val()));
        self.ram.write_enable.next = self.wr.val();
        self.ram.write_address.next =
            (self.head.q.val() + self.cnt.q.val().get_bits::<5>(0)) & self.mask.val();
        self.ram.write_data.next = self.wr_data.val();
        self.rd_data.next = self.ram.read_data.val();

        self.head.d.next = self.head.q.val();
        if self.pop.val() {
            self.head.d.next = (self.head.q.val() + self.one5.val()) & self.mask.val();
        }
        self.cnt.d.next = self.cnt.q.val();
        if self.wr.val() & !self.pop.val() {
            self.cnt.d.next = self.cnt.q.val() + self.one6.val();
        } else if !self.wr.val() & self.pop.val() {
            self.cnt.d.next = self.cnt.q.val() - self.one6.val();
        }
        // rx_ready: the FIFO was not empty at the previous edge, so the read data
        // register already holds the head written into an empty FIFO
        self.ready.d.next = self.cnt.q.val() != self.zero6.val();
        if self.clear.val() {
            self.ready.d.next = false;
            self.head.d.next = self.zero5.val();
            self.cnt.d.next = self.zero6.val();
        }
        self.count.next = self.cnt.q.val();
        self.rx_ready.next = self.ready.q.val();
    }
}
