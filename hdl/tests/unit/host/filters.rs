//! Tests of `drcc_hdl::host::filters`: the filter registers of DRCC contract
//! §11.1 (cfg registers: stored in reset mode, refused outside it, cleared by
//! `rst`), with the addresses and fields from the register table.

use drcc_hdl::host::filters::*;
use drcc_hdl::host::registers::{self as map, MAP};
use rust_hdl::prelude::*;

/// One clock: inputs set before the edge, outputs read after it.
fn clock(uut: &mut FilterRegs) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

fn write(uut: &mut FilterRegs, index: u32, value: u32) {
    uut.wr.next = true;
    uut.adr.next = (index as u64).into();
    uut.wdat.next = (value as u64).into();
    clock(uut);
    uut.wr.next = false;
}

/// The word at `index` and whether the block claims it (before the edge).
fn read(uut: &mut FilterRegs, index: u32) -> (bool, u32) {
    uut.adr.next = (index as u64).into();
    assert!(simulate(uut, 100));
    (uut.hit.val(), uut.word.val().index() as u32)
}

fn fresh() -> FilterRegs {
    let mut uut = FilterRegs::default();
    uut.connect_all();
    uut.wr.next = false;
    uut.reset_mode.next = true;
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut
}

/// §11.1: in reset mode the four words are stored as written; `FILT_IDk[31]`
/// does not exist and reads 0; the enable bit is `FILT_MASKk[31]`.
#[test]
fn the_filters_are_stored_in_reset_mode() {
    let mut uut = fresh();
    let enable = MAP.field("FILT_MASK0", "enable").put(1);
    let ide = MAP.field("FILT_ID0", "ide").put(1);
    write(&mut uut, map::FILT_ID0, 0x123 | ide | 0x8000_0000);
    write(&mut uut, map::FILT_MASK0, 0x7FF | ide | enable);
    write(&mut uut, map::FILT_ID1, 0x1ABC_DEF0);
    write(&mut uut, map::FILT_MASK1, 0x1FFF_FFFF);
    assert_eq!(read(&mut uut, map::FILT_ID0), (true, 0x123 | ide));
    assert_eq!(
        read(&mut uut, map::FILT_MASK0),
        (true, 0x7FF | ide | enable)
    );
    assert_eq!(read(&mut uut, map::FILT_ID1), (true, 0x1ABC_DEF0));
    assert_eq!(read(&mut uut, map::FILT_MASK1), (true, 0x1FFF_FFFF));
    assert_eq!(uut.mask0.val().index() as u32, 0x7FF | ide | enable);
    assert_eq!(uut.id1.val().index() as u32, 0x1ABC_DEF0);
    assert_eq!(
        read(&mut uut, map::CAP_B),
        (false, 0),
        "not a filter register"
    );
}

/// §9, §11.1: outside reset mode a write is refused and changes nothing;
/// `rst` clears the filters (disabled).
#[test]
fn outside_reset_mode_a_filter_write_is_refused() {
    let mut uut = fresh();
    write(&mut uut, map::FILT_MASK1, 0x8000_0001);
    uut.reset_mode.next = false;
    uut.adr.next = (map::FILT_MASK1 as u64).into();
    assert!(simulate(&mut uut, 100));
    assert!(uut.illegal.val(), "refused outside reset mode");
    write(&mut uut, map::FILT_MASK1, 0x7FFF_FFFF);
    assert_eq!(read(&mut uut, map::FILT_MASK1), (true, 0x8000_0001));
    uut.adr.next = (map::TX_ID as u64).into();
    assert!(simulate(&mut uut, 100));
    assert!(!uut.illegal.val(), "other registers are not this block's");
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    assert_eq!(read(&mut uut, map::FILT_MASK1), (true, 0));
}

#[test]
fn filter_registers_synthesize() {
    let mut uut = FilterRegs::default();
    uut.connect_all();
    crate::synth_check::yosys_check("filter_regs", &generate_verilog(&uut));
}
