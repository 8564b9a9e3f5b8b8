//! Tests of `drcc_hdl::channel::bsp::rx_frame`.

use drcc_hdl::channel::bsp::rx_frame::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn clock<const H: u64>(uut: &mut RxFrame<H>) {
        assert!(simulate(uut, 100), "settles");
        uut.clk.next = Clock { clk: true };
        simulate(uut, 100);
        uut.clk.next = Clock { clk: false };
        simulate(uut, 100);
    }

    /// Feed the destuffed bits of a base data frame (ID 0x123, DLC 1, data
    /// 0xA5; ISO 11898-1 10.4.2 order, MSB first) and publish it.
    #[test]
    fn captures_a_base_frame() {
        let mut uut: RxFrame = RxFrame::default();
        feed_and_publish(&mut uut);
        // the published frame holds through the next frame's SOF (`rx_hold`)
        uut.clear.next = true;
        clock(&mut uut);
        uut.clear.next = false;
        assert_eq!(uut.rx_id.val(), Bits::<29>::from(0x123));
        assert_eq!(uut.rx_data.val(), Bits::<64>::from(0xA5u64 << 56));
    }

    /// `RX_HOLD = 0` (the DRCC's channels): the same frame at `rx_valid`, and
    /// the outputs follow the capture registers afterwards.
    #[test]
    fn without_hold_the_frame_is_valid_with_rx_valid() {
        let mut uut = RxFrame::<0>::default();
        feed_and_publish(&mut uut);
        uut.clear.next = true;
        clock(&mut uut);
        uut.clear.next = false;
        assert_eq!(
            uut.rx_id.val(),
            Bits::<29>::from(0),
            "SOF cleared the capture"
        );
        assert_eq!(uut.rx_data.val(), Bits::<64>::from(0));
    }

    /// The frame of `captures_a_base_frame`, checked at its `rx_valid`.
    fn feed_and_publish<const H: u64>(uut: &mut RxFrame<H>) {
        uut.connect_all();
        uut.rst.next = true;
        clock(uut);
        uut.rst.next = false;
        uut.clear.next = true;
        clock(uut);
        uut.clear.next = false;
        let id = [0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 1];
        let dlc = [0, 0, 0, 1];
        let data = [1, 0, 1, 0, 0, 1, 0, 1];
        for b in id {
            uut.sampled.next = b == 1;
            uut.shift_id.next = true;
            clock(uut);
        }
        uut.shift_id.next = false;
        uut.sampled.next = false; // RTR: data frame
        uut.take_srr_rtr.next = true;
        clock(uut);
        uut.take_srr_rtr.next = false;
        uut.take_ide.next = true; // IDE dominant: base frame
        clock(uut);
        uut.take_ide.next = false;
        for (n, b) in dlc.iter().enumerate() {
            uut.sampled.next = *b == 1;
            uut.take_dlc.next = true;
            uut.take_data_len.next = n == 3;
            if n == 3 {
                simulate(uut, 100);
                assert!(!uut.no_data.val(), "DLC 1: eight data bits");
            }
            clock(uut);
        }
        uut.take_dlc.next = false;
        uut.take_data_len.next = false;
        for (n, b) in data.iter().enumerate() {
            uut.sampled.next = *b == 1;
            uut.bit_cnt.next = (n as u64).into();
            uut.bit_cnt_inc.next = (n as u64 + 1).into();
            uut.take_data.next = true;
            clock(uut);
            uut.take_data.next = false;
            clock(uut);
            assert_eq!(uut.data_end.val(), n == 7, "last data bit at n = 7");
        }
        uut.publish.next = true;
        clock(uut);
        uut.publish.next = false;
        assert!(uut.rx_valid.val());
        assert_eq!(uut.rx_id.val(), Bits::<29>::from(0x123));
        assert!(!uut.rx_ide.val() && !uut.rx_rtr.val());
        assert_eq!(uut.rx_dlc.val(), Bits::<4>::from(1));
        assert_eq!(uut.rx_data.val(), Bits::<64>::from(0xA5u64 << 56));
        clock(uut);
        assert!(!uut.rx_valid.val(), "rx_valid is one clock");
        assert_eq!(
            uut.rx_id.val(),
            Bits::<29>::from(0x123),
            "until the next SOF"
        );
    }

    #[test]
    fn rx_frame_synthesizes() {
        let mut uut: RxFrame = RxFrame::default();
        uut.connect_all();
        crate::synth_check::yosys_check("rx_frame", &generate_verilog(&uut));
    }
}
