//! Tests of `drcc_hdl::dmr::cs_rx`.

use drcc_hdl::dmr::cs_rx::*;
use rust_hdl::prelude::*;

#[test]
fn dmr_cs_rx_synthesizes() {
    let mut uut = DmrCsRx::default();
    uut.connect_all();
    crate::synth_check::yosys_check("dmr_cs_rx", &generate_verilog(&uut));
}

#[test]
fn cs_detect_synthesizes() {
    let mut uut = CsDetect::default();
    uut.connect_all();
    crate::synth_check::yosys_check("cs_detect", &generate_verilog(&uut));
}

/// DMR contract §7 on one line whose own CS identifier is 0x701 and the other
/// line's 0x702: a base data frame with DLC 0 and the own identifier counts good,
/// with the other's counts bad; any other frame (another identifier, DLC, IDE or
/// RTR) is delivered; nothing without `rx_valid`.
#[test]
fn cs_detect_tells_cs_frames_from_deliveries() {
    let mut uut = CsDetect::default();
    uut.connect_all();
    uut.cs_id_own.next = 0x701.into();
    uut.cs_id_other.next = 0x702.into();
    // (valid, ide, rtr, dlc, id) -> (good, bad, deliver)
    type Frame = (bool, bool, bool, u64, u64);
    let cases: [(Frame, (bool, bool, bool)); 8] = [
        ((true, false, false, 0, 0x701), (true, false, false)),
        ((true, false, false, 0, 0x702), (false, true, false)),
        ((true, false, false, 0, 0x703), (false, false, true)),
        ((true, false, false, 1, 0x701), (false, false, true)),
        ((true, true, false, 0, 0x701), (false, false, true)),
        ((true, false, true, 0, 0x702), (false, false, true)),
        ((false, false, false, 0, 0x701), (false, false, false)),
        ((false, false, false, 3, 0x123), (false, false, false)),
    ];
    for ((valid, ide, rtr, dlc, id), want) in cases {
        uut.rx_valid.next = valid;
        uut.rx_ide.next = ide;
        uut.rx_rtr.next = rtr;
        uut.rx_dlc.next = dlc.into();
        uut.rx_id.next = id.into();
        assert!(simulate(&mut uut, 50));
        let got = (uut.good.val(), uut.bad.val(), uut.deliver.val());
        assert_eq!(
            got, want,
            "valid {valid} ide {ide} rtr {rtr} dlc {dlc} id {id:#x}"
        );
    }
    // one identifier for both lines: the own one wins (good, never bad)
    uut.cs_id_other.next = 0x701.into();
    uut.rx_valid.next = true;
    uut.rx_ide.next = false;
    uut.rx_rtr.next = false;
    uut.rx_dlc.next = 0.into();
    uut.rx_id.next = 0x701.into();
    assert!(simulate(&mut uut, 50));
    assert_eq!(
        (uut.good.val(), uut.bad.val(), uut.deliver.val()),
        (true, false, false)
    );
}
