//! Tests of `drcc_hdl::pelican::native_window` against the contract's native
//! window (pelican_contract.md §13, P-X-3, P-X-4, §15), with the core's native
//! port played by the test: the access the block makes at an edge, the answer
//! the test gives in the clock after it.

use drcc_hdl::pelican::native_window::NativeWindow;
use rust_hdl::prelude::*;

fn clock(uut: &mut NativeWindow) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

/// After `rst`, in host reset mode, the native port answering nothing.
fn fresh() -> NativeWindow {
    let mut uut = NativeWindow::default();
    uut.connect_all();
    uut.wr.next = false;
    uut.addr.next = 0u64.into();
    uut.wdata.next = 0u64.into();
    uut.hrm.next = true;
    uut.nat_rdat.next = 0u64.into();
    uut.nat_err.next = false;
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut
}

/// The native access the block makes for a write of `b` to `addr`:
/// (`cyc`, `we`, index, write data, capture re-arm); the edge is then taken.
fn write(uut: &mut NativeWindow, addr: u64, b: u64) -> (bool, bool, u64, u64, u64) {
    uut.wr.next = true;
    uut.addr.next = addr.into();
    uut.wdata.next = b.into();
    assert!(simulate(uut, 100));
    let access = (
        uut.nat_cyc.val(),
        uut.nat_we.val(),
        uut.nat_adr.val().to_u64(),
        uut.nat_wdat.val().to_u64(),
        uut.cap_rearm.val().to_u64(),
    );
    clock(uut);
    uut.wr.next = false;
    access
}

/// The answer clock: the port's read data and error for one edge.
fn answer(uut: &mut NativeWindow, rdat: u64, err: bool) -> bool {
    uut.nat_rdat.next = rdat.into();
    uut.nat_err.next = err;
    assert!(simulate(uut, 100));
    let refused = uut.refused.val();
    clock(uut);
    uut.nat_rdat.next = 0u64.into();
    uut.nat_err.next = false;
    refused
}

fn read(uut: &mut NativeWindow, addr: u64) -> u64 {
    uut.addr.next = addr.into();
    assert!(simulate(uut, 100));
    uut.rdata.val().to_u64()
}

fn word(uut: &mut NativeWindow) -> u64 {
    (0..4).fold(0, |w, k| w | read(uut, 124 + k) << (8 * k))
}

#[test]
fn native_window_synthesizes() {
    let mut uut = NativeWindow::default();
    uut.connect_all();
    crate::synth_check::yosys_check("native_window", &generate_verilog(&uut));
}

/// P-X-3: a write of `XWIN_IDX` is a native read of that index at its edge;
/// the answer of the next clock loads `XWIN_D0..3` (`D0` = bits [7:0]); a
/// reload reads the stored index again.
#[test]
fn p_x_3_a_load_is_a_native_read_answered_next_clock() {
    let mut uut = fresh();
    let (cyc, we, adr, _, rearm) = write(&mut uut, 122, 0xE3);
    assert_eq!(
        (cyc, we, adr, rearm),
        (true, false, 0x23, 0),
        "read of word 35"
    );
    assert_eq!(read(&mut uut, 122), 0x23, "XWIN_IDX [5:0]");
    answer(&mut uut, 0xA1B2_C3D4, false);
    assert_eq!(word(&mut uut), 0xA1B2_C3D4, "loaded from the answer");
    let (cyc, we, adr, _, _) = write(&mut uut, 123, 0x02);
    assert_eq!(
        (cyc, we, adr),
        (true, false, 0x23),
        "reload: the same index"
    );
    answer(&mut uut, 0x0000_0042, false);
    assert_eq!(word(&mut uut), 0x42);
}

/// P-X-3: the words the view owns (6, 7, 12..21) are not read and load 0;
/// a load of `CAP_A` / `CAP_B` re-arms that channel.
#[test]
fn p_x_3_owned_words_stay_idle_and_captures_rearm() {
    let mut uut = fresh();
    for i in [6u64, 7, 12, 16, 17, 21] {
        let (cyc, ..) = write(&mut uut, 122, i);
        assert!(!cyc, "word {i} is the view's: no native read");
        answer(&mut uut, 0, false);
        assert_eq!(word(&mut uut), 0);
    }
    for (i, ch) in [(5u64, 0u64), (22, 0), (40, 1), (41, 2)] {
        let (cyc, _, _, _, rearm) = write(&mut uut, 122, i);
        assert!(cyc, "word {i} is read");
        assert_eq!(rearm, ch, "re-arm of word {i}");
        answer(&mut uut, 0, false);
    }
}

/// P-X-4: a commit of a listed word in host reset mode is a native full-word
/// write of `XWIN_D0..3`; the port's error answer refuses it one clock later
/// (`refused`, `XWIN_CMD[0] = 1`); a later accepted commit clears the flag.
#[test]
fn p_x_4_a_commit_is_a_native_write_the_native_rules_may_refuse() {
    let mut uut = fresh();
    write(&mut uut, 122, 25); // DMR_CFG
    answer(&mut uut, 0x64, false);
    write(&mut uut, 124, 0x00);
    write(&mut uut, 126, 0x05);
    let (cyc, we, adr, wdat, _) = write(&mut uut, 123, 0x01);
    assert_eq!((cyc, we, adr, wdat), (true, true, 25, 0x0005_0000));
    assert!(answer(&mut uut, 0, true), "refused by the port's error");
    assert_eq!(read(&mut uut, 123), 1, "XWIN_CMD[0]");
    write(&mut uut, 124, 0x32);
    let (cyc, we, ..) = write(&mut uut, 123, 0x01);
    assert!(cyc && we);
    assert!(!answer(&mut uut, 0, false), "acknowledged: accepted");
    assert_eq!(read(&mut uut, 123), 0, "XWIN_CMD[0] cleared");
}

/// P-X-4: a word outside the list, or any word outside host reset mode, is
/// refused at the commit's edge without a native access.
#[test]
fn p_x_4_unlisted_or_outside_reset_mode_refused_without_access() {
    let mut uut = fresh();
    write(&mut uut, 122, 1); // CTRL
    answer(&mut uut, 0x107, false);
    uut.wr.next = true;
    uut.addr.next = 123u64.into();
    uut.wdata.next = 1u64.into();
    assert!(simulate(&mut uut, 100));
    assert!(
        !uut.nat_cyc.val() && uut.refused.val(),
        "CTRL: refused at E"
    );
    clock(&mut uut);
    uut.wr.next = false;
    assert_eq!(read(&mut uut, 123), 1);
    write(&mut uut, 122, 3); // RMB_CFG
    answer(&mut uut, 0x400, false);
    uut.hrm.next = false;
    let (cyc, ..) = write(&mut uut, 123, 0x01);
    assert!(!cyc, "outside host reset mode: no access");
    assert_eq!(read(&mut uut, 123), 1, "refused");
    assert_eq!(word(&mut uut), 0x400, "the loaded word unchanged");
}
