//! The receive writer's block bench: `RxWriter` + `RxFifo` + `now`, and the
//! frame and FIFO-entry layouts the lock step compares.

use drcc_cosim::frame::Frame;
use drcc_hdl::memory::dedup::RxWriter;
use drcc_hdl::memory::rx_fifo::RxFifo;
use rust_hdl::prelude::*;

/// Test-only wrapper: the writer, the FIFO and `now` as `BitTick` provides it
/// (counts `tick`s, cleared by `clear`). Pops are gated by `count != 0` as the
/// register block does.
#[derive(LogicBlock, Default)]
pub struct RxBench {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub reset_mode: Signal<In, Bit>,
    pub dedup_on: Signal<In, Bit>,
    pub dmr: Signal<In, Bit>,
    pub first_copy: Signal<In, Bit>,
    pub acl: Signal<In, Bit>,
    pub release_set: Signal<In, Bit>,
    pub window: Signal<In, Bits<15>>,
    pub tick: Signal<In, Bit>,
    pub pop: Signal<In, Bit>,
    pub rxv_a: Signal<In, Bit>,
    pub rxv_b: Signal<In, Bit>,
    pub frame_a: Signal<In, Bits<99>>,
    pub frame_b: Signal<In, Bits<99>>,
    pub rxw: RxWriter,
    pub fifo: RxFifo,
    pub now: DFF<Bits<16>>,
}

impl Logic for RxBench {
    fn update(&mut self) {
        dff_setup!(self, clk, now);
        let clear = self.rst.val() | self.reset_mode.val();
        if self.tick.val() {
            self.now.d.next = self.now.q.val() + Bits::<16>::from(1u64);
        }
        if clear {
            self.now.d.next = Bits::<16>::from(0u64);
        }
        let w = &mut self.rxw;
        w.clk.next = self.clk.val();
        w.rst.next = self.rst.val();
        w.clear.next = clear;
        w.dedup_on.next = self.dedup_on.val();
        w.window.next = self.window.val();
        w.now.next = self.now.q.val();
        w.tick.next = self.tick.val();
        w.rxv_a.next = self.rxv_a.val();
        w.rxv_b.next = self.rxv_b.val();
        w.frame_a.next = self.frame_a.val();
        w.frame_b.next = self.frame_b.val();
        w.fifo_count.next = self.fifo.count.val();
        // the core's wiring (DMR contract §8.1): the ACL rule unless first copy
        // with a history
        w.acl_rule.next = self.dmr.val() & !(self.first_copy.val() & self.dedup_on.val());
        w.count_pcl.next = self.dmr.val();
        w.acl.next = self.acl.val();
        w.release_set.next = self.release_set.val();
        // the filters (DRCC contract §11.1) are the system lock step's: disabled here
        w.filt_id0.next = Bits::<31>::default();
        w.filt_mask0.next = Bits::<32>::default();
        w.filt_id1.next = Bits::<31>::default();
        w.filt_mask1.next = Bits::<32>::default();
        w.stats_clear.next = false;
        let nonempty = self.fifo.count.val().any();
        let f = &mut self.fifo;
        f.clk.next = self.clk.val();
        f.clear.next = clear;
        f.wr.next = self.rxw.fifo_wr.val();
        f.wr_data.next = self.rxw.fifo_data.val();
        f.pop.next = self.pop.val() & nonempty;
    }
}

/// The 99 frame bits of the channel `rx_*` ports: [98] rtr, [97] ide,
/// [96:68] id, [67:64] dlc, [63:0] data (byte 0 in [63:56]).
pub fn frame_bits(f: &Frame) -> Bits<99> {
    let mut b = Bits::<99>::default();
    b.set_bits::<64>(0, f.data_word().into());
    b.set_bits::<4>(64, (f.dlc as u64).into());
    b.set_bits::<29>(68, (f.id as u64).into());
    b.replace_bit(97, f.ide).replace_bit(98, f.rtr)
}

/// A FIFO entry: [99] channel, [98:0] frame.
pub fn entry_bits(e: &(Frame, u8)) -> Bits<100> {
    bit_cast::<100, 99>(frame_bits(&e.0)).replace_bit(99, e.1 != 0)
}
