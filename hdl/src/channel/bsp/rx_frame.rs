//! The receive frame (ISO 11898-1:2015, 10.4.2): the destuffed bits of the
//! frame on the bus, captured field by field, and the host-visible copy that is
//! published when the frame becomes valid (10.7: the last but one EOF bit).
//!
//! The protocol controller says which field the sampled bit belongs to (one
//! strobe per capture); this block only stores. The capture registers are not
//! reset: SOF clears what a frame needs cleared.
//!
//! Generation parameter `RX_HOLD` (`rx_hold` in the Verilog; 1 by default, the channel contract's
//! outputs): the `rx_*` outputs hold the published frame until the next one
//! (timing contract §5). With 0 (the DRCC's channels, whose every reader takes
//! the frame at `rx_valid`: the RX writer latches it, the DMR, echo and ECSS
//! logic compare it there) they show the capture registers instead, which at
//! `rx_valid` hold the same frame: the publish edge copies them, and nothing
//! changes them before the next frame's SOF, bit times later. The published
//! copy (99 flip-flops) then has no reader and synthesis removes it.

use crate::channel::sized::{Const, Param};
use rust_hdl::prelude::*;

/// The receive shift registers and the published frame.
#[derive(LogicBlock, Default)]
pub struct RxFrame<const RX_HOLD: u64 = 1> {
    /// Clock of the channel.
    pub clk: Signal<In, Clock>,
    /// Synchronous reset (of the published frame).
    pub rst: Signal<In, Bit>,
    /// The bus level at the sample point (true: recessive).
    pub sampled: Signal<In, Bit>,
    /// Position of the sampled bit in its field.
    pub bit_cnt: Signal<In, Bits<6>>,
    /// `bit_cnt + 1`, the position of the next bit (shared adder).
    pub bit_cnt_inc: Signal<In, Bits<7>>,
    // capture strobes from the protocol controller (at a sample point)
    /// SOF: clear the identifier, the data and RTR.
    pub clear: Signal<In, Bit>,
    /// An identifier bit (ID_A or ID_B): shift it in.
    pub shift_id: Signal<In, Bit>,
    /// The bit after ID_A: SRR (extended) or RTR (base), not known yet.
    pub take_srr_rtr: Signal<In, Bit>,
    /// The IDE bit; a dominant IDE makes the previous bit the RTR bit.
    pub take_ide: Signal<In, Bit>,
    /// The RTR bit of an extended frame.
    pub take_rtr_ext: Signal<In, Bit>,
    /// A DLC bit.
    pub take_dlc: Signal<In, Bit>,
    /// The last DLC bit: the data length is known.
    pub take_data_len: Signal<In, Bit>,
    /// A data bit.
    pub take_data: Signal<In, Bit>,
    /// 10.7: the frame is valid for this receiver: publish it.
    pub publish: Signal<In, Bit>,
    /// The data field has no bits (remote frame or DLC 0), valid with
    /// `take_data_len`.
    pub no_data: Signal<Out, Bit>,
    /// Registered: the next data bit is the last one (valid at a sample point).
    pub data_end: Signal<Out, Bit>,
    /// One clock: a received frame was published.
    pub rx_valid: Signal<Out, Bit>,
    /// Published identifier (base frame: ID[10:0]).
    pub rx_id: Signal<Out, Bits<29>>,
    /// Published IDE bit (extended frame).
    pub rx_ide: Signal<Out, Bit>,
    /// Published RTR bit (remote frame).
    pub rx_rtr: Signal<Out, Bit>,
    /// Published data length code.
    pub rx_dlc: Signal<Out, Bits<4>>,
    /// Published data, byte 0 in bits 63..56.
    pub rx_data: Signal<Out, Bits<64>>,
    /// 1: the `rx_*` outputs hold the published frame; 0: valid with
    /// `rx_valid` only (module doc).
    rx_hold: Param<1, RX_HOLD>,
    // capture registers
    id: DFF<Bits<29>>,
    srr_rtr: DFF<Bit>,
    ide: DFF<Bit>,
    rtr: DFF<Bit>,
    dlc: DFF<Bits<4>>,
    data: DFF<Bits<64>>,
    data_len: DFF<Bits<7>>,
    data_end_q: DFF<Bit>,
    // published frame
    rx_valid_q: DFF<Bit>,
    rx_id_q: DFF<Bits<29>>,
    rx_ide_q: DFF<Bit>,
    rx_rtr_q: DFF<Bit>,
    rx_dlc_q: DFF<Bits<4>>,
    rx_data_q: DFF<Bits<64>>,
    bus_bit: Signal<Local, Bits<1>>,
    dlc_n: Signal<Local, Bits<4>>,
    data_bits: Signal<Local, Bits<7>>,
    data_wr_idx: Signal<Local, Bits<6>>,
    zero7: Const<7, 0>,
    n7_64: Const<7, 64>,
    n6_63: Const<6, 63>,
    zero3: Const<3, 0>,
    zero4: Const<4, 0>,
    zero29: Const<29, 0>,
    zero64: Const<64, 0>,
}

impl<const RX_HOLD: u64> Logic for RxFrame<RX_HOLD> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, id, srr_rtr, ide, rtr, dlc, data, data_len, data_end_q, rx_valid_q, rx_id_q,
            rx_ide_q, rx_rtr_q, rx_dlc_q, rx_data_q
        );
        self.bus_bit.next = self.sampled.val().into();
        self.dlc_n.next = (self.dlc.q.val() << 1) | bit_cast::<4, 1>(self.bus_bit.val());
        // 10.4.2.4: a remote frame has no data; DLC 9..15 mean 8 bytes.
        if self.rtr.q.val() {
            self.data_bits.next = self.zero7.val();
        } else if self.dlc_n.val().get_bit(3) {
            self.data_bits.next = self.n7_64.val();
        } else {
            self.data_bits.next = bit_cast::<7, 3>(self.dlc_n.val().get_bits::<3>(0)) << 3;
        }
        // The same decision from the registers directly (data_bits is 0 exactly
        // when RTR is recessive or the DLC is 0): this output feeds the protocol
        // controller's next state, so it shares no signal with the capture logic
        // that the controller's strobes drive (no false loop for Verilator).
        self.no_data.next = self.rtr.q.val()
            || ((self.dlc.q.val().get_bits::<3>(0) == self.zero3.val()) && !self.sampled.val());
        self.data_wr_idx.next = self.n6_63.val() - self.bit_cnt.val();
        // Registered every clock; the next sample point is clocks away.
        self.data_end_q.d.next = self.bit_cnt_inc.val() == self.data_len.q.val();
        self.data_end.next = self.data_end_q.q.val();
        self.rx_valid_q.d.next = false;

        if self.shift_id.val() {
            self.id.d.next = (self.id.q.val() << 1) | bit_cast::<29, 1>(self.bus_bit.val());
        }
        if self.take_srr_rtr.val() {
            self.srr_rtr.d.next = self.sampled.val();
        }
        if self.take_ide.val() {
            self.ide.d.next = self.sampled.val();
            if !self.sampled.val() {
                self.rtr.d.next = self.srr_rtr.q.val();
            }
        }
        if self.take_rtr_ext.val() {
            self.rtr.d.next = self.sampled.val();
        }
        if self.take_dlc.val() {
            self.dlc.d.next = self.dlc_n.val();
        }
        if self.take_data_len.val() {
            self.data_len.d.next = self.data_bits.val();
        }
        if self.take_data.val() {
            self.data.d.next = self
                .data
                .q
                .val()
                .replace_bit(self.data_wr_idx.val().index(), self.sampled.val());
        }
        if self.clear.val() {
            self.id.d.next = self.zero29.val();
            self.data.d.next = self.zero64.val();
            self.rtr.d.next = false;
        }
        if self.publish.val() {
            self.rx_valid_q.d.next = true;
            self.rx_id_q.d.next = self.id.q.val();
            self.rx_ide_q.d.next = self.ide.q.val();
            self.rx_rtr_q.d.next = self.rtr.q.val();
            self.rx_dlc_q.d.next = self.dlc.q.val();
            self.rx_data_q.d.next = self.data.q.val();
        }
        self.rx_valid.next = self.rx_valid_q.q.val();
        if self.rx_hold.val().get_bit(0) {
            self.rx_id.next = self.rx_id_q.q.val();
            self.rx_ide.next = self.rx_ide_q.q.val();
            self.rx_rtr.next = self.rx_rtr_q.q.val();
            self.rx_dlc.next = self.rx_dlc_q.q.val();
            self.rx_data.next = self.rx_data_q.q.val();
        } else {
            self.rx_id.next = self.id.q.val();
            self.rx_ide.next = self.ide.q.val();
            self.rx_rtr.next = self.rtr.q.val();
            self.rx_dlc.next = self.dlc.q.val();
            self.rx_data.next = self.data.q.val();
        }
        if self.rst.val() {
            self.rx_valid_q.d.next = false;
            self.rx_id_q.d.next = self.zero29.val();
            self.rx_ide_q.d.next = false;
            self.rx_rtr_q.d.next = false;
            self.rx_dlc_q.d.next = self.zero4.val();
            self.rx_data_q.d.next = self.zero64.val();
        }
    }
}
