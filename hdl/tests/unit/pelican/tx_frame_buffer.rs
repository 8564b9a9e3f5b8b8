//! Tests of `drcc_hdl::pelican::tx_frame_buffer` against the SJA1000 data
//! sheet's transmit buffer (6.4.13: the window at 16..28 in operating mode,
//! locked while `TBS = 0`; the RAM addresses 96..108 in reset mode; the frame
//! information, identifier and data layouts) and pelican_contract.md P-TX-1,
//! P-MAP-1 (`SCR0..2` at 109..111). The bytes are written as SJA1000 drivers
//! write them (standard: FI, `id >> 3`, `id << 5`, data; extended: FI, `id >>
//! 21`, `id >> 13`, `id >> 5`, `id << 3`, data); the frame word is the DRCC's
//! TX RAM layout (DRCC contract §6: [98] rtr, [97] ide, [96:68] id, [67:64]
//! dlc, [63:0] data with the first byte in [63:56]).

use drcc_hdl::pelican::tx_frame_buffer::TxFrameBuffer;
use rust_hdl::prelude::*;

fn clock(uut: &mut TxFrameBuffer) {
    uut.clk.next = Clock::from(false);
    assert!(simulate(uut, 100));
    uut.clk.next = Clock::from(true);
    assert!(simulate(uut, 100));
}

fn fresh() -> TxFrameBuffer {
    let mut uut = TxFrameBuffer::default();
    uut.connect_all();
    uut.wr.next = false;
    uut.addr.next = 0u64.into();
    uut.wdata.next = 0u64.into();
    uut.rm.next = false;
    uut.tbs.next = true;
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    uut
}

fn write(uut: &mut TxFrameBuffer, addr: u8, byte: u8) {
    uut.wr.next = true;
    uut.addr.next = (addr as u64).into();
    uut.wdata.next = (byte as u64).into();
    clock(uut);
    uut.wr.next = false;
}

fn read(uut: &mut TxFrameBuffer, addr: u8) -> u8 {
    uut.addr.next = (addr as u64).into();
    assert!(simulate(uut, 100));
    uut.rdata.val().to_u64() as u8
}

/// The DRCC frame word of a frame.
fn word(rtr: bool, ide: bool, id: u32, dlc: u8, data: [u8; 8]) -> u128 {
    ((rtr as u128) << 98)
        | ((ide as u128) << 97)
        | ((id as u128) << 68)
        | ((dlc as u128) << 64)
        | u64::from_be_bytes(data) as u128
}

fn frame(uut: &TxFrameBuffer) -> u128 {
    let v = uut.frame.val();
    ((v.get_bits::<35>(64).to_u64() as u128) << 64) | v.get_bits::<64>(0).to_u64() as u128
}

/// A standard data frame through the window, as Linux's sja1000 driver
/// writes it.
#[test]
fn a_standard_frame_written_through_the_window() {
    let mut uut = fresh();
    let id = 0x5A5u32;
    let data = [1, 2, 3, 4, 5, 6, 7, 8];
    write(&mut uut, 16, 0x08); // FI: standard, data, DLC 8
    write(&mut uut, 17, (id >> 3) as u8);
    write(&mut uut, 18, (id << 5) as u8);
    for (k, b) in data.iter().enumerate() {
        write(&mut uut, 19 + k as u8, *b);
    }
    assert_eq!(frame(&uut), word(false, false, id, 8, data));
    // the same bytes read back at the RAM addresses
    assert_eq!(read(&mut uut, 96), 0x08);
    assert_eq!(read(&mut uut, 97), (id >> 3) as u8);
    assert_eq!(read(&mut uut, 98), (id << 5) as u8);
    assert_eq!(read(&mut uut, 106), 8);
}

/// An extended remote frame: FF and RTR set, 29 identifier bits over four
/// bytes, the low three bits of the fourth unused.
#[test]
fn an_extended_remote_frame_written_through_the_window() {
    let mut uut = fresh();
    let id = 0x1ABC_DEF5u32;
    write(&mut uut, 16, 0xC3); // FF, RTR, DLC 3
    write(&mut uut, 17, (id >> 21) as u8);
    write(&mut uut, 18, (id >> 13) as u8);
    write(&mut uut, 19, (id >> 5) as u8);
    write(&mut uut, 20, (id << 3) as u8 | 0x07); // bits 2..0 ignored
    for k in 0..8 {
        write(&mut uut, 21 + k, 0xA0 + k);
    }
    let data = [0xA0, 0xA1, 0xA2, 0xA3, 0xA4, 0xA5, 0xA6, 0xA7];
    assert_eq!(frame(&uut), word(true, true, id, 3, data));
    // FI bits 5 and 4 are not part of the frame
    write(&mut uut, 16, 0xF3);
    assert_eq!(frame(&uut), word(true, true, id, 3, data));
}

/// P-TX-1: the window is locked while `TBS = 0`, and in reset mode 16..28 are
/// not the buffer (they are the acceptance filter there); the RAM addresses
/// 96..108 take writes in reset mode only.
#[test]
fn writes_land_only_where_and_when_the_data_sheet_allows() {
    let mut uut = fresh();
    write(&mut uut, 17, 0x11);
    uut.tbs.next = false;
    write(&mut uut, 17, 0x22);
    assert_eq!(read(&mut uut, 97), 0x11, "locked buffer");
    uut.tbs.next = true;
    uut.rm.next = true;
    write(&mut uut, 17, 0x33);
    assert_eq!(read(&mut uut, 97), 0x11, "16..28 in reset mode");
    write(&mut uut, 97, 0x44);
    assert_eq!(read(&mut uut, 97), 0x44, "RAM address in reset mode");
    uut.rm.next = false;
    write(&mut uut, 97, 0x55);
    assert_eq!(read(&mut uut, 97), 0x44, "RAM address in operating mode");
    // 29 (RMC) and 15 (TXERR) are not the buffer
    write(&mut uut, 29, 0x66);
    write(&mut uut, 15, 0x77);
    for a in 96..=108 {
        let v = read(&mut uut, a);
        assert!(v != 0x66 && v != 0x77, "address {a}");
    }
}

/// P-MAP-1: `SCR0..2` (109..111) are written in reset mode, read in both, and
/// cleared by `rst`, which leaves `TXB` alone (P-TX-1: not reset).
#[test]
fn the_scratch_bytes_and_reset() {
    let mut uut = fresh();
    write(&mut uut, 16, 0x01);
    uut.rm.next = true;
    for (a, v) in [(109, 0xA1), (110, 0xB2), (111, 0xC3)] {
        write(&mut uut, a, v);
    }
    uut.rm.next = false;
    write(&mut uut, 110, 0x00);
    assert_eq!(
        [
            read(&mut uut, 109),
            read(&mut uut, 110),
            read(&mut uut, 111)
        ],
        [0xA1, 0xB2, 0xC3]
    );
    assert_eq!(read(&mut uut, 5), 0, "not a buffer address");
    uut.rst.next = true;
    clock(&mut uut);
    uut.rst.next = false;
    assert_eq!([read(&mut uut, 109), read(&mut uut, 111)], [0, 0]);
    assert_eq!(read(&mut uut, 96), 0x01, "TXB keeps its bytes");
}

#[test]
fn tx_frame_buffer_synthesizes() {
    let mut uut = TxFrameBuffer::default();
    uut.connect_all();
    crate::synth_check::yosys_check("tx_frame_buffer", &generate_verilog(&uut));
}
