//! Tests of `drcc_hdl::pelican::rbsa` against the SJA1000 data sheet's RBSA
//! (6.4.17: the start address of the next frame in the 64-byte RX FIFO, each
//! frame taking FI, 2 (standard) or 4 (extended) identifier bytes and its data
//! bytes; pelican_contract.md P-RX-4).

use drcc_hdl::pelican::rbsa::Rbsa;
use rust_hdl::prelude::*;

fn clock(uut: &mut Rbsa) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

fn fresh() -> Rbsa {
    let mut uut = Rbsa::default();
    uut.connect_all();
    uut.pop.next = false;
    uut.write.next = false;
    uut.ide.next = false;
    uut.rtr.next = false;
    uut.dlc.next = 0u64.into();
    uut.wdata.next = 0u64.into();
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut
}

/// Releases a frame; returns RBSA after the edge.
fn release(uut: &mut Rbsa, ide: bool, rtr: bool, dlc: u64) -> u64 {
    uut.pop.next = true;
    uut.ide.next = ide;
    uut.rtr.next = rtr;
    uut.dlc.next = dlc.into();
    clock(uut);
    uut.pop.next = false;
    uut.rbsa.val().to_u64()
}

#[test]
fn each_release_advances_by_the_frames_fifo_bytes() {
    let mut uut = fresh();
    assert_eq!(uut.rbsa.val().to_u64(), 0);
    assert_eq!(release(&mut uut, false, false, 8), 11, "3 + 8");
    assert_eq!(release(&mut uut, true, false, 8), 24, "+ 5 + 8");
    assert_eq!(release(&mut uut, false, false, 0), 27, "+ 3");
    assert_eq!(release(&mut uut, true, true, 8), 32, "remote: + 5, no data");
    assert_eq!(release(&mut uut, false, false, 15), 43, "DLC 15: 8 bytes");
    assert_eq!(release(&mut uut, false, false, 2), 48, "+ 5");
    assert_eq!(release(&mut uut, true, false, 3), 56, "+ 8");
    assert_eq!(release(&mut uut, true, false, 8), 5, "+ 13, wraps at 64");
}

#[test]
fn a_write_sets_it_and_rst_clears_it() {
    let mut uut = fresh();
    uut.write.next = true;
    uut.wdata.next = 0x3Fu64.into();
    clock(&mut uut);
    uut.write.next = false;
    assert_eq!(uut.rbsa.val().to_u64(), 63, "six bits");
    assert_eq!(release(&mut uut, false, false, 1), 3, "63 + 4 mod 64");
    uut.rst.next = true;
    clock(&mut uut);
    assert_eq!(uut.rbsa.val().to_u64(), 0);
}

#[test]
fn rbsa_synthesizes() {
    let mut uut = Rbsa::default();
    uut.connect_all();
    crate::synth_check::yosys_check("rbsa", &generate_verilog(&uut));
}
