//! Tests of `drcc_hdl::pelican::rx_window` against the SJA1000 data sheet's
//! receive buffer layout (6.4.14; pelican_contract.md P-RX-2): the bytes a
//! driver reads back are the ones an SJA1000 would show (Linux's sja1000 driver
//! reads FI at 16, then `id = (b17 << 3) | (b18 >> 5)` for a standard frame,
//! `id = (b17 << 21) | (b18 << 13) | (b19 << 5) | (b20 >> 3)` for an extended
//! one, and the data from 19 or 21).

use drcc_hdl::pelican::rx_window::RxWindow;
use rust_hdl::prelude::*;

/// The DRCC frame word (DRCC contract §6 layout) of a frame.
fn word(rtr: bool, ide: bool, id: u32, dlc: u8, data: [u8; 8]) -> Bits<99> {
    let hi = ((rtr as u64) << 34) | ((ide as u64) << 33) | ((id as u64) << 4) | dlc as u64;
    (bit_cast::<99, 35>(hi.into()) << 64) | bit_cast::<99, 64>(u64::from_be_bytes(data).into())
}

fn window(frame: Bits<99>) -> Vec<u8> {
    let mut uut = RxWindow::default();
    uut.connect_all();
    uut.frame.next = frame;
    (0..128u64)
        .map(|a| {
            uut.addr.next = a.into();
            assert!(simulate(&mut uut, 100));
            uut.rdata.val().to_u64() as u8
        })
        .collect()
}

#[test]
fn a_standard_frame_reads_as_the_data_sheet_lays_it_out() {
    let id = 0x6B3;
    let w = window(word(false, false, id, 5, [1, 2, 3, 4, 5, 0, 0, 0]));
    assert_eq!(w[16], 0x05, "FI: standard data frame, DLC 5");
    let read_id = ((w[17] as u32) << 3) | (w[18] as u32 >> 5);
    assert_eq!(read_id, id);
    assert_eq!(w[18] & 0x1F, 0, "RTR 0 and the low bits 0");
    assert_eq!(&w[19..24], &[1, 2, 3, 4, 5]);
    assert_eq!(
        &w[24..29],
        &[0; 5],
        "past DLC, and 27, 28 of a standard frame"
    );
    for (a, b) in w.iter().enumerate() {
        if !(16..29).contains(&a) {
            assert_eq!(*b, 0, "address {a} is not the window");
        }
    }
}

#[test]
fn an_extended_frame_reads_as_the_data_sheet_lays_it_out() {
    let id = 0x1234_5678 & 0x1FFF_FFFF;
    let data = [0xF1, 0xF2, 0xF3, 0xF4, 0xF5, 0xF6, 0xF7, 0xF8];
    let w = window(word(false, true, id, 8, data));
    assert_eq!(w[16], 0x88, "FI: extended data frame, DLC 8");
    let read_id = ((w[17] as u32) << 21)
        | ((w[18] as u32) << 13)
        | ((w[19] as u32) << 5)
        | (w[20] as u32 >> 3);
    assert_eq!(read_id, id);
    assert_eq!(w[20] & 0x07, 0, "RTR 0");
    assert_eq!(&w[21..29], &data);
}

#[test]
fn remote_frames_carry_rtr_in_fi_and_beside_the_identifier() {
    let w = window(word(true, false, 0x7FF, 4, [0; 8]));
    assert_eq!(w[16], 0x44, "FI: RTR, DLC as received");
    assert_eq!(w[18], 0xF0, "id[2:0] = 111, RTR = 1");
    let w = window(word(true, true, 0x1FFF_FFFF, 15, [0; 8]));
    assert_eq!(w[16], 0xCF, "FI: FF, RTR, DLC 15 as received");
    assert_eq!(w[20], 0xFC, "id[4:0] = 11111, RTR = 1");
}

#[test]
fn rx_window_synthesizes() {
    let mut uut = RxWindow::default();
    uut.connect_all();
    crate::synth_check::yosys_check("rx_window", &generate_verilog(&uut));
}
