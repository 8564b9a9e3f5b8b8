//! Tests of `drcc_hdl::host::ecss_regs`: the ECSS registers of DRCC contract
//! §12.1 (cfg registers: stored in reset mode, refused outside it; a write
//! that would store `ttoggle` 0, `period` 0 or a reserved bit refused as a
//! whole; `rst` sets the reset values), addresses from the register table.

use drcc_hdl::host::ecss_regs::*;
use drcc_hdl::host::registers as map;
use rust_hdl::prelude::*;

fn clock(uut: &mut EcssRegs) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

/// Writes `value` at `index`; whether the write was refused (before the edge).
fn write(uut: &mut EcssRegs, index: u32, value: u32) -> bool {
    uut.wr.next = true;
    uut.adr.next = (index as u64).into();
    uut.wdat.next = (value as u64).into();
    assert!(simulate(uut, 100));
    let refused = uut.illegal.val();
    clock(uut);
    uut.wr.next = false;
    refused
}

fn read(uut: &mut EcssRegs, index: u32) -> u32 {
    uut.adr.next = (index as u64).into();
    assert!(simulate(uut, 100));
    assert!(uut.hit.val(), "register {index} is the block's");
    uut.word.val().index() as u32
}

fn fresh() -> EcssRegs {
    let mut uut = EcssRegs::default();
    uut.connect_all();
    uut.reset_mode.next = true;
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut
}

/// §12.1's reset values: ttoggle 3, ntoggle 3, bdefault A, disabled; the
/// CANopen heartbeat of node 1 (0x701); a period of 100,000 bit times.
#[test]
fn reset_values_are_the_contracts() {
    let mut uut = fresh();
    assert_eq!(read(&mut uut, map::ECSS_CFG), 3 | 3 << 8);
    assert_eq!(read(&mut uut, map::ECSS_HB), 0x701);
    assert_eq!(read(&mut uut, map::ECSS_PERIOD), 100_000);
}

/// In reset mode legal words are stored as written; each illegal value of
/// §12.1 refuses the write as a whole and leaves the stored word.
#[test]
fn illegal_values_are_refused_and_not_stored() {
    let mut uut = fresh();
    let cfg = 5 | 2 << 8 | 1 << 24 | 1 << 31;
    assert!(!write(&mut uut, map::ECSS_CFG, cfg));
    assert_eq!(read(&mut uut, map::ECSS_CFG), cfg);
    for (what, bad) in [
        ("ttoggle 0", 2 << 8 | 1 << 31),
        ("ntoggle 256 in the reserved byte", 5 | 0x100 << 8),
        ("reserved bit 25", 5 | 1 << 25),
    ] {
        assert!(write(&mut uut, map::ECSS_CFG, bad), "{what}: refused");
        assert_eq!(read(&mut uut, map::ECSS_CFG), cfg, "{what}: not stored");
    }
    assert!(!write(&mut uut, map::ECSS_HB, 1 << 29 | 0x1234_5678));
    assert_eq!(read(&mut uut, map::ECSS_HB), 1 << 29 | 0x1234_5678);
    assert!(write(&mut uut, map::ECSS_HB, 1 << 30 | 0x700));
    assert_eq!(read(&mut uut, map::ECSS_HB), 1 << 29 | 0x1234_5678);
    assert!(!write(&mut uut, map::ECSS_PERIOD, 0xFF_FFFF));
    assert_eq!(read(&mut uut, map::ECSS_PERIOD), 0xFF_FFFF);
    for bad in [0, 1 << 24 | 5] {
        assert!(
            write(&mut uut, map::ECSS_PERIOD, bad),
            "period {bad:#x}: refused"
        );
        assert_eq!(read(&mut uut, map::ECSS_PERIOD), 0xFF_FFFF);
    }
}

/// §9: outside reset mode every write is refused, legal or not.
#[test]
fn writes_outside_reset_mode_are_refused() {
    let mut uut = fresh();
    uut.reset_mode.next = false;
    assert!(write(&mut uut, map::ECSS_CFG, 7));
    assert!(write(&mut uut, map::ECSS_PERIOD, 10));
    assert_eq!(read(&mut uut, map::ECSS_CFG), 3 | 3 << 8);
    assert_eq!(read(&mut uut, map::ECSS_PERIOD), 100_000);
}

#[test]
fn ecss_regs_synthesize() {
    let mut uut = EcssRegs::default();
    uut.connect_all();
    crate::synth_check::yosys_check("ecss_regs", &generate_verilog(&uut));
}
