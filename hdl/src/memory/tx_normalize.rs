//! Normalization of a frame at its push into a TX queue (DRCC contract §6): the
//! frame is stored as a receiver delivers it (timing contract §C.4.4), so that
//! the echo of §4.4 can compare the head message with a received frame bit for
//! bit. Combinational, on the 99-bit frame of the channel ports:
//!
//! - a base frame (`ide = 0`) keeps `id[10:0]`, `id[28:11]` reads 0;
//! - data bytes at index >= min(dlc, 8) read 0, all of them for a remote frame;
//! - `rtr`, `ide` and `dlc` as written.
//!
//! The channels transmit the same bits either way (a base frame sends `id[10:0]`,
//! a data field has min(dlc, 8) bytes, a remote frame none).
//! Frame layout (as the TX buffer): [98] rtr, [97] ide, [96:68] id, [67:64] dlc,
//! [63:0] data, byte 0 (the first on the bus) in [63:56].

use rust_hdl::prelude::*;

/// The normalized copy of a frame (contract §6 "Normalized").
#[derive(LogicBlock)]
pub struct FrameNormalizer {
    // ---- the staged frame ----
    /// The frame as staged in `TX_ID`..`TX_DATA1`.
    pub frame: Signal<In, Bits<99>>,
    // ---- the stored frame ----
    /// The frame as a receiver delivers it.
    pub normalized: Signal<Out, Bits<99>>,
    // ---- internals ----
    rtr: Signal<Local, Bit>,
    ide: Signal<Local, Bit>,
    id: Signal<Local, Bits<29>>,
    dlc: Signal<Local, Bits<4>>,
    data: Signal<Local, Bits<64>>,
    /// Data bytes delivered, when fewer than 8: `rtr ? 0 : dlc[2:0]`.
    len: Signal<Local, Bits<3>>,
    /// Bits of the data field past the delivered bytes: 8 x `len`.
    shift: Signal<Local, Bits<6>>,
    base_id: Constant<Bits<29>>,
    ones64: Constant<Bits<64>>,
    eight4: Constant<Bits<4>>,
    zero3: Constant<Bits<3>>,
}

impl Default for FrameNormalizer {
    fn default() -> Self {
        Self {
            frame: Default::default(),
            normalized: Default::default(),
            rtr: Default::default(),
            ide: Default::default(),
            id: Default::default(),
            dlc: Default::default(),
            data: Default::default(),
            len: Default::default(),
            shift: Default::default(),
            base_id: Constant::new(0x7FF.into()),
            ones64: Constant::new(u64::MAX.into()),
            eight4: Constant::new(8.into()),
            zero3: Constant::new(0.into()),
        }
    }
}

impl Logic for FrameNormalizer {
    #[hdl_gen]
    fn update(&mut self) {
        self.rtr.next = self.frame.val().get_bit(98);
        self.ide.next = self.frame.val().get_bit(97);
        self.dlc.next = self.frame.val().get_bits::<4>(64);
        // a base identifier is id[10:0]
        if self.ide.val() {
            self.id.next = self.frame.val().get_bits::<29>(68);
        } else {
            self.id.next = self.frame.val().get_bits::<29>(68) & self.base_id.val();
        }
        // the first min(dlc, 8) bytes (none of a remote frame) are the top
        // 8 x len bits: the mask is !(ones >> 8 x len), for len 0..7; with
        // dlc >= 8 all 8 bytes stay (a shift by 64 is avoided)
        if self.rtr.val() {
            self.len.next = self.zero3.val();
        } else {
            self.len.next = self.dlc.val().get_bits::<3>(0);
        }
        self.shift.next = bit_cast::<6, 3>(self.len.val()) << 3;
        if !self.rtr.val() & (self.dlc.val() >= self.eight4.val()) {
            self.data.next = self.frame.val().get_bits::<64>(0);
        } else {
            self.data.next =
                self.frame.val().get_bits::<64>(0) & !(self.ones64.val() >> self.shift.val());
        }
        self.normalized.next = (bit_cast::<99, 1>(self.rtr.val().into()) << 98)
            | (bit_cast::<99, 1>(self.ide.val().into()) << 97)
            | (bit_cast::<99, 29>(self.id.val()) << 68)
            | (bit_cast::<99, 4>(self.dlc.val()) << 64)
            | bit_cast::<99, 64>(self.data.val());
    }
}
