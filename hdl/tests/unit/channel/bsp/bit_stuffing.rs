//! Tests of `drcc_hdl::channel::bsp::bit_stuffing`.

use drcc_hdl::channel::bsp::bit_stuffing::*;
use rust_hdl::prelude::*;

mod tests {
    use super::*;

    fn clock(uut: &mut BitStuffing) {
        assert!(simulate(uut, 100), "settles");
        uut.clk.next = Clock { clk: true };
        simulate(uut, 100);
        uut.clk.next = Clock { clk: false };
        simulate(uut, 100);
    }

    /// Sample one bit: a clock with `sample`, then an idle clock so the
    /// registered `at_stuff_bit` catches up, as between two real sample points.
    fn sample(uut: &mut BitStuffing, bit: bool, start: bool) {
        uut.sample.next = true;
        uut.sampled.next = bit;
        uut.start.next = start;
        clock(uut);
        uut.sample.next = false;
        uut.start.next = false;
        clock(uut);
    }

    /// 10.5: after SOF and four more dominant bits (five equal bits) the next
    /// bit is a stuff bit, recessive; after it the count starts again.
    #[test]
    fn five_equal_bits_make_a_stuff_bit() {
        let mut uut = BitStuffing::default();
        uut.connect_all();
        uut.rst.next = true;
        clock(&mut uut);
        uut.rst.next = false;
        clock(&mut uut);
        assert!(!uut.insert.val());
        sample(&mut uut, false, true); // SOF
        for _ in 0..3 {
            sample(&mut uut, false, false);
            assert!(!uut.insert.val());
        }
        sample(&mut uut, false, false); // fifth dominant bit
        assert!(uut.insert.val() && uut.at_stuff_bit.val());
        assert!(
            !uut.last.val(),
            "the stuff bit is the complement of dominant"
        );
        sample(&mut uut, true, false); // the stuff bit itself
        assert!(!uut.insert.val());
        assert!(uut.last.val());
        // Four more recessive bits make five with the stuff bit: stuff again.
        for _ in 0..4 {
            assert!(!uut.insert.val());
            sample(&mut uut, true, false);
        }
        assert!(uut.insert.val());
        // The region ends: no stuff bits after the CRC sequence.
        uut.stop.next = true;
        uut.sample.next = true;
        clock(&mut uut);
        uut.stop.next = false;
        uut.sample.next = false;
        clock(&mut uut);
        assert!(!uut.insert.val());
    }

    #[test]
    fn bit_stuffing_synthesizes() {
        let mut uut = BitStuffing::default();
        uut.connect_all();
        crate::synth_check::yosys_check("bit_stuffing", &generate_verilog(&uut));
    }
}
