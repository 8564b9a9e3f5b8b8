//! Tests of `drcc_hdl::memory::tx_normalize`.

use drcc_hdl::memory::tx_normalize::*;
use rust_hdl::prelude::*;

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
