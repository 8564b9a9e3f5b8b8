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

#[cfg(test)]
mod tests {
    use super::*;

    /// The 99-bit frame of the ports (data byte 0 in [63:56]).
    fn frame(rtr: bool, ide: bool, id: u32, dlc: u8, data: [u8; 8]) -> Bits<99> {
        let data = u64::from_be_bytes(data);
        (bit_cast::<99, 1>(rtr.into()) << 98)
            | (bit_cast::<99, 1>(ide.into()) << 97)
            | (bit_cast::<99, 29>((id as u64).into()) << 68)
            | (bit_cast::<99, 4>((dlc as u64).into()) << 64)
            | bit_cast::<99, 64>(data.into())
    }

    fn normalize(f: Bits<99>) -> Bits<99> {
        let mut uut = FrameNormalizer::default();
        uut.connect_all();
        uut.frame.next = f;
        assert!(simulate(&mut uut, 10));
        uut.normalized.val()
    }

    #[test]
    fn frame_normalizer_synthesizes() {
        let mut uut = FrameNormalizer::default();
        uut.connect_all();
        crate::synth_check::yosys_check("frame_normalizer", &generate_verilog(&uut));
    }

    /// Contract §6: the frame as a receiver delivers it, for every dlc.
    #[test]
    fn bytes_past_the_data_length_read_zero() {
        let bytes = [0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88];
        for dlc in 0..16u8 {
            let len = dlc.min(8) as usize;
            let mut kept = [0u8; 8];
            kept[..len].copy_from_slice(&bytes[..len]);
            let ext = 0x1ABC_DEF0;
            assert_eq!(
                normalize(frame(false, true, ext, dlc, bytes)),
                frame(false, true, ext, dlc, kept),
                "data frame, dlc {dlc}"
            );
            assert_eq!(
                normalize(frame(true, true, ext, dlc, bytes)),
                frame(true, true, ext, dlc, [0; 8]),
                "remote frame, dlc {dlc}"
            );
        }
    }

    #[test]
    fn a_base_identifier_is_its_low_11_bits() {
        let f = frame(false, false, 0x1FFF_F123, 8, [0xFF; 8]);
        assert_eq!(normalize(f), frame(false, false, 0x123, 8, [0xFF; 8]));
        let f = frame(false, true, 0x1FFF_F123, 0, [0; 8]);
        assert_eq!(normalize(f), f, "an extended identifier is kept");
    }
}
