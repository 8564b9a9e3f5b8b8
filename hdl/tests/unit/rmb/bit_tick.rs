//! Tests of `drcc_hdl::rmb::bit_tick`.

use drcc_hdl::rmb::bit_tick::*;
use rust_hdl::prelude::*;

#[test]
fn bit_tick_period() {
    let mut uut = BitTick::default();
    uut.connect_all();
    uut.clk.next = Clock::from(false);
    uut.hold.next = true;
    uut.brp.next = 1.into();
    uut.tseg1.next = 4.into();
    uut.tseg2.next = 1.into();
    assert!(simulate(&mut uut, 100));
    let mut ticks = vec![];
    for cycle in 0..100 {
        uut.hold.next = cycle < 2;
        uut.clk.next = Clock::from(false);
        assert!(simulate(&mut uut, 100));
        if uut.tick.val() {
            ticks.push(cycle);
        }
        uut.clk.next = Clock::from(true);
        assert!(simulate(&mut uut, 100));
    }
    // (1+1) * (1 + 5 + 2) = 16 clocks per bit, first tick 16 clocks after hold.
    assert_eq!(&ticks[..3], &[17, 33, 49]);
    assert_eq!(uut.now.val(), Bits::<16>::from(ticks.len() as u64));
    crate::synth_check::yosys_check("bit_tick", &generate_verilog(&uut));
}
