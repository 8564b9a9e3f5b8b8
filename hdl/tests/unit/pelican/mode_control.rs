//! Tests of `drcc_hdl::pelican::mode_control` against the SJA1000 data sheet's
//! MOD, CMR and SR (6.4.2 reset values, 6.4.3 "writable in reset mode only",
//! 6.4.4 the commands, 6.4.5 TBS/TCS/DOS) and pelican_contract.md §3, §6, §7,
//! §8. Expected values are the data sheet's bits and the contract's rules.

use drcc_hdl::pelican::mode_control::ModeControl;
use rust_hdl::prelude::*;

// MOD bits (data sheet 6.4.3)
const RM: u64 = 0x01;
const LOM: u64 = 0x02;
const STM: u64 = 0x04;
const AFM: u64 = 0x08;
const SM: u64 = 0x10;
// CMR bits (data sheet 6.4.4)
const TR: u64 = 0x01;
const AT: u64 = 0x02;
const RRB: u64 = 0x04;
const CDO: u64 = 0x08;
const SRR: u64 = 0x10;

/// The strobes the block shows before an edge (they act at it).
#[derive(Debug, Default, PartialEq)]
struct Strobes {
    push: bool,
    pop: bool,
    rm_rise: bool,
    ti: bool,
    doi: bool,
    ign: bool,
    self_offer: bool,
}

/// Settles the inputs, records the strobes, takes one rising edge, then drops
/// every one-edge input.
fn edge(uut: &mut ModeControl) -> Strobes {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    let s = Strobes {
        push: uut.push.val(),
        pop: uut.pop.val(),
        rm_rise: uut.rm_rise.val(),
        ti: uut.ti_evt.val(),
        doi: uut.doi_evt.val(),
        ign: uut.ign_evt.val(),
        self_offer: uut.self_offer.val(),
    };
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
    uut.mod_write.next = false;
    uut.cmr_write.next = false;
    uut.reconfig.next = false;
    uut.bs_rise.next = false;
    uut.tx_complete.next = false;
    uut.tx_ok.next = false;
    uut.overrun.next = false;
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    s
}

fn fresh(single: bool, bom: bool) -> ModeControl {
    let mut uut = ModeControl::default();
    uut.connect_all();
    uut.wdata.next = 0u64.into();
    uut.single.next = single;
    uut.bom.next = bom;
    uut.rx_ready.next = false;
    uut.rst.next = true;
    edge(&mut uut);
    uut.rst.next = false;
    uut
}

fn write_mod(uut: &mut ModeControl, v: u64) -> Strobes {
    uut.mod_write.next = true;
    uut.wdata.next = v.into();
    edge(uut)
}

fn write_cmr(uut: &mut ModeControl, v: u64) -> Strobes {
    uut.cmr_write.next = true;
    uut.wdata.next = v.into();
    edge(uut)
}

fn complete(uut: &mut ModeControl, ok: bool) -> Strobes {
    uut.tx_complete.next = true;
    uut.tx_ok.next = ok;
    edge(uut)
}

fn bus_off(uut: &mut ModeControl) -> Strobes {
    uut.bs_rise.next = true;
    edge(uut)
}

/// MOD, TBS, TCS, DOS as read.
fn status(uut: &ModeControl) -> (u64, bool, bool, bool) {
    (
        uut.mod_q.val().to_u64(),
        uut.tbs.val(),
        uut.tcs.val(),
        uut.dos.val(),
    )
}

/// Out of reset, in operating mode with the mode bits `m`.
fn operating(single: bool, bom: bool, m: u64) -> ModeControl {
    let mut uut = fresh(single, bom);
    write_mod(&mut uut, m);
    assert!(!uut.rm.val());
    uut
}

#[test]
fn reset_values_are_the_data_sheets() {
    let uut = fresh(true, true);
    // 6.4.2: MOD 0x01, SR.TBS = SR.TCS = 1, DOS 0
    assert_eq!(status(&uut), (0x01, true, true, false));
    assert!(uut.hrm.val() && !uut.boh.val() && uut.chan_reset.val());
}

#[test]
fn leaving_host_reset_keeps_the_channels_in_reset_one_clock_more() {
    let mut uut = fresh(true, true);
    write_mod(&mut uut, 0);
    assert!(!uut.rm.val() && !uut.hrm.val());
    assert!(
        uut.chan_reset.val(),
        "P-MOD-3: one more clock of channel reset"
    );
    edge(&mut uut);
    assert!(!uut.chan_reset.val());
    assert!(write_mod(&mut uut, RM).rm_rise);
    assert!(uut.rm.val() && uut.hrm.val() && uut.chan_reset.val());
}

#[test]
fn mode_bits_are_taken_in_reset_mode_only() {
    let mut uut = fresh(true, true);
    write_mod(&mut uut, RM | LOM | AFM);
    assert_eq!(uut.mod_q.val().to_u64(), RM | LOM | AFM);
    // the write that clears RM also takes them (P-MOD-2)
    write_mod(&mut uut, STM);
    assert_eq!(uut.mod_q.val().to_u64(), STM);
    // in operating mode only RM is taken
    write_mod(&mut uut, LOM | AFM);
    assert_eq!(uut.mod_q.val().to_u64(), STM);
    write_mod(&mut uut, RM | LOM);
    assert_eq!(uut.mod_q.val().to_u64(), RM | STM, "RM set, mode bits kept");
}

#[test]
fn sleep_mode_is_refused_and_flagged() {
    let mut uut = fresh(true, true);
    let s = write_mod(&mut uut, RM | SM);
    assert!(s.ign, "P-MOD-7: XIR.ign");
    assert_eq!(uut.mod_q.val().to_u64() & SM, 0, "SM reads 0");
}

#[test]
fn a_transmission_request_locks_the_buffer_until_completion() {
    let mut uut = operating(true, true, 0);
    let s = write_cmr(&mut uut, TR);
    assert!(s.push, "P-TX-2: pushed at the TR edge");
    assert_eq!(status(&uut), (0, false, false, false));
    assert!(!uut.one_shot.val() && !uut.self_rx.val());
    // TBS = 0: a second request is ignored (the buffer is locked)
    assert!(!write_cmr(&mut uut, TR).push);
    let s = complete(&mut uut, true);
    assert!(s.ti, "P-IR-4: TI event with the completion");
    assert_eq!(status(&uut), (0, true, true, false));
    // a failed completion: TCS 0
    write_cmr(&mut uut, TR | AT);
    assert!(uut.one_shot.val(), "P-TX-4: TR with AT is one-shot");
    complete(&mut uut, false);
    assert_eq!(status(&uut), (0, true, false, false));
    assert!(!uut.one_shot.val(), "cleared by the completion");
}

#[test]
fn transmit_commands_do_nothing_in_reset_mode() {
    let mut uut = fresh(true, true);
    for c in [TR, TR | AT, SRR, AT] {
        let s = write_cmr(&mut uut, c);
        assert!(!s.push, "command {c:#x} in reset mode");
        assert_eq!(status(&uut), (RM, true, true, false));
        assert!(!uut.abort_req.val());
    }
}

#[test]
fn one_shot_and_abort_act_in_the_single_modes_only() {
    let mut uut = operating(false, true, 0);
    let s = write_cmr(&mut uut, TR | AT);
    assert!(
        s.push && s.ign,
        "P-TX-4: pushed, one-shot ignored with XIR.ign"
    );
    assert!(!uut.one_shot.val());
    let s = write_cmr(&mut uut, AT);
    assert!(
        s.ign && !uut.abort_req.val(),
        "P-TX-3: no abort in redundancy"
    );

    let mut uut = operating(true, true, 0);
    // AT alone with TBS = 1: nothing to abort
    assert!(!write_cmr(&mut uut, AT).ign);
    assert!(!uut.abort_req.val());
    write_cmr(&mut uut, TR);
    let s = write_cmr(&mut uut, AT);
    assert!(
        !s.ign && uut.abort_req.val(),
        "P-TX-3: held until completion"
    );
    edge(&mut uut);
    assert!(uut.abort_req.val());
    complete(&mut uut, false);
    assert!(!uut.abort_req.val());
    assert_eq!(status(&uut), (0, true, false, false));
}

#[test]
fn self_reception_offers_the_frame_on_success_only() {
    let mut uut = operating(true, true, STM);
    let s = write_cmr(&mut uut, SRR);
    assert!(s.push && uut.self_rx.val(), "P-TX-5");
    assert!(complete(&mut uut, true).self_offer);
    assert!(!uut.self_rx.val());
    write_cmr(&mut uut, SRR | AT);
    assert!(!complete(&mut uut, false).self_offer);
    // a plain TR is never offered
    write_cmr(&mut uut, TR);
    assert!(!complete(&mut uut, true).self_offer);
}

#[test]
fn listen_only_completes_a_request_without_sending() {
    let mut uut = operating(true, true, 0);
    write_mod(&mut uut, RM | LOM);
    write_mod(&mut uut, LOM);
    let s = write_cmr(&mut uut, TR);
    assert!(!s.push, "P-TX-6: not passed to the core");
    assert_eq!(status(&uut), (LOM, false, false, false));
    let s = edge(&mut uut);
    assert!(s.ti, "TI one clock later");
    assert_eq!(
        status(&uut),
        (LOM, true, false, false),
        "TBS back, TCS stays 0"
    );
}

#[test]
fn bus_off_enters_the_hold_and_only_clearing_rm_leaves_it() {
    let mut uut = operating(true, true, 0);
    write_cmr(&mut uut, TR);
    let s = bus_off(&mut uut);
    assert!(s.rm_rise, "P-BO-1");
    assert!(uut.boh.val() && !uut.hrm.val() && uut.rm.val());
    assert!(!uut.chan_reset.val(), "P-MOD-4: the channels are not reset");
    assert_eq!(
        status(&uut),
        (RM, true, false, false),
        "message dropped, TCS 0"
    );
    // RM = 1 while the hold is on changes nothing
    write_mod(&mut uut, RM);
    assert!(uut.boh.val() && !uut.hrm.val());
    // the restart: RM = 0 with the mode bits unchanged
    let s = write_mod(&mut uut, 0);
    assert!(!s.rm_rise);
    assert!(!uut.rm.val() && !uut.boh.val() && !uut.chan_reset.val());
}

#[test]
fn a_reconfiguration_in_the_hold_is_a_host_reset() {
    let mut uut = operating(true, true, 0);
    bus_off(&mut uut);
    uut.reconfig.next = true;
    edge(&mut uut);
    assert!(
        !uut.boh.val() && uut.hrm.val() && uut.chan_reset.val(),
        "P-BO-6"
    );
    // MOD's own LOM changed by the restart write
    let mut uut = operating(true, true, 0);
    bus_off(&mut uut);
    write_mod(&mut uut, LOM);
    assert!(!uut.boh.val() && uut.hrm.val(), "P-BO-6: a changed LOM");
    assert_eq!(uut.mod_q.val().to_u64(), RM | LOM);
}

#[test]
fn bus_off_in_auto_mode_or_in_reset_mode_sets_no_hold() {
    let mut uut = operating(true, false, 0);
    assert!(!bus_off(&mut uut).rm_rise, "P-BO-7: auto recovery");
    assert!(!uut.rm.val());
    let mut uut = fresh(true, true);
    bus_off(&mut uut);
    assert!(
        !uut.boh.val(),
        "the rise in reset mode is no operating-mode bus-off"
    );
    // a host RM = 1 write at the bus-off edge: the host reset
    let mut uut = operating(true, true, 0);
    uut.bs_rise.next = true;
    write_mod(&mut uut, RM);
    assert!(uut.hrm.val() && !uut.boh.val());
}

#[test]
fn receive_buffer_commands_and_overrun() {
    let mut uut = operating(true, true, 0);
    assert!(
        !write_cmr(&mut uut, RRB).pop,
        "P-CMR-4: nothing on an empty FIFO"
    );
    uut.rx_ready.next = true;
    assert!(write_cmr(&mut uut, RRB).pop);
    uut.overrun.next = true;
    assert!(edge(&mut uut).doi, "P-RX-6: DOS 0 -> 1");
    assert!(uut.dos.val());
    uut.overrun.next = true;
    assert!(!edge(&mut uut).doi, "DOS already 1");
    // CDO at an overrun edge loses
    uut.overrun.next = true;
    write_cmr(&mut uut, CDO);
    assert!(uut.dos.val(), "P-CMR-5");
    write_cmr(&mut uut, CDO);
    assert!(!uut.dos.val());
    // entering reset mode clears DOS
    uut.overrun.next = true;
    edge(&mut uut);
    write_mod(&mut uut, RM);
    assert!(!uut.dos.val(), "P-MOD-5");
    // RRB and CDO act in reset mode too
    assert!(write_cmr(&mut uut, RRB).pop);
}

#[test]
fn mode_control_synthesizes() {
    let mut uut = ModeControl::default();
    uut.connect_all();
    crate::synth_check::yosys_check("mode_control", &generate_verilog(&uut));
}
