//! Tests of `drcc_hdl::pelican::acceptance_filter` against the SJA1000 data
//! sheet's acceptance filter (6.4.15, pelican_contract.md P-ACF-1). The filter
//! bytes are laid out from a frame as the data sheet's figures place the bits
//! (and as SJA1000 drivers compute them); the verdicts are the data sheet's:
//! a filter set to a frame accepts it, one identifier or RTR bit off rejects
//! it unless that bit is masked, and a data byte the frame lacks matches.

use drcc_hdl::pelican::acceptance_filter::AcceptanceFilter;
use rust_hdl::prelude::*;

/// A frame as the filter sees it.
#[derive(Clone, Copy, Debug)]
struct Frame {
    id: u32,
    ide: bool,
    rtr: bool,
    dlc: u8,
    data: [u8; 2],
}

fn std(id: u32, data: &[u8]) -> Frame {
    let mut d = [0; 2];
    for (k, b) in data.iter().take(2).enumerate() {
        d[k] = *b;
    }
    Frame {
        id,
        ide: false,
        rtr: false,
        dlc: data.len() as u8,
        data: d,
    }
}

fn ext(id: u32) -> Frame {
    Frame {
        id,
        ide: true,
        rtr: false,
        dlc: 0,
        data: [0; 2],
    }
}

fn remote(mut f: Frame) -> Frame {
    f.rtr = true;
    f.data = [0; 2];
    f
}

/// `ACR0..3`, `AMR0..3` and `AFM`.
#[derive(Clone, Copy, Debug)]
struct Filter {
    acr: [u8; 4],
    amr: [u8; 4],
    single: bool,
}

/// The data sheet's reset-free default of the view: accept everything.
const OPEN: Filter = Filter {
    acr: [0; 4],
    amr: [0xFF; 4],
    single: true,
};

fn verdict(f: Filter, fr: Frame) -> bool {
    let mut uut = AcceptanceFilter::default();
    uut.connect_all();
    uut.acr0.next = (f.acr[0] as u64).into();
    uut.acr1.next = (f.acr[1] as u64).into();
    uut.acr2.next = (f.acr[2] as u64).into();
    uut.acr3.next = (f.acr[3] as u64).into();
    uut.amr0.next = (f.amr[0] as u64).into();
    uut.amr1.next = (f.amr[1] as u64).into();
    uut.amr2.next = (f.amr[2] as u64).into();
    uut.amr3.next = (f.amr[3] as u64).into();
    uut.afm.next = f.single;
    uut.id.next = (fr.id as u64).into();
    uut.ide.next = fr.ide;
    uut.rtr.next = fr.rtr;
    uut.dlc.next = (fr.dlc as u64).into();
    uut.data1.next = (fr.data[0] as u64).into();
    uut.data2.next = (fr.data[1] as u64).into();
    assert!(simulate(&mut uut, 100));
    uut.accept.val()
}

/// Single filter, standard frame (data sheet figure "single filter
/// configuration, receiving standard frame messages"): ACR0 = ID.28..21,
/// ACR1[7:5] = ID.20..18, ACR1[4] = RTR, ACR2 = data byte 1, ACR3 = data
/// byte 2. The standard identifier's bits 10..0 are ID.28..18.
fn single_std(fr: Frame) -> [u8; 4] {
    [
        (fr.id >> 3) as u8,
        ((fr.id & 7) << 5) as u8 | (fr.rtr as u8) << 4,
        fr.data[0],
        fr.data[1],
    ]
}

/// Single filter, extended frame: ACR0 = ID.28..21, ACR1 = ID.20..13, ACR2 =
/// ID.12..5, ACR3[7:3] = ID.4..0, ACR3[2] = RTR.
fn single_ext(fr: Frame) -> [u8; 4] {
    [
        (fr.id >> 21) as u8,
        (fr.id >> 13) as u8,
        (fr.id >> 5) as u8,
        ((fr.id & 0x1F) << 3) as u8 | (fr.rtr as u8) << 2,
    ]
}

#[test]
fn an_open_filter_accepts_every_frame_in_both_modes() {
    for single in [true, false] {
        let f = Filter { single, ..OPEN };
        for fr in [
            std(0x000, &[]),
            std(0x7FF, &[0xFF, 0xFF]),
            remote(std(0x123, &[])),
            ext(0x1FFF_FFFF),
            remote(ext(0)),
        ] {
            assert!(verdict(f, fr), "{fr:?} (single {single})");
        }
    }
}

/// P-ACF-1, single filter, standard: every identifier bit and the RTR bit are
/// compared; flipping any one of them rejects the frame; masking that bit
/// (AMR bit 1) accepts it again.
#[test]
fn single_filter_standard_compares_every_identifier_bit_and_rtr() {
    let base = std(0x5A3, &[0x11, 0x22]);
    let f = Filter {
        acr: single_std(base),
        amr: [0x00, 0x0F, 0xFF, 0xFF],
        single: true,
    };
    assert!(verdict(f, base));
    for bit in 0..11 {
        let other = std(base.id ^ (1 << bit), &[0x11, 0x22]);
        assert!(!verdict(f, other), "ID bit {bit} differs");
        // the same bit masked: its AMR bit (ID.28..21 in AMR0, ID.20..18 in AMR1[7:5])
        let mut masked = f;
        if bit >= 3 {
            masked.amr[0] |= 1 << (bit - 3);
        } else {
            masked.amr[1] |= 1 << (bit + 5);
        }
        assert!(verdict(masked, other), "ID bit {bit} masked");
    }
    assert!(!verdict(f, remote(base)), "RTR differs");
    let mut rtr_masked = f;
    rtr_masked.amr[1] |= 0x10;
    assert!(verdict(rtr_masked, remote(base)), "RTR masked");
    // the unused low nibble of ACR1 is not compared in single mode
    let mut nibble = f;
    nibble.acr[1] ^= 0x0F;
    nibble.amr[1] &= 0xF0;
    assert!(verdict(nibble, base), "ACR1[3:0] is unused");
}

/// P-ACF-1, single filter, standard: data bytes 1 and 2 are compared when the
/// frame has them; a frame without them (DLC 0 or 1, or a remote frame)
/// matches (data sheet: "messages may also be accepted if there are no data
/// bytes").
#[test]
fn single_filter_standard_compares_the_first_two_data_bytes_the_frame_has() {
    let base = std(0x123, &[0xAB, 0xCD]);
    let f = Filter {
        acr: single_std(base),
        amr: [0x00, 0x0F, 0x00, 0x00],
        single: true,
    };
    assert!(verdict(f, base));
    assert!(
        !verdict(f, std(0x123, &[0xAB, 0xCE])),
        "data byte 2 differs"
    );
    assert!(
        !verdict(f, std(0x123, &[0x2B, 0xCD])),
        "data byte 1 differs"
    );
    assert!(verdict(f, std(0x123, &[0xAB])), "no data byte 2");
    assert!(
        !verdict(f, std(0x123, &[0xAC])),
        "data byte 1 still compared"
    );
    assert!(verdict(f, std(0x123, &[])), "no data bytes");
    // a DLC of 9..15 carries 8 bytes: both compared
    let mut long = std(0x123, &[0xAB, 0xCE]);
    long.dlc = 15;
    assert!(!verdict(f, long), "DLC 15 has data byte 2");
    // a remote frame has no data bytes, whatever its DLC
    let mut rf = Filter {
        acr: single_std(remote(base)),
        ..f
    };
    rf.acr[2] = 0xAB;
    rf.acr[3] = 0xCD;
    let mut r = remote(base);
    r.dlc = 8;
    assert!(verdict(rf, r), "remote frame, DLC 8: no data bytes");
}

/// P-ACF-1, single filter, extended: 29 identifier bits and RTR; each one off
/// rejects, each one masked accepts.
#[test]
fn single_filter_extended_compares_29_identifier_bits_and_rtr() {
    let base = ext(0x1234_5678 & 0x1FFF_FFFF);
    let f = Filter {
        acr: single_ext(base),
        amr: [0x00, 0x00, 0x00, 0x03],
        single: true,
    };
    assert!(verdict(f, base));
    for bit in 0..29 {
        let other = ext(base.id ^ (1 << bit));
        assert!(!verdict(f, other), "ID bit {bit} differs");
        // ID.4..0 in AMR3[7:3], ID.12..5 in AMR2, ID.20..13 in AMR1, ID.28..21 in AMR0
        let mut masked = f;
        match bit {
            0..=4 => masked.amr[3] |= 1 << (bit + 3),
            5..=12 => masked.amr[2] |= 1 << (bit - 5),
            13..=20 => masked.amr[1] |= 1 << (bit - 13),
            _ => masked.amr[0] |= 1 << (bit - 21),
        }
        assert!(verdict(masked, other), "ID bit {bit} masked");
    }
    assert!(!verdict(f, remote(base)), "RTR differs");
    let mut rtr_masked = f;
    rtr_masked.amr[3] |= 0x04;
    assert!(verdict(rtr_masked, remote(base)), "RTR masked");
    // a standard frame is judged by the standard layout, not this one
    assert!(!verdict(f, std(base.id & 0x7FF, &[])));
}

/// P-ACF-1, dual filter, standard (data sheet figure "dual filter
/// configuration, receiving standard frame messages"): filter 1 = ACR0,
/// ACR1[7:4] (ID.28..18, RTR) and data byte 1 split over ACR1[3:0] (high
/// nibble) and ACR3[3:0] (low nibble); filter 2 = ACR2, ACR3[7:4] (ID.28..18,
/// RTR). Either accepts.
#[test]
fn dual_filter_standard_two_identifiers_and_data_byte_1_on_filter_1() {
    let (a, b) = (0x123u32, 0x6DE);
    let f = Filter {
        acr: [
            (a >> 3) as u8,
            ((a & 7) << 5) as u8 | 0x0A, // data byte 1 high nibble 0xA
            (b >> 3) as u8,
            ((b & 7) << 5) as u8 | 0x05, // data byte 1 low nibble 0x5
        ],
        amr: [0; 4],
        single: false,
    };
    assert!(verdict(f, std(a, &[0xA5])), "filter 1 with its data byte");
    assert!(
        !verdict(f, std(a, &[0xA4])),
        "filter 1, data low nibble off"
    );
    assert!(
        !verdict(f, std(a, &[0xB5])),
        "filter 1, data high nibble off"
    );
    assert!(verdict(f, std(a, &[])), "filter 1, no data byte");
    assert!(
        verdict(f, std(b, &[0x00, 0x00])),
        "filter 2 ignores the data"
    );
    assert!(!verdict(f, std(0x124, &[0xA5])), "neither filter");
    assert!(!verdict(f, remote(std(b, &[]))), "filter 2 compares RTR");
    // filter 2's identifier with filter 1's mask open: only the data decides
    let mut open1 = f;
    open1.amr[0] = 0xFF;
    open1.amr[1] = 0xF0;
    assert!(
        verdict(open1, std(0x321, &[0xA5])),
        "filter 1: any ID, data 0xA5"
    );
    assert!(!verdict(open1, std(0x321, &[0xA6])));
}

/// P-ACF-1, dual filter, extended: filter 1 = ACR0, ACR1 (ID.28..13), filter
/// 2 = ACR2, ACR3 (ID.28..13); ID.12..0 and RTR are not compared.
#[test]
fn dual_filter_extended_compares_the_top_16_identifier_bits() {
    let (a, b) = (0x1ABC_DEF0 & 0x1FFF_FFFF, 0x0246_8ACE);
    let f = Filter {
        acr: [
            (a >> 21) as u8,
            (a >> 13) as u8,
            (b >> 21) as u8,
            (b >> 13) as u8,
        ],
        amr: [0; 4],
        single: false,
    };
    assert!(verdict(f, ext(a)));
    assert!(verdict(f, ext(b)));
    assert!(verdict(f, ext(a ^ 0x1FFF)), "ID.12..0 not compared");
    assert!(verdict(f, remote(ext(b))), "RTR not compared");
    for bit in 13..29 {
        assert!(!verdict(f, ext(a ^ (1 << bit))), "filter 1, ID bit {bit}");
    }
}

#[test]
fn acceptance_filter_synthesizes() {
    let mut uut = AcceptanceFilter::default();
    uut.connect_all();
    crate::synth_check::yosys_check("acceptance_filter", &generate_verilog(&uut));
}
