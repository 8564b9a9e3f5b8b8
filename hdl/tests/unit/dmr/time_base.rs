//! Tests of `drcc_hdl::dmr::time_base`.

use drcc_hdl::dmr::time_base::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_time_base_periods() {
    let mut uut = DmrTimeBase::default();
    uut.connect_all();
    uut.tick_bits.next = 3.into();
    uut.cs_period.next = 2.into();
    uut.clear.next = true;
    let (mut ticks, mut dues) = (vec![], vec![]);
    for cycle in 0..40u32 {
        uut.clk.next = Clock::from(false);
        uut.clear.next = cycle == 0;
        // a bit tick every other clock
        uut.tick.next = cycle % 2 == 1;
        assert!(simulate(&mut uut, 50));
        if uut.period_due.val() {
            dues.push(cycle);
        }
        uut.clk.next = Clock::from(true);
        assert!(simulate(&mut uut, 50));
        if uut.dmr_tick.val() {
            ticks.push(cycle);
        }
    }
    // §3: one dmr_tick per 3 bit ticks (bit ticks at 1, 3, 5, ...: the third at 5).
    assert_eq!(&ticks[..3], &[5, 11, 17]);
    // §7: every second dmr_tick (seen the clock after it) is a period.
    assert_eq!(&dues[..2], &[12, 24]);
}

#[test]
fn dmr_time_base_synthesizes() {
    let mut uut = DmrTimeBase::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_time_base", &generate_verilog(&uut));
}
