//! The SJA1000 receive window (pelican_contract.md P-RX-2; SJA1000 data sheet
//! 6.4.14 "receive buffer"): the RX FIFO's head frame as the bytes at 16..28 in
//! operating mode.
//!
//! 16 = FI {FF, RTR, 0, 0, DLC}. Standard: 17 = `id[10:3]`, 18 = {`id[2:0]`,
//! RTR, 0000}, 19..26 = data bytes 1..8, 27 and 28 read 0 (the SJA1000 shows
//! the next FIFO bytes there). Extended: 17 = `id[28:21]`, 18 = `id[20:13]`, 19
//! = `id[12:5]`, 20 = {`id[4:0]`, RTR, 00}, 21..28 = data bytes 1..8. The FIFO
//! holds frames as the channels deliver them (timing contract §4.4: bytes past
//! min(DLC, 8) and every byte of a remote frame are 0) and self-received
//! frames normalized (DRCC contract §6), so the data bytes a frame lacks read 0
//! as the contract asks. Combinational; the register block reads it only in
//! operating mode and only for 16..28.

use crate::channel::sized::Const;
use rust_hdl::prelude::*;

/// The receive window's byte at a register address.
#[derive(LogicBlock, Default)]
pub struct RxWindow {
    /// The RX FIFO's head frame: [98] rtr, [97] ide, [96:68] id, [67:64] dlc,
    /// [63:0] data (byte 1 of the data sheet in [63:56]).
    pub frame: Signal<In, Bits<99>>,
    /// The register address; 16..28 are the window.
    pub addr: Signal<In, Bits<7>>,
    /// The byte at `addr` (0 outside 16..28).
    pub rdata: Signal<Out, Bits<8>>,
    /// FI, the identifier bytes and the data bytes of the frame.
    fi: Signal<Local, Bits<8>>,
    rtr: Signal<Local, Bit>,
    id: Signal<Local, Bits<29>>,
    data: Signal<Local, Bits<64>>,
    /// The window's byte index `addr - 16`, and whether `addr` is 16..31.
    idx: Signal<Local, Bits<4>>,
    in_window: Signal<Local, Bit>,
    page_window: Const<3, 1>,
    zero8: Const<8, 0>,
}

impl Logic for RxWindow {
    #[hdl_gen]
    fn update(&mut self) {
        self.rtr.next = self.frame.val().get_bit(98);
        self.id.next = self.frame.val().get_bits::<29>(68);
        self.data.next = self.frame.val().get_bits::<64>(0);
        // FI: [7] FF, [6] RTR, [5:4] 0, [3:0] DLC as received.
        self.fi.next = (bit_cast::<8, 1>(self.frame.val().get_bit(97).into()) << 7)
            | (bit_cast::<8, 1>(self.rtr.val().into()) << 6)
            | bit_cast::<8, 4>(self.frame.val().get_bits::<4>(64));
        self.idx.next = self.addr.val().get_bits::<4>(0);
        self.in_window.next = self.addr.val().get_bits::<3>(4) == self.page_window.val();

        self.rdata.next = self.zero8.val();
        if self.in_window.val() {
            if self.frame.val().get_bit(97) {
                // extended
                match self.idx.val().index() {
                    0 => self.rdata.next = self.fi.val(),
                    1 => self.rdata.next = self.id.val().get_bits::<8>(21),
                    2 => self.rdata.next = self.id.val().get_bits::<8>(13),
                    3 => self.rdata.next = self.id.val().get_bits::<8>(5),
                    4 => {
                        self.rdata.next = (bit_cast::<8, 5>(self.id.val().get_bits::<5>(0)) << 3)
                            | (bit_cast::<8, 1>(self.rtr.val().into()) << 2)
                    }
                    5 => self.rdata.next = self.data.val().get_bits::<8>(56),
                    6 => self.rdata.next = self.data.val().get_bits::<8>(48),
                    7 => self.rdata.next = self.data.val().get_bits::<8>(40),
                    8 => self.rdata.next = self.data.val().get_bits::<8>(32),
                    9 => self.rdata.next = self.data.val().get_bits::<8>(24),
                    10 => self.rdata.next = self.data.val().get_bits::<8>(16),
                    11 => self.rdata.next = self.data.val().get_bits::<8>(8),
                    12 => self.rdata.next = self.data.val().get_bits::<8>(0),
                    _ => {}
                }
            } else {
                match self.idx.val().index() {
                    0 => self.rdata.next = self.fi.val(),
                    1 => self.rdata.next = self.id.val().get_bits::<8>(3),
                    2 => {
                        self.rdata.next = (bit_cast::<8, 3>(self.id.val().get_bits::<3>(0)) << 5)
                            | (bit_cast::<8, 1>(self.rtr.val().into()) << 4)
                    }
                    3 => self.rdata.next = self.data.val().get_bits::<8>(56),
                    4 => self.rdata.next = self.data.val().get_bits::<8>(48),
                    5 => self.rdata.next = self.data.val().get_bits::<8>(40),
                    6 => self.rdata.next = self.data.val().get_bits::<8>(32),
                    7 => self.rdata.next = self.data.val().get_bits::<8>(24),
                    8 => self.rdata.next = self.data.val().get_bits::<8>(16),
                    9 => self.rdata.next = self.data.val().get_bits::<8>(8),
                    10 => self.rdata.next = self.data.val().get_bits::<8>(0),
                    _ => {}
                }
            }
        }
    }
}
