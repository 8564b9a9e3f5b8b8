//! Tests of `drcc_hdl::pelican::extension` against the contract's extension
//! window (pelican_contract.md §13, P-X-1, P-X-2); the native window, 122..127,
//! is `native_window`'s.

use drcc_hdl::pelican::extension::ExtensionRegs;
use rust_hdl::prelude::*;

fn clock(uut: &mut ExtensionRegs) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

/// Keys: `XMODE` 0x44 (single A, error-passive, bom), `XK` 3; with or without DMR.
fn fresh(dmr: bool) -> ExtensionRegs {
    let mut uut = ExtensionRegs::new(0x44, 3, dmr, false);
    uut.connect_all();
    uut.wr.next = false;
    uut.rd.next = false;
    uut.addr.next = 0u64.into();
    uut.wdata.next = 0u64.into();
    uut.rm.next = true;
    uut.ev_switch.next = false;
    uut.ev_aux.next = false;
    uut.ev_dmr.next = false;
    uut.ev_domain.next = false;
    uut.ev_err_state.next = false;
    uut.ev_bus.next = false;
    uut.ev_ign.next = false;
    uut.ev_win.next = false;
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut
}

fn write(uut: &mut ExtensionRegs, addr: u64, b: u64) {
    uut.wr.next = true;
    uut.addr.next = addr.into();
    uut.wdata.next = b.into();
    clock(uut);
    uut.wr.next = false;
}

/// A read taken at one edge: the value before it.
fn read(uut: &mut ExtensionRegs, addr: u64) -> u64 {
    uut.rd.next = true;
    uut.addr.next = addr.into();
    assert!(simulate(uut, 100));
    let v = uut.rdata.val().to_u64();
    clock(uut);
    uut.rd.next = false;
    v
}

#[test]
fn identification_and_keys_after_reset() {
    let mut uut = fresh(true);
    assert_eq!(read(&mut uut, 112), 0x44, "XID0 'D'");
    assert_eq!(read(&mut uut, 113), 0x52, "XID1 'R'");
    assert_eq!(read(&mut uut, 114), 0x10, "XVER 1.0");
    assert_eq!(read(&mut uut, 115), 0x44, "XMODE: the keys");
    assert_eq!(read(&mut uut, 116), 3, "XK: the key");
    for a in [117, 120, 121] {
        assert_eq!(read(&mut uut, a), 0, "register {a} resets to 0");
    }
}

#[test]
fn p_x_1_keys_change_in_reset_mode_only() {
    let mut uut = fresh(true);
    uut.rm.next = false;
    write(&mut uut, 115, 0x01);
    assert_eq!(read(&mut uut, 115), 0x44, "operating mode: ignored");
    assert_eq!(read(&mut uut, 120) & 0x80, 0x80, "with XIR.ign");
    uut.rm.next = true;
    write(&mut uut, 115, 0x01);
    assert_eq!(read(&mut uut, 115), 0x01);
    write(&mut uut, 116, 0);
    assert_eq!(read(&mut uut, 116), 1, "k = 0 is stored as 1");
    write(&mut uut, 115, 0x21);
    assert_eq!(
        read(&mut uut, 115),
        0x01,
        "star without the star node: refused"
    );
    let mut uut = fresh(false);
    write(&mut uut, 115, 0x02);
    assert_eq!(
        read(&mut uut, 115),
        0x44,
        "DMR without the DMR function: refused"
    );
    assert_eq!(read(&mut uut, 120), 0x80, "XIR.ign alone");
}

#[test]
fn p_x_2_xir_is_status_cleared_by_a_read_an_event_winning() {
    let mut uut = fresh(true);
    uut.ev_switch.next = true;
    uut.ev_err_state.next = true;
    clock(&mut uut);
    uut.ev_switch.next = false;
    uut.ev_err_state.next = false;
    assert!(!uut.xir_pending.val(), "XIER 0: no request");
    write(&mut uut, 121, 0x01);
    assert!(uut.xir_pending.val(), "enabled switch bit: a request");
    // a read with an event at the same edge: the event stays
    uut.ev_aux.next = true;
    assert_eq!(read(&mut uut, 120), 0x11, "switch and err_state");
    uut.ev_aux.next = false;
    assert_eq!(
        read(&mut uut, 120),
        0x02,
        "the aux event of the read's edge"
    );
    assert_eq!(read(&mut uut, 120), 0x00);
}

/// P-X-2, P-X-4: the native window's refusal is the `XIR.win` event.
#[test]
fn p_x_4_a_refused_window_commit_sets_xir_win() {
    let mut uut = fresh(true);
    uut.ev_win.next = true;
    clock(&mut uut);
    uut.ev_win.next = false;
    assert_eq!(read(&mut uut, 120), 0x40, "XIR.win");
    assert_eq!(read(&mut uut, 120), 0x00, "cleared by the read");
}
