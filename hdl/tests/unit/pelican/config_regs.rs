//! Tests of `drcc_hdl::pelican::config_regs` against the SJA1000 data sheet's
//! BTR0/BTR1 (6.4.5), EWLR (6.4.10), ACR/AMR (6.4.15), CDR (6.5) and the
//! contract's P-CFG-1, P-CFG-2, P-CFG-5, P-BO-6 and §16 reset values.

use drcc_hdl::pelican::config_regs::ConfigRegs;
use rust_hdl::prelude::*;

fn clock(uut: &mut ConfigRegs) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

fn fresh() -> ConfigRegs {
    let mut uut = ConfigRegs::default();
    uut.connect_all();
    uut.wr.next = false;
    uut.addr.next = 0u64.into();
    uut.wdata.next = 0u64.into();
    uut.rm.next = true;
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut
}

/// A write taken at one edge; returns `reconfig` of that edge.
fn write(uut: &mut ConfigRegs, rm: bool, addr: u64, b: u64) -> bool {
    uut.wr.next = true;
    uut.rm.next = rm;
    uut.addr.next = addr.into();
    uut.wdata.next = b.into();
    assert!(simulate(uut, 100));
    let reconfig = uut.reconfig.val();
    clock(uut);
    uut.wr.next = false;
    reconfig
}

fn read(uut: &mut ConfigRegs, rm: bool, addr: u64) -> u64 {
    uut.rm.next = rm;
    uut.addr.next = addr.into();
    assert!(simulate(uut, 100));
    uut.rdata.val().to_u64()
}

#[test]
fn reset_values_are_the_contracts() {
    let mut uut = fresh();
    let got: Vec<u64> = [6, 7, 8, 13, 31]
        .iter()
        .map(|&a| read(&mut uut, true, a))
        .collect();
    assert_eq!(
        got,
        vec![0x00, 0x14, 0x00, 96, 0x00],
        "BTR0 BTR1 OCR EWLR CDR"
    );
    for k in 0..4 {
        assert_eq!(read(&mut uut, true, 16 + k), 0x00, "ACR{k}");
        assert_eq!(read(&mut uut, true, 20 + k), 0xFF, "AMR{k}");
    }
}

#[test]
fn btr_is_the_native_word_of_the_sja1000_timing() {
    let mut uut = fresh();
    // BTR0 = SJW 2 (code 1), BRP 3; BTR1 = SAM, TSEG2 3 (code 2), TSEG1 12 (code 11)
    write(&mut uut, true, 6, 0x43);
    write(&mut uut, true, 7, 0x80 | 0x20 | 0x0B);
    write(&mut uut, true, 13, 0x70);
    let w = uut.view_btr.val().to_u64();
    // P-CFG-2: cfg_brp = 2 x 3 + 1 = 7 (tq = 8 clocks = 2 x (BRP + 1))
    assert_eq!(w & 0x3F, 7, "brp");
    assert_eq!((w >> 24) & 0xF, 0, "brp high bits");
    assert_eq!((w >> 6) & 0xF, 0x0B, "tseg1 code");
    assert_eq!((w >> 10) & 0x7, 2, "tseg2 code");
    assert_eq!((w >> 13) & 0x3, 1, "sjw code");
    assert_eq!((w >> 15) & 1, 1, "triple sampling (SAM)");
    assert_eq!((w >> 16) & 0xFF, 0x70, "error warning limit");
    // BRP 63: 127 needs the high bit
    write(&mut uut, true, 6, 0x3F);
    let w = uut.view_btr.val().to_u64();
    assert_eq!((w & 0x3F) | ((w >> 24) & 1) << 6, 127);
}

#[test]
fn timing_writes_need_reset_mode_and_report_a_change() {
    let mut uut = fresh();
    assert!(!write(&mut uut, false, 6, 0x01), "operating mode: ignored");
    assert_eq!(read(&mut uut, false, 6), 0x00, "P-CFG-1");
    assert!(write(&mut uut, true, 6, 0x01), "P-BO-6: a change");
    assert!(
        !write(&mut uut, true, 6, 0x01),
        "an equal value is no change"
    );
    assert!(write(&mut uut, true, 13, 0x50), "EWLR changes");
    assert!(
        !write(&mut uut, true, 8, 0x1A),
        "OCR is no channel configuration"
    );
    assert_eq!(read(&mut uut, true, 8), 0x1A);
}

#[test]
fn cdr_keeps_bit_4_clear_and_only_cd_in_operating_mode() {
    let mut uut = fresh();
    write(&mut uut, true, 31, 0xFF);
    assert_eq!(read(&mut uut, true, 31), 0xEF, "P-CFG-5");
    write(&mut uut, false, 31, 0x00);
    assert_eq!(
        read(&mut uut, false, 31),
        0xE8,
        "operating mode: CD[2:0] only"
    );
}

#[test]
fn acceptance_registers_are_bytes_of_two_words_in_reset_mode() {
    let mut uut = fresh();
    for k in 0..4 {
        write(&mut uut, true, 16 + k, 0x10 + k);
        write(&mut uut, true, 20 + k, 0x20 + k);
    }
    assert_eq!(uut.acr.val().to_u64(), 0x1312_1110, "ACR0 in [7:0]");
    assert_eq!(uut.amr.val().to_u64(), 0x2322_2120, "AMR0 in [7:0]");
    assert_eq!(read(&mut uut, true, 18), 0x12);
    assert_eq!(read(&mut uut, true, 23), 0x23);
    assert_eq!(
        read(&mut uut, false, 18),
        0x00,
        "operating mode: the window's"
    );
    write(&mut uut, false, 16, 0xAA);
    assert_eq!(
        uut.acr.val().to_u64(),
        0x1312_1110,
        "the TX window in operating mode"
    );
}
