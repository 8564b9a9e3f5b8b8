//! The Verilated `drcc` top through the safe wrapper: a Wishbone read of the `ID`
//! register (contract: constant 0x44524343, "DRCC") and the reset state of the
//! paper's main FSM (idle1 = 0). Without the model it skips, except under CI.

use verilator_sys::{available, unavailable_reason, Drcc, DrccIn};

#[test]
fn id_register_reads_drcc_after_reset() {
    if !available() {
        let ci = verilator_sys::required();
        assert!(
            !ci,
            "the Verilated model is required in CI: {:?}",
            unavailable_reason()
        );
        eprintln!("skipped: {:?}", unavailable_reason());
        return;
    }
    let mut top = Drcc::new().expect("model available");
    let idle = DrccIn {
        chan_a_rx: 1,
        chan_b_rx: 1,
        ..DrccIn::default()
    };
    for _ in 0..3 {
        top.step(&DrccIn { rst: 1, ..idle });
    }
    let read = DrccIn {
        wb_cyc_i: 1,
        wb_stb_i: 1,
        wb_adr_i: 0,
        ..idle
    };
    let out = top.step(&read);
    assert_eq!(
        out.wb_ack_o, 1,
        "classic Wishbone: ack one clock after the request"
    );
    assert_eq!(out.wb_dat_o, 0x4452_4343);
    assert_eq!(out.state, 0, "main FSM in idle1");
    assert_eq!(
        (out.chan_a_tx, out.chan_b_tx),
        (1, 1),
        "both lines recessive"
    );
}
